//! Sphere packings filling a box, for the 3D kernel: a face-centred cubic lattice of equal
//! spheres and a seeded, deterministic, isotropic dense random packing of slightly
//! polydisperse spheres, with the bonds between touching (or nearly touching) neighbours and
//! the measures that check them (packing fraction, coordination, fabric tensor).
//!
//! The 3D counterpart of [`crate::lattice`]. Every sphere lies wholly inside its box (centre at
//! least its radius from every face). Results are bit-identical on every run and machine: plain
//! f64 arithmetic in a fixed order, no hashing, no threads, no clock.

use crate::error::{Error, Result};
use crate::lattice::SplitMix64;
use std::f64::consts::PI;

pub mod cache;
mod graded;
pub use graded::{Grading, random_dense_graded};

/// An axis-aligned box, m.
#[derive(Debug, Clone, Copy, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Box3 {
    /// Low x face, m.
    pub x_min_m: f64,
    /// High x face, m.
    pub x_max_m: f64,
    /// Low y face, m.
    pub y_min_m: f64,
    /// High y face, m.
    pub y_max_m: f64,
    /// Low z face, m.
    pub z_min_m: f64,
    /// High z face, m.
    pub z_max_m: f64,
}

impl Box3 {
    /// True when the point `p` (m) lies inside or on the boundary.
    pub fn contains(&self, p: [f64; 3]) -> bool {
        let (lo, hi) = (self.lo(), self.hi());
        (0..3).all(|k| p[k] >= lo[k] && p[k] <= hi[k])
    }

    /// Volume, m³.
    pub fn volume_m3(&self) -> f64 {
        (self.x_max_m - self.x_min_m) * (self.y_max_m - self.y_min_m) * (self.z_max_m - self.z_min_m)
    }

    /// Check the box is proper (finite, each max above its min); `field` names it in messages.
    pub fn validate(&self, field: &str) -> Result<()> {
        let (lo, hi) = (self.lo(), self.hi());
        let finite = lo.iter().chain(&hi).all(|v| v.is_finite());
        if !finite || (0..3).any(|k| hi[k] <= lo[k]) {
            return Err(Error::input(field, format!("needs finite x_min_m < x_max_m, y_min_m < y_max_m and z_min_m < z_max_m, got {self:?}")));
        }
        Ok(())
    }

    /// Low corner [x, y, z], m.
    fn lo(&self) -> [f64; 3] {
        [self.x_min_m, self.y_min_m, self.z_min_m]
    }

    /// High corner [x, y, z], m.
    fn hi(&self) -> [f64; 3] {
        [self.x_max_m, self.y_max_m, self.z_max_m]
    }
}

/// What holds a random packing in ([`random_dense_in`]): a box, or a solid
/// (`shape3d::Projectile3`). The walls push a sphere back by its overlap along their inward
/// normals, as a sphere would.
pub trait Walls {
    /// The bounding box, m.
    fn bounds(&self) -> Box3;
    /// Volume, m³.
    fn volume_m3(&self) -> f64;
    /// The volume left once the walls' looser first layer, `layer_m` thick, is taken off, m³
    /// (how many spheres to make).
    fn filled_m3(&self, layer_m: f64) -> f64;
    /// True when a sphere of radius `r_m` at `c` lies wholly inside.
    fn holds(&self, c: [f64; 3], r_m: f64) -> bool;
    /// True when a start point `c` drawn in the bounds (at least `r_m` inside them) is kept.
    fn may_start(&self, c: [f64; 3], r_m: f64) -> bool {
        self.holds(c, r_m)
    }
    /// The walls' push on a sphere of radius `r_m` at `c` (overlaps, m, along the inward
    /// normals, summed) and its largest overlap, m.
    fn push(&self, c: [f64; 3], r_m: f64) -> ([f64; 3], f64);
    /// After the relaxation: bring a sphere within the walls if the soft walls left it a hair
    /// outside, or say it must go (false).
    fn settle(&self, c: &mut [f64; 3], r_m: f64) -> bool {
        self.holds(*c, r_m)
    }
}

impl Walls for Box3 {
    fn bounds(&self) -> Box3 {
        *self
    }
    fn volume_m3(&self) -> f64 {
        Box3::volume_m3(self)
    }
    fn filled_m3(&self, layer_m: f64) -> f64 {
        let (lo, hi) = (self.lo(), self.hi());
        (0..3).map(|k| hi[k] - lo[k] - 2.0 * layer_m).product()
    }
    fn holds(&self, c: [f64; 3], r_m: f64) -> bool {
        let (lo, hi) = (self.lo(), self.hi());
        (0..3).all(|k| c[k] >= lo[k] + r_m && c[k] <= hi[k] - r_m)
    }
    fn may_start(&self, _: [f64; 3], _: f64) -> bool {
        // The bounds are the box: every point drawn in them is a start.
        true
    }
    fn push(&self, c: [f64; 3], r_m: f64) -> ([f64; 3], f64) {
        let (lo, hi) = (self.lo(), self.hi());
        let (mut f, mut worst) = ([0.0; 3], 0.0f64);
        for k in 0..3 {
            let low = (lo[k] + r_m - c[k]).max(0.0);
            let high = (c[k] + r_m - hi[k]).max(0.0);
            f[k] = low - high;
            worst = worst.max(low.max(high));
        }
        (f, worst)
    }
    fn settle(&self, c: &mut [f64; 3], r_m: f64) -> bool {
        let (lo, hi) = (self.lo(), self.hi());
        for k in 0..3 {
            c[k] = c[k].clamp(lo[k] + r_m, hi[k] - r_m);
        }
        true
    }
}

