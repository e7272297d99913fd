//! Observed order, Richardson extrapolate and Grid Convergence Index from three meshes refined by
//! a constant ratio α (seed 000 eq 4.1; SPEC §5; Roache 1998, *Verification and Validation in
//! Computational Science and Engineering*, ch. 5).
//!
//! Eq 4.1 reads an order off the three solutions only if they sit in the asymptotic range, where
//! the error shrinks by the same factor at each refinement. The ratio R = (φ2−φ3)/(φ1−φ2) tells
//! whether they do: 0 < R < 1 is monotone convergence, R < 0 oscillation, R ≥ 1 no convergence.
//! Outside 0 < R < 1 the formulas still produce numbers (the seed's simple-cubic p = 4.57 is one
//! such), so [`richardson`] refuses with a [`NotConvergent`] instead of returning one.

use std::fmt;

/// Roache's safety factor for a three-mesh study, where the order is observed rather than assumed
/// (Roache 1998 recommends 3 when only two meshes are available).
pub const GCI_SAFETY_FACTOR: f64 = 1.25;

/// What three monotonically converging solutions say about the limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Convergence {
    /// Observed order p (dimensionless), eq 4.1.
    pub order: f64,
    /// Richardson extrapolate φ3 + (φ3−φ2)/(α^p − 1), in the unit of φ.
    pub extrapolate: f64,
    /// Grid Convergence Index of the finest solution, relative to |φ3| (a fraction, not per
    /// cent): 1.25 |(φ3−φ2)/φ3| / (α^p − 1). Infinite when φ3 = 0.
    pub gci_fine: f64,
    /// R = (φ2−φ3)/(φ1−φ2) (dimensionless), in (0, 1) here; α^p = 1/R.
    pub ratio: f64,
}

/// Why three solutions give no order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NotConvergent {
    /// R < 0: the differences change sign, the solutions oscillate about their limit.
    Oscillatory {
        /// R = (φ2−φ3)/(φ1−φ2).
        ratio: f64,
    },
    /// R ≥ 1: the difference does not shrink with refinement (R = 1 would give p = 0).
    Divergent {
        /// R = (φ2−φ3)/(φ1−φ2).
        ratio: f64,
    },
    /// φ1 = φ2 or φ2 = φ3 exactly: a vanishing difference gives R = 0 or ∞, i.e. no finite order.
    Indeterminate {
        /// The three solutions, coarse to fine.
        phi: [f64; 3],
    },
    /// α ≤ 1 or a non-finite input: the study is not a refinement sequence.
    InvalidInput {
        /// The refinement ratio given.
        alpha: f64,
        /// The three solutions given, coarse to fine.
        phi: [f64; 3],
    },
}

impl fmt::Display for NotConvergent {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NotConvergent::Oscillatory { ratio } => {
                write!(f, "oscillatory convergence (R = {ratio:.4} < 0): no observed order")
            }
            NotConvergent::Divergent { ratio } => {
                write!(f, "no convergence (R = {ratio:.4} ≥ 1): the error does not shrink")
            }
            NotConvergent::Indeterminate { phi } => write!(
                f,
                "two consecutive solutions are equal ({:e}, {:e}, {:e}): no observed order",
                phi[0], phi[1], phi[2]
            ),
            NotConvergent::InvalidInput { alpha, phi } => write!(
                f,
                "not a refinement study: α = {alpha} (must be > 1), φ = {:e}, {:e}, {:e} (must be finite)",
                phi[0], phi[1], phi[2]
            ),
        }
    }
}

impl std::error::Error for NotConvergent {}

