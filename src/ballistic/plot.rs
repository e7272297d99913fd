//! `ballistic.png`: penetration depth (left) and residual velocity (right) against impact
//! velocity, every run a point (scabbed runs amber, perforated red), our two thresholds as
//! vertical lines (with several packings: the V50s with their 90 % intervals shaded, and each
//! packing's bisected threshold a tick at the top), the empirical formulas' bands shaded, and the Lambert–Jonas and Recht–Ipson
//! curves over the perforating runs.

use std::path::Path;

use plotters::prelude::*;

use super::bracket::Finding;
use super::fit::residual_velocity;
use super::thresholds::{Empirical, Ours, band};
use crate::error::{Error, Result};
use crate::table::Table;

const WIDTH_PX: u32 = 1600;
const HEIGHT_PX: u32 = 700;
const SCAB: RGBColor = RGBColor(230, 150, 0);
const PERF: RGBColor = RGBColor(200, 30, 30);
const HELD: RGBColor = RGBColor(40, 40, 40);

type Area<'a> = DrawingArea<BitMapBackend<'a>, plotters::coord::Shift>;
type AreaResult = std::result::Result<(), DrawingAreaErrorKind<<BitMapBackend<'static> as DrawingBackend>::ErrorType>>;
type Chart<'a, 'b> = ChartContext<'a, BitMapBackend<'b>, Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>>;

struct Run {
    v: f64,
    depth: f64,
    vr: f64,
    scabbed: bool,
    perforated: bool,
}

fn runs(t: &Table) -> Vec<Run> {
    (0..t.rows.len())
        .filter_map(|r| {
            let f = |c: &str| t.get(r, c)?.parse::<f64>().ok();
            Some(Run {
                v: f("v0_fps")?,
                depth: f("depth_in")?,
                vr: f("v_residual_fps").unwrap_or(0.0),
                scabbed: t.get(r, "scabbed")? == "true",
                perforated: t.get(r, "perforated")? == "true",
            })
        })
        .collect()
}

/// Draw the picture of a ballistic sweep to `path` (a PNG, written whole).
pub fn draw(path: &Path, t: &Table, ours: &Ours<'_>, formulas: &[Empirical], grid: &[f64]) -> Result<()> {
    crate::picture::font::ensure();
    let err = |e: &dyn std::fmt::Display| Error::io(path, e);
    let pts = runs(t);
    let (v_lo, v_hi) = (grid.first().copied().unwrap_or(0.0), grid.last().copied().unwrap_or(1.0));
    let pad = 0.05 * (v_hi - v_lo).max(100.0);
    let x = (v_lo - pad)..(v_hi + pad);
    let mut buffer = vec![0u8; (WIDTH_PX * HEIGHT_PX * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (WIDTH_PX, HEIGHT_PX)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let (left, right) = root.split_horizontally(WIDTH_PX / 2);
        depth_panel(&left, &pts, ours, formulas, x.clone()).map_err(|e| err(&e))?;
        residual_panel(&right, &pts, ours, formulas, x).map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))?;
    }
    crate::picture::encode_png(path, &buffer, WIDTH_PX, HEIGHT_PX)
}

fn shade(
    chart: &mut Chart<'_, '_>,
    formulas: &[Empirical],
    y_max: f64,
) -> AreaResult {
    for (name, color) in [("scabbing", SCAB), ("perforation", PERF)] {
        if let Some((a, b)) = band(formulas, name) {
            chart
                .draw_series([Rectangle::new([(a, 0.0), (b, y_max)], color.mix(0.12).filled())])?
                .label(format!("{name}: empirical formulas in validity, {a:.0}–{b:.0} ft/s"))
                .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], color.mix(0.3).filled()));
        }
    }
    Ok(())
}

