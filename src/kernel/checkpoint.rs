//! Checkpoints: the part of a model that stepping changes ([`State`]), serialised as it is
//! (serde, postcard), so that a run stopped at step n and restored into a model built from the
//! same scene continues exactly as if it had never stopped (MercuryDPM's restart equivalence;
//! `tests/restart_equivalence.rs`). Floats travel as their bytes.
//!
//! What the scene determines (element constants and initial velocities, contact classes with
//! every law part's parameters, the enabled parts, boundary groups with their profiles,
//! damping, gravity, the time step, the neighbour settings, the bodies) is not stored: it is
//! rebuilt from the scene, and a fingerprint over all of it, the serialised configuration,
//! refuses a checkpoint written by another scene. A new parameter is covered by the fingerprint
//! as soon as it is a field of the configuration.
//!
//! A checkpoint also names the build of demsweep that wrote it (`provenance::build_id`) and is
//! refused by any other: a run continued by a changed program would not be the run that never
//! stopped.
//!
//! Format: a header (magic, format version, build id, fingerprint), then the state.

use serde::{Deserialize, Serialize};

use super::Model;
use super::state::State;
use crate::error::{Error, Result};
use crate::fnv::fnv1a;
use crate::provenance::build_id;

const MAGIC: [u8; 8] = *b"DEMSWCK\0";
/// Format version: 2 is the serde-derived state (1 was a hand-listed record); 3 drops the
/// zero shift of the rate-dependent springs (secant moduli) and adds each bond's mean rate
/// (`law::rate`); 5 adds the build id.
const VERSION: u32 = 5;

#[derive(Serialize, Deserialize)]
struct Header {
    magic: [u8; 8],
    version: u32,
    /// The writer's build id, its 16 hex digits (bytes 9..25 of the checkpoint).
    build: [u8; 16],
    fingerprint: u64,
}

/// This build's id as the header stores it.
fn this_build() -> [u8; 16] {
    build_id().as_bytes().try_into().expect("a build id of 16 hex digits")
}

fn bad(message: String) -> Error {
    Error::input("checkpoint", message)
}

fn decode_error(e: postcard::Error) -> Error {
    match e {
        postcard::Error::DeserializeUnexpectedEnd => bad("truncated: the bytes end before the state does".into()),
        other => bad(format!("damaged: {other}")),
    }
}

impl Model {
    /// A fingerprint of everything the scene determines (the configuration), the same for
    /// models built from the same scene.
    pub fn fingerprint(&self) -> u64 {
        let config = (
            &self.el,
            &self.classes,
            self.parts,
            &self.bodies,
            &self.motions,
            &self.loads,
            self.motion,
            self.neighbours,
            self.damp_relative_to_rigid,
        );
        fnv1a(&postcard::to_stdvec(&config).expect("the configuration serialises"))
    }

    /// The evolving state as bytes (see the module documentation).
    pub fn checkpoint(&self) -> Vec<u8> {
        let header = Header { magic: MAGIC, version: VERSION, build: this_build(), fingerprint: self.fingerprint() };
        let mut out = postcard::to_stdvec(&header).expect("the header serialises");
        out.extend(postcard::to_stdvec(&self.state).expect("the state serialises"));
        out
    }

    /// Put the state of `bytes` (from [`Model::checkpoint`] of a model built from the same
    /// scene) into this model. On error the model is unchanged.
    pub fn restore(&mut self, bytes: &[u8]) -> Result<()> {
        if bytes.len() < MAGIC.len() || bytes[..MAGIC.len()] != MAGIC {
            return Err(bad("not a demsweep checkpoint (bad magic bytes)".into()));
        }
        let (header, rest) = postcard::take_from_bytes::<Header>(bytes).map_err(decode_error)?;
        if header.version != VERSION {
            return Err(bad(format!("format version {}, this demsweep reads {VERSION}", header.version)));
        }
        if header.build != this_build() {
            return Err(bad(format!(
                "written by another build of demsweep (build {}; this is {}): resumed by this one, the run would not be the one that never stopped; run it from the start, or resume it with that build",
                String::from_utf8_lossy(&header.build),
                build_id()
            )));
        }
        if header.fingerprint != self.fingerprint() {
            return Err(bad("written for a different scene (elements, materials, laws, boundary groups or time step differ)".into()));
        }
        let (state, rest) = postcard::take_from_bytes::<State>(rest).map_err(decode_error)?;
        if !rest.is_empty() {
            return Err(bad(format!("{} bytes after the end of the state", rest.len())));
        }
        self.check(&state)?;
        self.scratch.plan.forget();
        self.state = state;
        Ok(())
    }

    /// A decoded state must fit this model before it replaces the present one.
    fn check(&self, s: &State) -> Result<()> {
        let n = self.el.len();
        for (what, len) in [("positions", s.pos.len()), ("velocities", s.vel.len()), ("forces", s.force.len()), ("rebuild positions", s.rebuild_pos.len()), ("margins", s.margin_m.len())] {
            if len != n {
                return Err(bad(format!("{len} {what}, the model has {n} elements")));
            }
        }
        let c = &s.contacts;
        let extra = if self.parts.needs_extra() { c.list.len() } else { 0 };
        if c.force.len() != c.list.len() || c.extra.len() != extra {
            return Err(bad(format!("{} contacts with {} forces and {} extra slots", c.list.len(), c.force.len(), c.extra.len())));
        }
        for (k, ct) in c.list.iter().enumerate() {
            if ct.i >= ct.j || ct.j as usize >= n || ct.class as usize >= self.classes.len() {
                return Err(bad(format!("contact {k}: elements ({}, {}) or class {} out of range", ct.i, ct.j, ct.class)));
            }
        }
        Ok(())
    }
}
