//! How a step runs on the pool, apart from what it computes: the contact list cut into pieces
//! and the scatter plan that keeps contact order on any thread count (`pieces`), one span of
//! jobs per thread with stealing from the back (`spans`), and workers kept looking for work
//! between the stages of a batch of steps (`awake`). The laws and the update never name what is
//! in here; the stages hand it their jobs and take back finished sums. Which thread runs what
//! never changes a bit.
//!
//! The motion stage sees only this file: [`MOTION_CHUNK`], [`Pending`] (a chunk's sums made
//! whole) and [`each_chunk`] (its chunks on this thread or in the contact stage's spans).

pub(crate) mod awake;
pub mod pieces;
pub mod scatter;
pub mod spans;

pub use pieces::MOTION_CHUNK;
pub use scatter::{Serial, Sums};

/// The contact stage's sums as the motion stage takes them. On the pool, a piece adds its
/// forces to its own elements directly and keeps the rest as records, in contact order; a
/// chunk's sums are whole once its records are added, which [`Pending::finish`] does just before
/// the chunk is moved (while its elements are in cache). On one thread nothing is pending.
#[derive(Debug, Clone, Copy, Default)]
pub struct Pending<'a> {
    records: &'a [pieces::Kept],
}

impl<'a> Pending<'a> {
    /// Nothing pending: the sums were added in contact order on one thread.
    pub const NONE: Pending<'static> = Pending { records: &[] };

    /// The records a contact stage on the pool left.
    pub(crate) fn of(records: &'a [pieces::Kept]) -> Pending<'a> {
        Pending { records }
    }

    /// Make the sums of motion chunk `k` (elements `k·MOTION_CHUNK..`, `sums` being that
    /// chunk's rows) whole: every piece's records for them added, piece by piece, each in its
    /// contact order, so the bits are those of one thread's scatter.
    #[inline]
    pub fn finish(&self, sums: &mut [[f64; 3]], k: usize) {
        if !self.records.is_empty() {
            pieces::fix_up_chunk(sums, k, self.records);
        }
    }
}

/// Run `one` on every chunk: here, in order (`spans` None), or on the pool in the spans the
/// contact stage used (`spans[s]` the first chunk of span s, then the number of chunks), so a
/// thread finds its span's elements in its cache.
pub fn each_chunk<W: Send>(chunks: impl Iterator<Item = W>, spans: Option<&[usize]>, one: impl Fn(W) + Sync) {
    match spans {
        Some(starts) => spans::run(chunks.collect(), starts, one),
        None => chunks.for_each(one),
    }
}
