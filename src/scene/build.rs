//! Scene → model: lattices, materials, cracks, boundary groups and probes.

use serde::{Deserialize, Serialize};

use super::Scene;
use crate::error::{Error, Result};
use crate::kernel::boundary::{LoadGroup, MotionGroup};
use crate::kernel::{Model, ModelBuilder, StepChoice};
use crate::lattice::{self, Rect};
use crate::material::Arrangement;

/// What a probe measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ProbeQuantity {
    /// Mean x displacement of the group, m.
    MeanDisplacementXM,
    /// Mean y displacement of the group, m.
    MeanDisplacementYM,
    /// Sum of the x forces on the group (a reaction for a fixed group), N.
    ForceXN,
    /// Sum of the y forces on the group, N.
    ForceYN,
    /// Kinetic energy of the model, J.
    KineticEnergyJ,
    /// Elastic energy in the contacts, J.
    StrainEnergyJ,
    /// Bonds broken so far.
    BondsBroken,
    /// Energy-balance residual, J.
    EnergyResidualJ,
    /// x force a load group applies, N.
    AppliedLoadXN,
    /// y force a load group applies, N.
    AppliedLoadYN,
}

impl ProbeQuantity {
    /// True when the quantity is measured on a group of elements.
    pub fn needs_group(self) -> bool {
        matches!(self, Self::MeanDisplacementXM | Self::MeanDisplacementYM | Self::ForceXN | Self::ForceYN)
    }
}

/// A probe bound to its elements.
#[derive(Debug, Clone, PartialEq)]
pub struct Probe {
    /// Column name.
    pub name: String,
    /// Quantity.
    pub quantity: ProbeQuantity,
    /// Element indices (sorted).
    pub elements: Vec<usize>,
    /// Load group index, for `applied_load_*`.
    pub load_group: Option<usize>,
}

impl Probe {
    /// Evaluate on the model's present state.
    pub fn value(&self, m: &Model) -> f64 {
        match self.quantity {
            ProbeQuantity::MeanDisplacementXM => m.mean_displacement_m(&self.elements)[0],
            ProbeQuantity::MeanDisplacementYM => m.mean_displacement_m(&self.elements)[1],
            ProbeQuantity::ForceXN => m.force_on(&self.elements)[0],
            ProbeQuantity::ForceYN => m.force_on(&self.elements)[1],
            ProbeQuantity::KineticEnergyJ => m.kinetic_energy_j(),
            ProbeQuantity::StrainEnergyJ => m.strain_energy_j(),
            ProbeQuantity::BondsBroken => m.state.ledger.bonds_broken() as f64,
            ProbeQuantity::EnergyResidualJ => m.energy_residual_j(),
            ProbeQuantity::AppliedLoadXN => m.applied_load_n(self.load_group.expect("validated"))[0],
            ProbeQuantity::AppliedLoadYN => m.applied_load_n(self.load_group.expect("validated"))[1],
        }
    }
}

/// A built scene of the 2D kernel, ready to run.
pub type Built = crate::simulation::Built<Model>;

impl crate::simulation::Measure<Model> for Probe {
    fn name(&self) -> &str {
        &self.name
    }

    fn value(&self, model: &Model) -> f64 {
        Probe::value(self, model)
    }
}

/// Rayleigh coefficients (α 1/s, β s) from one point (mass-proportional only) or two points.
pub fn rayleigh(points: &[(f64, f64)]) -> (f64, f64) {
    match points {
        [] => (0.0, 0.0),
        [(w, xi)] => (2.0 * xi * w, 0.0),
        [(w1, x1), (w2, x2), ..] => {
            // ξ(ω) = α/(2ω) + βω/2 at both points.
            let beta = 2.0 * (x2 * w2 - x1 * w1) / (w2 * w2 - w1 * w1);
            let alpha = 2.0 * x1 * w1 - beta * w1 * w1;
            (alpha, beta)
        }
    }
}

