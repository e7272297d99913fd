//! `demsweep bench`: the kernel's speed on the benchmark workloads, one thread and all threads.

use crate::bench::{self, COLUMNS, Figures, Laws, ROWS, Workload};
use crate::error::{Error, Result};

/// Arguments of `demsweep bench`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Workload: the all-bonded block, or the projectile at 1500 ft/s into the breakable block
    /// (which is measured beside the block, in the same run, and compared with it).
    #[arg(long, value_enum, default_value = "block")]
    pub workload: Workload,
    /// Steps per timed repeat of the block (the impact runs while its nose crosses the first
    /// 20 % of the block).
    #[arg(long, default_value_t = 500)]
    pub steps: u64,
    /// Timed rounds, each timing one repeat on every thread count in turn (the medians are
    /// reported; a speed-up is the median of the rounds' own ratios).
    #[arg(long, default_value_t = 7)]
    pub repeats: usize,
    /// Thread counts to measure (default: 1 and all available).
    #[arg(long, value_delimiter = ',')]
    pub threads: Vec<usize>,
    /// Block sizes, columns × rows of elements (e.g. `20x16,240x200`): the kernel's cost per
    /// contact-step against the problem's size, from a block in the first level of cache to one
    /// in the last. Each repeat takes `--steps` × 12 000 / (columns × rows) steps (at least
    /// one), so every size does the default block's work.
    #[arg(long, value_delimiter = ',', value_parser = parse_size, default_value = "120x100")]
    pub size: Vec<(usize, usize)>,
    /// Instead: the block on one thread with no optional law, each one alone, all of them, and
    /// the simple kernel (linear springs, central differences, serial scatter), timed in turn.
    #[arg(long)]
    pub laws: bool,
}

/// "COLUMNSxROWS", each at least 2.
fn parse_size(s: &str) -> std::result::Result<(usize, usize), String> {
    let bad = || format!("expected COLUMNSxROWS with each ≥ 2 (e.g. 120x100), got {s:?}");
    let (c, r) = s.split_once(['x', '×']).ok_or_else(bad)?;
    match (c.trim().parse::<usize>(), r.trim().parse::<usize>()) {
        (Ok(c), Ok(r)) if c >= 2 && r >= 2 => Ok((c, r)),
        _ => Err(bad()),
    }
}

/// Steps per repeat of a `columns` × `rows` block: `steps` of the default block's work.
fn steps_for(steps: u64, (columns, rows): (usize, usize)) -> u64 {
    ((steps as f64 * (COLUMNS * ROWS) as f64 / (columns * rows) as f64).round() as u64).max(1)
}

/// `--laws`: "model only what a scene needs" and the full law against the simple kernel.
fn laws(args: &Args) -> Result<()> {
    let none = Laws::default();
    let sets = [
        none,
        Laws { friction: true, ..none },
        Laws { damping: true, ..none },
        Laws { rate: true, ..none },
        Laws { compaction: true, ..none },
        Laws::ALL,
    ];
    println!(
        "demsweep bench --laws: close-packed block {COLUMNS} × {ROWS}, one thread, {} steps × {} rounds (round-robin); times medians, ratios medians of each round's own",
        args.steps, args.repeats
    );
    let rows = bench::measure_laws(&sets, COLUMNS, ROWS, args.steps, args.repeats)?;
    let (none_row, simple_row) = (&rows[0], &rows[rows.len() - 1]);
    for (name, laws) in [("none", none), ("all", Laws::ALL)] {
        let (e, c) = bench::footprint(&bench::workload_with(COLUMNS, ROWS, laws)?);
        println!("memory, optional parts {name}: {e:.0} bytes per element, {c:.0} bytes per contact");
    }
    println!("{:>22}  {:>8}  {:>8}  {:>16}  {:>8}  {:>9}", "optional parts", "contacts", "ms/step", "(min–max)", "/ none", "/ simple");
    for r in &rows {
        println!(
            "{:>22}  {:>8}  {:>8.3}  ({:.3}–{:.3})  {:>8.3}  {:>9.3}",
            r.name,
            r.contacts,
            r.step_s * 1e3,
            r.range_s.0 * 1e3,
            r.range_s.1 * 1e3,
            r.ratio_to(none_row),
            r.ratio_to(simple_row)
        );
    }
    Ok(())
}

fn row(name: &str, f: &Figures) {
    println!(
        "{name:>7}  {:>7}  {:>8}  {:>9.0}  {:>7.3}   {:>15.2}  ({:.2}–{:.2})  {:>14.4e}  {:>8.1} ({:.1})",
        f.threads,
        f.elements,
        f.contacts,
        f.step_s * 1e3,
        f.ns_per_contact_step,
        f.range_ns.0,
        f.range_ns.1,
        f.element_steps_per_s,
        f.rebuilds_per_1000,
        f.local_updates_per_1000
    );
}

