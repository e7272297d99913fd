//! The contact law on the Minkowski features: the seed's normal force k_n δ_M^n along n_M
//! (eqs 4–5), a dashpot set from the restitution e, and a tangential spring capped by Coulomb
//! friction, carried in the contact plane as the normal turns.

use nalgebra::Vector3;

use super::epa::Contact;
use crate::{Error, Result};

/// The parameters of one kind of pair (rock–rock, rock–projectile).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Law {
    /// k_n, N/m^n (N/m for the linear law).
    pub stiffness: f64,
    /// The exponent n ≥ 1: 1 linear, 1.5 Hertz-type (eq 5).
    pub exponent: f64,
    /// Tangential spring stiffness k_s, N/m.
    pub shear_stiffness: f64,
    /// Coulomb friction coefficient μ.
    pub friction: f64,
    /// Coefficient of restitution e, in (0, 1].
    pub restitution: f64,
}

impl Law {
    /// Refuses each bad field by name.
    pub fn check(&self, field: &str) -> Result<()> {
        let bad = |name: &str, message: &str| Err(Error::input(format!("{field}.{name}"), message));
        if !(self.stiffness > 0.0 && self.stiffness.is_finite()) {
            return bad("stiffness", "must be positive and finite (N/m^n)");
        }
        if !(self.exponent >= 1.0 && self.exponent.is_finite()) {
            return bad("exponent", "must be 1 (linear) or more (1.5: Hertz-type)");
        }
        if !(self.shear_stiffness >= 0.0 && self.shear_stiffness.is_finite()) {
            return bad("shear_stiffness", "must be zero or positive and finite (N/m)");
        }
        if !(self.friction >= 0.0 && self.friction.is_finite()) {
            return bad("friction", "must be zero or positive");
        }
        if !(self.restitution > 0.0 && self.restitution <= 1.0) {
            return bad("restitution", "must be in (0, 1]");
        }
        Ok(())
    }

    /// The damping ratio ζ that makes a linear spring–dashpot rebound at e:
    /// ζ = −ln e / √(π² + ln² e).
    pub fn damping_ratio(&self) -> f64 {
        let l = self.restitution.ln();
        -l / (std::f64::consts::PI.powi(2) + l * l).sqrt()
    }

    /// The force on B (N) at the contact `c`, with `approach` = v_B − v_A at c_M (m/s), `mass`
    /// the pair's effective mass along the normal at the contact point (kg; for a central
    /// contact, the reduced mass), over a step of `dt` (s); `shear` (m), the tangential
    /// spring's stretch, is carried into the new contact plane, stretched and capped.
    ///
    /// The dashpot is 2ζ√(m k) with k the spring's tangent stiffness n k_n δ^(n−1): exactly e
    /// for the linear law; for n > 1 its scaling with δ keeps e independent of the speed, but
    /// the value is e only approximately. The normal force is not clipped at zero, so the
    /// linear law's rebound is exactly e (a brief pull as the dashpot closes).
    pub fn force(&self, c: &Contact, approach: &Vector3<f64>, mass: f64, shear: &mut Vector3<f64>, dt: f64) -> Vector3<f64> {
        self.act(c, approach, mass, shear, dt).force
    }

    /// [`Law::force`] with the energies a kernel's ledger needs.
    pub fn act(&self, c: &Contact, approach: &Vector3<f64>, mass: f64, shear: &mut Vector3<f64>, dt: f64) -> Act {
        let n = c.normal;
        let tangent_stiffness = self.exponent * self.stiffness * c.depth.powf(self.exponent - 1.0);
        let dashpot = 2.0 * self.damping_ratio() * (mass * tangent_stiffness).sqrt();
        let closing = approach.dot(&n);
        let normal = self.stiffness * c.depth.powf(self.exponent) - dashpot * closing;
        // Carried: projected into the new plane with its length kept, then stretched by the slip.
        let kept = *shear - n * n.dot(shear);
        *shear = if kept.norm() > 0.0 { kept * (shear.norm() / kept.norm()) } else { Vector3::zeros() };
        let carried = *shear;
        let slip = (approach - n * n.dot(approach)) * dt;
        *shear += slip;
        let cap = self.friction * normal.max(0.0);
        if self.shear_stiffness * shear.norm() > cap {
            *shear *= cap / (self.shear_stiffness * shear.norm());
        }
        let spring = 0.5 * self.shear_stiffness;
        Act {
            force: n * normal - *shear * self.shear_stiffness,
            elastic_j: self.stiffness * c.depth.powf(self.exponent + 1.0) / (self.exponent + 1.0) + spring * shear.norm_squared(),
            damping_j: dashpot * closing * closing * dt,
            // The tangential force's work against the slip, less what the spring kept: zero
            // without friction, the Coulomb loss when capped.
            friction_j: self.shear_stiffness * shear.dot(&slip) - spring * (shear.norm_squared() - carried.norm_squared()),
        }
    }
}

/// One contact's force and energies in a step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Act {
    /// Force on B, N.
    pub force: Vector3<f64>,
    /// Elastic energy stored now: k_n δ^(n+1)/(n+1) in the normal spring, ½ k_s |s|² in the
    /// tangential one, J.
    pub elastic_j: f64,
    /// What the dashpot took over the step, J.
    pub damping_j: f64,
    /// What sliding took over the step, J (with an uncapped spring, the ½ k_s |slip|² the
    /// step's end-of-step spring force spends).
    pub friction_j: f64,
}