/// A generated assembly of spheres.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Packing {
    /// Sphere centres [x, y, z], m, in layer order (z slabs, then y rows, then x).
    pub centres_m: Vec<[f64; 3]>,
    /// Sphere radii, m, one per centre.
    pub radii_m: Vec<f64>,
    /// Bonded pairs (i < j), sorted: gap below the bond gap ratio × the mean radius R
    /// (fcc: 1e-9 R, the touching pairs).
    pub bonds: Vec<(u32, u32)>,
    /// Volume of the box the packing fills, m³: the material volume the spheres stand for
    /// (element masses that sum to density × this give the assembly the continuum's density).
    pub volume_m3: f64,
}

impl Packing {
    /// The spheres for which `keep(centre, radius)` holds, with the bonds among them (indices
    /// renumbered, order kept), standing for a solid of `volume_m3`: a shape cut from a
    /// packing of its bounding box.
    pub fn keep(&self, keep: impl Fn([f64; 3], f64) -> bool, volume_m3: f64) -> Packing {
        let mut index = vec![u32::MAX; self.centres_m.len()];
        let (mut centres_m, mut radii_m) = (Vec::new(), Vec::new());
        for (k, (&c, &r)) in self.centres_m.iter().zip(&self.radii_m).enumerate() {
            if keep(c, r) {
                index[k] = centres_m.len() as u32;
                centres_m.push(c);
                radii_m.push(r);
            }
        }
        let bonds = self
            .bonds
            .iter()
            .map(|&(i, j)| (index[i as usize], index[j as usize]))
            .filter(|&(i, j)| i != u32::MAX && j != u32::MAX)
            .collect();
        Packing { centres_m, radii_m, bonds, volume_m3 }
    }
}

/// Relative tolerance on "touching" for the fcc lattice's bonds (× the radius).
const TOUCH: f64 = 1e-9;

/// Half-width of the radius distribution of [`random_dense`]: radii are uniform in
/// [(1 − s)R, (1 + s)R], i.e. [0.8R, 1.2R]. Enough size spread to stop the packing from
/// crystallising; too little to let small spheres rattle in the big ones' holes.
pub const RADIUS_SPREAD: f64 = 0.2;

/// Packing fraction (sphere volume over the box's volume less its walls' loose layer) that
/// [`random_dense`] inflates to. Below the random close packing of this size mix (about
/// 0.65), so the overlaps can still be relaxed away, reliably and fast.
pub const DENSE_FRACTION: f64 = 0.62;

/// Thickness of the looser layer at each wall, × R, taken off the box when [`random_dense`]
/// decides how many spheres to make: a sphere's centre cannot come nearer a face than its
/// radius, so the first layer is sparse and the whole box ends below its interior.
const WALL_LAYER: f64 = 0.4;

/// Largest overlap of two spheres of [`random_dense`], × R (its guarantee; in practice their
/// overlap is none).
pub const MAX_OVERLAP_RATIO: f64 = 1e-6;

/// The last relaxation of [`random_dense`] is of spheres this fraction bigger than their
/// radius, to an overlap of (1 − [`RADIUS_SPREAD`]) × this × R: a pair then overlaps by less
/// than that minus the (r_i + r_j) × this ≥ 2(1 − s)R × this added to it, a wall by less
/// than that minus r_i × this, so neither at all, and the slow tail of a tight tolerance is
/// not needed.
const FINAL_MARGIN: f64 = 1e-3;

/// Most spheres a packing may have ([`crate::lattice::MAX_ELEMENTS`], as for disks).
pub use crate::lattice::MAX_ELEMENTS as MAX_SPHERES;

/// Check `radius_m` is positive and that a sphere of `fit_radius_m` fits in the box.
fn check_fits(b: &Box3, radius_m: f64, fit_radius_m: f64) -> Result<()> {
    b.validate("box")?;
    if !(radius_m.is_finite() && radius_m > 0.0) {
        return Err(Error::input("radius_m", format!("must be finite and > 0, got {radius_m}")));
    }
    let (lo, hi) = (b.lo(), b.hi());
    if (0..3).any(|k| hi[k] - lo[k] < 2.0 * fit_radius_m) {
        return Err(Error::input("radius_m", format!("{radius_m} m is too large for the box {b:?}")));
    }
    Ok(())
}

/// Number of planes of spacing `pitch` from `lo` to `hi` (inclusive, with rounding slack).
fn planes(lo: f64, hi: f64, pitch: f64) -> usize {
    if hi < lo { 0 } else { ((hi - lo) / pitch + 1e-9).floor() as usize + 1 }
}

/// Face-centred cubic lattice of equal spheres of radius `radius_m` (m), touching: the cubic
/// cell of side 2√2 R, i.e. the points of a simple cubic grid of pitch √2 R whose three
/// indices sum to an even number, from the box's low corner shifted by R, kept where the
/// centre is at least R inside every face. Each interior sphere touches 12; the packing
/// fraction is π/(3√2) ≈ 0.7405. Bonds join the touching pairs (gap below 1e-9 R).
pub fn fcc(b: &Box3, radius_m: f64) -> Result<Packing> {
    check_fits(b, radius_m, radius_m)?;
    let r = radius_m;
    let h = 2f64.sqrt() * r;
    let (lo, hi) = (b.lo(), b.hi());
    let n: [usize; 3] = std::array::from_fn(|k| planes(lo[k] + r, hi[k] - r, h));
    check_count(n[0] * n[1] * n[2] / 2 + 1)?;
    let mut centres = Vec::new();
    for k in 0..n[2] {
        for j in 0..n[1] {
            for i in (0..n[0]).filter(|i| (i + j + k) % 2 == 0) {
                centres.push([lo[0] + r + h * i as f64, lo[1] + r + h * j as f64, lo[2] + r + h * k as f64]);
            }
        }
    }
    let radii = vec![r; centres.len()];
    let bonds = bonds_within(&centres, &radii, TOUCH * r);
    Ok(Packing { centres_m: centres, radii_m: radii, bonds, volume_m3: b.volume_m3() })
}

