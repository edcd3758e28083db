//! Appending what parts of a list make, in order and in parallel, each
//! part writing straight into its place at the end of a `Vec` (two
//! `Vec`s side by side: an item and a small summary of it).
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

/// Where a part's items and their side items go: its slots at the end
/// of the lists, or (after a miscount) the ends of the lists themselves.
pub enum Sink<'a, T, U> {
    Slots {
        slots: (&'a mut [MaybeUninit<T>], &'a mut [MaybeUninit<U>]),
        /// Items pushed so far (may pass the slots: a miscount).
        n: usize,
    },
    Lists(&'a mut Vec<T>, &'a mut Vec<U>),
}

impl<T, U> Sink<'_, T, U> {
    /// Pushes `item` and its `side` item (the tests' way to push).
    #[cfg(test)]
    pub fn push(&mut self, item: T, side: U) {
        // SAFETY: the item is written whole.
        unsafe {
            self.push_with(|slot| {
                slot.write(item);
                side
            })
        }
    }

    /// Pushes the item `write` writes into its slot, and the side item it
    /// returns. Why: an item made on the stack and then
    /// pushed is copied, and a copy by 64-byte loads of what narrower
    /// stores have just written stalls on every load (store forwarding
    /// fails); for 248-byte triangles that was 13 % of a 100k-triangle
    /// frame on Sapphire Rapids, all of it in `memcpy`.
    ///
    /// # Safety
    /// `write` must initialise every field of the item it is given.
    #[inline(always)]
    pub unsafe fn push_with(&mut self, write: impl FnOnce(&mut MaybeUninit<T>) -> U) {
        match self {
            Sink::Slots { slots, n } => {
                if let Some(ahead) = slots.0.get(*n + AHEAD) {
                    prefetch_write(ahead);
                }
                if let (Some(a), Some(b)) = (slots.0.get_mut(*n), slots.1.get_mut(*n)) {
                    b.write(write(a));
                } else {
                    // A miscount: the item is not kept (see `extend_in_place`).
                    write(&mut MaybeUninit::uninit());
                }
                *n += 1;
            }
            Sink::Lists(items, sides) => {
                let mut item = MaybeUninit::uninit();
                let side = write(&mut item);
                // SAFETY: `write` initialised the item (this function's
                // contract).
                items.push(unsafe { item.assume_init() });
                sides.push(side);
            }
        }
    }
}

/// How many slots ahead of the one being written [`prefetch_write`]
/// claims: about 2 KB of 248-byte triangles, a few hundred cycles of
/// set-up.
const AHEAD: usize = 8;

/// Asks the CPU to own every cache line of `slot` before it is written
/// (x86-64 `prefetchw`, a hint: it changes no value; a no-op on CPUs
/// without it and elsewhere). Why: set-up writes its triangles
/// sequentially into lines no cache holds, and each store waits for its
/// line's ownership; the stores of a few triangles fill the store buffer
/// and set-up stalls there (a quarter of its write closure's time in a
/// profile of the 100k-triangle frame).
#[inline(always)]
fn prefetch_write<T>(slot: &MaybeUninit<T>) {
    #[cfg(target_arch = "x86_64")]
    {
        let at = slot.as_ptr().cast::<u8>();
        let size = std::mem::size_of::<T>();
        // Every 64-byte line from the first byte, and the last byte's
        // (a slot need not start on a line).
        let lines = (0..size).step_by(64).chain((size > 0).then(|| size - 1));
        for off in lines {
            // SAFETY: `prefetchw` reads and writes nothing the program
            // sees and never faults; the address is inside `slot`.
            unsafe {
                std::arch::asm!(
                    "prefetchw [{0}]",
                    in(reg) at.wrapping_add(off),
                    options(nostack, preserves_flags, readonly)
                )
            };
        }
    }
}

