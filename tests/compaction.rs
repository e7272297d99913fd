//! Compaction (seed §6, eq 6.11 and the rule after it): a bond in compression is linear up to
//! the critical compressive force, then its rest length moves plastically along the yield line
//! until full compaction, after which it is linear with Kn again; unloading follows Kn from the
//! moved rest length; the work along the yield line is its own line in the ledger; the rest
//! length and the touching test of a broken, compacted pair stay consistent.

mod common;

use demsweep::kernel::contact::{Bond, Contact};
use demsweep::material::CompactionSpec;
use demsweep::material::RateSpec;
use demsweep::kernel::law::{self, ContactClass, Dissipation, Extra, Kinematics};
use demsweep::kernel::{ModelBuilder, boundary};
use demsweep::lattice::{self, Rect};
use demsweep::material::{Arrangement, FailureCriterion, Material, Plane};
use demsweep::units::psi_to_pa;

/// Compaction on, the rest off.
type Compacting = law::With<true, false, false, true>;
/// Compaction and rate effects on.
type RatedCompacting = law::With<true, false, true, true>;

const R: f64 = 0.00635;

fn concrete(compaction: CompactionSpec, rate: Option<RateSpec>) -> Material {
    Material {
        tensile_strength_pa: psi_to_pa(300.0),
        compressive_strength_pa: psi_to_pa(3000.0),
        fracture_toughness_pa_sqrt_m: 1.0e6,
        failure: FailureCriterion::StrengthEnergy,
        compaction: Some(compaction),
        rate,
        ..Material::elastic("concrete", psi_to_pa(3122e3), 0.2, 2320.0)
    }
}

fn class(m: &Material) -> ContactClass {
    let side = law::Side { material: m, arrangement: Arrangement::ClosePacked, radius_m: R };
    let ctx = law::Context { plane: Plane::Strain, thickness_m: 1.0, beta_s: 0.0, max_speed_mps: 1e3 };
    let mut k = ContactClass::between(side, side, &ctx).unwrap();
    k.set_time_step(1e-8);
    k
}

/// Step of the drives, s.
const DT: f64 = 1e-8;

/// Drive a bond of initial length 2R through the centre distances `path` (m), one point a step
/// of `DT` (the relative speed is the path's); returns the normal force (tension positive) at
/// each, the contact and its dissipation.
fn drive<P: law::PartSet>(k: &ContactClass, path: &[f64]) -> (Vec<f64>, Contact, Dissipation) {
    let d0 = 2.0 * R;
    let (mut c, mut x, mut diss) = (Contact::bonded(0, 1, 0, d0), Extra::new(d0), Dissipation::default());
    let mut out = Vec::new();
    let mut prev = d0;
    for &d in path {
        let g = Kinematics { d_m: d, nx: 1.0, ny: 0.0, vn_mps: (d - prev) / DT, vt_mps: 0.0, li_m: 0.5 * d, lj_m: 0.5 * d };
        prev = d;
        out.push(law::interact::<P>(&mut c, &mut x, k, &g, DT, &mut diss).fx);
    }
    (out, c, diss)
}

