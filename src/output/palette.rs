//! A 256-colour palette for a frame: median cut over its colour histogram
//! (Heckbert 1982, "Color image quantization for frame buffer display"),
//! always splitting the box whose best cut (the one that leaves the two
//! halves' summed squared error least) lowers the error most.
//!
//! Each GIF frame gets its own palette: one palette for a whole animation
//! whose lighting changes spreads 256 colours too thin (the demo has
//! ~120 000 colours over 100 frames), and the dithering then mixes in
//! far-off colours that show as coloured specks. Sums are integers and
//! sorts total, so the palette is the same on every machine.

/// Colour counts, sorted by colour (`0x00RRGGBB`).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Histogram {
    pub colours: Vec<(u32, u64)>,
}

impl Histogram {
    /// Counts the colours of `pixels` (`0x00RRGGBB`; the top byte is ignored).
    pub fn of_pixels(pixels: &[u32]) -> Histogram {
        let mut v: Vec<u32> = pixels.iter().map(|c| c & 0x00ff_ffff).collect();
        v.sort_unstable();
        let mut colours: Vec<(u32, u64)> = Vec::new();
        for c in v {
            match colours.last_mut() {
                Some((last, n)) if *last == c => *n += 1,
                _ => colours.push((c, 1)),
            }
        }
        Histogram { colours }
    }

    /// Adds `other`'s counts (a merge of two sorted lists).
    pub fn merge(&mut self, other: &Histogram) {
        let a = std::mem::take(&mut self.colours);
        let b = &other.colours;
        let mut out = Vec::with_capacity(a.len().max(b.len()));
        let (mut i, mut j) = (0, 0);
        while i < a.len() || j < b.len() {
            let take_a = j >= b.len() || (i < a.len() && a[i].0 <= b[j].0);
            let take_b = i >= a.len() || (j < b.len() && b[j].0 <= a[i].0);
            match (take_a, take_b) {
                (true, true) => {
                    out.push((a[i].0, a[i].1 + b[j].1));
                    i += 1;
                    j += 1;
                }
                (true, false) => {
                    out.push(a[i]);
                    i += 1;
                }
                _ => {
                    out.push(b[j]);
                    j += 1;
                }
            }
        }
        self.colours = out;
    }
}

/// Up to 256 RGB colours.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Palette {
    pub colours: Vec<[u8; 3]>,
}

impl Palette {
    /// `r,g,b,r,g,b,…` as GIF colour tables want.
    pub fn to_rgb_bytes(&self) -> Vec<u8> {
        self.colours.iter().flatten().copied().collect()
    }
}

fn channels(c: u32) -> [u64; 3] {
    [
        ((c >> 16) & 0xff) as u64,
        ((c >> 8) & 0xff) as u64,
        (c & 0xff) as u64,
    ]
}

/// Count and per-channel sums of a set of histogram entries.
#[derive(Clone, Copy, Default)]
struct Sums {
    n: u64,
    s1: [u64; 3],
    s2: [u64; 3],
}

impl Sums {
    fn add(&mut self, (c, n): (u32, u64)) {
        let ch = channels(c);
        self.n += n;
        for (k, &v) in ch.iter().enumerate() {
            self.s1[k] += n * v;
            self.s2[k] += n * v * v;
        }
    }

    fn minus(&self, o: &Sums) -> Sums {
        let mut r = Sums {
            n: self.n - o.n,
            ..Sums::default()
        };
        for k in 0..3 {
            r.s1[k] = self.s1[k] - o.s1[k];
            r.s2[k] = self.s2[k] - o.s2[k];
        }
        r
    }

    /// Summed squared distance of the entries to their mean.
    fn sse(&self) -> f64 {
        if self.n == 0 {
            return 0.0;
        }
        (0..3)
            .map(|k| self.s2[k] as f64 - (self.s1[k] as f64).powi(2) / self.n as f64)
            .sum()
    }

    fn mean(&self) -> [u8; 3] {
        let n = self.n.max(1);
        // Rounded integer mean; each channel's mean lies in 0..=255.
        [0, 1, 2].map(|k| ((self.s1[k] + n / 2) / n) as u8)
    }
}

struct ColourBox {
    lo: usize,
    hi: usize,
    sums: Sums,
    /// Best split found for this box: (error after − error before, axis, cut).
    split: Option<(f64, usize, usize)>,
}

