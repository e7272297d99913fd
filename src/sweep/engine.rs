//! Running a set of jobs: each run one rayon task on one thread (the kernel in
//! `Threading::Serial`, so a sweep of N runs on N threads never oversubscribes; the last runs
//! borrow the cores the others left idle, [`super::share`]), every finished
//! run sent over a crossbeam channel to one writer, which adds it to the [`Store`] and rewrites
//! the tables at once. A run that fails is reported and left out (a rerun tries it again); the
//! others go on.

use super::claims::Claims;
use super::job::{Base, Job, run_job};
use super::progress::Progress;
use super::share::Cores;
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
    /// The runs `run_shared` is making now (one maker per run).
    claims: Claims,
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
        Engine { base, quiet, cores: Cores::new(threads), claims: Claims::default() }
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
        for j in jobs {
            j.check(self.base)?;
        }
        for (build, n, path) in store.set_aside.drain(..) {
            if !self.quiet {
                eprintln!(
                    "{n} runs of another build of demsweep (build {build}; this is {}) set aside in {}: they are made again",
                    super::hash::build_id(),
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
            let (tx, rx) = crossbeam_channel::unbounded::<(&Job, Result<Vec<(String, String)>>)>();
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
    /// Run one job on the calling thread unless `store` holds it or another caller is making it
    /// (then wait for that run: [`Claims`]), then add it to `store` and rewrite the tables (the
    /// store shared by concurrent callers, e.g. two bisections). Returns whether it ran.
    pub fn run_shared(&self, job: &Job, store: &std::sync::Mutex<&mut Store>) -> Result<bool> {
        job.check(self.base)?;
        let mut written = Ok(());
        let claim = self.claims.claim(&job.id(), || {
            let mut s = store.lock().expect("no run panics while holding the table");
            // Written at once: a bisection that finds every run it asks for done makes no
            // insert that would write the table later, and its purpose would be lost on one
            // thread while two threads, interleaving inserts, kept it (regression test
            // `sweep_engine::the_tables_are_the_same_on_one_thread_and_on_two`).
            let has = s.has(job);
            if has && s.add_purpose(job) {
                written = s.write();
            }
            has
        });
        // Held until the row is in the store (dropped after `s` below).
        let Some(_claim) = claim else { return written.map(|()| false) };
        let t0 = std::time::Instant::now();
        self.cores.prepare()?;
        let row = {
            let _busy = self.cores.start(false);
            run_job(self.base, job, Some(&self.cores))
        }
        .map_err(|e| Error::input("sweep", format!("run {} failed: {e}", job.id())))?;
        if !self.quiet {
            eprintln!("[{}] {}: {}  ({:.1} s)", job.purpose, job.id(), super::progress::outcome(&row), t0.elapsed().as_secs_f64());
        }
        let mut s = store.lock().expect("no run panics while holding the table");
        s.insert(job, &self.base.level(), &row)?;
        s.write()?;
        Ok(true)
    }
}

impl Finished {
    /// An error if any run failed, naming each.
    pub fn check(&self) -> Result<()> {
        if self.failed.is_empty() {
            return Ok(());
        }
        let list: Vec<String> = self.failed.iter().map(|(id, e)| format!("  {id}: {e}")).collect();
        Err(Error::input("sweep", format!("{} run(s) failed (the others are in the table; a rerun retries these):\n{}", self.failed.len(), list.join("\n"))))
    }
}
