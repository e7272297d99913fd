//! A projectile in 3D: the 2D outline ([`crate::shape::Projectile`], flat, hemispherical or
//! tangent-ogive nose) turned about its axis, filled with a sphere packing.
//!
//! The packing is made in the projectile's own frame (the axis along w from the tail at 0 to
//! the tip at L, u and v across it), as a dense random packing inflated against the solid's own
//! surface (`packing3d::random_dense_in`: the tail disc, the side, the nose's flat or arc),
//! so its surface layer is as dense as a box's face. A sphere of radius r at distance ρ from
//! the axis lies inside when the outline holds the disc of radius r at (ρ, w): each
//! cross-section of the outline is an interval about the axis. The packing is then turned so
//! that w points along `axis` and moved so that the tail is at `tail_m`.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::packing3d::{self, Box3, Packing, Walls};
use crate::shape::{Nose, Projectile};

/// A projectile's solid of revolution.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Projectile3 {
    /// The point of the axis at the tail, m.
    pub tail_m: [f64; 3],
    /// Direction of the axis from the tail to the nose (normalised when used).
    pub axis: [f64; 3],
    /// Diameter (calibre) D, m.
    pub diameter_m: f64,
    /// Length from the tail to the nose tip L, m.
    pub length_m: f64,
    /// Nose shape.
    pub nose: Nose,
    /// Calibre-radius-head of an ogive nose (≥ 0.5).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crh: Option<f64>,
}

impl Projectile3 {
    /// The meridian outline (x from the axis, y along it), on which the 2D rules act.
    fn outline(&self) -> Projectile {
        Projectile { tail_m: [0.0, 0.0], axis: [0.0, 1.0], width_m: self.diameter_m, length_m: self.length_m, nose: self.nose, crh: self.crh }
    }

    /// Check the solid; `field` names it in messages.
    pub fn validate(&self, field: &str) -> Result<()> {
        let n = self.axis.iter().map(|a| a * a).sum::<f64>().sqrt();
        if !(n.is_finite() && n > 0.0 && self.tail_m.iter().all(|v| v.is_finite())) {
            return Err(Error::input(format!("{field}.axis"), "needs a finite, non-zero direction and a finite tail point"));
        }
        self.outline().validate(field).map_err(|e| match e {
            Error::Input { file, field, message } => Error::Input { file, field: field.replace("width_m", "diameter_m"), message },
            other => other,
        })
    }

    /// Length of the nose along the axis, m.
    pub fn nose_length_m(&self) -> f64 {
        self.outline().nose_length_m()
    }

    /// Volume, m³: the cylinder behind the nose and the nose's solid of revolution.
    pub fn volume_m3(&self) -> f64 {
        let a = 0.5 * self.diameter_m;
        let l = self.nose_length_m();
        let pi = std::f64::consts::PI;
        let nose = match self.nose {
            Nose::Flat => 0.0,
            Nose::Hemispherical => 2.0 / 3.0 * pi * a * a * a,
            Nose::Ogive => {
                // π ∫₀ˡ (√(s² − z²) − (s − a))² dz with s = CRH × D.
                let s = self.crh.unwrap_or(0.5) * self.diameter_m;
                let off = s - a;
                let arc = 0.5 * (l * (s * s - l * l).max(0.0).sqrt() + s * s * (l / s).asin());
                pi * ((s * s + off * off) * l - l * l * l / 3.0 - 2.0 * off * arc)
            }
        };
        pi * a * a * (self.length_m - l) + nose
    }

