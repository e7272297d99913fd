//! `demsweep calibrate --v0 500 --depth-in 5 [--scene FILE] [--out FILE]`: the source's one
//! calibration factor, written into a calibrated copy of the scene.

use std::path::PathBuf;

use crate::calibrate::{Target, calibrate, calibrated_text};
use crate::error::{Error, Result};
use crate::scene::SceneFile;

/// Arguments of `demsweep calibrate`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Reference impact speed, ft/s.
    #[arg(long = "v0", default_value_t = 500.0)]
    pub v0_fps: f64,
    /// Penetration depth wanted at the reference speed, in.
    #[arg(long = "depth-in", default_value_t = 5.0)]
    pub depth_in: f64,
    /// Accepted |depth − wanted|, in.
    #[arg(long = "tol-in", default_value_t = 0.25)]
    pub tol_in: f64,
    /// The penetration scene to calibrate.
    #[arg(long, default_value = "sweeps/penetration_base.toml")]
    pub scene: PathBuf,
    /// Where to write the calibrated scene (default: `<scene stem>_calibrated.toml` beside it).
    #[arg(long)]
    pub out: Option<PathBuf>,
}

/// Calibrate and write.
pub fn run(args: Args) -> Result<()> {
    let scene = match crate::scene::load(&args.scene, &[])? {
        SceneFile::Penetration(p) => p,
        SceneFile::Kernel(_) => return Err(Error::input("--scene", format!("{} is not a penetration scene ([penetration])", args.scene.display()))),
    };
    let out = args.out.clone().unwrap_or_else(|| {
        let stem = args.scene.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        args.scene.with_file_name(format!("{stem}_calibrated.toml"))
    });
    let target = Target { v0_fps: args.v0_fps, depth_in: args.depth_in, tolerance_in: args.tol_in, ..Target::seed() };
    let mut each = |f: f64, r: &crate::penetration::Row| {
        let o = &r.outcome;
        eprintln!(
            "factor {f:<12.6} depth {:.3} in, scabbed {}, perforated {}, {} ({} steps, {:.1} s)",
            o.depth_in, o.scabbed, o.perforated, r.run.end_reason, r.run.steps, r.run.wall_s
        );
    };
    let c = calibrate(&scene, &target, &mut each)?;
    let o = &c.row.outcome;
    let comment = format!(
        "Calibrated by: demsweep calibrate --v0 {} --depth-in {} --tol-in {} --scene {}\n  strength_factor {} gives {:.3} in at {} ft/s (scabbed: {}, perforated: {}), after {} runs{}.",
        args.v0_fps,
        args.depth_in,
        args.tol_in,
        args.scene.display(),
        c.factor,
        o.depth_in,
        args.v0_fps,
        o.scabbed,
        o.perforated,
        c.runs.len(),
        if c.converged { "" } else { "; NOT within the tolerance (the closest run)" }
    );
    let text = std::fs::read_to_string(&args.scene).map_err(|e| Error::io(&args.scene, e))?;
    let written = calibrated_text(&text, c.factor, &comment);
    // The written scene must read back as the scene that was calibrated.
    match crate::scene::load_text(&written, &out, &[])? {
        SceneFile::Penetration(p) if p.concrete.strength_factor == c.factor => {}
        _ => return Err(Error::input("calibrate", "the calibrated scene does not read back with its factor")),
    }
    crate::table::write_atomic(&out, written.as_bytes())?;
    println!("strength_factor = {} (depth {:.3} in at {} ft/s); written {}", c.factor, o.depth_in, args.v0_fps, out.display());
    if !c.converged {
        return Err(Error::input("calibrate", format!("closest depth {:.3} in is outside ±{} in of {} in", o.depth_in, args.tol_in, args.depth_in)));
    }
    Ok(())
}