/// The next `counts[i]` spare slots of `list` for each part `i`, in order
/// (reserved first).
fn split_spare<'a, T>(list: &'a mut Vec<T>, counts: &[usize]) -> Vec<&'a mut [MaybeUninit<T>]> {
    list.reserve(counts.iter().sum());
    let mut rest = list.spare_capacity_mut();
    let mut out = Vec::with_capacity(counts.len());
    for &c in counts {
        let (here, after) = std::mem::take(&mut rest).split_at_mut(c);
        out.push(here);
        rest = after;
    }
    out
}

/// Appends to `items` what each of `parts` makes, in the parts' order,
/// and to `sides` the side item pushed with each: `count(part)` must say
/// how many `make(part, sink)` pushes. Parts run in parallel, each into
/// its own slots. Should a count be wrong (a bug, not bad input), nothing
/// written in place is kept and the parts are made again one after the
/// other, straight onto the lists: the same lists, only slower.
pub fn extend_in_place<P, T, U>(
    (items, sides): (&mut Vec<T>, &mut Vec<U>),
    parts: &[P],
    count: impl Fn(&P) -> usize + Sync,
    make: impl Fn(&P, &mut Sink<T, U>) + Sync,
) where
    P: Sync,
    T: Copy + Send,
    U: Copy + Send,
{
    let counts: Vec<usize> = parts.par_iter().map(&count).collect();
    let total: usize = counts.iter().sum();
    let (old_items, old_sides) = (items.len(), sides.len());
    let mut sinks: Vec<Sink<T, U>> = split_spare(items, &counts)
        .into_iter()
        .zip(split_spare(sides, &counts))
        .map(|slots| Sink::Slots { slots, n: 0 })
        .collect();
    let exact = sinks
        .par_iter_mut()
        .zip(parts.par_iter())
        .all(|(sink, part)| {
            make(part, sink);
            matches!(sink, Sink::Slots { slots, n } if *n == slots.0.len())
        });
    if exact {
        // SAFETY: both lists reserved `total` slots after their old
        // length, split into one run per part of its count's length (the
        // same for both), and each part pushed exactly that many pairs,
        // each into the next slot of both runs: every slot is written.
        unsafe {
            items.set_len(old_items + total);
            sides.set_len(old_sides + total);
        }
        return;
    }
    let mut sink = Sink::Lists(items, sides);
    for part in parts {
        make(part, &mut sink);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Parts make 0 to 6 items each (the part's number, repeated, with
    /// its index, and a side item from the index); appended in place
    /// they are the serial lists, after items already there (the side
    /// list starting empty), whatever the thread count.
    #[test]
    fn in_place_is_the_serial_list() {
        let parts: Vec<u32> = (0..500).map(|i| (i * 7919) % 7).collect();
        let make = |p: &u32, s: &mut Sink<(u32, u32), u32>| {
            for k in 0..*p {
                s.push((*p, k), k * 3);
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
            let (mut got, mut sides) = (vec![(9, 9)], vec![]);
            let lists = (&mut got, &mut sides);
            pool.install(|| extend_in_place(lists, &parts, |p| *p as usize, make));
            assert_eq!(got, serial, "{threads} threads");
            let serial_sides: Vec<u32> = serial[1..].iter().map(|p| p.1 * 3).collect();
            assert_eq!(sides, serial_sides, "{threads} threads");
        }
    }

    /// A count that is wrong, too high or too low, still gives the
    /// serial list (made again one part after the other).
    #[test]
    fn a_wrong_count_still_gives_the_serial_list() {
        let parts: Vec<u32> = (0..100).map(|i| i % 5).collect();
        let make = |p: &u32, s: &mut Sink<u32, ()>| {
            for k in 0..*p {
                s.push(k, ());
            }
        };
        let serial: Vec<u32> = parts.iter().flat_map(|&p| 0..p).collect();
        for off in [1, -1] {
            let count = |p: &u32| (*p as isize + off * (*p == 3) as isize) as usize;
            let (mut got, mut sides) = (vec![], vec![]);
            extend_in_place((&mut got, &mut sides), &parts, count, make);
            assert_eq!(got, serial, "count off by {off}");
            assert_eq!(sides.len(), serial.len());
        }
    }
}