/// An error if `n` spheres are more than [`MAX_SPHERES`].
fn check_count(n: usize) -> Result<()> {
    if n > MAX_SPHERES {
        return Err(Error::input("radius_m", format!("would make {n} spheres, more than {MAX_SPHERES}")));
    }
    Ok(())
}

/// Dense random packing of spheres with radii uniform in [0.8R, 1.2R] ([`RADIUS_SPREAD`]),
/// R = `radius_m` (m), filling the box; seeded and deterministic (same seed, same bits).
///
/// Method, a quasi-static Lubachevsky–Stillinger-like inflation:
/// 1. radii are drawn while their spheres' volume stays within [`DENSE_FRACTION`] of the box
///    less a layer of 0.4R at each face (the walls' looser first layer);
/// 2. centres are placed uniformly at random (Poisson, no rejection) with every radius shrunk
///    to a packing fraction of 0.25: a dilute gas with no memory of any lattice;
/// 3. the radii are grown back in [`INFLATION_STEPS`] steps; after each, the overlap energy
///    (sphere pairs and walls) is minimised with FIRE until no overlap exceeds 0.01R, so the
///    growing spheres find room among each other without a preferred direction;
/// 4. the last step grows them 0.1 % past full size ([`FINAL_MARGIN`]) and relaxes to an
///    overlap below 0.08 % of R, which leaves the spheres at their true size strictly apart.
///
/// Simpler than event-driven Lubachevsky–Stillinger and, below random close packing (about
/// 0.65 for this mix), it reaches the same kind of state: isotropic, disordered, with an
/// interior packing fraction of about 0.62 (the walls' first layer is looser, so the whole
/// box holds less, 0.56–0.60 with the box's size). Chosen over gravity deposition
/// (anisotropic: vertical force chains) and random sequential addition (jams near 0.38).
/// About 2 s for 20 000 spheres. Bonds join the pairs whose gap is below `bond_gap_ratio` × R
/// (in [0, 1]).
///
/// Guarantees: every sphere lies inside the box, and no two overlap by more than
/// [`MAX_OVERLAP_RATIO`] × R. In practice none overlaps at all; only if a relaxation failed
/// to converge (a box too thin to hold its share, e.g. a cube of 3R) are all the radii scaled
/// down by the one factor that brings the overlaps within that bound, and then the smallest
/// may lie below 0.8R.
pub fn random_dense(b: &Box3, radius_m: f64, seed: u64, bond_gap_ratio: f64) -> Result<Packing> {
    check_fits(b, radius_m, (1.0 + RADIUS_SPREAD) * radius_m)?;
    random_dense_in(b, radius_m, seed, bond_gap_ratio)
}

/// [`random_dense`] in any [`Walls`]: the spheres start at random points the walls keep and
/// inflate against them, so a curved solid is filled as densely as a box, its surface layer
/// as loose as a box's face (not cut from a box's packing, which leaves it sparse).
pub fn random_dense_in(walls: &dyn Walls, radius_m: f64, seed: u64, bond_gap_ratio: f64) -> Result<Packing> {
    if !(bond_gap_ratio.is_finite() && (0.0..=1.0).contains(&bond_gap_ratio)) {
        return Err(Error::input("bond_gap_ratio", format!("must lie in [0, 1], got {bond_gap_ratio}")));
    }
    let mut rng = SplitMix64(seed ^ 0x5EED_3D5F_E7E5_0001);
    let b = walls.bounds();
    let (lo, hi) = (b.lo(), b.hi());
    let radii = draw_radii(&mut rng, walls.filled_m3(WALL_LAYER * radius_m) * DENSE_FRACTION, radius_m)?;
    let s0 = (0.25 / DENSE_FRACTION).cbrt();
    let mut centres: Vec<[f64; 3]> = Vec::with_capacity(radii.len());
    for &ri in &radii {
        // Draws until the walls keep one (a box keeps the first; a solid of its bounding box's
        // volume fraction f, 1/f draws on average).
        let mut tries = 0;
        loop {
            let c: [f64; 3] = std::array::from_fn(|k| lo[k] + s0 * ri + rng.unit() * (hi[k] - lo[k] - 2.0 * s0 * ri));
            if walls.may_start(c, s0 * ri) {
                centres.push(c);
                break;
            }
            tries += 1;
            if tries > 10_000 {
                return Err(Error::input("radius_m", format!("{radius_m} m: no room for a sphere in the walls after 10 000 draws")));
            }
        }
    }
    let (centres, radii) = grow_apart(walls, centres, radii, radius_m, (1.0 + RADIUS_SPREAD) * radius_m, s0);
    let (centres, radii) = layer_order(centres, radii, lo, 2.0 * radius_m);
    let bonds = bonds_within(&centres, &radii, bond_gap_ratio * radius_m);
    Ok(Packing { centres_m: centres, radii_m: radii, bonds, volume_m3: walls.volume_m3() })
}

