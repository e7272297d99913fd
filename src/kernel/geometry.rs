//! Contact geometry and kinematics (YADE's Ig2 stage), apart from the law, written once over
//! [`Real`]: from two centres the squared distance ([`between`]; alone it tells a frictional
//! pair that is apart), then where the law needs more the distance and the unit normal
//! ([`of`]), and from the velocities the relative velocity at the contact point
//! ([`relative`]). One contact at a time ([`separation`]) or four in lanes ([`of_four`]).

use super::contact::Contact;
use super::lanes::{Lanes, Real};
use super::law::Kinematics;

/// From i's centre to j's.
#[derive(Clone, Copy)]
pub struct Separation<R = f64> {
    /// x of j's centre less i's, m.
    pub dx_m: R,
    /// y of j's centre less i's, m.
    pub dy_m: R,
    /// dx² + dy², m².
    pub d2_m2: R,
}

/// The geometry of a contact.
#[derive(Debug, Clone, Copy)]
pub struct Geometry<R = f64> {
    /// Squared centre distance d², m².
    pub d2_m2: R,
    /// Centre distance d, m.
    pub d_m: R,
    /// Unit normal from i's centre to j's, x.
    pub nx: R,
    /// Its y.
    pub ny: R,
}

/// The separation of centres (xi m, yi m) and (xj m, yj m).
#[inline(always)]
pub fn between<R: Real>(xi: R, yi: R, xj: R, yj: R) -> Separation<R> {
    let (dx_m, dy_m) = (xj - xi, yj - yi);
    Separation { dx_m, dy_m, d2_m2: dx_m * dx_m + dy_m * dy_m }
}

/// The separation of contact `c` at positions `pos` [x m, y m, θ rad].
#[inline(always)]
pub fn separation(pos: &[[f64; 3]], c: &Contact) -> Separation {
    let (pi, pj) = (pos[c.i as usize], pos[c.j as usize]);
    between(pi[0], pi[1], pj[0], pj[1])
}

/// The geometry of a separation: d = √d², n = (dx, dy) × (1/d).
#[inline(always)]
pub fn of<R: Real>(s: Separation<R>) -> Geometry<R> {
    let d_m = s.d2_m2.sqrt();
    let inv = R::splat(1.0) / d_m;
    Geometry { d2_m2: s.d2_m2, d_m, nx: s.dx_m * inv, ny: s.dy_m * inv }
}

/// The geometry of the four contacts `cs` at `pos`, lane l contact l.
#[inline(always)]
pub fn of_four<L: Lanes>(pos: &[[f64; 3]], cs: &[Contact; 4]) -> Geometry<L> {
    let (xi, yi) = L::xy(pos, |l| cs[l].i as usize);
    let (xj, yj) = L::xy(pos, |l| cs[l].j as usize);
    of(between(xi, yi, xj, yj))
}

/// The kinematics of a contact of geometry `g` whose j moves relative to i at (dvx, dvy) m/s,
/// i and j spinning at `wi`, `wj` rad/s; the contact point divides the distance by the levers
/// r_i/(r_i + r_j) and r_j/(r_i + r_j).
#[inline(always)]
pub fn relative<R: Real>(g: &Geometry<R>, dvx: R, dvy: R, wi: R, wj: R, lever_i: R, lever_j: R) -> Kinematics<R> {
    let (nx, ny, dist) = (g.nx, g.ny, g.d_m);
    let (li, lj) = (dist * lever_i, dist * lever_j);
    Kinematics { d_m: dist, nx, ny, vn_mps: dvx * nx + dvy * ny, vt_mps: -dvx * ny + dvy * nx - li * wi - lj * wj, li_m: li, lj_m: lj }
}
