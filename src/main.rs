//! The `demsweep` command: parse arguments, call one library function, report errors.

use clap::Parser;

fn main() {
    let cli = demsweep::cli::Cli::parse();
    if let Err(e) = demsweep::cli::dispatch(cli) {
        // A reader that stops early (`demsweep empirical | head`) is not a failure.
        if let demsweep::Error::Io { path, message } = &e
            && path.as_os_str() == "<stdout>"
            && message.contains("Broken pipe")
        {
            std::process::exit(0);
        }
        eprintln!("demsweep: error: {e}");
        std::process::exit(e.exit_code());
    }
}
