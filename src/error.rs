//! One error type for the library. Every variant names what was wrong and where: the file and
//! field of a scene, the element and step of a numerical failure, the argument of a command.

use std::fmt;
use std::path::PathBuf;

/// Everything that can stop demsweep. Each message is meant for the engineer at the terminal.
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// A bad input value: `field` is the dotted path (scene) or the argument name (CLI).
    Input {
        /// Scene file, if the value came from one.
        file: Option<PathBuf>,
        /// Dotted field path, e.g. `material.concrete.poisson_ratio`, or `--weight-lb`.
        field: String,
        /// What is wrong and what is allowed.
        message: String,
    },
    /// A material that the chosen lattice cannot represent (e.g. ν* > 1/3 on a hexagonal lattice).
    Material {
        /// Material name.
        material: String,
        /// Explanation, including the allowed range and the named fallbacks.
        message: String,
    },
    /// The requested time step exceeds the stability bound.
    UnstableStep {
        /// Requested step, s.
        requested_s: f64,
        /// Stability bound, s.
        bound_s: f64,
        /// How the bound was obtained.
        detail: String,
    },
    /// The state became non-finite or ran away during a run.
    BlowUp {
        /// Step number (0-based count of completed steps when detected).
        step: u64,
        /// Simulated time at detection, s.
        time_s: f64,
        /// Element index.
        element: usize,
        /// What was seen.
        detail: String,
    },
    /// A run ended early because nobody needs it any more (a guess of the ballistic
    /// bisection that an outcome ruled out, [`crate::run::Lend::wanted`]); never shown as a failure.
    Abandoned {
        /// Steps completed when it ended.
        step: u64,
    },
    /// File-system failure.
    Io {
        /// Path involved.
        path: PathBuf,
        /// The OS message.
        message: String,
    },
}

impl Error {
    /// A bad-input error without a file.
    pub fn input(field: impl Into<String>, message: impl Into<String>) -> Self {
        Error::Input { file: None, field: field.into(), message: message.into() }
    }

    /// Attach a file name to an input error (other variants are returned unchanged).
    pub fn in_file(self, path: impl Into<PathBuf>) -> Self {
        match self {
            Error::Input { file: None, field, message } => {
                Error::Input { file: Some(path.into()), field, message }
            }
            other => other,
        }
    }

    /// Process exit code: 2 for bad input (as clap), 3 for numerical failure, 1 otherwise.
    pub fn exit_code(&self) -> i32 {
        match self {
            Error::Input { .. } | Error::Material { .. } | Error::UnstableStep { .. } => 2,
            Error::BlowUp { .. } => 3,
            Error::Io { .. } | Error::Abandoned { .. } => 1,
        }
    }

    /// An I/O error on `path`.
    pub fn io(path: impl Into<PathBuf>, err: impl fmt::Display) -> Self {
        Error::Io { path: path.into(), message: err.to_string() }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Input { file: Some(p), field, message } => {
                write!(f, "{}: field `{}`: {}", p.display(), field, message)
            }
            Error::Input { file: None, field, message } => write!(f, "`{field}`: {message}"),
            Error::Material { material, message } => write!(f, "material `{material}`: {message}"),
            Error::UnstableStep { requested_s, bound_s, detail } => write!(
                f,
                "time step {requested_s:.6e} s exceeds the stability bound {bound_s:.6e} s ({detail})"
            ),
            Error::BlowUp { step, time_s, element, detail } => write!(
                f,
                "numerical blow-up at step {step} (t = {time_s:.6e} s), element {element}: {detail}"
            ),
            Error::Abandoned { step } => write!(f, "run abandoned at step {step}: no longer needed"),
            Error::Io { path, message } => write!(f, "{}: {}", path.display(), message),
        }
    }
}

impl std::error::Error for Error {}

/// Result alias.
pub type Result<T> = std::result::Result<T, Error>;
