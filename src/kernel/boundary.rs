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
#[derive(Debug, Clone, PartialEq, serde::Deserialize, serde::Serialize)]
pub struct MotionGroup {
    /// Name, for outputs.
    pub name: String,
    /// Velocity [vx m/s, vy m/s, ω rad/s] at profile value 1.
    pub velocity: [f64; 3],
    /// Time variation.
    pub profile: Profile,
    /// Prescribed dofs (x, y, rotation); the others are free (a roller prescribes one).
    pub dofs: [bool; 3],
}

impl MotionGroup {
    /// All dofs prescribed: a support (zero velocity) or a driven grip.
    pub fn all(name: &str, velocity: [f64; 3], profile: Profile) -> Self {
        MotionGroup { name: name.into(), velocity, profile, dofs: [true; 3] }
    }

    /// Bit mask of the prescribed dofs (bit 0 x, bit 1 y, bit 2 rotation).
    pub fn mask(&self) -> u8 {
        self.dofs.iter().enumerate().fold(0, |m, (d, &on)| if on { m | (1 << d) } else { m })
    }
}

/// An external force on a group of free elements, shared equally among them.
#[derive(Debug, Clone, PartialEq, serde::Deserialize, serde::Serialize)]
pub struct LoadGroup {
    /// Name, for outputs.
    pub name: String,
    /// Total force [Fx N, Fy N] at profile value 1 (unused with a servo).
    pub force_n: [f64; 2],
    /// Time variation.
    pub profile: Profile,
    /// Displacement control of the total force, if any.
    pub servo: Option<Servo>,
    /// The elements sharing it (set when the model is built).
    pub members: Vec<u32>,
}

impl LoadGroup {
    /// A given force, varying with `profile`.
    pub fn force(name: &str, force_n: [f64; 2], profile: Profile) -> Self {
        LoadGroup { name: name.into(), force_n, profile, servo: None, members: Vec::new() }
    }

    /// A displacement-controlled grip.
    pub fn servo(name: &str, servo: Servo) -> Self {
        LoadGroup { name: name.into(), force_n: [0.0; 2], profile: Profile::Constant, servo: Some(servo), members: Vec::new() }
    }
}

/// A testing machine's grip: the group's total force is that of a stiff spring between a
/// cross-head moving at `rate_mps` along `direction` and the group's mean displacement along
/// it, shared equally by the members (a whiffle-tree grip: uniform traction, displacement
/// control of the mean). The force only pulls or pushes along `direction`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Servo {
    /// Unit direction of the cross-head motion.
    pub direction: [f64; 2],
    /// Cross-head speed, m/s.
    pub rate_mps: f64,
    /// Machine stiffness, N/m.
    pub stiffness_n_per_m: f64,
    /// The speed rises from 0 to `rate_mps` along a half cosine over this time, s, so the start
    /// does not ring the whole mesh (mass-proportional damping hardly damps high modes).
    #[serde(default)]
    pub start_s: f64,
}

impl Servo {
    /// Cross-head displacement at time `t_s`, m.
    pub fn target_m(&self, t_s: f64) -> f64 {
        let tr = self.start_s;
        if tr <= 0.0 || t_s >= tr {
            // ∫ of the ramp is rate·tr/2.
            self.rate_mps * (t_s - 0.5 * tr.max(0.0))
        } else {
            let w = std::f64::consts::PI / tr;
            0.5 * self.rate_mps * (t_s - (w * t_s).sin() / w)
        }
    }
}
