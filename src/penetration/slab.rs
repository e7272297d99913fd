//! The penetration scene in 3D (`[penetration] dim = 3`): the empirical formulas' own scenario,
//! a square plain-concrete slab struck at the centre of its front face by a steel projectile,
//! made of bonded spheres of the 3D kernel (`crate::kernel3d`).
//!
//! The scene file is the 2D one (the same `[penetration]`, `[target]`, `[concrete]`,
//! `[projectile]` and `[outcome]` fields, read the same way) plus `[slab]`, what only the 3D
//! scene has. What changes with the dimension:
//! * the target: `target.length_in` is the side of the square slab, `target.depth_in` its
//!   thickness (along y, the projectile coming from above as in 2D); its four side faces held
//!   (`slab.edges`): clamped over `target.support_length_in`, simply supported on a line of
//!   spheres along the back face's edges, or absorbing (dashpots that let the waves out, the
//!   slab standing for the middle of a wall of large extent);
//! * the projectile: a real cylinder of steel with its nose, `projectile.weight_lb` at
//!   `slab.steel_density_lbs2_per_in4`, so its length follows from the weight unless
//!   `projectile.length_in` is given (then the density follows: nothing to map, `[mapping]`
//!   is refused);
//! * elements: both bodies random dense packings of spheres; the concrete's graded about the
//!   projectile's path (`packing3d::random_dense_graded`): mean radius
//!   `slab.element_radius_in` within `slab.fine_radius_in` of it, growing by
//!   `slab.radius_growth` per unit distance up to `slab.max_element_radius_in` (a 2 in sphere
//!   cannot resolve the crushing under a 3.5 in nose, and spheres that fine everywhere would
//!   be a hundred thousand); the projectile's `slab.projectile_element_radius_in`; every
//!   radius (and the growth) halved per level;
//! * masses are the bodies' own (no slice).
//!
//! Compaction's default full strain (`concrete.compaction.full_strain`, the Holmquist–Johnson–
//! Cook μ_lock = 0.10 over plane strain's two directions) is read as the same volumetric strain:
//! a bond strain of μ_lock / 3 in 3D.

use serde::{Deserialize, Serialize};

use super::scene::{Layout, PenetrationScene};
use crate::error::{Error, Result};
use crate::kernel3d::solid::Solid;
use crate::material::{CompactionSpec, FailureCriterion, RateSpec};
use crate::packing3d::{Box3, Grading};
use crate::scene::OutputSpec;
use crate::scene3d::{self, Absorb3, Axis3, Body3, Damping3, Fix3, General3, Mirror3, Packing3, Scene3, TimeStep3};
use crate::shape3d::Projectile3;
use crate::units::{M_PER_IN, fps_to_mps, in_to_m, lb_to_kg, lbs2_per_in4_to_kg_per_m3, psi_sqrt_in_to_pa_sqrt_m, psi_to_pa};

/// How the slab's four side faces are held.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Edges {
    /// Every sphere within `target.support_length_in` of a side face held.
    #[default]
    Clamped,
    /// A line of spheres along each edge of the back face held in translation (free to turn
    /// about it): the slab bears on four knife edges.
    SimplySupported,
    /// The slab as the middle of a wall of large extent: the spheres at each side face tied to
    /// the wall beyond by dashpots matched to the concrete's impedance (`scene3d::Absorb3`,
    /// Lysmer & Kuhlemeyer 1969), so the waves that reach the edges leave instead of ringing.
    Absorbing,
}

/// How much of the slab and projectile the model holds (`kernel3d::mirror`): the whole, or the
/// part on the high side of mirror planes through the impact axis — normal to z (half: the
/// obliquity turns the projectile in the x–y plane, so z is always a symmetry), and normal to
/// x too at normal incidence (quarter). Outcomes, masses and energies are reported for the
/// whole.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Symmetry {
    /// The whole slab and projectile.
    #[default]
    Full,
    /// The half z ≥ the impact point's, one mirror plane.
    Half,
    /// The quarter x, z ≥ the impact point's, two mirror planes (normal impact at the centre
    /// of the slab only).
    Quarter,
}

