//! The 3D contact law, composed as the 2D one is: normal ⊕ shear ⊕ failure for a bond, normal ⊕
//! Coulomb for a frictional contact, and the moment transfer law's rolling ⊕ twisting parts
//! (seed 004) where a class turns them on. Where the physics is the 2D kernel's, so is the code:
//! the bond's normal spring with its tensile plateau (`kernel::law::normal`), the failure rule
//! (`kernel::law::failure`), Coulomb's limit (`kernel::law::friction::coulomb`) and the scalar
//! return map (`kernel::law::tangential`, for the twist). What is 3D here: the shear spring and
//! the rolling moment as vectors in the contact plane ([`capped`]), carried as the contact turns.

pub mod capped;
pub mod rolling;
pub mod twisting;

use serde::{Deserialize, Serialize};

use super::contact::{Bond, Contact};
use super::vec3::{V3, add, carried, cross, dot, in_plane, norm, scale, sub};
use crate::kernel::law::{compaction, failure, friction, normal, rate};

/// Parameters of one kind of contact: configuration, fixed when the model is built. Every
/// stiffness and strength is a modulus, scaled at each contact by its mean radius r̄ (k_n and
/// k_s by r̄, k_r and k_t by r̄³, forces by the bond's area π r̄²), so a packing of other
/// sphere sizes gives the same material without recalibration (`kernel3d::stiffness`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Class {
    /// Bond normal stiffness over r̄, Pa (k_n = this × r̄).
    pub bond_kn_pa: f64,
    /// Bond shear stiffness over r̄, Pa.
    pub bond_ks_pa: f64,
    /// Bond tensile strength, Pa: the plateau is this × π r̄² (∞: no yield).
    pub bond_tension_pa: f64,
    /// Bond shear strength, Pa: the shear plateau is this × π r̄² (∞: none).
    pub bond_shear_pa: f64,
    /// Fracture energy G_f, J/m²: a bond breaks when the work of its normal force reaches
    /// G_f π r̄² (seed 000 §5, eq 5.7, on the bond's area; 0: at the plateau; ∞: never).
    pub bond_fracture_j_per_m2: f64,
    /// Frictional contacts: normal stiffness over r̄, Pa.
    pub kn_pa: f64,
    /// Frictional contacts: shear stiffness over r̄, Pa.
    pub ks_pa: f64,
    /// Coulomb coefficient μ.
    pub mu: f64,
    /// Frictional contacts: damping ratio ζ of the normal dashpot that gives them their
    /// coefficient of restitution ([`restitution_damping_ratio`]; 0: elastic, e = 1).
    #[serde(default)]
    pub contact_damping_ratio: f64,
    /// The most shear stress a contact carries, Pa, bonded (its shear plateau) or frictional
    /// (its Coulomb limit), on π r̄²: crushed concrete's limit, which grains that cannot break
    /// do not have (∞: none).
    #[serde(default = "unlimited")]
    pub crushed_shear_pa: f64,

    /// Rolling resistance (None: off).
    pub rolling: Option<rolling::Params>,
    /// Twisting resistance (None: off).
    pub twisting: Option<twisting::Params>,
    /// Strain-rate effects on the bonds (seed 000 §6: the 2D kernel's rate part; off unless
    /// `enabled`).
    #[serde(default)]
    pub rate: rate::Params,
    /// Compaction of the bonds in compression (seed 000 eq 6.11, the 2D kernel's return map) at
    /// a critical stress f'c on the bond's area π r̄² (None: off).
    #[serde(default)]
    pub compaction: Option<Compaction>,
}

fn unlimited() -> f64 {
    f64::INFINITY
}

/// A class's compaction: the critical compressive force is `critical_pa` × π r̄², the yield
/// line's slope `law.stiffness_ratio` × the bond's k_n, full at `law.full_strain`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Compaction {
    /// f'c, Pa.
    pub critical_pa: f64,
    /// The law.
    pub law: crate::material::CompactionSpec,
}

