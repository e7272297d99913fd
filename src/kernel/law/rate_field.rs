//! The rate part's velocity field: the strain rate of a bond measured over a fixed physical
//! length instead of over the bond (seed 000 eq 6.7 made mesh-objective).
//!
//! **Why.** Eq 6.7 takes ε̇ = |v·n| / L0, the bond's own relative velocity over its own length.
//! Where the velocity field is smooth on the scale of a bond that is the continuum's strain
//! rate, whatever the element size. Where it is not — the projectile's front, a wave front, a
//! crack opening — the lattice carries a velocity jump Δv across the few bonds it can resolve,
//! so the bond rate is Δv over a few bond lengths and grows as the elements shrink: each
//! halving of R raised the dynamic strengths and made the calibrated depth at 500 ft/s fall
//! 6.57 → 4.88 → 3.33 in over three levels. Rate-dependent strength is a property of a volume
//! of concrete, not of a bond (Klepaczko's criterion and the CEB laws were fitted to specimens
//! many aggregates across), and the steepest gradient concrete can carry is set by its
//! heterogeneity: the fracture process zone's width, about 2.7 aggregate sizes (Bažant &
//! Pijaudier-Cabot, "Measurement of characteristic length of nonlocal continuum", J. Eng.
//! Mech. 115(4), 1989). Integral-type nonlocal models average the variable that drives the
//! softening over that length (Pijaudier-Cabot & Bažant 1987; Bažant & Jirásek, "Nonlocal
//! integral formulations of plasticity and damage", J. Eng. Mech. 128(11), 2002); here the
//! variable is the velocity that the rate is read from.
//!
//! **What eq 6.7 becomes.** ε̇ = |(ṽ_j − ṽ_i)·n| / L0, with ṽ the velocity field smoothed over
//! the averaging length ℓ (`RateSpec::averaging_length_m`): a mass-weighted bilinear
//! transfer of the elements' velocities to the nodes of a square grid of spacing h = ℓ/2 and
//! back (the particle-to-grid and grid-to-particle transfers of the material point method). A
//! linear velocity field passes unchanged (so a resolved rate is the continuum's, as before);
//! a jump is spread over about ℓ, so the rate it gives is Δv/ℓ at any element size once the
//! mesh resolves ℓ (R ≤ ℓ/4). Each element's ṽ draws on the elements within ℓ of it. The grid
//! is fixed in space over the initial extent of the smoothed elements plus a margin; an
//! element outside it keeps its own velocity (free debris, whose bonds carry no rate of
//! interest). The transfer runs over the elements in index order on one thread, so the bits
//! do not depend on the thread count, and it is remade every step from the state, so a
//! restored checkpoint continues bit for bit without storing it.

/// The smoothed velocity field of the elements whose material measures its rate over a length,
/// in `D` dimensions (2: the 2D kernel's discs, 3: the 3D kernel's spheres; the same transfer,
/// bilinear or trilinear).
#[derive(Debug, Clone, PartialEq)]
pub struct RateField<const D: usize> {
    // Configuration, fixed when the model is built.
    /// Grid spacing h = ℓ/2, m.
    pub spacing_m: f64,
    /// 1/h, 1/m.
    inv_spacing: f64,
    /// The grid's lowest node, m.
    origin_m: [f64; D],
    /// Nodes along each axis.
    nodes: [usize; D],
    /// Index step of a node along each axis (1, then the product of the nodes before).
    strides: [usize; D],
    /// The elements smoothed, in index order.
    members: Vec<u32>,
    /// Symmetry planes (`kernel3d::mirror`) as (axis, the node index they pass through): the
    /// velocity across a plane is zero on it (the mirrored elements' momenta cancel there).
    planes: Vec<(usize, usize)>,
    // Scratch, remade every step.
    /// Per node: (Σ w m v (kg·m/s), Σ w m (kg)); then, for nodes with mass, the node's
    /// velocity (m/s) in the first.
    sums: Vec<([f64; D], f64)>,
    /// Per member: its cell and weights, as the transfer to the grid found them.
    cells: Vec<Option<(usize, [f64; 8])>>,
    /// The nodes the last transfer touched, each once: only they are cleared and normalised
    /// (a 3D grid has millions of nodes, the elements touch a few hundred thousand).
    touched: Vec<u32>,
    /// Per node: the transfer that last touched it (`epoch`).
    mark: Vec<u32>,
    /// The transfer's number.
    epoch: u32,
    /// Per element: its smoothed velocity, m/s (its own for elements outside the grid; 0 for
    /// elements not smoothed, whose bonds carry no averaged rate); empty when no element is
    /// smoothed.
    pub vel_mps: Vec<[f64; D]>,
}