/// Run the benchmark and print its figures.
pub fn run(args: Args) -> Result<()> {
    if args.steps == 0 || args.repeats == 0 {
        return Err(Error::input("--steps/--repeats", "must be ≥ 1"));
    }
    if args.laws {
        if args.size != [(COLUMNS, ROWS)] {
            return Err(Error::input("--size", format!("--laws measures the {COLUMNS} × {ROWS} block only")));
        }
        return laws(&args);
    }
    let all = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
    let threads = if args.threads.is_empty() { if all > 1 { vec![1, all] } else { vec![1] } } else { args.threads.clone() };
    let workloads: &[Workload] = match args.workload {
        Workload::Block => &[Workload::Block],
        Workload::Impact => &[Workload::Block, Workload::Impact],
        Workload::Block3d => return block3d(&args, &threads),
        Workload::Impact3d => return impact3d(&args, &threads),
    };
    let sizes: Vec<String> = args.size.iter().map(|(c, r)| format!("{c} × {r}")).collect();
    println!(
        "demsweep bench: close-packed block {}{}; medians of {} rounds, each timing every thread count in turn",
        sizes.join(", "),
        if args.workload == Workload::Impact { ", and the seed's projectile at 1500 ft/s through 20 % of it" } else { ", all bonds intact, undamped" },
        args.repeats
    );
    println!("   work  threads  elements  contacts  ms/step   ns/contact-step  (min–max)      element-steps/s  rebuilds (local) /1000 steps");
    for &size in &args.size {
        let mut block: Option<Vec<Figures>> = None;
        for &w in workloads {
            let figures = bench::measure(w, size.0, size.1, steps_for(args.steps, size), args.repeats, &threads)?;
            for f in &figures {
                row(if w == Workload::Block { "block" } else { "impact" }, f);
            }
            if let Some(one) = figures.iter().find(|f| f.threads == 1) {
                for f in figures.iter().filter(|f| f.threads > 1) {
                    let s = f.speed_up_over(one);
                    println!("         speed-up on {} threads over 1: {s:.2} (parallel efficiency {:.0} %; median of the rounds' own ratios)", f.threads, 100.0 * s / f.threads as f64);
                }
            }
            if let (Workload::Impact, Some(b)) = (w, &block) {
                for (f, b) in figures.iter().zip(b) {
                    println!("         impact / block on {} thread(s), ns per contact-step: {:.3} ({} steps)", f.threads, f.ns_per_contact_step / b.ns_per_contact_step, f.steps);
                }
            }
            if w == Workload::Block {
                block = Some(figures);
            }
        }
    }
    Ok(())
}

/// The 3D kernel's block: ns per bond-step on each thread count.
fn block3d(args: &Args, threads: &[usize]) -> Result<()> {
    let side = 30.0;
    let figures = bench::block3d::measure(side, args.steps, args.repeats, threads)?;
    println!("demsweep bench --workload block3d: fcc block of side {side} R, every bond intact, rolling and twisting on, undamped; medians of {} rounds", args.repeats);
    let m = bench::block3d::workload(side)?;
    println!(
        "block3d model: spheres {} bonds {} contacts {} dt_s {:.17e} dt_bound_s {:.17e} skin_m {:.6e} mass_kg {:.17e}",
        m.spheres.len(),
        m.intact_bonds(),
        m.state.contacts.len(),
        m.motion.dt_s,
        m.dt_bound_s,
        m.skin_m,
        m.spheres.mass_kg[0]
    );
    println!("threads  spheres  bonds   ns/bond-step  (min–max)");
    for f in &figures {
        println!("{:7}  {:7}  {:6}  {:12.2}  ({:.2}–{:.2})", f.threads, f.spheres, f.bonds, f.ns_per_bond_step, f.range_ns.0, f.range_ns.1);
    }
    Ok(())
}

/// The 3D kernel's example impact: ns per contact-step on each thread count.
fn impact3d(args: &Args, threads: &[usize]) -> Result<()> {
    let figures = bench::impact3d::measure(args.steps, args.repeats, threads)?;
    let m = bench::impact3d::workload()?;
    println!(
        "demsweep bench --workload impact3d: sweeps/impact3d.toml, its first {} steps ({:.3e} s of {} s), {} spheres; medians of {} rounds",
        args.steps,
        args.steps as f64 * m.motion.dt_s,
        bench::impact3d::SCENE.lines().find_map(|l| l.strip_prefix("duration_s = ")).unwrap_or("?"),
        m.spheres.len(),
        args.repeats
    );
    println!("threads  contacts (mean)  bonds broken  ns/contact-step  (min–max)");
    for f in &figures {
        println!("{:7}  {:15.0}  {:12}  {:15.2}  ({:.2}–{:.2})", f.threads, f.mean_contacts, f.bonds_broken, f.ns_per_contact_step, f.range_ns.0, f.range_ns.1);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_size_is_columns_by_rows_of_at_least_two() {
        assert_eq!(parse_size("20x16"), Ok((20, 16)));
        assert_eq!(parse_size("240×200"), Ok((240, 200)));
        for bad in ["120", "1x100", "120x1", "ax2", "12x", "-3x4", ""] {
            assert!(parse_size(bad).is_err(), "{bad:?} taken");
        }
    }

    #[test]
    fn every_size_does_the_default_blocks_work_per_repeat() {
        assert_eq!(steps_for(500, (COLUMNS, ROWS)), 500);
        // A quarter of the elements, four times the steps; twice, half (rounded).
        assert_eq!(steps_for(500, (COLUMNS / 2, ROWS / 2)), 2000);
        assert_eq!(steps_for(501, (2 * COLUMNS, ROWS)), 251);
        // Never no step at all.
        assert_eq!(steps_for(1, (100 * COLUMNS, ROWS)), 1);
    }
}
