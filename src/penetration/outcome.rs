//! What a penetration run did: penetration depth, scabbing, perforation, front-face spall, and
//! when the run is settled. Reads the model, never changes it.
//!
//! Definitions (the front face is the top of the target's top row of disks at the start; the
//! back face y = 0; the projectile comes from above; "attached" material is connected through
//! intact bonds to a support):
//! * **penetration depth**: the deepest point of the projectile (its lowest disk's bottom) below
//!   the original front face, the largest over the run. **Relative depth**: the same less the
//!   beam's own deflection under the impact point (the mean downward displacement of the
//!   attached back-face elements within half a projectile width of the impact point), the
//!   largest over the run: what a crater gauge on a bending beam would read.
//! * **fragment**: a connected set of target elements over intact bonds (a union-find), or a
//!   single element, that holds no supported element.
//! * **scabbing**: a crater in the back face, at least `scab_crater_calibres` projectile widths
//!   across. A scab fragment is a fragment holding back-face material (elements that started
//!   within one element diameter of the back face) moving away from the back face, i.e.
//!   downward faster than the attached back face beside it (within one projectile width) by
//!   more than `separation_fps`; or any fragment whose centre has passed the original back face
//!   (material that left through it, ahead of or with the projectile, whatever its speed). The
//!   **back-face crater** is the part of the back face the scab fragments took: each back-face
//!   element carries its share of the face's area in proportion to its section (r² in 3D; in
//!   the 2D slice, its share of the face's width in proportion to r), and the crater's diameter
//!   is that of the circle of the area taken (in 2D, the width taken). A single element is then
//!   a crater of about its own diameter, never a scab while elements are finer than the
//!   calibre, at any level. A perforation holes the back face, so a perforated run is a scabbed
//!   run too, from its first look through at the latest, even when nothing came loose (a beam
//!   split in two under the projectile): in any sweep the first scabbing is at or below the
//!   first perforation. Reported: the crater's largest diameter, the number of scab fragments
//!   and their mass at the end, and the first time the back face scabbed.
//! * **front-face spall (crater)**: the same for front-face material moving up, away from the
//!   front face.
//! * **perforation**: the projectile's rearmost point below the original back face and below
//!   every attached target element within the projectile's width: wholly past the back face.
//!   Residual velocity: the speed of the projectile's centre of mass, when first perforated and
//!   at the end.
//! * **settled** (the stop rule): the projectile has turned back (`rebounded`: its centre moves
//!   out along the impact axis, or away from the front face: a glancing ricochet) or stopped (`embedded`: its centre's speed is below 1 % of the
//!   impact speed), and the attached target has been quiet for `quiet_s` (its count of intact
//!   bonds has not changed: no crack grew and nothing came loose; debris grinding against
//!   debris does not count); or the projectile perforated and has been clear of the back face,
//!   by two element diameters, for `quiet_s` (`perforated`), time for the back face to shed
//!   what the exit loosened; or the projectile has gone on into the target at a steady speed
//!   (within `unresisted_change` of it, at ≥ 1 % of the impact speed) for `unresisted_s`, its
//!   nose going in at least half as fast as its centre (`unresisted`): nothing pushes on it,
//!   so the target has given way and cannot stop it. It
//!   is then perforated (and scabbed) from the start of that stretch, with that speed as its
//!   residual: in the 2D slice this is the beam broken into a mechanism, its halves swinging
//!   away with the projectile between them, which a time cap would call lodged or perforated
//!   depending only on how long it waited. A run that never settles ends at its time cap
//!   (`time_cap`); the outcome is then what was seen up to the cap.


use std::ops::Range;

use serde::{Deserialize, Serialize};

use crate::penetration::scene::{Layout, OutcomeSpec};
use crate::error::{Error, Result};
use crate::run::StopRule;
use crate::simulation::Bodies;
use crate::units::{M_PER_IN, fps_to_mps, kg_to_lb, mps_to_fps};

use super::fragments;
pub use super::fragments::{Fragment, UnionFind};

