//! The time step: stability of central differences and bounds on the mesh's top frequency.
//!
//! Central differences are stable for Δt < 2/ω_max without damping. With the stiffness-
//! proportional half of Rayleigh damping on the lagged velocity (ξ = βω/2 at ω_max) the
//! single-mode recurrence (1 + a) z² + (ω²Δt² − 2 + 2ξωΔt) z + (1 − a − 2ξωΔt) = 0 is stable
//! iff ω²Δt² + 4ξωΔt < 4, i.e.
//!
//!   Δt < (2/ω_max) (√(1 + ξ²) − ξ),
//!
//! and the centred mass-proportional half (a = αΔt/2) does not enter. The seed prints eq 2.2
//! with √(1 − ξ²): that is stricter than the recurrence allows (a misprint or a conservative
//! variant; Cook, Malkus & Plesha give √(1 + ξ²)); `tests` check the form used here against the
//! recurrence itself.
//!
//! Top frequency. The seed's 7-element cell gives ω_max ≈ 3.742 √(Kn/m) (eq 2.3), but a free
//! cell is not a bound on an assembled mesh (SPEC §2). Two rigorous bounds are provided:
//! * a regular lattice of identical elements and contacts (any subset of it, with any elements
//!   held fixed) cannot exceed the top of the infinite lattice's dispersion relation: its
//!   stiffness is the infinite lattice's restricted to fewer degrees of freedom, minus the
//!   missing springs (positive semi-definite), so every Rayleigh quotient is bounded by the
//!   infinite lattice's supremum. `lattice_coefficient` scans the Brillouin zone for it.
//! * any mesh: Gershgorin's theorem on D⁻¹ M^-½ K M^-½ D with the rotational degrees of
//!   freedom scaled by the s that minimises the bound (`gershgorin`).
//!
//! The measured top frequency of an assembled mesh comes from Lanczos (`lanczos_top`) or a
//! dense eigen-solve (`dense_top`), both lower estimates of the truth (Rayleigh–Ritz).

use nalgebra::{DMatrix, Matrix6, SymmetricEigen};

use super::Body;
use super::contact::{Bond, Contact};
use super::contacts::Contacts;
use super::law::{ContactClass, Extra, Springs};
use super::state::Elements;
use crate::material::Arrangement;

/// Largest stable step for top frequency `omega_rad_per_s` with stiffness-proportional damping
/// ratio `xi` at that frequency, s.
pub fn critical_step_s(omega_rad_per_s: f64, xi: f64) -> f64 {
    2.0 / omega_rad_per_s * ((1.0 + xi * xi).sqrt() - xi)
}

/// The 6×6 stiffness of one contact in the dofs (xi, yi, θi, xj, yj, θj): a normal spring along
/// `n` and a tangential spring on the contact points' relative slip, lever arms `li`, `lj`.
pub fn contact_matrix(n: [f64; 2], li: f64, lj: f64, kn: f64, kt: f64) -> [[f64; 6]; 6] {
    let t = [-n[1], n[0]];
    let bn = [-n[0], -n[1], 0.0, n[0], n[1], 0.0];
    let bt = [-t[0], -t[1], -li, t[0], t[1], -lj];
    let mut k = [[0.0; 6]; 6];
    for a in 0..6 {
        for b in 0..6 {
            k[a][b] = kn * bn[a] * bn[b] + kt * bt[a] * bt[b];
        }
    }
    k
}

/// The springs contact `k` (of `list`) has: a bond's at its present modulus (`extra` holds the
/// rate part's ratio; empty: static), or at the stiffest the rate part allows (`stiffest`); a
/// frictional contact's own springs.
fn springs_of(c: &Contact, class: &ContactClass, extra: Option<&Extra>, stiffest: bool) -> Springs {
    match c.bond {
        Bond::Intact if stiffest => class.stiffest_bond(),
        Bond::Intact => {
            let r = match extra {
                Some(x) if class.rate.enabled => x.modulus_ratio,
                _ => 1.0,
            };
            Springs { kn_n_per_m: class.bond.kn_n_per_m * r, kt_n_per_m: class.bond.kt_n_per_m * r }
        }
        Bond::Frictional if stiffest => class.stiffest_contact(),
        Bond::Frictional => class.contact.springs,
    }
}