/// Steps 3–4 of [`random_dense`]: spheres started at `s0` × their `radii` grown to full size
/// apart within the walls, those the soft walls left outside dropped; `radius_m` (m) is the
/// unit of the tolerances, `r_max_m` (m) the largest radius.
fn grow_apart(walls: &dyn Walls, mut centres: Vec<[f64; 3]>, mut radii: Vec<f64>, radius_m: f64, r_max_m: f64, s0: f64) -> (Vec<[f64; 3]>, Vec<f64>) {
    inflate(&mut Relax::new(walls, radius_m, r_max_m), &mut centres, &radii, s0);
    // The relaxation's walls are soft; a no-op after the last step converged, which leaves
    // every sphere strictly inside.
    let keep: Vec<bool> = centres.iter_mut().zip(&radii).map(|(c, &ri)| walls.settle(c, ri)).collect();
    if keep.iter().any(|&k| !k) {
        let mut k = keep.iter();
        centres.retain(|_| *k.next().expect("one flag per sphere"));
        let mut k = keep.iter();
        radii.retain(|_| *k.next().expect("one flag per sphere"));
    }
    remove_residual(&mut centres, &mut radii, radius_m, r_max_m);
    (centres, radii)
}

/// Radii uniform in [(1 − s)R, (1 + s)R] while their spheres' volume stays within
/// `volume_m3` (at least one: the caller has checked the biggest fits).
fn draw_radii(rng: &mut SplitMix64, volume_m3: f64, radius_m: f64) -> Result<Vec<f64>> {
    // Mean sphere volume of the mix: 4π/3 · E[r³], E[r³] = R³(1 + s²) for r uniform on R(1 ± s).
    let estimate = volume_m3 / (4.0 / 3.0 * PI * radius_m.powi(3) * (1.0 + RADIUS_SPREAD * RADIUS_SPREAD));
    check_count(estimate as usize)?;
    let mut radii = Vec::with_capacity(estimate as usize + 16);
    let mut total = 0.0;
    loop {
        let ri = radius_m * (1.0 - RADIUS_SPREAD + 2.0 * RADIUS_SPREAD * rng.unit());
        total += 4.0 / 3.0 * PI * ri.powi(3);
        if total > volume_m3 && !radii.is_empty() {
            break;
        }
        radii.push(ri);
    }
    check_count(radii.len())?;
    Ok(radii)
}

/// Steps of the inflation from a packing fraction of 0.25 to full size (each about 0.02 in
/// fraction: overlaps of a few per cent of R, relaxed in tens of iterations).
const INFLATION_STEPS: usize = 20;

/// Most FIRE iterations per inflation step; a converging step takes hundreds at most.
const MAX_ITERATIONS: usize = 20_000;

/// Grow the radii from `s0` × their size to full size in steps, relaxing after each.
fn inflate(relax: &mut Relax<'_>, centres: &mut [[f64; 3]], radii: &[f64], s0: f64) {
    let mut scaled = vec![0.0; radii.len()];
    for step in 1..=INFLATION_STEPS {
        let last = step == INFLATION_STEPS;
        // The last step overshoots by FINAL_MARGIN, so that a loose tolerance on the bigger
        // spheres leaves the true ones strictly apart.
        let s = if last { 1.0 + FINAL_MARGIN } else { s0 * (1.0 / s0).powf(step as f64 / INFLATION_STEPS as f64) };
        scaled.iter_mut().zip(radii).for_each(|(sr, &ri)| *sr = s * ri);
        let tol = if last { (1.0 - RADIUS_SPREAD) * FINAL_MARGIN } else { 1e-2 };
        relax.run(centres, &scaled, tol, MAX_ITERATIONS);
    }
}

/// Scale the radii down by the one factor that leaves no pair overlapping by more than
/// [`MAX_OVERLAP_RATIO`] × R (a no-op after a relaxation that converged).
fn remove_residual(centres: &mut [[f64; 3]], radii: &mut [f64], radius_m: f64, r_max_m: f64) {
    let mut pairs = Vec::new();
    Grid::new(centres, 2.0 * r_max_m).pairs(centres, |i, j| radii[i] + radii[j], &mut pairs);
    let allowed = MAX_OVERLAP_RATIO * radius_m;
    let mut factor = 1.0f64;
    for &(i, j) in &pairs {
        let (i, j) = (i as usize, j as usize);
        let d = dist(centres[i], centres[j]);
        if radii[i] + radii[j] - d > allowed {
            factor = factor.min((d + 0.5 * allowed) / (radii[i] + radii[j]));
        }
    }
    if factor < 1.0 {
        radii.iter_mut().for_each(|ri| *ri *= factor);
    }
}

/// Overlap relaxation: FIRE (Bitzek et al. 2006) minimisation of the overlap energy
/// Σ ½ overlap² over sphere pairs and sphere–wall contacts (unit stiffness and mass, time in
/// those units). Below random close packing its minimum is zero, a state without overlap;
/// FIRE gets there far faster than plain pushing apart, which oscillates among many contacts.
/// Pairs come from a Verlet list (contact distance plus a skin), rebuilt when a sphere may
/// have moved far enough to meet one not listed.
struct Relax<'a> {
    walls: &'a dyn Walls,
    /// Skin of the pair list, m.
    skin_m: f64,
    /// Largest radius the relaxation will see, m (sizes the grid cells).
    r_max_m: f64,
    /// Unit of the tolerances, m.
    radius_m: f64,
    pairs: Vec<(u32, u32)>,
    force: Vec<[f64; 3]>,
    velocity: Vec<[f64; 3]>,
    /// Centres when the list was built, m.
    built_at: Vec<[f64; 3]>,
}

