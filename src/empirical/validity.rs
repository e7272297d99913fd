//! What a formula predicts ([`Quantity`]) and whether its inputs lie inside the formula's stated
//! range ([`Validity`]).

use std::fmt;

/// The three local-damage quantities of FORMULAS §4.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// Penetration depth x into a semi-infinite target, in.
    Penetration,
    /// Scabbing limit h_s: least thickness with no rear-face scabbing, in.
    Scabbing,
    /// Perforation limit h_p: least thickness not perforated, in.
    Perforation,
}

impl Quantity {
    /// All three, in table order.
    pub const ALL: [Quantity; 3] = [Quantity::Penetration, Quantity::Scabbing, Quantity::Perforation];

    /// Short symbol (x, h_s, h_p).
    pub fn symbol(self) -> &'static str {
        match self {
            Quantity::Penetration => "x",
            Quantity::Scabbing => "h_s",
            Quantity::Perforation => "h_p",
        }
    }
}

/// Whether a prediction's inputs lie inside the formula's stated validity range.
#[derive(Debug, Clone, PartialEq)]
pub enum Validity {
    /// Every stated bound holds.
    Inside,
    /// At least one stated bound fails; the text says which (e.g. `V = 457 m/s > 311.8 m/s`).
    Outside(String),
    /// The sources state no range for this formula (e.g. Petry, BRL: "limited test data").
    Unstated,
}

impl Validity {
    /// `lo ≤ value ≤ hi`, else `Outside` naming the quantity, its value and the broken bound.
    pub fn range(name: &str, value: f64, lo: f64, hi: f64, unit: &str) -> Validity {
        let unit = if unit.is_empty() { String::new() } else { format!(" {unit}") };
        let shown = significant(value, 4);
        if value < lo {
            Validity::Outside(format!("{name} = {shown}{unit} < {lo}{unit}"))
        } else if value > hi {
            Validity::Outside(format!("{name} = {shown}{unit} > {hi}{unit}"))
        } else {
            Validity::Inside
        }
    }

    /// Combine: any `Outside` wins (reasons joined), else any `Inside`, else `Unstated`.
    pub fn and(self, other: Validity) -> Validity {
        match (self, other) {
            (Validity::Outside(a), Validity::Outside(b)) => {
                // The same bound can fail for two quantities (e.g. f'c for h_s and h_p): say it once.
                let mut reasons: Vec<&str> = a.split("; ").collect();
                for r in b.split("; ") {
                    if !reasons.contains(&r) {
                        reasons.push(r);
                    }
                }
                Validity::Outside(reasons.join("; "))
            }
            (o @ Validity::Outside(_), _) | (_, o @ Validity::Outside(_)) => o,
            (Validity::Inside, _) | (_, Validity::Inside) => Validity::Inside,
            (Validity::Unstated, Validity::Unstated) => Validity::Unstated,
        }
    }

    /// Combine a list (empty → `Unstated`).
    pub fn all(checks: impl IntoIterator<Item = Validity>) -> Validity {
        checks.into_iter().fold(Validity::Unstated, Validity::and)
    }

    /// False only when a stated bound fails.
    pub fn is_usable(&self) -> bool {
        !matches!(self, Validity::Outside(_))
    }

    /// Table cell: `true`, `false` or `unstated`.
    pub fn cell(&self) -> &'static str {
        match self {
            Validity::Inside => "true",
            Validity::Outside(_) => "false",
            Validity::Unstated => "unstated",
        }
    }
}

/// `value` with `digits` significant digits (at least 0 decimals): 607.4, 20.68, 0.1234.
fn significant(value: f64, digits: i32) -> String {
    let magnitude = if value == 0.0 { 0 } else { value.abs().log10().floor() as i32 };
    let decimals = (digits - 1 - magnitude).max(0) as usize;
    format!("{value:.decimals$}")
}

impl fmt::Display for Validity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Validity::Inside => write!(f, "inside the stated validity range"),
            Validity::Outside(why) => write!(f, "outside the stated validity range: {why}"),
            Validity::Unstated => write!(f, "no validity range stated"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn combination_rules() {
        let out = Validity::range("V", 400.0, 25.0, 311.8, "m/s");
        assert_eq!(out, Validity::Outside("V = 400.0 m/s > 311.8 m/s".into()));
        let fc = Validity::range("f'c", 20.6843, 22.8, 45.5, "MPa");
        assert_eq!(Validity::all([fc.clone(), out.clone(), fc]).to_string(),
            "outside the stated validity range: f'c = 20.68 MPa < 22.8 MPa; V = 400.0 m/s > 311.8 m/s");
        assert_eq!(Validity::range("I", 1.0, 0.3, 21.0, ""), Validity::Inside);
        assert_eq!(Validity::all([]), Validity::Unstated);
        assert_eq!(Validity::all([Validity::Unstated, Validity::Inside]), Validity::Inside);
        assert!(!Validity::all([Validity::Inside, out.clone(), Validity::Unstated]).is_usable());
        assert_eq!(out.cell(), "false");
    }
}
