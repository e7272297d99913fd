//! A rockfill settled and compacted (seed §4.1): the rocks dropped under gravity into a box of
//! held walls, a top wall (the lid) then brought down onto them until the solid fills the asked
//! fraction of the box below it, or the lid's push reaches a cap; the rocks then left to come to
//! rest, and unloaded (gravity off, the lid lifted) so that no packing overlap is left. Eq 6's viscous damping takes the motion out (a packing wants the state, not the path).

use std::time::Instant;

use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use serde::{Deserialize, Serialize};

use super::body::Body;
use super::container::{as_given, walls};
use super::kernel::{Model, ModelBuilder};
use super::law::Law;
use super::rockfill::{Grading, Rocks, rocks};
use super::rotation::Spin;
use super::shape::Polyhedron;
use crate::error::{Error, Result};

/// How to pack.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Packing {
    /// Rock density, kg/m³.
    pub density: f64,
    /// The law between rocks, and rocks and walls, while packing (a softer one settles in fewer steps).
    pub law: Law,
    /// Viscous damping rate of eq 6, 1/s.
    pub damping_per_s: f64,
    /// Packing fraction to compact to: rock volume over the box's volume below the lid.
    pub fraction: f64,
    /// Speed of the lid coming down, m/s.
    pub lid_speed_mps: f64,
    /// Mean pressure of the lid at which compaction stops short of the fraction, Pa.
    pub lid_pressure_pa: f64,
    /// Simulated time allowed for each of the drop, the compaction, the rest and the unloading, s.
    pub phase_s: f64,
}

/// A packed rockfill.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(into = "Kept", from = "Kept")]
pub struct Packed {
    /// The rocks' shapes (body frame).
    pub shapes: Vec<Polyhedron>,
    /// The rocks at rest, in the box's frame.
    pub bodies: Vec<Body>,
    /// Height of the lid's inner face at the end, m.
    pub top_m: f64,
    /// The packing fraction reached (rock volume over the box below the lid).
    pub fraction: f64,
    /// Whether the lid's pressure cap stopped the compaction first.
    pub pressure_capped: bool,
    /// Steps taken, all phases.
    pub steps: u64,
    /// Wall time, s.
    pub wall_s: f64,
    /// Kinetic energy left at the end, J.
    pub kinetic_j: f64,
    /// Elastic energy in the packing law's springs under gravity and the lid, J.
    pub loaded_j: f64,
    /// Elastic energy left in them once unloaded, J.
    pub elastic_j: f64,
}