/// The contacts that carry stiffness now (bonded, or frictional and touching), with their
/// normal and lever arms. Kinematic elements' dofs are excluded by the callers.
fn active<'a>(
    pos: &'a [[f64; 3]],
    list: &'a [Contact],
    extra: &'a [Extra],
    classes: &'a [ContactClass],
    stiffest: bool,
) -> impl Iterator<Item = (usize, usize, [[f64; 6]; 6])> + 'a {
    list.iter().enumerate().filter_map(move |(idx, c)| {
        let (i, j) = (c.i as usize, c.j as usize);
        let (dx, dy) = (pos[j][0] - pos[i][0], pos[j][1] - pos[i][1]);
        let d = (dx * dx + dy * dy).sqrt();
        if c.bond == Bond::Frictional && d >= c.rest_m {
            return None;
        }
        let k = &classes[c.class as usize];
        let s = springs_of(c, k, extra.get(idx), stiffest);
        Some((i, j, contact_matrix([dx / d, dy / d], d * k.lever_i, d * k.lever_j, s.kn_n_per_m, s.kt_n_per_m)))
    })
}

fn inv_sqrt_mass(el: &Elements, e: usize) -> [f64; 3] {
    el.free_inv_sqrt_mass(e)
}

/// Gershgorin bound on ω_max of the assembled mesh, rad/s, with every contact at the stiffest
/// its law allows and the rotational dofs scaled by the factor that minimises the bound
/// (golden-section search on log s). Returns (ω bound, s).
pub fn gershgorin(el: &Elements, pos: &[[f64; 3]], list: &[Contact], classes: &[ContactClass]) -> (f64, f64) {
    let n = el.len();
    // Per element: signed self block (sums of contacts) and per dof the sums of |off-diagonal|
    // entries split by the column's dof type (translation, rotation).
    let mut diag = vec![[[0.0f64; 3]; 3]; n];
    let mut off = vec![[[0.0f64; 2]; 3]; n];
    for (i, j, k) in active(pos, list, &[], classes, true) {
        let (si, sj) = (inv_sqrt_mass(el, i), inv_sqrt_mass(el, j));
        for a in 0..3 {
            for b in 0..3 {
                diag[i][a][b] += k[a][b] * si[a] * si[b];
                diag[j][a][b] += k[a + 3][b + 3] * sj[a] * sj[b];
                let kind = usize::from(b == 2);
                off[i][a][kind] += (k[a][b + 3] * si[a] * sj[b]).abs();
                off[j][a][kind] += (k[a + 3][b] * sj[a] * si[b]).abs();
            }
        }
    }
    let bound = |s: f64| -> f64 {
        let w = [1.0, 1.0, s];
        let mut worst = 0.0f64;
        for e in 0..n {
            for a in 0..3 {
                let mut row = 0.0;
                for b in 0..3 {
                    row += diag[e][a][b].abs() * w[b];
                }
                row += off[e][a][0] + off[e][a][1] * s;
                worst = worst.max(row / w[a]);
            }
        }
        worst
    };
    let (mut lo, mut hi) = ((1e-3f64).ln(), (1e3f64).ln());
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut a, mut b) = (hi - g * (hi - lo), lo + g * (hi - lo));
    let (mut fa, mut fb) = (bound(a.exp()), bound(b.exp()));
    for _ in 0..80 {
        if fa < fb {
            hi = b;
            b = a;
            fb = fa;
            a = hi - g * (hi - lo);
            fa = bound(a.exp());
        } else {
            lo = a;
            a = b;
            fa = fb;
            b = lo + g * (hi - lo);
            fb = bound(b.exp());
        }
    }
    let s = (0.5 * (lo + hi)).exp();
    // Any s gives a valid bound; evaluate at the one found (and never above s = 1's).
    let best = bound(s).min(bound(1.0));
    (best.sqrt(), s)
}

/// What the bound needs of an element kind.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KindInfo {
    /// Lattice of its body.
    pub arrangement: Arrangement,
    /// Radius, m.
    pub radius_m: f64,
    /// Mass, kg.
    pub mass_kg: f64,
}

