//! The runs being made right now by callers of `Engine::run_shared`, so that two callers asking
//! for the same run make it once: the second waits for the first's row. The two bisections of a
//! ballistic sweep do ask for the same run when both thresholds lie in one grid interval (the
//! default scene's do: both start at its midpoint, and on a thin target they meet at every
//! step). Before the claims, each made the run beside the other — a whole run's core time lost
//! per shared velocity, and the run reported made twice.

use std::collections::HashSet;
use std::sync::{Condvar, Mutex, MutexGuard};

/// Run ids claimed (what evolves), and a signal when one is released.
#[derive(Default)]
pub struct Claims {
    held: Mutex<HashSet<String>>,
    released: Condvar,
}

/// A claim on one run, released when dropped — after the caller has put the run's row in the
/// store, or when it failed (a waiter then makes the run itself).
pub struct Claim<'a> {
    claims: &'a Claims,
    id: String,
}

impl Claims {
    fn lock(&self) -> MutexGuard<'_, HashSet<String>> {
        // A holder that panicked has released nothing worth keeping: the set is still valid.
        self.held.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Claim run `id`, or None when `done()` finds its row made. While another caller holds
    /// the claim, waits for its release and asks `done()` again. `done` is asked under the
    /// claims' lock and a claim is released only after its row is in the store, so no run is
    /// made twice, whichever thread finishes first.
    pub fn claim(&self, id: &str, mut done: impl FnMut() -> bool) -> Option<Claim<'_>> {
        let mut held = self.lock();
        loop {
            if done() {
                return None;
            }
            if held.insert(id.to_string()) {
                return Some(Claim { claims: self, id: id.to_string() });
            }
            held = self.released.wait(held).unwrap_or_else(|e| e.into_inner());
        }
    }
}

impl Drop for Claim<'_> {
    fn drop(&mut self) {
        self.claims.lock().remove(&self.id);
        self.claims.released.notify_all();
    }
}

#[cfg(test)]
mod tests {
    use std::sync::atomic::{AtomicBool, Ordering::SeqCst};
    use std::time::Duration;

    use super::Claims;

    #[test]
    fn a_second_claimant_waits_for_the_first_and_then_finds_the_run_made() {
        let claims = Claims::default();
        let made = AtomicBool::new(false);
        let first = claims.claim("v=575", || made.load(SeqCst)).expect("nobody holds it yet");
        std::thread::scope(|s| {
            let waiter = s.spawn(|| claims.claim("v=575", || made.load(SeqCst)).is_none());
            std::thread::sleep(Duration::from_millis(50));
            assert!(!waiter.is_finished(), "the second claimant waits while the first holds the run");
            assert!(claims.claim("v=600", || false).is_some(), "another run is not held up");
            made.store(true, SeqCst);
            drop(first);
            assert!(waiter.join().unwrap(), "the second claimant found the run made instead of making it again");
        });
    }

    #[test]
    fn a_claim_released_without_its_run_passes_the_run_to_the_waiter() {
        let claims = Claims::default();
        let first = claims.claim("v=575", || false).expect("nobody holds it yet");
        std::thread::scope(|s| {
            let waiter = s.spawn(|| claims.claim("v=575", || false).is_some());
            std::thread::sleep(Duration::from_millis(50));
            drop(first);
            assert!(waiter.join().unwrap(), "the run failed: the waiter makes it itself");
        });
    }
}
