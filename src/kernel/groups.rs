//! Four consecutive contacts of one class at once, in lanes ([`super::lanes`]), through the same
//! laws as one contact at a time ([`super::law`], [`super::geometry`], written once over
//! `Real`), with no rate, compaction or damping part: so the forces and the history are bitwise
//! those of four scalar calls.
//!
//! * [`bonds`]: four intact bonds of one class, when each stays on the elastic branch of the
//!   bond law (below both plateaus, not breaking): nearly every contact-step of a lattice that
//!   is loaded but not failing (the benchmark block; the peers' beam until it cracks).
//! * [`mixed`]: any four of one class, whatever their kinds: intact bonds on the elastic branch,
//!   frictional pairs touching (sticking or sliding) or apart (forgetting, or with nothing to
//!   forget). A cracked body's contact list mixes the kinds at random, so the scalar loop's kind
//!   tests are guessed wrong about half the time; here every lane computes every kind and keeps
//!   its own, with one test per group (does some bond leave the elastic branch?) that is almost
//!   never true. On the all-bonded groups [`bonds`], which computes only the bonds, is faster,
//!   so the contact loop keeps both.
//!
//! A group where some bond leaves the elastic branch yields nothing and changes nothing: the
//! caller evaluates its contacts one by one with the full law.

use super::contact::{Bond, Contact, ContactForce};
use super::geometry::{self, Geometry};
use super::lanes::{Lanes, Mask};
use super::law::{self, ContactClass, Dissipation, Kinematics, PartSet, failure, friction, normal, rate, tangential};

/// Contacts per group.
pub const LANES: usize = 4;

/// A group's outcome when every bond stayed elastic, in contact order.
pub struct Group {
    /// Forces of the four bonds.
    pub force: [ContactForce; LANES],
    /// New elastic shear displacement u_t of each, m.
    pub ut_m: [f64; LANES],
}

/// True when the four contacts are intact bonds of one class (one branch for the four: on a
/// cracked body the answer changes from group to group).
#[inline(always)]
pub fn eligible(cs: &[Contact; LANES]) -> bool {
    // Bits that differ from the first class, and any bond that is not intact (`Intact` is 0):
    // one test of the ORs instead of four keys compared.
    const { assert!(Bond::Intact as u8 == 0) };
    let k0 = cs[0].class;
    let classes = (cs[1].class ^ k0) | (cs[2].class ^ k0) | (cs[3].class ^ k0);
    let bonds = cs[0].bond as u8 | cs[1].bond as u8 | cs[2].bond as u8 | cs[3].bond as u8;
    (classes == 0) & (bonds == 0)
}

/// True when the four contacts are of one class (the lanes share its constants).
#[inline(always)]
pub fn one_class(cs: &[Contact; LANES]) -> bool {
    let k0 = cs[0].class;
    (cs[1].class == k0) & (cs[2].class == k0) & (cs[3].class == k0)
}

/// The four bonds `cs` ([`eligible`], class `k`) of geometry `geo` ([`geometry::of_four`]) at
/// half-step velocities `vel` over `dt_s`: their forces and new shear springs if all four stay
/// elastic, else None. The contacts are not written (the caller stores `ut_m`).
#[inline(always)]
pub fn bonds<L: Lanes>(geo: &Geometry<L>, vel: &[[f64; 3]], cs: &[Contact; LANES], k: &ContactClass, dt_s: f64) -> Option<Group> {
    let g = kinematics(geo, vel, cs, k);
    let b = bond_branch(&g, cs, k, dt_s);
    if !b.elastic.all() {
        return None;
    }
    Some(Group { force: forces(law::components(&g, b.f_n, b.f_t)), ut_m: b.ut_m.to_array() })
}

