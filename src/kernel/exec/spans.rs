//! Jobs on the pool in spans, one span per thread: each thread takes the jobs of its own span
//! from the front, in order, and when its span is empty takes what is left of the others from
//! their backs. The thread that calls takes the first span, in both stages of a step on the
//! pool (the contact stage's pieces, the motion stage's chunks of the same elements), so a
//! thread tends to find the elements of its span in its own cache from the stage before; and
//! with the jobs shrinking towards each span's end, what another thread takes first is small,
//! and the threads finish closer together.
//!
//! Spans rather than pieces in list order (which send each piece to either core) or rayon's
//! halving (which idles one core at the end): measured, in the commit that made them.
//!
//! Which thread takes which job never changes a result: the jobs write disjoint data.

use std::sync::Mutex;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

/// The jobs not yet taken of one span, `front..back`, packed in one word so that a thread
/// taking from the front and one taking from the back never both take the last job.
struct Span(AtomicU64);

impl Span {
    fn new(front: usize, back: usize) -> Span {
        Span(AtomicU64::new(((front as u64) << 32) | back as u64))
    }

    /// Takes the job at the front (`back`: false) or at the back.
    fn take(&self, back: bool) -> Option<usize> {
        let mut now = self.0.load(Ordering::Relaxed);
        loop {
            let (f, b) = (now >> 32, now & 0xffff_ffff);
            if f >= b {
                return None;
            }
            let (next, k) = if back { ((f << 32) | (b - 1), b - 1) } else { (((f + 1) << 32) | b, f) };
            match self.0.compare_exchange_weak(now, next, Ordering::Relaxed, Ordering::Relaxed) {
                Ok(_) => return Some(k as usize),
                Err(seen) => now = seen,
            }
        }
    }
}

/// Run `job` on every item of `jobs` on the current pool; span s holds the jobs
/// `starts[s]..starts[s + 1]` (`starts` increasing, from 0 to `jobs.len()`). Returns when
/// all are done.
pub fn run<W: Send>(jobs: Vec<W>, starts: &[usize], job: impl Fn(W) + Sync) {
    assert!(starts.first() == Some(&0) && starts.last() == Some(&jobs.len()), "spans must cover the jobs");
    let spans: Vec<Span> = starts.windows(2).map(|w| Span::new(w[0], w[1])).collect();
    // One lock per job, each taken once by whoever drew its number: never contended.
    let slots: Vec<Mutex<Option<W>>> = jobs.into_iter().map(|w| Mutex::new(Some(w))).collect();
    let go = |k: usize| job(slots[k].lock().expect("a job panicked").take().expect("each job is drawn once"));
    let threads = rayon::current_num_threads().min(spans.len());
    if threads <= 1 {
        return drain(&spans, 0, &go);
    }
    // The calling thread takes the first span; a helper that starts after everything is taken
    // finds nothing and returns at once.
    let next_span = AtomicUsize::new(1);
    rayon::scope(|s| {
        for _ in 1..threads {
            s.spawn(|_| drain(&spans, next_span.fetch_add(1, Ordering::Relaxed), &go));
        }
        drain(&spans, 0, &go);
    });
}

/// Span `mine` from the front, then the others from their backs, the next span first (its
/// thread is the furthest from its back).
fn drain(spans: &[Span], mine: usize, go: &impl Fn(usize)) {
    let n = spans.len();
    for s in (0..n).map(|d| (mine + d) % n) {
        while let Some(k) = spans[s].take(s != mine) {
            go(k);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_job_runs_once_on_any_pool_size() {
        for threads in [1, 2, 3, 8] {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            for starts in [vec![0, 15], vec![0, 7, 15], vec![0, 3, 4, 9, 15], vec![0, 0, 15, 15]] {
                let mut out = vec![0u32; 100];
                pool.install(|| run(out.chunks_mut(7).enumerate().collect(), &starts, |(k, c): (usize, &mut [u32])| c.iter_mut().for_each(|v| *v += k as u32 + 1)));
                for (e, v) in out.iter().enumerate() {
                    assert_eq!(*v, e as u32 / 7 + 1, "{threads} threads, spans {starts:?}: element {e}");
                }
            }
        }
    }

    #[test]
    fn a_span_is_taken_from_its_front_by_its_thread_and_from_its_back_by_the_others() {
        // One thread: its span from the front, then the other from the back.
        let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap();
        let seen = Mutex::new(Vec::new());
        pool.install(|| run((0..10).collect(), &[0, 6, 10], |k: usize| seen.lock().unwrap().push(k)));
        assert_eq!(seen.into_inner().unwrap(), [0, 1, 2, 3, 4, 5, 9, 8, 7, 6]);
        // Two threads: the caller starts at job 0 and takes jobs in increasing order while in
        // its span; every job once.
        let pool = rayon::ThreadPoolBuilder::new().num_threads(2).build().unwrap();
        for _ in 0..20 {
            let seen = Mutex::new(Vec::new());
            let caller = pool.install(|| {
                run((0..200).collect(), &[0, 100, 200], |k: usize| seen.lock().unwrap().push((rayon::current_thread_index(), k)));
                rayon::current_thread_index()
            });
            let seen = seen.into_inner().unwrap();
            let mut all: Vec<usize> = seen.iter().map(|s| s.1).collect();
            all.sort_unstable();
            assert_eq!(all, (0..200).collect::<Vec<_>>());
            let mine: Vec<usize> = seen.iter().filter(|s| s.0 == caller && s.1 < 100).map(|s| s.1).collect();
            assert_eq!(mine.first(), Some(&0), "the caller must start its span");
            assert!(mine.windows(2).all(|w| w[0] < w[1]), "the caller took its span out of order: {mine:?}");
        }
    }
}