/// Observed order, extrapolate and GCI from `phi` = [coarse, medium, fine], each mesh's element
/// size 1/`alpha` of the previous one.
///
/// Computed through R, which is exact where the printed formulas round: α^p − 1 = (1 − R)/R.
pub fn richardson(phi: [f64; 3], alpha: f64) -> Result<Convergence, NotConvergent> {
    if !(alpha > 1.0 && alpha.is_finite()) || phi.iter().any(|v| !v.is_finite()) {
        return Err(NotConvergent::InvalidInput { alpha, phi });
    }
    let [phi1, phi2, phi3] = phi;
    let (d12, d23) = (phi1 - phi2, phi2 - phi3);
    if d12 == 0.0 || d23 == 0.0 {
        return Err(NotConvergent::Indeterminate { phi });
    }
    let ratio = d23 / d12;
    if ratio < 0.0 {
        return Err(NotConvergent::Oscillatory { ratio });
    }
    if ratio >= 1.0 {
        return Err(NotConvergent::Divergent { ratio });
    }
    let order = -ratio.ln() / alpha.ln();
    let gain = (1.0 - ratio) / ratio; // α^p − 1
    Ok(Convergence {
        order,
        extrapolate: phi3 - d23 / gain,
        gci_fine: GCI_SAFETY_FACTOR * (d23 / phi3).abs() / gain,
        ratio,
    })
}

