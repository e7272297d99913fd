//! Lending idle cores to the runs still going. A sweep runs each run on one thread; at the end
//! of the grid, and in a ballistic bisection when no thread has a run to make or guess
//! (`ballistic::schedule`), a thread of the engine sits idle while the last run steps alone.
//! [`Cores`] counts the runs in progress and the grid runs not yet started; a run asks it
//! ([`Lend`]) every few steps and, while a core is spare, steps on a kernel pool of the
//! engine's size (the kernel's results do not depend on the threads it steps on, so a run that
//! switches back and forth gives the same bits).
//!
//! Why a pool of its own and only when no grid run is waiting: a rayon worker that waits for
//! a join steals whatever its pool holds; in the engine's pool that can be a whole run, which
//! would then run inside the waiting run's step and stall it. The kernel pool holds only
//! steps, and the engine's pool holds no run once every grid run has started.

use std::sync::atomic::{AtomicUsize, Ordering};

use crate::error::{Error, Result};
use crate::run::Lend;

/// The engine's count of its cores' work.
pub struct Cores {
    // Configuration: the engine's threads.
    threads: usize,
    // What evolves: runs in progress, and grid runs not yet started.
    busy: AtomicUsize,
    unstarted: AtomicUsize,
    // Built once, on the first sweep of more than one thread.
    pool: std::sync::OnceLock<rayon::ThreadPool>,
}

impl Cores {
    /// For an engine of `threads` threads (0: rayon's default, as the engine's pool has).
    pub fn new(threads: usize) -> Cores {
        let threads = if threads == 0 { rayon::current_num_threads() } else { threads };
        Cores { threads, busy: AtomicUsize::new(0), unstarted: AtomicUsize::new(0), pool: std::sync::OnceLock::new() }
    }

    /// The engine's threads.
    pub fn threads(&self) -> usize {
        self.threads
    }

    /// `n` grid runs are queued (none of them started).
    pub fn queue(&self, n: usize) {
        self.unstarted.store(n, Ordering::SeqCst);
    }

    /// A run starts (a queued one if `queued`); it counts as busy until the guard drops.
    pub fn start(&self, queued: bool) -> Busy<'_> {
        if queued {
            self.unstarted.fetch_sub(1, Ordering::SeqCst);
        }
        self.busy.fetch_add(1, Ordering::SeqCst);
        Busy(self)
    }

    /// Build the kernel pool now (a run asks for it only once a core is spare; an error to
    /// build it is reported before the sweep starts).
    pub fn prepare(&self) -> Result<()> {
        if self.threads > 1 && self.pool.get().is_none() {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(self.threads)
                .thread_name(|k| format!("demsweep-kernel-{k}"))
                .build()
                .map_err(|e| Error::input("--threads", e.to_string()))?;
            let _ = self.pool.set(pool);
        }
        Ok(())
    }
}

impl Lend for Cores {
    fn spare(&self) -> bool {
        self.threads > 1 && self.pool.get().is_some() && self.unstarted.load(Ordering::SeqCst) == 0 && self.busy.load(Ordering::SeqCst) < self.threads
    }

    fn pool(&self) -> &rayon::ThreadPool {
        self.pool.get().expect("spare() is true only once the pool is built")
    }
}

/// One run's view of the cores: theirs to borrow, and whether the run is still wanted (a
/// flag its scheduler clears to end it, [`Lend::wanted`]).
pub struct Wanted<'a> {
    /// The engine's cores.
    pub cores: &'a Cores,
    /// Cleared when nobody needs the run any more.
    pub flag: &'a std::sync::atomic::AtomicBool,
}

impl Lend for Wanted<'_> {
    fn spare(&self) -> bool {
        self.cores.spare()
    }

    fn pool(&self) -> &rayon::ThreadPool {
        self.cores.pool()
    }

    fn wanted(&self) -> bool {
        self.flag.load(Ordering::SeqCst)
    }
}

/// A run in progress (see [`Cores::start`]).
pub struct Busy<'a>(&'a Cores);

impl Drop for Busy<'_> {
    fn drop(&mut self) {
        self.0.busy.fetch_sub(1, Ordering::SeqCst);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_core_is_spare_only_when_no_queued_run_waits_and_fewer_runs_than_threads_go() {
        let c = Cores::new(2);
        c.prepare().unwrap();
        c.queue(2);
        assert!(!c.spare(), "two queued runs");
        let a = c.start(true);
        assert!(!c.spare(), "one run going, one queued: the idle thread will take it");
        let b = c.start(true);
        assert!(!c.spare(), "both threads busy");
        drop(a);
        assert!(c.spare(), "the last run goes alone");
        drop(b);
        let one = Cores::new(1);
        one.prepare().unwrap();
        assert!(!one.spare(), "one thread has nothing to lend");
    }
}
