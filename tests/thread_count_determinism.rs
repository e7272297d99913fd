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
fn batches_stepped_from_outside_the_pool_with_its_workers_looking_give_the_one_thread_bits() {
    // `run_steps` from a thread outside any pool (a single large run: `demsweep run`) runs
    // each batch on a worker of the global pool while the others look for work
    // (`kernel::awake`); every other test here steps inside a pool.
    // Two threads, unless this process made its global pool already (then the assert below
    // says whether it can serve).
    let _ = rayon::ThreadPoolBuilder::new().num_threads(2).build_global();
    assert!(rayon::current_thread_index().is_none() && rayon::current_num_threads() > 1, "needs a global pool of two threads or more");
    let mut m = common::impact::model();
    for _ in 0..3 {
        m.run_steps(500).unwrap();
    }
    let (one, broken, _) = fingerprint(1, 1500);
    assert_eq!(m.state.ledger.bonds_broken(), broken);
    assert!(common::impact::state_bits(&m) == one, "batches from outside the pool differ from one thread");
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

/// Lends its pool on every other look: a run that borrows it switches between stepping alone
/// and stepping on the pool every `LEND_POLL_STEPS` steps.
struct Flicker {
    pool: rayon::ThreadPool,
    looks: std::sync::atomic::AtomicUsize,
    lent: std::sync::atomic::AtomicUsize,
}

impl demsweep::run::Lend for Flicker {
    fn spare(&self) -> bool {
        let spare = self.looks.fetch_add(1, std::sync::atomic::Ordering::SeqCst).is_multiple_of(2);
        self.lent.fetch_add(spare as usize, std::sync::atomic::Ordering::SeqCst);
        spare
    }
    fn pool(&self) -> &rayon::ThreadPool {
        &self.pool
    }
}

#[test]
fn a_run_that_borrows_idle_cores_now_and_then_gives_the_bits_of_a_serial_run() {
    // A sweep's last runs step on the cores the others left idle (sweep::share), switching
    // whenever a core frees or is taken again.
    use demsweep::kernel::Threading;
    use demsweep::run::{self, Options};
    let built = || {
        let model = common::impact::model();
        let duration_s = 400.0 * model.dt_s();
        demsweep::scene::Built { name: "impact".into(), model, probes: Vec::new(), duration_s, every_steps: 100 }
    };
    let serial = run::run_with(built(), Options { threading: Threading::Serial, ..Default::default() }).unwrap();
    let lend = Flicker { pool: rayon::ThreadPoolBuilder::new().num_threads(2).build().unwrap(), looks: Default::default(), lent: Default::default() };
    let borrowing = run::run_with(built(), Options { threading: Threading::Serial, lend: Some(&lend), ..Default::default() }).unwrap();
    let lent = lend.lent.load(std::sync::atomic::Ordering::SeqCst);
    assert!(lent >= 15, "the pool was lent {lent} times");
    assert!(serial.model.state.ledger.bonds_broken() > 0, "the scene must break bonds in 400 steps");
    assert!(common::impact::state_bits(&serial.model) == common::impact::state_bits(&borrowing.model), "borrowing cores changed the result");
}

#[test]
fn recording_contact_forces_changes_no_bit_and_gives_forces_whose_gather_is_the_scattered_sum() {
    // The contact stage adds each force to its two elements as it goes and keeps no
    // per-contact copy unless asked: asking must change nothing else, the copy must be the
    // same on any thread count, and summing it per element in contact order (a gather) must
    // give, bit for bit, the element forces the scatter made.
    let run = |threads: usize, record: bool| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        pool.install(|| {
            let mut m = common::impact::model();
            m.record_contact_forces = record;
            m.run_steps(400).unwrap();
            let forces: Vec<u64> = m.state.contacts.force.iter().flat_map(|f| [f.fx, f.fy, f.ti, f.tj]).map(f64::to_bits).collect();
            (common::impact::state_bits(&m), forces, m)
        })
    };
    let (plain, _, _) = run(1, false);
    let (recorded, forces_serial, m) = run(1, true);
    let (parallel, forces_parallel, _) = run(2, true);
    assert!(plain == recorded, "recording the contact forces changed the state");
    assert!(plain == parallel, "two threads differ from one");
    assert!(forces_serial.iter().any(|&b| b != 0), "no contact carried a force");
    assert!(forces_serial == forces_parallel, "the recorded forces differ between one and two threads");
    // The impact has no gravity, load or damping: an element's force is its contacts' sum,
    // gathered here per element over its own list of contacts, in increasing contact order.
    let c = &m.state.contacts;
    let mut of: Vec<Vec<(usize, bool)>> = vec![vec![]; m.el.len()];
    for (k, ct) in c.list.iter().enumerate() {
        of[ct.i as usize].push((k, false));
        of[ct.j as usize].push((k, true));
    }
    let mut gathered = 0;
    for (e, mine) in of.iter().enumerate() {
        let mut g = [0.0f64; 3];
        for &(k, as_j) in mine {
            let f = &c.force[k];
            if as_j {
                g = [g[0] - f.fx, g[1] - f.fy, g[2] + f.tj];
            } else {
                g = [g[0] + f.fx, g[1] + f.fy, g[2] + f.ti];
            }
        }
        assert!(g.map(f64::to_bits) == m.state.force[e].map(f64::to_bits), "element {e}: gathered {g:?}, scattered {:?}", m.state.force[e]);
        gathered += !mine.is_empty() as usize;
    }
    assert!(gathered > m.el.len() / 2, "only {gathered} elements have contacts");
}

#[test]
fn pieces_of_one_chunk_give_the_one_thread_bits_on_2_and_8_threads() {
    // The scatter on the pool cuts the contact list into pieces (`kernel::pieces`): with the
    // smallest pieces, the most contributions go through the records and the fix-up, and the
    // pool may run the pieces in any order; the sums must still be the one-thread sums.
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        pool.install(|| {
            let mut m = common::impact::fine();
            m.scatter_piece_contacts = demsweep::kernel::forces::CHUNK;
            let pieces = m.state.contacts.len().div_ceil(demsweep::kernel::forces::CHUNK);
            m.run_steps(300).unwrap();
            (common::impact::state_bits(&m), m.state.ledger.bonds_broken(), pieces)
        })
    };
    let (one, broken, pieces) = run(1);
    assert!(pieces >= 5, "{pieces} pieces");
    assert!(broken > 0, "the scene must break bonds in 300 steps");
    for threads in [2, 8] {
        assert!(run(threads).0 == one, "{threads} threads with pieces of one chunk differ from one thread");
    }
}

#[test]
fn held_ends_give_the_same_bits_on_one_thread_and_on_the_pool() {
    // Every row has a kinematic element at each end, so the motion stage takes runs of free
    // elements over flat arrays between them and the general update for the held ones; on the
    // pool it does so chunk by chunk, the runs cut at the chunks' ends, from sums the contact
    // stage made in pieces.
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        pool.install(|| {
            let mut m = common::impact::held_ends();
            if threads == 1 {
                m.threading = demsweep::kernel::Threading::Serial;
            }
            m.run_steps(1000).unwrap();
            let held_still = m.el.motion.iter().zip(&m.state.vel).all(|(&g, v)| g == 0 || *v == [0.0; 3]);
            (common::impact::state_bits(&m), m.state.ledger.bonds_broken(), held_still)
        })
    };
    let (serial, broken, still) = run(1);
    assert!(broken > 50 && still, "{broken} bonds broken; held elements still: {still}");
    assert!(run(2).0 == serial, "the pool differs from one thread with held elements");
}
