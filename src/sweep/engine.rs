//! Running a set of jobs: each run one rayon task on one thread (the kernel in
//! `Threading::Serial`, so a sweep of N runs on N threads never oversubscribes; the last runs
//! borrow the cores the others left idle, [`super::share`]), every finished
//! run sent over a crossbeam channel to one writer, which adds it to the [`Store`] and rewrites
//! the tables at once. A run that fails is reported and written as a failed row (status and
//! message; a rerun makes it again); the others go on.

use super::job::{Base, Job, Row, run_job};
use super::progress::Progress;
use super::share::{Cores, Wanted};
use super::store::Store;
use crate::error::{Error, Result};

/// The sweep engine: a thread pool and the scene.
pub struct Engine<'a> {
    /// The scene.
    pub base: &'a Base,
    /// No progress display.
    pub quiet: bool,
    /// Its threads (resolved once, see [`Engine::new`]) and what they are doing (runs borrow
    /// the idle ones).
    cores: Cores,
}

/// What a call to [`Engine::run`] did.
#[derive(Debug, Clone, Default)]
pub struct Finished {
    /// Runs made now.
    pub ran: usize,
    /// Runs found done and skipped.
    pub skipped: usize,
    /// Runs that failed: (run id, message).
    pub failed: Vec<(String, String)>,
}

impl<'a> Engine<'a> {
    /// An engine of `threads` threads (0: rayon's default, one per core unless
    /// RAYON_NUM_THREADS says otherwise) for `base`.
    pub fn new(base: &'a Base, threads: usize, quiet: bool) -> Engine<'a> {
        Engine { base, quiet, cores: Cores::new(threads) }
    }

    /// The threads it runs on: `threads`, or rayon's default for 0.
    pub fn thread_count(&self) -> usize {
        self.cores.threads()
    }
}

impl Engine<'_> {
    /// The engine's thread pool.
    pub fn pool(&self) -> Result<rayon::ThreadPool> {
        rayon::ThreadPoolBuilder::new()
            .num_threads(self.thread_count())
            .thread_name(|k| format!("demsweep-run-{k}"))
            .build()
            .map_err(|e| Error::input("--threads", e.to_string()))
    }

    /// Run every job of `jobs` that `store` does not hold yet; `store` is kept on disk as they
    /// finish. Checks every job's overrides before the first run starts.
    pub fn run(&self, jobs: &[Job], store: &mut Store) -> Result<Finished> {
        store.threads = self.thread_count();
        for j in jobs {
            j.check(self.base)?;
        }
        for (build, n, path) in store.set_aside.drain(..) {
            if !self.quiet {
                eprintln!(
                    "{n} runs of another build of demsweep (build {build}; this is {}) set aside in {}: they are made again",
                    crate::provenance::build_id(),
                    path.display()
                );
            }
        }
        let mut seen = std::collections::HashSet::new();
        let todo: Vec<&Job> = jobs.iter().filter(|j| !store.has(j) && seen.insert(j.id())).collect();
        let skipped = jobs.iter().filter(|j| store.has(j)).count();
        let mut progress = Progress::new(todo.len() + skipped, skipped, self.quiet);
        let level = self.base.level();
        let pool = self.pool()?;
        self.cores.prepare()?;
        self.cores.queue(todo.len());
        let mut failed = Vec::new();
        let written: Result<()> = std::thread::scope(|s| {
            let (tx, rx) = crossbeam_channel::unbounded::<(&Job, Result<Row>)>();
            let writer = s.spawn(|| -> Result<()> {
                let mut first_error = None;
                for (job, result) in rx {
                    match result {
                        Ok(row) => {
                            progress.finished(&job.id(), Ok(&row));
                            let saved = store.insert(job, &level, &row).and_then(|_| store.write());
                            if let Err(e) = saved {
                                first_error.get_or_insert(e);
                            }
                        }
                        Err(e) => {
                            progress.finished(&job.id(), Err(e.to_string()));
                            store.insert_failed(job, &level, &e.to_string());
                            if let Err(e) = store.write() {
                                first_error.get_or_insert(e);
                            }
                            failed.push((job.id(), e.to_string()));
                        }
                    }
                }
                progress.finish();
                first_error.map_or(Ok(()), Err)
            });
            pool.install(|| {
                use rayon::prelude::*;
                todo.par_iter().for_each_with(tx, |tx, job| {
                    let r = {
                        let _busy = self.cores.start(true);
                        run_job(self.base, job, Some(&self.cores))
                    };
                    let _ = tx.send((job, r));
                });
            });
            writer.join().expect("the writer thread does not panic")
        });
        written?;
        Ok(Finished { ran: todo.len() - failed.len(), skipped, failed })
    }
}

impl Engine<'_> {
    /// Make one run on the calling thread, borrowing the engine's idle cores, and end it early
    /// ([`Error::Abandoned`]) once `wanted` is cleared; the summary row. The caller
    /// keeps the table (the ballistic bisection's schedule does).
    pub fn run_one(&self, job: &Job, wanted: &std::sync::atomic::AtomicBool) -> Result<Row> {
        job.check(self.base)?;
        self.cores.prepare()?;
        let _busy = self.cores.start(false);
        run_job(self.base, job, Some(&Wanted { cores: &self.cores, flag: wanted }))
    }
}

impl Finished {
    /// An error if any run failed, naming each.
    pub fn check(&self) -> Result<()> {
        if self.failed.is_empty() {
            return Ok(());
        }
        let list: Vec<String> = self.failed.iter().map(|(id, e)| format!("  {id}: {e}")).collect();
        Err(Error::input("sweep", format!("{} run(s) failed (rows with status failed in the table, beside the others; a rerun retries them):\n{}", self.failed.len(), list.join("\n"))))
    }
}
