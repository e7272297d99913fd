//! The energy ledger of either kernel: work and dissipation accumulated since the start of a
//! run, per mechanism (the contacts' listed once, in the kernel's `law::Dissipation`, declared
//! with [`mechanisms!`]). `energy` computes the strain energy it is balanced against.

use serde::{Deserialize, Serialize};

/// What a kernel's contacts dissipate, by mechanism: a struct made by [`mechanisms!`].
pub trait Mechanisms: Copy + Default {
    /// Everything dissipated, J.
    fn total_j(&self) -> f64;
    /// Bonds broken.
    fn broken(&self) -> u64;
}

/// A struct of the energy a kernel's contacts dissipate, J, one field per mechanism, and the
/// bonds broken; each mechanism listed once, where the struct is declared: `terms` gives them
/// to the ledger, the run summary and the checkpoint. The 2D and 3D kernels each declare theirs.
macro_rules! mechanisms {
    ($(#[$sdoc:meta])* $name:ident { $($(#[$doc:meta])* $field:ident),* $(,)? }) => {
        $(#[$sdoc])*
        #[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize, serde::Deserialize)]
        pub struct $name {
            $($(#[$doc])* pub $field: f64,)*
            /// Bonds broken.
            pub broken: u64,
        }

        impl $name {
            /// Add another step's or chunk's dissipation.
            #[inline(always)]
            pub fn add(&mut self, o: &$name) {
                $(self.$field += o.$field;)*
                self.broken += o.broken;
            }

            /// Add `weight` × another's energies (its bonds broken counted whole): a contact
            /// that stands for part of a pair of the whole (`kernel3d::mirror`).
            #[inline(always)]
            pub fn add_scaled(&mut self, o: &$name, weight: f64) {
                $(self.$field += weight * o.$field;)*
                self.broken += o.broken;
            }

            /// (name, J) of every mechanism, in a fixed order.
            pub fn terms(&self) -> Vec<(&'static str, f64)> {
                vec![$((stringify!($field), self.$field)),*]
            }

            /// Everything dissipated, J.
            pub fn total_j(&self) -> f64 {
                0.0 $(+ self.$field)*
            }
        }

        impl $crate::kernel::ledger::Mechanisms for $name {
            fn total_j(&self) -> f64 {
                $name::total_j(self)
            }
            fn broken(&self) -> u64 {
                self.broken
            }
        }
    };
}
pub(crate) use mechanisms;

/// Accumulated work and dissipation since the start of the run, J; `D` the kernel's contact
/// mechanisms.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct Ledger<D> {
    /// Kinetic + strain energy at the start, J.
    pub initial_j: f64,
    /// Work of loads, gravity and prescribed motions on the model, J.
    pub external_j: f64,
    /// Mass-proportional Rayleigh damping, J.
    pub mass_damping_j: f64,
    /// Local (non-viscous) damping of the element motion, J (3D kernel, `kernel3d::integrate`).
    #[serde(default)]
    pub local_damping_j: f64,
    /// Energy carried out of the model by its viscous (absorbing) boundaries, J (3D kernel,
    /// `kernel3d::integrate`): waves that leave, booked with what was dissipated.
    #[serde(default)]
    pub radiated_j: f64,
    /// What the contacts dissipated, by mechanism, and the bonds broken.
    pub contacts: D,
}

impl<D: Mechanisms> Ledger<D> {
    /// Everything dissipated, J.
    pub fn dissipated_j(&self) -> f64 {
        self.mass_damping_j + self.local_damping_j + self.radiated_j + self.contacts.total_j()
    }

    /// Balance error given the present kinetic and strain energy, J (0 for a perfect ledger).
    pub fn residual_j(&self, kinetic_j: f64, strain_j: f64) -> f64 {
        kinetic_j + strain_j - (self.initial_j + self.external_j - self.dissipated_j())
    }

    /// Bonds broken so far.
    pub fn bonds_broken(&self) -> u64 {
        self.contacts.broken()
    }
}
