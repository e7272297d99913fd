//! The outcome definitions of `demsweep::outcome` on hand-built states: a model of a small beam
//! and projectile is built, then moved and cut by hand into the situation each definition is
//! about, and the detector's reading is compared with what the definition says it must be.

use demsweep::penetration::scene::{Layout, OutcomeSpec, PenetrationScene};
use demsweep::kernel::Model;
use demsweep::kernel::contact::Bond;
use demsweep::penetration::outcome::{Detector, Look, Tracking};
use demsweep::units::M_PER_IN;

/// A 24 in × 6 in beam at level 0 (R = 0.5 in), the seed's projectile 1 in above it.
fn small() -> (Model, Detector, Layout) {
    let mut s = PenetrationScene::with_name("outcomes");
    s.penetration.level = 0;
    // The definitions are about states built by hand in rows of the regular lattice.
    s.target.arrangement = demsweep::material::Arrangement::ClosePacked;
    s.target.length_in = 24.0;
    s.target.depth_in = 6.0;
    s.projectile.standoff_in = 1.0;
    let (scene, layout) = s.to_scene().unwrap();
    let built = scene.build().unwrap();
    let det = Detector::new(&built.model, layout.clone(), s.outcome.clone()).unwrap();
    (built.model, det, layout)
}

fn range(m: &Model, name: &str) -> std::ops::Range<usize> {
    m.body(name).unwrap().elements.clone()
}

/// Break every bond with exactly one end in `inside`.
fn cut(m: &mut Model, inside: &dyn Fn(usize) -> bool) -> usize {
    let mut n = 0;
    for c in m.state.contacts.list.iter_mut() {
        if c.bond == Bond::Intact && inside(c.i as usize) != inside(c.j as usize) {
            c.bond = Bond::Frictional;
            n += 1;
        }
    }
    n
}

fn shift_projectile(m: &mut Model, dy_m: f64, vy_mps: f64) {
    for e in range(m, "projectile") {
        m.state.pos[e][1] += dy_m;
        m.state.vel[e] = [0.0, vy_mps, 0.0];
    }
}

#[test]
fn at_rest_nothing_has_happened() {
    let (m, det, lay) = small();
    let l = det.look(&m);
    assert!((l.depth_m + 1.0 * M_PER_IN).abs() < 1e-9, "the tip starts 1 in above the face: {}", l.depth_m / M_PER_IN);
    assert_eq!((l.scab.0, l.spall.0), (0, 0));
    assert!(!l.through);
    assert!(l.deflection_m.abs() < 1e-15);
    // The front face is the top of the top row: within a row spacing (√3 R) below the 6 in.
    let gap = 6.0 * M_PER_IN - lay.front_y_m;
    assert!(gap >= 0.0 && gap < 3f64.sqrt() * 0.5 * M_PER_IN, "front face {} in", lay.front_y_m / M_PER_IN);
}

#[test]
fn a_fragment_flying_off_the_back_is_a_scab_with_its_mass() {
    let (mut m, det, lay) = small();
    let target = range(&m, "target");
    // A lump of back-face material under the impact point, 2.5 in deep and 6 in wide.
    let lump = |e: usize| {
        target.contains(&e) && m.el.initial[e][1] < 2.5 * M_PER_IN && (m.el.initial[e][0] - lay.impact_x_m).abs() < 3.0 * M_PER_IN
    };
    let members: Vec<usize> = target.clone().filter(|&e| lump(e)).collect();
    let mass: f64 = members.iter().map(|&e| m.el.mass[e]).sum();
    assert!(members.len() > 10);
    let lump_set: std::collections::HashSet<usize> = members.iter().copied().collect();
    assert!(cut(&mut m, &|e| lump_set.contains(&e)) > 0);
    // Detached but still: not (yet) a scab.
    assert_eq!(det.look(&m).scab.0, 0, "a detached piece at rest is not a scab");
    // Moving away from the back face at 2 ft/s: below the 3 ft/s separation.
    for &e in &members {
        m.state.vel[e][1] = -2.0 * 0.3048;
    }
    assert_eq!(det.look(&m).scab.0, 0, "2 ft/s is below the separation speed");
    for &e in &members {
        m.state.vel[e][1] = -10.0;
        m.state.pos[e][1] -= 3.0 * M_PER_IN;
    }
    let l = det.look(&m);
    assert_eq!(l.scab.0, 1, "one scab fragment");
    assert!((l.scab.1 - mass).abs() <= 1e-12 * mass, "scab mass {} kg, lump {} kg", l.scab.1, mass);
    assert_eq!(l.spall.0, 0);
    // On the slice the crater is the back face's width the lump took: the lump's elements
    // within 3 in of the impact point, 6 in (less than an element's spread at either end).
    let crater_in = l.back_crater_m / M_PER_IN;
    assert!((crater_in - 6.0).abs() <= 1.0, "crater {crater_in} in across a 6 in lump");
    assert!(l.scabs, "6 in is over the 3.5 in calibre");
    // In its place and moving up into the beam, it is not scabbing (past the back face it
    // would be, whatever its speed: it has left the target).
    for &e in &members {
        m.state.vel[e][1] = 10.0;
        m.state.pos[e][1] += 3.0 * M_PER_IN;
    }
    assert_eq!(det.look(&m).scab.0, 0);
}

