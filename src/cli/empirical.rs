//! `demsweep empirical`: the classical formulas for the scenario on the command line, as a
//! velocity sweep, as thresholds (scabbing velocity and ballistic limit), and as a plot.
//! Defaults are the source report's scenario (SPEC §4; the aggregate size is an assumption).

use std::io::Write;
use std::path::PathBuf;

use crate::empirical::{Missile, Nose, Target, plot, table};
use crate::error::{Error, Result};

use crate::sweep::range;

/// Output format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Aligned text for reading.
    Table,
    /// CSV for tools.
    Csv,
}

/// Arguments of `demsweep empirical`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Missile weight, lb.
    #[arg(long, default_value_t = 15.0, allow_negative_numbers = true)]
    pub weight_lb: f64,
    /// Missile diameter, in.
    #[arg(long, default_value_t = 3.5, allow_negative_numbers = true)]
    pub diameter_in: f64,
    /// Missile Young's modulus, psi (Kar; mild steel 29e6).
    #[arg(long, default_value_t = crate::empirical::MILD_STEEL_MODULUS_PSI, allow_negative_numbers = true)]
    pub modulus_psi: f64,
    /// Nose shape: flat, blunt, spherical, very-sharp.
    #[arg(long, default_value = "spherical")]
    pub nose: String,
    /// Concrete compressive strength f'c, psi.
    #[arg(long, default_value_t = 3000.0, allow_negative_numbers = true)]
    pub fc_psi: f64,
    /// Concrete tensile strength f_t, psi (Hughes).
    #[arg(long, default_value_t = 300.0, allow_negative_numbers = true)]
    pub ft_psi: f64,
    /// Concrete density, lb/ft³ (CEA-EDF).
    #[arg(long, default_value_t = 145.0, allow_negative_numbers = true)]
    pub density_pcf: f64,
    /// Wall thickness, in.
    #[arg(long, default_value_t = 30.0, allow_negative_numbers = true)]
    pub thickness_in: f64,
    /// Maximum aggregate size, in (Whiffen, Kar; assumed, not in the report).
    #[arg(long, default_value_t = 0.75, allow_negative_numbers = true)]
    pub aggregate_in: f64,
    /// Impact velocities, ft/s: START..END (inclusive) or one value.
    #[arg(long, default_value = "500..1500", allow_hyphen_values = true)]
    pub v0: String,
    /// Velocity step, ft/s.
    #[arg(long, default_value_t = 50.0, allow_negative_numbers = true)]
    pub step: f64,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
    /// Print the scabbing velocity and ballistic limit per formula instead of the sweep.
    #[arg(long)]
    pub thresholds: bool,
    /// Also draw h_s and h_p against velocity (over --v0) to this PNG.
    #[arg(long)]
    pub plot: Option<PathBuf>,
}

/// The library names a bad field `weight_lb`; the command line calls it `--weight-lb`.
fn flag_error(e: Error) -> Error {
    match e {
        Error::Input { file: None, field, message } => Error::input(format!("--{}", field.replace('_', "-")), message),
        other => other,
    }
}

/// Print the sweep or the thresholds, and draw the plot if asked.
pub fn run(args: Args) -> Result<()> {
    let nose = Nose::parse(&args.nose).map_err(flag_error)?;
    let missile = Missile::new(args.weight_lb, args.diameter_in, nose, args.modulus_psi).map_err(flag_error)?;
    let target =
        Target::new(args.fc_psi, args.ft_psi, args.density_pcf, args.thickness_in, args.aggregate_in).map_err(flag_error)?;
    let (v_min, v_max) = range::parse("--v0", &args.v0)?;
    let velocities = range::steps(v_min, v_max, args.step, "--step")?;

    let mut out = std::io::stdout().lock();
    let written = if args.thresholds {
        let rows = table::thresholds(&missile, &target);
        match args.format {
            Format::Csv => table::write_thresholds_csv(&rows, &mut out),
            Format::Table => scenario_header(&mut out, &missile, &target)
                .and_then(|_| table::write_thresholds_text(&rows, &mut out)),
        }
    } else {
        let rows = table::sweep(&missile, &target, &velocities);
        match args.format {
            Format::Csv => table::write_sweep_csv(&rows, &mut out),
            Format::Table => scenario_header(&mut out, &missile, &target)
                .and_then(|_| table::write_sweep_text(&rows, &mut out)),
        }
    };
    written.and_then(|_| out.flush()).map_err(|e| Error::io("<stdout>", e))?;

    if let Some(path) = &args.plot {
        plot::draw(path, &missile, &target, v_min, v_max)?;
    }
    Ok(())
}

fn scenario_header(out: &mut impl Write, m: &Missile, t: &Target) -> std::io::Result<()> {
    writeln!(
        out,
        "missile: W = {} lb, D = {} in, {} nose, E = {} psi | target: f'c = {} psi, f_t = {} psi, ρ = {} lb/ft³, h = {} in, max aggregate {} in\n",
        m.weight_lb, m.diameter_in, m.nose.name(), m.modulus_psi, t.fc_psi, t.ft_psi, t.density_pcf, t.thickness_in, t.aggregate_in
    )
}