    /// The unit axis and two unit vectors across it (a right-handed frame u, v, w).
    fn frame(&self) -> [[f64; 3]; 3] {
        let n = self.axis.iter().map(|a| a * a).sum::<f64>().sqrt();
        let w = self.axis.map(|a| a / n);
        // Across: the coordinate axis least aligned with w, made normal to it.
        let k = (0..3).min_by(|&a, &b| w[a].abs().total_cmp(&w[b].abs())).expect("three axes");
        let mut e = [0.0; 3];
        e[k] = 1.0;
        let d = e[k] * w[k];
        let u0 = [e[0] - d * w[0], e[1] - d * w[1], e[2] - d * w[2]];
        let un = u0.iter().map(|a| a * a).sum::<f64>().sqrt();
        let u = u0.map(|a| a / un);
        let v = [w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0]];
        [u, v, w]
    }

    /// A point of the projectile's frame (u, v across, w along the axis from the tail) in the
    /// model's, m.
    pub fn to_world(&self, local: [f64; 3]) -> [f64; 3] {
        let [u, v, w] = self.frame();
        std::array::from_fn(|k| self.tail_m[k] + local[0] * u[k] + local[1] * v[k] + local[2] * w[k])
    }

    /// The nose tip in the model's frame, m.
    pub fn tip_m(&self) -> [f64; 3] {
        self.to_world([0.0, 0.0, self.length_m])
    }

    /// True when a sphere of radius `r_m` at `local` (the projectile's frame) lies inside.
    pub fn holds(&self, local: [f64; 3], r_m: f64) -> bool {
        self.outline().holds(local[0].hypot(local[1]), local[2], r_m)
    }

    /// The projectile as a dense random packing of spheres of mean radius `radius_m` (`seed`,
    /// `bond_gap_ratio` as [`packing3d::random_dense`]) inflated against its own surface, in
    /// the model's frame.
    pub fn packing(&self, radius_m: f64, seed: u64, bond_gap_ratio: f64) -> Result<Packing> {
        if !(radius_m.is_finite() && radius_m > 0.0 && 2.4 * radius_m < self.diameter_m.min(self.length_m)) {
            return Err(Error::input("radius_m", format!("{radius_m} m: a sphere of 1.2 of it must fit across the projectile ({} m)", self.diameter_m.min(self.length_m))));
        }
        let mut p = packing3d::random_dense_in(self, radius_m, seed, bond_gap_ratio)?;
        p.centres_m.iter_mut().for_each(|c| *c = self.to_world(*c));
        Ok(p)
    }

    /// Half-width of the outline at `w` along the axis (0 ≤ w ≤ L), m.
    fn half_width_m(&self, w: f64) -> f64 {
        let (a, base) = (0.5 * self.diameter_m, self.length_m - self.nose_length_m());
        if w <= base {
            return a;
        }
        match self.nose {
            Nose::Flat => a,
            Nose::Hemispherical => (a * a - (w - base).powi(2)).max(0.0).sqrt(),
            Nose::Ogive => {
                let s = self.crh.unwrap_or(0.5) * self.diameter_m;
                ((s * s - (w - base).powi(2)).max(0.0).sqrt() - (s - a)).max(0.0)
            }
        }
    }

    /// Surface area, m²: the tail disc, the side and the nose (a flat nose's disc), summed
    /// over thin frusta of the outline.
    pub fn area_m2(&self) -> f64 {
        let a = 0.5 * self.diameter_m;
        let pi = std::f64::consts::PI;
        let n = 4000;
        let dw = self.length_m / n as f64;
        let side: f64 = (0..n)
            .map(|k| {
                let (h0, h1) = (self.half_width_m(k as f64 * dw), self.half_width_m((k + 1) as f64 * dw));
                pi * (h0 + h1) * dw.hypot(h1 - h0)
            })
            .sum();
        let front = if self.nose == Nose::Flat { pi * a * a } else { 0.0 };
        pi * a * a + side + front
    }
}

