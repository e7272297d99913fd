//! `demsweep empirical`: tables of the classical formulas (placeholder until [2/5] lands).

/// Arguments of `demsweep empirical`.
#[derive(Debug, clap::Args)]
pub struct Args {}

/// Print the table.
pub fn run(_args: Args) -> crate::error::Result<()> {
    Err(crate::error::Error::input("empirical", "not implemented yet"))
}
