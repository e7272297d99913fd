//! The scatter's sinks: where the contact stage adds each contact's force to its two elements,
//! in contact order ([`Sums`]), on one thread ([`Serial`]) or a piece's on the pool
//! (`pieces::PieceSums`), and the chunk of contacts whose dissipation is summed apart.

use crate::kernel::contact::{Contact, ContactForce};

/// Contacts per chunk: fixed, so partial sums do not depend on the number of threads.
pub const CHUNK: usize = 2048;

/// Where a scatter adds each contact's force: (fx, fy, ti) to element i, (−fx, −fy, tj) to j,
/// visited in contact order.
pub trait Sums {
    /// Add contact `c`'s force `f`.
    fn add(&mut self, c: &Contact, f: &ContactForce);
    /// Write out what is still held.
    fn finish(&mut self);
}

/// The one-thread scatter: contacts are sorted by i, so i's running sum stays in registers
/// while i repeats.
pub struct Serial<'a> {
    sums: &'a mut [[f64; 3]],
    run_i: u32,
    acc: [f64; 3],
}

impl<'a> Serial<'a> {
    /// Adding into `sums` (zero where nothing was added yet).
    pub fn new(sums: &'a mut [[f64; 3]]) -> Self {
        Serial { sums, run_i: u32::MAX, acc: [0.0; 3] }
    }
}

impl Sums for Serial<'_> {
    #[inline(always)]
    fn add(&mut self, c: &Contact, f: &ContactForce) {
        if c.i != self.run_i {
            if self.run_i != u32::MAX {
                self.sums[self.run_i as usize] = self.acc;
            }
            self.run_i = c.i;
            self.acc = self.sums[self.run_i as usize];
        }
        self.acc[0] += f.fx;
        self.acc[1] += f.fy;
        self.acc[2] += f.ti;
        let s = &mut self.sums[c.j as usize];
        s[0] -= f.fx;
        s[1] -= f.fy;
        s[2] += f.tj;
    }

    #[inline(always)]
    fn finish(&mut self) {
        if self.run_i != u32::MAX {
            self.sums[self.run_i as usize] = self.acc;
        }
    }
}