fn thresholds(
    chart: &mut Chart<'_, '_>,
    ours: &Ours<'_>,
    y_max: f64,
) -> AreaResult {
    if let Some((scab, perf)) = ours.v50 {
        // Several packings: each threshold's V50, its 90 % interval hatched, each packing's
        // bisected threshold a short tick at the top.
        for (name, v, color) in [("scabbing", scab, SCAB), ("perforation", perf, PERF)] {
            let Some(v) = v else { continue };
            let (lo, hi) = (v.lower_fps.unwrap_or(f64::NEG_INFINITY), v.upper_fps.unwrap_or(f64::INFINITY));
            chart.draw_series([Rectangle::new([(lo.max(chart.x_range().start), 0.0), (hi.min(chart.x_range().end), y_max)], color.mix(0.25).filled())])?;
            chart
                .draw_series(LineSeries::new([(v.v50_fps, 0.0), (v.v50_fps, y_max)], color.stroke_width(3)))?
                .label(format!(
                    "demsweep {name} V50 {:.0} ft/s, 90 % {}–{} ({} packings)",
                    v.v50_fps,
                    v.lower_fps.map_or("?".into(), |x| format!("{x:.0}")),
                    v.upper_fps.map_or("?".into(), |x| format!("{x:.0}")),
                    ours.packings.len()
                ))
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color.stroke_width(3)));
        }
        for p in ours.packings {
            for (f, color) in [(&p.scabbing, SCAB), (&p.perforation, PERF)] {
                if let Some(v) = f.estimate_fps() {
                    chart.draw_series(LineSeries::new([(v, 0.93 * y_max), (v, y_max)], color.stroke_width(2)))?;
                }
            }
        }
        return Ok(());
    }
    let lines: [(&str, &Finding, RGBColor); 2] = [("scabbing", ours.scabbing, SCAB), ("perforation", ours.perforation, PERF)];
    for (name, f, color) in lines {
        if let Some(v) = f.estimate_fps() {
            chart
                .draw_series(LineSeries::new([(v, 0.0), (v, y_max)], color.stroke_width(3)))?
                .label(format!("demsweep {name} threshold {v:.1} ft/s"))
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color.stroke_width(3)));
        }
    }
    Ok(())
}

fn marker(r: &Run) -> RGBColor {
    if r.perforated {
        PERF
    } else if r.scabbed {
        SCAB
    } else {
        HELD
    }
}

/// The legend in the lower right: both panels rise to the right, so that corner is empty, and
/// the packings' ticks along the top stay in view.
fn legend<'a, 'b: 'a>(
    chart: &mut Chart<'a, 'b>,
) -> AreaResult {
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 14))
        .draw()
}

fn depth_panel(area: &Area<'_>, pts: &[Run], ours: &Ours<'_>, formulas: &[Empirical], x: std::ops::Range<f64>) -> AreaResult {
    let y_max = pts.iter().map(|r| r.depth).fold(1.0, f64::max) * 1.15;
    let mut chart = ChartBuilder::on(area)
        .caption("Peak penetration depth (nose below the front face)", ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(55)
        .build_cartesian_2d(x, 0.0..y_max)?;
    chart.configure_mesh().x_desc("impact velocity, ft/s").y_desc("depth, in").label_style(("sans-serif", 15)).draw()?;
    shade(&mut chart, formulas, y_max)?;
    thresholds(&mut chart, ours, y_max)?;
    chart.draw_series(pts.iter().map(|r| Circle::new((r.v, r.depth), 5, marker(r).filled())))?;
    chart
        .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())?
        .label("runs: grey held, amber scabbed, red perforated")
        .legend(|(x, y)| Circle::new((x + 10, y), 5, HELD.filled()));
    legend(&mut chart)
}

fn residual_panel(area: &Area<'_>, pts: &[Run], ours: &Ours<'_>, formulas: &[Empirical], x: std::ops::Range<f64>) -> AreaResult {
    let y_max = pts.iter().map(|r| r.vr).fold(100.0, f64::max) * 1.15;
    let (x0, x1) = (x.start, x.end);
    let mut chart = ChartBuilder::on(area)
        .caption("Residual velocity of the perforating runs", ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(55)
        .build_cartesian_2d(x, 0.0..y_max)?;
    chart.configure_mesh().x_desc("impact velocity, ft/s").y_desc("residual velocity, ft/s").label_style(("sans-serif", 15)).draw()?;
    shade(&mut chart, formulas, y_max)?;
    thresholds(&mut chart, ours, y_max)?;
    let curves = [("Lambert–Jonas", ours.lambert_jonas, RGBColor(0, 90, 200)), ("Recht–Ipson (p = 2)", ours.recht_ipson, RGBColor(0, 150, 120))];
    for (name, fit, color) in curves {
        let Some(f) = fit else { continue };
        let curve = (0..=300).map(|k| x0 + (x1 - x0) * k as f64 / 300.0).map(|v| (v, residual_velocity(f.a, f.p, f.v_bl_fps, v)));
        chart
            .draw_series(LineSeries::new(curve, color.stroke_width(2)))?
            .label(format!("{name}: V_bl {:.1} ft/s, a {:.3}, p {:.2}, rms {:.1} ft/s", f.v_bl_fps, f.a, f.p, f.rms_fps))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color.stroke_width(2)));
    }
    chart.draw_series(pts.iter().filter(|r| r.perforated).map(|r| Circle::new((r.v, r.vr), 5, PERF.filled())))?;
    legend(&mut chart)
}
