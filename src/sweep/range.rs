//! Velocity ranges on the command line: `START..END` (inclusive) or a single `V`, stepped by
//! `--step`. Parsed for the command line, stepped for every sweep over impact velocity.

use crate::error::{Error, Result};

/// Parse `START..END` or `V` (ft/s) given to argument `arg`; the start must be > 0 and not
/// exceed the end.
pub fn parse(arg: &str, text: &str) -> Result<(f64, f64)> {
    let number = |s: &str| -> Result<f64> {
        let v: f64 = s.trim().parse().map_err(|_| {
            Error::input(arg, format!("`{text}` is not a range: expected START..END or a single value, e.g. 500..1500"))
        })?;
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err(Error::input(arg, format!("velocities must be > 0, got {v}")))
        }
    };
    let (start, end) = match text.split_once("..") {
        Some((a, b)) => (number(a)?, number(b)?),
        None => {
            let v = number(text)?;
            (v, v)
        }
    };
    if start > end {
        return Err(Error::input(arg, format!("reversed range {text}: the start must not exceed the end")));
    }
    Ok((start, end))
}

/// The velocities start, start + step, … up to end inclusive (within 1e-9 of a step, so that
/// 500..1500 by 50 ends at 1500 despite rounding). `step_arg` names the step's argument.
pub fn steps(start: f64, end: f64, step: f64, step_arg: &str) -> Result<Vec<f64>> {
    if !(step.is_finite() && step > 0.0) {
        return Err(Error::input(step_arg, format!("must be > 0, got {step}")));
    }
    let n = ((end - start) / step + 1e-9).floor() as usize;
    Ok((0..=n).map(|k| start + step * k as f64).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inclusive_range_and_single_value() {
        let (a, b) = parse("--v0", "500..1500").unwrap();
        let v = steps(a, b, 50.0, "--step").unwrap();
        assert_eq!(v.len(), 21);
        assert_eq!((v[0], v[20]), (500.0, 1500.0));
        assert_eq!(parse("--v0", "750").unwrap(), (750.0, 750.0));
        assert_eq!(steps(0.1, 0.3, 0.1, "--step").unwrap().len(), 3);
    }

    #[test]
    fn bad_ranges_name_the_argument() {
        for bad in ["1500..500", "abc", "500..", "-5..10", "0..10"] {
            let e = parse("--v0", bad).unwrap_err().to_string();
            assert!(e.starts_with("`--v0`"), "{bad}: {e}");
        }
        assert!(parse("--v0", "1500..500").unwrap_err().to_string().contains("reversed"));
        assert!(steps(1.0, 2.0, 0.0, "--step").is_err());
    }
}
