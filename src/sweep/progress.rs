//! Progress of a sweep on stderr: an indicatif bar (runs done, ETA, outcomes so far) on a
//! terminal, one plain line per finished run otherwise (logs, Slurm).

use std::io::IsTerminal;
use std::time::Instant;

/// What the user sees while a sweep runs.
pub struct Progress {
    bar: Option<indicatif::ProgressBar>,
    total: usize,
    done: usize,
    quiet: bool,
    start: Instant,
    /// Outcome counts so far (`scabbed`, `perforated`, failures).
    counts: [usize; 3],
}

/// A short outcome of a summary row (penetration rows: scabbed / perforated / end reason).
pub fn outcome(row: &[(String, String)]) -> String {
    let get = |k: &str| row.iter().find(|c| c.0 == k).map(|c| c.1.as_str());
    match (get("scabbed"), get("perforated"), get("end_reason")) {
        (Some(s), Some(p), Some(e)) => {
            let mut words = Vec::new();
            if p == "true" {
                words.push("perforated".to_string());
            } else if s == "true" {
                words.push("scabbed".to_string());
            } else {
                words.push("held".to_string());
            }
            words.push(format!("({e})"));
            if let Some(d) = get("depth_in").and_then(|d| d.parse::<f64>().ok()) {
                words.push(format!("depth {d:.2} in"));
            }
            words.join(" ")
        }
        _ => "done".into(),
    }
}

impl Progress {
    /// A display for `total` runs (of which `skipped` are already done).
    pub fn new(total: usize, skipped: usize, quiet: bool) -> Progress {
        let bar = (!quiet && std::io::stderr().is_terminal()).then(|| {
            let b = indicatif::ProgressBar::new(total as u64);
            b.set_style(
                indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len} runs, {elapsed} elapsed, ETA {eta}  {msg}")
                    .expect("a valid template"),
            );
            b.set_position(skipped as u64);
            b
        });
        if !quiet && bar.is_none() && skipped > 0 {
            eprintln!("{skipped} of {total} runs already done");
        }
        Progress { bar, total, done: skipped, quiet, start: Instant::now(), counts: [0; 3] }
    }

    /// A run finished (`Ok` row) or failed.
    pub fn finished(&mut self, id: &str, row: std::result::Result<&[(String, String)], String>) {
        self.done += 1;
        let word = match row {
            Ok(r) => {
                let get = |k: &str| r.iter().find(|c| c.0 == k).map(|c| c.1 == "true").unwrap_or(false);
                self.counts[0] += get("scabbed") as usize;
                self.counts[1] += get("perforated") as usize;
                outcome(r)
            }
            Err(e) => {
                self.counts[2] += 1;
                format!("FAILED: {e}")
            }
        };
        let so_far = format!("{} scabbed, {} perforated, {} failed", self.counts[0], self.counts[1], self.counts[2]);
        match &self.bar {
            Some(b) => {
                b.set_position(self.done as u64);
                b.set_message(so_far);
            }
            None if !self.quiet => {
                eprintln!("[{}/{}] {id}: {word}  ({:.1} s elapsed; {so_far})", self.done, self.total, self.start.elapsed().as_secs_f64())
            }
            None => {}
        }
    }

    /// Clear the bar.
    pub fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }
}
