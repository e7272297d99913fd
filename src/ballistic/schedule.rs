//! The bisections of a ballistic sweep as one schedule on the engine's threads.
//!
//! Each bisection — a *chain* — needs one run at a time: the midpoint of its bracket, read
//! from the grid and its own runs ([`bracket`]). A free thread takes a needed run nobody is
//! making. When there is none — both chains wait for one run (at the start, when both
//! thresholds lie in one grid interval), or one chain waits while the other is done — the
//! thread makes a *guess*: a run a chain will need next if a run in flight turns out one way,
//! the likeliest first. A chain that comes to need a guess takes its row as if made then; a
//! guess an outcome has ruled out ends at once ([`crate::run::Lend::wanted`]) and is never
//! written. So the tables hold exactly the runs a one-thread sweep makes, whatever the thread
//! count; one thread never guesses (nothing is in flight when the only thread chooses).
//!
//! Why guess rather than lend the idle core to the run in flight: a borrowed core made the
//! default sweep's shared first midpoint 1.47× faster (28.9 s against 42.6 s alone), a right
//! guess saves the whole next run, and a wrong one costs no more than the borrowing would
//! have saved.

use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Condvar, Mutex};
use std::time::Instant;

use super::bracket::{self, Point};
use super::job;
use crate::error::{Error, Result};
use crate::scene::overrides::Override;
pub use crate::sweep::Row;
use crate::sweep::Job;

/// Where the chains' runs are kept: the runs table.
pub trait Book: Send {
    /// The run's outcome `column` (`true` or not), or None when the book does not hold the run.
    /// An error when it holds the run without that column.
    fn outcome(&self, job: &Job, column: &str) -> Result<Option<bool>>;
    /// Keep a run a chain has asked for, on disk before returning: its row when made now, or
    /// None when the book holds it already (the chain's purpose is added to the row's).
    fn keep(&mut self, job: &Job, row: Option<&Row>) -> Result<()>;
    /// Keep a run a chain asked for that failed, with its message, on disk before returning.
    fn keep_failed(&mut self, job: &Job, message: &str) -> Result<()>;
}

/// One bisection.
#[derive(Debug, Clone)]
pub struct Chain {
    /// The overrides its runs share besides the velocity (a packing's `target.seed`).
    pub fixed: Vec<Override>,
    /// The outcome it brackets (`scabbed`, `perforated`).
    pub column: String,
    /// Its runs' purpose (`bisect scabbing`).
    pub purpose: String,
    /// The grid's points and those of its own runs so far (what evolves).
    pub points: Vec<Point>,
    /// Its own runs, in the order it asked for them (what evolves).
    pub runs: Vec<Job>,
    /// The run that failed and stopped it, with the message (what evolves): its bracket stays
    /// as wide as it was.
    pub failed: Option<(Job, String)>,
}

impl Chain {
    /// A chain starting from the grid's points.
    pub fn new(column: &str, purpose: &str, grid: Vec<Point>) -> Chain {
        Chain { fixed: Vec::new(), column: column.into(), purpose: purpose.into(), points: grid, runs: Vec::new(), failed: None }
    }

    /// The same chain with its runs sharing `fixed` overrides.
    pub fn with_fixed(self, fixed: Vec<Override>) -> Chain {
        Chain { fixed, ..self }
    }

    /// Its run at `v_fps`, ft/s.
    pub fn job(&self, v_fps: f64, purpose: &str) -> Job {
        job_with(&self.fixed, v_fps, purpose)
    }
}

/// A run at `v_fps` with the overrides `fixed` before the velocity.
pub fn job_with(fixed: &[Override], v_fps: f64, purpose: &str) -> Job {
    let mut j = job(v_fps, purpose);
    j.overrides.splice(0..0, fixed.iter().cloned());
    j
}

/// A run some chain may still need.
#[derive(Debug, Clone)]
struct Want {
    /// The run (no purpose yet).
    job: Job,
    /// Its velocity, ft/s.
    v_fps: f64,
    /// The chance it is needed.
    p: f64,
}

