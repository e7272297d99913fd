//! The groups of four (`kernel::groups`) against the scalar laws: the same bits, group by group
//! on every lane type the processor runs (the portable lanes everywhere), and over whole runs
//! where bonds yield, break and fragments slide.

mod common;

use demsweep::kernel::contact::{Bond, Contact, ContactForce};
use demsweep::kernel::lanes::{self, Lanes, Task, Width};
use demsweep::kernel::law::{self, ContactClass, Dissipation, Extra, With};
use demsweep::kernel::{Threading, forces, geometry, groups};

/// Four bonds through `groups::bonds` on some lanes.
struct Bonds<'a> {
    pos: &'a [[f64; 3]],
    vel: &'a [[f64; 3]],
    cs: &'a [Contact; groups::LANES],
    k: &'a ContactClass,
    dt_s: f64,
}

impl Task for Bonds<'_> {
    type Output = Option<groups::Group>;
    #[inline(always)]
    fn run<L: Lanes>(self) -> Self::Output {
        groups::bonds(&geometry::of_four::<L>(self.pos, self.cs), self.vel, self.cs, self.k, self.dt_s)
    }
}

/// Four contacts through `groups::mixed` (parts [`Friction`]) on some lanes.
struct Mixed<'a> {
    pos: &'a [[f64; 3]],
    vel: &'a [[f64; 3]],
    cs: &'a mut [Contact; groups::LANES],
    k: &'a ContactClass,
    dt_s: f64,
    d: &'a mut Dissipation,
}

impl Task for Mixed<'_> {
    type Output = Option<[ContactForce; groups::LANES]>;
    #[inline(always)]
    fn run<L: Lanes>(self) -> Self::Output {
        groups::mixed::<L, Friction>(&geometry::of_four::<L>(self.pos, self.cs), self.vel, self.cs, self.k, self.dt_s, self.d)
    }
}

/// No optional part. The lanes serve it and friction on (friction changes only frictional
/// contacts, so a bond's law is this one either way).
type Plain = With<false, false, false, false>;

#[test]
fn four_elastic_bonds_at_once_are_four_scalar_calls_bit_for_bit() {
    for w in lanes::widths() {
        four_elastic_bonds(w);
    }
}

