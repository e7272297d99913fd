//! Building a 3D model: bodies of spheres, their bonds, supports and loads, the contact classes,
//! and the time step from the stability bound.

use std::ops::Range;

use super::contact::{Bond, Contact, Extra};
use super::law::Class;
use super::mirror::Mirrors;
use super::stability::{Link, omega_max_sq};
use super::state::{Spheres, State};
use super::vec3::{V3, norm, scale, sub};
use super::{Model, integrate};
use crate::error::{Error, Result};
use crate::kernel::Body;
use crate::kernel::law::rate_field::RateField;
use crate::simulation::Threading;

/// What a 3D model is built from.
#[derive(Debug, Clone)]
pub struct Builder {
    spheres: Spheres,
    bodies: Vec<Body>,
    kinds: usize,
    classes: Vec<Option<Class>>,
    /// Bonds (i, j, image): j itself (image 0) or seen through symmetry planes.
    bonds: Vec<(u32, u32, u8)>,
    /// The symmetry planes (`mirror`): the model is a part of a mirror-symmetric whole.
    pub mirrors: Mirrors,
    /// Mass-proportional damping α, 1/s.
    pub alpha_per_s: f64,
    /// Fraction of the stability limit taken as the step.
    pub safety: f64,
    /// Neighbour skin over the mean radius.
    pub skin_ratio: f64,
    /// A fixed step, s, taken whatever the bound says (to measure where the bound lies; the
    /// bound is still computed and reported).
    pub dt_s: Option<f64>,
    /// The rate part's averaging length, m, and the sphere kinds whose velocities are smoothed
    /// over it (`kernel::law::rate_field`; None: each bond reads its own pair).
    pub rate_averaging: Option<(f64, Vec<u16>)>,
}

impl Builder {
    /// An empty model of `kinds` sphere kinds (materials).
    pub fn new(kinds: usize) -> Builder {
        Builder { spheres: Spheres::default(), bodies: Vec::new(), kinds, classes: vec![None; kinds * kinds], bonds: Vec::new(), mirrors: Mirrors::default(), alpha_per_s: 0.0, safety: 0.9, skin_ratio: 0.3, dt_s: None, rate_averaging: None }
    }

    /// The class of contacts between kinds a and b (both orders).
    pub fn class(&mut self, a: usize, b: usize, class: Class) {
        self.classes[a * self.kinds + b] = Some(class.clone());
        self.classes[b * self.kinds + a] = Some(class);
    }

    /// A body of spheres of `kind` at `centres_m` with `radii_m` and density `density_kg_m3`,
    /// at rest. Returns its sphere range.
    pub fn body(&mut self, name: &str, centres_m: &[V3], radii_m: &[f64], kind: u16, density_kg_m3: f64) -> Range<usize> {
        let start = self.spheres.len();
        let s = &mut self.spheres;
        for (&c, &r) in centres_m.iter().zip(radii_m) {
            let m = density_kg_m3 * 4.0 / 3.0 * std::f64::consts::PI * r * r * r;
            s.radius_m.push(r);
            s.mass_kg.push(m);
            s.inertia_kg_m2.push(0.4 * m * r * r);
            s.kind.push(kind);
            s.initial_m.push(c);
            s.held.push(false);
            s.prescribed_mps.push([0.0; 3]);
            s.load_n.push([0.0; 3]);
            s.load_nm.push([0.0; 3]);
        }
        let range = start..self.spheres.len();
        self.bodies.push(Body { name: name.to_string(), elements: range.clone() });
        range
    }

    /// Damp the motion of the spheres in `range` locally at `ratio` of critical
    /// (`integrate`: λ = π ζ).
    pub fn damp_locally(&mut self, range: Range<usize>, ratio: f64) {
        // Spheres added after this call are undamped: `build` pads the list to every sphere.
        let s = &mut self.spheres;
        s.local_damping.resize(s.len(), 0.0);
        range.for_each(|e| s.local_damping[e] = std::f64::consts::PI * ratio);
    }

    /// Bond spheres i and j at their present distance.
    pub fn bond(&mut self, i: usize, j: usize) {
        self.bonds.push((i.min(j) as u32, i.max(j) as u32, 0));
    }