#[test]
fn single_detached_elements_count_as_fragments_and_front_face_spall_is_apart() {
    let (mut m, det, lay) = small();
    let target = range(&m, "target");
    // Two front-face elements near the impact point, knocked loose and flying up (spall).
    let front: Vec<usize> = target
        .clone()
        .filter(|&e| m.el.initial[e][1] + m.el.radius[e] > lay.front_y_m - 1e-9 && (m.el.initial[e][0] - lay.impact_x_m).abs() < 3.0 * M_PER_IN)
        .take(2)
        .collect();
    assert_eq!(front.len(), 2);
    let set: std::collections::HashSet<usize> = front.iter().copied().collect();
    cut(&mut m, &|e| set.contains(&e));
    // Break the bond between the two too: two single-element fragments.
    for c in m.state.contacts.list.iter_mut() {
        if set.contains(&(c.i as usize)) && set.contains(&(c.j as usize)) {
            c.bond = Bond::Frictional;
        }
    }
    for &e in &front {
        m.state.vel[e][1] = 20.0;
    }
    let l = det.look(&m);
    assert_eq!(l.spall.0, 2);
    let mass: f64 = front.iter().map(|&e| m.el.mass[e]).sum();
    assert!((l.spall.1 - mass).abs() <= 1e-12 * mass);
    assert_eq!(l.scab.0, 0, "front-face material is never scab");
}

#[test]
fn a_projectile_half_way_through_has_its_depth_and_is_not_through() {
    let (mut m, det, lay) = small();
    let depth = lay.front_y_m - lay.back_y_m;
    // Tip from 1 in above the face to half the depth below it.
    shift_projectile(&mut m, -(1.0 * M_PER_IN + 0.5 * depth), 100.0 * -0.3048);
    let l = det.look(&m);
    assert!((l.depth_m - 0.5 * depth).abs() < 1e-9, "depth {} in", l.depth_m / M_PER_IN);
    assert!(!l.through && !l.clear);
    assert!(l.v_axial_mps > 0.0, "going in");
}

#[test]
fn a_bent_but_intact_beam_has_no_fragments_and_the_relative_depth_takes_off_the_deflection() {
    let (mut m, det, lay) = small();
    let target = range(&m, "target");
    let length = 24.0 * M_PER_IN;
    let w0 = 0.8 * M_PER_IN;
    // Bend the free part of the beam (the supports stay) and let it swing down fast.
    for e in target.clone() {
        if !m.el.is_fully_prescribed(e) {
            let x = m.el.initial[e][0];
            let w = w0 * (std::f64::consts::PI * x / length).sin();
            m.state.pos[e][1] -= w;
            m.state.vel[e][1] = -30.0 * w / w0;
        }
    }
    // The projectile's tip 0.5 in into the bent beam.
    shift_projectile(&mut m, -(1.0 * M_PER_IN + w0 + 0.5 * M_PER_IN), 0.0);
    let l = det.look(&m);
    assert_eq!((l.scab.0, l.spall.0), (0, 0), "an intact beam sheds nothing however fast it swings");
    assert!((l.depth_m - (w0 + 0.5 * M_PER_IN)).abs() < 1e-9);
    // The deflection is read on the back face within half a width of the impact point.
    let half = 0.5 * lay.projectile_width_m;
    let lo = w0 * (std::f64::consts::PI * (0.5 * length + half) / length).sin();
    assert!(l.deflection_m <= w0 + 1e-12 && l.deflection_m >= lo - 1e-12, "deflection {} in", l.deflection_m / M_PER_IN);
    let rel = l.depth_m - l.deflection_m;
    assert!((rel - 0.5 * M_PER_IN).abs() < (w0 - lo) + 1e-12, "relative depth {} in", rel / M_PER_IN);
}

