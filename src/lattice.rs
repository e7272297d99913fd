//! Lattice generators: simple cubic, close-packed and irregular assemblies of equal disks
//! filling a rectangle, with the bonds between touching (or, irregular, nearly touching)
//! neighbours.
//!
//! Element mass is the material's density times the area each element represents (its
//! lattice cell: 4R² square, 2√3R² hexagonal; the rectangle's area over the count for the
//! irregular packing), so the assembly has the continuum's density; the rotational inertia is
//! that of a uniform disk of that mass, mR²/2.

use crate::error::{Error, Result};
use crate::broad_phase::BroadPhase;

/// An axis-aligned rectangle, m.
#[derive(Debug, Clone, Copy, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Rect {
    /// Left edge, m.
    pub x_min_m: f64,
    /// Right edge, m.
    pub x_max_m: f64,
    /// Bottom edge, m.
    pub y_min_m: f64,
    /// Top edge, m.
    pub y_max_m: f64,
}

impl Rect {
    /// True when (x, y) lies inside or on the boundary.
    pub fn contains(&self, x: f64, y: f64) -> bool {
        x >= self.x_min_m && x <= self.x_max_m && y >= self.y_min_m && y <= self.y_max_m
    }

    /// Area, m².
    pub fn area_m2(&self) -> f64 {
        (self.x_max_m - self.x_min_m) * (self.y_max_m - self.y_min_m)
    }

    /// Check the rectangle is proper; `field` names it in messages.
    pub fn validate(&self, field: &str) -> Result<()> {
        let finite = [self.x_min_m, self.x_max_m, self.y_min_m, self.y_max_m].iter().all(|v| v.is_finite());
        if !finite || self.x_max_m <= self.x_min_m || self.y_max_m <= self.y_min_m {
            return Err(Error::input(field, format!("needs finite x_min_m < x_max_m and y_min_m < y_max_m, got {self:?}")));
        }
        Ok(())
    }
}

/// A generated assembly.
#[derive(Debug, Clone, PartialEq)]
pub struct Lattice {
    /// Element centres [x, y], m, in generation order (row by row).
    pub centres: Vec<[f64; 2]>,
    /// Element radius, m.
    pub radius_m: f64,
    /// Area each element stands for, m².
    pub area_per_element_m2: f64,
    /// Bonded pairs (i < j), sorted.
    pub bonds: Vec<(u32, u32)>,
}

/// Default bond gap ratio of irregular packings.
pub const IRREGULAR_BOND_GAP: f64 = 0.35;

/// Relative tolerance on "touching" for the regular lattices' bonds.
pub(crate) const TOUCH: f64 = 1e-9;

/// The pairs of `centres` (disks of radius `radius_m`) whose gap is below `margin_m`.
pub(crate) fn bonds_within(centres: &[[f64; 2]], radius_m: f64, margin_m: f64) -> Vec<(u32, u32)> {
    let r = vec![radius_m; centres.len()];
    let mut out = Vec::new();
    BroadPhase::default().pairs(|e| centres[e], &r, |_| 0.5 * margin_m, None, false, &mut out);
    out
}

fn rows(lo: f64, hi: f64, pitch: f64) -> usize {
    if hi < lo {
        0
    } else {
        ((hi - lo) / pitch + 1e-9).floor() as usize + 1
    }
}

/// Most elements a lattice or packing may have: a typo must not fill the memory or take hours
/// before it is refused (six times the largest level: 2D level 4 has 3.4 million disks).
pub const MAX_ELEMENTS: usize = 20_000_000;

fn check_fits(rect: &Rect, radius_m: f64) -> Result<()> {
    if !(radius_m.is_finite() && radius_m > 0.0) {
        return Err(Error::input("element_radius_m", format!("must be > 0, got {radius_m}")));
    }
    if rect.x_max_m - rect.x_min_m < 2.0 * radius_m || rect.y_max_m - rect.y_min_m < 2.0 * radius_m {
        return Err(Error::input("element_radius_m", format!("{radius_m} m is too large for the rectangle {rect:?}")));
    }
    // Close-packed is the densest: 2√3 R² per disk.
    let n = rect.area_m2() / (2.0 * 3f64.sqrt() * radius_m * radius_m);
    if !(n <= MAX_ELEMENTS as f64) {
        return Err(Error::input("element_radius_m", format!("{radius_m} m in {rect:?} would make about {n:.3e} elements, more than {}", MAX_ELEMENTS)));
    }
    Ok(())
}

