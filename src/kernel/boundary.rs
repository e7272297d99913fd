//! Boundary conditions: prescribed motion of element groups and external loads on them, each
//! scaled in time by a profile.

/// Time variation of a prescribed velocity or load.
#[derive(Debug, Clone, Copy, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Profile {
    /// 1 at all times.
    Constant,
    /// sin(ω t).
    Sine {
        /// ω, rad/s.
        omega_rad_per_s: f64,
    },
    /// Linear from 0 at t = 0 to 1 at `duration_s`, then 1.
    Ramp {
        /// Ramp duration, s.
        duration_s: f64,
    },
}

impl Profile {
    /// Value at time `t_s`.
    pub fn at(&self, t_s: f64) -> f64 {
        match *self {
            Profile::Constant => 1.0,
            Profile::Sine { omega_rad_per_s } => (omega_rad_per_s * t_s).sin(),
            Profile::Ramp { duration_s } => (t_s / duration_s).clamp(0.0, 1.0),
        }
    }
}

/// A group of kinematic elements moving with a prescribed velocity (zero: fixed support).
#[derive(Debug, Clone, PartialEq)]
pub struct MotionGroup {
    /// Name, for outputs.
    pub name: String,
    /// Velocity [vx m/s, vy m/s, ω rad/s] at profile value 1.
    pub velocity: [f64; 3],
    /// Time variation.
    pub profile: Profile,
}

/// An external force on a group of free elements, shared equally among them.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadGroup {
    /// Name, for outputs.
    pub name: String,
    /// Total force [Fx N, Fy N] at profile value 1.
    pub force_n: [f64; 2],
    /// Time variation.
    pub profile: Profile,
    /// Number of elements sharing it (set when the model is built).
    pub count: usize,
}