/// The solid as walls for the packing (in its own frame: u, v across, w along the axis).
impl Walls for Projectile3 {
    fn bounds(&self) -> Box3 {
        let a = 0.5 * self.diameter_m;
        Box3 { x_min_m: -a, x_max_m: a, y_min_m: -a, y_max_m: a, z_min_m: 0.0, z_max_m: self.length_m }
    }
    fn volume_m3(&self) -> f64 {
        Projectile3::volume_m3(self)
    }
    fn filled_m3(&self, layer_m: f64) -> f64 {
        Projectile3::volume_m3(self) - self.area_m2() * layer_m
    }
    fn holds(&self, c: [f64; 3], r_m: f64) -> bool {
        Projectile3::holds(self, c, r_m)
    }
    fn push(&self, c: [f64; 3], r_m: f64) -> ([f64; 3], f64) {
        let (a, l) = (0.5 * self.diameter_m, self.length_m);
        let base = l - self.nose_length_m();
        let rho = c[0].hypot(c[1]);
        // The outward radial direction (any, on the axis).
        let e = if rho > 0.0 { [c[0] / rho, c[1] / rho] } else { [1.0, 0.0] };
        // Each wall's overlap and its push in the meridian plane (radial, axial).
        let mut pushes: [(f64, [f64; 2]); 3] = [((r_m - c[2]).max(0.0), [0.0, 1.0]), (0.0, [0.0; 2]), (0.0, [0.0; 2])];
        if c[2] <= base || self.nose == Nose::Flat {
            pushes[1] = ((rho + r_m - a).max(0.0), [-1.0, 0.0]);
        }
        match self.nose {
            Nose::Flat => pushes[2] = ((c[2] + r_m - l).max(0.0), [0.0, -1.0]),
            // The nose's arc, seen from its centre in the meridian plane: (0, base) for the
            // hemisphere, (−(s − a), base) for the ogive (the arc bounding this side).
            Nose::Hemispherical | Nose::Ogive if c[2] > base => {
                let s = if self.nose == Nose::Ogive { self.crh.unwrap_or(0.5) * self.diameter_m } else { a };
                let (dx, dw) = (rho + (s - a), c[2] - base);
                let d = dx.hypot(dw);
                if d > 0.0 {
                    pushes[2] = ((d + r_m - s).max(0.0), [-dx / d, -dw / d]);
                }
            }
            _ => {}
        }
        let (mut f, mut worst) = ([0.0; 3], 0.0f64);
        for (overlap, [radial, axial]) in pushes {
            f[0] += overlap * radial * e[0];
            f[1] += overlap * radial * e[1];
            f[2] += overlap * axial;
            worst = worst.max(overlap);
        }
        (f, worst)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn projectile(nose: Nose, crh: Option<f64>, axis: [f64; 3]) -> Projectile3 {
        Projectile3 { tail_m: [0.1, 0.2, 0.3], axis, diameter_m: 0.08, length_m: 0.2, nose, crh }
    }

    #[test]
    fn an_ogive_of_half_a_calibre_is_the_hemisphere_and_volumes_match_quadrature() {
        let h = projectile(Nose::Hemispherical, None, [0.0, 0.0, 1.0]);
        let o = projectile(Nose::Ogive, Some(0.5), [0.0, 0.0, 1.0]);
        assert!((h.volume_m3() - o.volume_m3()).abs() < 1e-15, "{} {}", h.volume_m3(), o.volume_m3());
        // The surface: tail disc, side and half sphere, π a² + 2π a (L − a) + 2π a².
        let a = 0.5 * h.diameter_m;
        let area = std::f64::consts::PI * a * (a + 2.0 * (h.length_m - a) + 2.0 * a);
        assert!((h.area_m2() / area - 1.0).abs() < 1e-6, "{} against {area}", h.area_m2());
        // The solid's volume by a midpoint sum over thin discs of the outline's half-width.
        for p in [h, projectile(Nose::Flat, None, [1.0, 0.0, 0.0]), projectile(Nose::Ogive, Some(3.0), [0.0, -1.0, 0.0])] {
            let n = 200_000;
            let dz = p.length_m / n as f64;
            let sum: f64 = (0..n)
                .map(|k| {
                    let z = (k as f64 + 0.5) * dz;
                    // Half-width at z: the largest ρ the outline holds (bisection on a point disc).
                    let (mut lo, mut hi) = (0.0, 0.5 * p.diameter_m);
                    for _ in 0..60 {
                        let mid = 0.5 * (lo + hi);
                        if p.holds([mid, 0.0, z], 0.0) { lo = mid } else { hi = mid }
                    }
                    std::f64::consts::PI * lo * lo * dz
                })
                .sum();
            assert!((sum / p.volume_m3() - 1.0).abs() < 1e-6, "{:?}: quadrature {sum} against {}", p.nose, p.volume_m3());
        }
    }

    #[test]
    fn every_sphere_lies_inside_the_solid_and_the_tip_points_along_the_axis() {
        let r = 0.004;
        for (nose, crh, axis) in [(Nose::Flat, None, [0.0, 0.0, -1.0]), (Nose::Hemispherical, None, [1.0, 1.0, 0.0]), (Nose::Ogive, Some(2.0), [0.0, 1.0, 0.0])] {
            let p = projectile(nose, crh, axis);
            let pk = p.packing(r, 3, 0.1).unwrap();
            let [u, v, w] = p.frame();
            for (c, &ri) in pk.centres_m.iter().zip(&pk.radii_m) {
                let d: [f64; 3] = std::array::from_fn(|k| c[k] - p.tail_m[k]);
                let local = [0, 1, 2].map(|a| [u, v, w][a].iter().zip(&d).map(|(x, y)| x * y).sum::<f64>());
                assert!(p.holds(local, ri * (1.0 - 1e-9)), "{nose:?}: sphere at {c:?} pokes out");
            }
            // The spheres fill the solid as densely as a box of its bounds is filled (both with
            // a looser layer at their walls); cut from the box's packing instead, the solid 20 R
            // across kept 0.46.
            let vol = |radii: &[f64]| radii.iter().map(|r| 4.0 / 3.0 * std::f64::consts::PI * r * r * r).sum::<f64>();
            let fraction = vol(&pk.radii_m) / p.volume_m3();
            let bounds = Walls::bounds(&p);
            let in_box = vol(&packing3d::random_dense(&bounds, r, 3, 0.1).unwrap().radii_m) / bounds.volume_m3();
            println!("{nose:?}: {} spheres, packing fraction {fraction:.4} (its bounding box's packing {in_box:.4})", pk.centres_m.len());
            assert!((fraction - in_box).abs() < 0.02, "{nose:?}: packing fraction {fraction} against {in_box} in a box");
            // Bonds join spheres that remain.
            assert!(pk.bonds.iter().all(|&(i, j)| (i as usize) < pk.centres_m.len() && (j as usize) < pk.centres_m.len() && i < j));
            let tip = p.tip_m();
            let n = axis.iter().map(|a| a * a).sum::<f64>().sqrt();
            for k in 0..3 {
                assert!((tip[k] - (p.tail_m[k] + p.length_m * axis[k] / n)).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn a_bad_solid_is_refused_naming_its_field() {
        let mut p = projectile(Nose::Ogive, None, [0.0, 0.0, 1.0]);
        let e = p.validate("body.shape").unwrap_err().to_string();
        assert!(e.contains("body.shape.crh"), "{e}");
        p.crh = Some(3.0);
        p.axis = [0.0; 3];
        assert!(p.validate("body.shape").unwrap_err().to_string().contains("body.shape.axis"));
        p.axis = [0.0, 0.0, 1.0];
        p.length_m = 0.01;
        assert!(p.validate("body.shape").unwrap_err().to_string().contains("body.shape.length_m"));
    }
}
