//! Rigid convex polyhedra (seed 001, Zhao, Feng et al. 2021): shapes with exact mass
//! properties, the seed's quaternion rotation update, and the GJK/EPA contact geometry on the
//! Minkowski difference. Internal units SI (m, kg, s); inertia per unit density in m⁵.
//!
//! Not yet a kernel: nothing here is wired to `simulation`'s contract.

pub mod detect;
pub mod epa;
pub mod gjk;
pub mod hull;
pub mod mass;
pub mod rotation;
pub mod shape;
pub mod simplex;
pub mod support;

pub use detect::contact;
pub use epa::Contact;
pub use rotation::Spin;
pub use shape::Polyhedron;
pub use support::Placed;