impl Class {
    /// An elastic class: bonds of normal stiffness `kappa_n_pa` × r̄ and shear `alpha` times it
    /// that never yield or break, frictional contacts with the same springs and Coulomb `mu`,
    /// no moment transfer (`kernel3d::stiffness::springs` gives κ_n and α for E and ν).
    pub fn elastic(kappa_n_pa: f64, alpha: f64, mu: f64) -> Class {
        Class {
            bond_kn_pa: kappa_n_pa,
            bond_ks_pa: alpha * kappa_n_pa,
            bond_tension_pa: f64::INFINITY,
            bond_shear_pa: f64::INFINITY,
            bond_fracture_j_per_m2: f64::INFINITY,
            kn_pa: kappa_n_pa,
            ks_pa: alpha * kappa_n_pa,
            mu,
            contact_damping_ratio: 0.0,
            crushed_shear_pa: f64::INFINITY,
            rolling: None,
            twisting: None,
            rate: rate::Params::default(),
            compaction: None,
        }
    }
}

/// The damping ratio ζ of a linear spring–dashpot that parts two bodies meeting head-on at e
/// times their approach speed: ζ = −ln e / √(π² + ln² e) (the LAMMPS GRANULAR and YADE
/// viscoelastic form; e = 1 gives 0).
pub fn restitution_damping_ratio(e: f64) -> f64 {
    let l = e.ln();
    -l / (std::f64::consts::PI * std::f64::consts::PI + l * l).sqrt()
}

/// A class's springs and strengths at one contact of mean radius r̄.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Local {
    /// Bond springs, N/m.
    pub bond_kn: f64,
    /// Bond shear spring, N/m.
    pub bond_ks: f64,
    /// Bond tensile plateau, N.
    pub tension_n: f64,
    /// Bond shear plateau, N.
    pub shear_n: f64,
    /// The most shear force the contact carries, bonded or frictional, N (∞: no limit).
    pub crushed_shear_n: f64,
    /// Plastic opening at which the bond breaks, m.
    pub at_break_m: f64,
    /// Frictional springs, N/m.
    pub kn: f64,
    /// Frictional shear spring, N/m.
    pub ks: f64,
    /// Rolling stiffness, N·m/rad (0: off).
    pub kr: f64,
    /// Twisting stiffness, N·m/rad (0: off).
    pub kt: f64,
    /// 1/r̄, 1/m (the rolling angle's divisor).
    pub per_r_mean: f64,
    /// G_f π r̄², J (the rate part's dynamic opening at break).
    pub fracture_area_j: f64,
    /// The bond's compaction at this contact (off: `enabled` false).
    pub compaction: compaction::Params,
}

impl Class {
    /// The springs and strengths at a contact of mean radius `r_m` (m).
    #[inline]
    pub fn at(&self, r_m: f64) -> Local {
        let area = std::f64::consts::PI * r_m * r_m;
        let (bond_kn, tension_n) = (self.bond_kn_pa * r_m, self.bond_tension_pa * area);
        // The area under the normal force–opening curve, F_t²/(2 k_n) + F_t δ_p, reaches
        // G_f A at δ_p = G_f A / F_t − F_t / (2 k_n) (the 2D kernel's rule, on the 3D area).
        let at_break_m = if self.bond_fracture_j_per_m2.is_infinite() || tension_n.is_infinite() {
            f64::INFINITY
        } else {
            (self.bond_fracture_j_per_m2 * area / tension_n - 0.5 * tension_n / bond_kn).max(0.0)
        };
        let r3 = r_m * r_m * r_m;
        Local {
            bond_kn,
            bond_ks: self.bond_ks_pa * r_m,
            tension_n,
            shear_n: self.bond_shear_pa * area,
            crushed_shear_n: self.crushed_shear_pa * area,
            at_break_m,
            kn: self.kn_pa * r_m,
            ks: self.ks_pa * r_m,
            kr: self.rolling.map_or(0.0, |p| p.kr_pa * r3),
            kt: self.twisting.map_or(0.0, |p| p.kt_pa * r3),
            per_r_mean: 1.0 / r_m,
            fracture_area_j: self.bond_fracture_j_per_m2 * area,
            compaction: self.compaction.map_or(compaction::Params::default(), |c| compaction::Params {
                enabled: true,
                critical_force_n: c.critical_pa * area,
                stiffness_n_per_m: c.law.stiffness_ratio * bond_kn,
                full_strain: c.law.full_strain,
            }),
        }
    }
}

