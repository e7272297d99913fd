//! `demsweep report DIR`: write (or write again) an output folder's `report.html`.

use std::path::PathBuf;

use clap::Parser;

use crate::error::Result;

/// Arguments.
#[derive(Debug, Parser)]
pub struct Args {
    /// An output folder of `ballistic`, `sweep`, `merge` or `converge` (e.g. results/ballistic).
    pub dir: PathBuf,
    /// Draw the pictures too: make again the first packing's first scabbing and first
    /// perforation runs of a ballistic folder (`DIR/pictures/`).
    #[arg(long)]
    pub pictures: bool,
}

/// Write the page and say where.
pub fn run(args: Args) -> Result<()> {
    if args.pictures {
        let runs = crate::table::Table::read_csv(&crate::sweep::store::Store::csv_path(&args.dir))?;
        let sweep = std::fs::read_to_string(args.dir.join("sweep.toml")).map_err(|e| crate::error::Error::io(args.dir.join("sweep.toml"), e))?;
        let scene = crate::report::scene_named(&sweep).ok_or_else(|| crate::error::Error::input("sweep.toml", "names no scene file"))?;
        for p in crate::ballistic::pictures::draw(&scene, &runs, &args.dir)? {
            println!("picture: {}", p.display());
        }
    }
    let path = crate::report::write(&args.dir)?;
    println!("report: {}", path.display());
    Ok(())
}
