//! The inverse (scabbing velocity, ballistic limit): closed forms of FORMULAS §5 against the
//! bisection, the forward→inverse round trip, monotonicity in velocity (with the documented
//! exceptions), and the answers that are not numbers.

mod common;

use common::{missile, target};
use demsweep::empirical::inverse::{self, Threshold};
use demsweep::empirical::{
    Formula, Missile, Nose, Quantity, Target, closed_form, degen, hughes, impact_factor, kar, ndrc,
};
use proptest::prelude::*;

#[test]
fn closed_forms_agree_with_bisection() {
    let (mut compared, mut beyond_scan) = (0, 0);
    for f in Formula::ALL {
        for q in [Quantity::Scabbing, Quantity::Perforation] {
            for nose in Nose::ALL {
                for h_in in [12.0, 20.0, 30.0, 45.0, 60.0] {
                    let (m, t) = (missile(nose), target());
                    let Some(closed) = closed_form::velocity_fps(f, q, &m, &t, h_in) else { continue };
                    let Some(bisected) = inverse::velocity_for(f, q, &m, &t, h_in).v_fps() else {
                        // Not reached inside the scan: the closed form must say it lies beyond.
                        let scan_max = demsweep::units::mps_to_fps(inverse::SCAN_MAX_MPS);
                        assert!(closed > scan_max, "{} {:?} {h_in} in: closed {closed}", f.id(), q);
                        beyond_scan += 1;
                        continue;
                    };
                    let rel = (closed / bisected - 1.0).abs();
                    // FORMULAS §5 reports 3e-11; the bisection here runs to adjacent doubles.
                    assert!(rel < 1e-11, "{} {} {:?} {h_in} in: closed {closed} vs {bisected} ({rel:e})", f.id(), f.variant(), q);
                    compared += 1;
                }
            }
        }
    }
    // Petry ×3, BRL ×2, ACE, NDRC, Kar, Chang: both quantities; Degen, CEA-EDF ×2: h_p;
    // Bechtel, S&W ×2: h_s — 24 (formula, quantity) pairs × 4 noses × 5 thicknesses.
    assert_eq!(compared + beyond_scan, 24 * 4 * 5);
    assert!(beyond_scan < 10, "{beyond_scan} beyond the scan");
}

#[test]
fn kar_closed_form_with_a_softer_missile() {
    // E/E_s ≠ 1 exercises both of Kar's exponents and the aggregate term.
    let m = Missile { modulus_psi: 10.0e6, ..missile(Nose::Blunt) };
    for q in [Quantity::Scabbing, Quantity::Perforation] {
        let closed = closed_form::velocity_fps(Formula::Kar, q, &m, &target(), 30.0).unwrap();
        let bisected = inverse::velocity_for(Formula::Kar, q, &m, &target(), 30.0).v_fps().unwrap();
        assert!((closed / bisected - 1.0).abs() < 1e-11, "{q:?}: {closed} vs {bisected}");
    }
    assert!(kar::beta(&m) < 1.0);
}

#[test]
fn answers_that_are_not_numbers() {
    let (m, t) = (missile(Nose::Spherical), target());
    assert_eq!(inverse::ballistic_limit(Formula::Bechtel, &m, &t), Threshold::NotDefined);
    assert_eq!(inverse::scabbing_velocity(Formula::Degen, &m, &t), Threshold::NotDefined);
    assert_eq!(inverse::scabbing_velocity(Formula::AdeliAmin, &m, &t), Threshold::NotReachable);
    // ACE's x/d ≥ 0.5, so h_s/d ≥ 2.69 at any velocity: a 5 in wall (h/d = 1.43) scabs at any.
    assert_eq!(inverse::velocity_for(Formula::Ace, Quantity::Scabbing, &m, &t, 5.0), Threshold::AnyVelocity);
    assert_eq!(closed_form::velocity_fps(Formula::Ace, Quantity::Scabbing, &m, &t, 5.0), None);
    // A thin wall Adeli–Amin does reach: h_p/d = 3 at some I < 15.2.
    let th = inverse::velocity_for(Formula::AdeliAmin, Quantity::Perforation, &m, &t, 3.0 * m.diameter_in);
    let v = th.v_fps().expect("reachable below the fold");
    let i = impact_factor::impact_factor(&m, &t, v);
    assert!(i < 15.2, "I = {i}");
    assert_eq!(Threshold::NotReachable.cell(0), "not reachable");
}

// ---- Property tests. Documented exceptions (FORMULAS §3, §5): where a fit drops at a branch
// join (Kennedy h_p at x/d = 1.35: 2.998 → 2.994; Hughes h_p at 0.7: 2.520 → 2.506; Degen at
// 1.52: 2.65088 → 2.6508; Haldar–Hamieh x at I = 21: 1.865 → 1.815) or turns over (Adeli–Amin:
// x/d beyond I = 19.1, h_s/d beyond 17.7, h_p/d beyond 15.2). The drops are recomputed here from
// the printed coefficients, independently of the implementation.