/// Square lattice of spacing 2R; centres in [x_min + R, x_max − R] × [y_min + R, y_max − R].
pub fn simple_cubic(rect: &Rect, radius_m: f64) -> Result<Lattice> {
    check_fits(rect, radius_m)?;
    let r = radius_m;
    let nx = rows(rect.x_min_m + r, rect.x_max_m - r, 2.0 * r);
    let ny = rows(rect.y_min_m + r, rect.y_max_m - r, 2.0 * r);
    let centres: Vec<[f64; 2]> = (0..ny)
        .flat_map(|j| (0..nx).map(move |i| [rect.x_min_m + r + 2.0 * r * i as f64, rect.y_min_m + r + 2.0 * r * j as f64]))
        .collect();
    let bonds = bonds_within(&centres, r, 2.0 * r * TOUCH);
    Ok(Lattice { centres, radius_m: r, area_per_element_m2: 4.0 * r * r, bonds })
}

/// Hexagonal lattice, rows of pitch √3 R, odd rows shifted by R; centres inside the rectangle
/// shrunk by R.
pub fn close_packed(rect: &Rect, radius_m: f64) -> Result<Lattice> {
    check_fits(rect, radius_m)?;
    let r = radius_m;
    let ny = rows(rect.y_min_m + r, rect.y_max_m - r, 3f64.sqrt() * r);
    let mut centres = Vec::new();
    for j in 0..ny {
        let y = rect.y_min_m + r + 3f64.sqrt() * r * j as f64;
        let x0 = rect.x_min_m + r + if j % 2 == 1 { r } else { 0.0 };
        for i in 0..rows(x0, rect.x_max_m - r, 2.0 * r) {
            centres.push([x0 + 2.0 * r * i as f64, y]);
        }
    }
    let bonds = bonds_within(&centres, r, 2.0 * r * TOUCH);
    Ok(Lattice { centres, radius_m: r, area_per_element_m2: 2.0 * 3f64.sqrt() * r * r, bonds })
}

/// SplitMix64 (Steele, Lea & Flood 2014): a tiny, well-tested generator, pinned here so a seed
/// means the same mesh forever (the crate's one seeded generator).
pub(crate) struct SplitMix64(pub(crate) u64);

impl SplitMix64 {
    pub(crate) fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1) with 53 random bits.
    pub(crate) fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Irregular assembly, seeded and deterministic:
/// 1. maximal Poisson-disk sampling (Bridson 2007) with minimum spacing 1.6R, which fills the
///    rectangle to about 0.82 of close packing with no lattice directions;
/// 2. Jacobi relaxation of the overlaps until no two disks of radius R overlap (more than
///    1e-9 R), which turns the sample into a dense disordered packing;
/// 3. bonds between pairs whose gap is at most `bond_gap_ratio` × 2R (rest length = the
///    initial distance). 0.35 (`IRREGULAR_BOND_GAP`) gives a mean coordination of about 5,
///    with bonds shorter than the hexagonal second-neighbour distance 2√3 R.
///
/// The bond network has no preferred fracture direction (its fabric tensor is isotropic to
/// sampling error; a test checks it). This replaces the source's megaclustering.
pub fn irregular(rect: &Rect, radius_m: f64, seed: u64, bond_gap_ratio: f64) -> Result<Lattice> {
    check_fits(rect, radius_m)?;
    // Slow to make (the relaxation: about 1.7 s for the penetration beam at level 1), and a
    // scene asks for its target's several times while it is built (its front face places the
    // projectile; the model makes its bodies): the last few made are kept, by their inputs'
    // bits, and handed out as copies.
    type Key = ([u64; 4], u64, u64, u64);
    static MADE: std::sync::Mutex<Vec<(Key, std::sync::Arc<Lattice>)>> = std::sync::Mutex::new(Vec::new());
    const KEEP: usize = 8;
    let key: Key = ([rect.x_min_m, rect.x_max_m, rect.y_min_m, rect.y_max_m].map(f64::to_bits), radius_m.to_bits(), seed, bond_gap_ratio.to_bits());
    let made = |m: &mut Vec<(Key, std::sync::Arc<Lattice>)>| m.iter().find(|(k, _)| *k == key).map(|(_, l)| l.clone());
    if let Some(l) = made(&mut MADE.lock().unwrap_or_else(|e| e.into_inner())) {
        return Ok((*l).clone());
    }
    let l = std::sync::Arc::new(make_irregular(rect, radius_m, seed, bond_gap_ratio)?);
    let mut m = MADE.lock().unwrap_or_else(|e| e.into_inner());
    if made(&mut m).is_none() {
        if m.len() == KEEP {
            m.remove(0);
        }
        m.push((key, l.clone()));
    }
    Ok((*l).clone())
}

