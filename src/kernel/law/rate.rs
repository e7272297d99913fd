//! Rate part: strain-rate effects on a bond's stiffness and strength (seed 000 §6, eq 6.6–6.15;
//! SPEC §2). Everything rate-dependent in the contact law is here.
//!
//! **The rate.** ε̇ = |v·n| / L0 (eq 6.7), L0 the bond's initial centre distance, capped at
//! [`Params::cap_per_s`], with v·n the relative normal velocity at the step, the mean of the
//! half-step velocities before and after it ([`centred_mps`]), not the half-step velocity
//! itself. Central differences give a mode of energy E a half-step velocity amplitude of
//! √(2E/m) / √(1 − (ωΔt/2)²): the lattice's top modes, which an impact fills, look up to twice
//! as fast at 0.9 of the stability limit as at 0.45, and a rate law reading them made the
//! concrete's strength depend on the step (the calibrated penetration run at 500 ft/s went
//! 4.94 in deep at safety 0.9, 6.09 in at 0.45 and scabbed at 0.3). The mean of two successive
//! half-step velocities has amplitude √(2E/m) cos(θ/2) / cos(θ/2) = √(2E/m) for every mode
//! (θ the mode's phase per step, sin(θ/2) = ωΔt/2): the step drops out. The first step of a bond
//! sees half its velocity (its last one is taken as 0). The instantaneous value is useless as
//! it stands: a bond stretched to
//! its peak has v·n = 0 at the very moment it is most loaded, and in a vibrating lattice it
//! flickers every step. Each bond therefore keeps two rates:
//! * the **held** rate, for the strengths: ε̇_h ← max(ε̇, ε̇_h e^(−Δt/τ)), a peak detector that
//!   forgets with τ ([`RateSpec::memory_s`], by default Klepaczko's critical time t_c0 = 50 µs,
//!   the time over which his criterion integrates the load history). Klepaczko's strength is
//!   that of a load applied at the rate up to failure, and a wave front loads a bond to failure
//!   within a few µs: the rate seen then is the one that counts;
//! * the **mean** rate, for the moduli: ε̇_m ← ε̇ + (ε̇_m − ε̇) e^(−Δt/τ_m), a first-order
//!   low-pass ([`RateSpec::modulus_filter_s`], by default t_c0 too). A modulus changes the
//!   force at a configuration (below), so it must not follow the peaks of the top lattice
//!   modes, whose amplitude depends on the time step: with peak-held moduli, a penetration run
//!   booked −13.7 kJ of rate work at 0.9 of the stability limit and −8.6 kJ at 0.45; with the
//!   mean rate −12.9 and −12.0 kJ, and the depth agreed to 0.1 %.
//!
//! **The laws**, each a ratio to the static value, each ≥ 1, continuous and non-decreasing in ε̇
//! (the property tests check it over 1e-6 … 1e5 s⁻¹), except the seed's printed compressive form,
//! kept as a named option:
//! * tensile strength (Klepaczko 1990, eq 6.5–6.6): integrating t_c0 = ∫ (σ(t)/σ_ult)^α dt over
//!   linear loading σ = E ε̇ t gives σ_F = [(α+1) t_c0 E σ_ult^α ε̇]^(1/(α+1)). The seed prints
//!   σ_ult where the integral gives σ_ult^α: a misprint (its formula is not dimensionally
//!   homogeneous for α ≠ 1, so its value would depend on the unit system, 26 % apart between SI
//!   and psi for the seed's concrete; with σ_ult^α it gives about 11× at 120 s⁻¹, the "order of
//!   magnitude" of Brara et al. that the seed cites). The seed uses σ_F above 0.75 s⁻¹ and the
//!   static value below, which jumps (σ_F crosses σ_ult at ε̇ = σ_ult/((α+1) t_c0 E) ≈ 0.99 s⁻¹
//!   for its concrete); we take max(σ_ult, σ_F), equal to the seed's law wherever σ_F exceeds
//!   the static strength, and continuous;
//! * moduli (CEB 1988, eq 6.8–6.9): E_d/E_s = (ε̇/ε̇0)^0.026 in compression, ^0.016 in tension,
//!   ε̇0 = 30e-6 s⁻¹, not below 1 (the formulas fall under 1 below the quasi-static rate);
//! * fracture energy (eq 6.10): (G_f)_d = ξ (G_f)_s with ξ the tensile-strength ratio;
//! * compressive strength: CEB 1990 (continuous, the default): (ε̇/ε̇0)^(1.026 α_s) up to
//!   30 s⁻¹, γ_s (ε̇/ε̇0)^(1/3) above, log10 γ_s = 6.156 α_s − 2, α_s = 1/(5 + 9 f'c/f_co),
//!   f_co = 10 MPa; or the seed's printed form (eq 6.12–6.15: switch at 10 s⁻¹, γ ε̇^(1/3),
//!   log γ = 6.15 α − 0.492, α = 1/(5 + 3 f'c/4), f'c in MPa), which jumps down at its switch
//!   (1.89 → 1.38 for f'c = 3000 psi).
//!
//! **Stiffness.** The moduli scale the bond's springs as secant moduli, CEB's definition of a
//! dynamic modulus: force = r(ε̇_m) K × stretch, the spring's zero fixed. When the ratio changes
//! the force at the present configuration changes with it, and so does the stored energy; the
//! ledger books ½ (K_last − K) × last stretch × new stretch as rate work, which with the
//! plateau's and compaction's own bookings (the mean of the last and the new force) is exactly
//! the trapezoidal work of the step less the change of stored energy, as central differences
//! see it. The alternative, moduli acting on increments (hypoelastic: the force kept, the
//! spring's zero shifted), was the first version; under any rate that varies in phase with a
//! vibration its zero ratchets: a bond vibrating at half its plateau opening moved its zero by
//! its whole amplitude in 2000 cycles with the held rate (78 % with the branch switch done
//! right, half with the mean rate, 130 % with the instantaneous one), and in the penetration
//! scene a vibrating pair of a scab crept shut to 0.49 L0 and fired an element off at 1 km/s
//! (`tests/rate_laws.rs`, `regression_a_bond_vibrating_through_zero_force_keeps_its_zero`). A
//! secant spring cannot drift. Its price: where a preloaded bond's rate rises the spring gains
//! energy. In a realistic run that is small (−0.1 kJ of 79 kJ at 500 ft/s with the calibrated
//! concrete); in an unbreakable target under an embedded projectile, where the beam's vibration
//! raises the rates of bonds held in compression, it reached 16 % of the impact energy. The
//! summary reports it (`rate_work_j`).