/// The outcome of a run, as the summary row reports it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Outcome {
    /// Peak depth of the nose below the original front face, in.
    pub depth_in: f64,
    /// Peak depth less the beam's deflection under the impact point, in.
    pub depth_rel_in: f64,
    /// When the peak depth was reached, s.
    pub depth_time_s: f64,
    /// The back face scabbed: its crater reached `outcome.scab_crater_calibres` projectile
    /// widths across, or the projectile went through.
    pub scabbed: bool,
    /// The back-face crater's diameter at its largest, in: the diameter of the circle of the
    /// back face's area that its scab fragments took (in 2D, the width of the slice's back
    /// face they took).
    pub back_crater_in: f64,
    /// The scab fragments' mass at the end, lb (per the mapping's slice).
    pub scab_mass_lb: f64,
    /// Their number at the end.
    pub scab_fragments: u64,
    /// First time the back face scabbed (its crater at the threshold, or the perforation), s
    /// (empty: never).
    pub scab_time_s: Option<f64>,
    /// The projectile went through.
    pub perforated: bool,
    /// Its centre's speed when it first was through, ft/s (0 when not).
    pub v_residual_fps: f64,
    /// When it first was through, s.
    pub perforation_time_s: Option<f64>,
    /// Its centre's speed at the end, ft/s.
    pub v_final_fps: f64,
    /// Front-face spall (crater) mass at the end, lb.
    pub spall_mass_lb: f64,
    /// Front-face spall fragments at the end.
    pub spall_fragments: u64,
    /// First time spall was seen, s.
    pub spall_time_s: Option<f64>,
    /// Share of the target's bonds lying beyond [`FAR_CALIBRES`] projectile widths of the
    /// impact axis that broke (their midpoints' distance at the start).
    pub far_bonds_broken_fraction: f64,
}

/// Where "far from the path" begins, in projectile widths from the impact axis: a wall's
/// damage should stay within a crater, a tunnel and a scab cone.
pub const FAR_CALIBRES: f64 = 4.0;

/// What the detector keeps between looks (it travels in checkpoints).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Tracking {
    /// Peak depth so far, m.
    pub depth_m: f64,
    /// When, s.
    pub depth_time_s: f64,
    /// Peak relative depth so far, m.
    pub depth_rel_m: f64,
    /// First scab, s.
    pub scab_time_s: Option<f64>,
    /// The back-face crater's largest diameter so far, m.
    #[serde(default)]
    pub back_crater_m: f64,
    /// First spall, s.
    pub spall_time_s: Option<f64>,
    /// First perforation, s.
    pub perforation_time_s: Option<f64>,
    /// Projectile speed then, m/s.
    pub v_residual_mps: f64,
    /// Intact bonds of the attached target at the last look.
    pub attached_bonds: u64,
    /// Last look at which that count had changed, s.
    pub last_break_s: f64,
    /// Since when the projectile has been clear of the back face, s.
    pub clear_since_s: Option<f64>,
    /// Since when (s) the projectile has gone on into the target at about one axial speed
    /// (m/s), and its depth then (m): the start of an unresisted stretch.
    #[serde(default)]
    pub unresisted_since: Option<(f64, f64, f64)>,
}

/// One look at the model, reduced to what the outcome and the stop rule need.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Look {
    /// Time, s.
    pub time_s: f64,
    /// Depth of the projectile's lowest point below the front face, m.
    pub depth_m: f64,
    /// The beam's deflection under the impact point (down positive), m.
    pub deflection_m: f64,
    /// Scab fragments, their mass (kg).
    pub scab: (u64, f64),
    /// The back-face crater's diameter, m (`Outcome::back_crater_in`).
    pub back_crater_m: f64,
    /// ... and it is wide enough to be a scab (`OutcomeSpec::scab_crater_calibres`).
    pub scabs: bool,
    /// Spall fragments, their mass (kg).
    pub spall: (u64, f64),
    /// The projectile is wholly past the back face.
    pub through: bool,
    /// ... and has cleared it by two element diameters.
    pub clear: bool,
    /// Its centre's velocity along the impact axis, m/s (> 0 going in).
    pub v_axial_mps: f64,
    /// Its centre's velocity into the target across the front face, m/s (> 0 going in).
    pub v_face_mps: f64,
    /// Its centre's speed, m/s.
    pub speed_mps: f64,
    /// Intact bonds between attached target elements.
    pub attached_bonds: u64,
}