    /// Bond sphere i to the image of j across the symmetry planes of `image` (`mirrors`), at
    /// their present distance.
    pub fn bond_image(&mut self, i: usize, j: usize, image: u8) {
        self.bonds.push((i.min(j) as u32, i.max(j) as u32, image));
    }

    /// Hold sphere e, moving at `velocity_mps` (zero: fixed), without spin.
    pub fn hold(&mut self, e: usize, velocity_mps: V3) {
        self.spheres.held[e] = true;
        self.spheres.prescribed_mps[e] = velocity_mps;
    }

    /// Tie sphere e to what lies beyond the model by a dashpot of `c_kg_per_s` along x, y, z
    /// (added to any it has: a sphere at a corner sits on two faces).
    pub fn dashpot(&mut self, e: usize, c_kg_per_s: V3) {
        let s = &mut self.spheres;
        s.dashpot_kg_per_s.resize(s.len(), [0.0; 3]);
        s.dashpot_kg_per_s[e] = [0, 1, 2].map(|k| s.dashpot_kg_per_s[e][k] + c_kg_per_s[k]);
    }

    /// A constant force (N) and moment (N·m) on sphere e.
    pub fn load(&mut self, e: usize, force_n: V3, moment_nm: V3) {
        self.spheres.load_n[e] = force_n;
        self.spheres.load_nm[e] = moment_nm;
    }

    /// Set the mass and inertia of sphere e (kg, kg·m²): a beam of spheres carries the mass of
    /// its cylinder, not of its balls.
    pub fn mass(&mut self, e: usize, mass_kg: f64, inertia_kg_m2: f64) {
        self.spheres.mass_kg[e] = mass_kg;
        self.spheres.inertia_kg_m2[e] = inertia_kg_m2;
    }

    /// Weigh each sphere of `range` that a symmetry plane (`mirrors`) cuts by the share of its
    /// volume on the model's side (the rest is its image's): a whole made of the part and its
    /// images then has the packing's mass where the packing had it.
    pub fn weigh_cut_spheres(&mut self, range: Range<usize>) {
        for e in range {
            let (c, r) = (self.spheres.initial_m[e], self.spheres.radius_m[e]);
            let share: f64 = self.mirrors.0.iter().map(|m| Mirrors::volume_share(c[m.axis] - m.at_m, r)).product();
            self.spheres.mass_kg[e] *= share;
            self.spheres.inertia_kg_m2[e] *= share;
        }
    }

    /// Scale the masses and inertias of the spheres `range` so that they weigh `total_kg`: a
    /// packing standing for a solid carries the solid's mass (density × its volume), not the
    /// spheres' alone.
    pub fn mass_total(&mut self, range: Range<usize>, total_kg: f64) {
        let now: f64 = self.spheres.mass_kg[range.clone()].iter().sum();
        let f = total_kg / now;
        for e in range {
            self.spheres.mass_kg[e] *= f;
            self.spheres.inertia_kg_m2[e] *= f;
        }
    }