//! **Speed.** The four ratios are tabulated per contact class on a grid of 16 points per octave
//! of ε̇, plus the laws' kinks and jumps, and read by linear interpolation in a piecewise-linear
//! log₂ (exponent and mantissa of the float): no transcendental function in the step loop;
//! within 2e-4 of the exact laws (a test checks it), continuous and non-decreasing where they
//! are, and with the seed's jump where it has one.

use serde::{Deserialize, Serialize};

use crate::material::{CompressiveRate, RateSpec};

/// Quasi-static reference rate ε̇0 of the CEB laws, 1/s (eq 6.8–6.9, 6.12).
pub const REFERENCE_RATE_PER_S: f64 = 30e-6;
/// f_co of the CEB compressive law, Pa.
const CEB_FCO_PA: f64 = 10e6;
/// Lowest rate the table resolves, 1/s (below it every ratio is 1).
const TABLE_LOW_PER_S: f64 = 1e-7;
/// Table points per octave of rate.
const PER_OCTAVE: f64 = 16.0;

/// Dynamic tensile strength of Klepaczko's criterion under linear loading at `rate_per_s`
/// (eq 6.6 with σ_ult^α, see the module doc), Pa.
pub fn klepaczko_pa(rate_per_s: f64, youngs_modulus_pa: f64, static_pa: f64, spec: &RateSpec) -> f64 {
    let a = spec.alpha;
    ((a + 1.0) * spec.critical_time_s * youngs_modulus_pa * static_pa.powf(a) * rate_per_s).powf(1.0 / (a + 1.0))
}

