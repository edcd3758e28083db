//! Appending what parts of a list make, in order and in parallel, each
//! part writing straight into its place at the end of one `Vec`.
//!
//! Why a file of its own: set-up made each chunk of a mesh's triangles
//! into a list of its own, then copied the lists into the frame's list:
//! for a 100k-triangle mesh that is 25 MB written twice and read once
//! more, a memory-bound copy the profile showed as 4–6 % of the frame.
//! Here a first, cheap pass counts what each part makes; the second
//! makes it into the slots the counts give, so every item is written
//! once, where it stays.

use rayon::prelude::*;
use std::mem::MaybeUninit;

/// Where a part's items go: its slots at the end of the list, or (after
/// a miscount) the end of the list itself.
pub enum Sink<'a, T> {
    Slots {
        slots: &'a mut [MaybeUninit<T>],
        /// Items pushed so far (may pass `slots.len()`: a miscount).
        n: usize,
    },
    List(&'a mut Vec<T>),
}

impl<T> Sink<'_, T> {
    #[inline(always)]
    pub fn push(&mut self, item: T) {
        match self {
            Sink::Slots { slots, n } => {
                if let Some(s) = slots.get_mut(*n) {
                    s.write(item);
                }
                *n += 1;
            }
            Sink::List(list) => list.push(item),
        }
    }
}

/// Appends to `dest` what each of `parts` makes, in the parts' order:
/// `count(part)` must say how many items `make(part, sink)` pushes. Parts
/// run in parallel, each into its own slots. Should a count be wrong
/// (a bug, not bad input), nothing written in place is kept and the parts
/// are made again one after the other, straight onto `dest`: the same
/// list, only slower.
pub fn extend_in_place<P, T>(
    dest: &mut Vec<T>,
    parts: &[P],
    count: impl Fn(&P) -> usize + Sync,
    make: impl Fn(&P, &mut Sink<T>) + Sync,
) where
    P: Sync,
    T: Copy + Send,
{
    let counts: Vec<usize> = parts.par_iter().map(&count).collect();
    let total: usize = counts.iter().sum();
    dest.reserve(total);
    let old = dest.len();
    let mut rest = &mut dest.spare_capacity_mut()[..total];
    let mut sinks = Vec::with_capacity(parts.len());
    for &c in &counts {
        let (here, after) = std::mem::take(&mut rest).split_at_mut(c);
        sinks.push(Sink::Slots { slots: here, n: 0 });
        rest = after;
    }
    let exact = sinks
        .par_iter_mut()
        .zip(parts.par_iter())
        .all(|(sink, part)| {
            make(part, sink);
            matches!(sink, Sink::Slots { slots, n } if *n == slots.len())
        });
    if exact {
        // SAFETY: the `total` slots after the old length were reserved
        // above, split into one run per part of its count's length, and
        // each part pushed exactly that many items, each into the next
        // slot of its run: every slot is written.
        unsafe { dest.set_len(old + total) };
        return;
    }
    let mut sink = Sink::List(dest);
    for part in parts {
        make(part, &mut sink);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Parts make 0 to 6 items each (the part's number, repeated, with
    /// its index); appended in place they are the serial list, after
    /// items already there, whatever the thread count; a count that is
    /// wrong (too many, too few) still gives the serial list.
    #[test]
    fn in_place_is_the_serial_list() {
        let parts: Vec<u32> = (0..500).map(|i| (i * 7919) % 7).collect();
        let make = |p: &u32, s: &mut Sink<(u32, u32)>| {
            for k in 0..*p {
                s.push((*p, k));
            }
        };
        let serial: Vec<(u32, u32)> = [(9, 9)]
            .into_iter()
            .chain(parts.iter().flat_map(|&p| (0..p).map(move |k| (p, k))))
            .collect();
        for threads in [1, 2, 3] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let mut got = vec![(9, 9)];
            pool.install(|| extend_in_place(&mut got, &parts, |p| *p as usize, make));
            assert_eq!(got, serial, "{threads} threads");
        }
    }

    /// A count that is wrong, too high or too low, still gives the
    /// serial list (made again one part after the other).
    #[test]
    fn a_wrong_count_still_gives_the_serial_list() {
        let parts: Vec<u32> = (0..100).map(|i| i % 5).collect();
        let make = |p: &u32, s: &mut Sink<u32>| {
            for k in 0..*p {
                s.push(k);
            }
        };
        let serial: Vec<u32> = parts.iter().flat_map(|&p| 0..p).collect();
        for off in [1, -1] {
            let count = |p: &u32| (*p as isize + off * (*p == 3) as isize) as usize;
            let mut got = vec![];
            extend_in_place(&mut got, &parts, count, make);
            assert_eq!(got, serial, "count off by {off}");
        }
    }
}
