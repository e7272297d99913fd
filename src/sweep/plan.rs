//! What a sweep runs: a grid (`--vary FIELD=START..END[:STEP]`, the Cartesian product of the
//! fields in the order given, the last fastest) or a parameter table (`--table PARAMS.csv`: one
//! column per dotted scene field, one run per row).

use std::path::Path;

use super::Job;
use crate::error::{Error, Result};
use crate::scene::overrides::Override;
use crate::table::Table;

/// One varied field.
#[derive(Debug, Clone, PartialEq)]
pub struct Vary {
    /// Dotted scene field.
    pub field: String,
    /// Its values, in order.
    pub values: Vec<toml::Value>,
}

impl Vary {
    /// Parse `FIELD=START..END[:STEP]` (inclusive; STEP may be left out for integer ends, then
    /// 1) or `FIELD=V1,V2,…`. Integer ends and step give integer values (a refinement level).
    pub fn parse(text: &str) -> Result<Vary> {
        let arg = format!("--vary {text}");
        let (field, spec) = text
            .split_once('=')
            .ok_or_else(|| Error::input(&arg, "expected FIELD=START..END[:STEP] or FIELD=V1,V2,… (e.g. projectile.v0_fps=500..1500:50)"))?;
        let field = field.trim().to_string();
        if field.is_empty() || field.split('.').any(|p| p.is_empty()) {
            return Err(Error::input(&arg, "the field is not a dotted path"));
        }
        let Some((start, rest)) = spec.split_once("..") else {
            let values = spec.split(',').map(|v| Override::parse(&format!("{field}={v}")).map(|o| o.value)).collect::<Result<Vec<_>>>()?;
            return Ok(Vary { field, values });
        };
        let (end, step) = match rest.split_once(':') {
            Some((e, s)) => (e, Some(s)),
            None => (rest, None),
        };
        let int = |s: &str| s.trim().parse::<i64>().ok();
        let num = |s: &str, what: &str| -> Result<f64> {
            s.trim().parse::<f64>().ok().filter(|v| v.is_finite()).ok_or_else(|| Error::input(&arg, format!("the {what} `{s}` is not a number")))
        };
        let (a, b) = (num(start, "start")?, num(end, "end")?);
        if a > b {
            return Err(Error::input(&arg, format!("reversed range: the start {a} exceeds the end {b}")));
        }
        let integral = int(start).is_some() && int(end).is_some() && step.is_none_or(|s| int(s).is_some());
        let h = match step {
            Some(s) => num(s, "step")?,
            None if integral => 1.0,
            None => return Err(Error::input(&arg, "give a step (START..END:STEP) for a range of non-integers")),
        };
        if h.is_nan() || h <= 0.0 {
            return Err(Error::input(&arg, format!("the step must be > 0, got {h}")));
        }
        let values = crate::sweep::range::steps(a, b, h, &arg)?
            .into_iter()
            .map(|v| if integral { toml::Value::Integer(v.round() as i64) } else { toml::Value::Float(v) })
            .collect();
        Ok(Vary { field, values })
    }
}

/// The runs of a grid: every combination, the last field varying fastest.
pub fn grid(vary: &[Vary]) -> Result<Vec<Job>> {
    if vary.is_empty() {
        return Err(Error::input("--vary", "nothing to vary: give --vary FIELD=START..END:STEP or --table PARAMS.csv"));
    }
    for (k, v) in vary.iter().enumerate() {
        if vary[..k].iter().any(|w| w.field == v.field) {
            return Err(Error::input("--vary", format!("{} is varied twice", v.field)));
        }
    }
    let mut jobs = vec![Vec::<Override>::new()];
    for v in vary {
        jobs = jobs
            .into_iter()
            .flat_map(|prefix| {
                v.values.iter().map(move |value| {
                    let mut o = prefix.clone();
                    o.push(Override { field: v.field.clone(), value: value.clone() });
                    o
                })
            })
            .collect();
    }
    Ok(jobs.into_iter().map(|overrides| Job { overrides, purpose: "grid".into() }).collect())
}

/// The runs of a parameter table: a column per dotted field, a run per row; each cell is a
/// TOML value (`850`, `"ogive"`, `true`), as with `--set`.
pub fn from_table(path: &Path) -> Result<Vec<Job>> {
    let t = Table::read_csv(path)?;
    if t.header.is_empty() || t.rows.is_empty() {
        return Err(Error::input(path.display().to_string(), "a parameter table needs a header of dotted scene fields and at least one row"));
    }
    t.rows
        .iter()
        .enumerate()
        .map(|(r, row)| {
            let overrides = t
                .header
                .iter()
                .zip(row)
                .map(|(field, cell)| Override::parse(&format!("{field}={cell}")))
                .collect::<Result<Vec<_>>>()
                .map_err(|e| Error::input(format!("{} row {}", path.display(), r + 1), e.to_string()))?;
            Ok(Job { overrides, purpose: "table".into() })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_lists_and_integers() {
        let v = Vary::parse("projectile.v0_fps=500..600:50").unwrap();
        assert_eq!(v.values, vec![toml::Value::Integer(500), toml::Value::Integer(550), toml::Value::Integer(600)]);
        let v = Vary::parse("projectile.angle_deg=0..1:0.5").unwrap();
        assert_eq!(v.values, vec![toml::Value::Float(0.0), toml::Value::Float(0.5), toml::Value::Float(1.0)]);
        assert_eq!(Vary::parse("penetration.level=0..2").unwrap().values.len(), 3);
        assert_eq!(Vary::parse("projectile.nose=\"flat\",\"hemispherical\"").unwrap().values.len(), 2);
        let g = grid(&[Vary::parse("a.x=1..2").unwrap(), Vary::parse("b.y=10..30:10").unwrap()]).unwrap();
        assert_eq!(g.len(), 6);
        assert_eq!(g[1].id(), "a.x=1;b.y=20");
    }

    #[test]
    fn bad_ranges_say_what_is_wrong() {
        for (bad, says) in [
            ("projectile.v0_fps=1500..500:50", "reversed"),
            ("projectile.v0_fps=500..1500:0", "step must be > 0"),
            ("projectile.v0_fps=500..1500:-50", "step must be > 0"),
            ("projectile.v0_fps=0.5..1.5", "give a step"),
            ("projectile.v0_fps", "expected FIELD="),
            ("projectile.v0_fps=a..b:1", "not a number"),
        ] {
            let e = Vary::parse(bad).unwrap_err().to_string();
            assert!(e.contains(says), "{bad}: {e}");
        }
    }
}