/// What the schedule did.
#[derive(Debug, Clone, Default)]
pub struct Tally {
    /// Runs made now and kept (needed runs and guesses a chain took).
    pub ran: usize,
    /// Runs a chain found kept already (by the other chain, or an earlier sweep).
    pub skipped: usize,
    /// Guesses made (whether kept or not).
    pub guesses: usize,
    /// Guesses not kept: ruled out while running (ended early) or after.
    pub guesses_lost: usize,
    /// Core time those took, s.
    pub lost_s: f64,
}

/// Make `job` on the calling thread; end it early (`Error::Abandoned`) once the flag is cleared.
pub type Make<'a> = dyn Fn(&Job, &AtomicBool) -> Result<Row> + Sync + 'a;

/// The schedule's state, under one lock (what evolves).
struct State<'b> {
    chains: Vec<Chain>,
    book: &'b mut dyn Book,
    /// Runs made and not yet taken by a chain: the row (or the run's error), and its wall time, s.
    made: HashMap<String, (Result<Row>, f64)>,
    /// Runs in flight: the flag that keeps each going.
    flight: HashMap<String, Arc<AtomicBool>>,
    /// Runs a chain took that failed, by id: the message (each is made once; a rerun tries
    /// again).
    failed: HashMap<String, String>,
    error: Option<Error>,
    done: bool,
    tally: Tally,
}

/// Bisect every chain to `tol_fps` on `threads` threads (the calling one among them), making
/// runs with `make`; returns the chains with their runs, and the tally.
pub fn bisect(chains: Vec<Chain>, book: &mut dyn Book, tol_fps: f64, threads: usize, quiet: bool, make: &Make<'_>) -> Result<(Vec<Chain>, Tally)> {
    let state = Mutex::new(State { chains, book, made: HashMap::new(), flight: HashMap::new(), failed: HashMap::new(), error: None, done: false, tally: Tally::default() });
    let signal = Condvar::new();
    let work = || worker(&state, &signal, tol_fps, quiet, make);
    // Plain threads, not rayon tasks: a rayon worker that waits (polars writing the Parquet
    // table uses its own pool) steals other tasks of its pool, and would start another run
    // inside this one's lock on the table.
    std::thread::scope(|s| {
        for _ in 1..threads.max(1) {
            s.spawn(work);
        }
        work();
    });
    let st = state.into_inner().unwrap_or_else(|e| e.into_inner());
    if let Some(e) = st.error {
        return Err(e);
    }
    if !quiet && st.tally.guesses > 0 {
        let t = &st.tally;
        eprintln!("bisection: {} guesses made, {} kept, {} not needed ({:.1} s of one core)", t.guesses, t.guesses - t.guesses_lost, t.guesses_lost, t.lost_s);
    }
    Ok((st.chains, st.tally))
}

fn worker(state: &Mutex<State<'_>>, signal: &Condvar, tol_fps: f64, quiet: bool, make: &Make<'_>) {
    let lock = || state.lock().unwrap_or_else(|e| e.into_inner());
    let mut st = lock();
    loop {
        if st.done {
            return;
        }
        let wants = match st.take(tol_fps).and_then(|()| st.wants(tol_fps)) {
            Ok(w) => w,
            Err(e) => {
                st.finish(Some(e));
                signal.notify_all();
                return;
            }
        };
        st.rule_out(&wants);
        if wants.is_empty() {
            // Every chain is done.
            st.finish(None);
            signal.notify_all();
            return;
        }
        let Some((id, template, chance)) = st.pick(&wants) else {
            st = signal.wait(st).unwrap_or_else(|e| e.into_inner());
            continue;
        };
        let guess = chance < 1.0;
        let flag = Arc::new(AtomicBool::new(true));
        st.flight.insert(id.clone(), flag.clone());
        st.tally.guesses += usize::from(guess);
        drop(st);
        let t0 = Instant::now();
        let made = make(&Job { purpose: if guess { "guess" } else { "bisect" }.into(), ..template.clone() }, &flag);
        let secs = t0.elapsed().as_secs_f64();
        st = lock();
        st.flight.remove(&id);
        if flag.load(Ordering::SeqCst) {
            if !quiet {
                let what = if guess { format!("guess, p = {chance:.2}") } else { "bisect".into() };
                let outcome = made.as_ref().map_or_else(|e| format!("failed: {e}"), |r| crate::sweep::progress::outcome(r));
                eprintln!("[{what}] {id}: {outcome}  ({secs:.1} s)");
            }
            st.made.insert(id, (made, secs));
        } else if guess {
            // Ruled out by an outcome (or the schedule ended: then nothing is counted on).
            st.tally.guesses_lost += 1;
            st.tally.lost_s += secs;
            if !quiet {
                eprintln!("[guess] {id}: not needed, ended after {secs:.1} s");
            }
        }
        signal.notify_all();
    }
}

