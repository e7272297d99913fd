//! The rockfill scene built: the rocks cut and packed (eqs 26–29), then the event's model —
//! the rocks as packed, no walls and no gravity (over the event's few milliseconds gravity
//! moves a rock by about 0.1 mm), and the projectile, nose first along +x, its nose
//! `standoff_m` before the centre of the face x = 0.

use std::sync::Arc;

use nalgebra::{UnitQuaternion, Vector3};

use super::super::body::Body;
use super::super::kernel::{Model, ModelBuilder};
use super::super::law::Law;
use super::super::rockfill::rocks;
use super::super::rockfill::Grading;
use super::super::settle::{Packed, Packing, cached, pack};
use super::RockfillScene;
use super::probe::{Probe, Quantity};
use crate::error::Result;
use crate::simulation::{Built, Measure};

/// Kinds of body: rock 0, projectile 1.
const KINDS: usize = 2;

impl RockfillScene {
    /// The packed layer: cut from a box as tall as the layer times the asked fraction over the
    /// cells' fraction q̄³, so that compacted it stands about the layer's height. Built once per
    /// recipe and kept (`settle::cached`).
    pub fn pack(&self) -> Result<Packed> {
        let (grading, lo, hi, packing) = self.packing_recipe()?;
        cached(&grading, &lo, &hi, &packing)
    }

    /// The packed layer built afresh, not kept.
    pub fn pack_afresh(&self) -> Result<Packed> {
        let (grading, lo, hi, packing) = self.packing_recipe()?;
        pack(&rocks(&grading, &lo, &hi)?, &lo, &hi, &packing)
    }

    /// What the layer is packed from: its grading, the box it is cut from, the packing.
    pub fn packing_recipe(&self) -> Result<(Grading, Vector3<f64>, Vector3<f64>, Packing)> {
        self.validate()?;
        let r = &self.rockfill;
        let [l, w, h] = r.layer.size_m;
        let tall = h * (r.packing.fraction / r.layer.grade.powi(3)).max(1.0);
        let (lo, hi) = (Vector3::zeros(), Vector3::new(l, w, tall));
        let p = &r.packing;
        let law = Law { stiffness: p.stiffness_n_per_m, exponent: 1.0, shear_stiffness: 0.5 * p.stiffness_n_per_m, friction: r.rock_law.friction, restitution: r.rock_law.restitution };
        let packing = Packing { density: r.layer.density_kg_per_m3, law, damping_per_s: p.damping_per_s, fraction: p.fraction, lid_speed_mps: p.lid_speed_mps, lid_pressure_pa: p.lid_pressure_pa, phase_s: p.phase_s };
        Ok((self.grading(), lo, hi, packing))
    }

    /// The event's model on a packed layer, and what the run records.
    pub fn build_on(&self, packed: &Packed) -> Result<Built<Model>> {
        let r = &self.rockfill;
        let (rock, hit) = (r.rock_law.law(), r.projectile_law.law());
        let mut b = ModelBuilder::new(KINDS, vec![rock, hit, hit, hit])?;
        for (shape, body) in packed.shapes.iter().zip(&packed.bodies) {
            let s = b.shape(shape.clone());
            b.body(s, 0, *body);
        }
        b.group("target", 0);
        let q = &r.projectile;
        let shape = q.ogive().polyhedron();
        // The outline's tip is at its frame's origin, the base at +length: turned half round z,
        // the nose leads along +x.
        let orientation = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::PI) * shape.rest_orientation;
        let tip_from_centroid = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::PI).transform_vector(&-shape.rest_position);
        let aim = Vector3::new(-q.standoff_m, 0.5 * r.layer.size_m[1], 0.5 * packed.top_m);
        let density = q.mass_kg / shape.volume;
        let mut body = Body::new(&shape, density, aim - tip_from_centroid, orientation);
        body.velocity = Vector3::new(q.speed_mps, 0.0, 0.0);
        let s = b.shape(shape);
        let start = b.len();
        let projectile = b.body(s, 1, body);
        b.group("projectile", start);
        let dt = r.dt_fraction * b.dt_bound_s();
        let model = b.build(dt)?;
        let far = r.layer.size_m[0];
        let probes: Vec<Arc<dyn Measure<Model>>> = [
            Quantity::Speed,
            Quantity::AlongPath,
            Quantity::Resistance,
            Quantity::Deflection,
            Quantity::Yaw,
            Quantity::NoseX,
            Quantity::ExitTime,
        ]
        .into_iter()
        .map(|quantity| Arc::new(Probe { quantity, body: projectile, far_face_m: far }) as Arc<dyn Measure<Model>>)
        .collect();
        Ok(Built { name: r.name.clone(), model, probes, duration_s: r.duration_s, every_steps: r.every_steps })
    }

    /// Packs the layer and builds the event on it.
    pub fn build(&self) -> Result<Built<Model>> {
        let started = std::time::Instant::now();
        let packed = self.pack()?;
        eprintln!(
            "{}: packed layer ready in {:.2} s; {} rocks packed to a fraction {:.3} under {:.3} m ({}), {} steps in {:.1} s when built; packing springs {:.3e} J loaded, {:.3e} J once unloaded",
            self.rockfill.name,
            started.elapsed().as_secs_f64(),
            packed.bodies.len(),
            packed.fraction,
            packed.top_m,
            if packed.pressure_capped { "stopped by the lid's pressure cap" } else { "the asked fraction" },
            packed.steps,
            packed.wall_s,
            packed.loaded_j,
            packed.elastic_j
        );
        self.build_on(&packed)
    }
}
