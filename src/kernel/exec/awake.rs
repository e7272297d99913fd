//! The pool's other workers kept looking for work while one worker runs a batch of steps.
//!
//! Between the parallel stages of a step (while one thread does the serial parts of a neighbour
//! update, say) an idle rayon worker goes to sleep after a few rounds of
//! looking, and each stage then waits for the system to wake it: 20–50 µs on the level-2
//! penetration event, twice a step. Here each other worker runs a job that looks for work in a
//! loop until the batch returns, so it takes a stage's jobs as soon as they are pushed; its
//! core spins meanwhile, which only a run that has the pool to itself should ask for. Which
//! thread runs a job never changes a result.
//!
//! The gain is within the machine's noise (measured in the commit that made it); the change is
//! bitwise neutral.

use std::sync::atomic::{AtomicBool, Ordering};

/// Runs `batch` on a worker of the current pool (the global one from outside any pool), with
/// every other worker looking for work until it returns.
pub(crate) fn while_running<R: Send>(batch: impl FnOnce() -> R + Send) -> R {
    let stop = AtomicBool::new(false);
    rayon::scope(|s| {
        // Set on the way out, also when `batch` panics: the lookers end, so the scope can.
        let _stop = Stop(&stop);
        let home = rayon::current_thread_index();
        for _ in 1..rayon::current_num_threads() {
            let stop = &stop;
            s.spawn(move |_| look(stop, home));
        }
        batch()
    })
}

struct Stop<'a>(&'a AtomicBool);

impl Drop for Stop<'_> {
    fn drop(&mut self) {
        self.0.store(true, Ordering::Release);
    }
}

thread_local! {
    static LOOKING: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Looks for work until `stop`. A looker that the batch's own worker takes from its queue
/// (while it waits on some other job) returns at once, or the batch would never go on; so does
/// one that a looker takes, on a thread that already looks.
fn look(stop: &AtomicBool, home: Option<usize>) {
    if rayon::current_thread_index() == home || LOOKING.with(|l| l.replace(true)) {
        return;
    }
    while !stop.load(Ordering::Acquire) {
        if rayon::yield_now() != Some(rayon::Yield::Executed) {
            std::hint::spin_loop();
        }
    }
    LOOKING.with(|l| l.set(false));
}

#[cfg(test)]
mod tests {
    use rayon::prelude::*;

    use super::while_running;

    /// The batch's parallel work is all done, on any pool size, from inside the pool and from
    /// outside it, and the call returns (the lookers end).
    #[test]
    fn a_batch_runs_its_parallel_work_and_returns_on_any_pool_size() {
        let batch = || (0..50).map(|r| (0..10_000u64).into_par_iter().map(|x| x * x + r).sum::<u64>()).collect::<Vec<_>>();
        let want: Vec<u64> = (0..50).map(|r| (0..10_000u64).map(|x| x * x + r).sum()).collect();
        for threads in [1, 2, 3, 8] {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            assert_eq!(pool.install(|| while_running(batch)), want, "{threads} threads");
        }
        assert_eq!(while_running(batch), want, "the global pool, from outside it");
    }

    /// A batch that panics ends its lookers too: the panic comes back out, no hang (waited for
    /// on another thread, so that a hang fails the test instead of stalling it).
    #[test]
    fn a_batch_that_panics_lets_the_lookers_end() {
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(2).build().unwrap();
            let r = pool.install(|| std::panic::catch_unwind(|| while_running(|| -> u32 { panic!("the batch failed") })));
            // The pool still works.
            let sum = pool.install(|| (0..100u32).into_par_iter().sum::<u32>());
            tx.send((r.is_err(), sum)).unwrap();
        });
        assert_eq!(rx.recv_timeout(std::time::Duration::from_secs(60)), Ok((true, 4950)), "the call hung or lost the panic");
    }
}
