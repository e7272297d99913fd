//! PNG of the scabbing and perforation thickness against impact velocity for every formula, with
//! the target thickness marked: the source report's Figures 7.3 (h_s) and 7.5 (h_p), side by side.
//!
//! Pure Rust (plotters' bitmap backend and PNG encoder, text through ab_glyph with the embedded
//! DejaVu Sans), so nothing from the system is needed at build or run time.

use std::path::Path;
use plotters::prelude::*;

use super::{Formula, Missile, Quantity, Target};
use crate::error::{Error, Result};

/// Width of the PNG, px.
pub const WIDTH_PX: u32 = 1600;
/// Height of the PNG, px.
pub const HEIGHT_PX: u32 = 800;
/// Velocities sampled per curve.
const SAMPLES: usize = 301;

/// One colour per registry entry, dark enough on white and far enough apart to tell 22 curves
/// apart (plotters' palettes include pale yellows).
const COLORS: [RGBColor; 22] = [
    RGBColor(230, 25, 75),
    RGBColor(245, 130, 48),
    RGBColor(128, 0, 0),
    RGBColor(0, 130, 200),
    RGBColor(70, 200, 240),
    RGBColor(60, 180, 75),
    RGBColor(0, 0, 128),
    RGBColor(145, 30, 180),
    RGBColor(170, 110, 40),
    RGBColor(240, 50, 230),
    RGBColor(128, 128, 0),
    RGBColor(0, 128, 128),
    RGBColor(210, 160, 0),
    RGBColor(100, 100, 100),
    RGBColor(0, 90, 0),
    RGBColor(255, 100, 130),
    RGBColor(90, 60, 200),
    RGBColor(160, 80, 80),
    RGBColor(30, 200, 160),
    RGBColor(200, 120, 255),
    RGBColor(120, 180, 0),
    RGBColor(40, 40, 40),
];

/// Draw h_s and h_p against velocity over `v_min_fps..=v_max_fps` to the PNG `path`.
/// Thick lines: inside the formula's stated validity (or none stated) for a wall of the curve's
/// own thickness there; thin: outside.
pub fn draw(path: &Path, m: &Missile, t: &Target, v_min_fps: f64, v_max_fps: f64) -> Result<()> {
    two_panels(path, |area, q| {
        let caption = match q {
            Quantity::Scabbing => "Scabbing thickness h_s (cf. report Fig. 7.3)",
            _ => "Perforation thickness h_p (cf. report Fig. 7.5)",
        };
        panel(area, q, caption, m, t, v_min_fps, v_max_fps)
    })
}

/// What drawing on a PNG's area gives.
pub type AreaResult = std::result::Result<(), DrawingAreaErrorKind<<BitMapBackend<'static> as DrawingBackend>::ErrorType>>;

/// A PNG at `path` of two panels side by side, scabbing (left) and perforation (right), each
/// drawn by `panel`, written whole.
pub fn two_panels(path: &Path, mut panel: impl FnMut(&DrawingArea<BitMapBackend<'_>, plotters::coord::Shift>, Quantity) -> AreaResult) -> Result<()> {
    crate::picture::font::ensure();
    let err = |e: &dyn std::fmt::Display| Error::io(path, e);
    let root = BitMapBackend::new(path, (WIDTH_PX, HEIGHT_PX)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let (left, right) = root.split_horizontally(WIDTH_PX / 2);
    for (area, q) in [(left, Quantity::Scabbing), (right, Quantity::Perforation)] {
        panel(&area, q).map_err(|e| err(&e))?;
    }
    root.present().map_err(|e| err(&e))?;
    Ok(())
}

fn panel(
    area: &DrawingArea<BitMapBackend<'_>, plotters::coord::Shift>,
    q: Quantity,
    caption: &str,
    m: &Missile,
    t: &Target,
    v_min_fps: f64,
    v_max_fps: f64,
) -> AreaResult {
    let y_max = 2.0 * t.thickness_in;
    let v_hi = if v_max_fps > v_min_fps { v_max_fps } else { v_min_fps + 1.0 };
    let mut chart = thickness_axes(area, caption, (v_min_fps, v_hi), y_max, &format!("{}, in", q.symbol()))?;

    let target = format!("target {} in (thin lines: outside stated validity)", t.thickness_in);
    chart
        .draw_series(LineSeries::new([(v_min_fps, t.thickness_in), (v_hi, t.thickness_in)], BLACK.stroke_width(3)))?
        .label(target)
        .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], BLACK.stroke_width(3)));

    curves(&mut chart, q, m, t, (v_min_fps, v_hi), y_max)?;
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 13))
        .draw()?;
    Ok(())
}

/// The chart's type: thickness, in, against velocity, ft/s, on a PNG.
pub type Axes<'a, 'b> = ChartContext<'a, BitMapBackend<'b>, Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>>;