/// FIRE's constants, the published ones but for the largest step, in units of
/// √(mass/stiffness): the published 1.0 overshoots and restarts again and again; 0.5, of the
/// order of the stable limit 2/√(4z) ≈ 0.4 of a sphere with z ≈ 7 contacts, took half the
/// iterations (1435 against 3102 for 20 000 spheres).
const FIRE_DT: f64 = 0.1;
const FIRE_DT_MAX: f64 = 0.5;
const FIRE_N_MIN: usize = 5;
const FIRE_ALPHA: f64 = 0.1;

impl<'a> Relax<'a> {
    fn new(walls: &'a dyn Walls, radius_m: f64, r_max_m: f64) -> Self {
        Relax {
            walls,
            skin_m: 0.5 * radius_m,
            r_max_m,
            radius_m,
            pairs: Vec::new(),
            force: Vec::new(),
            velocity: Vec::new(),
            built_at: Vec::new(),
        }
    }

    fn rebuild(&mut self, centres: &[[f64; 3]], radii: &[f64]) {
        let skin = self.skin_m;
        Grid::new(centres, 2.0 * self.r_max_m + skin).pairs(centres, |i, j| radii[i] + radii[j] + skin, &mut self.pairs);
        self.built_at.clear();
        self.built_at.extend_from_slice(centres);
    }

    /// Minimise until the largest overlap is below `tol` × R or `cap` iterations are done;
    /// returns the iterations made. Starts at rest with a fresh list (the radii may have grown).
    fn run(&mut self, centres: &mut [[f64; 3]], radii: &[f64], tol: f64, cap: usize) -> usize {
        self.rebuild(centres, radii);
        let n = centres.len();
        self.force.resize(n, [0.0; 3]);
        self.velocity.clear();
        self.velocity.resize(n, [0.0; 3]);
        let (mut dt, mut alpha, mut positive) = (FIRE_DT, FIRE_ALPHA, 0usize);
        for it in 0..cap {
            let worst = self.forces(centres, radii);
            if worst < tol * self.radius_m {
                return it;
            }
            let power: f64 = self.force.iter().zip(&self.velocity).map(|(f, v)| dot(*f, *v)).sum();
            if power > 0.0 {
                positive += 1;
                if positive > FIRE_N_MIN {
                    dt = (dt * 1.1).min(FIRE_DT_MAX);
                    alpha *= 0.99;
                }
            } else {
                // Going uphill: stop, and take smaller, more careful steps.
                positive = 0;
                dt *= 0.5;
                alpha = FIRE_ALPHA;
                self.velocity.iter_mut().for_each(|v| *v = [0.0; 3]);
            }
            self.step(centres, dt, alpha);
            let moved = centres.iter().zip(&self.built_at).map(|(c, b)| dist2(*c, *b)).fold(0.0, f64::max);
            if moved > (0.5 * self.skin_m).powi(2) {
                self.rebuild(centres, radii);
            }
        }
        cap
    }

    /// Semi-implicit Euler step, the velocity turned towards the force by `alpha` (FIRE's mix).
    fn step(&mut self, centres: &mut [[f64; 3]], dt: f64, alpha: f64) {
        let v2: f64 = self.velocity.iter().map(|v| dot(*v, *v)).sum();
        let f2: f64 = self.force.iter().map(|f| dot(*f, *f)).sum();
        let mix = if f2 > 0.0 { alpha * (v2 / f2).sqrt() } else { 0.0 };
        for ((c, v), f) in centres.iter_mut().zip(&mut self.velocity).zip(&self.force) {
            for k in 0..3 {
                v[k] = (1.0 - alpha) * (v[k] + dt * f[k]) + mix * f[k];
                c[k] += dt * v[k];
            }
        }
    }

    /// Overlap forces into `self.force`; returns the largest overlap (pairs and walls), m.
    fn forces(&mut self, centres: &[[f64; 3]], radii: &[f64]) -> f64 {
        let mut worst = 0.0f64;
        for ((f, c), &ri) in self.force.iter_mut().zip(centres).zip(radii) {
            // Walls push back by their overlap, as a sphere would.
            let (push, overlap) = self.walls.push(*c, ri);
            *f = push;
            worst = worst.max(overlap);
        }
        for &(i, j) in &self.pairs {
            let (i, j) = (i as usize, j as usize);
            let d = sub(centres[j], centres[i]);
            let len = norm(d);
            let overlap = radii[i] + radii[j] - len;
            if overlap <= 0.0 {
                continue;
            }
            worst = worst.max(overlap);
            // Coincident centres (measure zero, but possible): part them along x.
            let n = if len > 0.0 { d.map(|v| v / len) } else { [1.0, 0.0, 0.0] };
            for (k, nk) in n.iter().enumerate() {
                self.force[i][k] -= overlap * nk;
                self.force[j][k] += overlap * nk;
            }
        }
        worst
    }
}

