//! A run killed part-way and resumed from its last checkpoint writes the tables of a run that
//! never stopped (the kernel's restart equivalence, tests/restart_equivalence.rs, carried up to
//! the run and the `demsweep run` command).

use std::process::Command;

use demsweep::Error;
use demsweep::cases::cracked_plate::{self, Setup, Study};
use demsweep::run::{self, Checkpointing, RunCheckpoint};
use demsweep::scene::Scene;
use demsweep::simulation::Bodies;
use demsweep::table::Table;

/// The coarse energy-criterion plate: the crack runs during the second half of the run.
fn plate() -> Scene {
    cracked_plate::scene(Study::EnergyClosePacked, 0, true, &Setup::default())
}

/// The summary without the columns that time the run.
fn timeless(summary: &Table) -> Vec<(String, String)> {
    summary
        .header
        .iter()
        .cloned()
        .zip(summary.rows[0].iter().cloned())
        .filter(|(h, _)| h != "wall_s" && h != "element_steps_per_s")
        .collect()
}

/// Run the plate, "killed" right after its `kill_at`-th checkpoint; returns that checkpoint.
fn killed_run(every_steps: u64, kill_at: usize) -> RunCheckpoint {
    let mut saved = Vec::new();
    let mut save = |c: &RunCheckpoint| {
        saved.push(c.to_bytes());
        if saved.len() == kill_at { Err(Error::input("test", "killed")) } else { Ok(()) }
    };
    let options = run::Options { checkpointing: Some(Checkpointing { every_steps, save: &mut save }), ..Default::default() };
    let err = run::run_with(plate().build().unwrap(), options);
    assert!(err.is_err(), "the run was not interrupted");
    RunCheckpoint::from_bytes(saved.last().unwrap()).unwrap()
}

#[test]
fn a_resumed_run_writes_the_tables_of_an_uninterrupted_one() {
    let straight = run::run(plate().build().unwrap(), &mut |_| {}).unwrap();
    let checkpoint = killed_run(5000, 3);
    let resumed = run::run_with(plate().build().unwrap(), run::Options { resume: Some(&checkpoint), ..Default::default() }).unwrap();
    let broken = |r: &run::RunResult<demsweep::kernel::Model>| r.column("bonds_broken").unwrap();
    let at_kill = broken(&straight)[checkpoint.values.len() - 1];
    assert!(at_kill > 0.0 && *broken(&straight).last().unwrap() > at_kill + 20.0, "the kill must fall while the crack runs");
    assert_eq!(resumed.series, straight.series);
    assert_eq!(timeless(&resumed.summary_table()), timeless(&straight.summary_table()));
}