/// What one contact's law needs of the two spheres at this step.
#[derive(Debug, Clone, Copy)]
pub struct Pair {
    /// Radii, m.
    pub r: [f64; 2],
    /// Centre of j minus centre of i, m.
    pub dx_m: V3,
    /// Half-step velocities, m/s.
    pub v: [V3; 2],
    /// Half-step spins, rad/s.
    pub w: [V3; 2],
    /// Masses, kg (the restitution dashpot's reduced mass).
    pub m: [f64; 2],
}

/// A contact's action: the force on j (i takes its opposite), N, and the moments on i and j
/// about their centres, N·m.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Action {
    /// Force on j, N.
    pub force_j_n: V3,
    /// Moment on i, N·m.
    pub moment_i_nm: V3,
    /// Moment on j, N·m.
    pub moment_j_nm: V3,
}

crate::kernel::ledger::mechanisms! {
    /// Energy the 3D contacts dissipated, J, by mechanism, and the bonds broken.
    Dissipation {
        /// Sliding of frictional contacts (Coulomb), J.
        slip_j,
        /// Intact bonds sheared along their shear plateau, J.
        bond_shear_j,
        /// The bond's tensile plateau, J.
        plastic_j,
        /// Rolling past its cap, J.
        rolling_j,
        /// Twisting past its cap, J.
        twisting_j,
        /// Elastic energy of bonds when they broke, J.
        fracture_j,
        /// Work along the bonds' compaction yield line, J.
        compaction_j,
        /// Frictional contacts' normal dashpots (a restitution below 1), J.
        collision_j,
        /// Energy the rate-dependent moduli took out of (> 0) or put into the bonds, J.
        rate_j,
    }
}

/// The contact's action at this step, its history advanced. Increments use the half-step
/// velocities (central differences, as in 2D); the history's frame turns from the stored normal
/// to the present one.
pub fn act(c: &mut Contact, class: &Class, g: &Pair, dt_s: f64, diss: &mut Dissipation) -> Action {
    act_at(c, class, &class.at(mean_radius_m(g.r)), g, None, dt_s, diss)
}

/// The mean radius r̄ a contact's springs are scaled by (`Class::at`), m, of radii `r` (m).
#[inline(always)]
pub fn mean_radius_m(r: [f64; 2]) -> f64 {
    0.5 * (r[0] + r[1])
}