/// `[slab]`: what only the 3D scene has (defaults in code).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Slab {
    /// How the side faces are held.
    #[serde(default)]
    pub edges: Edges,
    /// How much of the slab and projectile is modelled (mirror planes through the impact axis).
    #[serde(default, skip_serializing_if = "is_full")]
    pub symmetry: Symmetry,
    /// The concrete's mean sphere radius at level 1 near the impact axis, in (the finest;
    /// halved per level).
    #[serde(default = "default_radius")]
    pub element_radius_in: f64,
    /// The concrete's largest mean sphere radius at level 1, in (halved per level): the slab
    /// is graded from `element_radius_in` within `fine_radius_in` of the impact axis, growing by
    /// `radius_growth` per unit distance, up to this. Equal to `element_radius_in`: uniform.
    #[serde(default = "default_max_radius")]
    pub max_element_radius_in: f64,
    /// Distance from the impact axis within which the concrete has its finest spheres, in (the
    /// same at every level: the region the nose crushes and the plug forms in).
    #[serde(default = "default_fine_radius")]
    pub fine_radius_in: f64,
    /// Growth of the mean sphere radius per unit distance beyond `fine_radius_in` at level 1,
    /// in/in (halved per level with the radii, so every level grades over the same region).
    #[serde(default = "default_growth")]
    pub radius_growth: f64,
    /// The projectile's mean sphere radius at level 1, in (halved per level). Default: at each
    /// level the concrete's, but at most a fifth of the calibre (eight spheres at least). A discretisation choice, not
    /// physics: steel's springs are stiffer than concrete's by E/ρ, so at half the concrete's
    /// radius the projectile bounded the step at 1.24e-6 s against the concrete's 2.71e-6 s at
    /// level 1 (measured), and at the concrete's 2 in of level 0 the calibre held one sphere.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub projectile_element_radius_in: Option<f64>,
    /// The projectile's steel density, lb·s²/in⁴ (0.2836 lb/in³).
    #[serde(default = "default_steel_density")]
    pub steel_density_lbs2_per_in4: f64,
    /// Seed of the projectile's packing.
    #[serde(default = "default_projectile_seed")]
    pub projectile_seed: u64,
    /// The concrete's own damping, a fraction of critical (local damping, the same in every
    /// mode; `kernel3d::integrate::local`). The steel and loose fragments are not damped.
    #[serde(default = "default_damping_ratio", skip_serializing_if = "scene3d::is_zero")]
    pub damping_ratio: f64,
}

/// Half an inch at level 1: 3.5 spheres across the calibre (1.75 at level 0, 7 at level 2)
/// under the impact, where the 1 in spheres of a uniform slab resisted as jammed grains
/// (docs/penetration3d.md).
fn default_radius() -> f64 {
    0.5
}
/// Two inches at level 1 away from the impact: 7.5 spheres across the 30 in slab.
fn default_max_radius() -> f64 {
    2.0
}
/// Two calibres of the source's 3.5 in projectile.
fn default_fine_radius() -> f64 {
    7.0
}
/// The radius doubles over 5 in at level 1 (neighbours differ by about 10 %).
fn default_growth() -> f64 {
    0.1
}
fn is_full(s: &Symmetry) -> bool {
    *s == Symmetry::Full
}
fn default_steel_density() -> f64 {
    7.33e-4
}
fn default_projectile_seed() -> u64 {
    1
}
fn default_damping_ratio() -> f64 {
    0.0
}


impl Default for Slab {
    fn default() -> Self {
        Slab {
            edges: Edges::default(),
            symmetry: Symmetry::default(),
            element_radius_in: default_radius(),
            max_element_radius_in: default_max_radius(),
            fine_radius_in: default_fine_radius(),
            radius_growth: default_growth(),
            projectile_element_radius_in: None,
            steel_density_lbs2_per_in4: default_steel_density(),
            projectile_seed: default_projectile_seed(),
            damping_ratio: default_damping_ratio(),
        }
    }
}