/// The rocks of `rocks` packed in the box `lo`–`hi` (m) as `p` says.
pub fn pack(rocks: &Rocks, lo: &Vector3<f64>, hi: &Vector3<f64>, p: &Packing) -> Result<Packed> {
    let started = Instant::now();
    let mut b = ModelBuilder::new(1, vec![p.law])?;
    b.gravity = Vector3::new(0.0, 0.0, -9.81);
    b.damping_per_s = p.damping_per_s;
    for shape in &rocks.shapes {
        let body = as_given(shape, p.density);
        let s = b.shape(shape.clone());
        b.body(s, 0, body);
    }
    let n = b.len();
    let lid = walls(&mut b, 0, lo, hi, hi.z, 0.0);
    let dt = 0.25 * b.dt_bound_s();
    let mut m = b.build(dt)?;
    let solid: f64 = rocks.shapes.iter().map(|s| s.volume).sum();
    let area = (hi.x - lo.x) * (hi.y - lo.y);
    let lid_face = |m: &Model| m.state.bodies[lid].position.z - lid_half(m, lid);
    let chunk = ((0.005 / dt).ceil() as u64).max(1);
    let phase = ((p.phase_s / dt).ceil() as u64).max(1);
    let weight: f64 = m.state.bodies[..n].iter().map(|b| b.mass * 9.81).sum();
    // Still: kinetic energy under a millionth of the pile's weight times the box height.
    let still = |m: &Model| m.state.ledger.kinetic_j < 1e-6 * weight * (hi.z - lo.z);
    run_until(&mut m, chunk, phase, still)?;
    // The lid down to just above the highest rock, then driven down.
    let highest = (0..n).map(|k| m.state.bodies[k].position.z + m.shapes[m.members[k].shape].radius()).fold(lo.z, f64::max);
    let half = lid_half(&m, lid);
    m.state.bodies[lid].position.z = highest.min(hi.z) + half;
    m.state.bodies[lid].velocity.z = -p.lid_speed_mps;
    let cap = p.lid_pressure_pa * area;
    let mut pressure_capped = false;
    let reached = |m: &Model| solid / (area * (lid_face(m) - lo.z));
    let mut taken = 0;
    while reached(&m) < p.fraction && taken < phase {
        m.run_steps(chunk)?;
        taken += chunk;
        if m.state.contact_force_n[lid][2] > cap {
            pressure_capped = true;
            break;
        }
    }
    m.state.bodies[lid].velocity.z = 0.0;
    run_until(&mut m, chunk, phase, still)?;
    let fraction = reached(&m);
    let top_m = lid_face(&m);
    // Unloaded: gravity off and the lid lifted, the rocks let go of the overlaps their weight
    // and the lid pressed into the soft packing law. Left in, those overlaps would be springs
    // of the event's far stiffer law, and their energy (MJ in the full layer) would burst it.
    m.gravity = Vector3::zeros();
    m.state.bodies[lid].position.z += 0.1 * (hi.z - lo.z);
    let loaded_j = m.state.ledger.elastic_j;
    run_until(&mut m, chunk, phase, |m: &Model| m.state.ledger.elastic_j < 1e-3 * loaded_j && still(m))?;
    if !fraction.is_finite() {
        return Err(Error::input("rockfill.fraction", "the packing came apart"));
    }
    let mut bodies: Vec<Body> = m.state.bodies[..n].to_vec();
    for body in &mut bodies {
        body.velocity = Vector3::zeros();
        body.spin.momentum = Vector3::zeros();
    }
    Ok(Packed {
        shapes: rocks.shapes.clone(),
        bodies,
        top_m,
        fraction,
        pressure_capped,
        steps: m.state.steps,
        wall_s: started.elapsed().as_secs_f64(),
        kinetic_j: m.state.ledger.kinetic_j,
        loaded_j,
        elastic_j: m.state.ledger.elastic_j,
    })
}

/// Packed rockfills, from the code that cuts and packs them: kept by `crate::keep` under a
/// recipe that names the box, the grading and the packing ([`cached`]).
pub const KIND: crate::keep::Kind = crate::keep::Kind {
    name: "demsweep rockfill 1",
    sources: || {
        &[
            include_str!("settle.rs"),
            include_str!("rockfill.rs"),
            include_str!("voronoi.rs"),
            include_str!("clip.rs"),
            include_str!("container.rs"),
            include_str!("shape.rs"),
            include_str!("hull.rs"),
            include_str!("mass.rs"),
            include_str!("body.rs"),
            include_str!("rotation.rs"),
            include_str!("law.rs"),
            include_str!("pair.rs"),
            include_str!("patch.rs"),
            include_str!("detect.rs"),
            include_str!("gjk.rs"),
            include_str!("epa.rs"),
            include_str!("simplex.rs"),
            include_str!("support.rs"),
            include_str!("kernel/mod.rs"),
            include_str!("kernel/broad.rs"),
            include_str!("kernel/build.rs"),
            include_str!("kernel/state.rs"),
            include_str!("kernel/step.rs"),
            include_str!("../lattice.rs"),
        ]
    },
};

/// The rocks of `grading` cut from the box `lo`–`hi` and packed as `p` says, built once per
/// recipe and kept (`crate::keep`: in memory for the process, on disk for the machine).
pub fn cached(grading: &Grading, lo: &Vector3<f64>, hi: &Vector3<f64>, p: &Packing) -> Result<Packed> {
    crate::keep::cached(&KIND, &recipe(grading, lo, hi, p), || pack(&rocks(grading, lo, hi)?, lo, hi, p))
}

/// The recipe of a packed rockfill: every input, f64s by their `Debug` (which round-trips).
pub fn recipe(grading: &Grading, lo: &Vector3<f64>, hi: &Vector3<f64>, p: &Packing) -> String {
    format!("rockfill\nbox {:?} {:?}\n{grading:?}\n{p:?}", lo.as_slice(), hi.as_slice())
}

/// A packed rockfill as kept: vectors as arrays, quaternions as [w, i, j, k].
#[derive(Serialize, Deserialize)]
struct Kept {
    shapes: Vec<KeptShape>,
    bodies: Vec<KeptBody>,
    top_m: f64,
    fraction: f64,
    pressure_capped: bool,
    steps: u64,
    wall_s: f64,
    kinetic_j: f64,
    loaded_j: f64,
    elastic_j: f64,
}

