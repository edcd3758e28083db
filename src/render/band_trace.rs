//! When each band of a frame was drawn, and by which thread — recorded only
//! while `animed bench --only split` asks for it — so the bench can show
//! whether the threads finish a frame together or one waits for the other
//! (issue 15: the two-thread shading rate swung by ~20 % between runs).
//! Off, the drawing loop pays one relaxed load per band and frame.
//!
//! `coarse` brings back rayon's default split of the band list (a few runs
//! of consecutive bands per thread) so the bench can time the old split
//! beside the new one in one run.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// One band of one traced frame.
#[derive(Clone, Copy, Debug)]
pub struct Band {
    /// Rayon worker index that drew it.
    pub thread: usize,
    /// Start and end, from the start of the frame's drawing.
    pub start: Duration,
    pub end: Duration,
}

static ON: AtomicBool = AtomicBool::new(false);
static COARSE: AtomicBool = AtomicBool::new(false);
static FRAMES: Mutex<Vec<Vec<Band>>> = Mutex::new(Vec::new());

/// Starts (or stops) recording; starting forgets earlier frames.
/// `coarse` picks rayon's default split for the frames drawn meanwhile.
pub fn record(on: bool, coarse: bool) {
    lock().clear();
    COARSE.store(on && coarse, Ordering::Relaxed);
    ON.store(on, Ordering::Relaxed);
}

/// The frames recorded since [`record`]`(true, _)`, each its bands.
pub fn take() -> Vec<Vec<Band>> {
    std::mem::take(&mut *lock())
}

/// Whether the frames being drawn use rayon's default split.
pub(super) fn coarse() -> bool {
    COARSE.load(Ordering::Relaxed)
}

/// The clock of a frame about to be drawn, when recording.
pub(super) fn frame_start() -> Option<Instant> {
    ON.load(Ordering::Relaxed).then(|| {
        lock().push(Vec::new());
        Instant::now()
    })
}

/// Notes a band of the frame whose clock is `frame`, drawn from `start`
/// until now.
pub(super) fn band_done(frame: Instant, start: Instant) {
    let band = Band {
        thread: rayon::current_thread_index().unwrap_or(usize::MAX),
        start: start - frame,
        end: frame.elapsed(),
    };
    if let Some(f) = lock().last_mut() {
        f.push(band);
    }
}

fn lock() -> std::sync::MutexGuard<'static, Vec<Vec<Band>>> {
    // A poisoned lock only means a traced render panicked.
    FRAMES.lock().unwrap_or_else(|e| e.into_inner())
}

/// What the bands of one frame say about the split.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Split {
    /// From the start of drawing to the end of the last band.
    pub wall: Duration,
    /// Summed band time of the busiest and the least busy thread.
    pub busiest: Duration,
    pub idlest: Duration,
    /// How long the thread that finished its last band first waited for
    /// the other(s) at the end of the frame.
    pub tail: Duration,
    /// Bands drawn by the busiest and by the least busy thread.
    pub bands: (usize, usize),
}

/// Summarises one frame's bands (`None` for an empty frame).
pub fn split(bands: &[Band]) -> Option<Split> {
    let mut threads: Vec<(usize, Duration, Duration, usize)> = Vec::new();
    for b in bands {
        match threads.iter_mut().find(|t| t.0 == b.thread) {
            Some(t) => {
                t.1 += b.end - b.start;
                t.2 = t.2.max(b.end);
                t.3 += 1;
            }
            None => threads.push((b.thread, b.end - b.start, b.end, 1)),
        }
    }
    let wall = threads.iter().map(|t| t.2).max()?;
    let first_done = threads.iter().map(|t| t.2).min()?;
    let busiest = threads.iter().max_by_key(|t| t.1)?;
    let idlest = threads.iter().min_by_key(|t| t.1)?;
    Some(Split {
        wall,
        busiest: busiest.1,
        idlest: idlest.1,
        tail: wall - first_done,
        bands: (busiest.3, idlest.3),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn split_finds_the_waiting_thread() {
        let ms = Duration::from_millis;
        let b = |thread, s, e| Band {
            thread,
            start: ms(s),
            end: ms(e),
        };
        let s = split(&[b(0, 0, 4), b(1, 1, 3), b(0, 4, 6), b(1, 3, 4)]).unwrap();
        assert_eq!(s.wall, ms(6));
        assert_eq!((s.busiest, s.idlest), (ms(6), ms(3)));
        assert_eq!(s.tail, ms(2));
        assert_eq!(s.bands, (2, 2));
        assert_eq!(split(&[]), None);
    }
}
