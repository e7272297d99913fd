//! Contact arrays: one entry per pair that is bonded or may touch before the next neighbour
//! rebuild, sorted by (i, j); the optional parts' state beside it; the per-contact force
//! output; the fixed per-element adjacency through which stored forces are gathered in a fixed
//! order; and the plan by which the contact stage on the pool scatters them in that order
//! (`pieces`).

use serde::{Deserialize, Serialize};

use super::law::{Dissipation, Extra};

/// State of a contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[repr(u8)]
pub enum Bond {
    /// Bonded: tension and compression, shear spring, failure law.
    Intact = 0,
    /// Frictional: compression only, Coulomb (eq 2.1). New contacts and broken bonds.
    Frictional = 1,
}

/// One contact: which pair, its class, and its history (what evolves). Geometry is recomputed
/// every step.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Contact {
    /// First element (i < j).
    pub i: u32,
    /// Second element.
    pub j: u32,
    /// Contact class (stiffness, strength, friction), see `law::ContactClass`.
    pub class: u16,
    /// Bonded or frictional.
    pub bond: Bond,
    /// Rest length d0*, m: the distance at which the normal spring carries no force. A bond
    /// starts at its initial distance and compaction moves it in; a new pair starts at
    /// r_i + r_j. A frictional contact touches while the distance is below it.
    pub rest_m: f64,
    /// Elastic tangential displacement u_t, m (shear force = Kt u_t).
    pub ut_m: f64,
    /// Plastic normal opening δ_p of a bond's tension plateau, m.
    pub dp_m: f64,
}

impl Contact {
    /// A bond between i and j at rest distance `rest_m`.
    pub fn bonded(i: u32, j: u32, class: u16, rest_m: f64) -> Contact {
        Contact { i, j, class, bond: Bond::Intact, rest_m, ut_m: 0.0, dp_m: 0.0 }
    }

    /// A new frictional contact, touching once the distance drops below `rest_m` (r_i + r_j).
    pub fn frictional(i: u32, j: u32, class: u16, rest_m: f64) -> Contact {
        Contact { i, j, class, bond: Bond::Frictional, rest_m, ut_m: 0.0, dp_m: 0.0 }
    }

    fn key(&self) -> u64 {
        ((self.i as u64) << 32) | self.j as u64
    }
}

/// Force of one contact in the current step: (fx, fy) acts on i, −(fx, fy) on j.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
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

/// The contact list with its optional state, its forces and the per-element adjacency.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct Contacts {
    /// Contacts sorted by (i, j).
    pub list: Vec<Contact>,
    /// The optional parts' state, parallel to `list` (empty when no part needs it).
    pub extra: Vec<Extra>,
    /// Forces of the last step, parallel to `list`: written only with
    /// `Model::record_contact_forces` (else they are stale).
    pub force: Vec<ContactForce>,
    /// CSR row starts: element e's entries are `adj[start[e]..start[e+1]]` (derived from `list`).
    #[serde(skip)]
    pub start: Vec<u32>,
    /// Entries `(contact << 1) | side`, side 0 when e is the contact's i, 1 when j; each
    /// element's entries are in increasing contact order (derived from `list`).
    #[serde(skip)]
    pub adj: Vec<u32>,
    /// Per piece of the list cut at `piece_cuts`, the elements it scatters into directly: the
    /// plan of the contact stage's scatter on the pool (`pieces::plan`; derived from `list`,
    /// made by [`Contacts::plan_pieces`] and kept up with the list from then on).
    #[serde(skip)]
    pub piece_ranges: Vec<std::ops::Range<u32>>,
    /// Where the list is cut into pieces (`pieces::cuts`): piece p is `piece_cuts[p]..piece_cuts[p + 1]`.
    #[serde(skip)]
    pub piece_cuts: Vec<usize>,
    /// The pieces' spans, one per thread: span s is pieces `piece_spans[s]..piece_spans[s + 1]`.
    #[serde(skip)]
    pub piece_spans: Vec<usize>,
    /// Scratch of the plan: each element's first piece.
    #[serde(skip)]
    first_piece: Vec<u32>,
    /// The threads and the longest piece, contacts, the cuts are made for (None: no plan).
    #[serde(skip)]
    pub piece_rule: Option<(usize, usize)>,
    #[serde(skip)]
    merged: Vec<Contact>,
    #[serde(skip)]
    merged_extra: Vec<Extra>,
    #[serde(skip)]
    fill: Vec<u32>,
}