/// ξ = dynamic / static tensile strength: max(1, σ_F/σ_ult).
pub fn tensile_ratio(rate_per_s: f64, youngs_modulus_pa: f64, static_pa: f64, spec: &RateSpec) -> f64 {
    (klepaczko_pa(rate_per_s, youngs_modulus_pa, static_pa, spec) / static_pa).max(1.0)
}

/// E_cd/E_cs = max(1, (ε̇/ε̇0)^0.026) (eq 6.8).
pub fn modulus_ratio_compression(rate_per_s: f64) -> f64 {
    (rate_per_s / REFERENCE_RATE_PER_S).powf(0.026).max(1.0)
}

/// E_td/E_ts = max(1, (ε̇/ε̇0)^0.016) (eq 6.9).
pub fn modulus_ratio_tension(rate_per_s: f64) -> f64 {
    (rate_per_s / REFERENCE_RATE_PER_S).powf(0.016).max(1.0)
}

/// f'cd/f'cs, not below 1.
pub fn compressive_ratio(rate_per_s: f64, compressive_strength_pa: f64, law: CompressiveRate) -> f64 {
    let x = rate_per_s / REFERENCE_RATE_PER_S;
    let r = match law {
        CompressiveRate::Ceb => {
            let alpha = 1.0 / (5.0 + 9.0 * compressive_strength_pa / CEB_FCO_PA);
            if rate_per_s <= 30.0 {
                x.powf(1.026 * alpha)
            } else {
                10f64.powf(6.156 * alpha - 2.0) * x.powf(1.0 / 3.0)
            }
        }
        CompressiveRate::SeedPrinted => {
            let alpha = 1.0 / (5.0 + 0.75 * compressive_strength_pa / 1e6);
            if rate_per_s <= 10.0 { x.powf(1.026 * alpha) } else { 10f64.powf(6.15 * alpha - 0.492) * rate_per_s.powf(1.0 / 3.0) }
        }
    };
    r.max(1.0)
}

/// The four ratios at one rate: [E_cd/E_cs, E_td/E_ts, ξ (tensile strength and fracture
/// energy), f'cd/f'cs].
pub type Ratios = [f64; 4];

/// No rate effect.
pub const STATIC: Ratios = [1.0; 4];

/// A piecewise-linear log₂: exponent plus mantissa − 1. Continuous, increasing, exact at powers
/// of two (x > 0, finite, normal).
#[inline(always)]
fn pseudo_log2(x: f64) -> f64 {
    let b = x.to_bits();
    let e = ((b >> 52) & 0x7ff) as i64 - 1023;
    let m = f64::from_bits((b & ((1u64 << 52) - 1)) | (1023u64 << 52));
    e as f64 + (m - 1.0)
}

/// Inverse of [`pseudo_log2`].
fn pseudo_exp2(u: f64) -> f64 {
    let e = u.floor();
    2f64.powi(e as i32) * (1.0 + (u - e))
}

/// A point inside a table interval where a law has a kink or a jump, with the values just
/// below and just above it.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
struct Split {
    u: f64,
    below: Ratios,
    above: Ratios,
}

/// The ratios tabulated against `pseudo_log2` of the rate: nodes at 16 per octave, plus the
/// points where a law has a kink or a jump (the quasi-static rate, Klepaczko's crossing of the
/// static strength, the compressive law's switch), so that linear interpolation keeps them.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Table {
    u0: f64,
    nodes: Vec<Node>,
    splits: Vec<Split>,
}