/// Bound on the top frequency of everything the model can become, rad/s, and what sets it.
/// The largest of:
/// * each body's bonds at their stiffest (rate-enhanced moduli at the rate cap; full
///   compaction returns to the initial Kn): a regular lattice of one kind gets the infinite
///   lattice's exact top, a rigorous bound for any subset of it; other bodies the Gershgorin
///   bound of their assembled bonds;
/// * each body whose bonds can break, or that has none (loose disks): its fragments packed in
///   the densest network there is, a close-packed lattice of its elements joined by frictional
///   contacts in stick (Kt = Kn/3);
/// * each pair of kinds of different bodies (the projectile–target interface): the same
///   close-packed lattice of elements of the pair's reduced mass, 2/(1/m_a + 1/m_b), joined by
///   the interface's contact springs. This one is an estimate, not a proof (the interface is a
///   line, not a lattice); `tests/frequency_bound.rs` holds it against the measured top of a
///   projectile pressed into a block.
///
/// Not covered: elements brought closer than r_i + r_j by compaction can touch more neighbours
/// than a close packing has.
pub fn model_bound(
    el: &Elements,
    pos: &[[f64; 3]],
    list: &[Contact],
    classes: &[ContactClass],
    kinds: &[KindInfo],
    bodies: &[Body],
) -> (f64, String) {
    let nk = kinds.len();
    let class = |a: usize, b: usize| &classes[a * nk + b];
    let mut best = (0.0f64, String::new());
    let mut consider = |w: f64, how: String| {
        if w > best.0 {
            best = (w, how);
        }
    };
    let lattice_top = |arrangement: Arrangement, s: Springs, mass_kg: f64| {
        let coef = lattice_coefficient(arrangement, s.kt_n_per_m / s.kn_n_per_m, 0.5);
        (coef * (s.kn_n_per_m / mass_kg).sqrt(), coef)
    };
    let body_kinds: Vec<Vec<usize>> = bodies
        .iter()
        .map(|b| {
            let mut v: Vec<usize> = el.kind[b.elements.clone()].iter().map(|&k| k as usize).collect();
            v.sort_unstable();
            v.dedup();
            v
        })
        .collect();
    for (b, ks) in bodies.iter().zip(&body_kinds) {
        let bonds: Vec<Contact> = list.iter().copied().filter(|c| b.elements.contains(&(c.i as usize))).collect();
        if !bonds.is_empty() {
            // Regular: one lattice of identical elements and identical springs. Kinds that
            // differ only in strength (e.g. an unbreakable platen) are still one lattice.
            let k0 = ks[0];
            let same = |k: usize| {
                let (a, z) = (&kinds[k], &kinds[k0]);
                a.arrangement == z.arrangement && a.radius_m == z.radius_m && a.mass_kg == z.mass_kg
            };
            let springs = |a: usize, c: usize| class(a, c).stiffest_bond();
            let regular = kinds[k0].arrangement != Arrangement::Irregular
                && ks.iter().all(|&k| same(k))
                && ks.iter().all(|&a| ks.iter().all(|&c| springs(a, c) == springs(k0, k0)));
            if regular {
                let (w, coef) = lattice_top(kinds[k0].arrangement, springs(k0, k0), kinds[k0].mass_kg);
                consider(w, format!("infinite {:?} lattice top {coef:.4} √(Kn/m) of the bonds of body {}", kinds[k0].arrangement, b.name));
            } else {
                let (w, s) = gershgorin(el, pos, &bonds, classes);
                consider(w, format!("Gershgorin bound of the bonds of body {} (rotation scale {s:.3})", b.name));
            }
        }
        let breakable = ks.iter().any(|&a| ks.iter().any(|&c| class(a, c).strength.normal_force_n.is_finite()));
        if bonds.is_empty() || breakable {
            for &k in ks {
                let (w, coef) = lattice_top(Arrangement::ClosePacked, class(k, k).stiffest_contact(), kinds[k].mass_kg);
                consider(w, format!("close-packed fragments of body {} in stick, {coef:.4} √(Kn/m)", b.name));
            }
        }
    }
    for (p, kp) in body_kinds.iter().enumerate() {
        for (q, kq) in body_kinds.iter().enumerate().skip(p + 1) {
            for &a in kp {
                for &c in kq {
                    let m = 2.0 / (1.0 / kinds[a].mass_kg + 1.0 / kinds[c].mass_kg);
                    let (w, coef) = lattice_top(Arrangement::ClosePacked, class(a, c).stiffest_contact(), m);
                    consider(w, format!("interface of bodies {} and {} (estimate {coef:.4} √(Kn/m_reduced))", bodies[p].name, bodies[q].name));
                }
            }
        }
    }
    best
}

