//! `thresholds.csv`: one row per threshold estimate — ours (bisection; Lambert–Jonas and
//! Recht–Ipson fits of the ballistic limit) and each empirical formula's for the same missile
//! and wall (`empirical`, issue [2/5]) — with the empirical band beside every row: the lowest
//! and highest velocity among the formulas that are inside (or state no) validity at it, leaving
//! out the variants for reinforced concrete (the wall is plain).

use super::bracket::{Bracket, Finding};
use super::fit::Fit;
use super::v50::V50;
use crate::penetration::scene::PenetrationScene;
use crate::empirical::{Missile, Nose as EmpiricalNose, Target, table as empirical_table};
use crate::error::Result;
use crate::shape::Nose;
use crate::table::Table;

/// The largest aggregate of the source's concrete, in (the empirical module's default: the
/// scene's concrete does not carry it; only Whiffen and Kar read it).
pub const AGGREGATE_IN: f64 = 0.75;

/// The scene's projectile and wall as the empirical formulas see them (the 3D missile of the
/// source's scenario: its weight and diameter, not the 2D slice's mass).
pub fn empirical_inputs(s: &PenetrationScene) -> Result<(Missile, Target)> {
    let nose = match s.projectile.nose {
        Nose::Flat => EmpiricalNose::Flat,
        Nose::Hemispherical => EmpiricalNose::Spherical,
        Nose::Ogive => EmpiricalNose::VerySharp,
    };
    let c = &s.concrete;
    // lb·s²/in⁴ → lb/ft³ of weight: ρ g, g = 386.09 in/s², 1728 in³/ft³.
    let density_pcf = c.density_lbs2_per_in4 * 386.088_582_677 * 1728.0;
    let m = Missile::new(s.projectile.weight_lb, s.projectile.width_in, nose, s.projectile.youngs_modulus_psi)?;
    let t = Target::new(c.compressive_strength_psi, c.tensile_strength_psi, density_pcf, s.target.depth_in, AGGREGATE_IN)?;
    Ok((m, t))
}

/// One formula's threshold velocity, ft/s, and whether it is usable there.
#[derive(Debug, Clone, PartialEq)]
pub struct Empirical {
    /// `scabbing` or `perforation`.
    pub threshold: &'static str,
    /// Formula id and variant.
    pub method: String,
    /// The velocity (a number) or what the formula says instead.
    pub cell: String,
    /// The velocity, ft/s.
    pub v_fps: Option<f64>,
    /// Inside (or without) stated validity there.
    pub usable: bool,
    /// Validity text.
    pub validity: String,
    /// A form for plain concrete (the scene's wall), not for reinforced.
    pub plain: bool,
}

/// Every formula's scabbing velocity and ballistic limit for the scene's wall.
pub fn empirical(s: &PenetrationScene) -> Result<Vec<Empirical>> {
    let (m, t) = empirical_inputs(s)?;
    let mut out = Vec::new();
    for r in empirical_table::thresholds(&m, &t) {
        for (threshold, th) in [("scabbing", &r.scabbing), ("perforation", &r.perforation)] {
            let (usable, validity) = match th {
                crate::empirical::inverse::Threshold::Velocity { validity, .. } => (validity.is_usable(), validity.to_string()),
                _ => (false, String::new()),
            };
            if matches!(th, crate::empirical::inverse::Threshold::NotDefined) {
                continue;
            }
            out.push(Empirical {
                threshold,
                method: format!("empirical {} ({})", r.formula.id(), r.formula.variant()),
                cell: th.cell(1),
                v_fps: th.v_fps(),
                usable,
                validity,
                plain: r.formula.for_plain_concrete(),
            });
        }
    }
    Ok(out)
}

/// Whether a formula's row counts toward the band: usable here, and not a variant for reinforced
/// concrete (Petry's `normal-rc`, `special-rc`): the scene's wall is plain concrete.
pub fn in_band(r: &Empirical) -> bool {
    r.usable && r.plain
}

/// The band of usable plain-concrete formula velocities for a threshold, ft/s.
pub fn band(rows: &[Empirical], threshold: &str) -> Option<(f64, f64)> {
    let v: Vec<f64> = rows.iter().filter(|r| r.threshold == threshold && in_band(r)).filter_map(|r| r.v_fps).collect();
    if v.is_empty() {
        return None;
    }
    Some((v.iter().cloned().fold(f64::INFINITY, f64::min), v.iter().cloned().fold(f64::NEG_INFINITY, f64::max)))
}

/// Our estimates.
pub struct Ours<'a> {
    /// Scabbing.
    pub scabbing: &'a Finding,
    /// Perforation.
    pub perforation: &'a Finding,
    /// Lambert–Jonas fit.
    pub lambert_jonas: Option<Fit>,
    /// Recht–Ipson fit.
    pub recht_ipson: Option<Fit>,
    /// With several packings: each one's bisected thresholds (empty: the scene's own only).
    pub packings: &'a [super::Packing],
    /// With several packings: the V50 of scabbing and of perforation.
    pub v50: Option<&'a (Option<V50>, Option<V50>)>,
}

