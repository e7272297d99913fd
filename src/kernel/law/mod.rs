//! The contact law, composed of small parts (LAMMPS GRANULAR style): normal ⊕ tangential ⊕
//! failure for bonds, normal ⊕ Coulomb for frictional contacts ([`friction`]), and the optional
//! parts damping ⊕ rate ⊕ compaction. Everything a part needs lives in this module:
//!
//! * its parameters, one struct per part inside [`ContactClass`], built from the two materials
//!   by [`ContactClass::between`] (YADE's Ip2 functors);
//! * its per-contact state: the core history in [`Contact`] (rest length, shear spring, plastic
//!   opening), the optional parts' in [`Extra`] (a parallel array, allocated only when a part
//!   that needs it is on);
//! * the energy it dissipates, a field of [`Dissipation`] (the ledger, the run summary and the
//!   checkpoint list the fields from there);
//! * whether it runs: [`Parts`], resolved once when the model is built, turned into a type
//!   ([`PartSet`]) by [`Parts::dispatch`], so a part a scene leaves off is not even a branch in
//!   the contact loop.

pub mod compaction;
pub mod damping;
pub mod failure;
pub mod friction;
pub mod normal;
pub mod rate;
pub mod rate_field;
pub mod tangential;

use serde::{Deserialize, Serialize};

use super::contact::{Bond, Contact, ContactForce};
use super::lanes::Real;
use crate::error::Result;
use crate::material::{Arrangement, FailureCriterion, Material, Plane, Strength};

/// A normal and a tangential stiffness, N/m.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Springs {
    /// Normal stiffness Kn, N/m.
    pub kn_n_per_m: f64,
    /// Tangential stiffness Kt, N/m.
    pub kt_n_per_m: f64,
}

/// Parameters of one kind of contact (a pair of element kinds): configuration, fixed when the
/// model is built. The fields every contact reads come first, in declaration order (`repr(C)`),
/// so that they share the first cache lines; the rate part's tables come last.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[repr(C)]
pub struct ContactClass {
    /// Springs of a bond (eq 1.1, 3.1–3.2; two materials: half-springs in series).
    pub bond: Springs,
    /// Bond strength (plateaus and breaking opening; two materials: the weaker).
    pub strength: Strength,
    /// Share of the centre distance from i's centre to the contact point: r_i/(r_i + r_j).
    pub lever_i: f64,
    /// Share for j: r_j/(r_i + r_j).
    pub lever_j: f64,
    /// r_i + r_j, m: a new pair's rest length.
    pub radius_sum_m: f64,
    /// Frictional contacts: springs and Coulomb constants.
    pub contact: friction::Params,
    /// Dashpots (stiffness-proportional Rayleigh damping).
    pub damping: damping::Params,
    /// Compaction.
    pub compaction: compaction::Params,
    /// Strain-rate effects.
    pub rate: rate::Params,
}

/// One element kind's side of a contact class.
#[derive(Debug, Clone, Copy)]
pub struct Side<'a> {
    /// Its material.
    pub material: &'a Material,
    /// Its lattice.
    pub arrangement: Arrangement,
    /// Its radius, m.
    pub radius_m: f64,
}

/// What the classes are built in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Context {
    /// Plane idealisation.
    pub plane: Plane,
    /// Out-of-plane thickness t, m.
    pub thickness_m: f64,
    /// Stiffness-proportional Rayleigh coefficient β, s.
    pub beta_s: f64,
    /// Fastest initial or prescribed speed in the scene, m/s (the default rate cap).
    pub max_speed_mps: f64,
}