impl Tracking {
    /// Take in a look; returns why the run is settled, if it is.
    pub fn observe(&mut self, l: &Look, spec: &OutcomeSpec, v0_mps: f64) -> Option<&'static str> {
        if l.depth_m > self.depth_m {
            self.depth_m = l.depth_m;
            self.depth_time_s = l.time_s;
        }
        self.depth_rel_m = self.depth_rel_m.max(l.depth_m - l.deflection_m);
        self.back_crater_m = self.back_crater_m.max(l.back_crater_m);
        if l.scabs && self.scab_time_s.is_none() {
            self.scab_time_s = Some(l.time_s);
        }
        if l.spall.0 > 0 && self.spall_time_s.is_none() {
            self.spall_time_s = Some(l.time_s);
        }
        if l.through && self.perforation_time_s.is_none() {
            self.perforation_time_s = Some(l.time_s);
            self.v_residual_mps = l.speed_mps;
        }
        // A perforation holes the back face: scabbed by then at the latest.
        if l.through && self.scab_time_s.is_none() {
            self.scab_time_s = Some(l.time_s);
        }
        if l.attached_bonds != self.attached_bonds {
            self.attached_bonds = l.attached_bonds;
            self.last_break_s = l.time_s;
        }
        if l.through {
            if !l.clear {
                self.clear_since_s = None;
                return None;
            }
            let since = *self.clear_since_s.get_or_insert(l.time_s);
            return (l.time_s - since >= spec.quiet_s).then_some("perforated");
        }
        self.clear_since_s = None;
        // Going on into the target with nothing pushing on it: the target has given way (a
        // beam broken into a mechanism carries the projectile along, or the hinges open under
        // it) and cannot stop it any more, so it goes through, whatever a time cap would see.
        if l.v_axial_mps >= 0.01 * v0_mps {
            match self.unresisted_since {
                // The nose must go on in too, at least half as fast: a projectile in free flight
                // over its crater, turning as it drifts, has a centre moving in and a nose that
                // does not (docs/penetration3d.md: packing 5 at 100 ft/s).
                Some((t0, v, d0)) if l.time_s - t0 >= spec.unresisted_s && l.depth_m - d0 < 0.5 * v * (l.time_s - t0) => {
                    self.unresisted_since = Some((l.time_s, l.v_axial_mps, l.depth_m));
                }
                Some((t0, v, _)) if (l.v_axial_mps - v).abs() <= spec.unresisted_change * v => {
                    if l.time_s - t0 >= spec.unresisted_s {
                        // A projectile that was through once keeps that first exit.
                        if self.perforation_time_s.is_none() {
                            self.perforation_time_s = Some(t0);
                            self.v_residual_mps = v;
                        }
                        self.scab_time_s.get_or_insert(t0);
                        return Some("unresisted");
                    }
                }
                _ => self.unresisted_since = Some((l.time_s, l.v_axial_mps, l.depth_m)),
            }
        } else {
            self.unresisted_since = None;
        }
        if l.time_s - self.last_break_s < spec.quiet_s {
            return None;
        }
        if l.speed_mps < 0.01 * v0_mps {
            return Some("embedded");
        }
        // Out along its path, or away from the front face (an oblique projectile that glanced
        // off and left along the face is as settled as one that came straight back).
        (l.v_axial_mps < 0.0 || l.v_face_mps < 0.0).then_some("rebounded")
    }
}

/// The detector: where the target, the projectile and the faces are.
#[derive(Debug, Clone)]
pub struct Detector {
    /// The scene's layout.
    pub layout: Layout,
    /// Thresholds.
    pub spec: OutcomeSpec,
    target: Range<usize>,
    projectile: Range<usize>,
    /// Per target element: started on the (back, front) face.
    faces: Vec<(bool, bool)>,
    /// Target elements of the back face under the impact point.
    under: Vec<usize>,
    /// Per target element, its share of the back face's area (m²; in 2D, of its width, m):
    /// the face's extent in proportion to its section r² (in 2D, r) among the elements that
    /// started on it; 0 off the back face.
    back_share: Vec<f64>,
    /// Target bonds at the start beyond `FAR_CALIBRES` of the impact axis.
    far_bonds_initial: u64,
    /// The model is a 2D slice (its back face a line).
    slice: bool,
    /// The evolving record.
    pub tracking: Tracking,
}