/// [`act`] with the class's springs at this contact, `k` = `class.at(mean_radius_m(g.r))`, given:
/// the step takes them once per class when every sphere has the same radius (the same bits).
/// `rate` is the rate part's smoothed velocity at i and at j, m/s (None: the bond reads its
/// own pair's velocities; `kernel::law::rate_field`).
#[inline(always)]
pub fn act_at(c: &mut Contact, class: &Class, k: &Local, g: &Pair, rate: Option<[V3; 2]>, dt_s: f64, diss: &mut Dissipation) -> Action {
    let d = norm(g.dx_m);
    let n = scale(1.0 / d, g.dx_m);
    let n_old = c.normal;
    let [ri, rj] = g.r;
    // Lever arms to the contact point, shared in proportion to the radii.
    let (li, lj) = (d * ri / (ri + rj), d * rj / (ri + rj));
    // Velocity of j's material point at the contact relative to i's.
    let vi = add(g.v[0], cross(g.w[0], scale(li, n)));
    let vj = add(g.v[1], cross(g.w[1], scale(-lj, n)));
    let v_rel = sub(vj, vi);
    let opening = d - c.rest_m;
    let step = dot(v_rel, n) * dt_s;
    let slip = scale(dt_s, in_plane(v_rel, n));
    let shear_last = carried(c.shear_n, n);
    let (f_n, shear) = match c.bond {
        Bond::Intact => {
            // One source for a bond with its rate or compaction state (`extra`) and without
            // (compiled twice: the static bond pays nothing for the parts it does not have).
            let at = Geometry { d, n, n_old, opening, step, slip, shear_last };
            let kept = if c.extra.is_some() { bonded::<true>(c, class, k, g, &at, rate, dt_s, diss) } else { bonded::<false>(c, class, k, g, &at, rate, dt_s, diss) };
            match kept {
                Some(fs) => fs,
                // Broken in tension past the plateau: apart, carrying nothing.
                None => return Action::default(),
            }
        }
        Bond::Frictional => {
            if opening >= 0.0 {
                // Apart: the history is forgotten, what the springs held booked where it went,
                // with the last values' half of their work over this step's increments (what
                // central differences took out of the kinetic energy).
                diss.slip_j += 0.5 * dot(c.shear_n, c.shear_n) / k.ks - 0.5 * dot(shear_last, slip);
                let (rolling, twisting) = moments_split_j(c, k);
                let (rolling_w, twisting_w) = last_moments_half_work_j(c, class, k, (g.r, g.w), (n_old, n), dt_s);
                diss.rolling_j += rolling + rolling_w;
                diss.twisting_j += twisting + twisting_w;
                c.forget(ri + rj, d);
                c.normal = n;
                return Action::default();
            }
            let mut f_n = normal::frictional(opening, k.kn);
            if class.contact_damping_ratio > 0.0 {
                // The restitution dashpot 2 ζ √(m* k_n) on the normal relative velocity (the half
                // step's: explicit, paid for in the stable step). Not clamped at zero force: as
                // in LAMMPS GRANULAR without limit_damping, the pair then parts at e exactly (a
                // clamp parts it early, at 0.55 for e = 0.5), pulled together only in the last
                // instants of an overlap.
                let [mi, mj] = g.m;
                let c = 2.0 * class.contact_damping_ratio * (mi * mj / (mi + mj) * k.kn).sqrt();
                let v_n = dot(v_rel, n);
                diss.collision_j += c * v_n * v_n * dt_s;
                f_n += c * v_n;
            }
            // A pair the dashpot pulls together holds no friction.
            let limit = friction::coulomb(f_n.min(0.0), class.mu, 0.0).min(k.crushed_shear_n);
            let (s, ws) = capped::capped(shear_last, scale(-1.0, slip), k.ks, limit);
            diss.slip_j += ws;
            (f_n, s)
        }
    };
    c.shear_n = shear;
    // Tension positive pulls j back toward i.
    let force_j = add(scale(-f_n, n), shear);
    let mut a = Action {
        force_j_n: force_j,
        // The shear force acts at the contact point: on j at −l_j n, on i (−force) at +l_i n.
        moment_i_nm: cross(scale(li, n), scale(-1.0, force_j)),
        moment_j_nm: cross(scale(-lj, n), force_j),
    };
    let r_mean = 0.5 * (ri + rj);
    if let Some(p) = &class.rolling {
        let d_theta = rolling::increment_per(ri, rj, k.per_r_mean, n_old, n, g.w[0], g.w[1], dt_s);
        let (m, w) = rolling::moment(carried(c.rolling_nm, n), d_theta, k.kr, p.eta, r_mean, f_n);
        // The moments' work is twice M dθ (`moments_j`).
        diss.rolling_j += 2.0 * w;
        c.rolling_nm = m;
        a.moment_i_nm = sub(a.moment_i_nm, m);
        a.moment_j_nm = add(a.moment_j_nm, m);
    }
    if let Some(p) = &class.twisting {
        let (t, w) = twisting::moment(c.twisting_nm, dot(g.w[0], n), dot(g.w[1], n), dt_s, k.kt, p.cap, ri.min(rj), f_n);
        diss.twisting_j += 2.0 * w;
        c.twisting_nm = t;
        a.moment_i_nm = sub(a.moment_i_nm, scale(t, n));
        a.moment_j_nm = add(a.moment_j_nm, scale(t, n));
    }
    c.normal = n;
    a
}

