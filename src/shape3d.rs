//! A projectile in 3D: the 2D outline ([`crate::shape::Projectile`], flat, hemispherical or
//! tangent-ogive nose) turned about its axis, filled with a sphere packing.
//!
//! The packing is made in the projectile's own frame (the axis along w from the tail at 0 to
//! the tip at L, u and v across it), as a dense random packing of the bounding box
//! [−D/2, D/2]² × [0, L], keeping the spheres that lie wholly inside the solid (a sphere of
//! radius r at distance ρ from the axis lies inside when the outline holds the disc of radius r
//! at (ρ, w): each cross-section of the outline is an interval about the axis). It is then
//! turned so that w points along `axis` and moved so that the tail is at `tail_m`.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::packing3d::{self, Box3, Packing};
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
    /// `bond_gap_ratio` as [`packing3d::random_dense`]), in the model's frame.
    pub fn packing(&self, radius_m: f64, seed: u64, bond_gap_ratio: f64) -> Result<Packing> {
        let a = 0.5 * self.diameter_m;
        let bounds = Box3 { x_min_m: -a, x_max_m: a, y_min_m: -a, y_max_m: a, z_min_m: 0.0, z_max_m: self.length_m };
        let full = packing3d::random_dense(&bounds, radius_m, seed, bond_gap_ratio)?;
        let mut p = full.keep(|c, r| self.holds(c, r), self.volume_m3());
        if p.centres_m.is_empty() {
            return Err(Error::input("element_radius_m", format!("{radius_m} m leaves no sphere inside the projectile")));
        }
        p.centres_m.iter_mut().for_each(|c| *c = self.to_world(*c));
        Ok(p)
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
            // The spheres fill the solid less densely than the box's packing fills its box: those
            // crossing the curved surface are cut away (a solid 20 R across keeps 0.46, against
            // 0.62 inside). Never more than the box's; and no less than the box's spheres whose
            // centres lie 1.2 R inside the surface (all kept), about 0.74 of it here.
            let solid: f64 = pk.radii_m.iter().map(|r| 4.0 / 3.0 * std::f64::consts::PI * r * r * r).sum();
            let fraction = solid / p.volume_m3();
            assert!((0.42..0.62).contains(&fraction), "{nose:?}: packing fraction {fraction}");
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