/// [`irregular`] made afresh.
fn make_irregular(rect: &Rect, radius_m: f64, seed: u64, bond_gap_ratio: f64) -> Result<Lattice> {
    if !(bond_gap_ratio.is_finite() && (0.0..=1.0).contains(&bond_gap_ratio)) {
        return Err(Error::input("bond_gap_ratio", format!("must lie in [0, 1], got {bond_gap_ratio}")));
    }
    let r = radius_m;
    let (x0, x1, y0, y1) = (rect.x_min_m + r, rect.x_max_m - r, rect.y_min_m + r, rect.y_max_m - r);
    let mut centres = poisson_disk([x0, x1, y0, y1], 1.6 * r, seed);
    relax_overlaps(&mut centres, r, [x0, x1, y0, y1]);
    // Row-by-row order (as the regular lattices) keeps neighbours close in memory.
    centres.sort_by(|a, b| {
        let (ra, rb) = (((a[1] - y0) / (2.0 * r)).floor(), ((b[1] - y0) / (2.0 * r)).floor());
        ra.total_cmp(&rb).then(a[0].total_cmp(&b[0]))
    });
    let bonds = bonds_within(&centres, r, 2.0 * r * bond_gap_ratio);
    let area = rect.area_m2() / centres.len() as f64;
    Ok(Lattice { centres, radius_m: r, area_per_element_m2: area, bonds })
}

/// Bridson's maximal Poisson-disk sampling of the box [x0, x1] × [y0, y1] with spacing `min_d`.
fn poisson_disk(b: [f64; 4], min_d: f64, seed: u64) -> Vec<[f64; 2]> {
    let [x0, x1, y0, y1] = b;
    let cell = min_d / 2f64.sqrt();
    let (gw, gh) = (((x1 - x0) / cell).floor() as usize + 1, ((y1 - y0) / cell).floor() as usize + 1);
    let mut grid = vec![u32::MAX; gw * gh];
    let mut rng = SplitMix64(seed ^ 0x5EED_DE35_EE70_0001);
    let mut centres: Vec<[f64; 2]> = Vec::new();
    let mut active: Vec<u32> = Vec::new();
    let gcoord = |p: [f64; 2]| (((p[0] - x0) / cell) as usize).min(gw - 1) + gw * (((p[1] - y0) / cell) as usize).min(gh - 1);
    let fits = |p: [f64; 2], centres: &[[f64; 2]], grid: &[u32]| -> bool {
        if p[0] < x0 || p[0] > x1 || p[1] < y0 || p[1] > y1 {
            return false;
        }
        let (gx, gy) = (((p[0] - x0) / cell) as isize, ((p[1] - y0) / cell) as isize);
        for yy in (gy - 2).max(0)..=(gy + 2).min(gh as isize - 1) {
            for xx in (gx - 2).max(0)..=(gx + 2).min(gw as isize - 1) {
                let q = grid[yy as usize * gw + xx as usize];
                if q != u32::MAX {
                    let c = centres[q as usize];
                    if (c[0] - p[0]).powi(2) + (c[1] - p[1]).powi(2) < min_d * min_d {
                        return false;
                    }
                }
            }
        }
        true
    };
    let first = [x0 + rng.unit() * (x1 - x0), y0 + rng.unit() * (y1 - y0)];
    grid[gcoord(first)] = 0;
    centres.push(first);
    active.push(0);
    while !active.is_empty() {
        let pick = (rng.next_u64() % active.len() as u64) as usize;
        let base = centres[active[pick] as usize];
        let mut placed = false;
        for _ in 0..30 {
            let (a, rr) = (rng.unit() * std::f64::consts::TAU, min_d * (1.0 + rng.unit()));
            let p = [base[0] + rr * a.cos(), base[1] + rr * a.sin()];
            if fits(p, &centres, &grid) {
                grid[gcoord(p)] = centres.len() as u32;
                active.push(centres.len() as u32);
                centres.push(p);
                placed = true;
                break;
            }
        }
        if !placed {
            active.swap_remove(pick);
        }
    }
    centres
}