/// Axes of thickness (0..`y_max`, in, labelled `y_desc`) against impact velocity (`v_range`,
/// ft/s) on `area`, with the grid drawn.
pub fn thickness_axes<'a, 'b>(
    area: &'a DrawingArea<BitMapBackend<'b>, plotters::coord::Shift>,
    caption: &str,
    v_range: (f64, f64),
    y_max: f64,
    y_desc: &str,
) -> std::result::Result<Axes<'a, 'b>, DrawingAreaErrorKind<<BitMapBackend<'b> as DrawingBackend>::ErrorType>> {
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(55)
        .build_cartesian_2d(v_range.0..v_range.1, 0.0..y_max)?;
    chart
        .configure_mesh()
        .x_desc("impact velocity, ft/s")
        .y_desc(y_desc)
        .label_style(("sans-serif", 15))
        .x_label_formatter(&|v| format!("{v:.0}"))
        .y_label_formatter(&|v| format!("{v:.0}"))
        .draw()?;
    Ok(chart)
}

/// Every formula's curve of `q` against velocity over `v_range` on `chart`, one colour each with
/// its legend entry: thick inside the formula's stated validity (or none stated), thin outside.
pub fn curves<DB: DrawingBackend>(
    chart: &mut ChartContext<'_, DB, Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>>,
    q: Quantity,
    m: &Missile,
    t: &Target,
    v_range: (f64, f64),
    y_max: f64,
) -> std::result::Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    for (k, f) in Formula::ALL.iter().enumerate().filter(|(_, f)| f.defines(q)) {
        let color = COLORS[k % COLORS.len()];
        let mut first = true;
        for (segment, usable) in segments(f, q, m, t, v_range.0, v_range.1, y_max) {
            let style = color.stroke_width(if usable { 2 } else { 1 });
            let drawn = chart.draw_series(LineSeries::new(segment, style))?;
            if first {
                drawn
                    .label(format!("{} {}", f.title(), variant_label(f)))
                    .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color.stroke_width(2)));
                first = false;
            }
        }
    }
    Ok(())
}

/// The band of the plain-concrete formulas usable for this missile and wall (inside their
/// stated validity, or none stated), as `thresholds.csv` counts them: at each sampled velocity, the least and greatest thickness `q` among them, in;
/// velocities where none is usable are left out.
pub fn usable_band(q: Quantity, m: &Missile, t: &Target, v_min: f64, v_max: f64) -> Vec<(f64, f64, f64)> {
    (0..SAMPLES)
        .filter_map(|k| {
            let v = v_min + (v_max - v_min) * k as f64 / (SAMPLES - 1) as f64;
            let hs: Vec<f64> = Formula::ALL
                .iter()
                .filter(|f| f.defines(q) && f.for_plain_concrete())
                .filter_map(|f| Some((f, f.evaluate(q, m, t, v)?)))
                .filter(|&(f, h)| h.is_finite() && h >= 0.0 && f.validity(q, m, &at(t, h), v).is_usable())
                .map(|(_, h)| h)
                .collect();
            let lo = hs.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = hs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            (!hs.is_empty()).then_some((v, lo, hi))
        })
        .collect()
}

/// The wall a curve's point stands for: `t` at the point's own thickness `h_in` (a validity
/// bound may be on h/d).
fn at(t: &Target, h_in: f64) -> Target {
    Target { thickness_in: h_in, ..*t }
}

fn variant_label(f: &Formula) -> &'static str {
    if f.variant() == "standard" { "" } else { f.variant() }
}

/// The curve as polylines, split where validity changes or the value is undefined, and clipped
/// to `y ≤ y_max` so steep formulas do not run off the panel.
fn segments(
    f: &Formula,
    q: Quantity,
    m: &Missile,
    t: &Target,
    v_min: f64,
    v_max: f64,
    y_max: f64,
) -> Vec<(Vec<(f64, f64)>, bool)> {
    let mut out: Vec<(Vec<(f64, f64)>, bool)> = Vec::new();
    let mut open = false;
    for k in 0..SAMPLES {
        let v = v_min + (v_max - v_min) * k as f64 / (SAMPLES - 1) as f64;
        let Some(h) = f.evaluate(q, m, t, v).filter(|h| *h <= y_max && *h >= 0.0) else {
            open = false;
            continue;
        };
        let usable = f.validity(q, m, &at(t, h), v).is_usable();
        match out.last_mut() {
            Some((points, u)) if open && *u == usable => points.push((v, h)),
            Some((points, _)) if open => {
                // Start the new segment where the old one ends, so the line stays joined.
                let join = *points.last().expect("open segments are non-empty");
                out.push((vec![join, (v, h)], usable));
            }
            _ => out.push((vec![(v, h)], usable)),
        }
        open = true;
    }
    out
}