#[test]
fn critical_force_is_eq_6_11_and_the_yield_line_leads_to_full_compaction() {
    // Eq 6.11 by hand: R t f'c / (2(1 − ν*)) (√3 − ν*/√3) with R = 6.35 mm, t = 1 m,
    // f'c = 3000 psi = 20.6843 MPa, ν* = 0.25: 87 563.4 N × 1.587713 = 139 025.6 N.
    let (kc_ratio, full) = (0.01, 0.5);
    let k = class(&concrete(CompactionSpec { stiffness_ratio: kc_ratio, full_strain: full }, None));
    assert!((k.compaction.critical_force_n / 139_025.6 - 1.0).abs() < 1e-6, "{}", k.compaction.critical_force_n);
    let (kn, fc) = (k.bond.kn_n_per_m, k.compaction.critical_force_n);
    let kc = kc_ratio * kn;
    let d0 = 2.0 * R;
    // Compress to 60 % of L0 (past full compaction at 50 % plastic strain), in small steps.
    let n = 200_000;
    let path: Vec<f64> = (1..=n).map(|s| d0 * (1.0 - 0.6 * s as f64 / n as f64)).collect();
    let (f, c, diss) = drive::<Compacting>(&k, &path);
    // The spring is linear until −fc, ...
    let elastic_end = fc / kn;
    for (s, &d) in path.iter().enumerate() {
        let shortening = d0 - d;
        if shortening < 0.99 * elastic_end {
            assert!((f[s] + kn * shortening).abs() < 1e-6 * fc, "elastic branch at {shortening}");
        } else if shortening > 1.01 * elastic_end && shortening < 0.49 * d0 {
            // ... then follows the yield line f_c + K_c p, p the plastic compaction ...
            let p = (kn * shortening - fc) / (kn + kc);
            assert!((-f[s] / (fc + kc * p) - 1.0).abs() < 1e-6, "yield line at {shortening}");
        }
    }
    // ... until p = 0.5 L0: the rest length stopped at L0/2, the spring is Kn again.
    assert!((c.rest_m / (0.5 * d0) - 1.0).abs() < 1e-12, "rest {} vs L0/2", c.rest_m);
    let last = path.len() - 1;
    let slope = (f[last] - f[last - 1]) / (path[last] - path[last - 1]);
    assert!((slope / kn - 1.0).abs() < 1e-6, "slope past full compaction {slope} vs Kn {kn}");
    // The work along the yield line: ∫ (f_c + K_c p) dp from 0 to L0/2.
    let p_full = 0.5 * d0;
    let work = fc * p_full + 0.5 * kc * p_full * p_full;
    assert!((diss.compaction_work_j / work - 1.0).abs() < 1e-6, "booked {} vs {work}", diss.compaction_work_j);
    // Unloading follows Kn from the moved rest length: back to zero force at d = L0/2.
    let back: Vec<f64> = (0..=100).map(|s| path[last] + (0.5 * d0 - path[last]) * s as f64 / 100.0).collect();
    let (f2, _, _) = {
        let (mut c2, mut x2, mut d2) = (c, Extra::new(d0), Dissipation::default());
        let mut out = Vec::new();
        for &d in &back {
            let g = Kinematics { d_m: d, nx: 1.0, ny: 0.0, vn_mps: 1.0, vt_mps: 0.0, li_m: 0.5 * d, lj_m: 0.5 * d };
            out.push(law::interact::<Compacting>(&mut c2, &mut x2, &k, &g, DT, &mut d2).fx);
        }
        (out, c2, d2)
    };
    assert!(f2.last().unwrap().abs() < 1e-6 * fc && (f2[50] / (-kn * (0.5 * d0 - back[50])) - 1.0).abs() < 1e-9);
}

#[test]
fn perfectly_plastic_by_default_and_the_rate_enhances_the_critical_force() {
    let spec = CompactionSpec::default();
    assert_eq!((spec.stiffness_ratio, spec.full_strain), (0.0, 0.5), "the seed's rule: plastic until d0* = R");
    let still = class(&concrete(spec, None));
    let fast = class(&concrete(spec, Some(RateSpec::default())));
    let d0 = 2.0 * R;
    // Closing by 1 % of L0 at 1.27 m/s (1.27e-8 m a step) on L0 = 12.7 mm: ε̇ = 100 s⁻¹; the
    // plateau is f'cd/f'cs f_c.
    let path: Vec<f64> = (1..=10_000).map(|s| d0 * (1.0 - 0.01 * s as f64 / 10_000.0)).collect();
    let (fs, _, _) = drive::<Compacting>(&still, &path);
    let (ff, _, diss) = drive::<RatedCompacting>(&fast, &path);
    let ratio = demsweep::kernel::law::rate::compressive_ratio(100.0, psi_to_pa(3000.0), Default::default());
    let (plateau_s, plateau_f) = (-fs.last().unwrap(), -ff.last().unwrap());
    assert!((plateau_s / still.compaction.critical_force_n - 1.0).abs() < 1e-9, "static plateau {plateau_s}");
    assert!((plateau_f / (ratio * still.compaction.critical_force_n) - 1.0).abs() < 1e-3, "dynamic plateau {plateau_f}, ratio {ratio}");
    assert!(diss.compaction_work_j > 0.0 && diss.rate_work_j.is_finite());
}