impl ContactClass {
    /// The class between two element kinds.
    pub fn between(a: Side<'_>, b: Side<'_>, ctx: &Context) -> Result<ContactClass> {
        let (ma, mb) = (a.material, b.material);
        let t = ctx.thickness_m;
        let (sa, sb) = (ma.stiffness(ctx.plane, a.arrangement, t)?, mb.stiffness(ctx.plane, b.arrangement, t)?);
        let bond = Springs {
            kn_n_per_m: friction::series(sa.kn_n_per_m, sb.kn_n_per_m),
            kt_n_per_m: friction::series(sa.kt_n_per_m, sb.kt_n_per_m),
        };
        let r = 0.5 * (a.radius_m + b.radius_m);
        let (qa, qb) = (ma.strength(ctx.plane, a.arrangement, r, t)?, mb.strength(ctx.plane, b.arrangement, r, t)?);
        let strength = Strength {
            normal_force_n: qa.normal_force_n.min(qb.normal_force_n),
            shear_force_n: qa.shear_force_n.min(qb.shear_force_n),
            plastic_opening_at_break_m: qa.plastic_opening_at_break_m.min(qb.plastic_opening_at_break_m),
        };
        let contact = friction::Params::between(ma, sa.kn_n_per_m, mb, sb.kn_n_per_m, t);
        let sum = a.radius_m + b.radius_m;
        // The energy criterion's G_f area per bond, recovered from the combined strength.
        let energy = ma.failure == FailureCriterion::StrengthEnergy && mb.failure == FailureCriterion::StrengthEnergy;
        let gf_area_j = if energy && strength.normal_force_n.is_finite() && strength.plastic_opening_at_break_m.is_finite() {
            strength.normal_force_n * (strength.plastic_opening_at_break_m + 0.5 * strength.normal_force_n / bond.kn_n_per_m)
        } else {
            0.0
        };
        let fc = |s: Side<'_>| -> Result<f64> { compaction::critical_force_n(s.material, ctx.plane, s.arrangement, r, t) };
        let compaction = if ma.compaction.is_some() && mb.compaction.is_some() {
            compaction::Params::between((ma.compaction, fc(a)?), (mb.compaction, fc(b)?), bond.kn_n_per_m)
        } else {
            compaction::Params::default()
        };
        Ok(ContactClass {
            bond,
            strength,
            contact,
            radius_sum_m: sum,
            lever_i: a.radius_m / sum,
            lever_j: b.radius_m / sum,
            damping: damping::Params::new(ctx.beta_s, bond, contact.springs),
            rate: rate::Params::between(rate::Source::of(ma), rate::Source::of(mb), sum, ctx.max_speed_mps, gf_area_j),
            compaction,
        })
    }

    /// Fix what depends on the time step (the rate part's memory).
    pub fn set_time_step(&mut self, dt_s: f64) {
        self.rate.set_time_step(dt_s);
    }

    /// The stiffest springs a bond of this class can have, N/m: the static ones times the
    /// largest modulus ratio of the rate part (at its cap). Full compaction returns to the
    /// initial Kn and the yield line is softer (K_c ≤ Kn), so compaction adds nothing.
    pub fn stiffest_bond(&self) -> Springs {
        let r = self.rate.max_modulus_ratio();
        let c = self.compaction.stiffness_n_per_m;
        Springs { kn_n_per_m: (self.bond.kn_n_per_m * r).max(c), kt_n_per_m: self.bond.kt_n_per_m * r }
    }

    /// The stiffest springs a frictional contact of this class can have, N/m (they are static).
    pub fn stiffest_contact(&self) -> Springs {
        if self.contact.has_friction() { self.contact.springs } else { Springs { kn_n_per_m: self.contact.springs.kn_n_per_m, kt_n_per_m: 0.0 } }
    }
}

/// The optional parts a model runs (resolved once, when it is built).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct Parts {
    /// Coulomb friction on frictional contacts (some class has μ > 0 or cohesion).
    pub friction: bool,
    /// Contact dashpots (β > 0).
    pub damping: bool,
    /// Strain-rate effects (some class's materials both have a rate law).
    pub rate: bool,
    /// Compaction (some class's materials both compact).
    pub compaction: bool,
}

impl Parts {
    /// The parts the classes need.
    pub fn resolve(classes: &[ContactClass], beta_s: f64) -> Parts {
        Parts {
            friction: classes.iter().any(|k| k.contact.has_friction()),
            damping: beta_s > 0.0,
            rate: classes.iter().any(|k| k.rate.enabled),
            compaction: classes.iter().any(|k| k.compaction.enabled),
        }
    }

