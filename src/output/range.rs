//! Which frames to render: `--range START:STEP:COUNT` (seconds),
//! `--frames A:B` (scene frames) and `--shard K/N`.
//!
//! Frame `i` of a range is drawn at `START + i·STEP` seconds, computed in
//! f64 and rounded once to f32, so the same `i` always gives the same time
//! whichever shard or thread draws it.

/// Most frames one command may ask for (a typo like `0:0.001:1e9` should
/// fail, not run for a week).
pub const MAX_FRAMES: u64 = 1_000_000;

/// An evenly spaced run of times, in seconds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameRange {
    pub start: f64,
    pub step: f64,
    pub count: u32,
}

impl FrameRange {
    /// Parses `START:STEP:COUNT` (seconds, seconds, frames). STEP must be
    /// positive, COUNT 1..=[`MAX_FRAMES`].
    pub fn parse(s: &str) -> Result<FrameRange, String> {
        let parts: Vec<&str> = s.split(':').collect();
        if parts.len() != 3 {
            return Err(format!(
                "range {s:?} is not START:STEP:COUNT (seconds:seconds:frames, e.g. 0:0.04:50)"
            ));
        }
        let num = |what: &str, v: &str| -> Result<f64, String> {
            let x: f64 = v
                .trim()
                .parse()
                .map_err(|_| format!("range {s:?}: {what} {v:?} is not a number"))?;
            if !x.is_finite() {
                return Err(format!("range {s:?}: {what} must be a finite number"));
            }
            Ok(x)
        };
        let start = num("START", parts[0])?;
        let step = num("STEP", parts[1])?;
        if step <= 0.0 {
            return Err(format!(
                "range {s:?}: STEP must be more than 0 seconds (it is {step})"
            ));
        }
        let count = parse_count(s, parts[2])?;
        FrameRange { start, step, count }.checked(s)
    }

    /// `--frames A:B`: scene frames A, A+1, …, B (inclusive; A and B may be
    /// fractional, B − A is rounded down to whole frames) at `fps`.
    pub fn from_frames(s: &str, fps: f32) -> Result<FrameRange, String> {
        let (a, b) = s
            .split_once(':')
            .ok_or_else(|| format!("frames {s:?} is not A:B (first and last frame, e.g. 0:95)"))?;
        let num = |v: &str| -> Result<f64, String> {
            let x: f64 = v
                .trim()
                .parse()
                .map_err(|_| format!("frames {s:?}: {v:?} is not a number"))?;
            if !x.is_finite() {
                return Err(format!("frames {s:?}: {v:?} is not a finite number"));
            }
            Ok(x)
        };
        let (a, b) = (num(a)?, num(b)?);
        if b < a {
            return Err(format!("frames {s:?}: the last frame is before the first"));
        }
        if !(fps.is_finite() && fps > 0.0) {
            return Err(format!("the scene's fps ({fps}) is not a positive number"));
        }
        let span = (b - a).floor();
        if span + 1.0 > MAX_FRAMES as f64 {
            return Err(format!(
                "frames {s:?}: more than {MAX_FRAMES} frames asked for"
            ));
        }
        let fps = fps as f64;
        FrameRange {
            start: a / fps,
            step: 1.0 / fps,
            count: span as u32 + 1,
        }
        .checked(s)
    }

    fn checked(self, s: &str) -> Result<FrameRange, String> {
        let last = self.start + self.step * (self.count as f64 - 1.0);
        if !last.is_finite() || last.abs() > f32::MAX as f64 {
            return Err(format!("range {s:?}: the last time is out of range"));
        }
        Ok(self)
    }

    /// Time of frame `i` in seconds.
    pub fn time(&self, i: u32) -> f32 {
        (self.start + self.step * i as f64) as f32
    }
}

fn parse_count(s: &str, v: &str) -> Result<u32, String> {
    let n: u64 = v
        .trim()
        .parse()
        .map_err(|_| format!("range {s:?}: COUNT {v:?} is not a whole number of frames"))?;
    if n == 0 || n > MAX_FRAMES {
        return Err(format!(
            "range {s:?}: COUNT must be 1..={MAX_FRAMES} (it is {n})"
        ));
    }
    Ok(n as u32)
}