/// A table node: the ratios there, and the split inside the interval that starts there. One
/// array, so that a lookup checks one range for both ends of its interval and the split.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
struct Node {
    ratios: Ratios,
    /// Index of the interval's split in `splits` (u32::MAX: none; the last node's is never read).
    split: u32,
}

impl Table {
    /// Tabulate `f` from `TABLE_LOW_PER_S` to at least `high_per_s`, with the kinks or jumps
    /// at the rates `kinks_per_s` (at most one per interval of 1/16 octave; `f` is the value at
    /// the kink and the limit from above is taken just past it).
    pub fn new(high_per_s: f64, kinks_per_s: &[f64], f: impl Fn(f64) -> Ratios) -> Table {
        let u0 = pseudo_log2(TABLE_LOW_PER_S).floor();
        let u1 = pseudo_log2(high_per_s.max(2.0 * TABLE_LOW_PER_S)).ceil() + 1.0;
        let n = ((u1 - u0) * PER_OCTAVE) as usize + 1;
        let mut nodes: Vec<Node> = (0..n).map(|k| Node { ratios: f(pseudo_exp2(u0 + k as f64 / PER_OCTAVE)), split: u32::MAX }).collect();
        let mut splits = Vec::new();
        for &x in kinks_per_s {
            if !(x > TABLE_LOW_PER_S && x.is_finite()) {
                continue;
            }
            let u = pseudo_log2(x);
            let k = ((u - u0) * PER_OCTAVE) as usize;
            if k + 1 >= n {
                continue;
            }
            assert!(nodes[k].split == u32::MAX, "two kinks in one table interval at {x} s⁻¹");
            nodes[k].split = splits.len() as u32;
            splits.push(Split { u, below: f(x), above: f(x * (1.0 + 1e-12)) });
        }
        Table { u0, nodes, splits }
    }

    /// The ratios at `rate_per_s` (≥ 0), by linear interpolation; STATIC below the table, the
    /// last row above it.
    #[inline(always)]
    pub fn at(&self, rate_per_s: f64) -> Ratios {
        // Also catches a NaN rate.
        if rate_per_s.partial_cmp(&TABLE_LOW_PER_S) != Some(std::cmp::Ordering::Greater) {
            return STATIC;
        }
        let u = pseudo_log2(rate_per_s);
        let s = (u - self.u0) * PER_OCTAVE;
        // s > 0 (u > pseudo_log2(TABLE_LOW_PER_S) ≥ u0), so ⌊s⌋ is the interval, and past the
        // last node exactly when s ≥ the last index: the test in integers, with no float made
        // of the table's length (the u32 is wide enough: a table has a few hundred nodes).
        let k = s as u32 as usize;
        let Some([node, next]) = self.nodes.get(k..k + 2) else {
            return self.nodes[self.nodes.len() - 1].ratios;
        };
        let (mut a, mut b, mut w) = (&node.ratios, &next.ratios, s - k as f64);
        if node.split != u32::MAX {
            let p = &self.splits[node.split as usize];
            let (uk, uk1) = (self.u0 + k as f64 / PER_OCTAVE, self.u0 + (k + 1) as f64 / PER_OCTAVE);
            if u <= p.u {
                if p.u == uk {
                    return p.below;
                }
                (b, w) = (&p.below, (u - uk) / (p.u - uk));
            } else {
                (a, w) = (&p.above, (u - p.u) / (uk1 - p.u));
            }
        }
        [a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2]), a[3] + w * (b[3] - a[3])]
    }
}

/// The relative normal velocity at the step, m/s: the mean of the last step's half-step value
/// (`last`, replaced by this step's) and this step's `vn_mps` (see "The rate" above).
#[inline(always)]
pub fn centred_mps(vn_mps: f64, last: &mut f64) -> f64 {
    let centred = 0.5 * (vn_mps + *last);
    *last = vn_mps;
    centred
}