/// Push overlapping disks of radius `r` apart (each moves half the overlap, accumulated per
/// sweep, then clamped to the box) until the largest overlap is below 1e-9 r.
fn relax_overlaps(centres: &mut [[f64; 2]], r: f64, b: [f64; 4]) {
    let radii = vec![r; centres.len()];
    let mut bp = BroadPhase::default();
    let mut pairs = Vec::new();
    let mut shift = vec![[0.0f64; 2]; centres.len()];
    for _ in 0..20_000 {
        bp.pairs(|e| centres[e], &radii, |_| 0.0, None, false, &mut pairs);
        let mut worst = 0.0f64;
        shift.iter_mut().for_each(|s| *s = [0.0, 0.0]);
        for &(i, j) in &pairs {
            let (p, q) = (centres[i as usize], centres[j as usize]);
            let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
            let d = (dx * dx + dy * dy).sqrt().max(1e-12 * r);
            let overlap = 2.0 * r - d;
            worst = worst.max(overlap);
            let (ux, uy) = (0.5 * overlap * dx / d, 0.5 * overlap * dy / d);
            shift[i as usize][0] -= ux;
            shift[i as usize][1] -= uy;
            shift[j as usize][0] += ux;
            shift[j as usize][1] += uy;
        }
        if worst < 1e-9 * r {
            return;
        }
        for (c, s) in centres.iter_mut().zip(&shift) {
            c[0] = (c[0] + s[0]).clamp(b[0], b[1]);
            c[1] = (c[1] + s[1]).clamp(b[2], b[3]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const R: Rect = Rect { x_min_m: 0.0, x_max_m: 1.0, y_min_m: 0.0, y_max_m: 0.5 };

    #[test]
    fn close_packed_interior_has_six_bonds() {
        let l = close_packed(&R, 0.05).unwrap();
        let mut deg = vec![0; l.centres.len()];
        for &(i, j) in &l.bonds {
            deg[i as usize] += 1;
            deg[j as usize] += 1;
        }
        assert_eq!(*deg.iter().max().unwrap(), 6);
        // 10 columns, rows alternate 10 and 9, ⌊(0.4/(√3·0.05))⌋ + 1 = 5 rows.
        assert_eq!(l.centres.len(), 10 + 9 + 10 + 9 + 10);
    }

    #[test]
    fn simple_cubic_counts_and_bonds() {
        let l = simple_cubic(&R, 0.05).unwrap();
        assert_eq!(l.centres.len(), 50);
        assert_eq!(l.bonds.len(), 5 * 9 + 10 * 4);
    }

    #[test]
    fn irregular_is_seeded_isotropic_and_non_overlapping() {
        const GAP: f64 = 0.35;
        let rect = Rect { x_min_m: 0.0, x_max_m: 1.0, y_min_m: 0.0, y_max_m: 1.0 };
        let a = irregular(&rect, 0.01, 7, GAP).unwrap();
        assert_eq!(a, irregular(&rect, 0.01, 7, GAP).unwrap());
        assert_ne!(a.centres, irregular(&rect, 0.01, 8, GAP).unwrap().centres);
        // Fabric tensor of bond directions: isotropic is diag(1/2, 1/2).
        let (mut fxx, mut fxy) = (0.0, 0.0);
        for &(i, j) in &a.bonds {
            let (p, q) = (a.centres[i as usize], a.centres[j as usize]);
            let d = ((q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2)).sqrt();
            assert!((0.02 * (1.0 - 1e-8)..=0.02 * (1.0 + GAP) + 1e-12).contains(&d));
            let (nx, ny) = ((q[0] - p[0]) / d, (q[1] - p[1]) / d);
            fxx += nx * nx;
            fxy += nx * ny;
        }
        let nb = a.bonds.len() as f64;
        assert!((fxx / nb - 0.5).abs() < 0.02 && (fxy / nb).abs() < 0.02, "fabric {} {}", fxx / nb, fxy / nb);
        let coordination = 2.0 * nb / a.centres.len() as f64;
        let packing = a.centres.len() as f64 * std::f64::consts::PI * 1e-4;
        eprintln!("irregular: {} elements, coordination {coordination:.3}, packing fraction {packing:.3}", a.centres.len());
        assert!(coordination > 4.5, "coordination {coordination}");
    }
}
