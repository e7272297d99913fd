//! Where the peers' beam spends its steps: per window of steps, the kinds of contact the
//! contact stage meets and the time per step on one thread, with the four-contact lanes and one
//! contact at a time. The beam breaks three quarters of its bonds in 5 000 steps: runs of four
//! intact bonds go through `groups::bonds`, the other groups of one class (bonds and frictional
//! pairs mixed at random as it cracks) through `groups::mixed`. This prints what each window holds and what
//! the lanes gain there (issue [6/6]).
//!
//! usage: cargo run --release --example beam_phases -- [SCENE] [WINDOW_STEPS] [REPEATS]
//!   SCENE         default ../shared/peers/demsweep/beam.toml
//!   WINDOW_STEPS  default 500 (of the scene's 5 000)
//!   REPEATS       default 3: each window is timed on that many copies of the model at its
//!                 start (the median is printed), so the machine's spells hit every window alike
//!
//! Columns, each a share of all contacts at the window's start: intact bonds, intact bonds in
//! the aligned groups of four the lanes take (`groups::eligible`), frictional pairs apart with
//! nothing to forget (settled in line), the other frictional pairs (touching, or holding a shear
//! spring); then ms per step with the lanes, one contact at a time (`Model::four_lanes` off),
//! and the ratio. The copies must end bitwise equal, with and without the lanes (checked): the
//! timing does not change the run.

use std::time::Instant;

use demsweep::kernel::Threading;
use demsweep::kernel::groups;
use demsweep::kernel::contacts::Bond;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let scene = args.first().map_or("../shared/peers/demsweep/beam.toml", String::as_str);
    let window: u64 = args.get(1).map_or(500, |s| s.parse().expect("WINDOW_STEPS"));
    let repeats: usize = args.get(2).map_or(3, |s| s.parse().expect("REPEATS"));
    let built = demsweep::scene::Scene::from_file(std::path::Path::new(scene)).expect("scene").build().expect("build");
    let total = (built.duration_s / built.model.dt_s()).ceil() as u64;
    let mut m = built.model;
    m.threading = Threading::Serial;
    println!(
        "{:>11} {:>9} {:>8} {:>12} {:>8} {:>10} {:>9} {:>14} {:>6}",
        "steps", "contacts", "intact", "in_runs_of_4", "apart", "touching", "ms/step", "one_at_a_time", "gain"
    );
    let mut from = 0;
    while from < total {
        let n = window.min(total - from);
        let census = Census::of(&m);
        // Lanes and one at a time alternate, so the machine's spells hit both alike.
        let mut times = [Vec::new(), Vec::new()];
        let mut end = None;
        for _ in 0..repeats.max(1) {
            for (lanes, t) in [true, false].into_iter().zip(times.iter_mut()) {
                let mut c = m.clone();
                c.four_lanes = lanes;
                let start = Instant::now();
                c.run_steps(n).expect("step");
                t.push(start.elapsed().as_secs_f64() / n as f64);
                let bits: Vec<u64> = c.state.pos.iter().chain(&c.state.vel).flatten().map(|v| v.to_bits()).collect();
                assert!(end.as_ref().is_none_or(|(b, _)| *b == bits), "copies of one model ended apart");
                end = Some((bits, c));
            }
        }
        let [lanes, scalar] = times.map(|mut t| {
            t.sort_by(f64::total_cmp);
            t[t.len() / 2] * 1e3
        });
        let share = |k: u64| k as f64 / census.contacts as f64;
        println!(
            "{:>5}-{:<5} {:>9} {:>8.3} {:>12.3} {:>8.3} {:>10.3} {:>9.3} {:>14.3} {:>6.2}",
            from,
            from + n,
            census.contacts,
            share(census.intact),
            share(census.in_runs),
            share(census.apart),
            share(census.touching),
            lanes,
            scalar,
            scalar / lanes
        );
        m = end.expect("one copy at least").1;
        from += n;
    }
}

/// Contacts of a model by what the contact stage does with them.
struct Census {
    contacts: u64,
    intact: u64,
    /// Intact bonds in the aligned groups of four of one class the lanes take.
    in_runs: u64,
    /// Frictional pairs apart with no shear spring and their rest length back at r_i + r_j.
    apart: u64,
    /// The other frictional pairs.
    touching: u64,
}

impl Census {
    fn of(m: &demsweep::kernel::Model) -> Census {
        let (cs, pos) = (&m.state.contacts.list, &m.state.pos);
        let mut n = Census { contacts: cs.len() as u64, intact: 0, in_runs: 0, apart: 0, touching: 0 };
        // The lanes take aligned groups of four within each chunk of the contact stage.
        for chunk in cs.chunks(demsweep::kernel::forces::CHUNK) {
            let runs = chunk.chunks_exact(groups::LANES).filter(|&g| groups::eligible(g.try_into().expect("a group of four")));
            n.in_runs += (runs.count() * groups::LANES) as u64;
        }
        // The contact stage's in-line test (`law::friction::idle`).
        for c in cs {
            if c.bond == Bond::Intact {
                n.intact += 1;
                continue;
            }
            let d2_m2 = demsweep::kernel::geometry::separation(pos, c).d2_m2;
            if demsweep::kernel::law::friction::idle(c.ut_m, c.rest_m, m.classes[c.class as usize].radius_sum_m, d2_m2) {
                n.apart += 1;
            } else {
                n.touching += 1;
            }
        }
        n
    }
}
