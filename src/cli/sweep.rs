//! `demsweep sweep SCENE --vary FIELD=START..END[:STEP] … | --table PARAMS.csv`: a scene over a
//! grid or a parameter table, in parallel, into `OUT/runs.csv` and `runs.parquet`.

use std::path::PathBuf;

use crate::error::{Error, Result};
use crate::sweep::job::Base;
use crate::sweep::{Engine, Store, Vary, from_table, grid};

/// Arguments of `demsweep sweep`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Scene file (a kernel or a penetration scene).
    pub scene: PathBuf,
    /// A varied field: `FIELD=START..END[:STEP]` (inclusive) or `FIELD=V1,V2,…`; repeatable (the
    /// grid is every combination, the last field fastest).
    #[arg(long, value_name = "FIELD=RANGE")]
    pub vary: Vec<String>,
    /// A parameter table instead: one column per dotted scene field, one run per row.
    #[arg(long, value_name = "PARAMS.csv", conflicts_with = "vary")]
    pub table: Option<PathBuf>,
    /// Output folder (runs.csv, runs.parquet).
    #[arg(long, default_value = "results/sweep")]
    pub out: PathBuf,
    /// Threads, one run each (0: one per core).
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// What to do with the runs the folder holds already.
    #[command(flatten)]
    pub reuse: super::ReuseArgs,
    /// No progress display.
    #[arg(long)]
    pub quiet: bool,
}

/// Run the sweep.
pub fn run(args: Args) -> Result<()> {
    let started = std::time::SystemTime::now();
    let jobs = match &args.table {
        Some(t) => from_table(t)?,
        None => grid(&args.vary.iter().map(|v| Vary::parse(v)).collect::<Result<Vec<_>>>()?)?,
    };
    let base = Base::load(&args.scene)?;
    let mut store = Store::open(&args.out, &base, args.reuse.reuse())?;
    let engine = Engine::new(&base, args.threads, args.quiet);
    let done = engine.run(&jobs, &mut store)?;
    eprintln!("{} runs made, {} found done; {} in {}", done.ran, done.skipped, store.len(), Store::csv_path(&args.out).display());
    crate::provenance::write_manifest(&args.out, started)?;
    eprintln!("report: {}", crate::report::write(&args.out)?.display());
    done.check().map_err(|e| match e {
        Error::Input { message, .. } => Error::input("sweep", message),
        other => other,
    })
}