impl Detector {
    /// A detector for a model built from a penetration scene.
    pub fn new(model: &(impl Bodies + ?Sized), layout: Layout, spec: OutcomeSpec) -> Result<Detector> {
        let body = |name: &str| model.body(name).ok_or_else(|| Error::input("body", format!("the model has no body {name:?}")));
        let (target, projectile) = (body("target")?, body("projectile")?);
        let d = 2.0 * layout.concrete_radius_m;
        let faces: Vec<(bool, bool)> = target.clone().map(|e| {
            let (y, r) = (model.initial_m(e)[1], model.radius_m(e));
            (y - r < layout.back_y_m + d, y + r > layout.front_y_m - d)
        }).collect();
        // Within half a projectile width of the impact point across the face (in 2D, z = 0).
        let across = |p: [f64; 3]| (p[0] - layout.impact_x_m).hypot(p[2] - layout.impact_z_m);
        let under = target.clone().filter(|&e| faces[e - target.start].0 && across(model.initial_m(e)) <= 0.5 * layout.projectile_width_m).collect();
        // The back face's extent across x (and z in 3D), and each of its elements' share.
        // A 2D model (a slice) has every element at z = 0; a 3D packing never does.
        let slice = target.clone().all(|e| model.initial_m(e)[2] == 0.0);
        let on_back: Vec<usize> = target.clone().filter(|&e| faces[e - target.start].0).collect();
        let extent = |k: usize| {
            let lo = on_back.iter().map(|&e| model.initial_m(e)[k] - model.radius_m(e)).fold(f64::INFINITY, f64::min);
            let hi = on_back.iter().map(|&e| model.initial_m(e)[k] + model.radius_m(e)).fold(f64::NEG_INFINITY, f64::max);
            (hi - lo).max(0.0)
        };
        let (size, weight): (f64, fn(f64) -> f64) = if slice { (extent(0), |r| r) } else { (extent(0) * extent(2), |r| r * r) };
        let total: f64 = on_back.iter().map(|&e| weight(model.radius_m(e))).sum();
        let mut back_share = vec![0.0; target.len()];
        for &e in &on_back {
            back_share[e - target.start] = size * weight(model.radius_m(e)) / total;
        }
        let mut detector = Detector { layout, spec, target, projectile, faces, under, back_share, far_bonds_initial: 0, slice, tracking: Tracking::default() };
        detector.far_bonds_initial = detector.bonds_near_far(model).1;
        Ok(detector)
    }

    /// The target's elements.
    pub fn target(&self) -> Range<usize> {
        self.target.clone()
    }

    /// The projectile's elements.
    pub fn projectile(&self) -> Range<usize> {
        self.projectile.clone()
    }

    /// Distance of a point from the impact axis (the line through the impact point along the
    /// projectile's path), m.
    pub fn from_axis_m(&self, p: [f64; 3]) -> f64 {
        let lay = &self.layout;
        let d = [p[0] - lay.impact_x_m, p[1] - lay.front_y_m, p[2] - lay.impact_z_m];
        let along = d[0] * lay.axis[0] + d[1] * lay.axis[1] + d[2] * lay.axis[2];
        let off = [d[0] - along * lay.axis[0], d[1] - along * lay.axis[1], d[2] - along * lay.axis[2]];
        (off[0] * off[0] + off[1] * off[1] + off[2] * off[2]).sqrt()
    }