/// Spheres reordered in z slabs of `slab_m`, then y rows of the same width, then by x, which
/// keeps neighbours close in memory.
fn layer_order(centres: Vec<[f64; 3]>, radii: Vec<f64>, lo: [f64; 3], slab_m: f64) -> (Vec<[f64; 3]>, Vec<f64>) {
    let key = |c: &[f64; 3]| (((c[2] - lo[2]) / slab_m).floor(), ((c[1] - lo[1]) / slab_m).floor(), c[0]);
    let mut order: Vec<usize> = (0..centres.len()).collect();
    // Stable: equal keys keep generation order.
    order.sort_by(|&a, &b| {
        let (ka, kb) = (key(&centres[a]), key(&centres[b]));
        ka.0.total_cmp(&kb.0).then(ka.1.total_cmp(&kb.1)).then(ka.2.total_cmp(&kb.2))
    });
    (order.iter().map(|&i| centres[i]).collect(), order.iter().map(|&i| radii[i]).collect())
}

/// The pairs (i < j, sorted) whose gap is below `gap_m`.
fn bonds_within(centres: &[[f64; 3]], radii: &[f64], gap_m: f64) -> Vec<(u32, u32)> {
    bonds_within_by(centres, radii, gap_m, |_, _| gap_m)
}

/// The pairs (i < j, sorted) whose gap is below `gap_m(i, j)`, at most `gap_max_m` (m).
fn bonds_within_by(centres: &[[f64; 3]], radii: &[f64], gap_max_m: f64, gap_m: impl Fn(usize, usize) -> f64) -> Vec<(u32, u32)> {
    let r_max = radii.iter().copied().fold(0.0, f64::max);
    let mut out = Vec::new();
    Grid::new(centres, 2.0 * r_max + gap_max_m).pairs(centres, |i, j| radii[i] + radii[j] + gap_m(i, j), &mut out);
    out.sort_unstable();
    out
}

/// A uniform cell grid over the centres' bounding box, cells no smaller than the largest
/// distance asked of [`Grid::pairs`], so each pair lies in neighbouring cells.
struct Grid {
    lo: [f64; 3],
    inv_cell: f64,
    dims: [usize; 3],
    /// Start of each cell's entries in `items` (one more than the cells).
    start: Vec<u32>,
    /// Sphere indices grouped by cell, ascending within a cell.
    items: Vec<u32>,
}

impl Grid {
    fn new(centres: &[[f64; 3]], cell_m: f64) -> Self {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for c in centres {
            for k in 0..3 {
                lo[k] = lo[k].min(c[k]);
                hi[k] = hi[k].max(c[k]);
            }
        }
        let dims: [usize; 3] = std::array::from_fn(|k| if centres.is_empty() { 1 } else { ((hi[k] - lo[k]) / cell_m) as usize + 1 });
        let mut g = Grid { lo, inv_cell: 1.0 / cell_m, dims, start: vec![0; dims[0] * dims[1] * dims[2] + 1], items: vec![0; centres.len()] };
        // Counting sort by cell: deterministic, and ascending indices within each cell.
        for c in centres {
            let cell = g.cell(c);
            g.start[cell + 1] += 1;
        }
        for i in 1..g.start.len() {
            g.start[i] += g.start[i - 1];
        }
        let mut fill = g.start.clone();
        for (i, c) in centres.iter().enumerate() {
            let cell = g.cell(c);
            g.items[fill[cell] as usize] = i as u32;
            fill[cell] += 1;
        }
        g
    }

    fn coords(&self, c: &[f64; 3]) -> [usize; 3] {
        std::array::from_fn(|k| (((c[k] - self.lo[k]) * self.inv_cell) as usize).min(self.dims[k] - 1))
    }

    fn cell(&self, c: &[f64; 3]) -> usize {
        let [x, y, z] = self.coords(c);
        x + self.dims[0] * (y + self.dims[1] * z)
    }

    /// Into `out` (cleared first): every pair i < j closer than `reach(i, j)` (m), once, in
    /// ascending i.
    fn pairs(&self, centres: &[[f64; 3]], reach: impl Fn(usize, usize) -> f64, out: &mut Vec<(u32, u32)>) {
        out.clear();
        for (i, c) in centres.iter().enumerate() {
            let at = self.coords(c);
            let range = |k: usize| at[k].saturating_sub(1)..=(at[k] + 1).min(self.dims[k] - 1);
            for z in range(2) {
                for y in range(1) {
                    for x in range(0) {
                        let cell = x + self.dims[0] * (y + self.dims[1] * z);
                        for &j in &self.items[self.start[cell] as usize..self.start[cell + 1] as usize] {
                            let j = j as usize;
                            if j > i && dist2(*c, centres[j]) < reach(i, j).powi(2) {
                                out.push((i as u32, j as u32));
                            }
                        }
                    }
                }
            }
        }
    }
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn norm(a: [f64; 3]) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

fn dist2(a: [f64; 3], b: [f64; 3]) -> f64 {
    let d = sub(a, b);
    d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    dist2(a, b).sqrt()
}

/// Structure of a packing measured in an inner box (away from the walls' disturbance).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fabric {
    /// Volume of the spheres whose centre lies in the inner box, each counted whole, over the
    /// inner box's volume (dimensionless). Unbiased when the box is much larger than a sphere.
    pub packing_fraction: f64,
    /// Mean number of bonds of the spheres whose centre lies in the inner box.
    pub coordination: f64,
    /// Eigenvalues of the fabric tensor F = ⟨n nᵀ⟩, ascending (dimensionless, summing to 1;
    /// 1/3 each when isotropic). Zero when there is no bond.
    pub eigenvalues: [f64; 3],
    /// Largest over smallest eigenvalue (1 when isotropic; NaN or ∞ without bonds).
    pub eigen_ratio: f64,
}