impl State<'_> {
    /// The outcome `column` of the run `j` if known: made here or kept in the book.
    fn known(&self, j: &Job, column: &str) -> Result<Option<bool>> {
        match self.made.get(&j.id()) {
            Some((Ok(row), _)) => Ok(row.iter().find(|(k, _)| k == column).map(|(_, x)| x == "true")),
            // A failed run's outcome is not known; the chain that needs it reports the error.
            Some((Err(_), _)) => Ok(None),
            None => self.book.outcome(j, column),
        }
    }

    /// Every chain takes the runs it needs that are made or kept, in order, until it needs one
    /// that is not (or is done). A needed run that failed is kept as failed and stops the chain
    /// (and any other that needs it); the others go on.
    fn take(&mut self, tol_fps: f64) -> Result<()> {
        for c in 0..self.chains.len() {
            loop {
                let chain = &self.chains[c];
                if chain.failed.is_some() {
                    break;
                }
                let Some(v) = bracket::find(&chain.points).next(tol_fps) else { break };
                let j = chain.job(v, &chain.purpose);
                if let Some(message) = self.failed.get(&j.id()).cloned() {
                    self.book.keep_failed(&j, &message)?;
                    self.chains[c].failed = Some((j, message));
                    break;
                }
                match self.made.remove(&j.id()) {
                    Some((Ok(row), _)) => {
                        self.book.keep(&j, Some(&row))?;
                        self.tally.ran += 1;
                    }
                    Some((Err(e), _)) => {
                        let message = e.to_string();
                        self.book.keep_failed(&j, &message)?;
                        self.failed.insert(j.id(), message.clone());
                        self.chains[c].failed = Some((j, message));
                        break;
                    }
                    None if self.book.outcome(&j, &chain.column)?.is_some() => {
                        self.book.keep(&j, None)?;
                        self.tally.skipped += 1;
                    }
                    None => break,
                }
                let hit = self.book.outcome(&j, &chain.column)?.ok_or_else(|| Error::input("sweep", format!("run {} was kept without its row", j.id())))?;
                let chain = &mut self.chains[c];
                chain.points.push(Point { v_fps: v, hit });
                chain.runs.push(j);
            }
        }
        Ok(())
    }

    /// Every run some chain may still need, by id: velocity and the chance it is needed. A
    /// chain's next run has chance 1; each run in flight is taken as even odds either way, and
    /// chains as independent (a run needed by one chain with chance a and by the other with b
    /// is needed with 1 − (1 − a)(1 − b)).
    fn wants(&self, tol_fps: f64) -> Result<HashMap<String, Want>> {
        let mut all: HashMap<String, Want> = HashMap::new();
        for c in self.chains.iter().filter(|c| c.failed.is_none()) {
            let mut mine = HashMap::new();
            self.grow(c, &mut c.points.clone(), 1.0, tol_fps, &mut mine)?;
            for (id, w) in mine {
                let e = all.entry(id).or_insert(Want { p: 0.0, ..w.clone() });
                e.p = 1.0 - (1.0 - e.p) * (1.0 - w.p);
            }
        }
        Ok(all)
    }

    /// The runs one chain may need from `points` on, reached with chance `p` (the branches of a
    /// chain exclude each other: their chances add).
    fn grow(&self, chain: &Chain, points: &mut Vec<Point>, p: f64, tol_fps: f64, out: &mut HashMap<String, Want>) -> Result<()> {
        let Some(v) = bracket::find(points).next(tol_fps) else { return Ok(()) };
        let j = chain.job(v, "");
        let id = j.id();
        let known = self.known(&j, &chain.column)?;
        out.entry(id.clone()).or_insert(Want { job: j, v_fps: v, p: 0.0 }).p += p;
        let branches: &[(bool, f64)] = match known {
            Some(true) => &[(true, 1.0)],
            Some(false) => &[(false, 1.0)],
            None if self.flight.contains_key(&id) => &[(true, 0.5), (false, 0.5)],
            None => &[],
        };
        for &(hit, share) in branches {
            points.push(Point { v_fps: v, hit });
            let grown = self.grow(chain, points, p * share, tol_fps, out);
            points.pop();
            grown?;
        }
        Ok(())
    }

    /// Runs in flight that no chain can need any more are told to end; made ones are dropped.
    fn rule_out(&mut self, wants: &HashMap<String, Want>) {
        for (id, flag) in &self.flight {
            if !wants.contains_key(id) {
                flag.store(false, Ordering::SeqCst);
            }
        }
        let lost: Vec<String> = self.made.keys().filter(|id| !wants.contains_key(*id)).cloned().collect();
        for id in lost {
            let (_, secs) = self.made.remove(&id).expect("listed above");
            self.tally.guesses_lost += 1;
            self.tally.lost_s += secs;
        }
    }

    /// The likeliest needed run nobody is making and nobody has made: id, run, chance. Ties
    /// go to the higher velocity, then the smaller id (any fixed rule keeps the schedule
    /// reproducible; the tables do not depend on it).
    fn pick(&self, wants: &HashMap<String, Want>) -> Option<(String, Job, f64)> {
        wants
            .iter()
            .filter(|(id, _)| !self.flight.contains_key(*id) && !self.made.contains_key(*id) && !self.failed.contains_key(*id))
            // Not held by the book (a run it holds is known to every chain alike).
            .filter(|(_, w)| self.chains.first().is_none_or(|c| matches!(self.book.outcome(&w.job, &c.column), Ok(None))))
            .max_by(|a, b| a.1.p.total_cmp(&b.1.p).then(a.1.v_fps.total_cmp(&b.1.v_fps)).then(b.0.cmp(a.0)))
            .map(|(id, w)| (id.clone(), w.job.clone(), w.p))
    }

    /// End the schedule: every run in flight is told to end; the first error is kept.
    fn finish(&mut self, error: Option<Error>) {
        self.done = true;
        for flag in self.flight.values() {
            flag.store(false, Ordering::SeqCst);
        }
        if self.error.is_none() {
            self.error = error;
        }
    }
}