#[derive(Serialize, Deserialize)]
struct KeptShape {
    vertices: Vec<[f64; 3]>,
    faces: Vec<Vec<usize>>,
    normals: Vec<[f64; 3]>,
    edges: Vec<(usize, usize)>,
    volume: f64,
    principal: [f64; 3],
    rest_position: [f64; 3],
    rest_orientation: [f64; 4],
}

#[derive(Serialize, Deserialize)]
struct KeptBody {
    mass: f64,
    inertia: [f64; 3],
    position: [f64; 3],
    velocity: [f64; 3],
    orientation: [f64; 4],
    momentum: [f64; 3],
}

fn quaternion(q: &UnitQuaternion<f64>) -> [f64; 4] {
    [q.w, q.i, q.j, q.k]
}

fn unit([w, i, j, k]: [f64; 4]) -> UnitQuaternion<f64> {
    UnitQuaternion::new_unchecked(Quaternion::new(w, i, j, k))
}

fn arrays(v: &[Vector3<f64>]) -> Vec<[f64; 3]> {
    v.iter().map(|x| (*x).into()).collect()
}

fn vectors(v: Vec<[f64; 3]>) -> Vec<Vector3<f64>> {
    v.into_iter().map(Vector3::from).collect()
}

impl From<Packed> for Kept {
    fn from(p: Packed) -> Self {
        let shapes = p
            .shapes
            .into_iter()
            .map(|s| KeptShape {
                vertices: arrays(&s.vertices),
                faces: s.faces,
                normals: arrays(&s.normals),
                edges: s.edges,
                volume: s.volume,
                principal: s.principal.into(),
                rest_position: s.rest_position.into(),
                rest_orientation: quaternion(&s.rest_orientation),
            })
            .collect();
        let bodies = p
            .bodies
            .iter()
            .map(|b| KeptBody {
                mass: b.mass,
                inertia: b.inertia.into(),
                position: b.position.into(),
                velocity: b.velocity.into(),
                orientation: quaternion(&b.spin.orientation),
                momentum: b.spin.momentum.into(),
            })
            .collect();
        let Packed { top_m, fraction, pressure_capped, steps, wall_s, kinetic_j, loaded_j, elastic_j, .. } = p;
        Kept { shapes, bodies, top_m, fraction, pressure_capped, steps, wall_s, kinetic_j, loaded_j, elastic_j }
    }
}

impl From<Kept> for Packed {
    fn from(k: Kept) -> Self {
        let shapes = k
            .shapes
            .into_iter()
            .map(|s| Polyhedron {
                vertices: vectors(s.vertices),
                faces: s.faces,
                normals: vectors(s.normals),
                edges: s.edges,
                volume: s.volume,
                principal: s.principal.into(),
                rest_position: s.rest_position.into(),
                rest_orientation: unit(s.rest_orientation),
            })
            .collect();
        let bodies = k
            .bodies
            .into_iter()
            .map(|b| Body {
                mass: b.mass,
                inertia: b.inertia.into(),
                position: b.position.into(),
                velocity: b.velocity.into(),
                spin: Spin { orientation: unit(b.orientation), momentum: b.momentum.into() },
            })
            .collect();
        let Kept { top_m, fraction, pressure_capped, steps, wall_s, kinetic_j, loaded_j, elastic_j, .. } = k;
        Packed { shapes, bodies, top_m, fraction, pressure_capped, steps, wall_s, kinetic_j, loaded_j, elastic_j }
    }
}

/// Half the lid's thickness, m.
fn lid_half(m: &Model, lid: usize) -> f64 {
    let s = &m.shapes[m.members[lid].shape];
    let z = m.state.bodies[lid].spin.orientation;
    s.vertices.iter().map(|v| z.transform_vector(v).z).fold(0.0, f64::max)
}

/// Steps `m` in chunks of `chunk` until `done` or `most` steps.
fn run_until(m: &mut Model, chunk: u64, most: u64, done: impl Fn(&Model) -> bool) -> Result<()> {
    let mut taken = 0;
    while taken < most {
        m.run_steps(chunk)?;
        taken += chunk;
        if done(m) {
            break;
        }
    }
    Ok(())
}