/// Neighbour offsets of a regular lattice of spacing 2R in lattice coordinates (c1, c2) and as
/// unit normals.
fn lattice_neighbours(arrangement: Arrangement) -> Vec<([f64; 2], [f64; 2])> {
    match arrangement {
        Arrangement::SimpleCubic => {
            vec![([1.0, 0.0], [1.0, 0.0]), ([-1.0, 0.0], [-1.0, 0.0]), ([0.0, 1.0], [0.0, 1.0]), ([0.0, -1.0], [0.0, -1.0])]
        }
        Arrangement::ClosePacked | Arrangement::Irregular => {
            // a1 = (2R, 0), a2 = (R, √3 R)
            let h = 3f64.sqrt() / 2.0;
            vec![
                ([1.0, 0.0], [1.0, 0.0]),
                ([0.0, 1.0], [0.5, h]),
                ([-1.0, 1.0], [-0.5, h]),
                ([-1.0, 0.0], [-1.0, 0.0]),
                ([0.0, -1.0], [-0.5, -h]),
                ([1.0, -1.0], [0.5, -h]),
            ]
        }
    }
}

fn bloch_top(nb: &[([f64; 2], [f64; 2])], kt_over_kn: f64, inertia_ratio: f64, p1: f64, p2: f64) -> f64 {
    // Units: R = 1, m = 1, Kn = 1, I = inertia_ratio.
    let s = [1.0, 1.0, 1.0 / inertia_ratio.sqrt()];
    let mut re = [[0.0; 3]; 3];
    let mut im = [[0.0; 3]; 3];
    for (c, n) in nb {
        let k = contact_matrix(*n, 1.0, 1.0, 1.0, kt_over_kn);
        let ph = c[0] * p1 + c[1] * p2;
        let (cs, sn) = (ph.cos(), ph.sin());
        for a in 0..3 {
            for b in 0..3 {
                re[a][b] += (k[a][b] + k[a][b + 3] * cs) * s[a] * s[b];
                im[a][b] += k[a][b + 3] * sn * s[a] * s[b];
            }
        }
    }
    // Hermitian H = re + i im as the real symmetric [[re, −im], [im, re]].
    let m = Matrix6::from_fn(|r, c| {
        let (a, b) = (r % 3, c % 3);
        match (r < 3, c < 3) {
            (true, true) | (false, false) => re[a][b],
            (true, false) => -im[a][b],
            (false, true) => im[a][b],
        }
    });
    SymmetricEigen::new(m).eigenvalues.max()
}

/// Top of the infinite regular lattice's dispersion relation in units of √(Kn/m): ω_max = c √(Kn/m)
/// for identical elements of inertia `inertia_ratio`·m R² joined by Kn, Kt = `kt_over_kn`·Kn.
/// A grid scan of the Brillouin zone, refined by pattern search around the best points.
pub fn lattice_coefficient(arrangement: Arrangement, kt_over_kn: f64, inertia_ratio: f64) -> f64 {
    let nb = lattice_neighbours(arrangement);
    let f = |p1: f64, p2: f64| bloch_top(&nb, kt_over_kn, inertia_ratio, p1, p2);
    let n = 48;
    let step = 2.0 * std::f64::consts::PI / n as f64;
    let mut pts: Vec<(f64, f64, f64)> = Vec::with_capacity(n * n);
    for a in 0..n {
        for b in 0..n {
            let (p1, p2) = (a as f64 * step, b as f64 * step);
            pts.push((f(p1, p2), p1, p2));
        }
    }
    pts.sort_by(|x, y| y.0.total_cmp(&x.0));
    let mut best = pts[0].0;
    for &(v0, p1, p2) in pts.iter().take(8) {
        let (mut v, mut q1, mut q2, mut h) = (v0, p1, p2, step);
        while h > 1e-9 {
            let mut moved = false;
            for (d1, d2) in [(h, 0.0), (-h, 0.0), (0.0, h), (0.0, -h), (h, h), (-h, -h), (h, -h), (-h, h)] {
                let w = f(q1 + d1, q2 + d2);
                if w > v {
                    (v, q1, q2, moved) = (w, q1 + d1, q2 + d2, true);
                }
            }
            if !moved {
                h *= 0.5;
            }
        }
        best = best.max(v);
    }
    best.sqrt()
}

