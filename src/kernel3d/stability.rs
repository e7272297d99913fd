//! The stability limit of the step: a bound on the top frequency over every contact that is or
//! can be formed. Element by element (Irons): each sphere's mass and inertia are shared among
//! its z contacts, and the top eigenvalue of the whole mass-normalised stiffness is at most the
//! largest of the contacts' own — xᵀKx = Σ_c x_cᵀK_c x_c ≤ max_c λ_c Σ_c x_cᵀM_c x_c = max_c λ_c
//! xᵀMx. Each contact's λ_c is bounded by Gershgorin on its 12 × 12 matrix (the rows of a held
//! sphere left out: its motion is given). A contact's stiffness is its linearisation: the
//! contact points' relative displacement u = x_j − x_i + l_i n×θ_i + l_j n×θ_j under
//! k_n n nᵀ + k_s (I − n nᵀ), and the relative turn θ_i − θ_j under (k_r/2)(I − n nᵀ) +
//! (k_t/2) n nᵀ (the moments act on both spheres with half the relative turn). Central
//! differences are stable for Δt < 2/ω_max. On a chain of equal springs the bound is exact.

use super::law::Class;
use super::vec3::V3;

/// One contact as the bound sees it.
#[derive(Debug, Clone, Copy)]
pub struct Link<'a> {
    /// Spheres.
    pub ends: [usize; 2],
    /// Lever arms to the contact point, m.
    pub lever_m: [f64; 2],
    /// Unit normal from the first to the second.
    pub normal: V3,
    /// Its class.
    pub class: &'a Class,
}

/// The bound on ω_max², rad²/s², of spheres with `radius_m`, `mass_kg` and `inertia_kg_m2`
/// (held spheres' rows left out) joined by `links`.
pub fn omega_max_sq(radius_m: &[f64], mass_kg: &[f64], inertia_kg_m2: &[f64], held: &[bool], links: &[Link<'_>]) -> f64 {
    let mut z = vec![0u32; mass_kg.len()];
    for l in links {
        z[l.ends[0]] += 1;
        // A sphere's contact with its own image (`mirror`) is one of its contacts.
        if l.ends[1] != l.ends[0] {
            z[l.ends[1]] += 1;
        }
    }
    links.iter().map(|l| contact_bound(l, radius_m, mass_kg, inertia_kg_m2, held, &z)).fold(0.0, f64::max)
}

fn contact_bound(l: &Link<'_>, radius_m: &[f64], mass_kg: &[f64], inertia_kg_m2: &[f64], held: &[bool], z: &[u32]) -> f64 {
    let [i, j] = l.ends;
    let k = l.class.at(0.5 * (radius_m[i] + radius_m[j]));
    // A bond stiffens with the rate part up to its largest modulus ratio (at the rate cap);
    // compaction's yield line is softer and full compaction returns to k_n.
    let r = l.class.rate.max_modulus_ratio();
    let (kn, ks, kr, kt) = ((r * k.bond_kn).max(k.kn), (r * k.bond_ks).max(k.ks), k.kr, k.kt);
    let n = l.normal;
    let nn = |a: usize, b: usize| n[a] * n[b];
    let eye = |a: usize, b: usize| if a == b { 1.0 } else { 0.0 };
    // [n]×: n × v.
    let cross = [[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]];
    // u = B q (3 × 12) over q = (x_i, θ_i, x_j, θ_j); the turn r = C q.
    let mut b = [[0.0; 12]; 3];
    let mut c = [[0.0; 12]; 3];
    for a in 0..3 {
        for d in 0..3 {
            b[a][d] = -eye(a, d);
            b[a][3 + d] = l.lever_m[0] * cross[a][d];
            b[a][6 + d] = eye(a, d);
            b[a][9 + d] = l.lever_m[1] * cross[a][d];
            c[a][3 + d] = eye(a, d);
            c[a][9 + d] = -eye(a, d);
        }
    }
    let s: [[f64; 3]; 3] = std::array::from_fn(|a| std::array::from_fn(|d| kn * nn(a, d) + ks * (eye(a, d) - nn(a, d))));
    let t: [[f64; 3]; 3] = std::array::from_fn(|a| std::array::from_fn(|d| 0.5 * kr * (eye(a, d) - nn(a, d)) + 0.5 * kt * nn(a, d)));
    // Mass shares: each sphere's over its contacts; a held sphere's rows are not free.
    let scale: [f64; 12] = std::array::from_fn(|q| {
        let (e, rot) = (l.ends[q / 6], (q % 6) >= 3);
        if held[e] {
            0.0
        } else {
            let share = f64::from(z[e].max(1));
            (share / if rot { inertia_kg_m2[e] } else { mass_kg[e] }).sqrt()
        }
    });
    let mut worst = 0.0f64;
    for p in 0..12 {
        if scale[p] == 0.0 {
            continue;
        }
        let mut row = 0.0;
        for q in 0..12 {
            let mut kpq = 0.0;
            for a in 0..3 {
                for d in 0..3 {
                    kpq += b[a][p] * s[a][d] * b[d][q] + c[a][p] * t[a][d] * c[d][q];
                }
            }
            row += (scale[p] * kpq * scale[q]).abs();
        }
        worst = worst.max(row);
    }
    worst
}