#[test]
fn a_projectile_wholly_past_the_back_face_is_through_and_then_clear() {
    let (mut m, det, lay) = small();
    let (lo, hi) = range(&m, "projectile").fold((f64::INFINITY, f64::NEG_INFINITY), |a, e| {
        (a.0.min(m.state.pos[e][1] - m.el.radius[e]), a.1.max(m.state.pos[e][1] + m.el.radius[e]))
    });
    let length = hi - lo;
    // Rear 0.1 in below the back face: through, not yet clear.
    shift_projectile(&mut m, -(lo - lay.back_y_m) - length - 0.1 * M_PER_IN, -50.0);
    let l = det.look(&m);
    assert!(l.through && !l.clear);
    // Two element diameters further: clear.
    shift_projectile(&mut m, -2.0 * 2.0 * lay.concrete_radius_m, -50.0);
    let l = det.look(&m);
    assert!(l.through && l.clear);
    assert!((l.speed_mps - 50.0).abs() < 1e-9);
}

#[test]
fn a_projectile_in_a_deflected_beam_is_not_through_until_past_the_material_under_it() {
    let (mut m, det, lay) = small();
    let target = range(&m, "target");
    // The beam sags 3 in as a whole (not the supports): the back face under the projectile is
    // then 3 in below y = 0.
    for e in target.clone() {
        if !m.el.is_fully_prescribed(e) {
            m.state.pos[e][1] -= 3.0 * M_PER_IN;
        }
    }
    let (lo, hi) = range(&m, "projectile").fold((f64::INFINITY, f64::NEG_INFINITY), |a, e| {
        (a.0.min(m.state.pos[e][1] - m.el.radius[e]), a.1.max(m.state.pos[e][1] + m.el.radius[e]))
    });
    shift_projectile(&mut m, -(lo - lay.back_y_m) - (hi - lo) - 0.1 * M_PER_IN, -50.0);
    assert!(!det.look(&m).through, "past y = 0 but still above attached material");
}

fn look(t: f64, v: f64, attached_bonds: u64) -> Look {
    Look {
        time_s: t,
        depth_m: 0.1,
        deflection_m: 0.0,
        scab: (0, 0.0),
        back_crater_m: 0.0,
        scabs: false,
        spall: (0, 0.0),
        through: false,
        clear: false,
        v_axial_mps: v,
        v_face_mps: v,
        speed_mps: v.abs(),
        attached_bonds,
    }
}

#[test]
fn a_rebounding_projectile_settles_once_the_target_is_quiet() {
    let spec = OutcomeSpec::default();
    let mut t = Tracking::default();
    assert_eq!(t.observe(&look(1e-4, 100.0, 10), &spec, 150.0), None, "going in");
    assert_eq!(t.observe(&look(5e-4, -5.0, 20), &spec, 150.0), None, "turned, but bonds broke just now");
    assert_eq!(t.observe(&look(5e-4 + 0.99 * spec.quiet_s, -5.0, 20), &spec, 150.0), None);
    assert_eq!(t.observe(&look(5e-4 + 1.01 * spec.quiet_s, -5.0, 20), &spec, 150.0), Some("rebounded"));
}

#[test]
fn regression_a_slow_late_fracture_is_not_cut_off() {
    // The projectile stops early; cracks keep running slowly, one bond every 0.8 quiet periods
    // for 10 periods. The run must not settle until the last of them is a quiet period old.
    let spec = OutcomeSpec::default();
    let mut t = Tracking::default();
    let q = spec.quiet_s;
    let mut bonds = 100;
    let mut time = 0.0;
    let mut settled = None;
    while settled.is_none() && time < 20.0 * q {
        time += 0.05 * q;
        if time < 10.0 * q && ((time / (0.8 * q)).fract() < 0.05 / 0.8) {
            bonds -= 1;
        }
        settled = t.observe(&look(time, 0.0, bonds), &spec, 150.0).map(|s| (s, time));
    }
    let (why, when) = settled.expect("settles eventually");
    assert_eq!(why, "embedded");
    assert!(when >= t.last_break_s + q && t.last_break_s > 9.0 * q, "settled at {when} s, last break {} s", t.last_break_s);
}