    /// Intact target bonds whose midpoints started within `FAR_CALIBRES` of the impact axis,
    /// and beyond (read at the end and by the history, not at every check).
    pub fn bonds_near_far(&self, m: &(impl Bodies + ?Sized)) -> (u64, u64) {
        let far = FAR_CALIBRES * self.layout.projectile_width_m;
        let (mut near_n, mut far_n) = (0, 0);
        m.each_bond(&mut |i, j| {
            if self.target.contains(&i) && self.target.contains(&j) {
                let (a, b) = (m.initial_m(i), m.initial_m(j));
                if self.from_axis_m([0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])]) > far {
                    far_n += 1;
                } else {
                    near_n += 1;
                }
            }
        });
        (near_n, far_n)
    }

    /// Look at the model.
    pub fn look(&self, m: &(impl Bodies + ?Sized)) -> Look {
        let lay = &self.layout;
        // The projectile.
        let (mut mass, mut mom, mut lowest, mut rear) = (0.0, [0.0; 3], f64::INFINITY, f64::NEG_INFINITY);
        // The projectile's footprint across the face, x and z.
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for e in self.projectile.clone() {
            let (p, v, r, me) = (m.position_m(e), m.velocity_mps(e), m.radius_m(e), m.mass_kg(e));
            mass += me;
            mom = [mom[0] + me * v[0], mom[1] + me * v[1], mom[2] + me * v[2]];
            lowest = lowest.min(p[1] - r);
            rear = rear.max(p[1] + r);
            for (k, a) in [0, 2].into_iter().enumerate() {
                lo[k] = lo[k].min(p[a] - r);
                hi[k] = hi[k].max(p[a] + r);
            }
        }
        let v = lay.whole_velocity(mom.map(|p| p / mass));
        // Fragments.
        let (frags, of) = fragments::fragments(m, self.target.clone(), |e| self.faces[e - self.target.start]);
        let attached = |e: usize| frags[of[e - self.target.start] as usize].supported;
        let under: Vec<usize> = self.under.iter().copied().filter(|&e| attached(e)).collect();
        let deflection = if under.is_empty() {
            0.0
        } else {
            -under.iter().map(|&e| m.position_m(e)[1] - m.initial_m(e)[1]).sum::<f64>() / under.len() as f64
        };
        // The attached faces' mean speed through the thickness (y) in square bins one projectile
        // width wide across the face (x, z; one row of them in 2D), zero where nothing is
        // attached, read over the bins around a fragment.
        let sep = fps_to_mps(self.spec.separation_fps);
        let w = lay.projectile_width_m;
        let bin = |x: f64| (x / w).floor().clamp(-1e6, 1e6) as i64;
        let cell = |p: [f64; 3]| (bin(p[0]), bin(p[2]));
        let mut bins: std::collections::BTreeMap<(bool, (i64, i64)), (usize, f64)> = Default::default();
        for e in self.target.clone() {
            let (b, f) = self.faces[e - self.target.start];
            if (b || f) && attached(e) {
                for (face, on) in [(true, b), (false, f)] {
                    if on {
                        let s = bins.entry((face, cell(m.position_m(e)))).or_default();
                        s.0 += 1;
                        s.1 += m.velocity_mps(e)[1];
                    }
                }
            }
        }
        let face_speed = |p: [f64; 3], back: bool| {
            let (bx, bz) = cell(p);
            let around = (bx - 1..=bx + 1).flat_map(|x| (bz - 1..=bz + 1).map(move |z| (x, z)));
            let (n, s) = around.filter_map(|k| bins.get(&(back, k))).fold((0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1));
            if n == 0 { 0.0 } else { s / n as f64 }
        };
        let (mut scab, mut spall) = ((0u64, 0.0), (0u64, 0.0));
        let mut is_scab = vec![false; frags.len()];
        for (k, f) in frags.iter().enumerate().filter(|(_, f)| !f.supported) {
            let (vy, x) = (f.velocity_mps()[1], f.centre_m());
            let left_through_back = f.centre_m()[1] < lay.back_y_m;
            if (f.back && vy < face_speed(x, true) - sep) || left_through_back {
                scab = (scab.0 + 1, scab.1 + f.mass_kg);
                is_scab[k] = true;
            } else if f.front && vy > face_speed(x, false) + sep {
                spall = (spall.0 + 1, spall.1 + f.mass_kg);
            }
        }
        // The back face's area (2D: width) its scab fragments took, as a crater's diameter.
        let lost: f64 = self.target.clone().filter(|&e| is_scab[of[e - self.target.start] as usize]).map(|e| self.back_share[e - self.target.start]).sum();
        let lost = lost * lay.copies();
        let back_crater_m = if self.slice { lost } else { 2.0 * (lost / std::f64::consts::PI).sqrt() };
        // Masses of the whole (fragment counts are the model's).
        let (scab, spall) = ((scab.0, scab.1 * lay.copies()), (spall.0, spall.1 * lay.copies()));
        let mut attached_bonds = 0u64;
        m.each_bond(&mut |i, _| attached_bonds += u64::from(self.target.contains(&i) && attached(i)));
        // Wholly past the back face: below it and below any attached material under it.
        let mut local = lay.back_y_m;
        for e in self.target.clone() {
            let (p, r) = (m.position_m(e), m.radius_m(e));
            if p[0] + r > lo[0] && p[0] - r < hi[0] && p[2] + r > lo[1] && p[2] - r < hi[1] && attached(e) {
                local = local.min(p[1] - r);
            }
        }
        Look {
            time_s: m.time_s(),
            depth_m: lay.front_y_m - lowest,
            deflection_m: deflection,
            scab,
            back_crater_m,
            scabs: back_crater_m >= self.spec.scab_crater_calibres * lay.projectile_width_m,
            spall,
            through: rear < local,
            clear: rear < local - 2.0 * 2.0 * lay.concrete_radius_m,
            v_axial_mps: v[0] * lay.axis[0] + v[1] * lay.axis[1] + v[2] * lay.axis[2],
            v_face_mps: -v[1],
            speed_mps: v[0].hypot(v[1]).hypot(v[2]),
            attached_bonds,
        }
    }

    /// The outcome, from the record and a last look at the model.
    pub fn outcome(&self, m: &(impl Bodies + ?Sized)) -> Outcome {
        let l = self.look(m);
        let t = &self.tracking;
        Outcome {
            depth_in: t.depth_m.max(l.depth_m) / M_PER_IN,
            depth_rel_in: t.depth_rel_m.max(l.depth_m - l.deflection_m) / M_PER_IN,
            depth_time_s: if l.depth_m > t.depth_m { l.time_s } else { t.depth_time_s },
            scabbed: t.scab_time_s.is_some() || l.scabs || l.through,
            back_crater_in: t.back_crater_m.max(l.back_crater_m) / M_PER_IN,
            scab_mass_lb: kg_to_lb(l.scab.1),
            scab_fragments: l.scab.0,
            scab_time_s: t.scab_time_s.or((l.scabs || l.through).then_some(l.time_s)),
            perforated: t.perforation_time_s.is_some() || l.through,
            v_residual_fps: mps_to_fps(if t.perforation_time_s.is_some() { t.v_residual_mps } else if l.through { l.speed_mps } else { 0.0 }),
            perforation_time_s: t.perforation_time_s.or(l.through.then_some(l.time_s)),
            v_final_fps: mps_to_fps(l.speed_mps),
            spall_mass_lb: kg_to_lb(l.spall.1),
            spall_fragments: l.spall.0,
            spall_time_s: t.spall_time_s.or((l.spall.0 > 0).then_some(l.time_s)),
            far_bonds_broken_fraction: if self.far_bonds_initial == 0 { 0.0 } else { 1.0 - self.bonds_near_far(m).1 as f64 / self.far_bonds_initial as f64 },
        }
    }
}

impl StopRule for Detector {
    fn every_steps(&self) -> u64 {
        self.spec.check_every_steps
    }

    fn check(&mut self, model: &dyn Bodies) -> Option<String> {
        let l = self.look(model);
        let v0 = self.layout.v0_mps;
        self.tracking.observe(&l, &self.spec, v0).map(str::to_string)
    }

    fn save(&self) -> Vec<u8> {
        postcard::to_stdvec(&self.tracking).expect("the tracking serialises")
    }

    fn load(&mut self, bytes: &[u8]) -> Result<()> {
        self.tracking = postcard::from_bytes(bytes).map_err(|e| Error::input("checkpoint", format!("outcome record: {e}")))?;
        Ok(())
    }
}
