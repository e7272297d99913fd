//! One two-node beam element, degrees of freedom [w₁, ψ₁, w₂, ψ₂] (deflection, m; section
//! rotation, rad), for the cantilever reference.
//!
//! Timoshenko: the interdependent-interpolation element (IIE) of Friedman & Kosmatka (1993,
//! *Comput. Struct.* 47(3)) — cubic w and quadratic ψ tied by the homogeneous equations, so the
//! stiffness is the exact static one (no shear locking, nodally exact under end loads) and the
//! static-limit tests hold to round-off at any element count. Φ = 12EI/(κGA l²). Its consistent
//! mass has a translational part (ρA) and a rotary part (ρI); the frequency error falls as l².
//! Euler–Bernoulli: the same element at Φ = 0 without rotary inertia, which is exactly the Hermite
//! cubic with its consistent mass (Przemieniecki 1968); the frequency error falls as l⁴.

use super::beam::{Beam, Theory};

/// A 4×4 element matrix.
pub(crate) type Mat4 = [[f64; 4]; 4];

/// Stiffness (N/m, N, N·m) and consistent mass (kg, kg·m, kg·m²) of one element.
pub(crate) struct Element {
    pub stiffness: Mat4,
    pub mass: Mat4,
}

/// The element of length `length_m` cut from `beam` under `theory`.
pub(crate) fn element(beam: &Beam, theory: Theory, length_m: f64) -> Element {
    let l = length_m;
    let ei = beam.bending_rigidity_n_m2();
    let (p, rho_i) = match theory {
        Theory::EulerBernoulli => (0.0, 0.0),
        Theory::Timoshenko => {
            (12.0 * ei / (beam.shear_rigidity_n() * l * l), beam.rotary_inertia_kg_m())
        }
    };

    let k = ei / ((1.0 + p) * l.powi(3));
    let (a, b) = ((4.0 + p) * l * l, (2.0 - p) * l * l);
    let s = 6.0 * l;
    let stiffness = [
        [12.0 * k, s * k, -12.0 * k, s * k],
        [s * k, a * k, -s * k, b * k],
        [-12.0 * k, -s * k, 12.0 * k, -s * k],
        [s * k, b * k, -s * k, a * k],
    ];

    let t = beam.mass_per_length_kg_per_m() * l / (210.0 * (1.0 + p).powi(2));
    let t11 = (70.0 * p * p + 147.0 * p + 78.0) * t;
    let t12 = (35.0 * p * p + 77.0 * p + 44.0) * l / 4.0 * t;
    let t13 = (35.0 * p * p + 63.0 * p + 27.0) * t;
    let t14 = -(35.0 * p * p + 63.0 * p + 26.0) * l / 4.0 * t;
    let t22 = (7.0 * p * p + 14.0 * p + 8.0) * l * l / 4.0 * t;
    let t24 = -(7.0 * p * p + 14.0 * p + 6.0) * l * l / 4.0 * t;

    let r = rho_i / (30.0 * (1.0 + p).powi(2) * l);
    let r11 = 36.0 * r;
    let r12 = -(15.0 * p - 3.0) * l * r;
    let r22 = (10.0 * p * p + 5.0 * p + 4.0) * l * l * r;
    let r24 = (5.0 * p * p - 5.0 * p - 1.0) * l * l * r;

    let mass = [
        [t11 + r11, t12 + r12, t13 - r11, t14 + r12],
        [t12 + r12, t22 + r22, -t14 - r12, t24 + r24],
        [t13 - r11, -t14 - r12, t11 + r11, -t12 - r12],
        [t14 + r12, t24 + r24, -t12 - r12, t22 + r22],
    ];
    Element { stiffness, mass }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn beam() -> Beam {
        Beam::rectangular(10.0, 0.9, 1.0, 1.2e9, 0.3, 2000.0)
    }

    fn times(m: &Mat4, v: [f64; 4]) -> [f64; 4] {
        m.map(|row| row.iter().zip(v).map(|(a, b)| a * b).sum())
    }

    fn assert_close(a: &Mat4, b: &Mat4, tol: f64) {
        let scale = a.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
        for i in 0..4 {
            for j in 0..4 {
                assert!(
                    (a[i][j] - b[i][j]).abs() <= tol * scale,
                    "[{i}][{j}]: {} vs {}",
                    a[i][j],
                    b[i][j]
                );
            }
        }
    }

    #[test]
    fn rigid_body_motions_cost_no_strain_energy() {
        for theory in [Theory::EulerBernoulli, Theory::Timoshenko] {
            let e = element(&beam(), theory, 0.7);
            for v in [[1.0, 0.0, 1.0, 0.0], [0.0, 1.0, 0.7, 1.0]] {
                let f = times(&e.stiffness, v);
                assert!(f.iter().all(|x| x.abs() < 1e-6 * e.stiffness[0][0]), "{theory:?}: {f:?}");
            }
        }
    }

    #[test]
    fn euler_bernoulli_is_the_hermite_cubic() {
        let (b, l) = (beam(), 0.7);
        let e = element(&b, Theory::EulerBernoulli, l);
        let k = b.bending_rigidity_n_m2() / l.powi(3);
        let hermite_k = [
            [12.0, 6.0 * l, -12.0, 6.0 * l],
            [6.0 * l, 4.0 * l * l, -6.0 * l, 2.0 * l * l],
            [-12.0, -6.0 * l, 12.0, -6.0 * l],
            [6.0 * l, 2.0 * l * l, -6.0 * l, 4.0 * l * l],
        ]
        .map(|r| r.map(|v| v * k));
        let m = b.mass_per_length_kg_per_m() * l / 420.0;
        let hermite_m = [
            [156.0, 22.0 * l, 54.0, -13.0 * l],
            [22.0 * l, 4.0 * l * l, 13.0 * l, -3.0 * l * l],
            [54.0, 13.0 * l, 156.0, -22.0 * l],
            [-13.0 * l, -3.0 * l * l, -22.0 * l, 4.0 * l * l],
        ]
        .map(|r| r.map(|v| v * m));
        assert_close(&e.stiffness, &hermite_k, 1e-14);
        assert_close(&e.mass, &hermite_m, 1e-14);
    }

    /// The IIE shape functions (Friedman & Kosmatka 1993), ξ = x/l, μ = 1/(1+Φ).
    fn shapes(xi: f64, l: f64, p: f64) -> ([f64; 4], [f64; 4]) {
        let mu = 1.0 / (1.0 + p);
        let (x2, x3) = (xi * xi, xi * xi * xi);
        let w = [
            2.0 * x3 - 3.0 * x2 - p * xi + 1.0 + p,
            l * (x3 - (2.0 + p / 2.0) * x2 + (1.0 + p / 2.0) * xi),
            -2.0 * x3 + 3.0 * x2 + p * xi,
            l * (x3 - (1.0 - p / 2.0) * x2 - p / 2.0 * xi),
        ];
        let psi = [
            6.0 / l * (x2 - xi),
            3.0 * x2 - (4.0 + p) * xi + 1.0 + p,
            -6.0 / l * (x2 - xi),
            3.0 * x2 - (2.0 - p) * xi,
        ];
        (w.map(|v| v * mu), psi.map(|v| v * mu))
    }

    #[test]
    fn timoshenko_mass_is_the_integral_of_its_shape_functions() {
        let (b, l) = (beam(), 0.3); // Φ ≈ 24: shear-dominated
        let p = 12.0 * b.bending_rigidity_n_m2() / (b.shear_rigidity_n() * l * l);
        let gauss = [
            (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
            (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
            (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
            (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
        ];
        let mut m = [[0.0; 4]; 4];
        for (g, wt) in gauss {
            let (nw, npsi) = shapes((g + 1.0) / 2.0, l, p);
            for i in 0..4 {
                for j in 0..4 {
                    m[i][j] += wt * l / 2.0
                        * (b.mass_per_length_kg_per_m() * nw[i] * nw[j]
                            + b.rotary_inertia_kg_m() * npsi[i] * npsi[j]);
                }
            }
        }
        assert_close(&element(&b, Theory::Timoshenko, l).mass, &m, 1e-13);
    }

    #[test]
    fn one_timoshenko_element_gives_the_exact_static_tip_deflection() {
        let b = beam();
        let e = element(&b, Theory::Timoshenko, b.length_m);
        // Clamped node 1: solve the 2×2 tip block for a unit tip force.
        let [[k11, k12], [k21, k22]] =
            [[e.stiffness[2][2], e.stiffness[2][3]], [e.stiffness[3][2], e.stiffness[3][3]]];
        let w = k22 / (k11 * k22 - k12 * k21);
        let exact = b.static_tip_deflection_m(Theory::Timoshenko, 1.0);
        assert!((w / exact - 1.0).abs() < 1e-13, "{w} vs {exact}");
    }
}