impl Contacts {
    /// A contact set from a list and its extra slots (empty or parallel); the adjacency is built
    /// by `rebuild_adjacency` or a merge.
    pub fn from_list(list: Vec<Contact>, extra: Vec<Extra>) -> Self {
        debug_assert!(extra.is_empty() || extra.len() == list.len());
        Contacts { list, extra, ..Default::default() }
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
    /// The forces are zeroed.
    pub fn rebuild_adjacency(&mut self, n_elements: usize) {
        self.force.clear();
        self.force.resize(self.list.len(), ContactForce::default());
        self.rebuild_index(n_elements);
    }

    /// Rebuild the adjacency only (the forces are kept: a restored checkpoint).
    pub fn rebuild_index(&mut self, n_elements: usize) {
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
        if self.piece_rule.is_some() {
            self.plan(n_elements);
        }
    }

    /// Plan the scatter on `threads` threads in pieces of `most` contacts at most (kept up with
    /// the list from now on, by every adjacency rebuild).
    pub fn plan_pieces(&mut self, threads: usize, most: usize, n_elements: usize) {
        self.piece_rule = Some((threads, most));
        self.plan(n_elements);
    }

    fn plan(&mut self, n_elements: usize) {
        let (threads, most) = self.piece_rule.expect("a rule to plan by");
        super::pieces::cuts(self.list.len(), threads, most, &mut self.piece_cuts, &mut self.piece_spans);
        super::pieces::plan(&self.list, &self.piece_cuts, n_elements, &mut self.first_piece, &mut self.piece_ranges);
    }

    /// Replace the list by the union of the contacts worth keeping and the broad phase's
    /// candidate `pairs` (sorted by (i, j)), which are all the candidates among the pairs for
    /// which `covered(i, j)` (every pair after a full search, the movers' after a local one;
    /// the contacts of the other pairs are kept as they are). Kept with their history: intact bonds (always) and
    /// frictional contacts that are still candidates or still touch (`touching(c)`; a candidate
    /// that is apart is kept too: the contact loop lets it forget, so the physics does not
    /// depend on when lists are rebuilt). Any other frictional contact is dropped; what its shear spring
    /// still held is booked in `released` as friction. Candidates not already present become
    /// `fresh(i, j)` contacts when `admit(i, j)` (pairs that can never interact, such as two
    /// fixed supports, are left out); `fresh_extra(i, j)` gives their extra slot.
    #[allow(clippy::too_many_arguments)]
    pub fn merge_candidates(
        &mut self,
        pairs: &[(u32, u32)],
        covered: impl Fn(u32, u32) -> bool,
        touching: impl Fn(&Contact) -> bool,
        fresh: impl Fn(u32, u32) -> Contact,
        fresh_extra: impl Fn(u32, u32) -> Extra,
        admit: impl Fn(u32, u32) -> bool,
        release_j: impl Fn(&Contact) -> f64,
        released: &mut Dissipation,
        n_elements: usize,
    ) {
        self.merged.clear();
        self.merged_extra.clear();
        let with_extra = !self.extra.is_empty();
        let (mut a, mut b) = (0usize, 0usize);
        let old = &self.list;
        while a < old.len() || b < pairs.len() {
            let ka = old.get(a).map_or(u64::MAX, Contact::key);
            let kb = pairs.get(b).map_or(u64::MAX, |&(i, j)| ((i as u64) << 32) | j as u64);
            if ka <= kb {
                let c = old[a];
                if c.bond == Bond::Intact || ka == kb || !covered(c.i, c.j) || touching(&c) {
                    self.merged.push(c);
                    if with_extra {
                        self.merged_extra.push(self.extra[a]);
                    }
                } else if c.ut_m != 0.0 {
                    released.friction_j += release_j(&c);
                }
                a += 1;
                if ka == kb {
                    b += 1;
                }
            } else {
                let (i, j) = pairs[b];
                if admit(i, j) {
                    self.merged.push(fresh(i, j));
                    if with_extra {
                        self.merged_extra.push(fresh_extra(i, j));
                    }
                }
                b += 1;
            }
        }
        std::mem::swap(&mut self.list, &mut self.merged);
        std::mem::swap(&mut self.extra, &mut self.merged_extra);
        self.rebuild_adjacency(n_elements);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn adjacency_lists_each_contact_twice_in_order() {
        let mut c = Contacts::from_list(
            vec![Contact::bonded(0, 1, 0, 1.0), Contact::bonded(0, 2, 0, 1.0), Contact::bonded(1, 2, 0, 1.0)],
            vec![],
        );
        c.rebuild_adjacency(3);
        assert_eq!(c.start, vec![0, 2, 4, 6]);
        // Entries are (contact << 1) | side.
        assert_eq!(c.adj, vec![0, 2, 1, 4, 3, 5]);
    }

    #[test]
    fn merge_keeps_bonds_and_candidates_with_history_and_books_what_is_dropped() {
        let mut f = Contact::frictional(0, 3, 0, 1.0);
        f.ut_m = 0.5;
        let mut gone = Contact::frictional(2, 3, 0, 1.0);
        gone.ut_m = 0.25;
        let mut c = Contacts::from_list(vec![Contact::bonded(0, 1, 0, 1.0), f, gone], vec![]);
        let mut released = Dissipation::default();
        // (2,3) is no longer a candidate: dropped, its spring booked. (1,2) new. (0,3) kept.
        c.merge_candidates(
            &[(0, 3), (1, 2)],
            |_, _| true,
            |_| false,
            |i, j| Contact::frictional(i, j, 7, 2.0),
            |_, _| Extra::new(0.0),
            |_, _| true,
            |k| k.ut_m * 2.0,
            &mut released,
            4,
        );
        let keys: Vec<_> = c.list.iter().map(|k| (k.i, k.j, k.class)).collect();
        assert_eq!(keys, vec![(0, 1, 0), (0, 3, 0), (1, 2, 7)]);
        assert_eq!(c.list[1].ut_m, 0.5);
        assert_eq!(c.force.len(), 3);
        assert_eq!(released.friction_j, 0.5);
    }
}