/// Assemble the mass-normalised stiffness of the present configuration (every contact at its
/// present stiffness) as a dense matrix (small meshes); prescribed dofs get zero rows and
/// columns.
pub fn dense_operator(el: &Elements, pos: &[[f64; 3]], contacts: &Contacts, classes: &[ContactClass]) -> DMatrix<f64> {
    let mut a = DMatrix::zeros(3 * el.len(), 3 * el.len());
    for (i, j, k) in active(pos, &contacts.list, &contacts.extra, classes, false) {
        let ends = [(i, 0), (j, 3)];
        for &(p, op) in &ends {
            for &(q, oq) in &ends {
                let (sp, sq) = (inv_sqrt_mass(el, p), inv_sqrt_mass(el, q));
                for u in 0..3 {
                    for v in 0..3 {
                        a[(3 * p + u, 3 * q + v)] += k[op + u][oq + v] * sp[u] * sq[v];
                    }
                }
            }
        }
    }
    a
}

/// Exact top frequency of the assembled mesh, rad/s, by a dense symmetric eigen-solve.
pub fn dense_top(el: &Elements, pos: &[[f64; 3]], contacts: &Contacts, classes: &[ContactClass]) -> f64 {
    let a = dense_operator(el, pos, contacts, classes);
    SymmetricEigen::new(a).eigenvalues.max().max(0.0).sqrt()
}

/// Top frequency of the assembled mesh, rad/s, by `iterations` Lanczos steps with full
/// re-orthogonalisation (matrix-free). A Ritz value: never above the true ω_max.
pub fn lanczos_top(el: &Elements, pos: &[[f64; 3]], contacts: &Contacts, classes: &[ContactClass], iterations: usize) -> f64 {
    let n = 3 * el.len();
    let scale: Vec<f64> = (0..el.len()).flat_map(|e| inv_sqrt_mass(el, e)).collect();
    let ops: Vec<(usize, usize, [[f64; 6]; 6])> = active(pos, &contacts.list, &contacts.extra, classes, false).collect();
    let apply = |x: &[f64], y: &mut [f64]| {
        y.iter_mut().for_each(|v| *v = 0.0);
        for (i, j, k) in &ops {
            let idx = [3 * i, 3 * i + 1, 3 * i + 2, 3 * j, 3 * j + 1, 3 * j + 2];
            for a in 0..6 {
                let mut s = 0.0;
                for b in 0..6 {
                    s += k[a][b] * scale[idx[b]] * x[idx[b]];
                }
                y[idx[a]] += s * scale[idx[a]];
            }
        }
    };
    let m = iterations.min(n).max(1);
    let mut basis: Vec<Vec<f64>> = Vec::with_capacity(m);
    // Deterministic start vector with every dof excited.
    let mut q: Vec<f64> = (0..n).map(|k| if scale[k] > 0.0 { 1.0 + 0.5 * ((k * 7919) % 13) as f64 } else { 0.0 }).collect();
    let norm = q.iter().map(|v| v * v).sum::<f64>().sqrt();
    if norm == 0.0 {
        return 0.0;
    }
    q.iter_mut().for_each(|v| *v /= norm);
    let (mut alpha, mut beta) = (Vec::new(), Vec::new());
    let mut w = vec![0.0; n];
    for it in 0..m {
        apply(&q, &mut w);
        let a: f64 = w.iter().zip(&q).map(|(x, y)| x * y).sum();
        alpha.push(a);
        basis.push(q.clone());
        for b in &basis {
            let proj: f64 = w.iter().zip(b).map(|(x, y)| x * y).sum();
            w.iter_mut().zip(b).for_each(|(x, y)| *x -= proj * y);
        }
        let bnorm = w.iter().map(|v| v * v).sum::<f64>().sqrt();
        if it + 1 == m || bnorm < 1e-12 * a.abs().max(1e-300) {
            break;
        }
        beta.push(bnorm);
        q = w.iter().map(|v| v / bnorm).collect();
    }
    let k = alpha.len();
    let t = DMatrix::from_fn(k, k, |r, c| {
        if r == c {
            alpha[r]
        } else if r + 1 == c {
            beta[r]
        } else if c + 1 == r {
            beta[c]
        } else {
            0.0
        }
    });
    SymmetricEigen::new(t).eigenvalues.max().max(0.0).sqrt()
}

