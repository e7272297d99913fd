//! The stability limit of the step: a bound on the top frequency over every contact that is or
//! can be formed, by Gershgorin's theorem on the mass-normalised stiffness M^-½ K M^-½ of the
//! linearised contacts (each a sum of springs k a aᵀ on generalised displacements a·q).
//!
//! Per contact, the springs are the normal one (a = (−n, n) on the centres), two shear ones
//! (a = (−t, t) on the centres and the lever arms l_i, l_j on the spins), two rolling and one
//! twisting (k/2 on each spin, since the angle is half the relative spin). A row's absolute sum
//! is bounded with |a_x| + |a_y| + |a_z| ≤ √3 |a|. Central differences are stable for
//! Δt < 2/ω_max.

use super::law::Class;

/// One contact as the bound sees it: the two spheres' masses (kg), inertias (kg·m²), lever
/// arms (m), and its class.
#[derive(Debug, Clone, Copy)]
pub struct Link<'a> {
    /// Spheres.
    pub ends: [usize; 2],
    /// Lever arms to the contact point, m.
    pub lever_m: [f64; 2],
    /// Its class.
    pub class: &'a Class,
}

/// The bound on ω_max², rad²/s², of spheres with `radius_m`, `mass_kg` and `inertia_kg_m2`
/// (held spheres excluded: their rows are not free) joined by `links`.
pub fn omega_max_sq(radius_m: &[f64], mass_kg: &[f64], inertia_kg_m2: &[f64], held: &[bool], links: &[Link<'_>]) -> f64 {
    let n = mass_kg.len();
    let (mut trans, mut rot) = (vec![0.0f64; n], vec![0.0f64; n]);
    let r3 = 3f64.sqrt();
    for l in links {
        let [i, j] = l.ends;
        let k = l.class.at(0.5 * (radius_m[i] + radius_m[j]));
        let (kn, ks, kr, kt) = (k.bond_kn.max(k.kn), k.bond_ks.max(k.ks), k.kr, k.kt);
        let im = |e: usize| 1.0 / mass_kg[e].sqrt();
        let ii = |e: usize| 1.0 / inertia_kg_m2[e].sqrt();
        // Σ_q |a_q| / √M_q of each spring type.
        let s_normal = r3 * (im(i) + im(j));
        let s_shear = r3 * (im(i) + im(j) + l.lever_m[0] * ii(i) + l.lever_m[1] * ii(j));
        let s_spin = r3 * (ii(i) + ii(j));
        for (side, e) in [(0, i), (1, j)] {
            trans[e] += im(e) * (kn * s_normal + 2.0 * ks * s_shear);
            rot[e] += ii(e) * (2.0 * ks * l.lever_m[side] * s_shear + (kr + 0.5 * kt) * s_spin);
        }
    }
    (0..n).filter(|&e| !held[e]).map(|e| trans[e].max(rot[e])).fold(0.0, f64::max)
}