/// The four contacts `cs` ([`one_class`], class `k`) of geometry `geo` at half-step velocities
/// `vel` over `dt_s`, with the parts `P` (no rate, compaction or damping part): their forces,
/// with their history updated and the friction they dissipate added to `d` lane by lane in
/// contact order (as the scalar loop adds it; a lane that dissipates nothing adds +0, which
/// leaves a sum that starts at +0 unchanged), if every intact bond among them stays elastic;
/// else None, with nothing changed.
#[inline(always)]
pub fn mixed<L: Lanes, P: PartSet>(
    geo: &Geometry<L>,
    vel: &[[f64; 3]],
    cs: &mut [Contact; LANES],
    k: &ContactClass,
    dt_s: f64,
    d: &mut Dissipation,
) -> Option<[ContactForce; LANES]> {
    debug_assert!(!P::RATE && !P::COMPACTION && !P::DAMPING);
    let zero = L::zero();
    let intact = L::mask(|l| cs[l].bond == Bond::Intact);
    let (rest, ut0) = (L::gather(|l| cs[l].rest_m), L::gather(|l| cs[l].ut_m));
    let rs = L::splat(k.radius_sum_m);
    // Four frictional pairs apart with nothing to forget: what the lanes below would give them
    // — no force, nothing written, +0 booked — without their kinematics and laws. A sixth of
    // the groups at the end of the peers' beam, which has broken three quarters of its bonds.
    if (!intact & friction::idle(ut0, rest, rs, geo.d2_m2)).all() {
        return Some([ContactForce::default(); LANES]);
    }
    let g = kinematics(geo, vel, cs, k);
    // Bonds: the elastic branch, as `bonds` takes it.
    let bond = bond_branch(&g, cs, k, dt_s);
    if !bond.elastic.all_where(intact) {
        return None;
    }
    // Frictional pairs (`friction::touching` with kt_last = kt, `friction::apart`).
    let s = &k.contact.springs;
    let touching = !friction::is_apart(geo.d2_m2, rest);
    let fn_fric = normal::frictional(g.d_m - rest, L::splat(s.kn_n_per_m));
    let (ft_fric, ut_touch, w_touch) = if P::FRICTION {
        let (kt, limit) = (L::splat(s.kt_n_per_m), friction::coulomb(fn_fric, L::splat(k.contact.mu), L::splat(k.contact.cohesion_n)));
        // No limit in the lanes whose outcome is another kind's, so that only a touching
        // frictional pair that slides makes the lanes take the capped branch.
        let limit = L::select(!intact & touching, limit, L::splat(f64::INFINITY));
        tangential::capped_spring(ut0, g.vt_mps * L::splat(dt_s), kt, kt, limit)
    } else {
        (zero, ut0, zero)
    };
    let (ut_apart, rest_apart, w_apart) = friction::forget(ut0, rest, L::splat(0.5 * s.kt_n_per_m), rs, #[inline(always)] || g.d_m);

    // Each lane keeps its own kind's outcome.
    let pushing = intact | touching;
    let f_n = L::select(intact, bond.f_n, fn_fric);
    let f_t = L::select(intact, bond.f_t, ft_fric);
    let force = forces(law::components(&g, f_n, f_t).map(|x| x.keep(pushing)));
    let ut = L::select(intact, bond.ut_m, L::select(touching, ut_touch, ut_apart)).to_array();
    let rest = L::select(pushing, rest, rest_apart).to_array();
    let w = L::select(intact, zero, L::select(touching, w_touch, w_apart)).to_array();
    for (l, c) in cs.iter_mut().enumerate() {
        c.ut_m = ut[l];
        c.rest_m = rest[l];
        d.friction_j += w[l];
    }
    Some(force)
}

/// The bond law's elastic branch in lanes (`law::bonded` with no optional part:
/// `normal::elastic`, `tangential::trial`, `failure::breaks`).
struct Branch<L: Lanes> {
    /// Normal force Kn (d − d0 − δ_p), N (tension positive).
    f_n: L,
    /// Shear force Kt u_t, N.
    f_t: L,
    /// The trial shear spring u_t + v_t Δt, m.
    ut_m: L,
    /// Where the bond stays elastic (below both plateaus, holding).
    elastic: L::Mask,
}

/// [`Branch`] of the four contacts `cs` (class `k`) at `g` over `dt_s`, taken as bonds.
#[inline(always)]
fn bond_branch<L: Lanes>(g: &Kinematics<L>, cs: &[Contact; LANES], k: &ContactClass, dt_s: f64) -> Branch<L> {
    let xi = rate::STATIC[2];
    let dp = L::gather(|l| cs[l].dp_m);
    let opening = g.d_m - L::gather(|l| cs[l].rest_m);
    let (f_n, below_plateau) = normal::elastic(opening, dp, L::splat(k.bond.kn_n_per_m), L::splat(k.strength.normal_force_n * xi));
    let ut0 = L::gather(|l| cs[l].ut_m);
    let (ut_m, f_t, below_cap) = tangential::trial(ut0, g.vt_mps * L::splat(dt_s), L::splat(k.bond.kt_n_per_m), L::splat(k.strength.shear_force_n * xi));
    let holds = !failure::breaks(dp, L::splat(k.strength.plastic_opening_at_break_m));
    Branch { f_n, f_t, ut_m, elastic: below_plateau & below_cap & holds }
}

/// Kinematics of the four contacts `cs` (class `k`, geometry `geo`) at half-step velocities
/// `vel`, lane l contact l (`geometry::relative`, as the scalar loop's `along`).
#[inline(always)]
fn kinematics<L: Lanes>(geo: &Geometry<L>, vel: &[[f64; 3]], cs: &[Contact; LANES], k: &ContactClass) -> Kinematics<L> {
    let (vxi, vyi) = L::xy(vel, |l| cs[l].i as usize);
    let (vxj, vyj) = L::xy(vel, |l| cs[l].j as usize);
    let (wi, wj) = (L::gather(|l| vel[cs[l].i as usize][2]), L::gather(|l| vel[cs[l].j as usize][2]));
    geometry::relative(geo, vxj - vxi, vyj - vyi, wi, wj, L::splat(k.lever_i), L::splat(k.lever_j))
}

/// The four contacts' forces from their components in lanes.
#[inline(always)]
fn forces<L: Lanes>(c: [L; 4]) -> [ContactForce; LANES] {
    let [fx, fy, ti, tj] = c.map(L::to_array);
    std::array::from_fn(|l| ContactForce { fx: fx[l], fy: fy[l], ti: ti[l], tj: tj[l] })
}
