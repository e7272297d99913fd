//! `demsweep bench`: the kernel's speed on the benchmark block, one thread and all threads.

use crate::bench::{self, COLUMNS, ROWS};
use crate::error::{Error, Result};

/// Arguments of `demsweep bench`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Steps per timed repeat.
    #[arg(long, default_value_t = 500)]
    pub steps: u64,
    /// Timed repeats (the median is reported).
    #[arg(long, default_value_t = 7)]
    pub repeats: usize,
    /// Thread counts to measure (default: 1 and all available).
    #[arg(long, value_delimiter = ',')]
    pub threads: Vec<usize>,
}

/// Run the benchmark and print its figures.
pub fn run(args: Args) -> Result<()> {
    if args.steps == 0 || args.repeats == 0 {
        return Err(Error::input("--steps/--repeats", "must be ≥ 1"));
    }
    let all = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
    let threads = if args.threads.is_empty() { if all > 1 { vec![1, all] } else { vec![1] } } else { args.threads };
    println!("demsweep bench: close-packed block {COLUMNS} × {ROWS}, all bonds intact, undamped, median of {} × {} steps", args.repeats, args.steps);
    println!("threads  elements  contacts  ms/step   ns/contact-step  (min–max)      element-steps/s");
    let mut single = None;
    for t in threads {
        let f = bench::measure(COLUMNS, ROWS, args.steps, args.repeats, t)?;
        println!(
            "{:>7}  {:>8}  {:>8}  {:>7.3}   {:>15.2}  ({:.2}–{:.2})  {:>14.4e}",
            f.threads,
            f.elements,
            f.contacts,
            f.step_s * 1e3,
            f.ns_per_contact_step,
            f.range_ns.0,
            f.range_ns.1,
            f.element_steps_per_s
        );
        if t == 1 {
            single = Some(f.step_s);
        } else if let Some(s1) = single {
            println!("         speed-up over 1 thread: {:.2} (parallel efficiency {:.0} %)", s1 / f.step_s, 100.0 * s1 / f.step_s / t as f64);
        }
    }
    Ok(())
}
