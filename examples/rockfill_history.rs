//! What a projectile does in a rockfill, against time: the measurements behind docs/rockfill.md
//! ("Why the projectile stops").
//!
//! cargo run --release --example rockfill_history -- SCENE.toml OUT.csv [--every-us N] [FIELD=VALUE ...]
//!
//! The scene is packed (kept by recipe, `polyhedra::settle::cached`) and the event stepped; every
//! N µs of simulated time (default 20) a row of OUT.csv: the projectile's nose, speed and force,
//! the rocks touching it and those moving, the momentum and energy of rocks and projectile, and
//! the contact losses split by the pair's kinds (rock–rock, rock–projectile, with a wall). At
//! the end a summary on stdout: the momentum balance, the rocks it touched and the contacts'
//! length in steps, and the drag coefficient the speed implies.

use std::collections::{BTreeMap, BTreeSet};
use std::io::Write;
use std::path::Path;

use demsweep::polyhedra::kernel::Model;
use demsweep::scene::overrides::Override;
use demsweep::scene_file::{SceneFile, load};
use nalgebra::Vector3;

fn main() -> demsweep::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (mut every_us, mut rest) = (20.0, Vec::new());
    let mut k = 0;
    while k < args.len() {
        if args[k] == "--every-us" {
            every_us = args[k + 1].parse().expect("--every-us takes a number");
            k += 2;
        } else {
            rest.push(args[k].clone());
            k += 1;
        }
    }
    let [scene, out, sets @ ..] = rest.as_slice() else {
        eprintln!("usage: rockfill_history SCENE.toml OUT.csv [--every-us N] [FIELD=VALUE ...]");
        std::process::exit(2);
    };
    let overrides: Vec<Override> = sets.iter().map(|s| Override::parse(s)).collect::<demsweep::Result<_>>()?;
    let SceneFile::Rockfill(scene) = load(Path::new(scene), &overrides)? else { panic!("{scene}: not a rockfill scene") };
    let built = scene.build()?;
    let mut m: Model = built.model;
    let p = m.group("projectile").expect("a projectile").start;
    let rocks = m.group("target").expect("rocks");
    let kinds = m.kinds;
    let layer = scene.rockfill.layer.size_m;
    let (mp, v0) = (m.state.bodies[p].mass, m.state.bodies[p].velocity);
    let rock_mass: f64 = rocks.clone().map(|k| m.state.bodies[k].mass).sum();
    let momentum0: Vector3<f64> = m.state.bodies.iter().filter(|b| b.mass.is_finite()).map(|b| b.velocity * b.mass).sum();
    let chunk = ((every_us * 1e-6 / m.dt_s).round() as u64).max(1);
    let total = (built.duration_s / m.dt_s).ceil() as u64;
    let shape = m.members[p].shape;
    let nose = |m: &Model| m.shapes[shape].vertices.iter().map(|v| m.state.bodies[p].placed(&m.shapes[shape]).world(v).x).fold(f64::NEG_INFINITY, f64::max);
    let tail = |m: &Model| m.shapes[shape].vertices.iter().map(|v| m.state.bodies[p].placed(&m.shapes[shape]).world(v).x).fold(f64::INFINITY, f64::min);
    let mut csv = std::fs::File::create(out).map_err(|e| demsweep::Error::io(Path::new(out), e))?;
    writeln!(
        csv,
        "t_ms,nose_x_m,speed_mps,vx_mps,force_x_n,force_n,touching,moving_1mps,moving_100mps,mass_moving_100mps_kg,plug_kg,rock_px,projectile_px,momentum_residual,rock_kinetic_j,projectile_kinetic_j,elastic_j,dashpot_rr_j,sliding_rr_j,dashpot_rp_j,sliding_rp_j,dashpot_wall_j,sliding_wall_j,energy_residual_j"
    )
    .unwrap();
    // Contacts with the projectile: when each began (step), and the lengths of those ended.
    let (mut open, mut lengths, mut touched) = (BTreeMap::new(), Vec::new(), BTreeSet::new());
    let mut steps = 0;
    let mut last_touching;
    loop {
        let b = &m.state.bodies;
        let vp = b[p].velocity;
        let f = Vector3::from(m.state.contact_force_n[p]);
        let touching: Vec<usize> = m.state.touches.iter().filter(|t| t.i as usize == p || t.j as usize == p).map(|t| (t.i + t.j) as usize - p).collect();
        last_touching = touching.len();
        let speeds: Vec<(f64, f64, f64)> = rocks.clone().map(|k| (b[k].velocity.norm(), b[k].velocity.x, b[k].mass)).collect();
        let moving_1 = speeds.iter().filter(|s| s.0 > 1.0).count();
        let fast: Vec<_> = speeds.iter().filter(|s| s.0 > 100.0).collect();
        // The plug: rocks moving along the path at least half as fast as the projectile.
        let plug: f64 = speeds.iter().filter(|s| s.1 > 0.5 * vp.x).map(|s| s.2).sum();
        let rock_p: Vector3<f64> = rocks.clone().map(|k| b[k].velocity * b[k].mass).sum();
        let momentum: Vector3<f64> = b.iter().filter(|x| x.mass.is_finite()).map(|x| x.velocity * x.mass).sum();
        let rock_ke: f64 = rocks.clone().map(|k| b[k].kinetic_energy()).sum();
        let l = &m.state.ledger;
        let rr = m.state.dissipated_between(kinds, Some((0, 0)));
        let rp = m.state.dissipated_between(kinds, Some((0, 1)));
        let wall = m.state.dissipated_between(kinds, None);
        let residual = l.kinetic_j + l.elastic_j - (l.initial_j + l.external_j - l.damping_j - l.friction_j - l.viscous_j);
        writeln!(
            csv,
            "{:.6},{:.5},{:.3},{:.3},{:.6e},{:.6e},{},{},{},{:.3},{:.3},{:.6e},{:.6e},{:.3e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.3e}",
            m.time_s() * 1e3,
            nose(&m),
            vp.norm(),
            vp.x,
            f.x,
            f.norm(),
            touching.len(),
            moving_1,
            fast.len(),
            fast.iter().map(|s| s.2).sum::<f64>(),
            plug,
            rock_p.x,
            vp.x * mp,
            (momentum - momentum0).norm() / (momentum0.norm()),
            rock_ke,
            b[p].kinetic_energy(),
            l.elastic_j,
            rr[0],
            rr[1],
            rp[0],
            rp[1],
            wall[0],
            wall[1],
            residual
        )
        .unwrap();
        if steps >= total {
            break;
        }
        for _ in 0..chunk {
            m.run_steps(1)?;
            steps += 1;
            let now: BTreeSet<usize> = m.state.touches.iter().filter(|t| t.i as usize == p || t.j as usize == p).map(|t| (t.i + t.j) as usize - p).collect();
            for &r in &now {
                open.entry(r).or_insert(steps);
                touched.insert(r);
            }
            let ended: Vec<usize> = open.keys().copied().filter(|r| !now.contains(r)).collect();
            for r in ended {
                lengths.push(steps - open.remove(&r).unwrap());
            }
        }
    }
    let b = &m.state.bodies;
    let (v, x) = (b[p].velocity, nose(&m));
    let momentum: Vector3<f64> = b.iter().filter(|x| x.mass.is_finite()).map(|x| x.velocity * x.mass).sum();
    lengths.sort_unstable();
    let quantile = |q: f64| lengths.get(((lengths.len() as f64 - 1.0) * q).round() as usize).copied().unwrap_or(0);
    let touched_mass: f64 = touched.iter().map(|&k| b[k].mass).sum();
    let touched_px: f64 = touched.iter().map(|&k| b[k].velocity.x * b[k].mass).sum();
    let rock_px: f64 = rocks.clone().map(|k| b[k].velocity.x * b[k].mass).sum();
    // The bulk density and the path: the rocks' mass over the packed layer's volume (its height
    // the lid's at the end of the packing, kept in memory), the calibre's area.
    let top = scene.pack()?.top_m;
    let bulk = rock_mass / (layer[0] * layer[1] * top);
    let calibre = scene.rockfill.projectile.calibre_m;
    let area = std::f64::consts::PI * calibre * calibre / 4.0;
    let travelled = x.min(layer[0]).max(1e-9);
    // m dv/dx = −C ρ A v²: v = v0 exp(−C ρ A x / m).
    let c = (v0.norm() / v.norm()).ln() * mp / (bulk * area * travelled);
    let l = &m.state.ledger;
    println!("{}: {} rocks ({rock_mass:.0} kg, bulk {bulk:.0} kg/m³), projectile {mp} kg at {:.0} m/s; dt {:.3e} s", scene.rockfill.name, rocks.len(), v0.norm(), m.dt_s);
    println!(
        "at {:.3} ms: speed {:.1} m/s, vx {:.1} m/s, nose at {x:.3} m, tail at {:.3} m (layer {:.2} m), {last_touching} rocks touching",
        m.time_s() * 1e3,
        v.norm(),
        v.x,
        tail(&m),
        layer[0]
    );
    println!(
        "momentum: projectile lost {:.1} kg·m/s along x, rocks gained {rock_px:.1} (those it touched {touched_px:.1}); total drift {:.2e} of the start",
        mp * (v0.x - v.x),
        (momentum - momentum0).norm() / momentum0.norm()
    );
    println!(
        "rocks it touched: {} ({touched_mass:.0} kg); contacts with it: {} ended, length in steps min {} median {} 90 % {} max {}",
        touched.len(),
        lengths.len(),
        quantile(0.0),
        quantile(0.5),
        quantile(0.9),
        quantile(1.0)
    );
    println!(
        "path mass rho A L = {:.1} kg over {travelled:.3} m; drag coefficient implied C = ln(v0/v) m/(rho A x) = {c:.3}",
        bulk * area * travelled
    );
    // What a momentum balance over the whole thickness says: m dv/dx = −C ρ A v², v = v0 e^(−C ρ A L/m).
    let q = &scene.rockfill.projectile;
    let column = bulk * area * layer[0];
    let through = |c: f64| v0.norm() * (-c * column / mp).exp();
    let psi = q.ogive_radius_m / q.calibre_m;
    let nose = (8.0 * psi - 1.0) / (24.0 * psi * psi);
    let e_b = scene.rockfill.projectile_law.restitution;
    println!(
        "through {:.2} m (path mass {column:.1} kg): the column taken to the projectile's speed (C = 1) {:.0} m/s, bounced off it (C = 1 + e_b = {:.1}) {:.0} m/s, \
         flowing round the ogive (Forrestal's nose factor N* = (8 psi - 1)/(24 psi^2) = {nose:.4}, psi = {psi:.2}) {:.0} m/s; an exit at 1100 m/s wants C = {:.4}, a pushed mass C rho A L = {:.1} kg",
        layer[0],
        through(1.0),
        1.0 + e_b,
        through(1.0 + e_b),
        through(nose),
        (v0.norm() / 1100.0).ln() * mp / column,
        (v0.norm() / 1100.0).ln() * mp
    );
    let split = |name: &str, d: [f64; 2]| println!("  {name}: dashpot {:.3} MJ, sliding {:.3} MJ", d[0] * 1e-6, d[1] * 1e-6);
    println!("losses (ledger: dashpot {:.3} MJ, sliding {:.3} MJ):", l.damping_j * 1e-6, l.friction_j * 1e-6);
    split("rock-rock", m.state.dissipated_between(kinds, Some((0, 0))));
    split("rock-projectile", m.state.dissipated_between(kinds, Some((0, 1))));
    split("with a wall", m.state.dissipated_between(kinds, None));
    Ok(())
}