fn four_elastic_bonds(width: Width) {
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
    for g in list.chunks_exact(groups::LANES) {
        let cs: [Contact; groups::LANES] = g.try_into().unwrap();
        if !groups::eligible(&cs) {
            continue;
        }
        let k = &m.classes[cs[0].class as usize];
        let got = lanes::run_as(width, Bonds { pos: &pos, vel: &vel, cs: &cs, k, dt_s });
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
                        "lane {l} of {cs:?} ({width:?})"
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
    eprintln!("{width:?}: {taken} groups taken, {refused} refused");
    assert!(taken > 100 && refused > 100, "both outcomes must occur: {taken} taken, {refused} refused");
}

/// Bits of the small impact after `steps` steps, with the four-lane paths on lanes `width` or
/// without them (None), on one thread (the scatter) or on a pool of two (the scatter in pieces,
/// `kernel::pieces`).
fn impact_bits(width: Option<Width>, threads: usize, steps: u64) -> (Vec<u64>, u64, f64) {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| {
        let mut m = common::impact::model();
        m.four_lanes = width.is_some();
        m.lane_width = width.unwrap_or(Width::Portable);
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
    let (scalar, broken, plastic_j) = impact_bits(None, 1, steps);
    assert!(broken > 100 && plastic_j > 0.0, "bonds must yield and break: {broken} broken, {plastic_j} J plastic work");
    for w in lanes::widths() {
        for threads in [1, 2] {
            assert!(impact_bits(Some(w), threads, steps).0 == scalar, "four {w:?} lanes on {threads} thread(s) differ from one bond at a time");
        }
    }
    assert!(impact_bits(None, 2, steps).0 == scalar, "the pool one bond at a time differs from one thread");
}

/// Friction on, no other optional part: the parts of the small impact, whose cracked target
/// mixes bonds and frictional pairs in every group.
type Friction = With<true, false, false, false>;

/// One contact through the scalar law, as the contact loop takes it.
fn scalar_one(pos: &[[f64; 3]], vel: &[[f64; 3]], c: &mut Contact, k: &law::ContactClass, dt_s: f64, d: &mut Dissipation) -> ContactForce {
    match forces::kinematics(pos, vel, c, k) {
        Ok(g) if c.bond == Bond::Intact => law::bonded::<Friction>(c, &mut Extra::new(0.0), k, &g, dt_s, d),
        Ok(g) => law::friction::touching::<Friction>(c, k, &g, dt_s, d),
        Err(d2_m2) => {
            law::friction::apart(c, k, d2_m2, d);
            Default::default()
        }
    }
}

#[test]
fn four_mixed_contacts_at_once_are_four_scalar_calls_bit_for_bit() {
    for w in lanes::widths() {
        four_mixed_contacts(w);
    }
}

fn four_mixed_contacts(width: Width) {
    let mut m = common::impact::model();
    assert_eq!(m.parts, law::Parts { friction: true, ..Default::default() });
    // Mid-impact: the target cracked, bonds and frictional pairs mixed along the list.
    m.four_lanes = false;
    m.run_steps(1500).unwrap();
    // Then every branch of both laws exercised: the block strained in x from −3 to 1.5 times a
    // bond's plateau strain (cracks closed; some groups refused), fast random velocities (pairs that
    // touch slide), and the frictional pairs given shear springs, overlaps and rest lengths off
    // r_i + r_j (pairs that touch stick or slide, pairs that are apart forget).
    let k0 = &m.classes[0];
    let plateau_strain = k0.strength.normal_force_n / (k0.bond.kn_n_per_m * m.state.contacts.list[0].rest_m);
    let x_max = m.state.pos.iter().map(|p| p[0]).fold(0.0, f64::max);
    let pos: Vec<[f64; 3]> = m.state.pos.iter().map(|p| [p[0] * (1.0 + plateau_strain * (4.5 * p[0] / x_max - 3.0)), p[1], p[2]]).collect();
    let wobble = |e: usize| (e as f64 * 0.7548776662).fract() - 0.5;
    let vel: Vec<[f64; 3]> = m.state.vel.iter().enumerate().map(|(e, v)| [v[0] + 50.0 * wobble(e), v[1] - 30.0 * wobble(e + 7), v[2] + 4e3 * wobble(e + 3)]).collect();
    for (n, c) in m.state.contacts.list.iter_mut().enumerate().filter(|(_, c)| c.bond == Bond::Frictional) {
        let (a, b) = (pos[c.i as usize], pos[c.j as usize]);
        let d_m = (b[0] - a[0]).hypot(b[1] - a[1]);
        match n % 4 {
            0 => c.ut_m = 1e-7 * wobble(n),
            1 => (c.rest_m, c.ut_m) = (d_m * (1.0 + 1e-3 * wobble(n).abs()), 1e-8 * wobble(n + 1)),
            2 => c.rest_m = c.rest_m.min(d_m) * (1.0 - 0.02 * wobble(n).abs()),
            _ => {}
        }
    }
    let Groups { taken, refused, mixed, sliding, forgetting, .. } = groups_against_scalar(&m, &pos, &vel, width);
    eprintln!("{width:?}: {taken} groups taken ({mixed} of bonds and frictional pairs; {sliding} sliding and {forgetting} forgetting pairs), {refused} refused");
    assert!(taken > 100 && mixed > 20 && sliding > 5 && forgetting > 5, "every kind must occur: {taken} taken, {mixed} mixed, {sliding} sliding, {forgetting} forgetting");
    // The frictional pairs with nothing to forget and the target stretched by 1.5 %: groups of
    // four pairs apart with nothing to forget, which the lanes take without their laws, beside
    // groups of pairs apart, stretched bonds (refused) and mixed ones: the same bits.
    for c in m.state.contacts.list.iter_mut().filter(|c| c.bond == Bond::Frictional) {
        (c.ut_m, c.rest_m) = (0.0, m.classes[c.class as usize].radius_sum_m);
    }
    let stretched: Vec<[f64; 3]> = m.state.pos.iter().map(|p| [1.015 * p[0], 1.015 * p[1], p[2]]).collect();
    let Groups { taken, refused, nothing, .. } = groups_against_scalar(&m, &stretched, &m.state.vel, width);
    eprintln!("stretched: {taken} groups taken, {nothing} of them four pairs apart with nothing to forget, {refused} refused");
    assert!(nothing > 10 && taken > nothing, "{nothing} groups of four pairs apart with nothing to forget, of {taken}");
}

/// What [`groups_against_scalar`] met.
#[derive(Default)]
struct Groups {
    taken: usize,
    refused: usize,
    mixed: usize,
    sliding: usize,
    forgetting: usize,
    nothing: usize,
}

/// Every group of one class of `m`'s list through the mixed lanes at `pos`, `vel`, against
/// four scalar calls (forces, history and the friction booked, bit for bit; a refused group
/// changes nothing), counting the kinds met.
fn groups_against_scalar(m: &demsweep::kernel::Model, pos: &[[f64; 3]], vel: &[[f64; 3]], width: Width) -> Groups {
    let dt_s = m.dt_s();
    let mut n = Groups::default();
    let Groups { taken, refused, mixed, sliding, forgetting, nothing } = &mut n;
    for g in m.state.contacts.list.chunks_exact(groups::LANES) {
        let cs: [Contact; groups::LANES] = g.try_into().unwrap();
        if !groups::one_class(&cs) {
            continue;
        }
        let k = &m.classes[cs[0].class as usize];
        // The ledger is not at zero: the lanes add to a running sum as the loop does.
        let d0 = Dissipation { friction_j: 0.125, ..Default::default() };
        let (mut lane_cs, mut d_lanes) = (cs, d0);
        let got = lanes::run_as(width, Mixed { pos, vel, cs: &mut lane_cs, k, dt_s, d: &mut d_lanes });
        let (mut scalar, mut d) = (cs, d0);
        let mut lane_w = [0.0; groups::LANES];
        let forces: Vec<_> = scalar.iter_mut().enumerate().map(|(l, c)| {
            let before = d.friction_j;
            let f = scalar_one(pos, vel, c, k, dt_s, &mut d);
            lane_w[l] = d.friction_j - before;
            f
        }).collect();
        let elastic = d.plastic_work_j == 0.0 && d.broken == 0 && scalar.iter().zip(&cs).all(|(c, c0)| c.dp_m == c0.dp_m);
        match got {
            Some(f) => {
                assert!(elastic, "the mixed lanes took a group whose bonds the scalar law did not keep elastic: {cs:?}");
                for l in 0..groups::LANES {
                    let (a, b) = (&f[l], &forces[l]);
                    assert_eq!([a.fx, a.fy, a.ti, a.tj].map(f64::to_bits), [b.fx, b.fy, b.ti, b.tj].map(f64::to_bits), "force, lane {l} of {cs:?}");
                }
                assert_eq!(lane_cs, scalar, "history of {cs:?}");
                assert_eq!(lane_cs.map(|c| [c.ut_m.to_bits(), c.rest_m.to_bits()]), scalar.map(|c| [c.ut_m.to_bits(), c.rest_m.to_bits()]));
                assert_eq!(d_lanes.friction_j.to_bits(), d.friction_j.to_bits(), "friction booked for {cs:?}");
                let kinds = cs.iter().filter(|c| c.bond == Bond::Intact).count();
                *mixed += (kinds > 0 && kinds < groups::LANES) as usize;
                let mut idle = 0;
                for (l, c) in cs.iter().enumerate() {
                    let apart = forces::kinematics(pos, vel, c, k).is_err();
                    *sliding += (!apart && lane_w[l] != 0.0) as usize;
                    *forgetting += (apart && (c.ut_m != 0.0 || c.rest_m != k.radius_sum_m)) as usize;
                    idle += (apart && c.ut_m == 0.0 && c.rest_m == k.radius_sum_m) as usize;
                }
                *nothing += (idle == groups::LANES) as usize;
                *taken += 1;
            }
            None => {
                assert!(!elastic, "the mixed lanes refused a group whose bonds the scalar law kept elastic: {cs:?}");
                assert_eq!((lane_cs, d_lanes.friction_j.to_bits()), (cs, d0.friction_j.to_bits()), "a refused group must change nothing");
                *refused += 1;
            }
        }
    }
    n
}
