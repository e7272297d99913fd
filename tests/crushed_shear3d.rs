//! Crushed concrete's shear limit (`concrete.crushed_shear_strength_psi`, the 3D law's
//! `crushed_shear_pa`): a contact pressed hard and sheared slides at τ π r̄², not at μ |F_n|,
//! once μ |F_n| passes it, and below it Coulomb is untouched; a bond's shear plateau is capped
//! the same way; the energy the slip takes is booked. Against the closed form, contact by contact.

use demsweep::kernel3d::contact::{Bond, Contact};
use demsweep::kernel3d::law::{self, Class, Dissipation, Pair};

const R: f64 = 0.01;
const KAPPA: f64 = 30e9;
const MU: f64 = 0.5;
/// The limit, Pa.
const TAU: f64 = 80e6;
/// Steps of 0.1 µs at 1 m/s: 5 mm of sliding, past every elastic range here.
const STEPS: usize = 50_000;
const SLIDE_M: f64 = STEPS as f64 * 1e-7;

/// The shear force (N) a contact of `class` carries after sliding `SLIDE_M` along z at 1 m/s
/// pressed to an overlap of `overlap` (m), and what it booked as slip (J).
fn slide(class: &Class, bond: Bond, overlap: f64) -> (f64, f64, f64) {
    let d = 2.0 * R - overlap;
    let mut c = Contact::new(0, 1, 0, bond, 2.0 * R, [1.0, 0.0, 0.0]);
    let mut diss = Dissipation::default();
    let dt = 1e-7;
    let mut a = law::Action::default();
    for _ in 0..STEPS {
        let g = Pair { r: [R, R], dx_m: [d, 0.0, 0.0], v: [[0.0; 3], [0.0, 0.0, 1.0]], w: [[0.0; 3]; 2], m: [1.0, 1.0] };
        a = law::act(&mut c, class, &g, dt, &mut diss);
    }
    (a.force_j_n[2].abs(), a.force_j_n[0].abs(), diss.slip_j + diss.bond_shear_j)
}

#[test]
fn a_hard_pressed_contact_slides_at_the_crushed_limit_not_at_coulomb() {
    let rm = law::mean_radius_m([R, R]);
    let area = std::f64::consts::PI * rm * rm;
    let cap = TAU * area;
    let free = Class::elastic(KAPPA, 0.4, MU);
    let limited = Class { crushed_shear_pa: TAU, ..free.clone() };
    // Pressed lightly: μ |F_n| below the cap, Coulomb as before.
    let light = 0.05 * cap / (MU * KAPPA * rm);
    let (ft, fn_, _) = slide(&limited, Bond::Frictional, light);
    assert!((ft - MU * fn_).abs() < 1e-9 * ft, "light: {ft} N against μ F_n = {} N", MU * fn_);
    assert_eq!(slide(&free, Bond::Frictional, light).0, ft);
    // Pressed hard: μ |F_n| ten times the cap, the contact carries the cap.
    let hard = 10.0 * cap / (MU * KAPPA * rm);
    let (ft, fn_, slip) = slide(&limited, Bond::Frictional, hard);
    assert!(MU * fn_ > 9.0 * cap, "{fn_}");
    assert!((ft - cap).abs() < 1e-9 * cap, "hard: {ft} N against the cap {cap} N");
    let (ft_free, _, slip_free) = slide(&free, Bond::Frictional, hard);
    assert!((ft_free - MU * fn_).abs() < 1e-9 * ft_free, "{ft_free}");
    // What the sliding took: about the force times the slip past the elastic part.
    let elastic = cap / (0.4 * KAPPA * rm);
    let expected = cap * (SLIDE_M - elastic);
    assert!((slip - expected).abs() < 0.01 * expected, "booked {slip} J against {expected} J");
    assert!(slip_free > 5.0 * slip, "{slip_free} {slip}");
}

#[test]
fn a_bond_sheared_past_the_limit_carries_it() {
    let rm = law::mean_radius_m([R, R]);
    let area = std::f64::consts::PI * rm * rm;
    let mut bonded = Class::elastic(KAPPA, 0.4, MU);
    // A shear plateau above the cap (as the rate law makes it at the nose's rates).
    bonded.bond_shear_pa = 3.0 * TAU;
    let limited = Class { crushed_shear_pa: TAU, ..bonded.clone() };
    let (ft, _, _) = slide(&bonded, Bond::Intact, 0.0);
    assert!((ft - 3.0 * TAU * area).abs() < 1e-9 * ft, "{ft}");
    let (ft, _, booked) = slide(&limited, Bond::Intact, 0.0);
    assert!((ft - TAU * area).abs() < 1e-9 * ft, "{ft} against {}", TAU * area);
    assert!(booked > 0.0);
}
