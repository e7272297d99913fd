//! How a step runs on the pool, apart from what it computes: the contact list cut into pieces
//! and the scatter plan that keeps contact order on any thread count (`pieces`), one span of
//! jobs per thread with stealing from the back (`spans`), and workers kept looking for work
//! between the stages of a batch of steps (`awake`). The laws and the update never name what is
//! in here; the stages hand it their jobs and take back finished sums. Which thread runs what
//! never changes a bit.

pub(crate) mod awake;
pub mod pieces;
pub mod scatter;
pub mod spans;