impl Scene {
    /// Build the model (validates first).
    pub fn build(&self) -> Result<Built> {
        self.validate()?;
        let g = &self.scene;
        let mut b = ModelBuilder::new(g.plane, g.thickness_m);
        b.gravity_mps2 = g.gravity_mps2;
        let mat_index: Vec<(String, usize)> = self.material.iter().map(|m| (m.name.clone(), b.add_material(m.clone()))).collect();
        let index = |name: &str| mat_index.iter().find(|(n, _)| n == name).map(|p| p.1).expect("validated");
        for (k, body) in self.body.iter().enumerate() {
            let field = |e: Error| match e {
                Error::Input { file, field, message } => Error::Input { file, field: format!("body[{k}].{field}"), message },
                other => other,
            };
            let gap = body.bond_gap_ratio.unwrap_or(lattice::IRREGULAR_BOND_GAP);
            let r = body.element_radius_m;
            let lat = match (&body.rect, &body.shape) {
                (_, Some(shape)) => shape.lattice(body.lattice, r, body.seed, gap),
                (Some(rect), None) => match body.lattice {
                    Arrangement::SimpleCubic => lattice::simple_cubic(rect, r),
                    Arrangement::ClosePacked => lattice::close_packed(rect, r),
                    Arrangement::Irregular => lattice::irregular(rect, r, body.seed, gap),
                },
                (None, None) => unreachable!("validated"),
            }
            .map_err(field)?;
            let overrides: Vec<(Rect, usize)> = body.region.iter().map(|r| (r.rect, index(&r.material))).collect();
            let v = [body.velocity_mps[0], body.velocity_mps[1], 0.0];
            b.add_body(&body.name, &lat, body.lattice, index(&body.material), &overrides, v);
        }
        for c in &self.crack {
            b.cut(c.from_m, c.to_m);
        }
        let select = |b: &ModelBuilder, r: &Rect, free_only: bool| -> Vec<usize> {
            let el = b.elements();
            (0..el.len()).filter(|&e| r.contains(el.initial[e][0], el.initial[e][1]) && !(free_only && el.is_kinematic(e))).collect()
        };
        for (k, f) in self.fix.iter().enumerate() {
            let set = select(&b, &f.rect, false);
            if set.is_empty() {
                return Err(Error::input(format!("fix[{k}].rect"), "selects no elements"));
            }
            let dofs = [super::Dof::X, super::Dof::Y, super::Dof::Rotation].map(|d| f.dofs.contains(&d));
            let group = MotionGroup { name: f.name.clone(), velocity: [f.velocity_mps[0], f.velocity_mps[1], 0.0], profile: f.profile, dofs };
            b.add_motion(group, &set);
        }
        for (k, l) in self.load.iter().enumerate() {
            let set = select(&b, &l.rect, true);
            if set.is_empty() {
                return Err(Error::input(format!("load[{k}].rect"), "selects no free elements"));
            }
            b.add_load(LoadGroup { name: l.name.clone(), force_n: l.force_n, profile: l.profile, servo: l.servo, members: Vec::new() }, &set);
        }
        let mut probes = Vec::new();
        for (k, p) in self.probe.iter().enumerate() {
            let elements = match &p.rect {
                Some(r) if p.quantity.needs_group() => {
                    let set = select(&b, r, false);
                    if set.is_empty() {
                        return Err(Error::input(format!("probe[{k}].rect"), "selects no elements"));
                    }
                    set
                }
                _ => Vec::new(),
            };
            let load_group = p.load.as_ref().and_then(|n| self.load.iter().position(|l| &l.name == n));
            probes.push(Probe { name: p.name.clone(), quantity: p.quantity, elements, load_group });
        }
        let d = &self.damping;
        let (alpha, beta) = if d.points.is_empty() {
            (d.alpha_per_s.unwrap_or(0.0), d.beta_s.unwrap_or(0.0))
        } else {
            rayleigh(&d.points.iter().map(|p| (p.omega_rad_per_s, p.ratio)).collect::<Vec<_>>())
        };
        if alpha < 0.0 || beta < 0.0 {
            return Err(Error::input("damping.points", format!("the points give a negative Rayleigh coefficient (α = {alpha:.4e} 1/s, β = {beta:.4e} s); Rayleigh damping cannot fit them")));
        }
        b.alpha_per_s = alpha;
        b.beta_s = beta;
        b.damp_relative_to_rigid = d.relative_to_rigid_motion;
        let ts = &self.time_step;
        b.step = match (ts.dt_s, ts.refuse_unstable) {
            (Some(dt_s), true) => StepChoice::Fixed { dt_s },
            (Some(dt_s), false) => StepChoice::Unchecked { dt_s },
            (None, _) => StepChoice::Auto { safety: ts.safety },
        };
        b.collision_steps = ts.collision_steps;
        b.skin_ratio = ts.skin_ratio;
        let model = b.build()?;
        let probes = probes.into_iter().map(|p| std::sync::Arc::new(p) as std::sync::Arc<dyn crate::simulation::Measure<Model>>).collect();
        Ok(Built { name: g.name.clone(), model, probes, duration_s: g.duration_s, every_steps: self.output.every_steps })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rayleigh_hits_both_points() {
        let (a, b) = rayleigh(&[(10.0, 0.05), (100.0, 0.02)]);
        let xi = |w: f64| a / (2.0 * w) + b * w / 2.0;
        assert!((xi(10.0) - 0.05).abs() < 1e-14 && (xi(100.0) - 0.02).abs() < 1e-14);
        assert_eq!(rayleigh(&[(3.0, 0.1)]), (0.6000000000000001, 0.0));
    }
}