#[cfg(test)]
mod tests {
    use std::collections::{BTreeMap, BTreeSet};
    use std::time::Duration;

    use super::*;

    /// Thresholds of the made-up scene, ft/s: scabbing, perforation.
    const SCAB: f64 = 571.0;
    const PERF: f64 = 583.0;

    /// A runs table in memory: row and purposes by run id (failed runs: an empty row).
    #[derive(Default)]
    struct Memo(BTreeMap<String, (Row, BTreeSet<String>)>);

    impl Book for Memo {
        fn outcome(&self, job: &Job, column: &str) -> Result<Option<bool>> {
            Ok(self.0.get(&job.id()).filter(|(row, _)| !row.is_empty()).map(|(row, _)| row.iter().any(|(k, x)| k == column && x == "true")))
        }

        fn keep_failed(&mut self, job: &Job, _: &str) -> Result<()> {
            self.0.entry(job.id()).or_insert_with(|| (Row::new(), BTreeSet::new())).1.insert(job.purpose.clone());
            Ok(())
        }

        fn keep(&mut self, job: &Job, row: Option<&Row>) -> Result<()> {
            let e = self.0.entry(job.id()).or_insert_with(|| (row.cloned().expect("a new run comes with its row"), BTreeSet::new()));
            e.1.insert(job.purpose.clone());
            Ok(())
        }
    }

