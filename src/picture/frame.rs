//! One PNG frame: elements as filled disks at their true size, coloured by damage, cracks across
//! broken bonds, a title line and a scale bar in inches. A 2D model is drawn whole; a 3D one as
//! its section by the plane z = `View::section_z_m` through the impact point (each sphere the
//! plane cuts as the disc of the cut).

use std::ops::Range;

use plotters::prelude::*;

use crate::penetration::scene::PenetrationScene;
use crate::error::Result;
use crate::simulation::Bodies;
use crate::units::M_PER_IN;

/// Width of a frame, px.
pub const WIDTH_PX: u32 = 1600;
/// Height of the title band, px.
const TITLE_PX: u32 = 36;
/// Length of the scale bar, in.
const SCALE_BAR_IN: f64 = 12.0;

/// The part of the plane a frame shows (fixed for a series, so frames line up).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// Left edge, m.
    pub x_min_m: f64,
    /// Top edge, m.
    pub y_max_m: f64,
    /// Pixels per metre.
    pub px_per_m: f64,
    /// Frame height, px.
    pub height_px: u32,
    /// Impact speed, ft/s (for the title).
    pub v0_fps: f64,
    /// The section plane z, m (3D; None draws a 2D model whole).
    pub section_z_m: Option<f64>,
}

impl View {
    /// The beam with 4 in around it, the projectile's start above it and the beam's depth
    /// below it: an irregular beam that fails bends and opens far below its back face, where
    /// the scabs and the projectile go.
    pub fn of(scene: &PenetrationScene) -> Result<View> {
        let (t, p) = (&scene.target, &scene.projectile);
        let x = (-4.0 * M_PER_IN, (t.length_in + 4.0) * M_PER_IN);
        let length_in = if scene.penetration.dim == 3 { scene.projectile_length3_in()? } else { scene.projectile_length_in() };
        let y = (-t.depth_in * M_PER_IN, (t.depth_in + p.standoff_in.min(12.0) + length_in + 3.0) * M_PER_IN);
        let px_per_m = WIDTH_PX as f64 / (x.1 - x.0);
        let height_px = TITLE_PX + ((y.1 - y.0) * px_per_m).ceil() as u32;
        let section_z_m = (scene.penetration.dim == 3).then(|| 0.5 * t.length_in * M_PER_IN);
        Ok(View { x_min_m: x.0, y_max_m: y.1, px_per_m, height_px, v0_fps: p.v0_fps, section_z_m })
    }

    fn px(&self, p: [f64; 2]) -> (i32, i32) {
        (((p[0] - self.x_min_m) * self.px_per_m).round() as i32, TITLE_PX as i32 + ((self.y_max_m - p[1]) * self.px_per_m).round() as i32)
    }
}

/// Damage 0 → light grey, ½ → amber, 1 → dark red.
pub fn damage_colour(d: f64) -> RGBColor {
    let lerp = |a: (u8, u8, u8), b: (u8, u8, u8), t: f64| {
        let f = |x: u8, y: u8| (x as f64 + (y as f64 - x as f64) * t).round() as u8;
        RGBColor(f(a.0, b.0), f(a.1, b.1), f(a.2, b.2))
    };
    let (grey, amber, red) = ((205, 205, 205), (240, 190, 40), (140, 0, 0));
    let d = d.clamp(0.0, 1.0);
    if d < 0.5 { lerp(grey, amber, 2.0 * d) } else { lerp(amber, red, 2.0 * d - 1.0) }
}

const STEEL: RGBColor = RGBColor(40, 90, 180);
const SUPPORT: RGBColor = RGBColor(110, 110, 120);

/// The frame as PNG bytes.
pub fn render_png(view: &View, m: &(impl Bodies + ?Sized), damage: &[f64], broken: &[(u32, u32)], projectile: Range<usize>) -> std::result::Result<Vec<u8>, String> {
    super::font::ensure();
    let (w, h) = (WIDTH_PX, view.height_px);
    let mut rgb = vec![255u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, (w, h)).into_drawing_area();
        draw(&root, view, m, damage, broken, projectile).map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    super::png_bytes(&rgb, w, h)
}