impl<const D: usize> Default for RateField<D> {
    fn default() -> Self {
        RateField::new(Vec::new(), &[], 0, f64::INFINITY)
    }
}

impl<const D: usize> RateField<D> {
    /// Make a symmetry plane normal to `axis` at `at_m` (m) pass through a layer of nodes, on
    /// which the velocity across it is zero: the field the elements and their mirror images
    /// would give, to rounding (a cell beside the plane reads only the plane's nodes and its
    /// own side's; on the plane the images double the mass and cancel the normal momentum).
    pub fn mirror(&mut self, axis: usize, at_m: f64) {
        if let Some(k) = self.align(axis, at_m) {
            self.planes.push((axis, k));
        }
    }

    /// Shift the grid along `axis` so that a layer of nodes lies at `at_m` (m), one node more
    /// keeping the extent; returns that layer's index (None: no grid). A whole model symmetric
    /// about the plane then has the field its mirrored part has.
    pub fn align(&mut self, axis: usize, at_m: f64) -> Option<usize> {
        if self.members.is_empty() {
            return None;
        }
        let h = self.spacing_m;
        let k = ((at_m - self.origin_m[axis]) / h).ceil().max(0.0);
        self.origin_m[axis] = at_m - k * h;
        self.nodes[axis] += 1;
        for a in 1..D {
            self.strides[a] = self.strides[a - 1] * self.nodes[a - 1];
        }
        let count: usize = self.nodes.iter().product();
        (self.mark, self.sums, self.touched, self.epoch) = (vec![0; count], vec![([0.0; D], 0.0); count], Vec::new(), 0);
        Some(k as usize)
    }

    /// The 2^D corners of a cell.
    const CORNERS: usize = 1 << D;

    /// A field over `members` (element indices, ascending) at their initial positions
    /// `initial` with averaging length `length_m`, for a model of `elements` elements. The grid
    /// covers their extent plus half of its largest side each way (room for the target to bend
    /// and a plug to be pushed out).
    pub fn new(members: Vec<u32>, initial: &[[f64; D]], elements: usize, length_m: f64) -> RateField<D> {
        assert!(D == 2 || D == 3, "a rate field is 2D or 3D");
        let h = 0.5 * length_m;
        let (mut lo, mut hi) = ([f64::INFINITY; D], [f64::NEG_INFINITY; D]);
        for &e in &members {
            let p = initial[e as usize];
            for a in 0..D {
                lo[a] = lo[a].min(p[a]);
                hi[a] = hi[a].max(p[a]);
            }
        }
        // In 2D the largest side's half on every axis (a beam bends far below its depth); in 3D
        // each axis its own side's half (a slab's lateral sides would make the grid eight
        // times its volume for nothing).
        let largest = (0..D).map(|a| hi[a] - lo[a]).fold(f64::NEG_INFINITY, f64::max);
        let margin: [f64; D] = std::array::from_fn(|a| 0.5 * if D == 2 { largest } else { hi[a] - lo[a] } + 2.0 * h);
        let origin_m: [f64; D] = std::array::from_fn(|a| lo[a] - margin[a]);
        let empty = members.is_empty();
        let nodes: [usize; D] = std::array::from_fn(|a| if empty { 0 } else { ((hi[a] + margin[a] - origin_m[a]) / h).ceil() as usize + 1 });
        let mut strides = [1usize; D];
        for a in 1..D {
            strides[a] = strides[a - 1] * nodes[a - 1];
        }
        let count: usize = nodes.iter().product();
        RateField {
            spacing_m: h,
            inv_spacing: 1.0 / h,
            cells: Vec::new(),
            touched: Vec::new(),
            mark: vec![0; if empty { 0 } else { count }],
            epoch: 0,
            origin_m,
            nodes,
            strides,
            members,
            planes: Vec::new(),
            sums: vec![([0.0; D], 0.0); if empty { 0 } else { count }],
            vel_mps: if empty { Vec::new() } else { vec![[0.0; D]; elements] },
        }
    }