/// Where a material's laws have kinks or jumps, 1/s.
pub fn kinks_per_s(youngs_modulus_pa: f64, tensile_pa: f64, spec: &RateSpec) -> [f64; 3] {
    [
        REFERENCE_RATE_PER_S,
        tensile_pa / ((spec.alpha + 1.0) * spec.critical_time_s * youngs_modulus_pa),
        match spec.compressive {
            CompressiveRate::Ceb => 30.0,
            CompressiveRate::SeedPrinted => 10.0,
        },
    ]
}

/// The exact ratios of a material at `rate_per_s`.
pub fn exact(rate_per_s: f64, youngs_modulus_pa: f64, tensile_pa: f64, compressive_pa: f64, spec: &RateSpec) -> Ratios {
    [
        modulus_ratio_compression(rate_per_s),
        modulus_ratio_tension(rate_per_s),
        if tensile_pa > 0.0 { tensile_ratio(rate_per_s, youngs_modulus_pa, tensile_pa, spec) } else { 1.0 },
        if compressive_pa > 0.0 { compressive_ratio(rate_per_s, compressive_pa, spec.compressive) } else { 1.0 },
    ]
}

/// What the rate laws read of one material (2D or 3D): its modulus, its static strengths and
/// its rate law.
#[derive(Debug, Clone, Copy)]
pub struct Source<'a> {
    /// Young's modulus E, Pa.
    pub youngs_modulus_pa: f64,
    /// Static tensile strength σ_ult, Pa.
    pub tensile_strength_pa: f64,
    /// Static compressive strength f'c, Pa.
    pub compressive_strength_pa: f64,
    /// The rate law.
    pub spec: &'a RateSpec,
}

impl<'a> Source<'a> {
    /// A 2D material's (None: no rate law).
    pub fn of(m: &'a crate::material::Material) -> Option<Source<'a>> {
        m.rate.as_ref().map(|spec| Source {
            youngs_modulus_pa: m.youngs_modulus_pa,
            tensile_strength_pa: m.tensile_strength_pa,
            compressive_strength_pa: m.compressive_strength_pa,
            spec,
        })
    }
}

/// Per contact class: the tabulated laws, the cap and the memory of the held rate.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Params {
    /// Rate effects act on this class's bonds (both materials have a rate law).
    pub enabled: bool,
    /// Highest rate, 1/s.
    pub cap_per_s: f64,
    /// Memory τ of the held rate, s.
    pub memory_s: f64,
    /// Time constant of the mean rate, s.
    pub modulus_filter_s: f64,
    /// e^(−Δt/τ) of the held rate, set once the step is known.
    pub decay: f64,
    /// e^(−Δt/τ) of the mean rate.
    pub mean_decay: f64,
    /// The ratios.
    pub table: Table,
    /// G_f × 2Rt of the energy criterion (0 for the brittle criteria), J: with ξ it sets the
    /// dynamic breaking opening.
    pub gf_area_j: f64,
}

impl Params {
    /// Parameters between two materials: on when both have a rate law. Each ratio is the
    /// smaller of the two materials' (the weaker side sets a bond's strength, as the static
    /// strengths do). `radius_sum_m` sets the default cap with `max_speed_mps`.
    pub fn between(a: Option<Source<'_>>, b: Option<Source<'_>>, radius_sum_m: f64, max_speed_mps: f64, gf_area_j: f64) -> Params {
        let (Some(a), Some(b)) = (a, b) else { return Params::default() };
        let (ra, rb) = (a.spec, b.spec);
        let cap = match (ra.cap_per_s, rb.cap_per_s) {
            (Some(x), Some(y)) => x.min(y),
            (Some(x), None) | (None, Some(x)) => x,
            // The steepest gradient a pair can read: the fastest speed over one bond, or over
            // the smoothed field's grid spacing ℓ/2 when the rate is measured over ℓ.
            (None, None) => match ra.averaging_length().or(rb.averaging_length()) {
                Some(l) => (max_speed_mps / (0.5 * l)).max(1.0),
                None => (max_speed_mps / radius_sum_m).max(1.0),
            },
        };
        let f = |m: &Source<'_>, rate: f64| exact(rate, m.youngs_modulus_pa, m.tensile_strength_pa, m.compressive_strength_pa, m.spec);
        let mut kinks = kinks_per_s(a.youngs_modulus_pa, a.tensile_strength_pa, ra).to_vec();
        for k in kinks_per_s(b.youngs_modulus_pa, b.tensile_strength_pa, rb) {
            if !kinks.iter().any(|&x| (x / k - 1.0).abs() < 1e-9) {
                kinks.push(k);
            }
        }
        let table = Table::new(cap, &kinks, |rate| {
            let (x, y) = (f(&a, rate), f(&b, rate));
            [x[0].min(y[0]), x[1].min(y[1]), x[2].min(y[2]), x[3].min(y[3])]
        });
        Params {
            enabled: true,
            cap_per_s: cap,
            memory_s: ra.memory().min(rb.memory()),
            modulus_filter_s: ra.modulus_filter().min(rb.modulus_filter()),
            decay: 0.0,
            mean_decay: 0.0,
            table,
            gf_area_j,
        }
    }

