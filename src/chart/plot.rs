//! `chart.png`: the design chart, scabbing (left) and perforation (right) — target thickness
//! against impact velocity. Every formula's curve as in `demsweep empirical --plot` (thick inside
//! its stated validity), the band of the usable plain-concrete formulas shaded, and ours on top:
//! at each thickness the estimate with its interval as a horizontal bar, joined thickness to
//! thickness.

use std::path::Path;

use plotters::prelude::*;

use super::Point;
use crate::empirical::plot::{AreaResult, curves, thickness_axes, two_panels, usable_band};
use crate::empirical::{Missile, Quantity, Target};
use crate::error::Result;

const BAND: RGBColor = RGBColor(200, 215, 235);

/// Draw the chart of `points` to `path` over velocities `v_range`, ft/s (widened to hold every
/// interval), for the missile and wall of the base scene (the formulas' validity).
pub fn draw(path: &Path, points: &[Point], m: &Missile, t: &Target, v_range: (f64, f64)) -> Result<()> {
    let (mut v_min, mut v_max) = v_range;
    for p in points {
        for v in [p.v_low_fps, p.v_est_fps, p.v_high_fps].into_iter().flatten() {
            v_min = v_min.min(v);
            v_max = v_max.max(v);
        }
    }
    let v_max = if v_max > v_min { v_max } else { v_min + 1.0 };
    let h_max = 1.3 * points.iter().map(|p| p.thickness_in).fold(0.0, f64::max);
    two_panels(path, |area, q| {
        let threshold = if q == Quantity::Scabbing { "scabbing" } else { "perforation" };
        let mine: Vec<&Point> = points.iter().filter(|p| p.threshold == threshold).collect();
        panel(area, q, &mine, m, t, (v_min, v_max), h_max)
    })
}

fn panel(
    area: &DrawingArea<BitMapBackend<'_>, plotters::coord::Shift>,
    q: Quantity,
    points: &[&Point],
    m: &Missile,
    t: &Target,
    (v_min, v_max): (f64, f64),
    h_max: f64,
) -> AreaResult {
    let name = if q == Quantity::Scabbing { "Scabbing" } else { "Perforation" };
    let caption = format!("{name}: thickness {} against impact velocity", q.symbol());
    let mut chart = thickness_axes(area, &caption, (v_min, v_max), h_max, "target thickness, in")?;
    // The band, one polygon per run of velocities where some formula is usable.
    let band = usable_band(q, m, t, v_min, v_max);
    let mut first = true;
    for run in band.chunk_by(|a, b| b.0 - a.0 < 1.5 * (v_max - v_min) / 300.0) {
        let outline: Vec<(f64, f64)> = run.iter().map(|&(v, lo, _)| (v, lo.min(h_max))).chain(run.iter().rev().map(|&(v, _, hi)| (v, hi.min(h_max)))).collect();
        let drawn = chart.draw_series(std::iter::once(Polygon::new(outline, BAND.filled())))?;
        if first {
            drawn.label("band of the formulas valid here").legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], BAND.filled()));
            first = false;
        }
    }
    curves(&mut chart, q, m, t, (v_min, v_max), h_max)?;
    // Ours: the interval as a bar at its thickness, the estimate a dot, the estimates joined.
    let ours: Vec<(f64, f64)> = points.iter().filter_map(|p| Some((p.v_est_fps?, p.thickness_in))).collect();
    chart
        .draw_series(LineSeries::new(ours.clone(), BLACK.stroke_width(3)))?
        .label("demsweep (V50 or bisection, with its interval)")
        .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], BLACK.stroke_width(3)));
    for p in points {
        if let (Some(lo), Some(hi)) = (p.v_low_fps, p.v_high_fps) {
            let h = p.thickness_in;
            chart.draw_series(LineSeries::new([(lo, h), (hi, h)], BLACK.stroke_width(2)))?;
            let tick = 0.012 * h_max;
            for v in [lo, hi] {
                chart.draw_series(LineSeries::new([(v, h - tick), (v, h + tick)], BLACK.stroke_width(2)))?;
            }
        }
    }
    chart.draw_series(ours.iter().map(|&(v, h)| Circle::new((v, h), 6, BLACK.filled())))?;
    chart
        .configure_series_labels()
        // The curves rise to the upper left: the lower right is free.
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 13))
        .draw()?;
    Ok(())
}
