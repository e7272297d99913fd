//! A graded Voronoi rockfill (seed eqs 26–29): seeds uniform in a box, their Voronoi cells, each
//! cell shrunk about its seed to a drawn rock size. The seed's eq 29 gives each grade's shrink
//! factor from its sieve sizes; with one grade of ±`spread` about a mean (the seed's ±10 %), we
//! draw each rock's size from a normal of σ = spread/2, cut at ±spread, and shrink its cell
//! to it: q = d / d_cell, so sizes follow the asked distribution exactly (a rock's size is its
//! equivalent-sphere diameter, (6V/π)^⅓). The seed count is eq 28's with the cells' mean
//! radius r = mean / (2 q̄): `grade` q̄ is the mean shrink factor, the loosening that lets the
//! rocks fall apart.

use nalgebra::Vector3;

use super::shape::Polyhedron;
use super::voronoi::{cells, shrink};
use crate::error::{Error, Result};
use crate::lattice::SplitMix64;

/// The largest shrink factor: a small cell asked for a large rock keeps a gap to its neighbours.
pub const MOST_SHRINK: f64 = 0.95;

/// What rocks to make.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grading {
    /// Mean rock size (equivalent-sphere diameter), m.
    pub mean_m: f64,
    /// Half-width of the size range as a fraction of the mean (0.1: ±10 %).
    pub spread: f64,
    /// Mean shrink factor q̄ of eq 29, in (0, 0.95]: cells are mean/q̄ across.
    pub grade: f64,
    /// Seed of the draws.
    pub seed: u64,
}

impl Grading {
    /// Refuses each bad field by name.
    pub fn check(&self, field: &str) -> Result<()> {
        let bad = |name: &str, message: &str| Err(Error::input(format!("{field}.{name}"), message));
        if !(self.mean_m > 0.0 && self.mean_m.is_finite()) {
            return bad("mean_size_m", "must be positive (m)");
        }
        if !(self.spread >= 0.0 && self.spread < 0.5) {
            return bad("spread", "must be in [0, 0.5) (0.1: ±10 % about the mean)");
        }
        if !(self.grade > 0.0 && self.grade <= MOST_SHRINK) {
            return bad("grade", "must be in (0, 0.95]: the mean shrink factor of a cell");
        }
        Ok(())
    }
}

/// Rocks cut from a box, in the box's frame.
#[derive(Clone, Debug)]
pub struct Rocks {
    /// Each rock's shape (body frame; `rest_position`/`rest_orientation` place it in the box).
    pub shapes: Vec<Polyhedron>,
    /// Each rock's asked size, m.
    pub asked_m: Vec<f64>,
    /// Rocks whose cell was too small for their size (shrunk by `MOST_SHRINK` instead).
    pub capped: usize,
}

/// Equivalent-sphere diameter of a volume `v` (m³), m.
pub fn size_of(volume_m3: f64) -> f64 {
    (6.0 * volume_m3 / std::f64::consts::PI).cbrt()
}

/// The rocks of `grading` in the box `lo`–`hi` (m).
pub fn rocks(grading: &Grading, lo: &Vector3<f64>, hi: &Vector3<f64>) -> Result<Rocks> {
    grading.check("rockfill")?;
    let volume = (hi - lo).product();
    let r = grading.mean_m / (2.0 * grading.grade);
    // Eq 28: N = V / (4π r³/3).
    let count = (volume / (4.0 / 3.0 * std::f64::consts::PI * r.powi(3))).round() as usize;
    if count < 2 {
        return Err(Error::input("rockfill.mean_size_m", format!("{count} rocks fit the box: make the rocks smaller or the box larger")));
    }
    let mut rng = SplitMix64(grading.seed ^ 0x0C0C_F111_5EED_0029);
    let seeds: Vec<Vector3<f64>> = (0..count).map(|_| Vector3::from_fn(|k, _| lo[k] + rng.unit() * (hi[k] - lo[k]))).collect();
    let tol = 1e-12 * (hi - lo).norm();
    let mut out = Rocks { shapes: Vec::new(), asked_m: Vec::new(), capped: 0 };
    for (seed, cell) in seeds.iter().zip(cells(&seeds, lo, hi, tol)) {
        let Some(cell) = cell else { continue };
        let cell_size = size_of(Polyhedron::from_faces(&cell.vertices, cell.faces.clone()).volume);
        let asked = grading.mean_m * (1.0 + 0.5 * grading.spread * truncated_normal(&mut rng, 2.0));
        let mut q = asked / cell_size;
        if q > MOST_SHRINK {
            q = MOST_SHRINK;
            out.capped += 1;
        }
        let rock = shrink(&cell, seed, q);
        out.shapes.push(Polyhedron::from_faces(&rock.vertices, rock.faces));
        out.asked_m.push(asked);
    }
    Ok(out)
}

/// A standard normal draw cut at ±`cut` (Box–Muller, redrawn outside).
fn truncated_normal(rng: &mut SplitMix64, cut: f64) -> f64 {
    loop {
        let (u, v) = (rng.unit(), rng.unit());
        let z = (-2.0 * (1.0 - u).ln()).sqrt() * (std::f64::consts::TAU * v).cos();
        if z.abs() <= cut {
            return z;
        }
    }
}