/// Where a contact is at this step: centre distance d (m), the unit normal n and the last one,
/// the opening d − d0 (m), this step's normal and tangential increments (m) and the shear spring
/// carried into the new contact plane (N).
struct Geometry {
    d: f64,
    n: V3,
    n_old: V3,
    opening: f64,
    step: f64,
    slip: V3,
    shear_last: V3,
}

/// A bond at this step: the normal spring with its tensile plateau (and compaction), the shear
/// spring with its plateau, the failure rule, springs and strengths scaled by the rate part;
/// with `PARTS` the rate and compaction parts act where the class has them (the bond carries
/// their state), without, the static bond. Returns the normal force (tension positive, N) and
/// the shear force on j (N), or None when the bond broke (its energy booked).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn bonded<const PARTS: bool>(c: &mut Contact, class: &Class, k: &Local, g: &Pair, at: &Geometry, rate: Option<[V3; 2]>, dt_s: f64, diss: &mut Dissipation) -> Option<(f64, V3)> {
    let Geometry { d, n, n_old, opening, step, slip, shear_last } = *at;
    let [ri, rj] = g.r;
    // The rate part's ratios (moduli, tensile and compressive strength), the 2D
    // kernel's, from the relative normal velocity of the pair or of the smoothed field.
    let (mut kn, mut ks, mut kn_last, mut ks_last, mut ratios) = (k.bond_kn, k.bond_ks, k.bond_kn, k.bond_ks, rate::STATIC);
    if PARTS
        && class.rate.enabled
        && let Some(x) = c.extra.as_deref_mut()
    {
        let vn = match rate {
            None => dot(sub(g.v[1], g.v[0]), n),
            Some([a, b]) => dot(sub(b, a), n),
        };
        ratios = class.rate.update(&mut x.rate_per_s, &mut x.rate_mean_per_s, rate::centred_mps(vn, &mut x.vn_last_mps), 1.0 / x.length0_m);
        // Secant moduli: the springs keep their zero (`kernel::law::rate`).
        let ratio = if opening - c.plastic_opening_m < 0.0 { ratios[0] } else { ratios[1] };
        (kn_last, ks_last) = (kn * x.modulus_ratio, ks * x.modulus_ratio);
        x.modulus_ratio = ratio;
        (kn, ks) = (kn * ratio, ks * ratio);
    }
    let xi = ratios[2];
    let stretch_last = opening - step - c.plastic_opening_m;
    let (mut f_n, w) = normal::bonded(opening, step, &mut c.plastic_opening_m, kn, kn_last, k.tension_n * xi);
    diss.plastic_j += w;
    if PARTS
        && k.compaction.enabled
        && f_n < 0.0
        && let Some(x) = c.extra.as_deref()
    {
        let (f, work) = k.compaction.compress(f_n, step, (kn, kn_last), &mut c.rest_m, x.length0_m, ratios[3]);
        f_n = f;
        diss.compaction_j += work;
    }
    // The shear spring resists j's slip: its force on j is −k_s × slip.
    let base = if PARTS && ks != ks_last { scale(ks / ks_last, shear_last) } else { shear_last };
    let (s, ws) = capped::capped_from(shear_last, base, scale(-1.0, slip), ks, (k.shear_n * xi).min(k.crushed_shear_n));
    diss.bond_shear_j += ws;
    if PARTS && kn != kn_last {
        // What the change of modulus took out of the springs: ½ (K_last − K) × last
        // stretch × new stretch (`kernel::law::rate`, "Stiffness").
        diss.rate_j += 0.5 * ((kn_last - kn) * stretch_last * (f_n / kn) + (ks_last - ks) * dot(shear_last, s) / (ks_last * ks));
    }
    // With the rate part, the energy criterion's opening at break is (G_f)_d = ξ G_f on
    // the plateau ξ F_t (eq 6.10); a bond that cannot break keeps its ∞.
    let at_break = if PARTS && class.rate.enabled && k.at_break_m.is_finite() { rate::dynamic_opening_m(k.fracture_area_j, k.tension_n, xi, kn) } else { k.at_break_m };
    if failure::breaks(c.plastic_opening_m, at_break) {
        // The bond acts no more from this step: of the springs' work over its increments
        // central differences take the last forces' half (the trapezoid's) and not the
        // new forces' half, which the lines above booked (an error of order Δt a break).
        let unapplied = 0.5 * (f_n * step - dot(s, slip));
        let (rolling, twisting) = last_moments_half_work_j(c, class, k, (g.r, g.w), (n_old, n), dt_s);
        diss.fracture_j += failure::released_energy_j(f_n, norm(s), kn, ks) + moments_j(c, k) - unapplied + rolling + twisting;
        diss.broken += 1;
        c.bond = Bond::Frictional;
        c.plastic_opening_m = 0.0;
        c.extra = None;
        c.forget(ri + rj, d);
        c.normal = n;
        return None;
    }
    Some((f_n, s))
}

