//! Convergence studies of the validation cases: run a case at several refinement levels and
//! tabulate each level's figure, its cost and, from three levels, the observed order,
//! Richardson extrapolate and GCI (SPEC §5). The tables are what `results/validation/` holds
//! and what the regression tests compare against.

use std::time::Instant;

use crate::analysis::{Convergence, richardson};
use crate::error::Result;
use crate::run::RunResult;
use crate::table::Table;

/// One level's outcome.
#[derive(Debug, Clone, PartialEq)]
pub struct Level {
    /// Refinement level.
    pub level: u32,
    /// Elements.
    pub elements: usize,
    /// Steps.
    pub steps: u64,
    /// Time step, s.
    pub dt_s: f64,
    /// The figure (its unit is the study's).
    pub value: f64,
    /// Wall time, s.
    pub wall_s: f64,
}

impl Level {
    /// From a finished run and its figure.
    pub fn from_run<M>(level: u32, elements: usize, value: f64, result: &RunResult<M>, wall_s: f64) -> Level {
        Level { level, elements, steps: result.summary.steps, dt_s: result.summary.dt_s, value, wall_s }
    }
}

/// Time a closure returning (elements, figure, run).
pub fn timed<M>(level: u32, f: impl FnOnce() -> Result<(usize, f64, RunResult<M>)>) -> Result<Level> {
    let t0 = Instant::now();
    let (n, v, r) = f()?;
    Ok(Level::from_run(level, n, v, &r, t0.elapsed().as_secs_f64()))
}

/// A study's table: one row per level with the reference beside it, then (with three levels)
/// the observed order, extrapolate and GCI. `column` names the figure with its unit.
pub fn table(column: &str, reference: f64, levels: &[Level], alpha: f64) -> (Table, Option<Convergence>) {
    let header = ["level", "elements", "steps", "dt_s", "element_steps", "wall_s", column, "reference", "error_pct"];
    let mut rows: Vec<Vec<String>> = levels
        .iter()
        .map(|l| {
            vec![
                l.level.to_string(),
                l.elements.to_string(),
                l.steps.to_string(),
                format!("{:.6e}", l.dt_s),
                format!("{:.4e}", l.elements as f64 * l.steps as f64),
                format!("{:.2}", l.wall_s),
                format!("{:.9e}", l.value),
                format!("{reference:.9e}"),
                format!("{:+.4}", 100.0 * (l.value / reference - 1.0)),
            ]
        })
        .collect();
    let conv = if levels.len() == 3 { richardson([levels[0].value, levels[1].value, levels[2].value], alpha).ok() } else { None };
    if let Some(c) = conv {
        let blank = || String::new();
        rows.push(vec![
            "richardson".into(),
            blank(),
            blank(),
            blank(),
            blank(),
            format!("order={:.4}", c.order),
            format!("{:.9e}", c.extrapolate),
            format!("{reference:.9e}"),
            format!("{:+.4}", 100.0 * (c.extrapolate / reference - 1.0)),
        ]);
        rows.push(vec!["gci_fine_pct".into(), blank(), blank(), blank(), blank(), blank(), format!("{:.4}", 100.0 * c.gci_fine), blank(), blank()]);
    }
    (Table { header: header.iter().map(|s| s.to_string()).collect(), rows }, conv)
}
