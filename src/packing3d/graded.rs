//! A graded dense random packing: sphere sizes that grow with the distance from an axis, so a
//! solid is fine where it breaks (under an impact) and coarse where it only carries load.
//!
//! The same recipe as [`super::random_dense`] (a dilute start grown apart by FIRE relaxation),
//! with the radii drawn from a size field r(x) instead of one R: a point is kept with
//! probability (r₀ / r(x))³, so every region holds the same volume fraction of spheres, and its
//! sphere gets a radius uniform in r(x) (1 ± [`RADIUS_SPREAD`]). Bonds form where the gap is
//! below the bond gap ratio times the pair's mean field radius, the uniform recipe's rule at the
//! local size. Deterministic: plain f64 arithmetic in a fixed order from a seeded generator.

use serde::{Deserialize, Serialize};

use super::{DENSE_FRACTION, Packing, RADIUS_SPREAD, WALL_LAYER, Walls, bonds_within_by, check_count, grow_apart, layer_order};
use crate::error::{Error, Result};
use crate::lattice::SplitMix64;
use std::f64::consts::PI;

/// Sphere sizes graded about an axis: the finest mean radius r₀ (given with the grading, a
/// body's `element_radius_m`) within `core_m` of the axis, growing by `growth` per unit
/// distance beyond it, up to `max_radius_m`. A scene's `[body.grading]`.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Grading {
    /// A point on the axis [x, y, z], m.
    pub point_m: [f64; 3],
    /// The axis's direction (any length but zero).
    pub axis: [f64; 3],
    /// Distance from the axis within which the radius is the finest, m.
    pub core_m: f64,
    /// Growth of the mean radius per unit distance beyond the core, m/m (dimensionless).
    pub growth: f64,
    /// Largest mean radius, m.
    pub max_radius_m: f64,
}

/// Points drawn to measure the volume the spheres fill (the walls' loose first layer taken off
/// at the local size): a relative error of about 0.2 %.
const VOLUME_SAMPLES: usize = 200_000;

impl Grading {
    /// Check the fields for a finest radius `radius_m` (m); `field` names the grading in
    /// messages.
    pub fn validate(&self, field: &str, radius_m: f64) -> Result<()> {
        let finite = self.point_m.iter().chain(&self.axis).all(|v| v.is_finite());
        let len = self.axis.iter().map(|a| a * a).sum::<f64>().sqrt();
        if !finite || !(len > 0.0) {
            return Err(Error::input(format!("{field}.axis"), format!("needs a finite point and a non-zero axis, got {:?} and {:?}", self.point_m, self.axis)));
        }
        for (f, v) in [("radius_m", radius_m), ("max_radius_m", self.max_radius_m)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::input(format!("{field}.{f}"), format!("must be a finite number > 0, got {v}")));
            }
        }
        for (f, v) in [("core_m", self.core_m), ("growth", self.growth)] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(Error::input(format!("{field}.{f}"), format!("must be a finite number ≥ 0, got {v}")));
            }
        }
        if self.max_radius_m < radius_m {
            return Err(Error::input(format!("{field}.max_radius_m"), format!("{} m is below the core's radius {radius_m} m", self.max_radius_m)));
        }
        Ok(())
    }

    /// The mean sphere radius at `c` (m) for a finest radius `radius_m`, m.
    pub fn radius_at(&self, c: [f64; 3], radius_m: f64) -> f64 {
        let a = self.axis;
        let len2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
        let d: [f64; 3] = std::array::from_fn(|k| c[k] - self.point_m[k]);
        let along = (d[0] * a[0] + d[1] * a[1] + d[2] * a[2]) / len2;
        let off = (0..3).map(|k| (d[k] - along * a[k]).powi(2)).sum::<f64>().sqrt();
        (radius_m + self.growth * (off - self.core_m).max(0.0)).min(self.max_radius_m)
    }
}

