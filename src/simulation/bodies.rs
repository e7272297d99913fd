//! What outcome detectors read of a running model: its elements as bodies in space.

use std::ops::Range;

/// A model's elements as a detector sees them: where each is, how fast, how big and heavy,
/// which are held in place, and which pairs are bonded. Vectors have three components, x, y, z
/// (a 2D kernel's z is 0); element indices run over `0..element_count()`, and a scene's bodies
/// are contiguous ranges of them.
pub trait Bodies {
    /// Simulated time, s.
    fn time_s(&self) -> f64;
    /// The elements of the body named `name` (`target`, `projectile`), if there is one.
    fn body(&self, name: &str) -> Option<Range<usize>>;
    /// Number of elements.
    fn element_count(&self) -> usize;
    /// Where element `e` started, m.
    fn initial_m(&self, e: usize) -> [f64; 3];
    /// Where element `e` is, m.
    fn position_m(&self, e: usize) -> [f64; 3];
    /// Element `e`'s velocity, m/s (a leapfrog kernel's half-step velocity).
    fn velocity_mps(&self, e: usize) -> [f64; 3];
    /// Element `e`'s radius, m.
    fn radius_m(&self, e: usize) -> f64;
    /// Element `e`'s mass, kg.
    fn mass_kg(&self, e: usize) -> f64;
    /// True when element `e` is a support: its motion prescribed in every degree of freedom, or
    /// tied by a dashpot to what lies beyond the model (an absorbing boundary); what is bonded
    /// to it is attached.
    fn held(&self, e: usize) -> bool;
    /// Call `f(i, j)` for each intact bond once, in the kernel's contact order.
    fn each_bond(&self, f: &mut dyn FnMut(usize, usize));
}
