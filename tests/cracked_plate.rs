//! Cracked plate, Mode I (SPEC §3; seed 000 §4–5).

use demsweep::analysis::richardson;
use demsweep::cases::cracked_plate::{self as plate, Study};

#[test]
#[ignore]
fn explore() {
    let mut v = vec![];
    for level in 0..3 {
        let (p, _) = plate::run(Study::EnergyClosePacked, level, true).unwrap();
        eprintln!("energy cp level {level}: {p:?}");
        v.push(p.stress_pa);
        let (p, _) = plate::run(Study::EnergyClosePacked, level, false).unwrap();
        eprintln!("  uncracked: {p:?}");
    }
    eprintln!("{:?}", richardson([v[0], v[1], v[2]], 2.0));
    let mut v = vec![];
    for level in 0..3 {
        let (p, _) = plate::run(Study::ToughnessSimpleCubic, level, true).unwrap();
        eprintln!("toughness sc level {level}: {p:?}");
        v.push(p.stress_pa);
    }
    eprintln!("{:?}", richardson([v[0], v[1], v[2]], 2.0));
    eprintln!("handbook {:.5} MPa", plate::handbook_pa() / 1e6);
}
