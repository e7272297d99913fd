//! `demsweep calibrate --v0 500 --depth-in 5 [--scene FILE] [--out FILE]`: the source's one
//! calibration factor, written into a calibrated copy of the scene.

use std::path::PathBuf;

use crate::calibrate::{Target, Trial, calibrate, calibrated_text};
use crate::error::{Error, Result};
use crate::scene_file::SceneFile;

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
    /// Packings whose mean depth is calibrated (an irregular target: its seed and the ones
    /// after it).
    #[arg(long, default_value_t = 3)]
    pub packings: u32,
    /// Where to write the calibrated scene (default: `<scene stem>_calibrated.toml` beside it).
    #[arg(long)]
    pub out: Option<PathBuf>,
}

/// Calibrate and write.
pub fn run(args: Args) -> Result<()> {
    let scene = match crate::scene_file::load(&args.scene, &[])? {
        SceneFile::Penetration(p) => p,
        SceneFile::Kernel(_) | SceneFile::Kernel3(_) | SceneFile::Rockfill(_) => return Err(Error::input("--scene", format!("{} is not a penetration scene ([penetration])", args.scene.display()))),
    };
    let out = args.out.clone().unwrap_or_else(|| {
        let stem = args.scene.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        args.scene.with_file_name(format!("{stem}_calibrated.toml"))
    });
    let target = Target { v0_fps: args.v0_fps, depth_in: args.depth_in, tolerance_in: args.tol_in, packings: args.packings, ..Target::seed() };
    let mut each = |t: &Trial| {
        let depths: Vec<String> = t.rows.iter().map(|r| format!("{:.3}", r.outcome.depth_in)).collect();
        let wall: f64 = t.rows.iter().map(|r| r.run.wall_s).sum();
        eprintln!("factor {:<12.6} mean depth {:.3} in (packings: {} in; {:.1} s of runs)", t.factor, t.mean_depth_in, depths.join(", "), wall);
    };
    let c = calibrate(&scene, &target, &mut each)?;
    let t = &c.trial;
    let seeds = t.rows.len() as u64;
    let meaning = meaning(&scene, c.factor);
    let comment = format!(
        "Calibrated by: demsweep calibrate --v0 {} --depth-in {} --tol-in {} --packings {} --scene {}\n  strength_factor {} gives a mean depth of {:.3} in at {} ft/s over {} packing(s) (seeds {}..={}: {} in), after {} factors{}.\n  {meaning}.",
        args.v0_fps,
        args.depth_in,
        args.tol_in,
        args.packings,
        args.scene.display(),
        c.factor,
        t.mean_depth_in,
        args.v0_fps,
        seeds,
        scene.target.seed,
        scene.target.seed + seeds - 1,
        t.rows.iter().map(|r| format!("{:.3}", r.outcome.depth_in)).collect::<Vec<_>>().join(" / "),
        c.runs.len(),
        if c.converged { "" } else { "; NOT within the tolerance (the closest factor)" }
    );
    let text = std::fs::read_to_string(&args.scene).map_err(|e| Error::io(&args.scene, e))?;
    let written = calibrated_text(&text, c.factor, &comment);
    // The written scene must read back as the scene that was calibrated.
    match crate::scene_file::load_text(&written, &out, &[])? {
        SceneFile::Penetration(p) if p.concrete.strength_factor == c.factor => {}
        _ => return Err(Error::input("calibrate", "the calibrated scene does not read back with its factor")),
    }
    crate::table::write_atomic(&out, written.as_bytes())?;
    println!("strength_factor = {} (mean depth {:.3} in at {} ft/s); {meaning}; written {}", c.factor, t.mean_depth_in, args.v0_fps, out.display());
    if !c.converged {
        return Err(Error::input("calibrate", format!("closest mean depth {:.3} in is outside ±{} in of {} in", t.mean_depth_in, args.tol_in, args.depth_in)));
    }
    Ok(())
}

/// What the factor means: the effective static tensile strength and toughness it gives the
/// concrete, beside f'c.
fn meaning(scene: &crate::penetration::scene::PenetrationScene, factor: f64) -> String {
    let c = &scene.concrete;
    let sigma = factor * c.tensile_strength_psi;
    format!(
        "Effective static tensile strength {:.0} psi ({:.2} f'c), fracture toughness {:.0} psi·√in ({})",
        sigma,
        sigma / c.compressive_strength_psi,
        factor * c.fracture_toughness_psi_sqrt_in,
        if scene.penetration.dim == 3 { "3D slab".to_string() } else { format!("mapping {}", scene.mapping.rule.name()) }
    )
}