    /// True when contacts carry an [`Extra`] slot.
    pub fn needs_extra(self) -> bool {
        self.rate || self.compaction
    }

    /// Call `v` with the [`PartSet`] type of these parts.
    pub fn dispatch<V: PartsVisitor>(self, v: V) -> V::Output {
        macro_rules! arms {
            ($($f:literal $d:literal $r:literal $c:literal),*) => {
                match (self.friction, self.damping, self.rate, self.compaction) {
                    $(($f, $d, $r, $c) => v.visit::<With<$f, $d, $r, $c>>(),)*
                }
            };
        }
        arms!(
            false false false false, false false false true, false false true false, false false true true,
            false true false false, false true false true, false true true false, false true true true,
            true false false false, true false false true, true false true false, true false true true,
            true true false false, true true false true, true true true false, true true true true
        )
    }
}

/// A set of optional parts as a type: the contact loop is compiled once per set.
pub trait PartSet {
    /// Coulomb friction.
    const FRICTION: bool;
    /// Contact dashpots.
    const DAMPING: bool;
    /// Strain-rate effects.
    const RATE: bool;
    /// Compaction.
    const COMPACTION: bool;
    /// Contacts carry an [`Extra`] slot.
    const EXTRA: bool = Self::RATE || Self::COMPACTION;
}

/// The [`PartSet`] with the given parts on.
#[derive(Debug, Clone, Copy)]
pub struct With<const F: bool, const D: bool, const R: bool, const C: bool>;

impl<const F: bool, const D: bool, const R: bool, const C: bool> PartSet for With<F, D, R, C> {
    const FRICTION: bool = F;
    const DAMPING: bool = D;
    const RATE: bool = R;
    const COMPACTION: bool = C;
}

/// Something to run with the parts as a type (see [`Parts::dispatch`]).
pub trait PartsVisitor {
    /// What it returns.
    type Output;
    /// Run with part set `P`.
    fn visit<P: PartSet>(self) -> Self::Output;
}

/// Per-contact state of the optional parts (present when [`Parts::needs_extra`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Extra {
    /// Initial centre distance L0 of a bond, m (eq 6.7; the full-compaction limit).
    pub length0_m: f64,
    /// Held strain rate (sets the strengths), 1/s (see [`rate`]).
    pub rate_per_s: f64,
    /// Mean strain rate (sets the moduli), 1/s.
    pub rate_mean_per_s: f64,
    /// Modulus ratio the springs had in the last step.
    pub modulus_ratio: f64,
    /// Relative normal velocity of the last step (half-step value), m/s: the rate part reads
    /// the mean of it and this step's (see [`rate`], "The rate").
    pub vn_last_mps: f64,
}

impl Extra {
    /// A contact at rest with initial length `length0_m`.
    pub fn new(length0_m: f64) -> Extra {
        Extra { length0_m, rate_per_s: 0.0, rate_mean_per_s: 0.0, modulus_ratio: 1.0, vn_last_mps: 0.0 }
    }
}

crate::kernel::ledger::mechanisms! {
    /// Energy the 2D contacts dissipated, J, by mechanism, and the bonds broken.
    Dissipation {
    /// Plastic work on the bond plateaus (normal and shear), J.
    plastic_work_j,
    /// Elastic energy released by bonds breaking, J.
    fracture_energy_j,
    /// Coulomb sliding and shear springs released on separation, J.
    friction_j,
    /// Contact dashpots, J.
    contact_damping_j,
    /// Work along the compaction yield line, J.
    compaction_work_j,
    /// Energy the rate-dependent modulus took out of (> 0) or put into the springs, J.
    rate_work_j,
    }
}

