//! A 3D scene made into a model: each body's packing, its contact class from its material, the
//! supports, loads and probes, and the step from the stability bound.
//!
//! Each body is its own sphere kind, so that its class is computed on its own packing's bond
//! density: B of the packing recipe (random dense, the body's seed and bond gap ratio) measured
//! on a reference cube of side [`REFERENCE_SIDE_R`] R, [`REFERENCE_MARGIN_R`] R in from its
//! faces, as `kernel3d::stiffness::MEASURED` was (the walls' looser layers reach about that
//! deep: 3 R in, B came out 5 % lower). B is dimensionless and fixed by the recipe, not by the
//! body's size or shape, so a body of any size or outline gets the same material.

use std::sync::Arc;

use super::{Packing3, Scene3};
use crate::error::{Error, Result};
use crate::kernel3d::law::Class;
use crate::kernel3d::solid::{RateContext, Solid};
use crate::kernel3d::vec3::{norm, sub};
use crate::kernel3d::{Builder, Model, solid, stiffness};
use crate::packing3d::{self, Box3, Packing};
use crate::simulation::{Built, Measure};

/// Side of the reference cube a packing recipe's bond density is measured on, × R.
pub const REFERENCE_SIDE_R: f64 = 24.0;

/// How far inside the reference cube's faces B is measured, × R.
pub const REFERENCE_MARGIN_R: f64 = 4.0;

/// The bond density B of random dense packings of mean radius `radius_m`, `seed` and
/// `bond_gap_ratio` (dimensionless).
pub fn recipe_bond_density(radius_m: f64, seed: u64, bond_gap_ratio: f64) -> Result<f64> {
    let s = REFERENCE_SIDE_R * radius_m;
    let cube = Box3 { x_min_m: 0.0, x_max_m: s, y_min_m: 0.0, y_max_m: s, z_min_m: 0.0, z_max_m: s };
    let p = packing3d::random_dense(&cube, radius_m, seed, bond_gap_ratio)?;
    let m = REFERENCE_MARGIN_R * radius_m;
    let inner = Box3 { x_min_m: m, x_max_m: s - m, y_min_m: m, y_max_m: s - m, z_min_m: m, z_max_m: s - m };
    Ok(stiffness::bond_density(&p.centres_m, &p.radii_m, &p.bonds, |x| inner.contains(x), inner.volume_m3()))
}

impl Scene3 {
    /// The material of body `k`.
    fn solid(&self, k: usize) -> &Solid {
        self.material.iter().find(|m| m.name == self.body[k].material).expect("validated: the material exists")
    }

    /// Build the model and its probes.
    pub fn build(&self) -> Result<Built<Model>> {
        self.build_with(Vec::new())
    }

