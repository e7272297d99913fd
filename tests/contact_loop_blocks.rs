//! The one-at-a-time contact loop (`kernel::forces`), which with the rate or the damping part
//! takes the contacts in blocks — each contact's geometry and rate ratios first, then the rest
//! of each law —, against each contact's law called in turn: the same forces, histories, extra
//! slots and dissipation, bit for bit, mid-impact, on the penetration scene's parts (friction,
//! rate, compaction) and on the small impact's with dashpots (friction, damping).

mod common;

use std::path::Path;

use demsweep::kernel::contact::{Bond, Contact, ContactForce};
use demsweep::kernel::forces::{self, CHUNK, Out, Stage};
use demsweep::kernel::law::rate_field::RateField;
use demsweep::kernel::law::{self, Dissipation, Extra, PartSet, PartsVisitor};
use demsweep::kernel::{Model, Threading};
use demsweep::scene_file::{SceneFile, load};

/// What a pass over the contact list leaves: the contacts, their extra slots, their forces and
/// each chunk's dissipation.
type Outcome = (Vec<Contact>, Vec<Extra>, Vec<ContactForce>, Vec<Dissipation>);

/// The CI scene at 1 500 ft/s, `steps` steps in: the projectile in the target, bonds broken,
/// fragments touching, sliding and flying apart.
fn mid_impact(steps: u64) -> Model {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("sweeps/penetration_ci.toml");
    let SceneFile::Penetration(mut scene) = load(&path, &[]).unwrap() else { panic!("the CI scene is a penetration scene") };
    scene.projectile.v0_fps = 1500.0;
    let mut m = scene.to_scene().unwrap().0.build().unwrap().model;
    m.threading = Threading::Serial;
    m.run_steps(steps).unwrap();
    m
}

/// The contact stage as the kernel runs it (no four-lane path: these parts do not take it),
/// and each contact's law in turn.
struct Both<'a>(&'a Model);

impl PartsVisitor for Both<'_> {
    type Output = (Outcome, Outcome);

    fn visit<P: PartSet>(self) -> (Outcome, Outcome) {
        let m = self.0;
        let (pos, vel, dt_s) = (&m.state.pos, &m.state.vel, m.dt_s());
        let n = m.state.contacts.list.len();
        let (mut list, mut extra) = (m.state.contacts.list.clone(), m.state.contacts.extra.clone());
        let mut force = vec![ContactForce::default(); n];
        let mut partial = vec![Dissipation::default(); n.div_ceil(CHUNK)];
        let stage = Stage {
            pos,
            vel,
            list: &mut list,
            extra: &mut extra,
            force: &mut force,
            classes: &m.classes,
            dt_s,
            partial: &mut partial,
            out: Out::Stored,
            record: true,
            four_lanes: false,
            lane_width: demsweep::kernel::lanes::widest(),
            rate_vel: &m.rate_field.vel_mps,
        };
        stage.visit::<P>();

        let (mut r_list, mut r_extra) = (m.state.contacts.list.clone(), m.state.contacts.extra.clone());
        let mut r_force = vec![ContactForce::default(); n];
        let mut r_partial = vec![Dissipation::default(); n.div_ceil(CHUNK)];
        let mut scratch = Extra::new(0.0);
        for (e, c) in r_list.iter_mut().enumerate() {
            // A scratch slot where the parts keep none (it is never read then).
            let x = if r_extra.is_empty() { &mut scratch } else { &mut r_extra[e] };
            let k = &m.classes[c.class as usize];
            let d = &mut r_partial[e / CHUNK];
            r_force[e] = match forces::kinematics(pos, vel, c, k) {
                Ok(g) if c.bond == Bond::Intact => {
                    let vn = RateField::normal_velocity_mps(&m.rate_field.vel_mps, c.i, c.j, [g.nx, g.ny], g.vn_mps);
                    let ratios = law::bond_ratios::<P>(x, k, vn);
                    law::bonded_at::<P>(c, x, k, &g, ratios, dt_s, d)
                }
                Ok(g) => law::friction::touching::<P>(c, k, &g, dt_s, d),
                Err(d2_m2) => {
                    law::friction::apart(c, k, d2_m2, d);
                    ContactForce::default()
                }
            };
        }
        ((list, extra, force, partial), (r_list, r_extra, r_force, r_partial))
    }
}

fn contact_bits(c: &Contact) -> (u32, u32, Bond, [u64; 3]) {
    (c.i, c.j, c.bond, [c.rest_m, c.ut_m, c.dp_m].map(f64::to_bits))
}

