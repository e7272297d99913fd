//! `[[absorb]]`: a face through which waves leave the model, a viscous boundary after Lysmer &
//! Kuhlemeyer (1969). The spheres whose centres lie in its box (the layer at the face) are each
//! tied to what lies beyond by a dashpot ρ c_p A_e along the face's normal and ρ c_s A_e across
//! it, with the material's own plane-wave speeds; the face's area shared among them in
//! proportion to their sections (A_e = A r_e² / Σ r²). A plane wave arriving square to the face
//! then leaves whole, at any frequency; the boundary carries no static load (it is not a support
//! that holds the body up, only one that lets its waves out).

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::kernel3d::solid::Solid;
use crate::packing3d::Box3;

/// The axis a face is square to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Axis3 {
    /// x.
    X,
    /// y.
    Y,
    /// z.
    Z,
}

/// `[[absorb]]` of a 3D scene.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Absorb3 {
    /// Name.
    pub name: String,
    /// The layer at the face: the spheres whose centres lie in this box.
    #[serde(rename = "box")]
    pub region: Box3,
    /// The face's normal.
    pub normal: Axis3,
    /// The face's area, m².
    pub area_m2: f64,
}

/// Plane-wave speeds of a solid, m/s: (P, S), from E, ν and ρ.
pub fn wave_speeds_mps(s: &Solid) -> (f64, f64) {
    let (e, nu, rho) = (s.youngs_modulus_pa, s.poisson_ratio, s.density_kg_per_m3);
    let p_modulus = e * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
    ((p_modulus / rho).sqrt(), (0.5 * e / (1.0 + nu) / rho).sqrt())
}

impl Absorb3 {
    /// Check the fields; `field` names the table in messages.
    pub fn validate(&self, field: &str) -> Result<()> {
        self.region.validate(&format!("{field}.box"))?;
        if !(self.area_m2.is_finite() && self.area_m2 > 0.0) {
            return Err(Error::input(format!("{field}.area_m2"), format!("must be a finite area > 0, got {}", self.area_m2)));
        }
        Ok(())
    }

    /// The dashpot coefficients along x, y, z (kg/s) of the spheres of radii `radii_m[e]` and
    /// solids `solid(e)` in `layer`, in its order.
    pub fn dashpots_kg_per_s<'a>(&self, layer: &[usize], radii_m: &[f64], solid: impl Fn(usize) -> &'a Solid) -> Vec<[f64; 3]> {
        let sections: f64 = layer.iter().map(|&e| radii_m[e] * radii_m[e]).sum();
        let axis = match self.normal {
            Axis3::X => 0,
            Axis3::Y => 1,
            Axis3::Z => 2,
        };
        layer
            .iter()
            .map(|&e| {
                let s = solid(e);
                let (cp, cs) = wave_speeds_mps(s);
                let area = self.area_m2 * radii_m[e] * radii_m[e] / sections;
                let mut c = [s.density_kg_per_m3 * cs * area; 3];
                c[axis] = s.density_kg_per_m3 * cp * area;
                c
            })
            .collect()
    }
}