/// A dense random packing of the walls whose sphere sizes follow `grading` from the finest
/// mean radius `radius_m` (m; see the module); `bond_gap_ratio` in [0, 1] as in
/// [`super::random_dense`].
pub fn random_dense_graded(walls: &dyn Walls, grading: &Grading, radius_m: f64, seed: u64, bond_gap_ratio: f64) -> Result<Packing> {
    if !(bond_gap_ratio.is_finite() && (0.0..=1.0).contains(&bond_gap_ratio)) {
        return Err(Error::input("bond_gap_ratio", format!("must lie in [0, 1], got {bond_gap_ratio}")));
    }
    grading.validate("grading", radius_m)?;
    let b = walls.bounds();
    let (lo, hi) = (b.lo(), b.hi());
    let at = |rng: &mut SplitMix64| -> [f64; 3] { std::array::from_fn(|k| lo[k] + rng.unit() * (hi[k] - lo[k])) };
    // The volume to fill: the walls less their loose first layer, 0.4 r(x) thick where x is.
    let mut mc = SplitMix64(seed ^ 0x5EED_3D5F_E7E5_0003);
    let held = (0..VOLUME_SAMPLES)
        .filter(|_| {
            let c = at(&mut mc);
            walls.holds(c, WALL_LAYER * grading.radius_at(c, radius_m))
        })
        .count();
    let target_m3 = DENSE_FRACTION * b.volume_m3() * held as f64 / VOLUME_SAMPLES as f64;
    let s0 = (0.25 / DENSE_FRACTION).cbrt();
    let r0 = radius_m;
    let mut rng = SplitMix64(seed ^ 0x5EED_3D5F_E7E5_0002);
    let (mut centres, mut radii, mut total, mut misses) = (Vec::new(), Vec::new(), 0.0, 0usize);
    loop {
        let c = at(&mut rng);
        let rc = grading.radius_at(c, r0);
        // Kept r₀³/r³ as often as the finest: the same volume of spheres in every region.
        if rng.unit() >= (r0 / rc).powi(3) {
            continue;
        }
        let ri = rc * (1.0 - RADIUS_SPREAD + 2.0 * RADIUS_SPREAD * rng.unit());
        let in_bounds = (0..3).all(|k| c[k] >= lo[k] + s0 * ri && c[k] <= hi[k] - s0 * ri);
        if !in_bounds || !walls.may_start(c, s0 * ri) {
            misses += 1;
            if misses > 10_000_000 {
                return Err(Error::input("grading", "no room for the spheres in the walls after 10 000 000 draws"));
            }
            continue;
        }
        let v = 4.0 / 3.0 * PI * ri.powi(3);
        if total + v > target_m3 && !radii.is_empty() {
            break;
        }
        total += v;
        centres.push(c);
        radii.push(ri);
        check_count(radii.len())?;
    }
    let (centres, radii) = grow_apart(walls, centres, radii, r0, (1.0 + RADIUS_SPREAD) * grading.max_radius_m, s0);
    let (centres, radii) = layer_order(centres, radii, lo, 2.0 * r0);
    let nominal: Vec<f64> = centres.iter().map(|&c| grading.radius_at(c, r0)).collect();
    let bonds = bonds_within_by(&centres, &radii, bond_gap_ratio * grading.max_radius_m, |i, j| bond_gap_ratio * 0.5 * (nominal[i] + nominal[j]));
    Ok(Packing { centres_m: centres, radii_m: radii, bonds, volume_m3: walls.volume_m3() })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::packing3d::{Box3, fabric};

    fn slab() -> (Box3, Grading) {
        let b = Box3 { x_min_m: 0.0, x_max_m: 40.0, y_min_m: 0.0, y_max_m: 12.0, z_min_m: 0.0, z_max_m: 40.0 };
        let g = Grading { point_m: [20.0, 0.0, 20.0], axis: [0.0, 1.0, 0.0], core_m: 5.0, growth: 0.2, max_radius_m: 1.0 };
        (b, g)
    }

    #[test]
    fn the_radius_field_is_the_core_then_the_ramp_then_the_cap() {
        let (_, g) = slab();
        assert_eq!(g.radius_at([20.0, 5.0, 24.0], 0.5), 0.5);
        assert!((g.radius_at([27.0, 1.0, 20.0], 0.5) - 0.9).abs() < 1e-12);
        assert_eq!(g.radius_at([0.0, 1.0, 0.0], 0.5), 1.0);
    }

    #[test]
    fn a_graded_packing_is_as_dense_as_a_uniform_one_in_its_fine_and_coarse_parts() {
        let (b, g) = slab();
        let p = random_dense_graded(&b, &g, 0.5, 7, 0.1).unwrap();
        // Same bits on a second run.
        assert_eq!(p, random_dense_graded(&b, &g, 0.5, 7, 0.1).unwrap());
        // Each region against the uniform recipe at its size, same box and seed: the density of
        // spheres and of bonds (B = Σ r̄ l² / V, which sets the stiffness). Measured: fraction
        // 0.616 / 0.572 against 0.616 / 0.550, B 3.7 % and 3.3 % below the uniform's.
        for (name, inner, r) in [
            ("core", Box3 { x_min_m: 17.0, x_max_m: 23.0, y_min_m: 2.0, y_max_m: 10.0, z_min_m: 17.0, z_max_m: 23.0 }, 0.5),
            ("coarse", Box3 { x_min_m: 3.0, x_max_m: 11.0, y_min_m: 3.0, y_max_m: 9.0, z_min_m: 3.0, z_max_m: 11.0 }, 1.0),
        ] {
            let uniform = crate::packing3d::random_dense(&b, r, 7, 0.1).unwrap();
            let (f, u) = (fabric(&p, &inner), fabric(&uniform, &inner));
            let bd = |q: &Packing| crate::kernel3d::stiffness::bond_density(&q.centres_m, &q.radii_m, &q.bonds, |x| inner.contains(x), inner.volume_m3());
            let (bg, bu) = (bd(&p), bd(&uniform));
            let inside: Vec<f64> = p.radii_m.iter().zip(&p.centres_m).filter(|(_, c)| inner.contains(**c)).map(|(r, _)| *r).collect();
            let mean_r = inside.iter().sum::<f64>() / inside.len() as f64;
            assert!((mean_r / r - 1.0).abs() < 0.05, "{name}: mean radius {mean_r} against {r}");
            assert!((f.packing_fraction - u.packing_fraction).abs() < 0.04, "{name}: fraction {} against {}", f.packing_fraction, u.packing_fraction);
            assert!((bg / bu - 1.0).abs() < 0.06, "{name}: bond density {bg} against {bu}");
            assert!(f.eigen_ratio < 1.2, "{name}: fabric eigenvalue ratio {}", f.eigen_ratio);
        }
        // Every sphere inside, none overlapping.
        for (c, r) in p.centres_m.iter().zip(&p.radii_m) {
            assert!(b.contains([c[0] - r, c[1] - r, c[2] - r]) && b.contains([c[0] + r, c[1] + r, c[2] + r]));
        }
        let worst = p.bonds.iter().map(|&(i, j)| {
            let (i, j) = (i as usize, j as usize);
            p.radii_m[i] + p.radii_m[j] - super::super::dist(p.centres_m[i], p.centres_m[j])
        }).fold(0.0, f64::max);
        assert!(worst < 1e-6 * 0.5, "overlap {worst}");
    }
}
