//! Bitwise determinism (rapier's thread_count_determinism): a scene where bonds break gives
//! the same bits for 1, 2 and 8 threads, and from run to run.

mod common;

use demsweep::kernel::{Model, ModelBuilder};
use demsweep::lattice::{self, Rect};
use demsweep::material::{Arrangement, FailureCriterion, Plane, PoissonPolicy};

fn impact() -> Model {
    let r = 0.004;
    let mut b = ModelBuilder::new(Plane::Strain, 0.05);
    let mut concrete = common::plate_concrete(FailureCriterion::StrengthEnergy);
    concrete.poisson_ratio = 0.2;
    let c = b.add_material(concrete);
    let mut steel = common::elastic(200e9, 0.3, 7850.0);
    steel.poisson_policy = PoissonPolicy::ClampToOneThird;
    let s = b.add_material(steel);
    let target = lattice::close_packed(&Rect { x_min_m: 0.0, x_max_m: 0.4, y_min_m: 0.0, y_max_m: 0.12 }, r).unwrap();
    let projectile = lattice::close_packed(&Rect { x_min_m: 0.18, x_max_m: 0.22, y_min_m: 0.1205, y_max_m: 0.2 }, r).unwrap();
    // Irregular inclusion region of the target exercises a second material kind's classes.
    b.add_body("target", &target, Arrangement::ClosePacked, c, &[], [0.0; 3]);
    b.add_body("projectile", &projectile, Arrangement::ClosePacked, s, &[], [0.0, -250.0, 0.0]);
    let mut m = b.build().unwrap();
    m.parallel_min_contacts = 0;
    m
}

fn fingerprint(threads: usize, steps: u64) -> (Vec<u64>, u64, usize) {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| {
        let mut m = impact();
        m.run_steps(steps).unwrap();
        let mut bits = Vec::new();
        for e in 0..m.el.len() {
            bits.extend(m.el.pos[e].iter().chain(&m.el.vel[e]).chain(&m.el.force[e]).map(|v| v.to_bits()));
        }
        for c in &m.contacts.list {
            bits.extend([c.i as u64, c.j as u64, c.bond as u64, c.d0.to_bits(), c.ut.to_bits(), c.dp.to_bits()]);
        }
        let l = m.ledger;
        bits.extend([l.external_j, l.plastic_j, l.fracture_j, l.friction_j, l.mass_damping_j].map(f64::to_bits));
        (bits, l.bonds_broken, m.contacts.len())
    })
}

#[test]
fn bitwise_identical_for_1_2_and_8_threads_with_breaking_bonds() {
    let steps = 1500;
    let (one, broken, contacts) = fingerprint(1, steps);
    eprintln!("{broken} bonds broken, {contacts} contacts after {steps} steps");
    assert!(broken > 100, "the scene must break bonds, broke {broken}");
    for threads in [2, 8] {
        let (other, b, _) = fingerprint(threads, steps);
        assert_eq!(b, broken);
        assert!(one == other, "{threads} threads differ from 1 thread");
    }
    let (again, _, _) = fingerprint(2, steps);
    assert!(again == fingerprint(2, steps).0, "run-to-run difference");
}
