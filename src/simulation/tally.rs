//! What a kernel puts in a run's summary row.

/// A model's counts, time step and energy ledger at one moment: the kernel's part of
/// `crate::run::RunSummary`.
#[derive(Debug, Clone, PartialEq)]
pub struct Tally {
    /// Elements.
    pub elements: u64,
    /// Bonds broken so far.
    pub bonds_broken: u64,
    /// Time step, s.
    pub dt_s: f64,
    /// Stability limit of the frequency bound, s.
    pub dt_bound_s: f64,
    /// The frequency bound, rad/s.
    pub omega_bound_rad_per_s: f64,
    /// What sets the step: the safety factor and which contacts give the bound.
    pub dt_limit: String,
    /// Kinetic energy, J.
    pub kinetic_energy_j: f64,
    /// Strain energy, J.
    pub strain_energy_j: f64,
    /// Work of loads, gravity and prescribed motions, J.
    pub external_work_j: f64,
    /// Mass-proportional damping, J.
    pub mass_damping_j: f64,
    /// What the contacts dissipated, by mechanism, and the 3D kernel's local damping (column
    /// name, J).
    pub contacts_j: Vec<(String, f64)>,
    /// Everything dissipated, J.
    pub dissipated_j: f64,
    /// Energy balance residual, J.
    pub energy_residual_j: f64,
    /// The energy put in (initial + |external|), J: the residual's scale.
    pub energy_in_j: f64,
    /// Full neighbour rebuilds.
    pub neighbour_rebuilds: u64,
    /// Local neighbour updates.
    pub neighbour_local_updates: u64,
}
