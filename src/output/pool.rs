//! Running one job per frame on a fixed number of threads and handing the
//! results on in frame order (GIF frames must be written in order; PNG
//! sequences just report in order). Workers may run at most `window` frames
//! ahead of the consumer, so memory stays bounded however long the range.

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{mpsc, Condvar, Mutex};

/// Calls `work` on every item on `workers` threads, then `consume(i, result)`
/// on this thread for i = 0, 1, 2, … in order. The first error from
/// `consume` stops the workers (frames in flight finish) and is returned.
pub fn ordered_map<T, R>(
    items: &[T],
    workers: usize,
    window: usize,
    work: impl Fn(&T) -> R + Sync,
    mut consume: impl FnMut(usize, R) -> Result<(), String>,
) -> Result<(), String>
where
    T: Sync,
    R: Send,
{
    let n = items.len();
    let workers = workers.clamp(1, n.max(1));
    let window = window.max(workers);
    let next = AtomicUsize::new(0);
    let stop = AtomicBool::new(false);
    // How many results the consumer has taken.
    let gate = (Mutex::new(0usize), Condvar::new());
    std::thread::scope(|s| {
        let (tx, rx) = mpsc::channel::<(usize, R)>();
        for _ in 0..workers {
            let tx = tx.clone();
            let (next, stop, gate, work) = (&next, &stop, &gate, &work);
            s.spawn(move || loop {
                let i = next.fetch_add(1, Ordering::SeqCst);
                if i >= n || stop.load(Ordering::SeqCst) {
                    break;
                }
                {
                    // A poisoned lock means the consumer panicked; stop.
                    let Ok(mut taken) = gate.0.lock() else { break };
                    while i >= *taken + window && !stop.load(Ordering::SeqCst) {
                        match gate.1.wait(taken) {
                            Ok(t) => taken = t,
                            Err(_) => return,
                        }
                    }
                }
                if stop.load(Ordering::SeqCst) {
                    break;
                }
                if tx.send((i, work(&items[i]))).is_err() {
                    break;
                }
            });
        }
        drop(tx);
        let mut pending: BTreeMap<usize, R> = BTreeMap::new();
        let mut want = 0usize;
        let mut result = Ok(());
        for (i, r) in rx {
            pending.insert(i, r);
            while let Some(r) = pending.remove(&want) {
                if result.is_ok() {
                    if let Err(e) = consume(want, r) {
                        result = Err(e);
                        stop.store(true, Ordering::SeqCst);
                    }
                }
                want += 1;
                if let Ok(mut taken) = gate.0.lock() {
                    *taken = want;
                }
                gate.1.notify_all();
            }
        }
        result
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_arrive_in_order() {
        let items: Vec<u32> = (0..50).collect();
        let mut seen = Vec::new();
        ordered_map(
            &items,
            4,
            3,
            |&x| {
                // Later items finish first.
                std::thread::sleep(std::time::Duration::from_micros(((50 - x) * 20) as u64));
                x * 2
            },
            |i, r| {
                seen.push((i, r));
                Ok(())
            },
        )
        .unwrap();
        let want: Vec<(usize, u32)> = (0..50).map(|i| (i as usize, i * 2)).collect();
        assert_eq!(seen, want);
    }

    #[test]
    fn a_consumer_error_stops_the_run() {
        let items: Vec<u32> = (0..1000).collect();
        let done = AtomicUsize::new(0);
        let r = ordered_map(
            &items,
            2,
            4,
            |_| {
                done.fetch_add(1, Ordering::SeqCst);
            },
            |i, _| {
                if i == 3 {
                    Err("disk full".into())
                } else {
                    Ok(())
                }
            },
        );
        assert_eq!(r, Err("disk full".to_string()));
        // At most the window past the failing frame was started.
        assert!(done.load(Ordering::SeqCst) < 20);
    }
}
