//! Restart equivalence (MercuryDPM): a run checkpointed at step n and restored into a model
//! built afresh from the same scene ends with the same bits as a run that never stopped, for
//! a scene where bonds break, fragments slide and neighbour lists are rebuilt in between; a
//! checkpoint refuses a different scene, another build and damaged bytes without touching the
//! model.

mod common;

use common::impact;

#[test]
fn a_restored_run_ends_bitwise_equal_to_an_uninterrupted_one() {
    let (n, more) = (55, 445);
    let mut straight = impact::model();
    straight.run_steps(n + more).unwrap();

    let mut first = impact::model();
    first.run_steps(n).unwrap();
    let bytes = first.checkpoint();
    let (broken, rebuilds) = (first.state.ledger.bonds_broken(), first.state.rebuilds);
    drop(first);
    let mut resumed = impact::model();
    resumed.restore(&bytes).unwrap();
    resumed.run_steps(more).unwrap();

    // The restart must fall in the middle of the action, or the test proves little.
    assert!(broken > 100 && straight.state.ledger.bonds_broken() > broken + 1000, "bonds broken: {broken} then {}", straight.state.ledger.bonds_broken());
    assert!(straight.state.rebuilds > rebuilds, "no neighbour rebuild after the restart");
    assert!(impact::state_bits(&resumed) == impact::state_bits(&straight), "restored run differs from the uninterrupted one");
    // And a checkpoint of the restored state is the same bytes as one of the uninterrupted.
    assert_eq!(resumed.checkpoint(), straight.checkpoint());
}

#[test]
fn a_checkpoint_refuses_another_scene_another_build_and_damaged_bytes() {
    let mut m = impact::model();
    m.run_steps(50).unwrap();
    let bytes = m.checkpoint();
    let before = impact::state_bits(&m);
    let err = |m: &mut demsweep::kernel::Model, b: &[u8]| m.restore(b).unwrap_err().to_string();

    let msg = err(&mut m, &bytes[..bytes.len() - 3]);
    assert!(msg.contains("checkpoint") && msg.contains("truncated"), "{msg}");
    let mut junk = bytes.clone();
    junk[0] = b'X';
    assert!(err(&mut m, &junk).contains("not a demsweep checkpoint"));
    let mut longer = bytes.clone();
    longer.push(0);
    assert!(err(&mut m, &longer).contains("after the end"));
    assert!(impact::state_bits(&m) == before, "a refused restore changed the model");

    let mut other = common::impact::model();
    other.motion.dt_s *= 0.5;
    let msg = err(&mut other, &bytes);
    assert!(msg.contains("different scene"), "{msg}");

    // Written by another build: refused, naming both.
    let build = demsweep::provenance::build_id();
    assert_eq!(&bytes[9..25], build.as_bytes(), "the header carries the writer's build id");
    let mut rebuilt = bytes.clone();
    rebuilt[9..25].copy_from_slice(b"00000000000000ff");
    let msg = err(&mut m, &rebuilt);
    assert!(msg.contains("another build of demsweep (build 00000000000000ff; this is") && msg.contains(build), "{msg}");
    assert!(impact::state_bits(&m) == before, "a refused restore changed the model");
}