    fn v_of(job: &Job) -> f64 {
        job.overrides[0].value.as_float().or_else(|| job.overrides[0].value.as_integer().map(|i| i as f64)).unwrap()
    }

    fn row(v: f64, scab: f64, perf: f64) -> Row {
        vec![("scabbed".into(), (v >= scab).to_string()), ("perforated".into(), (v >= perf).to_string())]
    }

    fn chains(scab: f64, perf: f64) -> Vec<Chain> {
        let grid = |t: f64| (0..4).map(|k| 500.0 + 50.0 * k as f64).map(|v| Point { v_fps: v, hit: v >= t }).collect();
        vec![Chain::new("scabbed", "bisect scabbing", grid(scab)), Chain::new("perforated", "bisect perforation", grid(perf))]
    }

    /// A run takes `ms`; it looks at its flag every millisecond, as the kernel does every few steps.
    fn slow(ms: u64, scab: f64, perf: f64) -> impl Fn(&Job, &AtomicBool) -> Result<Row> + Sync {
        move |j: &Job, wanted: &AtomicBool| {
            for step in 0..ms {
                if !wanted.load(Ordering::SeqCst) {
                    return Err(Error::Abandoned { step });
                }
                std::thread::sleep(Duration::from_millis(1));
            }
            Ok(row(v_of(j), scab, perf))
        }
    }

    /// The velocities a plain serial bisection of each threshold visits (independent of the
    /// schedule: one chain after the other, one run at a time).
    fn serial(t: f64) -> Vec<f64> {
        let mut p: Vec<Point> = (0..4).map(|k| 500.0 + 50.0 * k as f64).map(|v| Point { v_fps: v, hit: v >= t }).collect();
        let mut seen = Vec::new();
        while let Some(v) = bracket::find(&p).next(5.0) {
            p.push(Point { v_fps: v, hit: v >= t });
            seen.push(v);
        }
        seen
    }

    fn velocities(c: &Chain) -> Vec<f64> {
        c.runs.iter().map(v_of).collect()
    }

    #[test]
    fn one_thread_never_guesses_and_visits_what_a_serial_bisection_visits() {
        let mut book = Memo::default();
        let (done, tally) = bisect(chains(SCAB, PERF), &mut book, 5.0, 1, true, &slow(0, SCAB, PERF)).unwrap();
        assert_eq!(velocities(&done[0]), serial(SCAB));
        assert_eq!(velocities(&done[1]), serial(PERF));
        assert_eq!((tally.guesses, tally.guesses_lost), (0, 0));
        // 575 is both chains' first midpoint: made once, found by the second chain.
        assert_eq!((tally.ran, tally.skipped), (book.0.len(), 1));
        assert_eq!(book.0["projectile.v0_fps=575"].1.len(), 2, "both purposes on the shared run");
    }

    #[test]
    fn more_threads_guess_and_keep_exactly_the_runs_of_one() {
        let mut one = Memo::default();
        let (serial_chains, _) = bisect(chains(SCAB, PERF), &mut one, 5.0, 1, true, &slow(0, SCAB, PERF)).unwrap();
        // The shared first midpoint runs long enough that a second thread surely looks for work
        // while it is in flight, however late a loaded machine starts that thread.
        let make = |j: &Job, wanted: &AtomicBool| slow(if v_of(j) == 575.0 { 300 } else { 40 }, SCAB, PERF)(j, wanted);
        for threads in [2, 3] {
            let mut many = Memo::default();
            let (done, tally) = bisect(chains(SCAB, PERF), &mut many, 5.0, threads, true, &make).unwrap();
            assert_eq!(many.0, one.0, "{threads} threads: the same rows and purposes as one thread");
            assert_eq!(velocities(&done[0]), velocities(&serial_chains[0]));
            assert_eq!(velocities(&done[1]), velocities(&serial_chains[1]));
            // While 575 is made, a free thread guesses its successors; 587.5 (needed unless 575
            // perforates) is the perforation chain's next run here.
            assert!(tally.guesses >= 1 && tally.guesses > tally.guesses_lost, "{threads} threads: {tally:?}");
            assert_eq!(tally.ran + tally.skipped, velocities(&done[0]).len() + velocities(&done[1]).len());
        }
    }