fn kennedy_hp_drop() -> f64 {
    (3.19 * 1.35 - 0.718 * 1.35 * 1.35) - (1.32 + 1.24 * 1.35)
}
fn hughes_hp_drop() -> f64 {
    3.6 * 0.7 - (1.58 * 0.7 + 1.4)
}
fn degen_drop() -> f64 {
    (2.2 * 1.52 - 0.3 * 1.52 * 1.52) - (0.69 + 1.29 * 1.52)
}
fn haldar_hamieh_drop() -> f64 {
    (0.6740 + 0.0567 * 21.0) - (1.1875 + 0.0299 * 21.0)
}

/// Largest decrease of `q` (in) that `f` is documented to have, for this missile.
fn allowed_drop_in(f: Formula, q: Quantity, m: &Missile) -> f64 {
    let d = m.diameter_in;
    match (f, q) {
        (Formula::Ndrc | Formula::Ace, Quantity::Perforation) => kennedy_hp_drop() * d,
        (Formula::Kar, Quantity::Perforation) => kennedy_hp_drop() * d / kar::beta(m),
        (Formula::Hughes(_), Quantity::Perforation) => hughes_hp_drop() * d,
        (Formula::Degen, Quantity::Perforation) => degen_drop() * d,
        (Formula::HaldarHamieh, Quantity::Penetration) => haldar_hamieh_drop() * d,
        _ => 0.0,
    }
}

/// Adeli–Amin's curves rise only up to their maxima.
fn rising_part(f: Formula, q: Quantity, m: &Missile, t: &Target, v_fps: f64) -> bool {
    if f != Formula::AdeliAmin {
        return true;
    }
    let i = impact_factor::impact_factor(m, t, v_fps);
    let peak = match q {
        Quantity::Penetration => 19.06,
        Quantity::Scabbing => 0.4035 / (2.0 * 0.0114),
        Quantity::Perforation => 0.3214 / (2.0 * 0.0106),
    };
    i <= peak
}

/// Whether `v_fps` lies where the same thickness is also reached at a lower velocity (a drop
/// window), so the first crossing is not `v_fps` itself.
fn in_drop_window(f: Formula, q: Quantity, m: &Missile, t: &Target, v_fps: f64) -> bool {
    let near = |x: f64, b: f64, w: f64| (x - b).abs() <= w;
    let at_a_drop = match (f, q) {
        (Formula::Ndrc | Formula::Ace | Formula::Kar, Quantity::Perforation) => {
            let xd = match f {
                Formula::Ndrc => ndrc::penetration_ratio(m, t, v_fps),
                Formula::Kar => kar::penetration_ratio(m, t, v_fps),
                _ => demsweep::empirical::ace::penetration_ratio(m, t, v_fps),
            };
            near(xd, 1.35, 0.01)
        }
        (Formula::Degen, Quantity::Perforation) => near(ndrc::penetration_ratio(m, t, v_fps), degen::BREAK_XD, 0.01),
        (Formula::Hughes(_), Quantity::Perforation) => {
            let h = f.evaluate(q, m, t, v_fps).unwrap() / m.diameter_in;
            near(h, 2.513, 0.01)
        }
        (Formula::HaldarHamieh, Quantity::Penetration) => {
            let i = impact_factor::impact_factor(m, t, v_fps);
            (20.0..=23.0).contains(&i)
        }
        _ => false,
    };
    at_a_drop || !rising_part(f, q, m, t, v_fps)
}

fn scenario() -> impl Strategy<Value = (Missile, Target)> {
    (1.0f64..2000.0, 1.0f64..14.0, 0usize..4, 0.3f64..1.5, 2500.0f64..8000.0, 0.3f64..3.0).prop_map(
        |(w, d, nose, e_ratio, fc, agg)| {
            let m = Missile::new(w, d, Nose::ALL[nose], e_ratio * 29.0e6).unwrap();
            let t = Target::new(fc, 0.1 * fc, 145.0, 30.0, agg).unwrap();
            (m, t)
        },
    )
}