type Area<'a> = DrawingArea<BitMapBackend<'a>, plotters::coord::Shift>;
type Drawn = std::result::Result<(), DrawingAreaErrorKind<<BitMapBackend<'static> as DrawingBackend>::ErrorType>>;

/// Element `e` as drawn: its centre in the frame's plane and its radius there, m (None: the
/// section plane misses it).
fn disc(view: &View, m: &(impl Bodies + ?Sized), e: usize) -> Option<([f64; 2], f64)> {
    let (p, r) = (m.position_m(e), m.radius_m(e));
    match view.section_z_m {
        None => Some(([p[0], p[1]], r)),
        Some(z) => {
            let dz = p[2] - z;
            (dz.abs() < r).then(|| ([p[0], p[1]], (r * r - dz * dz).sqrt()))
        }
    }
}

fn draw(root: &Area<'_>, view: &View, m: &(impl Bodies + ?Sized), damage: &[f64], broken: &[(u32, u32)], projectile: Range<usize>) -> Drawn {
    root.fill(&WHITE)?;
    let s = view.px_per_m;
    for e in 0..m.element_count() {
        let Some((c, r)) = disc(view, m, e) else { continue };
        let colour = if projectile.contains(&e) {
            STEEL
        } else if m.held(e) {
            SUPPORT
        } else {
            damage_colour(damage[e])
        };
        root.draw(&Circle::new(view.px(c), (r * s).max(0.75), colour.filled()))?;
    }
    for &(i, j) in broken {
        let (Some((a, ri)), Some((b, rj))) = (disc(view, m, i as usize), disc(view, m, j as usize)) else { continue };
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let d = dx.hypot(dy).max(1e-12);
        // The crack sits on the gap between the two disks, across the line of centres.
        let f = (ri + 0.5 * (d - ri - rj).max(0.0)) / d;
        let c = [a[0] + f * dx, a[1] + f * dy];
        let half = 0.55 * ri.min(rj);
        let (nx, ny) = (-dy / d * half, dx / d * half);
        root.draw(&PathElement::new(vec![view.px([c[0] - nx, c[1] - ny]), view.px([c[0] + nx, c[1] + ny])], BLACK.stroke_width(1)))?;
    }
    let title = format!(
        "t = {:.3} ms    v0 = {:.0} ft/s    bonds broken: {}{}    (grey intact → red all bonds broken; black: cracks; blue: projectile)",
        m.time_s() * 1e3,
        view.v0_fps,
        broken.len(),
        if view.section_z_m.is_some() { "    section through the impact point" } else { "" }
    );
    root.draw(&Text::new(title, (12, 9), ("sans-serif", 18).into_font().color(&BLACK)))?;
    // Scale bar, bottom left.
    let bar = (SCALE_BAR_IN * M_PER_IN * s).round() as i32;
    let (x0, y0) = (20, view.height_px as i32 - 24);
    root.draw(&PathElement::new(vec![(x0, y0), (x0 + bar, y0)], BLACK.stroke_width(3)))?;
    for k in 0..=4 {
        let x = x0 + bar * k / 4;
        root.draw(&PathElement::new(vec![(x, y0 - 6), (x, y0 + 1)], BLACK.stroke_width(2)))?;
    }
    root.draw(&Text::new(format!("{SCALE_BAR_IN:.0} in"), (x0 + bar + 10, y0 - 10), ("sans-serif", 18).into_font().color(&BLACK)))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_damage_scale_runs_grey_amber_red_and_clamps() {
        assert_eq!(damage_colour(0.0), RGBColor(205, 205, 205));
        assert_eq!(damage_colour(0.5), RGBColor(240, 190, 40));
        assert_eq!(damage_colour(1.0), RGBColor(140, 0, 0));
        assert_eq!(damage_colour(7.0), damage_colour(1.0));
        assert_eq!(damage_colour(-1.0), damage_colour(0.0));
    }
}