/// Kinematics of a contact at the current configuration (of one contact, or of several in
/// lanes).
#[derive(Debug, Clone, Copy)]
pub struct Kinematics<R = f64> {
    /// Centre distance d, m.
    pub d_m: R,
    /// Unit normal from i to j.
    pub nx: R,
    /// Unit normal y.
    pub ny: R,
    /// Relative normal velocity of j w.r.t. i (> 0 separating), m/s.
    pub vn_mps: R,
    /// Relative tangential velocity of the contact points (j w.r.t. i along t = (−ny, nx)), m/s.
    pub vt_mps: R,
    /// Lever arm of i, m.
    pub li_m: R,
    /// Lever arm of j, m.
    pub lj_m: R,
}

/// Evaluate one touching or bonded contact: update its history and return its force. `x` is
/// the contact's [`Extra`] slot (a scratch value when the parts need none).
#[inline(always)]
pub fn interact<P: PartSet>(c: &mut Contact, x: &mut Extra, k: &ContactClass, g: &Kinematics, dt_s: f64, diss: &mut Dissipation) -> ContactForce {
    if c.bond == Bond::Intact { bonded::<P>(c, x, k, g, dt_s, diss) } else { friction::touching::<P>(c, k, g, dt_s, diss) }
}

/// A bond: normal spring with a tensile plateau (and compaction), shear spring with its
/// plateau, the failure rule, dashpots; springs and strengths scaled by the rate part.
#[inline(always)]
pub fn bonded<P: PartSet>(c: &mut Contact, x: &mut Extra, k: &ContactClass, g: &Kinematics, dt_s: f64, diss: &mut Dissipation) -> ContactForce {
    let ratios = bond_ratios::<P>(x, k, g.vn_mps);
    bonded_at::<P>(c, x, k, g, ratios, dt_s, diss)
}

/// The rate part's ratios for a bond whose relative normal velocity, as the rate reads it, is
/// `vn_rate_mps` (the pair's own, or the smoothed field's: `rate_field`) ([`rate::STATIC`]
/// without it), its rates updated: [`bonded`]'s first step, which reads only the kinematics and
/// the rates, apart so that the contact loop can take it a few contacts ahead of the rest
/// (`forces`).
#[inline(always)]
pub fn bond_ratios<P: PartSet>(x: &mut Extra, k: &ContactClass, vn_rate_mps: f64) -> rate::Ratios {
    if P::RATE && k.rate.enabled {
        k.rate.update(&mut x.rate_per_s, &mut x.rate_mean_per_s, rate::centred_mps(vn_rate_mps, &mut x.vn_last_mps), 1.0 / x.length0_m)
    } else {
        rate::STATIC
    }
}