/// Frequencies, rad/s in units of √(Kn/m), of the free 7-element close-packed cell (centre,
/// ring of six; six spoke and six ring bonds; disks of inertia `inertia_ratio`·mR²), the cell
/// the seed analyses for eq 2.3. Sorted ascending.
pub fn seven_cell_frequencies(kt_over_kn: f64, inertia_ratio: f64) -> Vec<f64> {
    let mut pos = vec![[0.0, 0.0]];
    for k in 0..6 {
        let a = k as f64 * std::f64::consts::PI / 3.0;
        pos.push([2.0 * a.cos(), 2.0 * a.sin()]);
    }
    let mut bonds: Vec<(usize, usize)> = (1..7).map(|k| (0, k)).collect();
    bonds.extend((1..7).map(|k| (k, 1 + k % 6)));
    let s = [1.0, 1.0, 1.0 / inertia_ratio.sqrt()];
    let mut a = DMatrix::<f64>::zeros(21, 21);
    for (i, j) in bonds {
        let (dx, dy) = (pos[j][0] - pos[i][0], pos[j][1] - pos[i][1]);
        let d = (dx * dx + dy * dy).sqrt();
        let k = contact_matrix([dx / d, dy / d], 1.0, 1.0, 1.0, kt_over_kn);
        for (p, op) in [(i, 0), (j, 3)] {
            for (q, oq) in [(i, 0), (j, 3)] {
                for u in 0..3 {
                    for v in 0..3 {
                        a[(3 * p + u, 3 * q + v)] += k[op + u][oq + v] * s[u] * s[v];
                    }
                }
            }
        }
    }
    let mut w: Vec<f64> = SymmetricEigen::new(a).eigenvalues.iter().map(|l| l.max(0.0).sqrt()).collect();
    w.sort_by(f64::total_cmp);
    w
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The single-mode recurrence of the integrator, iterated: does it stay bounded?
    fn recurrence_stable(omega_dt: f64, xi_stiff: f64, alpha_dt: f64) -> bool {
        let a = 0.5 * alpha_dt;
        let c = 2.0 * xi_stiff * omega_dt;
        let (mut u0, mut u1) = (0.0f64, 1.0f64);
        for _ in 0..200_000 {
            let u2 = ((2.0 - omega_dt * omega_dt - c) * u1 - (1.0 - a - c) * u0) / (1.0 + a);
            (u0, u1) = (u1, u2);
            if u1.abs() > 1e6 {
                return false;
            }
        }
        true
    }

    #[test]
    fn damped_step_bound_is_the_recurrence_limit() {
        for xi in [0.0, 0.05, 0.3, 1.0] {
            for alpha_dt in [0.0, 0.01] {
                let limit = critical_step_s(1.0, xi);
                assert!(recurrence_stable(limit * 0.999, xi, alpha_dt), "ξ={xi}");
                assert!(!recurrence_stable(limit * 1.001, xi, alpha_dt), "ξ={xi}");
            }
        }
        // The seed's printed √(1 − ξ²) form is stricter than needed.
        let xi: f64 = 0.3;
        assert!(2.0 * ((1.0 - xi * xi).sqrt() - xi) < critical_step_s(1.0, xi));
    }

    #[test]
    fn lattice_coefficients_match_closed_forms() {
        // Hexagonal, no shear: √6 at the zone-boundary M point; square, Kt = Kn: 4 (rotation-
        // translation mode); hexagonal, Kt = Kn: the uniform-rotation mode √24.
        assert!((lattice_coefficient(Arrangement::ClosePacked, 0.0, 0.5) - 6f64.sqrt()).abs() < 1e-9);
        assert!((lattice_coefficient(Arrangement::SimpleCubic, 1.0, 0.5) - 4.0).abs() < 1e-9);
        assert!((lattice_coefficient(Arrangement::ClosePacked, 1.0, 0.5) - 24f64.sqrt()).abs() < 1e-9);
    }
}
