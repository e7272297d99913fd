//! Contact arrays: one entry per pair that is bonded or may touch before the next neighbour
//! rebuild, sorted by (i, j); the per-contact force output; and the fixed per-element
//! adjacency through which forces are gathered in a fixed order (bitwise determinism for any
//! thread count).

/// State of a contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub enum Bond {
    /// Bonded: tension and compression, shear spring, failure law.
    Intact = 0,
    /// Frictional: compression only, Coulomb (eq 2.1). New contacts and broken bonds.
    Frictional = 1,
}

/// One contact. Mutable history lives here; geometry is recomputed every step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// First element (i < j).
    pub i: u32,
    /// Second element.
    pub j: u32,
    /// Contact class (stiffness, strength, friction), see `law::ContactClass`.
    pub class: u16,
    /// Bonded or frictional.
    pub bond: Bond,
    /// Equilibrium centre distance d0, m: initial distance for bonds, r_i + r_j for new
    /// contacts. A frictional contact touches while the distance is below d0.
    pub d0: f64,
    /// Elastic tangential displacement u_t, m (shear force = Kt u_t).
    pub ut: f64,
    /// Plastic normal opening δ_p, m (bond tension plateau).
    pub dp: f64,
}

impl Contact {
    /// A bond between i and j at rest distance `d0`.
    pub fn bonded(i: u32, j: u32, class: u16, d0: f64) -> Contact {
        Contact { i, j, class, bond: Bond::Intact, d0, ut: 0.0, dp: 0.0 }
    }

    /// A frictional contact, touching once the distance drops below `d0`.
    pub fn frictional(i: u32, j: u32, class: u16, d0: f64) -> Contact {
        Contact { i, j, class, bond: Bond::Frictional, d0, ut: 0.0, dp: 0.0 }
    }

    fn key(&self) -> u64 {
        ((self.i as u64) << 32) | self.j as u64
    }
}

/// Force of one contact in the current step: (fx, fy) acts on i, −(fx, fy) on j.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ContactForce {
    /// Force on i, x, N.
    pub fx: f64,
    /// Force on i, y, N.
    pub fy: f64,
    /// Torque on i, N·m.
    pub ti: f64,
    /// Torque on j, N·m.
    pub tj: f64,
}

/// The contact list with its forces and the per-element adjacency.
#[derive(Debug, Clone, Default)]
pub struct Contacts {
    /// Contacts sorted by (i, j).
    pub list: Vec<Contact>,
    /// Forces, parallel to `list`.
    pub force: Vec<ContactForce>,
    /// CSR row starts: element e's entries are `adj[start[e]..start[e+1]]`.
    pub start: Vec<u32>,
    /// Entries `(contact << 1) | side`, side 0 when e is the contact's i, 1 when j; each
    /// element's entries are in increasing contact order.
    pub adj: Vec<u32>,
    merged: Vec<Contact>,
    fill: Vec<u32>,
}

impl Contacts {
    /// A contact set from a list (adjacency built later by `rebuild_adjacency` or a merge).
    pub fn from_list(list: Vec<Contact>) -> Self {
        Contacts { list, ..Default::default() }
    }

    /// Number of contacts.
    pub fn len(&self) -> usize {
        self.list.len()
    }

    /// True when there are none.
    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// Rebuild the per-element adjacency from `list` (counting sort: O(elements + contacts)).
    pub fn rebuild_adjacency(&mut self, n_elements: usize) {
        self.force.clear();
        self.force.resize(self.list.len(), ContactForce::default());
        self.start.clear();
        self.start.resize(n_elements + 1, 0);
        for c in &self.list {
            self.start[c.i as usize + 1] += 1;
            self.start[c.j as usize + 1] += 1;
        }
        for e in 0..n_elements {
            self.start[e + 1] += self.start[e];
        }
        self.adj.clear();
        self.adj.resize(self.start[n_elements] as usize, 0);
        self.fill.clear();
        self.fill.extend_from_slice(&self.start[..n_elements]);
        for (k, c) in self.list.iter().enumerate() {
            let k = k as u32;
            self.adj[self.fill[c.i as usize] as usize] = k << 1;
            self.fill[c.i as usize] += 1;
            self.adj[self.fill[c.j as usize] as usize] = (k << 1) | 1;
            self.fill[c.j as usize] += 1;
        }
    }

    /// Replace the list by the union of the contacts worth keeping and the broad phase's
    /// candidate `pairs` (sorted by (i, j)). Kept: intact bonds (always) and frictional contacts
    /// that still touch (`touching(c)`), with their history. Candidates not already present
    /// become fresh frictional contacts via `fresh(i, j)` when `admit(i, j)` (pairs that can
    /// never interact, such as two fixed supports, are left out).
    pub fn merge_candidates(
        &mut self,
        pairs: &[(u32, u32)],
        touching: impl Fn(&Contact) -> bool,
        fresh: impl Fn(u32, u32) -> Contact,
        admit: impl Fn(u32, u32) -> bool,
        n_elements: usize,
    ) {
        self.merged.clear();
        let (mut a, mut b) = (0usize, 0usize);
        let old = &self.list;
        while a < old.len() || b < pairs.len() {
            let ka = old.get(a).map_or(u64::MAX, Contact::key);
            let kb = pairs.get(b).map_or(u64::MAX, |&(i, j)| ((i as u64) << 32) | j as u64);
            if ka < kb {
                let c = old[a];
                if c.bond == Bond::Intact || touching(&c) {
                    self.merged.push(c);
                }
                a += 1;
            } else if kb < ka {
                let (i, j) = pairs[b];
                if admit(i, j) {
                    self.merged.push(fresh(i, j));
                }
                b += 1;
            } else {
                let c = old[a];
                // A separated frictional pair starts afresh (d0 back to r_i + r_j, no history).
                if c.bond == Bond::Intact || touching(&c) {
                    self.merged.push(c);
                } else {
                    self.merged.push(fresh(c.i, c.j));
                }
                a += 1;
                b += 1;
            }
        }
        std::mem::swap(&mut self.list, &mut self.merged);
        self.rebuild_adjacency(n_elements);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn adjacency_lists_each_contact_twice_in_order() {
        let mut c = Contacts::from_list(vec![
            Contact::bonded(0, 1, 0, 1.0),
            Contact::bonded(0, 2, 0, 1.0),
            Contact::bonded(1, 2, 0, 1.0),
        ]);
        c.rebuild_adjacency(3);
        assert_eq!(c.start, vec![0, 2, 4, 6]);
        // Entries are (contact << 1) | side.
        assert_eq!(c.adj, vec![0, 2, 1, 4, 3, 5]);
    }

    #[test]
    fn merge_keeps_bonds_and_touching_history_and_adds_candidates() {
        let mut f = Contact::frictional(0, 3, 0, 1.0);
        f.ut = 0.5;
        let mut c = Contacts::from_list(vec![Contact::bonded(0, 1, 0, 1.0), f, Contact::frictional(2, 3, 0, 1.0)]);
        // (2,3) separated and not a candidate: dropped. (1,2) new. (0,3) touching: kept with history.
        c.merge_candidates(&[(0, 3), (1, 2)], |k| k.i == 0 && k.j == 3, |i, j| Contact::frictional(i, j, 7, 2.0), |_, _| true, 4);
        let keys: Vec<_> = c.list.iter().map(|k| (k.i, k.j, k.class)).collect();
        assert_eq!(keys, vec![(0, 1, 0), (0, 3, 0), (1, 2, 7)]);
        assert_eq!(c.list[1].ut, 0.5);
        assert_eq!(c.force.len(), 3);
    }
}