    /// Build: bonds at their present lengths, the contacts the spheres start with, and the step.
    pub fn build(self, initial_velocity_mps: &[(Range<usize>, V3)]) -> Result<Model> {
        let kinds = self.kinds;
        let classes: Vec<Class> = self
            .classes
            .into_iter()
            .enumerate()
            .map(|(k, c)| c.ok_or_else(|| Error::input("class", format!("no contact class between kinds {} and {}", k / kinds, k % kinds))))
            .collect::<Result<_>>()?;
        let mut s = self.spheres;
        if !s.local_damping.is_empty() {
            s.local_damping.resize(s.len(), 0.0);
        }
        if !s.dashpot_kg_per_s.is_empty() {
            s.dashpot_kg_per_s.resize(s.len(), [0.0; 3]);
        }
        if let Some(e) = (0..s.len()).find(|&e| !(s.radius_m[e] > 0.0 && s.mass_kg[e] > 0.0 && s.initial_m[e].iter().all(|x| x.is_finite()))) {
            return Err(Error::input("sphere", format!("sphere {e}: radius {} m, mass {} kg, centre {:?} m", s.radius_m[e], s.mass_kg[e], s.initial_m[e])));
        }
        let n = s.len();
        let mean_r = s.radius_m.iter().sum::<f64>() / n.max(1) as f64;
        let mut vel = vec![[0.0; 3]; n];
        for (range, v) in initial_velocity_mps {
            range.clone().for_each(|e| vel[e] = *v);
        }
        for e in (0..n).filter(|&e| s.held[e]) {
            vel[e] = s.prescribed_mps[e];
        }
        let class_of = |i: u32, j: u32| (s.kind[i as usize] as usize * kinds + s.kind[j as usize] as usize) as u16;
        let mut bonds = self.bonds;
        bonds.sort_unstable();
        bonds.dedup();
        let pos = s.initial_m.clone();
        let mirrors = self.mirrors;
        let contacts: Vec<Contact> = bonds
            .iter()
            .map(|&(i, j, image)| {
                let dx = sub(mirrors.point(pos[j as usize], image), pos[i as usize]);
                let d = norm(dx);
                let mut c = Contact::new(i, j, class_of(i, j), Bond::Intact, d, scale(1.0 / d, dx));
                c.image = image;
                // A bond whose class has a rate or compaction part carries its state.
                let class = &classes[c.class as usize];
                if class.rate.enabled || class.compaction.is_some() {
                    c.extra = Some(Box::new(Extra::new(d)));
                }
                c
            })
            .collect();
        let mut rate_field = match &self.rate_averaging {
            Some((length_m, kinds)) => {
                let members = (0..n).filter(|&e| kinds.contains(&s.kind[e])).map(|e| e as u32).collect();
                RateField::new(members, &s.initial_m, n, *length_m)
            }
            None => RateField::default(),
        };
        mirrors.0.iter().for_each(|m| rate_field.mirror(m.axis, m.at_m));
        let uniform_radius_m = s.radius_m.first().copied().filter(|&r| s.radius_m.iter().all(|&x| x == r));
        let mut model = Model {
            spheres: s,
            classes,
            kinds,
            bodies: self.bodies,
            motion: integrate::Params { dt_s: 0.0, alpha_per_s: self.alpha_per_s },
            dt_bound_s: 0.0,
            omega_bound_rad_per_s: 0.0,
            skin_m: self.skin_ratio * mean_r,
            threading: Threading::Pool,
            parallel_min_contacts: super::PARALLEL_MIN_CONTACTS,
            uniform_radius_m,
            mirrors,
            actions: Vec::new(),
            shares: (Vec::new(), Vec::new()),
            locals: Vec::new(),
            rate_field,
            state: State { pos_m: pos, vel_mps: vel, spin_rad_per_s: vec![[0.0; 3]; n], contacts, ..Default::default() },
        };
        model.search();
        let links: Vec<Link<'_>> = model
            .state
            .contacts
            .iter()
            .map(|c| {
                let (i, j) = (c.i as usize, c.j as usize);
                let (ri, rj) = (model.spheres.radius_m[i], model.spheres.radius_m[j]);
                Link { ends: [i, j], lever_m: [ri, rj], normal: c.normal, class: &model.classes[c.class as usize] }
            })
            .collect();
        let sp = &model.spheres;
        let omega = omega_max_sq(&sp.radius_m, &sp.mass_kg, &sp.inertia_kg_m2, &sp.held, &links).sqrt();
        // Nothing free (every sphere driven, a kinematic test of a law): the step must be given.
        let driven_only = omega == 0.0 && self.dt_s.is_some();
        if !(omega > 0.0 && omega.is_finite()) && !driven_only {
            return Err(Error::input("class", format!("the contacts give no finite frequency bound ({omega} rad/s): no free sphere in a contact?")));
        }
        model.omega_bound_rad_per_s = omega;
        // A restitution dashpot on the lagged velocity costs the stable step the factor
        // √(1 + ζ²) − ζ (`kernel::stability::critical_step_s`), at the largest ζ of any class.
        let zeta = model.classes.iter().map(|c| c.contact_damping_ratio).fold(0.0, f64::max);
        model.dt_bound_s = crate::kernel::stability::critical_step_s(omega, zeta);
        model.motion.dt_s = self.dt_s.unwrap_or(self.safety * model.dt_bound_s);
        let dt = model.motion.dt_s;
        model.classes.iter_mut().for_each(|c| c.rate.set_time_step(dt));
        model.state.ledger.initial_j = model.kinetic_energy_j() + model.strain_energy_j();
        Ok(model)
    }
}