/// The work the contact's last rolling and twisting moments do over this step's turns when the
/// contact lets go (their trapezoid's half, M dθ: the moments' work is 2 M dθ), J, apart.
/// Given the radii (m) and spins (rad/s) of the pair, and the old and new normal. Out of line
/// and by value: a reference to the pair kept it out of registers on the hot path (1.12× slower).
#[cold]
#[inline(never)]
fn last_moments_half_work_j(c: &Contact, class: &Class, k: &Local, (r, w): ([f64; 2], [V3; 2]), (n_old, n): (V3, V3), dt_s: f64) -> (f64, f64) {
    let rolling = if class.rolling.is_some() {
        dot(carried(c.rolling_nm, n), rolling::increment_per(r[0], r[1], k.per_r_mean, n_old, n, w[0], w[1], dt_s))
    } else {
        0.0
    };
    let twisting = if class.twisting.is_some() { c.twisting_nm * 0.5 * (dot(w[0], n) - dot(w[1], n)) * dt_s } else { 0.0 };
    (rolling, twisting)
}

/// Elastic energy in the contact's rolling and twisting springs, J: |M|²/k, not ½|M|²/k, since
/// the moment M = k θ acts on both spheres and θ is half their relative turn (the moments'
/// work is 2 M dθ).
fn moments_j(c: &Contact, k: &Local) -> f64 {
    let (rolling, twisting) = moments_split_j(c, k);
    rolling + twisting
}

/// The rolling and the twisting spring's energy apart, J.
fn moments_split_j(c: &Contact, k: &Local) -> (f64, f64) {
    let rolling = if k.kr > 0.0 { dot(c.rolling_nm, c.rolling_nm) / k.kr } else { 0.0 };
    (rolling, if k.kt > 0.0 { c.twisting_nm * c.twisting_nm / k.kt } else { 0.0 })
}

/// Elastic energy the contact's springs hold, J, at centre distance `d_m` between spheres of
/// mean radius `r_mean_m` (m).
pub fn stored_j(c: &Contact, class: &Class, d_m: f64, r_mean_m: f64) -> f64 {
    let k = class.at(r_mean_m);
    // A bond's springs at the rate part's modulus of its last step.
    let ratio = c.extra.as_deref().map_or(1.0, |x| x.modulus_ratio);
    let (kn, ks) = match c.bond {
        Bond::Intact => (k.bond_kn * ratio, k.bond_ks * ratio),
        Bond::Frictional => (k.kn, k.ks),
    };
    let stretch = match c.bond {
        Bond::Intact => d_m - c.rest_m - c.plastic_opening_m,
        Bond::Frictional => (d_m - c.rest_m).min(0.0),
    };
    0.5 * kn * stretch * stretch + 0.5 * dot(c.shear_n, c.shear_n) / ks + moments_j(c, &k)
}