/// `--shard K/N`: this process renders frame indices `i` with `i mod N = K`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    pub k: u32,
    pub n: u32,
}

impl Default for Shard {
    /// Everything: shard 0 of 1.
    fn default() -> Self {
        Shard { k: 0, n: 1 }
    }
}

impl Shard {
    pub fn parse(s: &str) -> Result<Shard, String> {
        let (k, n) = s
            .split_once('/')
            .ok_or_else(|| format!("shard {s:?} is not K/N (e.g. 0/4: the first of 4 shards)"))?;
        let whole = |v: &str| -> Result<u32, String> {
            v.trim()
                .parse()
                .map_err(|_| format!("shard {s:?}: {v:?} is not a whole number"))
        };
        let (k, n) = (whole(k)?, whole(n)?);
        if n == 0 {
            return Err(format!("shard {s:?}: N must be at least 1"));
        }
        if k >= n {
            return Err(format!(
                "shard {s:?}: K must be 0..={} (shards count from 0)",
                n - 1
            ));
        }
        Ok(Shard { k, n })
    }

    /// The frame indices of `0..count` this shard renders, in order.
    pub fn indices(&self, count: u32) -> Vec<u32> {
        (self.k..count).step_by(self.n as usize).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn range_times_are_start_plus_i_step() {
        let r = FrameRange::parse("0.5:0.25:5").unwrap();
        assert_eq!(r.count, 5);
        assert_eq!(r.time(0), 0.5);
        assert_eq!(r.time(4), 1.5);
        // Computed in f64 then rounded once: 0.1·3 is 0.3 in f32, not 0.3000001.
        let r = FrameRange::parse("0:0.1:10").unwrap();
        assert_eq!(r.time(3), 0.3f32);
    }

    #[test]
    fn bad_ranges_say_what_is_wrong() {
        let e = |s| FrameRange::parse(s).unwrap_err();
        assert!(e("0:1").contains("START:STEP:COUNT"));
        assert!(e("a:1:2").contains("START \"a\""));
        assert!(e("0:0:2").contains("STEP must be more than 0"));
        assert!(e("0:-1:2").contains("STEP must be more than 0"));
        assert!(e("0:1:0").contains("COUNT must be"));
        assert!(e("0:1:2.5").contains("whole number"));
        assert!(e("0:1:99999999").contains("COUNT must be"));
        assert!(e("inf:1:2").contains("finite"));
        assert!(e("0:1e38:1000").contains("out of range"));
    }

    #[test]
    fn frames_are_inclusive_scene_frames() {
        let r = FrameRange::from_frames("24:48", 24.0).unwrap();
        assert_eq!(r.count, 25);
        assert_eq!(r.time(0), 1.0);
        assert_eq!(r.time(24), 2.0);
        assert_eq!(FrameRange::from_frames("3:3", 10.0).unwrap().count, 1);
        assert!(FrameRange::from_frames("5:3", 24.0)
            .unwrap_err()
            .contains("before the first"));
        assert!(FrameRange::from_frames("5", 24.0)
            .unwrap_err()
            .contains("A:B"));
        assert!(FrameRange::from_frames("0:5", 0.0).is_err());
    }

    #[test]
    fn shards_partition_the_indices() {
        let n = 3;
        let mut all: Vec<u32> = (0..n).flat_map(|k| Shard { k, n }.indices(10)).collect();
        all.sort();
        assert_eq!(all, (0..10).collect::<Vec<_>>());
        assert_eq!(Shard { k: 1, n: 3 }.indices(10), vec![1, 4, 7]);
        assert_eq!(Shard::parse("2/5").unwrap(), Shard { k: 2, n: 5 });
        assert!(Shard::parse("3/3").unwrap_err().contains("0..=2"));
        assert!(Shard::parse("0/0").unwrap_err().contains("at least 1"));
        assert!(Shard::parse("1-3").unwrap_err().contains("K/N"));
        assert!(Shard::parse("x/3").is_err());
    }
}
