//! The classical empirical formulas for local damage of plain concrete by hard missiles
//! (`shared/FORMULAS.md`), forward (thickness from velocity) and inverse (velocity from
//! thickness).
//!
//! Each formula lives in its family's file, in its original (customary) units, with its citation,
//! validity range and confidence level from FORMULAS.md. The typed inputs ([`Missile`],
//! [`Target`]) carry the unit in every field name and are the only way in, so a caller cannot feed
//! Pa where psi is meant; dimensionless formulas convert to SI through [`crate::units`].
//!
//! [`Formula`] is the registry: every formula and named variant, what it defines
//! ([`Quantity`]), its prediction and whether the inputs lie inside its stated validity
//! ([`Validity`]). [`inverse`] finds the scabbing velocity and the ballistic limit, [`table`]
//! formats sweeps, [`plot`] draws the thickness–velocity curves.

mod inputs;
mod validity;
mod formula;

pub mod petry;
pub mod brl;
pub mod ace;
pub mod ndrc;
pub mod kennedy;
pub mod degen;
pub mod kar;
pub mod ammann_whitney;
pub mod whiffen;
pub mod ukaea;
pub mod cea_edf;
pub mod chang;
pub mod impact_factor;
pub mod hughes;
pub mod bechtel;
pub mod stone_webster;

pub mod closed_form;
pub mod inverse;
pub mod table;
pub mod plot;

pub use formula::{BrlScabbing, CeaEdfForm, Formula, HughesTensile, PetryClass, Prediction, StoneWebsterC};
pub use inputs::{MILD_STEEL_MODULUS_PSI, Missile, Nose, Target};
pub use validity::{Quantity, Validity};
