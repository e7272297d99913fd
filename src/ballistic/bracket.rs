//! Where an outcome first appears along the velocity axis, from the runs made so far, and the
//! next velocity to bisect at. Recomputed from every run after each round, so a bisection
//! run that contradicts the grid is seen, never bisected across in silence.

/// A run's velocity and whether it showed the outcome.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    /// Impact velocity, ft/s.
    pub v_fps: f64,
    /// The outcome (scabbed, perforated) was seen.
    pub hit: bool,
}

/// Where the threshold is.
#[derive(Debug, Clone, PartialEq)]
pub enum Bracket {
    /// Between the last velocity without the outcome and the first with it, ft/s.
    Between {
        /// Highest velocity below the first hit without the outcome, ft/s.
        lo_fps: f64,
        /// Lowest velocity with the outcome, ft/s.
        hi_fps: f64,
    },
    /// The lowest velocity run already shows it: at or below that, ft/s.
    AtOrBelow(f64),
    /// No run shows it: not reached up to the highest velocity run, ft/s.
    NotReached(f64),
    /// No runs.
    Empty,
}

/// The bracket and the runs that break monotonicity.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    /// Where the first appearance is.
    pub bracket: Bracket,
    /// Velocities above the first hit without the outcome (ft/s, ascending): non-monotone.
    pub exceptions_fps: Vec<f64>,
}

/// The first appearance of the outcome among `points` (any order).
pub fn find(points: &[Point]) -> Finding {
    let mut p: Vec<Point> = points.to_vec();
    p.sort_by(|a, b| a.v_fps.total_cmp(&b.v_fps));
    let Some(first) = p.iter().position(|q| q.hit) else {
        let bracket = p.last().map_or(Bracket::Empty, |q| Bracket::NotReached(q.v_fps));
        return Finding { bracket, exceptions_fps: Vec::new() };
    };
    let exceptions_fps = p[first..].iter().filter(|q| !q.hit).map(|q| q.v_fps).collect();
    let bracket = match first {
        0 => Bracket::AtOrBelow(p[0].v_fps),
        k => Bracket::Between { lo_fps: p[k - 1].v_fps, hi_fps: p[k].v_fps },
    };
    Finding { bracket, exceptions_fps }
}

impl Finding {
    /// The next velocity to run, ft/s: the bracket's midpoint while it is wider than `tol_fps`.
    pub fn next(&self, tol_fps: f64) -> Option<f64> {
        match self.bracket {
            Bracket::Between { lo_fps, hi_fps } if hi_fps - lo_fps > tol_fps => Some(0.5 * (lo_fps + hi_fps)),
            _ => None,
        }
    }

    /// The estimate: the bracket's midpoint, ft/s.
    pub fn estimate_fps(&self) -> Option<f64> {
        match self.bracket {
            Bracket::Between { lo_fps, hi_fps } => Some(0.5 * (lo_fps + hi_fps)),
            _ => None,
        }
    }

    /// What to say about it in a table's note.
    pub fn note(&self, what: &str) -> String {
        let mut s = match self.bracket {
            Bracket::Between { .. } => String::new(),
            Bracket::AtOrBelow(v) => format!("{what} already at the lowest velocity run, {v} ft/s: not reached below the range"),
            Bracket::NotReached(v) => format!("no {what} up to {v} ft/s: not reached in the range"),
            Bracket::Empty => "no runs".into(),
        };
        if !self.exceptions_fps.is_empty() {
            let list: Vec<String> = self.exceptions_fps.iter().map(|v| v.to_string()).collect();
            if !s.is_empty() {
                s.push_str("; ");
            }
            s.push_str(&format!("non-monotone: no {what} at {} ft/s, above the first {what}", list.join(", ")));
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(v: &[(f64, bool)]) -> Vec<Point> {
        v.iter().map(|&(v_fps, hit)| Point { v_fps, hit }).collect()
    }

    #[test]
    fn brackets_the_first_appearance_and_bisects_to_the_tolerance() {
        let mut p = pts(&[(500.0, false), (550.0, false), (600.0, true), (650.0, true)]);
        let mut f = find(&p);
        assert_eq!(f.bracket, Bracket::Between { lo_fps: 550.0, hi_fps: 600.0 });
        let threshold = 571.0;
        let mut runs = 0;
        while let Some(v) = f.next(5.0) {
            p.push(Point { v_fps: v, hit: v >= threshold });
            f = find(&p);
            runs += 1;
        }
        assert_eq!(runs, 4, "50 → 25 → 12.5 → 6.25 → 3.125 ft/s");
        let Bracket::Between { lo_fps, hi_fps } = f.bracket else { panic!() };
        assert!(lo_fps < threshold && threshold <= hi_fps && hi_fps - lo_fps <= 5.0);
        assert!(f.exceptions_fps.is_empty());
    }

    #[test]
    fn non_monotone_outcomes_are_reported_not_bisected_across() {
        let f = find(&pts(&[(850.0, false), (900.0, true), (950.0, false), (1000.0, true)]));
        assert_eq!(f.bracket, Bracket::Between { lo_fps: 850.0, hi_fps: 900.0 });
        assert_eq!(f.exceptions_fps, vec![950.0]);
        assert!(f.note("scabbing").contains("non-monotone: no scabbing at 950 ft/s"));
    }

    #[test]
    fn a_range_that_does_not_bracket_says_so() {
        let f = find(&pts(&[(500.0, false), (550.0, false)]));
        assert_eq!(f.bracket, Bracket::NotReached(550.0));
        assert_eq!(f.next(5.0), None);
        assert!(f.note("perforation").contains("not reached in the range"));
        let f = find(&pts(&[(500.0, true), (550.0, true)]));
        assert_eq!(f.bracket, Bracket::AtOrBelow(500.0));
        assert!(f.note("scabbing").contains("not reached below the range"));
        assert_eq!(find(&[]).bracket, Bracket::Empty);
    }
}