/// [`bonded`] with its rate ratios already taken ([`bond_ratios`]).
#[inline(always)]
pub fn bonded_at<P: PartSet>(c: &mut Contact, x: &mut Extra, k: &ContactClass, g: &Kinematics, ratios: rate::Ratios, dt_s: f64, diss: &mut Dissipation) -> ContactForce {
    let opening = g.d_m - c.rest_m;
    let slip = g.vt_mps * dt_s;
    let (mut kn, mut kt) = (k.bond.kn_n_per_m, k.bond.kt_n_per_m);
    let (mut kn_last, mut kt_last) = (kn, kt);
    if P::RATE && k.rate.enabled {
        let ratio = if opening - c.dp_m < 0.0 { ratios[0] } else { ratios[1] };
        (kn_last, kt_last) = (kn * x.modulus_ratio, kt * x.modulus_ratio);
        x.modulus_ratio = ratio;
        kn *= ratio;
        kt *= ratio;
    }
    let xi = ratios[2];
    let step = g.vn_mps * dt_s;
    // Elastic stretches of the last step (the rate part books its work with them, below).
    let (stretch_last, ut_last) = (opening - step - c.dp_m, c.ut_m);
    let (mut f_n, w) = normal::bonded(opening, step, &mut c.dp_m, kn, kn_last, k.strength.normal_force_n * xi);
    if P::COMPACTION && k.compaction.enabled && f_n < 0.0 {
        let (f, work) = k.compaction.compress(f_n, step, (kn, kn_last), &mut c.rest_m, x.length0_m, ratios[3]);
        f_n = f;
        diss.compaction_work_j += work;
    }
    let (ft, ut, ws) = tangential::capped_spring(c.ut_m, slip, kt, kt_last, k.strength.shear_force_n * xi);
    if P::RATE && kn != kn_last {
        // Secant moduli (`rate`): the springs keep their zero; the energy the change of modulus
        // takes out of them is ½ (K_last − K) × (last stretch) × (new stretch), which with the
        // return maps' own bookings is the trapezoidal work of the step less the change of the
        // stored energy, as central differences see it.
        diss.rate_work_j += 0.5 * ((kn_last - kn) * stretch_last * (f_n / kn) + (kt_last - kt) * ut_last * ut);
    }
    diss.plastic_work_j += w + ws;
    let at_break = if P::RATE && k.rate.enabled {
        k.rate.opening_at_break_m(k.strength.plastic_opening_at_break_m, k.strength.normal_force_n, xi, kn)
    } else {
        k.strength.plastic_opening_at_break_m
    };
    if failure::breaks(c.dp_m, at_break) {
        diss.fracture_energy_j += failure::released_energy_j(f_n, ft, kn, kt);
        diss.broken += 1;
        c.bond = Bond::Frictional;
        c.dp_m = 0.0;
        c.ut_m = 0.0;
        if P::RATE {
            x.modulus_ratio = 1.0;
        }
        // Breaking needs tension beyond the plateau (opening > δ_p ≥ 0): the pair is apart,
        // and a frictional contact that is apart carries nothing.
        return ContactForce::default();
    }
    c.ut_m = ut;
    let mut f_t = ft;
    if P::DAMPING {
        let (dn, dt) = damping::dashpot(k.damping.bond_n, k.damping.bond_t, g.vn_mps, g.vt_mps);
        f_n += dn;
        f_t += dt;
        diss.contact_damping_j += (dn * g.vn_mps + dt * g.vt_mps) * dt_s;
    }
    force(g, f_n, f_t)
}

/// Elastic energy the contact's springs will hold once this step's slip is added, J: the law
/// is evaluated on a copy (the shear springs' history lags the positions by one step).
#[inline(always)]
pub fn stored_energy_j<P: PartSet>(c: &Contact, x: &Extra, k: &ContactClass, g: &Kinematics, dt_s: f64) -> f64 {
    let (mut probe, mut px) = (*c, *x);
    interact::<P>(&mut probe, &mut px, k, g, dt_s, &mut Dissipation::default());
    match probe.bond {
        Bond::Intact => {
            let (e, mut kn, mut kt) = (g.d_m - probe.rest_m - probe.dp_m, k.bond.kn_n_per_m, k.bond.kt_n_per_m);
            if P::RATE && k.rate.enabled {
                kn *= px.modulus_ratio;
                kt *= px.modulus_ratio;
            }
            0.5 * kn * e * e + 0.5 * kt * probe.ut_m * probe.ut_m
        }
        Bond::Frictional if g.d_m < probe.rest_m => {
            let (e, s) = (g.d_m - probe.rest_m, &k.contact.springs);
            0.5 * s.kn_n_per_m * e * e + 0.5 * s.kt_n_per_m * probe.ut_m * probe.ut_m
        }
        Bond::Frictional => 0.0,
    }
}

/// Cartesian force on i and the torques, from the normal (tension positive) and tangential force.
#[inline(always)]
pub(crate) fn force(g: &Kinematics, f_n: f64, f_t: f64) -> ContactForce {
    let [fx, fy, ti, tj] = components(g, f_n, f_t);
    ContactForce { fx, fy, ti, tj }
}

/// [`force`] over any [`Real`]: [Fx N, Fy N, T_i N·m, T_j N·m].
#[inline(always)]
pub(crate) fn components<R: Real>(g: &Kinematics<R>, f_n: R, f_t: R) -> [R; 4] {
    [f_n * g.nx - f_t * g.ny, f_n * g.ny + f_t * g.nx, g.li_m * f_t, g.lj_m * f_t]
}