/// A projectile going on into the target at a steady speed, with the target breaking around it
/// (a beam broken into a mechanism carries it along): nothing pushes on it, so the target cannot
/// stop it. It is perforated (and scabbed) from the start of the steady stretch, with that speed
/// as its residual, `unresisted_s` later, not at the time cap.
#[test]
fn a_projectile_the_target_no_longer_resists_goes_through() {
    let spec = OutcomeSpec::default();
    let (v0, q) = (300.0, spec.unresisted_s);
    let mut t = Tracking::default();
    let mut bonds = 1000;
    let (mut time, mut depth) = (0.0, 0.0);
    let mut settled = None;
    // Slowing hard (10 % of its speed per unresisted_s) until 5 q, then steady at 15 m/s
    // (5 % of v0) with a bond breaking every look; its nose goes in with it.
    while settled.is_none() && time < 40.0 * q {
        time += 0.05 * q;
        let v = if time < 5.0 * q { 15.0 * 1.1f64.powf(5.0 - time / q) } else { 15.0 };
        depth += v * 0.05 * q;
        bonds -= 1;
        let l = Look { depth_m: depth, ..look(time, v, bonds) };
        settled = t.observe(&l, &spec, v0).map(|s| (s, time));
    }
    let (why, when) = settled.expect("settles before 40 quiet periods");
    assert_eq!(why, "unresisted");
    let start = t.perforation_time_s.expect("perforated");
    // Within 2 % of 15 m/s from 1.1^x ≤ 1.02, x ≤ 0.21 q before 5 q.
    assert!(start >= 4.75 * q && start <= 5.0 * q, "the steady stretch began at {start} s");
    assert!(when >= start + q - 1e-12 && when < start + 1.1 * q, "settled at {when} s, {start} s after the stretch began");
    assert_eq!(t.scab_time_s, Some(start), "a perforation is a scab too");
    let r = t.v_residual_mps;
    assert!(r >= 15.0 && r <= 15.0 * (1.0 + spec.unresisted_change), "residual {r} m/s, the stretch's first speed");
}

/// A projectile in free flight over its crater after a glancing rebound, its centre drifting in
/// at a steady 2 % of the impact speed while it turns, its nose going no deeper (packing 5 of
/// the 3D slab at 100 ft/s, docs/penetration3d.md): nothing resists it, but nothing has given
/// way either; it is not perforated, and it settles when it turns back out.
#[test]
fn a_projectile_drifting_without_its_nose_going_in_is_not_taken_for_unresisted() {
    let spec = OutcomeSpec::default();
    let (v0, q) = (30.0, spec.unresisted_s);
    let mut t = Tracking::default();
    let (mut time, mut settled) = (0.0, None);
    while settled.is_none() && time < 40.0 * q {
        time += 0.05 * q;
        let v = if time < 10.0 * q { 0.61 } else { -0.3 };
        // The nose stays 0.6 in deep, wobbling by a hundredth of an inch as the body turns.
        let l = Look { depth_m: 0.015 + 2.5e-4 * (time / q).sin(), speed_mps: 1.02, ..look(time, v, 1000) };
        settled = t.observe(&l, &spec, v0).map(|s| (s, time));
    }
    let (why, when) = settled.expect("settles once it turns back");
    assert_eq!(why, "rebounded");
    assert!(when > 10.0 * q, "settled at {when} s, before it turned back");
    assert_eq!(t.perforation_time_s, None);
}

/// Slowing by more than `unresisted_change` of its speed per `unresisted_s` is resistance: the
/// run goes on (here to the embedded rule once it has stopped), nothing is perforated.
#[test]
fn a_projectile_still_slowing_is_not_taken_for_unresisted() {
    let spec = OutcomeSpec::default();
    let (v0, q) = (300.0, spec.unresisted_s);
    let rate = 2.0 * spec.unresisted_change;
    let mut t = Tracking::default();
    let mut time = 0.0;
    let mut settled = None;
    while settled.is_none() && time < 400.0 * q {
        time += 0.05 * q;
        let v = (30.0 * (-rate * time / q).exp() - 0.5).max(0.0);
        settled = t.observe(&look(time, v, 1000), &spec, v0).map(|s| (s, time));
    }
    assert_eq!(settled.map(|s| s.0), Some("embedded"));
    assert_eq!(t.perforation_time_s, None);
}

