//! Bitwise determinism (rapier's thread_count_determinism): a scene where bonds break gives
//! the same bits for 1, 2 and 8 threads, and from run to run.

mod common;

fn fingerprint(threads: usize, steps: u64) -> (Vec<u64>, u64, usize) {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| {
        let mut m = common::impact::model();
        m.run_steps(steps).unwrap();
        (common::impact::state_bits(&m), m.state.ledger.bonds_broken(), m.state.contacts.len())
    })
}

#[test]
fn bitwise_identical_for_1_2_and_8_threads_with_breaking_bonds() {
    let steps = 1500;
    let (one, broken, contacts) = fingerprint(1, steps);
    eprintln!("{broken} bonds broken, {contacts} contacts after {steps} steps");
    assert!(broken > 100, "the scene must break bonds, broke {broken}");
    for threads in [2, 8] {
        let (other, b, _) = fingerprint(threads, steps);
        assert_eq!(b, broken);
        assert!(one == other, "{threads} threads differ from 1 thread");
    }
    let (again, _, _) = fingerprint(2, steps);
    assert!(again == fingerprint(2, steps).0, "run-to-run difference");
}

#[test]
fn a_run_told_to_step_serially_gives_the_same_bits_inside_any_pool() {
    // Inside a sweep each run steps on its own thread (Threading::Serial) while the pool runs
    // other runs: the result must be the pool run's.
    let pooled = fingerprint(2, 600).0;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(8).build().unwrap();
    let serial = pool.install(|| {
        let mut m = common::impact::model();
        m.threading = demsweep::kernel::Threading::Serial;
        m.run_steps(600).unwrap();
        common::impact::state_bits(&m)
    });
    assert!(serial == pooled, "a serial run differs from a pooled one");
}
