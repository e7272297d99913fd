//! `<case>_speed.png`: each level's relative error against its wall time, log-log, so a user sees
//! what each digit costs.

use std::path::Path;

use plotters::prelude::*;

use super::{Report, reference};
use crate::error::{Error, Result};

const WIDTH_PX: u32 = 900;
const HEIGHT_PX: u32 = 650;

/// Draw the speed-against-error picture of a study.
pub fn draw(path: &Path, r: &Report) -> Result<()> {
    crate::picture::font::ensure();
    let (reference, against) = reference(r);
    let pts: Vec<(f64, f64, u32)> = r
        .levels
        .iter()
        .map(|l| (l.wall_s.max(1e-3), ((l.value - reference) / reference).abs(), l.level))
        .filter(|p| p.1 > 0.0 && p.1.is_finite())
        .collect();
    let err = |e: &dyn std::fmt::Display| Error::io(path, e);
    let mut buffer = vec![0u8; (WIDTH_PX * HEIGHT_PX * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (WIDTH_PX, HEIGHT_PX)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let (x0, x1) = pts.iter().fold((f64::INFINITY, 0.0f64), |a, p| (a.0.min(p.0), a.1.max(p.0)));
        let (y0, y1) = pts.iter().fold((f64::INFINITY, 0.0f64), |a, p| (a.0.min(p.1), a.1.max(p.1)));
        let (x0, x1) = if pts.is_empty() { (0.1, 10.0) } else { (x0 / 2.0, x1 * 2.0) };
        let (y0, y1) = if pts.is_empty() { (1e-4, 1.0) } else { (y0 / 2.0, y1 * 2.0) };
        let drawn = (|| -> std::result::Result<(), DrawingAreaErrorKind<<BitMapBackend<'_> as DrawingBackend>::ErrorType>> {
            let mut chart = ChartBuilder::on(&root)
                .caption(format!("{}: {} error against cost ({})", r.case.name(), r.case.quantity(), r.class.word()), ("sans-serif", 20))
                .margin(14)
                .x_label_area_size(45)
                .y_label_area_size(70)
                .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())?;
            chart
                .configure_mesh()
                .x_desc("wall time, s (the level's runs)")
                .y_desc(format!("relative error against the {against}"))
                // Plotters' own labels on a log axis print 0.4 as 0.4000000004.
                .y_label_formatter(&|v| if *v >= 0.01 { format!("{v:.2}") } else { format!("{v:.0e}") })
                .label_style(("sans-serif", 14))
                .draw()?;
            chart.draw_series(LineSeries::new(pts.iter().map(|p| (p.0, p.1)), BLUE.stroke_width(2)))?;
            chart.draw_series(pts.iter().map(|p| Circle::new((p.0, p.1), 6, BLUE.filled())))?;
            chart.draw_series(pts.iter().map(|p| Text::new(format!("level {}", p.2), (p.0, p.1), ("sans-serif", 15))))?;
            Ok(())
        })();
        drawn.map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))?;
    }
    crate::picture::encode_png(path, &buffer, WIDTH_PX, HEIGHT_PX)
}