/// [`richardson`] for three meshes whose refinement ratios differ (Celik et al. 2008, "Procedure
/// for estimation and reporting of uncertainty due to discretization in CFD applications", J.
/// Fluids Eng. 130, 078001, eqs 3–6): `h` are the element sizes, coarse to fine. The order solves
/// p = |ln|ε32/ε21| + q(p)| / ln r21 with q(p) = ln((r21^p − s)/(r32^p − s)), s = sign(ε32/ε21),
/// by fixed-point iteration (ε, r and the mesh numbering as in the paper: 1 is the finest). The
/// same refusals as [`richardson`]: Celik's absolute values would give an order to oscillating
/// or diverging solutions too, which is a number where there is none.
pub fn celik(phi: [f64; 3], h: [f64; 3]) -> Result<Convergence, NotConvergent> {
    let [phi3, phi2, phi1] = phi; // coarse, medium, fine in the paper's numbering
    let [h3, h2, h1] = h;
    let (r21, r32) = (h2 / h1, h3 / h2);
    if !(r21 > 1.0 && r32 > 1.0 && r21.is_finite() && r32.is_finite()) || phi.iter().any(|v| !v.is_finite()) {
        return Err(NotConvergent::InvalidInput { alpha: r21.min(r32), phi });
    }
    let (e32, e21) = (phi3 - phi2, phi2 - phi1);
    if e32 == 0.0 || e21 == 0.0 {
        return Err(NotConvergent::Indeterminate { phi });
    }
    let ratio = e21 / e32;
    if ratio < 0.0 {
        return Err(NotConvergent::Oscillatory { ratio });
    }
    if ratio >= 1.0 {
        return Err(NotConvergent::Divergent { ratio });
    }
    let s = 1.0f64; // monotone from here on
    let mut p = (e32 / e21).abs().ln() / r21.ln();
    for _ in 0..200 {
        let q = ((r21.powf(p) - s) / (r32.powf(p) - s)).ln();
        let next = ((e32 / e21).abs().ln() + q).abs() / r21.ln();
        if (next - p).abs() <= 1e-14 * p.abs().max(1.0) {
            p = next;
            break;
        }
        p = next;
    }
    if !(p.is_finite() && p > 0.0) {
        return Err(NotConvergent::Divergent { ratio });
    }
    let gain = r21.powf(p) - 1.0;
    Ok(Convergence { order: p, extrapolate: (r21.powf(p) * phi1 - phi2) / gain, gci_fine: GCI_SAFETY_FACTOR * ((phi1 - phi2) / phi1).abs() / gain, ratio })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn celik_recovers_order_and_limit_with_unequal_ratios() {
        for &p in &[0.8, 1.0, 2.0, 3.0] {
            let h = [1.0, 0.6, 0.25];
            let phi = h.map(|h: f64| 3.0 + 0.4 * h.powf(p));
            let c = celik(phi, h).unwrap();
            assert!((c.order - p).abs() < 1e-9, "p {p}: {c:?}");
            assert!((c.extrapolate - 3.0).abs() < 1e-9, "p {p}: {c:?}");
        }
        // Equal ratios: the same answer as eq 4.1.
        let phi = [2.1, 2.025, 2.00625];
        let (a, b) = (celik(phi, [1.0, 0.5, 0.25]).unwrap(), richardson(phi, 2.0).unwrap());
        assert!((a.order - b.order).abs() < 1e-12 && (a.extrapolate - b.extrapolate).abs() < 1e-12 && (a.gci_fine - b.gci_fine).abs() < 1e-12);
        assert!(matches!(celik([1.0, 1.2, 1.1], [1.0, 0.5, 0.2]), Err(NotConvergent::Oscillatory { .. })));
    }

    /// φ(h) = φ0 + C h^p on h = h0, h0/α, h0/α².
    fn synthetic(phi0: f64, c: f64, p: f64, h0: f64, alpha: f64) -> [f64; 3] {
        [0, 1, 2].map(|i| phi0 + c * (h0 / alpha.powi(i)).powf(p))
    }

    #[test]
    fn recovers_order_and_limit_of_a_power_law() {
        for &p in &[0.5, 1.0, 1.52, 2.0, 3.0, 4.57] {
            for &alpha in &[std::f64::consts::SQRT_2, 2.0, 3.0] {
                for &c in &[0.3, -0.7] {
                    let phi = synthetic(0.4754, c, p, 0.5, alpha);
                    let r = richardson(phi, alpha).unwrap();
                    assert!((r.order - p).abs() < 1e-12, "p {p} α {alpha}: {}", r.order);
                    assert!((r.extrapolate - 0.4754).abs() < 1e-12, "p {p} α {alpha}: {r:?}");
                    assert!((r.ratio - alpha.powf(-p)).abs() < 1e-12);
                }
            }
        }
    }

    #[test]
    fn gci_is_the_safety_factor_times_the_extrapolated_relative_error() {
        let phi = synthetic(2.0, 0.1, 2.0, 1.0, 2.0); // 2.1, 2.025, 2.00625
        let r = richardson(phi, 2.0).unwrap();
        // α^p − 1 = 3: GCI = 1.25 × (0.01875 / 2.00625) / 3.
        let by_hand = 1.25 * (0.01875 / 2.00625) / 3.0;
        assert!((r.gci_fine - by_hand).abs() < 1e-15, "{r:?}");
        let from_extrapolate = 1.25 * ((r.extrapolate - phi[2]) / phi[2]).abs();
        assert!((r.gci_fine - from_extrapolate).abs() < 1e-15);
    }

    #[test]
    fn a_band_of_the_gci_contains_the_limit() {
        let phi = synthetic(1.0, 0.5, 1.5, 1.0, 3.0);
        let r = richardson(phi, 3.0).unwrap();
        assert!((phi[2] - 1.0).abs() <= r.gci_fine * phi[2].abs());
    }

    #[test]
    fn oscillation_divergence_and_flat_pairs_are_refused() {
        match richardson([1.0, 1.2, 1.1], 2.0) {
            Err(NotConvergent::Oscillatory { ratio }) => assert!((ratio + 0.5).abs() < 1e-12),
            other => panic!("{other:?}"),
        }
        assert!(matches!(richardson([1.0, 1.1, 1.3], 2.0), Err(NotConvergent::Divergent { .. })));
        assert!(matches!(richardson([1.0, 1.5, 2.0], 2.0), Err(NotConvergent::Divergent { .. })));
        assert!(matches!(
            richardson([1.0, 1.0, 1.1], 2.0),
            Err(NotConvergent::Indeterminate { .. })
        ));
        assert!(matches!(
            richardson([1.0, 1.1, 1.1], 2.0),
            Err(NotConvergent::Indeterminate { .. })
        ));
    }

    #[test]
    fn non_refinement_inputs_are_refused() {
        for alpha in [1.0, 0.5, f64::NAN, f64::INFINITY] {
            assert!(matches!(
                richardson([1.0, 1.1, 1.12], alpha),
                Err(NotConvergent::InvalidInput { .. })
            ));
        }
        assert!(matches!(
            richardson([1.0, f64::NAN, 1.12], 2.0),
            Err(NotConvergent::InvalidInput { .. })
        ));
    }

    #[test]
    fn refusals_say_why() {
        let msg = richardson([1.0, 1.2, 1.1], 2.0).unwrap_err().to_string();
        assert!(msg.contains("oscillatory"), "{msg}");
    }
}
