//! Sweeps and thresholds as tables: rows computed once, then written as CSV or as aligned text.

use std::io::{self, Write};

use super::inverse::{self, Threshold};
use super::{Formula, Missile, Prediction, Quantity, Target, Validity};

/// CSV header of a velocity sweep.
pub const SWEEP_HEADER: &str = "formula,variant,v0_fps,x_in,hs_in,hp_in,valid";
/// CSV header of the thresholds table.
pub const THRESHOLD_HEADER: &str = "formula,variant,v_scab_fps,v_perf_fps,valid";

/// One formula at one impact velocity.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepRow {
    /// The formula and variant.
    pub formula: Formula,
    /// Impact velocity, ft/s.
    pub v0_fps: f64,
    /// Its prediction there.
    pub prediction: Prediction,
}

/// One formula's scabbing velocity and ballistic limit for the target's thickness.
#[derive(Debug, Clone, PartialEq)]
pub struct ThresholdRow {
    /// The formula and variant.
    pub formula: Formula,
    /// Velocity at which h_s = thickness.
    pub scabbing: Threshold,
    /// Velocity at which h_p = thickness.
    pub perforation: Threshold,
}

impl ThresholdRow {
    /// Validity at the thresholds found (each quantity at its own velocity).
    pub fn validity(&self) -> Validity {
        Validity::all([&self.scabbing, &self.perforation].into_iter().filter_map(|th| match th {
            Threshold::Velocity { validity, .. } => Some(validity.clone()),
            _ => None,
        }))
    }
}

/// Every formula at every velocity, formula by formula.
pub fn sweep(m: &Missile, t: &Target, velocities_fps: &[f64]) -> Vec<SweepRow> {
    Formula::ALL
        .iter()
        .flat_map(|&formula| {
            velocities_fps.iter().map(move |&v0_fps| SweepRow { formula, v0_fps, prediction: formula.predict(m, t, v0_fps) })
        })
        .collect()
}

/// Thresholds of every formula that defines h_s or h_p.
pub fn thresholds(m: &Missile, t: &Target) -> Vec<ThresholdRow> {
    Formula::ALL
        .iter()
        .filter(|f| f.defines(Quantity::Scabbing) || f.defines(Quantity::Perforation))
        .map(|&formula| ThresholdRow {
            formula,
            scabbing: inverse::scabbing_velocity(formula, m, t),
            perforation: inverse::ballistic_limit(formula, m, t),
        })
        .collect()
}

/// The seven cells of a sweep row, numbers and validity rendered by the caller's style.
fn sweep_cells(r: &SweepRow, number: impl Fn(Option<f64>) -> String, valid: impl Fn(&Validity) -> String) -> Vec<String> {
    let p = &r.prediction;
    vec![
        r.formula.id().to_string(),
        r.formula.variant().to_string(),
        r.v0_fps.to_string(),
        number(p.x_in),
        number(p.hs_in),
        number(p.hp_in),
        valid(&p.validity),
    ]
}

/// The five cells of a thresholds row.
fn threshold_cells(r: &ThresholdRow, velocity: impl Fn(&Threshold) -> String, valid: impl Fn(&Validity) -> String) -> Vec<String> {
    vec![
        r.formula.id().to_string(),
        r.formula.variant().to_string(),
        velocity(&r.scabbing),
        velocity(&r.perforation),
        valid(&r.validity()),
    ]
}

fn write_csv(out: &mut impl Write, header: &str, rows: impl IntoIterator<Item = Vec<String>>) -> io::Result<()> {
    writeln!(out, "{header}")?;
    for cells in rows {
        writeln!(out, "{}", cells.join(","))?;
    }
    Ok(())
}

/// Aligned text: the first two columns left-aligned, the last free, the others right-aligned.
/// With `blocks`, a blank line wherever formula or variant changes, so each is a block.
fn write_text(out: &mut impl Write, widths: &[usize], rows: impl IntoIterator<Item = Vec<String>>, blocks: bool) -> io::Result<()> {
    let mut previous: Option<(String, String)> = None;
    for cells in rows {
        let key = (cells[0].clone(), cells[1].clone());
        if blocks && previous.as_ref().is_some_and(|p| *p != key) {
            writeln!(out)?;
        }
        previous = Some(key);
        let mut line = String::new();
        for (k, c) in cells.iter().enumerate() {
            let w = widths.get(k).copied().unwrap_or(0);
            let piece = if k < 2 { format!("{c:<w$} ") } else if k + 1 < cells.len() { format!("{c:>w$} ") } else { format!(" {c}") };
            line.push_str(&piece);
        }
        writeln!(out, "{}", line.trim_end())?;
    }
    Ok(())
}

/// Sweep as CSV (`SWEEP_HEADER`); lengths to 6 decimals, empty where undefined.
pub fn write_sweep_csv(rows: &[SweepRow], out: &mut impl Write) -> io::Result<()> {
    let number = |v: Option<f64>| v.map_or_else(String::new, |v| format!("{v:.6}"));
    write_csv(out, SWEEP_HEADER, rows.iter().map(|r| sweep_cells(r, number, |v| v.cell().to_string())))
}

/// Thresholds as CSV (`THRESHOLD_HEADER`); velocities to 3 decimals, `not reachable` where the
/// curve never reaches the thickness, empty where the formula does not define the quantity.
pub fn write_thresholds_csv(rows: &[ThresholdRow], out: &mut impl Write) -> io::Result<()> {
    write_csv(out, THRESHOLD_HEADER, rows.iter().map(|r| threshold_cells(r, |t| t.cell(3), |v| v.cell().to_string())))
}

/// Sweep as an aligned text table, one block per formula, with the reason wherever a formula is
/// outside its stated range.
pub fn write_sweep_text(rows: &[SweepRow], out: &mut impl Write) -> io::Result<()> {
    let widths = [14, 10, 7, 8, 8, 8];
    let header = ["formula", "variant", "v0 ft/s", "x in", "h_s in", "h_p in", "valid"].map(String::from).to_vec();
    let number = |v: Option<f64>| v.map_or_else(|| "-".into(), |v| format!("{v:.2}"));
    write_text(out, &widths, [header], false)?;
    write_text(out, &widths, rows.iter().map(|r| sweep_cells(r, number, validity_text)), true)
}

/// Thresholds as an aligned text table.
pub fn write_thresholds_text(rows: &[ThresholdRow], out: &mut impl Write) -> io::Result<()> {
    let widths = [14, 10, 14, 14];
    let header = ["formula", "variant", "V_s ft/s", "V_p ft/s", "valid"].map(String::from).to_vec();
    let velocity = |t: &Threshold| if t == &Threshold::NotDefined { "-".to_string() } else { t.cell(0) };
    let body = rows.iter().map(|r| threshold_cells(r, velocity, validity_text));
    write_text(out, &widths, std::iter::once(header).chain(body), false)
}

fn validity_text(v: &Validity) -> String {
    match v {
        Validity::Outside(why) => format!("no ({why})"),
        Validity::Inside => "yes".into(),
        Validity::Unstated => "unstated".into(),
    }
}