    /// The cell of `p` and the weights of its corners (corner c takes, along axis a, the upper
    /// node when bit a of c is set: lower-left, lower-right, upper-left, upper-right in 2D), or
    /// None outside the grid.
    #[inline(always)]
    fn cell(&self, p: [f64; 3]) -> Option<(usize, [f64; 8])> {
        let mut base = 0;
        let mut frac = [0.0; D];
        for a in 0..D {
            let f = (p[a] - self.origin_m[a]) * self.inv_spacing;
            // Also refuses NaN.
            if !(f >= 0.0 && f < (self.nodes[a] - 1) as f64) {
                return None;
            }
            let i = f as usize;
            base += i * self.strides[a];
            frac[a] = f - i as f64;
        }
        let mut w = [0.0; 8];
        for (c, wc) in w.iter_mut().enumerate().take(Self::CORNERS) {
            *wc = (0..D).fold(1.0, |acc, a| acc * if c >> a & 1 == 1 { frac[a] } else { 1.0 - frac[a] });
        }
        Some((base, w))
    }

    /// The node of corner `c` of the cell at `base`.
    #[inline(always)]
    fn corner(&self, base: usize, c: usize) -> usize {
        (0..D).fold(base, |k, a| if c >> a & 1 == 1 { k + self.strides[a] } else { k })
    }

    /// Remake the field from positions `pos`, half-step velocities `vel` and masses `mass`
    /// (the first D components of each).
    pub fn update(&mut self, pos: &[[f64; 3]], vel: &[[f64; 3]], mass: &[f64]) {
        if self.members.is_empty() {
            return;
        }
        for &node in &self.touched {
            self.sums[node as usize] = ([0.0; D], 0.0);
        }
        self.touched.clear();
        // A new mark; on wrapping, every old mark is cleared so none can match.
        self.epoch = self.epoch.wrapping_add(1);
        if self.epoch == 0 {
            self.mark.iter_mut().for_each(|m| *m = 0);
            self.epoch = 1;
        }
        self.cells.clear();
        for &e in &self.members {
            let e = e as usize;
            let c = self.cell(pos[e]);
            if let Some((k, w)) = c {
                let (m, v) = (mass[e], vel[e]);
                for (corner, &wn) in w.iter().enumerate().take(Self::CORNERS) {
                    let node = self.corner(k, corner);
                    if self.mark[node] != self.epoch {
                        self.mark[node] = self.epoch;
                        self.touched.push(node as u32);
                    }
                    let s = &mut self.sums[node];
                    let wm = wn * m;
                    for a in 0..D {
                        s.0[a] += wm * v[a];
                    }
                    s.1 += wm;
                }
            }
            self.cells.push(c);
        }
        // Node momenta become node velocities once, not once per element that reads them.
        for &node in &self.touched {
            let s = &mut self.sums[node as usize];
            if s.1 > 0.0 {
                let inv = 1.0 / s.1;
                s.0.iter_mut().for_each(|x| *x *= inv);
            }
            for &(a, k) in &self.planes {
                if node as usize / self.strides[a] % self.nodes[a] == k {
                    s.0[a] = 0.0;
                }
            }
        }
        for (&e, c) in self.members.iter().zip(&self.cells) {
            let e = e as usize;
            let v = vel[e];
            self.vel_mps[e] = match *c {
                None => std::array::from_fn(|a| v[a]),
                Some((k, w)) => {
                    let mut out = [0.0; D];
                    for (corner, &wn) in w.iter().enumerate().take(Self::CORNERS) {
                        // A node the element weighs (wn > 0) is one it added mass to; a node of
                        // weight 0 may hold nothing, and adds nothing.
                        let s = &self.sums[self.corner(k, corner)];
                        for a in 0..D {
                            out[a] += wn * s.0[a];
                        }
                    }
                    out
                }
            };
        }
    }

    /// The relative normal velocity of the pair (i, j) along the unit normal `n` as the rate
    /// reads it, m/s: the smoothed field's where the model has one (`rate_vel` the field's
    /// [`RateField::vel_mps`]), else the pair's own `vn_mps`.
    #[inline(always)]
    pub fn normal_velocity_mps(rate_vel: &[[f64; D]], i: u32, j: u32, n: [f64; D], vn_mps: f64) -> f64 {
        if rate_vel.is_empty() {
            return vn_mps;
        }
        let (a, b) = (rate_vel[i as usize], rate_vel[j as usize]);
        (1..D).fold((b[0] - a[0]) * n[0], |acc, k| acc + (b[k] - a[k]) * n[k])
    }

