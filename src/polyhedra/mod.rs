//! Rigid convex polyhedra (seed 001, Zhao, Feng et al. 2021): shapes with exact mass
//! properties, the seed's quaternion rotation update, the GJK/EPA contact geometry on the
//! Minkowski difference, the contact law on its features, and Voronoi cells for a rockfill.
//! Internal units SI (m, kg, s); inertia per unit density in m⁵.
//!
//! [`kernel`] puts them under `simulation`'s contract; [`rockfill`] and [`settle`] cut and pack a
//! Voronoi rockfill; [`scene`] is the projectile-through-rockfill scene `demsweep run` takes.

pub mod body;
pub mod clip;
pub mod container;
pub mod detect;
pub mod epa;
pub mod gjk;
pub mod hull;
pub mod kernel;
pub mod law;
pub mod mass;
pub mod pair;
pub mod patch;
pub mod projectile;
pub mod rockfill;
pub mod rotation;
pub mod scene;
pub mod settle;
pub mod shape;
pub mod simplex;
pub mod support;
pub mod voronoi;

pub use body::Body;
pub use detect::contact;
pub use epa::Contact;
pub use law::Law;
pub use pair::{Push, interact};
pub use rotation::Spin;
pub use shape::Polyhedron;
pub use support::Placed;