#[test]
fn a_compacted_bond_that_breaks_touches_at_its_compacted_rest_length() {
    // Compact a bond, pull it apart until it breaks, then push it back: the frictional pair
    // touches again at the compacted rest length, not at r_i + r_j.
    let k = class(&concrete(CompactionSpec { stiffness_ratio: 0.0, full_strain: 0.2 }, None));
    let d0 = 2.0 * R;
    let mut path: Vec<f64> = (1..=10_000).map(|s| d0 * (1.0 - 0.3 * s as f64 / 10_000.0)).collect();
    let low = *path.last().unwrap();
    path.extend((1..=100_000).map(|s| low + 0.6 * d0 * s as f64 / 100_000.0));
    let (_, c, diss) = drive::<Compacting>(&k, &path);
    assert_eq!(c.bond, Bond::Frictional);
    assert_eq!(diss.broken, 1);
    let rest = 0.8 * d0;
    assert!((c.rest_m / rest - 1.0).abs() < 1e-9, "rest {} vs {rest}", c.rest_m);
    // Apart beyond r_i + r_j it becomes a plain new pair (rest r_i + r_j) in the contact loop.
    let mut gone = c;
    law::friction::apart(&mut gone, &k, (1.2 * d0).powi(2), &mut Dissipation::default());
    assert_eq!(gone.rest_m, k.radius_sum_m);
    // Apart but still overlapping (0.9 L0): the rest relaxes to that distance, no force jump.
    let mut near = c;
    law::friction::apart(&mut near, &k, (0.9 * d0).powi(2), &mut Dissipation::default());
    assert!((near.rest_m / (0.9 * d0) - 1.0).abs() < 1e-12);
}

#[test]
fn crushing_a_block_books_compaction_work_and_the_ledger_closes() {
    // A concrete block pressed by a rigid piston at 5 m/s for 1.2 ms (6 mm, 5 % of its height):
    // the bonds under the piston compact and most of the piston's work goes into compaction.
    let mut b = ModelBuilder::new(Plane::Strain, 1.0);
    let m = b.add_material(concrete(CompactionSpec { stiffness_ratio: 0.05, full_strain: 0.3 }, None));
    let block = lattice::close_packed(&Rect { x_min_m: 0.0, x_max_m: 30.0 * R, y_min_m: 0.0, y_max_m: 20.0 * R }, R).unwrap();
    b.add_body("block", &block, Arrangement::ClosePacked, m, &[], [0.0; 3]);
    let top = b.centres().iter().map(|c| c[1]).fold(0.0, f64::max) - 0.5 * R;
    let piston: Vec<usize> = (0..b.centres().len()).filter(|&e| b.centres()[e][1] > top).collect();
    let base: Vec<usize> = (0..b.centres().len()).filter(|&e| b.centres()[e][1] < 1.5 * R).collect();
    b.add_motion(boundary::MotionGroup::all("piston", [0.0, -5.0, 0.0], boundary::Profile::Constant), &piston);
    b.add_motion(boundary::MotionGroup::all("base", [0.0; 3], boundary::Profile::Constant), &base);
    let mut model = b.build().unwrap();
    assert!(model.parts.compaction && !model.parts.rate);
    model.run_steps((1.2e-3 / model.dt_s()).round() as u64).unwrap();
    let l = model.state.ledger;
    let residual = model.energy_residual_j() / l.external_j;
    eprintln!(
        "piston work {:.4e} J: compaction {:.1} %, plastic {:.1} %, fracture {:.1} %, damping {:.1} %, residual {:+.3} %",
        l.external_j,
        100.0 * l.contacts.compaction_work_j / l.external_j,
        100.0 * l.contacts.plastic_work_j / l.external_j,
        100.0 * l.contacts.fracture_energy_j / l.external_j,
        100.0 * l.mass_damping_j / l.external_j,
        100.0 * residual
    );
    assert!(l.contacts.compaction_work_j > 0.5 * l.external_j, "compaction must take most of the work");
    assert!(residual.abs() < 0.005, "residual {residual}");
}
