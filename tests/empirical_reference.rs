//! FORMULAS.md §6: every number it prints for the report's scenario (W = 15 lb, D = 3.5 in,
//! f'c = 3000 psi, f_t = 300 psi, 145 pcf, h = 30 in, aggregate 0.75 in), to the printed digits.

mod common;

use common::{missile, round, target, v_perf, v_scab};
use demsweep::empirical::inverse::{self, Threshold};
use demsweep::empirical::{
    BrlScabbing, CeaEdfForm, Formula, HughesTensile, Nose, PetryClass, Quantity, StoneWebsterC, Validity, brl,
    cea_edf, hughes,
};
use demsweep::units;

use Nose::{Blunt, Flat, Spherical, VerySharp};

/// A §6 row: formula, then (V_s, V_p) per nose flat, blunt, spherical, very sharp;
/// `None` where the formula does not define the quantity.
type Row = (Formula, [(Option<f64>, Option<f64>); 4]);

fn same(vs: Option<f64>, vp: Option<f64>) -> [(Option<f64>, Option<f64>); 4] {
    [(vs, vp); 4]
}

fn table() -> Vec<Row> {
    let s = Some;
    vec![
        (Formula::Petry(PetryClass::Plain), same(s(842.0), s(925.0))),
        (Formula::Petry(PetryClass::NormalRc), same(s(1761.0), s(2036.0))),
        (Formula::Brl(BrlScabbing::TwicePerforation), same(s(955.0), s(1609.0))),
        (Formula::Brl(BrlScabbing::TwicePenetration), same(s(1163.0), s(1609.0))),
        (Formula::Ace, same(s(1480.0), s(1726.0))),
        (Formula::Ndrc, [(s(2012.0), s(2323.0)), (s(1847.0), s(2132.0)), (s(1676.0), s(1935.0)), (s(1559.0), s(1799.0))]),
        (Formula::Degen, [(None, s(2392.0)), (None, s(2195.0)), (None, s(1993.0)), (None, s(1853.0))]),
        (Formula::Kar, [(s(1988.0), s(2300.0)), (s(1825.0), s(2111.0)), (s(1657.0), s(1916.0)), (s(1540.0), s(1782.0))]),
        (Formula::CeaEdf(CeaEdfForm::Base), same(None, s(2726.0))),
        (Formula::Chang, same(s(1428.0), s(2425.0))),
        (
            Formula::Hughes(HughesTensile::Given),
            [(s(1320.0), s(1550.0)), (s(1217.0), s(1433.0)), (s(1117.0), s(1320.0)), (s(1038.0), s(1230.0))],
        ),
        (
            Formula::Hughes(HughesTensile::ModulusOfRupture),
            [(s(1554.0), s(1825.0)), (s(1433.0), s(1687.0)), (s(1315.0), s(1553.0)), (s(1222.0), s(1448.0))],
        ),
        (Formula::Bechtel, same(s(2125.0), None)),
        (Formula::StoneWebster(StoneWebsterC::C900), same(s(1273.0), None)),
        (Formula::StoneWebster(StoneWebsterC::C1900), same(s(1849.0), None)),
    ]
}

fn threshold_or_none(th: Threshold) -> Option<f64> {
    match th {
        Threshold::NotDefined => None,
        other => Some(other.v_fps().unwrap_or_else(|| panic!("expected a velocity, got {other:?}"))),
    }
}