/// Packing fraction, coordination and fabric of `p` measured on the spheres whose centre lies
/// in `inner`. The fabric tensor averages n nᵀ over every bond end at such a sphere (n the
/// unit vector along the bond; a bond with both ends inside counts twice, as it does in the
/// coordination), so it is the per-sphere average that matches the coordination. With no
/// sphere in `inner` the coordination is NaN.
pub fn fabric(p: &Packing, inner: &Box3) -> Fabric {
    let inside: Vec<bool> = p.centres_m.iter().map(|&c| inner.contains(c)).collect();
    let volume: f64 = p.radii_m.iter().zip(&inside).filter(|(_, in_)| **in_).map(|(r, _)| 4.0 / 3.0 * PI * r.powi(3)).sum();
    let count = inside.iter().filter(|&&b| b).count();
    let mut f = nalgebra::Matrix3::<f64>::zeros();
    let mut ends = 0usize;
    for &(i, j) in &p.bonds {
        let (i, j) = (i as usize, j as usize);
        let d = sub(p.centres_m[j], p.centres_m[i]);
        let n = nalgebra::Vector3::from(d) / norm(d);
        let weight = inside[i] as usize + inside[j] as usize;
        f += n * n.transpose() * weight as f64;
        ends += weight;
    }
    if ends > 0 {
        f /= ends as f64;
    }
    let mut eigenvalues: [f64; 3] = nalgebra::SymmetricEigen::new(f).eigenvalues.into();
    eigenvalues.sort_by(f64::total_cmp);
    Fabric {
        packing_fraction: volume / inner.volume_m3(),
        coordination: ends as f64 / count as f64,
        eigenvalues,
        eigen_ratio: eigenvalues[2] / eigenvalues[0],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(lo: f64, hi: f64) -> Box3 {
        Box3 { x_min_m: lo, x_max_m: hi, y_min_m: lo, y_max_m: hi, z_min_m: lo, z_max_m: hi }
    }

    /// Largest overlap over all pairs, m.
    fn max_overlap(p: &Packing) -> f64 {
        let mut pairs = Vec::new();
        Grid::new(&p.centres_m, 2.0 * p.radii_m.iter().copied().fold(0.0, f64::max))
            .pairs(&p.centres_m, |i, j| p.radii_m[i] + p.radii_m[j], &mut pairs);
        pairs.iter().map(|&(i, j)| p.radii_m[i as usize] + p.radii_m[j as usize] - dist(p.centres_m[i as usize], p.centres_m[j as usize])).fold(0.0, f64::max)
    }

    // fcc with R = 1: planes at 1 + k√2. An inner box with faces midway between planes
    // (k + ½) encloses whole lattice cells: the fraction is exact, not a surface estimate.
    const H: f64 = std::f64::consts::SQRT_2;

    fn fcc_inner() -> Box3 {
        cube(1.0 + 1.5 * H, 1.0 + 11.5 * H)
    }

    fn fcc_box() -> Packing {
        fcc(&cube(0.0, 2.0 + 13.0 * H + 0.5), 1.0).unwrap()
    }

    #[test]
    fn fcc_interior_packing_fraction_is_close_packing() {
        let f = fabric(&fcc_box(), &fcc_inner());
        let expected = PI / (3.0 * 2f64.sqrt());
        assert!((f.packing_fraction / expected - 1.0).abs() < 0.02, "fraction {}", f.packing_fraction);
    }

    #[test]
    fn fcc_interior_coordination_is_twelve() {
        let p = fcc_box();
        let mut deg = vec![0; p.centres_m.len()];
        for &(i, j) in &p.bonds {
            deg[i as usize] += 1;
            deg[j as usize] += 1;
        }
        let inner = fcc_inner();
        assert!(p.centres_m.iter().zip(&deg).filter(|(c, _)| inner.contains(**c)).all(|(_, &d)| d == 12));
        assert_eq!(*deg.iter().max().unwrap(), 12);
        assert_eq!(fabric(&p, &inner).coordination, 12.0);
    }

    #[test]
    fn fcc_fabric_is_isotropic() {
        let f = fabric(&fcc_box(), &fcc_inner());
        assert!((f.eigen_ratio - 1.0).abs() < 1e-9, "eigenvalues {:?}", f.eigenvalues);
        assert!(f.eigenvalues.iter().all(|e| (e - 1.0 / 3.0).abs() < 1e-9));
    }

    #[test]
    fn fcc_spheres_touch_and_stay_inside() {
        let b = cube(0.0, 2.0 + 13.0 * H + 0.5);
        let p = fcc(&b, 1.0).unwrap();
        assert!(p.centres_m.iter().all(|&c| c.iter().all(|&v| (1.0..=b.x_max_m - 1.0).contains(&v))));
        assert!(p.bonds.iter().all(|&(i, j)| (dist(p.centres_m[i as usize], p.centres_m[j as usize]) - 2.0).abs() < 1e-12));
        assert!(max_overlap(&p) < 1e-12);
    }

    // A cube of side 24R holds about 2900 spheres; the inner cube keeps 3R from the walls.
    const R: f64 = 0.01;
    const GAP: f64 = 0.1;

    fn dense_box() -> Box3 {
        cube(0.0, 26.0 * R)
    }

    fn dense_inner() -> Box3 {
        cube(4.0 * R, 22.0 * R)
    }

    #[test]
    fn random_dense_is_seeded() {
        let a = random_dense(&dense_box(), R, 7, GAP).unwrap();
        let b = random_dense(&dense_box(), R, 7, GAP).unwrap();
        let bits = |p: &Packing| p.centres_m.iter().flatten().chain(&p.radii_m).map(|v| v.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&a), bits(&b));
        assert_eq!(a.bonds, b.bonds);
        let c = random_dense(&dense_box(), R, 8, GAP).unwrap();
        assert_ne!(bits(&a), bits(&c));
    }

    #[test]
    fn random_dense_stays_inside_without_overlap() {
        let b = dense_box();
        let p = random_dense(&b, R, 7, GAP).unwrap();
        for (c, &r) in p.centres_m.iter().zip(&p.radii_m) {
            assert!(c.iter().zip(b.lo()).zip(b.hi()).all(|((&v, lo), hi)| v - r >= lo && v + r <= hi), "{c:?} r {r}");
            assert!(((1.0 - RADIUS_SPREAD) * R * (1.0 - MAX_OVERLAP_RATIO)..=(1.0 + RADIUS_SPREAD) * R).contains(&r));
        }
        let worst = max_overlap(&p);
        eprintln!("random_dense: {} spheres, max overlap {:.3e} R", p.centres_m.len(), worst / R);
        assert!(worst <= MAX_OVERLAP_RATIO * R, "max overlap {} R", worst / R);
    }

    #[test]
    fn random_dense_is_dense_isotropic_and_connected() {
        let p = random_dense(&dense_box(), R, 7, GAP).unwrap();
        let f = fabric(&p, &dense_inner());
        let whole: f64 = p.radii_m.iter().map(|r| 4.0 / 3.0 * PI * r.powi(3)).sum::<f64>() / p.volume_m3;
        eprintln!(
            "random_dense: {} spheres, box fraction {whole:.4}, interior fraction {:.4}, coordination {:.3} (gap {GAP} R), eigenvalues {:?}, ratio {:.4}",
            p.centres_m.len(),
            f.packing_fraction,
            f.coordination,
            f.eigenvalues,
            f.eigen_ratio
        );
        assert!(p.centres_m.len() >= 2000);
        assert!((0.58..=0.66).contains(&f.packing_fraction), "fraction {}", f.packing_fraction);
        assert!(f.eigen_ratio < 1.15, "eigen ratio {}", f.eigen_ratio);
        assert!((5.0..=10.0).contains(&f.coordination), "coordination {}", f.coordination);
    }

    /// The figures of the 20 000-sphere packing: `cargo test --release --lib packing3d -- --ignored --nocapture`.
    #[test]
    #[ignore]
    fn random_dense_20k_timing() {
        let t = std::time::Instant::now();
        let p = random_dense(&cube(0.0, 53.0 * R), R, 1, GAP).unwrap();
        let f = fabric(&p, &cube(4.0 * R, 49.0 * R));
        eprintln!("20k: {} spheres in {:.2} s, {f:?}, max overlap {:.3e} R", p.centres_m.len(), t.elapsed().as_secs_f64(), max_overlap(&p) / R);
    }

    #[test]
    fn random_dense_fits_thin_and_tiny_boxes() {
        // A slab two to three spheres thick, a long bar, a cube with room for one sphere: the
        // walls' share is large, yet the relaxation converges (no radius shrunk, no overlap).
        let slab = Box3 { z_max_m: 4.0 * R, ..cube(0.0, 30.0 * R) };
        let bar = Box3 { x_max_m: 100.0 * R, ..cube(0.0, 6.0 * R) };
        for (b, seed) in [(slab, 1), (bar, 2), (cube(0.0, 3.0 * R), 3)] {
            let p = random_dense(&b, R, seed, GAP).unwrap();
            assert!(!p.centres_m.is_empty());
            assert!(p.radii_m.iter().all(|&r| ((1.0 - RADIUS_SPREAD) * R..=(1.0 + RADIUS_SPREAD) * R).contains(&r)));
            assert!(p.centres_m.iter().zip(&p.radii_m).all(|(c, &r)| (0..3).all(|k| c[k] - r >= b.lo()[k] && c[k] + r <= b.hi()[k])));
            assert!(max_overlap(&p) <= 0.0, "{b:?}: overlap {} R", max_overlap(&p) / R);
        }
    }

    #[test]
    fn bad_box_or_radius_names_the_field() {
        let field = |e: Error| match e {
            Error::Input { field, .. } => field,
            other => panic!("{other:?}"),
        };
        let flat = Box3 { z_max_m: 0.0, ..cube(0.0, 1.0) };
        assert_eq!(field(flat.validate("target.box").unwrap_err()), "target.box");
        assert_eq!(field(fcc(&flat, 0.1).unwrap_err()), "box");
        assert_eq!(field(random_dense(&Box3 { x_min_m: f64::NAN, ..cube(0.0, 1.0) }, 0.1, 1, GAP).unwrap_err()), "box");
        assert_eq!(field(fcc(&cube(0.0, 1.0), -0.1).unwrap_err()), "radius_m");
        assert_eq!(field(random_dense(&cube(0.0, 1.0), 0.0, 1, GAP).unwrap_err()), "radius_m");
        assert_eq!(field(random_dense(&cube(0.0, 1.0), 0.45, 1, GAP).unwrap_err()), "radius_m");
        assert_eq!(field(random_dense(&cube(0.0, 1.0), 0.1, 1, 2.0).unwrap_err()), "bond_gap_ratio");
    }
}