    #[test]
    fn a_guess_ruled_out_ends_at_once_and_is_not_kept() {
        // Both thresholds below 575: the first guess, 587.5, is never needed.
        let (scab, perf) = (560.0, 561.0);
        let ended = AtomicBool::new(false);
        let make = |j: &Job, wanted: &AtomicBool| {
            if j.purpose == "guess" && v_of(j) == 587.5 {
                // Far longer than the rest of the test: it ends early only when told to.
                for step in 0..20_000 {
                    if !wanted.load(Ordering::SeqCst) {
                        ended.store(true, Ordering::SeqCst);
                        return Err(Error::Abandoned { step });
                    }
                    std::thread::sleep(Duration::from_millis(1));
                }
                return Ok(row(587.5, scab, perf));
            }
            slow(40, scab, perf)(j, wanted)
        };
        let mut book = Memo::default();
        let (_, tally) = bisect(chains(scab, perf), &mut book, 5.0, 2, true, &make).unwrap();
        assert!(ended.load(Ordering::SeqCst), "the guess at 587.5 was told to end");
        assert!(tally.guesses_lost >= 1, "{tally:?}");
        assert!(!book.0.contains_key("projectile.v0_fps=587.5"), "a guess not needed is not kept");
    }

    #[test]
    fn a_needed_run_that_fails_is_kept_as_failed_and_stops_the_chains_that_need_it() {
        // 575 is both chains' first midpoint: both stop there, with their grid brackets; the
        // guesses in flight end.
        let make = |j: &Job, wanted: &AtomicBool| {
            if v_of(j) == 575.0 {
                std::thread::sleep(Duration::from_millis(40));
                return Err(Error::input("projectile", "made-up failure"));
            }
            slow(10_000, SCAB, PERF)(j, wanted)
        };
        let mut book = Memo::default();
        let (done, _) = bisect(chains(SCAB, PERF), &mut book, 5.0, 2, true, &make).unwrap();
        for c in &done {
            let (j, message) = c.failed.as_ref().expect("stopped by the failure");
            assert_eq!((v_of(j), message.contains("made-up failure")), (575.0, true), "{message}");
            assert!(c.runs.is_empty());
        }
        assert_eq!(book.0.keys().collect::<Vec<_>>(), ["projectile.v0_fps=575"], "only the failure is kept, once");
        assert!(book.0["projectile.v0_fps=575"].0.is_empty());
    }

    #[test]
    fn a_run_only_one_chain_needs_failing_leaves_the_other_to_finish() {
        // 575 scabs and does not perforate: perforation asks for 587.5 next, scabbing never.
        assert!(!serial(SCAB).contains(&587.5) && serial(PERF).contains(&587.5));
        let make = |j: &Job, wanted: &AtomicBool| if v_of(j) == 587.5 { Err(Error::input("projectile", "made-up failure")) } else { slow(0, SCAB, PERF)(j, wanted) };
        let mut book = Memo::default();
        let (done, _) = bisect(chains(SCAB, PERF), &mut book, 5.0, 1, true, &make).unwrap();
        assert!(done[0].failed.is_none());
        assert_eq!(velocities(&done[0]), serial(SCAB));
        assert_eq!(done[1].failed.as_ref().map(|f| v_of(&f.0)), Some(587.5));
        assert_eq!(velocities(&done[1]), [575.0]);
    }
}