    /// True when no element is smoothed.
    pub fn is_empty(&self) -> bool {
        self.members.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A square patch of elements at spacing `d`, m.
    fn patch(n: usize, d: f64) -> (Vec<[f64; 3]>, Vec<[f64; 2]>, Vec<f64>) {
        let mut pos = Vec::new();
        for j in 0..n {
            for i in 0..n {
                // A slight irregularity, deterministic.
                let jit = 0.1 * d * (((i * 7 + j * 13) % 11) as f64 / 11.0 - 0.5);
                pos.push([i as f64 * d + jit, j as f64 * d - jit, 0.0]);
            }
        }
        let initial = pos.iter().map(|p| [p[0], p[1]]).collect();
        let mass = vec![1.0; pos.len()];
        (pos, initial, mass)
    }

    #[test]
    fn a_uniform_velocity_passes_unchanged() {
        let (pos, initial, mass) = patch(40, 0.01);
        let mut f = RateField::<2>::new((0..pos.len() as u32).collect(), &initial, pos.len(), 0.05);
        let vel = vec![[3.0, -2.0, 0.5]; pos.len()];
        f.update(&pos, &vel, &mass);
        for v in &f.vel_mps {
            assert!((v[0] - 3.0).abs() < 1e-12 && (v[1] + 2.0).abs() < 1e-12, "{v:?}");
        }
    }

    /// A linear field (uniform strain rate) is kept in the interior, more than ℓ from the
    /// patch's edges: the rate of a resolved field is the continuum's, as eq 6.7 gives it.
    #[test]
    fn a_linear_velocity_field_keeps_its_gradient_in_the_interior() {
        let d = 0.005;
        let (pos, initial, mass) = patch(80, d);
        let ell = 0.04;
        let mut f = RateField::<2>::new((0..pos.len() as u32).collect(), &initial, pos.len(), ell);
        let rate = 100.0;
        let vel: Vec<[f64; 3]> = pos.iter().map(|p| [rate * p[0], -0.5 * rate * p[1], 0.0]).collect();
        f.update(&pos, &vel, &mass);
        let side = 79.0 * d;
        let mut worst = 0.0f64;
        for (e, p) in pos.iter().enumerate() {
            if p[0] > 1.5 * ell && p[0] < side - 1.5 * ell && p[1] > 1.5 * ell && p[1] < side - 1.5 * ell {
                let v = f.vel_mps[e];
                worst = worst.max((v[0] - rate * p[0]).abs()).max((v[1] + 0.5 * rate * p[1]).abs());
            }
        }
        // The jitter makes the nodal means slightly off the field: within 2 % of the velocity
        // difference across one element.
        assert!(worst < 0.02 * rate * d, "worst {worst} m/s");
    }

    /// A velocity jump Δv is spread over about ℓ whatever the element size: the largest rate a
    /// pair of neighbours reads across it is Δv/ℓ within a factor the element size does not
    /// change, where the bond's own rate Δv/L0 doubles with each halving.
    #[test]
    fn a_velocity_jump_gives_the_same_peak_rate_at_any_element_size() {
        let ell = 0.04;
        let mut peaks = Vec::new();
        for d in [0.01, 0.005, 0.0025] {
            let n = (0.4 / d) as usize;
            let (pos, initial, mass) = patch(n, d);
            let mut f = RateField::<2>::new((0..pos.len() as u32).collect(), &initial, pos.len(), ell);
            let vel: Vec<[f64; 3]> = pos.iter().map(|p| [0.0, if p[0] < 0.2 { 10.0 } else { 0.0 }, 0.0]).collect();
            f.update(&pos, &vel, &mass);
            // Rates between horizontal neighbours in the middle row band.
            let mut peak = 0.0f64;
            for j in n / 3..2 * n / 3 {
                for i in 0..n - 1 {
                    let (a, b) = (j * n + i, j * n + i + 1);
                    let dx = pos[b][0] - pos[a][0];
                    peak = peak.max((f.vel_mps[b][1] - f.vel_mps[a][1]).abs() / dx);
                }
            }
            peaks.push(peak);
        }
        eprintln!("peak shear rates {peaks:?} 1/s (Δv/ℓ = {})", 10.0 / ell);
        for p in &peaks {
            assert!(*p > 0.5 * 10.0 / ell && *p < 2.5 * 10.0 / ell, "{peaks:?}");
        }
        let (lo, hi) = peaks.iter().fold((f64::INFINITY, 0.0f64), |a, &p| (a.0.min(p), a.1.max(p)));
        assert!(hi / lo < 1.3, "peak rates vary {:.3}× over a fourfold refinement: {peaks:?}", hi / lo);
    }

    #[test]
    fn elements_outside_the_grid_keep_their_own_velocity() {
        let (mut pos, initial, mass) = patch(10, 0.01);
        let mut f = RateField::<2>::new((0..pos.len() as u32).collect(), &initial, pos.len(), 0.02);
        pos[5][0] = 50.0;
        let mut vel = vec![[0.0; 3]; pos.len()];
        vel[5] = [7.0, 8.0, 0.0];
        f.update(&pos, &vel, &mass);
        assert_eq!(f.vel_mps[5], [7.0, 8.0]);
    }

    /// The same transfer in 3D (trilinear): a linear field is kept inside, and a field uniform
    /// along z is smoothed as the 2D transfer smooths it.
    #[test]
    fn in_three_dimensions_a_linear_field_is_kept_and_a_planar_one_smoothed_as_in_2d() {
        let cube = |n: usize, d: f64| -> (Vec<[f64; 3]>, Vec<f64>) {
            let mut pos = Vec::new();
            for k in 0..n {
                for j in 0..n {
                    for i in 0..n {
                        let jit = 0.1 * d * (((i * 7 + j * 13 + k * 5) % 11) as f64 / 11.0 - 0.5);
                        pos.push([i as f64 * d + jit, j as f64 * d - jit, k as f64 * d + 0.5 * jit]);
                    }
                }
            }
            let mass = vec![1.0; pos.len()];
            (pos, mass)
        };
        let (d, ell, rate) = (0.005, 0.04, 100.0);
        let (pos, mass) = cube(40, d);
        let mut f = RateField::<3>::new((0..pos.len() as u32).collect(), &pos, pos.len(), ell);
        let vel: Vec<[f64; 3]> = pos.iter().map(|p| [rate * p[0], -0.5 * rate * p[1], 0.25 * rate * p[2]]).collect();
        f.update(&pos, &vel, &mass);
        let side = 39.0 * d;
        let inside = |p: &[f64; 3]| p.iter().all(|&x| x > 1.5 * ell && x < side - 1.5 * ell);
        let mut worst = 0.0f64;
        for e in (0..pos.len()).filter(|&e| inside(&pos[e])) {
            let v = f.vel_mps[e];
            worst = worst.max((v[0] - vel[e][0]).abs()).max((v[1] - vel[e][1]).abs()).max((v[2] - vel[e][2]).abs());
        }
        assert!(worst < 0.02 * rate * d, "worst {worst} m/s");
        // A field that does not vary along z is smoothed in 3D as in 2D: layers of the 2D
        // patch stacked along z give the 2D field's velocities (so the 2D jump test, mesh
        // objectivity included, holds in 3D).
        let (p2, initial2, m2) = patch(60, 0.005);
        let layers = 9;
        let p3: Vec<[f64; 3]> = (0..layers).flat_map(|k| p2.iter().map(move |p| [p[0], p[1], k as f64 * 0.005])).collect();
        let vel2: Vec<[f64; 3]> = p2.iter().map(|p| [0.0, if p[0] < 0.15 { 10.0 } else { 0.0 }, 0.0]).collect();
        let vel3: Vec<[f64; 3]> = (0..layers).flat_map(|_| vel2.iter().copied()).collect();
        let m3 = vec![1.0; p3.len()];
        let mut f2 = RateField::<2>::new((0..p2.len() as u32).collect(), &initial2, p2.len(), ell);
        let mut f3 = RateField::<3>::new((0..p3.len() as u32).collect(), &p3, p3.len(), ell);
        f2.update(&p2, &vel2, &m2);
        f3.update(&p3, &vel3, &m3);
        let middle = (layers / 2) * p2.len();
        for e in 0..p2.len() {
            let (a, b) = (f2.vel_mps[e], f3.vel_mps[middle + e]);
            assert!((a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12 && b[2].abs() < 1e-12, "element {e}: 2D {a:?}, 3D {b:?}");
        }
    }
}