/// The fewest spheres a projectile may be made of (a nose of one or two spheres is a ball).
const MIN_PROJECTILE_SPHERES: usize = 8;

/// Bonds form where the gap is below this × R (the packing recipe the stiffness relation was
/// measured on).
const BOND_GAP_RATIO: f64 = 0.1;

impl PenetrationScene {
    /// The `[slab]` settings of a 3D scene (the defaults when the table is absent).
    pub fn slab(&self) -> Slab {
        self.slab.clone().unwrap_or_default()
    }

    /// The 3D level's factor on the level-1 radii.
    fn level_scale(&self) -> f64 {
        0.5f64.powi(self.penetration.level as i32 - 1)
    }

    /// The projectile's mean sphere radius at the scene's level, in.
    pub fn projectile_radius3_in(&self) -> f64 {
        let s = self.slab();
        match s.projectile_element_radius_in {
            Some(r) => r * self.level_scale(),
            None => (s.element_radius_in * self.level_scale()).min(self.projectile.width_in / 5.0),
        }
    }

    /// Check the fields only the 3D scene reads.
    pub(super) fn validate_slab(&self) -> Result<()> {
        let s = self.slab();
        for (f, v) in [
            ("slab.element_radius_in", s.element_radius_in),
            ("slab.max_element_radius_in", s.max_element_radius_in),
            ("slab.projectile_element_radius_in", s.projectile_element_radius_in.unwrap_or(1.0)),
            ("slab.steel_density_lbs2_per_in4", s.steel_density_lbs2_per_in4),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::input(f, format!("must be a finite number > 0, got {v}")));
            }
        }
        for (f, v) in [("slab.fine_radius_in", s.fine_radius_in), ("slab.radius_growth", s.radius_growth)] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(Error::input(f, format!("must be a finite number ≥ 0, got {v}")));
            }
        }
        scene3d::check_local_damping_ratio("slab.damping_ratio", s.damping_ratio)?;
        if s.symmetry == Symmetry::Quarter {
            let centred = self.projectile.impact_x_in.is_none_or(|x| x == 0.5 * self.target.length_in);
            if self.projectile.angle_deg != 0.0 || !centred {
                return Err(Error::input("slab.symmetry", "a quarter needs a normal impact at the centre of the slab (take half at an angle or off the centre)"));
            }
        }
        if let Some(e) = self.concrete.restitution
            && !(e > 0.0 && e <= 1.0)
        {
            return Err(Error::input("concrete.restitution", format!("must lie in (0, 1], got {e}")));
        }
        if let Some(t) = self.concrete.crushed_shear_strength_psi
            && !(t > 0.0 && t.is_finite())
        {
            return Err(Error::input("concrete.crushed_shear_strength_psi", format!("must be positive and finite, got {t}")));
        }
        if s.max_element_radius_in < s.element_radius_in {
            return Err(Error::input(
                "slab.max_element_radius_in",
                format!("{} in is below slab.element_radius_in, {} in (the finest)", s.max_element_radius_in, s.element_radius_in),
            ));
        }
        if self.mapping != super::scene::Mapping::default() {
            return Err(Error::input("mapping", "a 3D scene has no slice to map: the projectile is a cylinder of its own mass"));
        }
        let t = &self.target;
        let rc = s.max_element_radius_in * self.level_scale();
        if t.depth_in < 4.0 * rc {
            return Err(Error::input("target.depth_in", format!("{} in holds fewer than two spheres of radius {rc} in across the slab", t.depth_in)));
        }
        if t.length_in < 2.0 * t.support_length_in + 8.0 * rc {
            return Err(Error::input("target.length_in", format!("a {} in slab cannot hold supports of {} in and spheres of radius {rc} in", t.length_in, t.support_length_in)));
        }
        let rp = self.projectile_radius3_in();
        let p = &self.projectile;
        if 2.4 * rp >= p.width_in {
            return Err(Error::input("slab.projectile_element_radius_in", format!("{rp} in at level {}: 1.2 spheres must fit across the {} in calibre", self.penetration.level, p.width_in)));
        }
        let d = &self.damping;
        if d.beta_s.is_some() || !d.points.is_empty() || d.relative_to_rigid_motion {
            return Err(Error::input("damping", "a 3D scene takes mass-proportional damping only (alpha_per_s)"));
        }
        Ok(())
    }

    /// The projectile's solid at the origin, pointing along `axis`: the given length, or the one
    /// at which steel of `slab.steel_density_lbs2_per_in4` weighs `projectile.weight_lb`.
    fn solid3(&self, axis: [f64; 3]) -> Result<Projectile3> {
        let p = &self.projectile;
        let mut shape = Projectile3 { tail_m: [0.0; 3], axis, diameter_m: in_to_m(p.width_in), length_m: 0.0, nose: p.nose, crh: p.crh };
        shape.length_m = shape.nose_length_m();
        shape.length_m = match p.length_in {
            Some(l) => in_to_m(l),
            None => {
                // Volume is linear in the cylinder's length behind the nose.
                let volume = lb_to_kg(p.weight_lb) / lbs2_per_in4_to_kg_per_m3(self.slab().steel_density_lbs2_per_in4);
                let (nose_v, area) = (shape.volume_m3(), std::f64::consts::FRAC_PI_4 * shape.diameter_m.powi(2));
                if volume < nose_v {
                    return Err(Error::input("projectile.weight_lb", format!("{} lb of steel is less than the {} in nose alone", p.weight_lb, p.width_in)));
                }
                shape.length_m + (volume - nose_v) / area
            }
        };
        shape.validate("projectile")?;
        Ok(shape)
    }

    /// The 3D kernel's scene, and where its pieces are.
    pub fn to_scene3(&self) -> Result<(Scene3, Layout)> {
        self.to_scene3_packed().map(|(scene, layout, _)| (scene, layout))
    }

    /// The 3D kernel's model, and where its pieces are (each body packed once: placing the
    /// projectile needs the slab's front face, checking the start its own packing).
    pub fn build3(&self) -> Result<(crate::simulation::Built<crate::kernel3d::Model>, Layout)> {
        let (scene, layout, [target, projectile]) = self.to_scene3_packed()?;
        Ok((scene.build_with(vec![Some(target), Some(projectile)])?, layout))
    }

    /// [`PenetrationScene::to_scene3`] and the packings it made of its bodies (target,
    /// projectile), the ones the scene's fields make.
    fn to_scene3_packed(&self) -> Result<(Scene3, Layout, [crate::packing3d::Packing; 2])> {
        self.validate()?;
        let (t, p, c, s) = (&self.target, &self.projectile, &self.concrete, self.slab());
        let (side, depth) = (in_to_m(t.length_in), in_to_m(t.depth_in));
        let (rc, rp) = (in_to_m(s.element_radius_in) * self.level_scale(), in_to_m(self.projectile_radius3_in()));
        let (x0, z0) = (in_to_m(p.impact_x_in.unwrap_or(0.5 * t.length_in)), 0.5 * side);
        // The mirror planes through the impact axis, (axis, where, m), and the part they leave.
        let planes: Vec<(usize, f64)> = match s.symmetry {
            Symmetry::Full => vec![],
            Symmetry::Half => vec![(2, z0)],
            Symmetry::Quarter => vec![(0, x0), (2, z0)],
        };
        let cut = |axis: usize| planes.iter().find(|p| p.0 == axis).map_or(0.0, |p| p.1);
        let slab_box = Box3 { x_min_m: 0.0, x_max_m: side, y_min_m: 0.0, y_max_m: depth, z_min_m: 0.0, z_max_m: side };
        // The part of a packing of the whole: the spheres centred on the planes' high sides (one
        // cut by a plane weighs its share there and overlaps its image, bonded to it:
        // `scene3d::Scene3::mirror`); a packing made against the planes as walls put a layer
        // bonded to nothing but its own images along them, two weak planes through the axis.
        let share = 0.5f64.powi(planes.len() as i32);
        let part = |p: crate::packing3d::Packing| {
            if planes.is_empty() {
                return p;
            }
            let v = share * p.volume_m3;
            p.keep(|c, _| planes.iter().all(|&(a, at)| c[a] >= at), v)
        };
        let compaction = c.compaction.map(|k| CompactionSpec { stiffness_ratio: k.stiffness_ratio, full_strain: k.full_strain * 2.0 / 3.0 });
        let concrete = Solid {
            name: "concrete".into(),
            density_kg_per_m3: lbs2_per_in4_to_kg_per_m3(c.density_lbs2_per_in4),
            youngs_modulus_pa: psi_to_pa(c.youngs_modulus_psi),
            poisson_ratio: c.poisson_ratio,
            failure: FailureCriterion::StrengthEnergy,
            tensile_strength_pa: psi_to_pa(c.tensile_strength_psi) * c.strength_factor,
            shear_strength_pa: None,
            fracture_toughness_pa_sqrt_m: psi_sqrt_in_to_pa_sqrt_m(c.fracture_toughness_psi_sqrt_in) * c.strength_factor,
            friction_coefficient: c.friction_coefficient,
            rolling: None,
            twisting: None,
            compressive_strength_pa: psi_to_pa(c.compressive_strength_psi),
            rate: c.rate.map(|r| RateSpec { averaging_length_m: Some(r.averaging_length_m.unwrap_or(in_to_m(super::scene::RATE_AVERAGING_LENGTH_IN))), ..r }),
            compaction,
            restitution: c.restitution,
            crushed_shear_strength_pa: c.crushed_shear_strength_psi.map(psi_to_pa),
        };
        let a = p.angle_deg.to_radians();
        let axis = [a.sin(), -a.cos(), 0.0];
        let mut shape = self.solid3(axis)?;
        let steel = Solid {
            name: "steel".into(),
            density_kg_per_m3: lb_to_kg(p.weight_lb) / shape.volume_m3(),
            youngs_modulus_pa: psi_to_pa(p.youngs_modulus_psi),
            poisson_ratio: p.poisson_ratio,
            failure: FailureCriterion::None,
            tensile_strength_pa: 0.0,
            shear_strength_pa: None,
            fracture_toughness_pa_sqrt_m: 0.0,
            friction_coefficient: p.friction_coefficient,
            rolling: None,
            twisting: None,
            compressive_strength_pa: 0.0,
            rate: None,
            compaction: None,
            restitution: None,
            crushed_shear_strength_pa: None,
        };
        // Graded about the projectile's path from the impact point, coarse beyond.
        let r_big = in_to_m(s.max_element_radius_in) * self.level_scale();
        let grading = (s.max_element_radius_in > s.element_radius_in).then(|| Grading {
            point_m: [x0, depth, z0],
            axis,
            core_m: in_to_m(s.fine_radius_in),
            growth: s.radius_growth * self.level_scale(),
            max_radius_m: r_big,
        });
        // The front face: the top of the target's top spheres.
        // Built once per recipe (`packing3d::cache`): 7 s of a level-1 event.
        let recipe = format!("slab\nwalls {slab_box:?}\ngrading {grading:?}\nradius_m {rc:?}\nseed {}\nbond_gap_ratio {BOND_GAP_RATIO:?}", t.seed);
        let target = part(crate::packing3d::cache::cached(&recipe, || match &grading {
            Some(g) => crate::packing3d::random_dense_graded(&slab_box, g, rc, t.seed, BOND_GAP_RATIO),
            None => crate::packing3d::random_dense(&slab_box, rc, t.seed, BOND_GAP_RATIO),
        })?);
        let front = (0..target.centres_m.len()).map(|e| target.centres_m[e][1] + target.radii_m[e]).fold(f64::NEG_INFINITY, f64::max);
        // Tail so that the tip is at the impact point, then back along the axis until the
        // lowest sphere clears the face by the standoff (at an angle the first to arrive is a
        // corner of the nose, not the tip).
        shape.tail_m = [x0 - axis[0] * shape.length_m, front - axis[1] * shape.length_m, z0];
        let packed = shape.packing(rp, s.projectile_seed, BOND_GAP_RATIO).map_err(|e| match e {
            Error::Input { file, message, .. } => Error::Input { file, field: "slab.projectile_element_radius_in".into(), message },
            other => other,
        })?;
        if packed.centres_m.len() < MIN_PROJECTILE_SPHERES {
            return Err(Error::input(
                "slab.projectile_element_radius_in",
                format!("spheres of {:.4} in leave {} in the projectile (at least {MIN_PROJECTILE_SPHERES}): a smaller radius", rp / M_PER_IN, packed.centres_m.len()),
            ));
        }
        // The part modelled sets the standoff (its lowest sphere, the whole's).
        let packed = part(packed);
        let lowest = (0..packed.centres_m.len()).map(|e| packed.centres_m[e][1] - packed.radii_m[e]).fold(f64::INFINITY, f64::min);
        let back = (front + in_to_m(p.standoff_in) - lowest) / a.cos();
        shape.tail_m = [shape.tail_m[0] - axis[0] * back, shape.tail_m[1] - axis[1] * back, z0];
        // A projectile released inside the target would start with its spheres overlapping the
        // slab's, a spring force nothing put there: refused, as the 2D model refuses it.
        let placed = part(shape.packing(rp, s.projectile_seed, BOND_GAP_RATIO)?);
        for (a_m, ra) in placed.centres_m.iter().zip(&placed.radii_m) {
            for (b_m, rb) in target.centres_m.iter().zip(&target.radii_m) {
                let d2 = (0..3).map(|k| (a_m[k] - b_m[k]).powi(2)).sum::<f64>();
                if d2 < (ra + rb).powi(2) {
                    return Err(Error::input(
                        "projectile.standoff_in",
                        format!("{} in puts the projectile's spheres into the target's (they would overlap at release)", p.standoff_in),
                    ));
                }
            }
        }
        let v = fps_to_mps(p.v0_fps);
        // The supports: the spheres reaching within `support_length_in` of a side face (centres
        // within it plus a mean radius), through the thickness when clamped, the layer touching
        // the back face when simply supported.
        let (band, pad) = (in_to_m(t.support_length_in) + r_big, 1e-9 + r_big);
        let y_max_m = match s.edges {
            Edges::Clamped | Edges::Absorbing => depth + pad,
            Edges::SimplySupported => 1.5 * r_big,
        };
        let all = Box3 { x_min_m: -pad, x_max_m: side + pad, y_min_m: -pad, y_max_m, z_min_m: -pad, z_max_m: side + pad };
        // The side faces the part has (a mirror plane is none).
        let (has_x_low, has_z_low) = (cut(0) == 0.0, cut(2) == 0.0);
        let present = |name: &str| match name {
            "x_low" => has_x_low,
            "z_low" => has_z_low,
            _ => true,
        };
        let bands: Vec<_> = [
            ("x_low", Box3 { x_max_m: band, ..all }),
            ("x_high", Box3 { x_min_m: side - band, ..all }),
            ("z_low", Box3 { z_max_m: band, ..all }),
            ("z_high", Box3 { z_min_m: side - band, ..all }),
        ]
        .into_iter()
        .filter(|(n, _)| present(n))
        .collect();
        let kind = match s.edges {
            Edges::Clamped => "clamped",
            Edges::SimplySupported => "supported",
            Edges::Absorbing => "absorbing",
        };
        let (fix, absorb) = match s.edges {
            Edges::Absorbing => {
                // The layer at each side face: centres within 1.5 mean radii of it (the radii
                // spread ±20 % about the mean: the whole first layer).
                let layer = 1.5 * r_big;
                let faces = [
                    ("x_low", Box3 { x_max_m: layer, ..all }, Axis3::X),
                    ("x_high", Box3 { x_min_m: side - layer, ..all }, Axis3::X),
                    ("z_low", Box3 { z_max_m: layer, ..all }, Axis3::Z),
                    ("z_high", Box3 { z_min_m: side - layer, ..all }, Axis3::Z),
                ];
                // Each face's area in the part: its extent along the other side axis.
                let across = |normal: Axis3| match normal {
                    Axis3::X => side - cut(2),
                    _ => side - cut(0),
                };
                let absorb = faces.into_iter().filter(|(n, ..)| present(n)).map(|(n, region, normal)| Absorb3 { name: format!("{kind}_{n}"), region, normal, area_m2: across(normal) * depth }).collect();
                (vec![], absorb)
            }
            _ => (bands.into_iter().map(|(n, region)| Fix3 { name: format!("{kind}_{n}"), region, velocity_mps: [0.0; 3] }).collect(), vec![]),
        };
        let scene = Scene3 {
            scene: General3 { name: self.penetration.name.clone(), dim: 3, duration_s: self.penetration.max_time_s },
            time_step: TimeStep3 { safety: self.penetration.safety, ..TimeStep3::default() },
            damping: Damping3 { alpha_per_s: self.damping.alpha_per_s.unwrap_or(0.0) },
            material: vec![concrete, steel],
            body: vec![
                Body3 {
                    name: "target".into(),
                    material: "concrete".into(),
                    element_radius_m: rc,
                    packing: Packing3::RandomDense,
                    seed: t.seed,
                    bond_gap_ratio: BOND_GAP_RATIO,
                    region: Some(slab_box),
                    shape: None,
                    grading,
                    velocity_mps: [0.0; 3],
                    local_damping_ratio: s.damping_ratio,
                },
                Body3 {
                    name: "projectile".into(),
                    material: "steel".into(),
                    element_radius_m: rp,
                    packing: Packing3::RandomDense,
                    seed: s.projectile_seed,
                    bond_gap_ratio: BOND_GAP_RATIO,
                    region: None,
                    shape: Some(shape.clone()),
                    grading: None,
                    velocity_mps: axis.map(|k| v * k),
                    local_damping_ratio: 0.0,
                },
            ],
            fix,
            absorb,
            load: vec![],
            probe: vec![],
            mirror: planes.iter().map(|&(a, at_m)| Mirror3 { normal: if a == 0 { Axis3::X } else { Axis3::Z }, at_m }).collect(),
            output: OutputSpec { every_steps: 1_000_000 },
        };
        // The 3D scene's own checks name its fields; say which of this file's they come from.
        scene.validate().map_err(|e| match e {
            Error::Input { file, field, message } => {
                Error::Input { file, field: field.replace("material[0]", "concrete").replace("material[1]", "projectile"), message }
            }
            other => other,
        })?;
        let layout = Layout {
            front_y_m: front,
            back_y_m: 0.0,
            impact_x_m: x0,
            impact_z_m: z0,
            projectile_width_m: shape.diameter_m,
            projectile_length_m: shape.length_m,
            axis,
            v0_mps: v,
            thickness_m: f64::NAN,
            concrete_radius_m: rc,
            mirror_axes: planes.iter().map(|p| p.0).collect(),
        };
        Ok((scene, layout, [target, placed]))
    }

    /// The projectile's length in a 3D scene, in (given, or from its weight).
    pub fn projectile_length3_in(&self) -> Result<f64> {
        Ok(self.solid3([0.0, -1.0, 0.0])?.length_m / M_PER_IN)
    }
}