fn extra_bits(x: &Extra) -> [u64; 5] {
    [x.length0_m, x.rate_per_s, x.rate_mean_per_s, x.modulus_ratio, x.vn_last_mps].map(f64::to_bits)
}

fn force_bits(f: &ContactForce) -> [u64; 4] {
    [f.fx, f.fy, f.ti, f.tj].map(f64::to_bits)
}

fn dissipation_bits(d: &Dissipation) -> (Vec<u64>, u64) {
    (d.terms().iter().map(|t| t.1.to_bits()).collect(), d.broken)
}

/// Branches taken in one pass: bonds, bonds that break, frictional pairs touching, frictional
/// pairs that changed (a spring released, a rest length relaxed, a slide), bonds with a rate.
fn branches(before: &[Contact], after: &[Contact], force: &[ContactForce], extra: &[Extra]) -> [usize; 5] {
    let both = || before.iter().zip(after);
    [
        before.iter().filter(|c| c.bond == Bond::Intact).count(),
        both().filter(|(a, b)| a.bond == Bond::Intact && b.bond == Bond::Frictional).count(),
        before.iter().zip(force).filter(|(c, f)| c.bond == Bond::Frictional && (f.fx != 0.0 || f.fy != 0.0)).count(),
        both().filter(|(a, b)| a.bond == Bond::Frictional && (a.ut_m != b.ut_m || a.rest_m != b.rest_m)).count(),
        extra.iter().filter(|x| x.rate_per_s > 0.0).count(),
    ]
}

/// `steps` steps of `m`, each contact stage compared with each contact's law in turn; the
/// branches seen over them.
fn compare_over(m: &mut Model, steps: usize) -> [usize; 5] {
    let mut seen = [0; 5];
    for step in 0..steps {
        let ((list, extra, force, partial), (r_list, r_extra, r_force, r_partial)) = m.parts.dispatch(Both(m));
        for e in 0..list.len() {
            assert_eq!(contact_bits(&list[e]), contact_bits(&r_list[e]), "step {step}: contact {e}");
            if !extra.is_empty() {
                assert_eq!(extra_bits(&extra[e]), extra_bits(&r_extra[e]), "step {step}: extra slot {e}");
            }
            assert_eq!(force_bits(&force[e]), force_bits(&r_force[e]), "step {step}: force of contact {e}");
        }
        for (c, (a, b)) in partial.iter().zip(&r_partial).enumerate() {
            assert_eq!(dissipation_bits(a), dissipation_bits(b), "step {step}: dissipation of chunk {c}");
        }
        for (s, b) in seen.iter_mut().zip(branches(&m.state.contacts.list, &list, &force, &extra)) {
            *s += b;
        }
        m.step().unwrap();
    }
    seen
}

#[test]
fn the_contact_loop_in_blocks_is_each_contact_in_turn_bit_for_bit() {
    let mut m = mid_impact(400);
    assert!(m.parts.rate && m.parts.compaction && m.parts.friction, "the penetration scene's parts: {:?}", m.parts);
    assert!(m.state.contacts.list.len() > 2 * CHUNK, "several chunks");
    // Every branch taken: bonds that hold and bonds that break, frictional pairs that touch and
    // pairs apart that still had a shear spring or a rest length to forget.
    let seen @ [bonds, broke, touching, changed, rated] = compare_over(&mut m, 40);
    eprintln!("40 steps: {bonds} bond-steps ({broke} breaking), {touching} frictional pairs touching, {changed} frictional pairs changed, {rated} with a rate");
    assert!(bonds > 40_000 && broke > 5 && touching > 1000 && changed > 1000 && rated > 40_000, "not every branch is exercised: {seen:?}");
}

#[test]
fn with_dashpots_the_contact_loop_in_blocks_is_each_contact_in_turn_bit_for_bit() {
    // The dashpots at 2 % of critical at a fifth of the top frequency (as `energy_ledger`'s test).
    let beta = 2.0 * 0.02 / (0.2 * common::impact::model().step_info.omega_bound_rad_per_s);
    let mut m = common::impact::damped(0.0, beta);
    assert!(m.parts.damping && m.parts.friction && !m.parts.rate, "the small impact's parts with dashpots: {:?}", m.parts);
    m.threading = Threading::Serial;
    m.run_steps(600).unwrap();
    let seen @ [bonds, broke, touching, changed, _] = compare_over(&mut m, 400);
    eprintln!("400 steps: {bonds} bond-steps ({broke} breaking), {touching} frictional pairs touching, {changed} frictional pairs changed");
    assert!(bonds > 50_000 && broke > 5 && touching > 100 && changed > 100, "not every branch is exercised: {seen:?}");
}