/// How a V50 row's interval was formed, for its note.
fn v50_note(v: &V50) -> String {
    let how = if v.separated {
        "the pooled outcomes separate completely (no velocity has both): Firth's penalised likelihood keeps the estimate finite, and the interval is its profile"
    } else {
        "Firth-penalised logistic fit, interval by profile penalised likelihood"
    };
    let open = match (v.lower_fps, v.upper_fps) {
        (None, None) => "; unbounded both ways",
        (None, _) => "; unbounded below",
        (_, None) => "; unbounded above",
        _ => "",
    };
    format!("{how}{open}; {} runs, {} with the outcome, logistic spread {:.1} ft/s", v.n, v.n_true, v.scale_fps)
}

const HEADER: [&str; 13] = [
    "threshold",
    "method",
    "v_low_fps",
    "v_high_fps",
    "v_est_fps",
    "fit_a",
    "fit_p",
    "fit_rms_fps",
    "points",
    "band_min_fps",
    "band_max_fps",
    "inside_band",
    "note",
];

fn num(v: Option<f64>) -> String {
    v.map_or(String::new(), |v| format!("{v:.3}"))
}

/// The thresholds table.
pub fn table(ours: &Ours<'_>, formulas: &[Empirical], bracket_points: (usize, usize)) -> Table {
    let mut rows = Vec::new();
    // One row: the estimate, its bracket or interval, a fit's a, p and rms, the points it rests
    // on, the formulas' band for its threshold and whether the estimate lies in it, a note.
    let mut push = |threshold: &str, method: String, (lo, hi): (Option<f64>, Option<f64>), est: Option<f64>, fit: [String; 3], points: String, note: String| {
        let band = band(formulas, threshold);
        let inside = match (band, est) {
            (Some((a, b)), Some(v)) => (v >= a && v <= b).to_string(),
            _ => String::new(),
        };
        let [a, p, rms] = fit;
        rows.push(vec![threshold.into(), method, num(lo), num(hi), num(est), a, p, rms, points, num(band.map(|b| b.0)), num(band.map(|b| b.1)), inside, note]);
    };
    let no_fit = || [String::new(), String::new(), String::new()];
    if let Some((scab, perf)) = ours.v50 {
        for (name, v, n) in [("scabbing", scab, bracket_points.0), ("perforation", perf, bracket_points.1)] {
            push(
                name,
                format!("v50 ({:.0} % interval, {} packings)", 100.0 * super::v50::LEVEL, ours.packings.len()),
                (v.as_ref().and_then(|v| v.lower_fps), v.as_ref().and_then(|v| v.upper_fps)),
                v.as_ref().map(|v| v.v50_fps),
                no_fit(),
                n.to_string(),
                v.as_ref().map_or_else(|| "every run had the same outcome: no V50".to_string(), v50_note),
            );
        }
    }
    let mut bisections: Vec<(String, &Finding, &Finding)> =
        ours.packings.iter().map(|p| (format!("bisection seed {}", p.seed), &p.scabbing, &p.perforation)).collect();
    if bisections.is_empty() {
        bisections.push(("bisection".into(), ours.scabbing, ours.perforation));
    }
    for (method, scab, perf) in &bisections {
        for (name, f, n) in [("scabbing", *scab, bracket_points.0), ("perforation", *perf, bracket_points.1)] {
            let bracket = match f.bracket {
                Bracket::Between { lo_fps, hi_fps } => (Some(lo_fps), Some(hi_fps)),
                Bracket::AtOrBelow(v) => (None, Some(v)),
                Bracket::NotReached(v) => (Some(v), None),
                Bracket::Empty => (None, None),
            };
            push(name, method.clone(), bracket, f.estimate_fps(), no_fit(), n.to_string(), f.note(name));
        }
    }
    for (method, fit) in [("lambert-jonas", ours.lambert_jonas), ("recht-ipson", ours.recht_ipson)] {
        let note = if fit.is_none() { "too few perforating runs to fit".to_string() } else { "V_r = a (V^p - V_bl^p)^(1/p) over the perforating runs".to_string() };
        let cols = fit.map_or_else(no_fit, |f| [format!("{:.4}", f.a), format!("{:.3}", f.p), num(Some(f.rms_fps))]);
        push("perforation", method.into(), (None, None), fit.map(|f| f.v_bl_fps), cols, fit.map_or(String::new(), |f| f.points.to_string()), note);
    }
    for e in formulas {
        let note = if e.usable { e.validity.clone() } else if e.v_fps.is_some() { format!("outside validity: {}", e.validity) } else { e.cell.clone() };
        push(e.threshold, e.method.clone(), (None, None), e.v_fps, no_fit(), String::new(), note);
    }
    Table { header: HEADER.iter().map(|s| s.to_string()).collect(), rows }
}

/// The row of `thresholds.csv` that answers for `threshold`: the V50 over packings where there is
/// one, else the bisection's bracket.
pub fn best_row(t: &Table, threshold: &str) -> Option<usize> {
    let rows: Vec<usize> = (0..t.rows.len()).filter(|&r| t.get(r, "threshold") == Some(threshold)).collect();
    let method = |r: &usize| t.get(*r, "method").unwrap_or("");
    rows.iter().find(|r| method(r).starts_with("v50")).or_else(|| rows.iter().find(|r| method(r).starts_with("bisection"))).copied()
}