#[test]
fn v_s_and_v_p_table_to_the_foot_per_second() {
    let mut failures = Vec::new();
    for (f, per_nose) in table() {
        for (nose, (vs, vp)) in Nose::ALL.into_iter().zip(per_nose) {
            let got_s = threshold_or_none(inverse::scabbing_velocity(f, &missile(nose), &target())).map(|v| round(v, 0));
            let got_p = threshold_or_none(inverse::ballistic_limit(f, &missile(nose), &target())).map(|v| round(v, 0));
            if (got_s, got_p) != (vs, vp) {
                failures.push(format!("{} {} {}: got {got_s:?}/{got_p:?}, FORMULAS {vs:?}/{vp:?}", f.id(), f.variant(), nose.name()));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn adeli_amin_is_not_reachable_for_the_30_in_wall() {
    for nose in Nose::ALL {
        assert_eq!(inverse::scabbing_velocity(Formula::AdeliAmin, &missile(nose), &target()), Threshold::NotReachable);
        assert_eq!(inverse::ballistic_limit(Formula::AdeliAmin, &missile(nose), &target()), Threshold::NotReachable);
    }
    // "h/d = 8.6 > max 5.4 / 3.3"
    assert_eq!(round(target().thickness_in / missile(Flat).diameter_in, 1), 8.6);
}

/// FORMULAS §6 prints "1496 (closed form 1493)" for the CEA-EDF extension with r = 0, but 2726
/// for the base formula. We use the exact inverse coefficient 1.3^-0.75 (0.82 is it rounded), so
/// the bisection and the closed form agree at 1493 and the base gives 2726. The printed 1496 is
/// what the rounded 0.82 gives (h ∝ c V^0.75, so V scales by (1.3^-0.75/0.82)^(4/3)), and with
/// 0.82 the base would print 2732, not 2726: the two printed figures used different coefficients.
#[test]
fn cea_edf_extension_1493_and_the_origin_of_1496() {
    let ext = Formula::CeaEdf(CeaEdfForm::ExtensionPlain);
    let v_ext = v_perf(ext, Spherical);
    assert_eq!(round(v_ext, 0), 1493.0);
    let closed = cea_edf::extension_ballistic_limit_fps(&missile(Spherical), &target(), 30.0, cea_edf::Reinforcement::PLAIN);
    assert_eq!(round(closed, 0), 1493.0);
    // "for plain concrete (r = 0) it lowers V_p by 0.548"
    assert_eq!(round(v_ext / v_perf(Formula::CeaEdf(CeaEdfForm::Base), Spherical), 3), 0.548);

    let with_printed_coefficient = (cea_edf::hp_coefficient() / 0.82).powf(4.0 / 3.0);
    assert_eq!(round(v_ext * with_printed_coefficient, 0), 1496.0);
    assert_eq!(round(v_perf(Formula::CeaEdf(CeaEdfForm::Base), Spherical) * with_printed_coefficient, 0), 2732.0);
}

fn x_at(f: Formula, nose: Nose, v_fps: f64) -> f64 {
    f.evaluate(Quantity::Penetration, &missile(nose), &target(), v_fps).expect("x defined")
}

#[test]
fn penetration_at_500_fps() {
    // "reproduced by BRL (4.88 in) and ACE (4.67) for any nose"
    for nose in Nose::ALL {
        assert_eq!(round(x_at(Formula::Brl(BrlScabbing::TwicePerforation), nose, 500.0), 2), 4.88);
        assert_eq!(round(x_at(Formula::Ace, nose, 500.0), 2), 4.67);
    }
    // "NDRC 4.56/4.87, Hughes (f_t = 300 psi) 4.84/5.34, Haldar-Hamieh 4.52/4.82,
    //  Adeli-Amin 4.64/4.91, UKAEA 4.22/4.55" for spherical / very sharp.
    let pairs = [
        (Formula::Ndrc, 4.56, 4.87),
        (Formula::Hughes(HughesTensile::Given), 4.84, 5.34),
        (Formula::HaldarHamieh, 4.52, 4.82),
        (Formula::AdeliAmin, 4.64, 4.91),
        (Formula::Ukaea, 4.22, 4.55),
    ];
    let mut flat = Vec::new();
    for (f, sph, sharp) in pairs {
        assert_eq!(round(x_at(f, Spherical, 500.0), 2), sph, "{}", f.id());
        assert_eq!(round(x_at(f, VerySharp, 500.0), 2), sharp, "{}", f.id());
        flat.push(x_at(f, Flat, 500.0));
    }
    // "A flat nose gives 3.5–3.9 in (22–30 % low)."
    let (lo, hi) = flat.iter().fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
    assert_eq!((round(lo, 1), round(hi, 1)), (3.5, 3.9));
    assert_eq!(round(100.0 * (1.0 - hi / 5.0), 0), 22.0);
    // The 30 % is (1 − 3.5/5) from the rounded depth; unrounded UKAEA (3.464 in) is 31 % low.
    assert_eq!(round(100.0 * (1.0 - round(lo, 1) / 5.0), 0), 30.0);
    assert_eq!(round(100.0 * (1.0 - lo / 5.0), 0), 31.0);
    // "Petry plain gives 7.2 in (+44 %)."
    let petry = x_at(Formula::Petry(PetryClass::Plain), Spherical, 500.0);
    assert_eq!((round(petry, 1), round(100.0 * (petry / 5.0 - 1.0), 0)), (7.2, 44.0));
}

#[test]
fn no_scabbing_at_500_fps_largest_is_adeli_amin() {
    // "largest h_s(500) = 17.2 in, Adeli-Amin" — for the report's spherical nose. (With a very
    // sharp nose Adeli–Amin gives 17.9 in, still far below 30 in.)
    let largest = |nose: Nose| {
        Formula::ALL
            .iter()
            .filter_map(|f| f.evaluate(Quantity::Scabbing, &missile(nose), &target(), 500.0).map(|h| (h, *f)))
            .fold((0.0, Formula::Ace), |best, c| if c.0 > best.0 { c } else { best })
    };
    let (h, f) = largest(Spherical);
    assert_eq!((round(h, 1), f), (17.2, Formula::AdeliAmin));
    let (h_sharp, f_sharp) = largest(VerySharp);
    assert_eq!((round(h_sharp, 1), f_sharp), (17.9, Formula::AdeliAmin));
    assert!(h_sharp < target().thickness_in);
}

#[test]
fn brl_760_fps_figures() {
    let m = missile(Spherical);
    let x760 = brl::penetration_in(&m, &target(), 760.0);
    assert_eq!(round(x760, 2), 8.51);
    // "760 ft/s needs h_s/x_BRL = 3.52 … a 22.1-in wall with h_s = 2h_p or a 17.0-in wall with h_s = 2x"
    assert_eq!(round(30.0 / x760, 2), 3.52);
    assert_eq!(round(brl::scabbing_twice_perforation_in(x760), 1), 22.1);
    assert_eq!(round(brl::scabbing_twice_penetration_in(x760), 1), 17.0);
    // "DOE design factors (30 in = 1.1 h_s) give 889 ft/s"
    let doe = inverse::velocity_for(Formula::Brl(BrlScabbing::TwicePerforation), Quantity::Scabbing, &m, &target(), 30.0 / 1.1);
    assert_eq!(round(doe.v_fps().unwrap(), 0), 889.0);
    // "its BRL V_p would be 760·2^(1/1.33) = 1280 ft/s": h_p = h_s/2 at V_p, and V ∝ h^(1/1.33).
    let vp_if_760 = inverse::velocity_for(
        Formula::Brl(BrlScabbing::TwicePerforation),
        Quantity::Perforation,
        &m,
        &target(),
        brl::scabbing_twice_perforation_in(x760),
    );
    assert_eq!(round(vp_if_760.v_fps().unwrap(), 0), 1280.0);
    // BRL's own V_s is 955 (+26 %) or 1163 (+53 %) against the report's 760.
    let pct = |v: f64| round(100.0 * (v / 760.0 - 1.0), 0);
    assert_eq!(pct(v_scab(Formula::Brl(BrlScabbing::TwicePerforation), Spherical)), 26.0);
    assert_eq!(pct(v_scab(Formula::Brl(BrlScabbing::TwicePenetration), Spherical)), 53.0);
}

#[test]
fn scenario_inputs_in_si_and_hughes_modulus_of_rupture() {
    let m = missile(Spherical);
    let t = target();
    assert_eq!(round(m.mass_kg(), 3), 6.804);
    assert_eq!(round(m.diameter_m(), 4), 0.0889);
    assert_eq!(round(t.fc_pa() / 1e6, 2), 20.68);
    assert_eq!(round(t.density_kg_per_m3(), 1), 2322.7);
    assert_eq!(round(t.thickness_in / m.diameter_in, 2), 8.57);
    let mor = hughes::modulus_of_rupture_psi(&t);
    assert_eq!((round(mor, 0), round(units::psi_to_pa(mor) / 1e6, 2)), (416.0, 2.87));
}

#[test]
fn out_of_validity_at_the_thresholds() {
    // "Chang (V > 311.8 m/s = 1023 ft/s; fc 20.7 < 22.8 MPa), CEA-EDF (V > 200 m/s = 656 ft/s),
    //  Degen (V > 311.8 m/s; fc < 28.4 MPa), Stone & Webster (h/d)"
    assert_eq!(round(units::mps_to_fps(311.8), 0), 1023.0);
    assert_eq!(round(units::mps_to_fps(200.0), 0), 656.0);
    let outside = |f: Formula, q: Quantity, needles: &[&str]| {
        let th = inverse::velocity_for(f, q, &missile(Spherical), &target(), 30.0);
        let Threshold::Velocity { validity: Validity::Outside(why), .. } = th else {
            panic!("{} {}: expected outside validity, got {th:?}", f.id(), f.variant())
        };
        for n in needles {
            assert!(why.contains(n), "{}: {why} lacks {n}", f.id());
        }
    };
    outside(Formula::Chang, Quantity::Scabbing, &["> 311.8 m/s", "f'c = 20.68 MPa < 22.8 MPa"]);
    outside(Formula::Chang, Quantity::Perforation, &["> 311.8 m/s"]);
    outside(Formula::CeaEdf(CeaEdfForm::Base), Quantity::Perforation, &["> 200 m/s"]);
    outside(Formula::CeaEdf(CeaEdfForm::ExtensionPlain), Quantity::Perforation, &["> 200 m/s"]);
    outside(Formula::Degen, Quantity::Perforation, &["> 311.8 m/s", "< 28.4 MPa"]);
    outside(Formula::StoneWebster(StoneWebsterC::C900), Quantity::Scabbing, &["h/d = 8.571 > 3"]);
    // And the Kennedy-chained and Hughes thresholds are inside their ranges.
    for f in [Formula::Ace, Formula::Ndrc, Formula::Kar, Formula::Hughes(HughesTensile::Given)] {
        let th = inverse::scabbing_velocity(f, &missile(Spherical), &target());
        assert!(matches!(th, Threshold::Velocity { validity: Validity::Inside, .. }), "{}: {th:?}", f.id());
    }
}

/// §6 "Against the report's statements", the velocity spans. The percentages FORMULAS prints are
/// reproduced except that Chang's V_s (1428) is 14 % above 1250, below the "18–70 %" it states
/// for the formulas above the span (18 % is ACE's).
#[test]
fn report_span_statements() {
    let t = |f| v_scab(f, Spherical);
    let inside_scab_span = |v: f64| (750.0..=1250.0).contains(&v);
    assert!(inside_scab_span(t(Formula::Petry(PetryClass::Plain))));
    assert!(inside_scab_span(t(Formula::Brl(BrlScabbing::TwicePerforation))));
    assert!(inside_scab_span(t(Formula::Brl(BrlScabbing::TwicePenetration))));
    for nose in [Blunt, Spherical, VerySharp] {
        assert!(inside_scab_span(v_scab(Formula::Hughes(HughesTensile::Given), nose)));
    }
    assert!(!inside_scab_span(v_scab(Formula::Hughes(HughesTensile::Given), Flat)));
    let above = |v: f64| round(100.0 * (v / 1250.0 - 1.0), 0);
    assert_eq!(above(t(Formula::Ace)), 18.0);
    assert_eq!(above(t(Formula::Bechtel)), 70.0);
    assert_eq!(above(t(Formula::Chang)), 14.0);
    assert_eq!(above(v_scab(Formula::Ndrc, VerySharp)), 25.0);
    assert_eq!(above(v_scab(Formula::Ndrc, Flat)), 61.0);

    // Perforation: "Petry-plain (925, −7.5 %) and BRL (1609, +7 %)" just outside 1000–1500.
    let vp_petry = v_perf(Formula::Petry(PetryClass::Plain), Spherical);
    assert_eq!(round(100.0 * (vp_petry / 1000.0 - 1.0), 1), -7.5);
    let vp_brl = v_perf(Formula::Brl(BrlScabbing::TwicePerforation), Spherical);
    assert_eq!(round(100.0 * (vp_brl / 1500.0 - 1.0), 0), 7.0);
    // Hughes (f_t = 300 psi) non-flat noses 1230–1433, flat 1550.
    let hughes: Vec<f64> = Nose::ALL.iter().map(|&n| round(v_perf(Formula::Hughes(HughesTensile::Given), n), 0)).collect();
    assert_eq!(hughes, [1550.0, 1433.0, 1320.0, 1230.0]);
}