#[test]
fn demsweep_run_resume_continues_a_killed_run_and_removes_its_checkpoint() {
    let dir = std::env::temp_dir().join(format!("demsweep-resume-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scene_path = dir.join("plate.toml");
    std::fs::write(&scene_path, plate().to_toml()).unwrap();
    let name = plate().scene.name;
    let run_dir = |out: &str| dir.join(out).join(&name);
    let demsweep = |out: &str, extra: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_demsweep"))
            .args(["run", "--quiet", "--out"])
            .arg(dir.join(out))
            .args(extra)
            .arg(&scene_path)
            .output()
            .unwrap()
    };
    let tables = |out: &str| {
        let series = Table::read_csv(&run_dir(out).join("series.csv")).unwrap();
        (series, timeless(&Table::read_csv(&run_dir(out).join("summary.csv")).unwrap()))
    };
    assert!(demsweep("straight", &[]).status.success());

    // Checkpointing on: the same tables, and no checkpoint left behind.
    assert!(demsweep("checkpointed", &["--checkpoint-every-steps", "5000"]).status.success());
    assert_eq!(tables("checkpointed"), tables("straight"));
    assert!(!run_dir("checkpointed").join("checkpoint.bin").exists());

    // A killed run's checkpoint where `--resume` looks for it.
    std::fs::create_dir_all(run_dir("resumed")).unwrap();
    std::fs::write(run_dir("resumed").join("checkpoint.bin"), killed_run(5000, 2).to_bytes()).unwrap();
    let out = demsweep("resumed", &["--resume"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(tables("resumed"), tables("straight"));
    assert!(!run_dir("resumed").join("checkpoint.bin").exists());

    // A damaged checkpoint is refused with its path, exit code 2, and left where it is.
    std::fs::create_dir_all(run_dir("damaged")).unwrap();
    std::fs::write(run_dir("damaged").join("checkpoint.bin"), &killed_run(5000, 2).to_bytes()[..1000]).unwrap();
    let out = demsweep("damaged", &["--resume"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("checkpoint.bin") && stderr.contains("truncated"), "{stderr}");
    assert!(run_dir("damaged").join("checkpoint.bin").exists() && !run_dir("damaged").join("series.csv").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Ends the run once `bonds` of the model's `initial` bonds have broken; counts its looks (state
/// it must carry across a resume).
struct BrokenBonds {
    initial: u64,
    bonds: u64,
    looks: u64,
}

impl run::StopRule for BrokenBonds {
    fn every_steps(&self) -> u64 {
        50
    }
    fn check(&mut self, m: &dyn Bodies) -> Option<String> {
        self.looks += 1;
        let mut intact = 0;
        m.each_bond(&mut |_, _| intact += 1);
        (self.initial - intact >= self.bonds).then(|| format!("settled after {} looks", self.looks))
    }
    fn save(&self) -> Vec<u8> {
        self.looks.to_le_bytes().to_vec()
    }
    fn load(&mut self, bytes: &[u8]) -> demsweep::Result<()> {
        self.looks = u64::from_le_bytes(bytes.try_into().map_err(|_| Error::input("stop", "8 bytes expected"))?);
        Ok(())
    }
}

#[test]
fn a_stop_rule_ends_a_run_early_and_a_resumed_run_ends_the_same_way() {
    let mut rule = BrokenBonds { initial: plate_bonds(), bonds: 10, looks: 0 };
    let straight = run::run_with(plate().build().unwrap(), run::Options { stop: Some(&mut rule), ..Default::default() }).unwrap();
    let cap = (plate().scene.duration_s / straight.summary.dt_s).ceil() as u64;
    assert!(straight.summary.steps < cap && straight.summary.bonds_broken >= 10, "{:?}", straight.summary);
    assert!(straight.summary.end_reason.starts_with("settled after"), "{}", straight.summary.end_reason);
    // Killed after its first checkpoint, resumed with a fresh rule: the rule's count comes back.
    let mut saved = Vec::new();
    let mut save = |c: &RunCheckpoint| {
        saved.push(c.to_bytes());
        Err(Error::input("test", "killed"))
    };
    let mut first = BrokenBonds { initial: plate_bonds(), bonds: 10, looks: 0 };
    let options = run::Options { stop: Some(&mut first), checkpointing: Some(Checkpointing { every_steps: 4000, save: &mut save }), ..Default::default() };
    assert!(run::run_with(plate().build().unwrap(), options).is_err());
    let checkpoint = RunCheckpoint::from_bytes(&saved[0]).unwrap();
    let mut again = BrokenBonds { initial: plate_bonds(), bonds: 10, looks: 0 };
    let resumed =
        run::run_with(plate().build().unwrap(), run::Options { resume: Some(&checkpoint), stop: Some(&mut again), ..Default::default() }).unwrap();
    assert_eq!(resumed.series, straight.series);
    assert_eq!(timeless(&resumed.summary_table()), timeless(&straight.summary_table()));
    // Without a rule the scene runs its whole duration.
    let full = run::run(plate().build().unwrap(), &mut |_| {}).unwrap();
    assert_eq!((full.summary.steps, full.summary.end_reason.as_str()), (cap, "duration"));
}

/// The plate's bonds at the start.
fn plate_bonds() -> u64 {
    plate().build().unwrap().model.intact_bonds() as u64
}

/// Never stops; notes the step of each look (from the time, `.1` being the step).
struct Looks(Vec<u64>, f64);

impl run::StopRule for Looks {
    fn every_steps(&self) -> u64 {
        7
    }
    fn check(&mut self, m: &dyn Bodies) -> Option<String> {
        self.0.push((m.time_s() / self.1).round() as u64);
        None
    }
    fn save(&self) -> Vec<u8> {
        Vec::new()
    }
    fn load(&mut self, _: &[u8]) -> demsweep::Result<()> {
        Ok(())
    }
}

#[test]
fn a_run_stepping_in_batches_looks_records_and_checkpoints_at_the_steps_it_would_one_by_one() {
    // run_with steps in batches up to the next step after which something is looked at; each
    // look, record and checkpoint must still come after exactly its step.
    let mut built = plate().build().unwrap();
    let cap = 100;
    built.every_steps = 5;
    built.duration_s = (cap as f64 - 0.5) * built.model.dt_s();
    let mut looks = Looks(Vec::new(), built.model.dt_s());
    let (mut recorded, mut saved) = (Vec::new(), Vec::new());
    let mut observe = |m: &demsweep::kernel::Model| {
        recorded.push(m.steps());
        Ok(())
    };
    let mut save = |c: &RunCheckpoint| {
        saved.push(c.values.len());
        Ok(())
    };
    let options = run::Options {
        stop: Some(&mut looks),
        observe: Some(&mut observe),
        checkpointing: Some(Checkpointing { every_steps: 11, save: &mut save }),
        ..Default::default()
    };
    let r = run::run_with(built, options).unwrap();
    assert_eq!(r.summary.steps, cap);
    assert_eq!(looks.0, (1..=cap / 7).map(|k| 7 * k).collect::<Vec<_>>());
    assert_eq!(recorded, (1..=cap / 5).map(|k| 5 * k).collect::<Vec<_>>());
    // A checkpoint at steps 11, 22, … 99 holds the records made so far (the initial one and one
    // per 5 steps).
    assert_eq!(saved, (1..=(cap - 1) / 11).map(|k| 1 + (11 * k / 5) as usize).collect::<Vec<_>>());
}

/// A run nobody needs any more (a ballistic guess ruled out) ends at the first look at its
/// lender after the flag turns, with `Error::Abandoned` naming the step.
#[test]
fn a_run_no_longer_wanted_ends_at_the_next_look() {
    struct Lender(std::sync::atomic::AtomicU64);
    impl run::Lend for Lender {
        fn spare(&self) -> bool {
            false
        }
        fn pool(&self) -> &rayon::ThreadPool {
            unreachable!("never spare")
        }
        fn wanted(&self) -> bool {
            self.0.fetch_add(1, std::sync::atomic::Ordering::SeqCst) < 3
        }
    }
    let lender = Lender(Default::default());
    let r = run::run_with(plate().build().unwrap(), run::Options { lend: Some(&lender), ..Default::default() });
    assert_eq!(r.err(), Some(Error::Abandoned { step: 3 * run::LEND_POLL_STEPS }));
}
