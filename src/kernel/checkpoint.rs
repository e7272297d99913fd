//! Checkpoints: the part of a model that stepping changes, written bit for bit, so that a run
//! stopped at step n and restored into a model built from the same scene continues exactly as
//! if it had never stopped (MercuryDPM's restart equivalence; `tests/restart_equivalence.rs`).
//!
//! What the scene determines (masses, radii, contact classes, groups, the time step) is not
//! stored: it is rebuilt from the scene and checked against a fingerprint, so a checkpoint
//! cannot be restored into a different scene. What is stored: positions, half-step velocities,
//! last forces, the contact list in its order with its history and forces, the positions at the
//! last neighbour rebuild (they decide when the next rebuild happens), the energy ledger and the
//! step and rebuild counts. The adjacency is a function of the contact list and is rebuilt.
//!
//! Format: little-endian; a magic string and a version, the fingerprint, then the arrays, each
//! prefixed by its length. Floats are stored as their IEEE bits.

use super::Model;
use super::contacts::{Bond, Contact, ContactForce};
use super::energy::Ledger;
use crate::binary::{Reader, Writer, bad};
use crate::error::Result;

const MAGIC: &[u8; 8] = b"DEMSWCK\0";
const VERSION: u32 = 1;

/// FNV-1a over the scene-determined state: the same scene gives the same value.
fn fingerprint(m: &Model) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let mut eat = |v: u64| {
        for b in v.to_le_bytes() {
            h = (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3);
        }
    };
    let el = &m.el;
    eat(el.len() as u64);
    for e in 0..el.len() {
        eat(el.radius[e].to_bits());
        eat(el.mass[e].to_bits());
        eat(el.inertia[e].to_bits());
        eat(el.initial[e][0].to_bits());
        eat(el.initial[e][1].to_bits());
        eat(((el.prescribed[e] as u64) << 48) | ((el.kind[e] as u64) << 32) | ((el.body[e] as u64) << 16) | el.motion[e] as u64);
        eat(el.load[e] as u64);
    }
    eat(m.classes.len() as u64);
    eat(m.motion.dt_s.to_bits());
    eat(m.motions.len() as u64);
    eat(m.loads.len() as u64);
    h
}

impl Model {
    /// The evolving state as bytes (see the module documentation).
    pub fn checkpoint(&self) -> Vec<u8> {
        let el = &self.el;
        let n_c = self.contacts.len();
        let mut w = Writer(Vec::with_capacity(64 + el.len() * 80 + n_c * 72));
        w.bytes(MAGIC);
        w.u32(VERSION);
        w.u64(fingerprint(self));
        w.u64(self.steps);
        w.u64(self.rebuilds);
        let l = &self.ledger;
        w.f64s(&[l.external_j, l.mass_damping_j, l.contact_damping_j, l.friction_j, l.plastic_j, l.fracture_j, l.initial_j]);
        w.u64(l.bonds_broken);
        w.u64(el.len() as u64);
        for e in 0..el.len() {
            w.f64s(&el.pos[e]);
            w.f64s(&el.vel[e]);
            w.f64s(&el.force[e]);
            w.f64s(&self.rebuild_pos[e]);
        }
        w.u64(n_c as u64);
        for (c, f) in self.contacts.list.iter().zip(&self.contacts.force) {
            w.u32(c.i);
            w.u32(c.j);
            w.u32(((c.bond as u32) << 16) | c.class as u32);
            w.f64s(&[c.d0, c.ut, c.dp, f.fx, f.fy, f.ti, f.tj]);
        }
        w.0
    }

    /// Put the state of `bytes` (from [`Model::checkpoint`] of a model built from the same
    /// scene) into this model. On error the model is unchanged.
    pub fn restore(&mut self, bytes: &[u8]) -> Result<()> {
        let mut r = Reader::new(bytes);
        if r.take::<8>()? != *MAGIC {
            return Err(bad("not a demsweep checkpoint (bad magic bytes)".into()));
        }
        let version = r.u32()?;
        if version != VERSION {
            return Err(bad(format!("format version {version}, this demsweep reads {VERSION}")));
        }
        if r.u64()? != fingerprint(self) {
            return Err(bad("written for a different scene (elements, materials or time step differ)".into()));
        }
        let steps = r.u64()?;
        let rebuilds = r.u64()?;
        let [external_j, mass_damping_j, contact_damping_j, friction_j, plastic_j, fracture_j, initial_j] = r.f64s()?;
        let ledger =
            Ledger { external_j, mass_damping_j, contact_damping_j, friction_j, plastic_j, fracture_j, bonds_broken: r.u64()?, initial_j };
        let n = self.el.len();
        r.count("elements", n)?;
        let (mut pos, mut vel, mut force, mut rebuild_pos) =
            (Vec::with_capacity(n), Vec::with_capacity(n), Vec::with_capacity(n), Vec::with_capacity(n));
        for _ in 0..n {
            pos.push(r.f64s()?);
            vel.push(r.f64s()?);
            force.push(r.f64s()?);
            rebuild_pos.push(r.f64s()?);
        }
        let n_c = r.len("contacts", 68)?;
        let (mut list, mut forces) = (Vec::with_capacity(n_c), Vec::with_capacity(n_c));
        for k in 0..n_c {
            let (i, j, tag) = (r.u32()?, r.u32()?, r.u32()?);
            let [d0, ut, dp, fx, fy, ti, tj] = r.f64s()?;
            let bond = match tag >> 16 {
                0 => Bond::Intact,
                1 => Bond::Frictional,
                b => return Err(bad(format!("contact {k}: bond state {b}"))),
            };
            let class = (tag & 0xffff) as u16;
            if i >= j || j as usize >= n || class as usize >= self.classes.len() {
                return Err(bad(format!("contact {k}: elements ({i}, {j}) or class {class} out of range")));
            }
            list.push(Contact { i, j, class, bond, d0, ut, dp });
            forces.push(ContactForce { fx, fy, ti, tj });
        }
        r.finish()?;
        self.steps = steps;
        self.time_s = steps as f64 * self.motion.dt_s;
        self.rebuilds = rebuilds;
        self.ledger = ledger;
        self.el.pos = pos;
        self.el.vel = vel;
        self.el.force = force;
        self.rebuild_pos = rebuild_pos;
        self.contacts.list = list;
        self.contacts.rebuild_adjacency(n);
        self.contacts.force = forces;
        Ok(())
    }
}