    /// Fix the decay of the held rate for the step Δt.
    pub fn set_time_step(&mut self, dt_s: f64) {
        self.decay = if self.enabled { (-dt_s / self.memory_s).exp() } else { 0.0 };
        self.mean_decay = if self.enabled { (-dt_s / self.modulus_filter_s).exp() } else { 0.0 };
    }

    /// Largest modulus ratio the class can reach (at the cap): what the time step must cover.
    pub fn max_modulus_ratio(&self) -> f64 {
        if self.enabled {
            let r = self.table.at(self.cap_per_s);
            r[0].max(r[1])
        } else {
            1.0
        }
    }

    /// Update a bond's held and mean rates from its relative normal speed and return the
    /// ratios: the moduli at the mean rate, the strengths at the held one.
    #[inline(always)]
    pub fn update(&self, held_per_s: &mut f64, mean_per_s: &mut f64, vn_mps: f64, inv_length0_per_m: f64) -> Ratios {
        let now = (vn_mps.abs() * inv_length0_per_m).min(self.cap_per_s);
        let h = now.max(*held_per_s * self.decay);
        let m = now + (*mean_per_s - now) * self.mean_decay;
        *held_per_s = h;
        *mean_per_s = m;
        let (strength, moduli) = (self.table.at(h), self.table.at(m));
        [moduli[0], moduli[1], strength[2], strength[3]]
    }

    /// Plastic opening at which a bond breaks when its tensile ratio is ξ and its normal
    /// stiffness `kn` (rate-enhanced): the energy criterion's area rule (eq 5.7) with
    /// (G_f)_d = ξ G_f (eq 6.10) on the plateau ξ f_n, i.e. G_f 2Rt / f_n − ξ f_n / (2 kn); never
    /// negative (a bond whose dynamic plateau stores more than (G_f)_d breaks on reaching it).
    /// The brittle criteria keep their static opening (0).
    #[inline(always)]
    pub fn opening_at_break_m(&self, static_opening_m: f64, static_plateau_n: f64, xi: f64, kn: f64) -> f64 {
        if self.gf_area_j > 0.0 { dynamic_opening_m(self.gf_area_j, static_plateau_n, xi, kn) } else { static_opening_m }
    }
}

/// The energy criterion's plastic opening at break with the tensile ratio ξ (eq 5.7 with
/// eq 6.10): G_f A / f_n − ξ f_n / (2 k_n) for G_f A = `gf_area_j` (J), the static plateau f_n
/// (N) and the rate-enhanced stiffness `kn` (N/m); never negative.
#[inline(always)]
pub fn dynamic_opening_m(gf_area_j: f64, static_plateau_n: f64, xi: f64, kn: f64) -> f64 {
    (gf_area_j / static_plateau_n - 0.5 * xi * static_plateau_n / kn).max(0.0)
}
