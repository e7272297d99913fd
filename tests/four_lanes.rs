//! The four-bond path (`kernel::bonds4`) against the scalar bond law: the same bits, group by
//! group and over whole runs where bonds yield, break and fragments slide.

mod common;

use demsweep::kernel::contacts::Contact;
use demsweep::kernel::law::{self, Dissipation, Extra, With};
use demsweep::kernel::{Threading, bonds4, forces};

/// No optional part. The lanes serve it and friction on (friction changes only frictional
/// contacts, so a bond's law is this one either way).
type Plain = With<false, false, false, false>;

#[test]
fn four_elastic_bonds_at_once_are_four_scalar_calls_bit_for_bit() {
    if !bonds4::available() {
        eprintln!("this processor has no AVX: the four-lane path is never taken");
        return;
    }
    let m = common::impact::model();
    let list: Vec<Contact> = m.state.contacts.list.clone();
    let k0 = &m.classes[list[0].class as usize];
    // Stretch the block in x by a strain that grows from 0 to 1.5 times the one at which a bond
    // along x reaches its tensile plateau, so that some groups stay elastic and some do not;
    // shear it and spin it a little so that every term of the law is exercised.
    let x_max = m.state.pos.iter().map(|p| p[0]).fold(0.0, f64::max);
    let plateau_strain = k0.strength.normal_force_n / (k0.bond.kn_n_per_m * list[0].rest_m);
    assert!(plateau_strain > 0.0 && plateau_strain < 0.01, "the first class must have a finite plateau: strain {plateau_strain}");
    let pos: Vec<[f64; 3]> = m.state.pos.iter().map(|p| {
        let e = 1.5 * plateau_strain * p[0] / x_max;
        [p[0] * (1.0 + e), p[1] + 0.1 * plateau_strain * p[0], p[2]]
    }).collect();
    let vel: Vec<[f64; 3]> = (0..pos.len()).map(|e| {
        let s = (e as f64 * 0.7548776662).fract() - 0.5;
        [s, 0.5 * s, 20.0 * s]
    }).collect();
    let dt_s = m.dt_s();
    let (mut taken, mut refused) = (0, 0);
    for g in list.chunks_exact(bonds4::LANES) {
        let cs: [Contact; bonds4::LANES] = g.try_into().unwrap();
        if !bonds4::eligible(&cs) {
            continue;
        }
        let k = &m.classes[cs[0].class as usize];
        // SAFETY: the processor has AVX (checked above).
        let got = unsafe { bonds4::elastic(&pos, &vel, &cs, k, dt_s) };
        let mut d = Dissipation::default();
        let scalar: Vec<_> = cs.iter().map(|c| {
            let mut c = *c;
            let g = forces::kinematics(&pos, &vel, &c, k).unwrap();
            let f = law::bonded::<Plain>(&mut c, &mut Extra::new(0.0), k, &g, dt_s, &mut d);
            (f, c)
        }).collect();
        let elastic = d.plastic_work_j == 0.0 && d.broken == 0 && scalar.iter().zip(&cs).all(|((_, c), c0)| c.dp_m == c0.dp_m);
        match got {
            Some(group) => {
                assert!(elastic, "the four-lane path took a group the scalar law did not keep elastic: {cs:?}");
                for (l, (f, c)) in scalar.iter().enumerate() {
                    let lane = &group.force[l];
                    assert_eq!(
                        [lane.fx, lane.fy, lane.ti, lane.tj, group.ut_m[l]].map(f64::to_bits),
                        [f.fx, f.fy, f.ti, f.tj, c.ut_m].map(f64::to_bits),
                        "lane {l} of {cs:?}"
                    );
                }
                taken += 1;
            }
            None => {
                assert!(!elastic, "the four-lane path refused a group the scalar law kept elastic: {cs:?}");
                refused += 1;
            }
        }
    }
    eprintln!("{taken} groups taken, {refused} refused");
    assert!(taken > 100 && refused > 100, "both outcomes must occur: {taken} taken, {refused} refused");
}

/// Bits of the small impact after `steps` steps, with or without the four-lane path, on one
/// thread (the scatter) or on a pool of two (per-contact forces, then the gather).
fn impact_bits(four_lanes: bool, threads: usize, steps: u64) -> (Vec<u64>, u64, f64) {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| {
        let mut m = common::impact::model();
        m.four_lanes = four_lanes;
        if threads == 1 {
            m.threading = Threading::Serial;
        }
        m.run_steps(steps).unwrap();
        (common::impact::state_bits(&m), m.state.ledger.bonds_broken(), m.state.ledger.contacts.plastic_work_j)
    })
}

#[test]
fn a_run_with_four_bonds_at_once_is_bitwise_the_run_one_at_a_time() {
    let steps = 1500;
    let (scalar, broken, plastic_j) = impact_bits(false, 1, steps);
    assert!(broken > 100 && plastic_j > 0.0, "bonds must yield and break: {broken} broken, {plastic_j} J plastic work");
    for threads in [1, 2] {
        assert!(impact_bits(true, threads, steps).0 == scalar, "four lanes on {threads} thread(s) differ from one bond at a time");
    }
    assert!(impact_bits(false, 2, steps).0 == scalar, "the pool one bond at a time differs from one thread");
}
