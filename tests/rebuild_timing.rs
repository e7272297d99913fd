//! Regression: a broken bond's rest length went back to r_i + r_j at the next neighbour
//! rebuild while the pair was apart, so the physics depended on when unrelated elements
//! triggered a rebuild. Now a pair forgets in the contact loop, at the moment it separates, and
//! the candidate list only decides what is checked: the same impact with neighbour skins and
//! look-aheads of very different widths (updates at different steps) gives the same bits.

mod common;

use demsweep::material::CompactionSpec;
use demsweep::material::RateSpec;
use demsweep::kernel::{Model, ModelBuilder};
use demsweep::lattice::{self, Rect};
use demsweep::material::{Arrangement, FailureCriterion, Plane, PoissonPolicy};

/// Steel into an irregular concrete block (bonds with gaps, whose rest lengths exceed
/// r_i + r_j), with rate effects and compaction (rest lengths below it).
fn model(skin_ratio: f64, lookahead_steps: f64) -> Model {
    let r = 0.004;
    let mut b = ModelBuilder::new(Plane::Strain, 0.05);
    let mut concrete = common::plate_concrete(FailureCriterion::StrengthEnergy);
    concrete.poisson_ratio = 0.2;
    concrete.rate = Some(RateSpec::default());
    concrete.compaction = Some(CompactionSpec { stiffness_ratio: 0.02, full_strain: 0.3 });
    let c = b.add_material(concrete);
    let mut steel = common::elastic(200e9, 0.3, 7850.0);
    steel.poisson_policy = PoissonPolicy::ClampToOneThird;
    let s = b.add_material(steel);
    let target = lattice::irregular(&Rect { x_min_m: 0.0, x_max_m: 0.3, y_min_m: 0.0, y_max_m: 0.1 }, r, 3, lattice::IRREGULAR_BOND_GAP).unwrap();
    let projectile = lattice::close_packed(&Rect { x_min_m: 0.13, x_max_m: 0.17, y_min_m: 0.1005, y_max_m: 0.16 }, r).unwrap();
    b.add_body("target", &target, Arrangement::Irregular, c, &[], [0.0; 3]);
    b.add_body("projectile", &projectile, Arrangement::ClosePacked, s, &[], [0.0, -300.0, 0.0]);
    b.skin_ratio = skin_ratio;
    let mut m = b.build().unwrap();
    m.neighbours.lookahead_steps = lookahead_steps;
    m
}

fn bits(m: &Model) -> Vec<u64> {
    m.state.pos.iter().chain(&m.state.vel).flat_map(|p| p.iter().map(|v| v.to_bits())).collect()
}

#[test]
fn a_broken_bonds_rest_length_reset_at_the_next_rebuild() {
    let (mut narrow, mut wide) = (model(0.05, 2.0), model(1.0, 40.0));
    assert_eq!(narrow.dt_s(), wide.dt_s());
    let mut same_steps = 0;
    for _ in 0..30 {
        narrow.run_steps(40).unwrap();
        wide.run_steps(40).unwrap();
        assert!(bits(&narrow) == bits(&wide), "the trajectories part at step {}", narrow.steps());
        same_steps += 40;
    }
    let updates = |m: &Model| m.state.rebuilds + m.state.local_updates;
    let (a, b) = (updates(&narrow), updates(&wide));
    let broken = narrow.state.ledger.bonds_broken();
    let compacted = narrow.state.contacts.list.iter().filter(|c| c.rest_m < narrow.classes[c.class as usize].radius_sum_m * (1.0 - 1e-6)).count();
    eprintln!(
        "{same_steps} steps bitwise equal; neighbour updates {a} vs {b} (full rebuilds {} vs {}); {broken} bonds broken, {compacted} contacts compacted",
        narrow.state.rebuilds, wide.state.rebuilds
    );
    assert!(a > b + b / 5 && b > 3, "the skins must rebuild at different steps: {a} vs {b}");
    assert!(broken > 200 && compacted > 20, "the impact must break and compact bonds");
    assert_eq!(narrow.state.ledger.bonds_broken(), wide.state.ledger.bonds_broken());
}