proptest! {
    // A fixed seed: CI runs the same cases every time (and writes no regression files).
    #![proptest_config(ProptestConfig {
        cases: 128,
        rng_seed: proptest::test_runner::RngSeed::Fixed(0x5EED_2026),
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    /// Each x, h_s, h_p is non-decreasing in velocity where its inputs are not outside the
    /// stated validity range, up to the documented drops.
    #[test]
    fn non_decreasing_in_velocity((m, t) in scenario(), v1 in 5.0f64..4000.0, dv in 0.0f64..1500.0) {
        let v2 = v1 + dv;
        for f in Formula::ALL {
            for q in Quantity::ALL {
                let (Some(h1), Some(h2)) = (f.evaluate(q, &m, &t, v1), f.evaluate(q, &m, &t, v2)) else { continue };
                let usable = f.validity(q, &m, &t, v1).is_usable() && f.validity(q, &m, &t, v2).is_usable();
                if !usable || !rising_part(f, q, &m, &t, v2) {
                    continue;
                }
                let slack = allowed_drop_in(f, q, &m) + 1e-12 * h1.abs();
                prop_assert!(h2 >= h1 - slack, "{} {} {:?}: h({v1}) = {h1} > h({v2}) = {h2}", f.id(), f.variant(), q);
            }
        }
    }

    /// The inverse of the forward prediction returns the velocity to 1e-9 relative; inside a
    /// documented drop or past a fold it returns an earlier velocity with the same thickness.
    #[test]
    fn inverse_round_trip((m, t) in scenario(), v in 10.0f64..4000.0) {
        for f in Formula::ALL {
            for q in Quantity::ALL {
                let Some(h) = f.evaluate(q, &m, &t, v) else { continue };
                let back = inverse::velocity_for(f, q, &m, &t, h);
                let Threshold::Velocity { v_fps, .. } = back else {
                    // ACE and Adeli–Amin start above zero thickness at zero velocity.
                    prop_assert!(back == Threshold::AnyVelocity, "{} {:?}: {back:?}", f.id(), q);
                    continue;
                };
                if in_drop_window(f, q, &m, &t, v) {
                    // The thickness is reached on both sides of a downward jump here; the part
                    // before the jump can be narrower than the scan's step and hide between two
                    // samples, so the answer is a crossing in the same window, not always ≤ v.
                    let reached = f.evaluate(q, &m, &t, v_fps).unwrap();
                    prop_assert!(reached >= h * (1.0 - 1e-9), "{} {:?}: {reached} < {h}", f.id(), q);
                    prop_assert!(
                        v_fps <= v * (1.0 + 1e-9) || in_drop_window(f, q, &m, &t, v_fps),
                        "{} {:?}: {v_fps} past the window of {v}", f.id(), q
                    );
                } else {
                    let rel = (v_fps / v - 1.0).abs();
                    prop_assert!(rel <= 1e-9, "{} {} {:?}: v = {v}, back {v_fps} ({rel:e})", f.id(), f.variant(), q);
                }
            }
        }
    }
}

#[test]
fn hughes_drop_window_is_the_documented_one() {
    // The window the round trip excuses is where h_p/d lies between the two join values.
    assert!((hughes::hp_over_d(0.7) - 2.506).abs() < 1e-9);
    assert!((hughes_hp_drop() - 0.014).abs() < 1e-9);
}

/// Regression (found by `inverse_round_trip` on an unseeded CI run): Kar's h_p jumps down at
/// the Kennedy branch join x/d = 1.35. The shrunk input put v 0.03 % below the join, where the
/// thickness is reached only up to the join: a window narrower than the scan's 0.43 % steps
/// and invisible to its samples, which rise across it. The test expected a velocity ≤ v in drop
/// windows; what the inverse can promise is the next crossing it resolves, here 0.26 % later,
/// in the same window (documented in `empirical::inverse`).
#[test]
fn kar_perforation_inverse_at_the_branch_join_stays_in_the_drop_window() {
    let m = Missile::new(1934.957359359767, 5.9075611548210265, Nose::Blunt, 19406991.493375454).unwrap();
    let t = Target::new(5041.154883216623, 504.11548832166227, 145.0, 30.0, 0.3).unwrap();
    let v = 132.72754695935396;
    let (f, q) = (Formula::Kar, Quantity::Perforation);
    assert!(in_drop_window(f, q, &m, &t, v));
    let h = f.evaluate(q, &m, &t, v).unwrap();
    // The thickness is reached from v up to the join only (< 0.04 %), then again 0.26 % later.
    let at = |r: f64| f.evaluate(q, &m, &t, v * r).unwrap();
    assert!(at(1.0 - 1e-6) < h && at(1.0001) >= h && at(1.0004) < h && at(1.0028) >= h);
    let back = inverse::velocity_for(f, q, &m, &t, h).v_fps().unwrap();
    assert!(f.evaluate(q, &m, &t, back).unwrap() >= h * (1.0 - 1e-9));
    assert!(back <= v * 1.003 && in_drop_window(f, q, &m, &t, back), "returned {back}, past the window of {v}");
}

/// Regression (same run): Adeli–Amin's quadratic h_p just under its maximum is reached only in a
/// window narrower than the scan's step; the inverse said "not reachable".
#[test]
fn adeli_amin_inverse_finds_the_top_of_its_parabola() {
    let m = missile(Nose::Spherical);
    let t = target();
    let (f, q) = (Formula::AdeliAmin, Quantity::Perforation);
    // I at the parabola's top, 0.3214 / (2 × 0.0106): solve for v by bisection on I.
    let i_top = 0.3214 / (2.0 * 0.0106);
    let (mut a, mut b) = (1.0, 5000.0);
    for _ in 0..200 {
        let mid = 0.5 * (a + b);
        if demsweep::empirical::impact_factor::impact_factor(&m, &t, mid) < i_top { a = mid } else { b = mid }
    }
    let v_top = 0.5 * (a + b);
    let h_top = f.evaluate(q, &m, &t, v_top).unwrap();
    let back = inverse::velocity_for(f, q, &m, &t, h_top * (1.0 - 1e-7)).v_fps();
    assert!(back.is_some_and(|v| (v / v_top - 1.0).abs() < 1e-3), "{back:?} vs the top at {v_top}");
}
