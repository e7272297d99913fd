//! Energy bookkeeping, per mechanism. The balance
//!
//!   kinetic + strain = initial (kinetic + strain) + external work − dissipated
//!
//! closes to O(Δt) (central differences carry velocities at half steps); `Ledger::residual_j`
//! is what a test or a run summary checks. The contacts' mechanisms are listed once, in
//! `law::Dissipation`.

use super::contacts::Contacts;
use super::forces;
use super::law::{self, ContactClass, Extra, Parts, PartSet, PartsVisitor};
use super::state::Elements;

struct Strain<'a> {
    el: &'a Elements,
    pos: &'a [[f64; 3]],
    vel: &'a [[f64; 3]],
    contacts: &'a Contacts,
    classes: &'a [ContactClass],
    dt_s: f64,
}

impl PartsVisitor for Strain<'_> {
    type Output = f64;
    fn visit<P: PartSet>(self) -> f64 {
        let _ = self.el;
        let mut sum = 0.0;
        let scratch = Extra::new(0.0);
        for (k, c) in self.contacts.list.iter().enumerate() {
            let class = &self.classes[c.class as usize];
            let Ok(g) = forces::kinematics(self.pos, self.vel, c, class) else { continue };
            let x = if P::EXTRA { &self.contacts.extra[k] } else { &scratch };
            sum += law::stored_energy_j::<P>(c, x, class, &g, self.dt_s);
        }
        sum
    }
}

/// Elastic energy stored in the contacts' springs at the current positions, J (the state the
/// next contact processing would produce; see `law::stored_energy_j`).
pub fn strain_energy_j(
    el: &Elements,
    pos: &[[f64; 3]],
    vel: &[[f64; 3]],
    contacts: &Contacts,
    classes: &[ContactClass],
    parts: Parts,
    dt_s: f64,
) -> f64 {
    parts.dispatch(Strain { el, pos, vel, contacts, classes, dt_s })
}
