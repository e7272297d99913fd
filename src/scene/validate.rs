//! Semantic checks of a parsed scene. Every error names the dotted field and what is allowed.

use super::{ProbeQuantity, Scene, TimeStep};
use crate::error::{Error, Result};

fn positive(field: &str, v: f64) -> Result<()> {
    if v.is_finite() && v > 0.0 { Ok(()) } else { Err(Error::input(field, format!("must be a finite number > 0, got {v}"))) }
}

fn finite(field: &str, v: &[f64]) -> Result<()> {
    if v.iter().all(|x| x.is_finite()) { Ok(()) } else { Err(Error::input(field, format!("must be finite, got {v:?}"))) }
}

impl Scene {
    /// Check the scene; errors name the field.
    pub fn validate(&self) -> Result<()> {
        let g = &self.scene;
        if g.name.is_empty() || !g.name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-') {
            return Err(Error::input("scene.name", format!("must be non-empty letters, digits, '_' or '-' (it names output files), got {:?}", g.name)));
        }
        positive("scene.thickness_m", g.thickness_m)?;
        positive("scene.duration_s", g.duration_s)?;
        finite("scene.gravity_mps2", &g.gravity_mps2)?;
        self.time_step.validate()?;
        let d = &self.damping;
        if !d.points.is_empty() && (d.alpha_per_s.is_some() || d.beta_s.is_some()) {
            return Err(Error::input("damping", "give either points or alpha_per_s/beta_s, not both"));
        }
        if d.points.len() > 2 {
            return Err(Error::input("damping.points", format!("Rayleigh damping takes one or two points, got {}", d.points.len())));
        }
        for (k, p) in d.points.iter().enumerate() {
            positive(&format!("damping.points[{k}].omega_rad_per_s"), p.omega_rad_per_s)?;
            if !(p.ratio.is_finite() && (0.0..1.0).contains(&p.ratio)) {
                return Err(Error::input(format!("damping.points[{k}].ratio"), format!("must lie in [0, 1), got {}", p.ratio)));
            }
        }
        if d.points.len() == 2 && d.points[0].omega_rad_per_s == d.points[1].omega_rad_per_s {
            return Err(Error::input("damping.points", "the two frequencies must differ"));
        }
        for (name, v) in [("damping.alpha_per_s", d.alpha_per_s), ("damping.beta_s", d.beta_s)] {
            if let Some(v) = v
                && !(v.is_finite() && v >= 0.0)
            {
                return Err(Error::input(name, format!("must be ≥ 0, got {v}")));
            }
        }
        for (k, m) in self.material.iter().enumerate() {
            if self.material[..k].iter().any(|o| o.name == m.name) {
                return Err(Error::input(format!("material[{k}].name"), format!("duplicate material name {:?}", m.name)));
            }
            m.validate(&format!("material.{}", m.name))?;
        }
        let known = |field: String, name: &str| -> Result<()> {
            if self.material.iter().any(|m| m.name == name) {
                Ok(())
            } else {
                let names: Vec<&str> = self.material.iter().map(|m| m.name.as_str()).collect();
                Err(Error::input(field, format!("unknown material {name:?}; defined: {names:?}")))
            }
        };
        if self.body.is_empty() {
            return Err(Error::input("body", "the scene needs at least one [[body]]"));
        }
        for (k, b) in self.body.iter().enumerate() {
            known(format!("body[{k}].material"), &b.material)?;
            positive(&format!("body[{k}].element_radius_m"), b.element_radius_m)?;
            match (&b.rect, &b.shape) {
                (Some(r), None) => r.validate(&format!("body[{k}].rect"))?,
                (None, Some(s)) => s.validate(&format!("body[{k}].shape"))?,
                _ => return Err(Error::input(format!("body[{k}]"), "give the region it fills: a rect or a shape, not both")),
            }
            finite(&format!("body[{k}].velocity_mps"), &b.velocity_mps)?;
            if let Some(gap) = b.bond_gap_ratio
                && !(gap.is_finite() && (0.0..=1.0).contains(&gap))
            {
                return Err(Error::input(format!("body[{k}].bond_gap_ratio"), format!("must lie in [0, 1], got {gap}")));
            }
            for (q, r) in b.region.iter().enumerate() {
                known(format!("body[{k}].region[{q}].material"), &r.material)?;
                r.rect.validate(&format!("body[{k}].region[{q}].rect"))?;
            }
        }
        for (k, c) in self.crack.iter().enumerate() {
            finite(&format!("crack[{k}].from_m"), &c.from_m)?;
            finite(&format!("crack[{k}].to_m"), &c.to_m)?;
        }
        for (k, f) in self.fix.iter().enumerate() {
            f.rect.validate(&format!("fix[{k}].rect"))?;
            if f.dofs.is_empty() {
                return Err(Error::input(format!("fix[{k}].dofs"), "must name at least one of \"x\", \"y\", \"rotation\""));
            }
            finite(&format!("fix[{k}].velocity_mps"), &f.velocity_mps)?;
        }
        for (k, l) in self.load.iter().enumerate() {
            l.rect.validate(&format!("load[{k}].rect"))?;
            finite(&format!("load[{k}].force_n"), &l.force_n)?;
        }
        for (k, p) in self.probe.iter().enumerate() {
            if p.quantity.needs_group() && p.rect.is_none() {
                return Err(Error::input(format!("probe[{k}].rect"), format!("quantity {:?} needs a rect selecting elements", p.quantity)));
            }
            if let Some(r) = &p.rect {
                r.validate(&format!("probe[{k}].rect"))?;
            }
            let wants_load = matches!(p.quantity, ProbeQuantity::AppliedLoadXN | ProbeQuantity::AppliedLoadYN);
            match (&p.load, wants_load) {
                (Some(n), true) if self.load.iter().any(|l| &l.name == n) => {}
                (Some(n), true) => return Err(Error::input(format!("probe[{k}].load"), format!("unknown load group {n:?}"))),
                (None, true) => return Err(Error::input(format!("probe[{k}].load"), format!("quantity {:?} needs the name of a [[load]]", p.quantity))),
                (Some(_), false) => return Err(Error::input(format!("probe[{k}].load"), "only applied_load_* probes take a load")),
                (None, false) => {}
            }
            if self.probe[..k].iter().any(|o| o.name == p.name) {
                return Err(Error::input(format!("probe[{k}].name"), format!("duplicate probe name {:?}", p.name)));
            }
        }
        if self.output.every_steps == 0 {
            return Err(Error::input("output.every_steps", "must be ≥ 1"));
        }
        Ok(())
    }
}

impl TimeStep {
    fn validate(&self) -> Result<()> {
        if !(self.safety > 0.0 && self.safety <= 1.0) {
            return Err(Error::input("time_step.safety", format!("must lie in (0, 1], got {}", self.safety)));
        }
        if let Some(dt) = self.dt_s {
            positive("time_step.dt_s", dt)?;
        }
        if let Some(n) = self.collision_steps
            && !(n.is_finite() && n >= 1.0)
        {
            return Err(Error::input("time_step.collision_steps", format!("must be ≥ 1, got {n}")));
        }
        if !(self.skin_ratio > 0.0 && self.skin_ratio <= 1.0) {
            return Err(Error::input("time_step.skin_ratio", format!("must lie in (0, 1], got {}", self.skin_ratio)));
        }
        Ok(())
    }
}
