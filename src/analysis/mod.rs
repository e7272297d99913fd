//! Analytic references that the kernel's validation tests compare against (SPEC §3, §5): mesh
//! convergence by Richardson extrapolation, the cantilever's tip response, and the handbook
//! critical stress of the cracked plate. Nothing here steps a DEM model; everything is a number
//! the DEM must approach.

pub mod beam;
mod beam_element;
pub mod richardson;
pub mod sdof;
pub mod sent;
pub mod timoshenko;

pub use beam::{Beam, Theory, cowper_rectangle};
pub use richardson::{Convergence, NotConvergent, celik, richardson};
pub use sdof::{sdof_natural_rad_per_s, sdof_tip_amplitude_m};
pub use sent::sent_critical_stress_pa;
pub use timoshenko::{CantileverModes, Mode, fundamental_rad_per_s, tip_amplitude_m};
