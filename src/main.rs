//! The `demsweep` command: parse arguments, call one library function, report errors.

use clap::Parser;

fn main() {
    let cli = demsweep::cli::Cli::parse();
    if let Err(e) = demsweep::cli::dispatch(cli) {
        eprintln!("demsweep: error: {e}");
        std::process::exit(e.exit_code());
    }
}