/// Median cut of `hist` into at most `max_colours` colours (1..=256).
/// With `max_colours` or fewer distinct colours, the palette is exact.
pub fn median_cut(hist: &Histogram, max_colours: usize) -> Palette {
    let max_colours = max_colours.clamp(1, 256);
    if hist.colours.is_empty() {
        return Palette {
            colours: vec![[0, 0, 0]],
        };
    }
    if hist.colours.len() <= max_colours {
        return Palette {
            colours: hist
                .colours
                .iter()
                .map(|&(c, _)| channels(c).map(|v| v as u8))
                .collect(),
        };
    }
    let mut entries = hist.colours.clone();
    let mut whole = Sums::default();
    entries.iter().for_each(|&e| whole.add(e));
    let mut boxes = vec![ColourBox {
        lo: 0,
        hi: entries.len(),
        sums: whole,
        split: None,
    }];
    find_split(&mut entries, &mut boxes[0]);
    while boxes.len() < max_colours {
        // The box whose best split lowers the total error most.
        let mut best: Option<(usize, f64)> = None;
        for (i, b) in boxes.iter().enumerate() {
            if let Some((gain, _, _)) = b.split {
                if best.is_none_or(|(_, g)| gain > g) {
                    best = Some((i, gain));
                }
            }
        }
        let Some((i, _)) = best else { break };
        let (lo, hi) = (boxes[i].lo, boxes[i].hi);
        let (_, axis, cut) = boxes[i].split.expect("chosen boxes have a split");
        sort_axis(&mut entries[lo..hi], axis);
        let mut left = Sums::default();
        entries[lo..cut].iter().for_each(|&e| left.add(e));
        let right = boxes[i].sums.minus(&left);
        let mut a = ColourBox {
            lo,
            hi: cut,
            sums: left,
            split: None,
        };
        let mut b = ColourBox {
            lo: cut,
            hi,
            sums: right,
            split: None,
        };
        find_split(&mut entries, &mut a);
        find_split(&mut entries, &mut b);
        boxes[i] = a;
        boxes.push(b);
    }
    Palette {
        colours: boxes.iter().map(|b| b.sums.mean()).collect(),
    }
}

/// Sorts by one channel, ties by the whole colour (so the order is total).
fn sort_axis(entries: &mut [(u32, u64)], axis: usize) {
    entries.sort_unstable_by_key(|&(c, _)| (channels(c)[axis], c));
}

/// For each axis, the cut that minimises the two halves' summed error;
/// stores the best over all axes as the gain (how much error it removes).
fn find_split(entries: &mut [(u32, u64)], b: &mut ColourBox) {
    b.split = None;
    if b.hi - b.lo < 2 {
        return;
    }
    let before = b.sums.sse();
    let mut best: Option<(f64, usize, usize)> = None;
    for axis in 0..3 {
        let slice = &mut entries[b.lo..b.hi];
        sort_axis(slice, axis);
        let mut left = Sums::default();
        for k in 0..slice.len() - 1 {
            left.add(slice[k]);
            // Only cut between different values of this channel.
            if channels(slice[k].0)[axis] == channels(slice[k + 1].0)[axis] {
                continue;
            }
            let err = left.sse() + b.sums.minus(&left).sse();
            let gain = before - err;
            if best.is_none_or(|(g, _, _)| gain > g) {
                best = Some((gain, axis, b.lo + k + 1));
            }
        }
    }
    b.split = best;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn histogram_counts_and_merges() {
        let h = Histogram::of_pixels(&[3, 1, 3, 0xff00_0003, 2]);
        assert_eq!(h.colours, vec![(1, 1), (2, 1), (3, 3)]);
        let mut m = Histogram::of_pixels(&[2, 5]);
        m.merge(&h);
        assert_eq!(m.colours, vec![(1, 1), (2, 2), (3, 3), (5, 1)]);
    }

    #[test]
    fn few_colours_are_kept_exactly() {
        let h = Histogram::of_pixels(&[0xff0000, 0x00ff00, 0x0000ff, 0xff0000]);
        let p = median_cut(&h, 256);
        assert_eq!(p.colours, vec![[0, 0, 255], [0, 255, 0], [255, 0, 0]]);
        assert_eq!(p.to_rgb_bytes(), vec![0, 0, 255, 0, 255, 0, 255, 0, 0]);
    }

    #[test]
    fn a_grey_ramp_is_cut_into_even_steps() {
        // 256 greys, equally common, into 16 colours: each box should hold
        // 16 consecutive greys, so every grey is within 8 of its colour.
        let px: Vec<u32> = (0..256u32).map(|v| v * 0x010101).collect();
        let p = median_cut(&Histogram::of_pixels(&px), 16);
        assert_eq!(p.colours.len(), 16);
        for v in 0..256i32 {
            let d = p
                .colours
                .iter()
                .map(|c| (c[0] as i32 - v).abs())
                .min()
                .unwrap();
            assert!(d <= 8, "grey {v} is {d} from the palette");
        }
    }

    #[test]
    fn two_clusters_get_their_means() {
        let mut px = vec![0x101010u32; 10];
        px.extend(vec![0x121212u32; 10]);
        px.extend(vec![0xf0f0f0u32; 5]);
        let p = median_cut(&Histogram::of_pixels(&px), 2);
        let mut c = p.colours.clone();
        c.sort();
        assert_eq!(c, vec![[0x11, 0x11, 0x11], [0xf0, 0xf0, 0xf0]]);
    }
}