#[test]
fn perforation_records_the_residual_speed_when_first_through_and_settles_when_clear() {
    let spec = OutcomeSpec::default();
    let mut t = Tracking::default();
    let mut l = look(1e-3, 80.0, 500);
    l.through = true;
    assert_eq!(t.observe(&l, &spec, 150.0), None);
    assert_eq!(t.perforation_time_s, Some(1e-3));
    assert_eq!(t.v_residual_mps, 80.0);
    let mut later = look(1e-3 + 2.0 * spec.quiet_s, 70.0, 500);
    later.through = true;
    assert_eq!(t.observe(&later, &spec, 150.0), None, "through but not clear yet");
    later.clear = true;
    assert_eq!(t.observe(&later, &spec, 150.0), None, "clear just now");
    // Debris keeps breaking bonds in the attached target: perforation settles anyway, a quiet
    // period after the exit.
    later.time_s += 0.99 * spec.quiet_s;
    later.attached_bonds -= 1;
    assert_eq!(t.observe(&later, &spec, 150.0), None);
    later.time_s += 0.02 * spec.quiet_s;
    later.attached_bonds -= 1;
    assert_eq!(t.observe(&later, &spec, 150.0), Some("perforated"));
    assert_eq!(t.v_residual_mps, 80.0, "the residual speed is the one at first exit");
}

/// A beam split in two under the projectile (the V of a hinged beam): both halves still
/// supported, nothing detached, the projectile wholly past the back face between them. The back
/// face has been holed, so the run is scabbed as well as perforated: scabbing can never come
/// after perforation in a sweep.
#[test]
fn a_perforation_through_a_split_beam_with_nothing_detached_is_a_scab_too() {
    let (mut m, mut det, lay) = small();
    let target = range(&m, "target");
    let x0 = lay.impact_x_m;
    // Cut the beam along x = impact point and open a gap wider than the projectile.
    let left = |e: usize| m.el.initial[e][0] < x0;
    let tset: Vec<bool> = (0..m.el.radius.len()).map(|e| target.contains(&e) && left(e)).collect();
    assert!(cut(&mut m, &|e| tset[e]) > 0);
    let half = 0.5 * lay.projectile_width_m + 2.0 * lay.concrete_radius_m;
    for e in target.clone() {
        if m.el.is_fully_prescribed(e) {
            continue;
        }
        let d = m.el.initial[e][0] - x0;
        if d.abs() < half {
            // Push the elements near the cut sideways out of the projectile's path.
            m.state.pos[e][0] = x0 + d.signum() * (half + d.abs());
        }
    }
    let (lo, hi) = range(&m, "projectile").fold((f64::INFINITY, f64::NEG_INFINITY), |a, e| {
        (a.0.min(m.state.pos[e][1] - m.el.radius[e]), a.1.max(m.state.pos[e][1] + m.el.radius[e]))
    });
    shift_projectile(&mut m, -(lo - lay.back_y_m) - (hi - lo) - 0.1 * M_PER_IN, -50.0);
    let l = det.look(&m);
    assert!(l.through, "the projectile is past the back face");
    assert_eq!(l.scab.0, 0, "nothing came loose");
    let o = det.outcome(&m);
    assert!(o.perforated && o.scabbed, "perforated {} scabbed {}", o.perforated, o.scabbed);
    assert_eq!(o.scab_time_s, o.perforation_time_s, "holed when first through");
    // And through the stop rule's record: the first look through books both.
    use demsweep::run::StopRule;
    det.check(&m);
    assert!(det.tracking.scab_time_s.is_some() && det.tracking.scab_time_s == det.tracking.perforation_time_s);
}

/// Material pushed out of the back face ahead of the projectile, detached but moving no faster
/// than the face (a plug carried at the projectile's speed when the face itself follows): it has
/// left the target through the back face, so it is scab.
#[test]
fn a_detached_piece_past_the_back_face_is_a_scab_whatever_its_speed() {
    let (mut m, det, lay) = small();
    let target = range(&m, "target");
    let plug = |e: usize| target.contains(&e) && m.el.initial[e][1] < 2.0 * M_PER_IN && (m.el.initial[e][0] - lay.impact_x_m).abs() < 2.0 * M_PER_IN;
    let members: Vec<usize> = target.clone().filter(|&e| plug(e)).collect();
    assert!(members.len() > 3);
    let set: std::collections::HashSet<usize> = members.iter().copied().collect();
    assert!(cut(&mut m, &|e| set.contains(&e)) > 0);
    // Moved 3 in down, at rest: no separation speed, but its centre is past the back face.
    for &e in &members {
        m.state.pos[e][1] -= 3.0 * M_PER_IN;
    }
    let l = det.look(&m);
    assert_eq!(l.scab.0, 1, "one plug, past the back face");
    let mass: f64 = members.iter().map(|&e| m.el.mass[e]).sum();
    assert!((l.scab.1 / mass - 1.0).abs() < 1e-12);
    // Put back in place (detached, at rest): not a scab.
    for &e in &members {
        m.state.pos[e][1] += 3.0 * M_PER_IN;
    }
    assert_eq!(det.look(&m).scab.0, 0);
}