    /// [`Scene3::build`], taking body k's packing from `packed[k]` where a caller already made
    /// it (it must be the one the body's fields make: the penetration slab places its
    /// projectile on the packing's front face, and the slab's packing is its costliest part).
    pub fn build_with(&self, mut packed: Vec<Option<Packing>>) -> Result<Built<Model>> {
        packed.resize_with(self.body.len(), || None);
        let kinds = self.body.len();
        // The fastest speed in the scene sets the rate part's default cap.
        let speed = |v: &[f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        let max_speed_mps = self.body.iter().map(|b| speed(&b.velocity_mps)).chain(self.fix.iter().map(|f| speed(&f.velocity_mps))).fold(0.0, f64::max);
        let mut packings: Vec<Packing> = Vec::with_capacity(kinds);
        let mut classes: Vec<Class> = Vec::with_capacity(kinds);
        for (k, b) in self.body.iter().enumerate() {
            let at = |e: Error| match e {
                Error::Input { file, field, message } => Error::Input { file, field: format!("body[{k}].{field}"), message },
                other => other,
            };
            let p = match packed[k].take() {
                Some(p) => Ok(p),
                None => match (b.packing, &b.region, &b.shape) {
                    (Packing3::RandomDense, Some(r), _) => match &b.grading {
                        Some(g) => packing3d::random_dense_graded(r, g, b.element_radius_m, b.seed, b.bond_gap_ratio),
                        None => packing3d::random_dense(r, b.element_radius_m, b.seed, b.bond_gap_ratio),
                    },
                    (Packing3::RandomDense, None, Some(s)) => s.packing(b.element_radius_m, b.seed, b.bond_gap_ratio),
                    (_, None, None) => unreachable!("validated: a box or a shape"),
                },
            }
            .map_err(at)?;
            let material = self.solid(k);
            let bd = recipe_bond_density(b.element_radius_m, b.seed, b.bond_gap_ratio).map_err(at)?;
            let r_max = p.radii_m.iter().copied().fold(0.0, f64::max);
            classes.push(material.class(bd, r_max, RateContext { max_speed_mps, radius_m: b.element_radius_m })?);
            packings.push(p);
        }
        let mut bld = Builder::new(kinds);
        for a in 0..kinds {
            for b in a..kinds {
                let class = if a == b {
                    classes[a].clone()
                } else {
                    let ctx = RateContext { max_speed_mps, radius_m: 0.5 * (self.body[a].element_radius_m + self.body[b].element_radius_m) };
                    solid::between((self.solid(a), &classes[a]), (self.solid(b), &classes[b]), ctx)
                };
                bld.class(a, b, class);
            }
        }
        let mirrors = self.mirrors();
        bld.mirrors = mirrors.clone();
        let mut velocities = Vec::with_capacity(kinds);
        for (k, (b, p)) in self.body.iter().zip(&packings).enumerate() {
            let material = self.solid(k);
            let range = bld.body(&b.name, &p.centres_m, &p.radii_m, k as u16, material.density_kg_per_m3);
            bld.weigh_cut_spheres(range.clone());
            bld.mass_total(range.clone(), material.density_kg_per_m3 * p.volume_m3);
            bld.damp_locally(range.clone(), b.local_damping_ratio);
            for &(i, j) in &p.bonds {
                bld.bond(range.start + i as usize, range.start + j as usize);
            }
            // Across the symmetry planes, the packing's own rule: a gap below the bond gap
            // ratio × the pair's mean nominal radius.
            let nominal = |c: [f64; 3]| b.grading.as_ref().map_or(b.element_radius_m, |g| g.radius_at(c, b.element_radius_m));
            let gap_max = b.bond_gap_ratio * b.grading.as_ref().map_or(b.element_radius_m, |g| g.max_radius_m);
            for (i, j, image) in mirrors.candidates(&p.centres_m, &p.radii_m, gap_max, false) {
                let (iu, ju) = (i as usize, j as usize);
                let (ci, cj) = (p.centres_m[iu], mirrors.point(p.centres_m[ju], image));
                let gap = norm(sub(cj, ci)) - p.radii_m[iu] - p.radii_m[ju];
                if image != 0 && gap < b.bond_gap_ratio * 0.5 * (nominal(p.centres_m[iu]) + nominal(p.centres_m[ju])) {
                    bld.bond_image(range.start + iu, range.start + ju, image);
                }
            }
            velocities.push((range, b.velocity_mps));
        }
        let centres: Vec<[f64; 3]> = packings.iter().flat_map(|p| p.centres_m.iter().copied()).collect();
        let inside = |b: &Box3| -> Vec<usize> { (0..centres.len()).filter(|&e| b.contains(centres[e])).collect() };
        let mut held = vec![false; centres.len()];
        for (k, f) in self.fix.iter().enumerate() {
            let group = inside(&f.region);
            if group.is_empty() {
                return Err(Error::input(format!("fix[{k}].box"), "holds no sphere centre"));
            }
            for e in group {
                bld.hold(e, f.velocity_mps);
                held[e] = true;
            }
        }
        // Each sphere's body (its material), for the boundary's impedance.
        let body_of: Vec<usize> = packings.iter().enumerate().flat_map(|(k, p)| std::iter::repeat_n(k, p.centres_m.len())).collect();
        let radii: Vec<f64> = packings.iter().flat_map(|p| p.radii_m.iter().copied()).collect();
        for (k, a) in self.absorb.iter().enumerate() {
            let layer: Vec<usize> = inside(&a.region).into_iter().filter(|&e| !held[e]).collect();
            if layer.is_empty() {
                return Err(Error::input(format!("absorb[{k}].box"), "holds no free sphere centre"));
            }
            for (&e, c) in layer.iter().zip(a.dashpots_kg_per_s(&layer, &radii, |e| self.solid(body_of[e]))) {
                bld.dashpot(e, c);
            }
        }
        for (k, l) in self.load.iter().enumerate() {
            let group: Vec<usize> = inside(&l.region).into_iter().filter(|&e| !held[e]).collect();
            if group.is_empty() {
                return Err(Error::input(format!("load[{k}].box"), "holds no free sphere centre"));
            }
            let share = l.force_n.map(|f| f / group.len() as f64);
            for e in group {
                bld.load(e, share, [0.0; 3]);
            }
        }
        let mut probes: Vec<Arc<dyn Measure<Model>>> = Vec::with_capacity(self.probe.len());
        for (k, p) in self.probe.iter().enumerate() {
            let mut p = p.clone();
            if let Some(b) = &p.region {
                p.spheres = inside(b);
                if p.spheres.is_empty() {
                    return Err(Error::input(format!("probe[{k}].box"), "holds no sphere centre"));
                }
            }
            probes.push(Arc::new(p));
        }
        // When a material reads its rate over a length, every body with a rate law is smoothed
        // over the shortest such length (as in 2D, `kernel::build`).
        let length = self.material.iter().filter_map(|m| m.rate.and_then(|r| r.averaging_length())).fold(f64::INFINITY, f64::min);
        if length.is_finite() {
            let smoothed = (0..kinds).filter(|&k| self.solid(k).rate.is_some()).map(|k| k as u16).collect();
            bld.rate_averaging = Some((length, smoothed));
        }
        let t = &self.time_step;
        bld.alpha_per_s = self.damping.alpha_per_s;
        bld.safety = t.safety;
        bld.skin_ratio = t.skin_ratio;
        bld.dt_s = t.dt_s;
        let model = bld.build(&velocities)?;
        if model.motion.dt_s > model.dt_bound_s {
            return Err(Error::input(
                "time_step.dt_s",
                format!("{:.4e} s is above the stability bound {:.4e} s of this scene's contacts", model.motion.dt_s, model.dt_bound_s),
            ));
        }
        let every_steps = self.output.every_steps;
        Ok(Built { name: self.scene.name.clone(), model, probes, duration_s: self.scene.duration_s, every_steps })
    }
}
