//! Which program made a result: the build id, a hash of the sources a run's result depends on
//! and the locked dependencies (`build.rs`), given to the crate as `DEMSWEEP_BUILD`. A sweep
//! keeps it in every row and reuses a row only under the same id; a checkpoint names it and is
//! refused by another build.

/// The id of this build of demsweep (16 hex digits). Two binaries with the same id compute the
/// same runs; a change to what only reads or draws the runs (the command line, pictures, the
/// formulas, the fits) keeps it.
pub fn build_id() -> &'static str {
    env!("DEMSWEEP_BUILD")
}

/// The commit checked out when this binary was built (12 hex digits, `-dirty` if tracked files
/// differed from it; `unknown` outside a git checkout). For the record only: runs are reused by
/// [`build_id`].
pub fn commit() -> &'static str {
    env!("DEMSWEEP_COMMIT")
}

/// `manifest.json` of an output folder: what made it — the command line, when it started and
/// ended (UTC), the machine, and the program's version, build and commit — written whole at the
/// end of a sweep (`ballistic`, `merge`, `sweep`, `converge`).
pub fn write_manifest(dir: &std::path::Path, started: std::time::SystemTime) -> crate::error::Result<std::path::PathBuf> {
    let q = |s: &str| {
        let mut out = String::from("\"");
        for c in s.chars() {
            match c {
                '"' => out.push_str("\\\""),
                '\\' => out.push_str("\\\\"),
                c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
                c => out.push(c),
            }
        }
        out + "\""
    };
    let args: Vec<String> = std::env::args().map(|a| q(&a)).collect();
    let cpu = std::fs::read_to_string("/proc/cpuinfo").ok().and_then(|t| t.lines().find(|l| l.starts_with("model name")).and_then(|l| l.split_once(':')).map(|(_, m)| m.trim().to_string()));
    let host = std::fs::read_to_string("/etc/hostname").ok().map(|h| h.trim().to_string()).or_else(|| std::env::var("HOSTNAME").ok());
    let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
    let fields = [
        ("command", format!("[{}]", args.join(", "))),
        ("started_utc", q(&utc(started))),
        ("ended_utc", q(&utc(std::time::SystemTime::now()))),
        ("host", q(host.as_deref().unwrap_or("unknown"))),
        ("cpu", q(cpu.as_deref().unwrap_or("unknown"))),
        ("cores", cores.to_string()),
        ("os", q(&format!("{} {}", std::env::consts::OS, std::env::consts::ARCH))),
        ("demsweep_version", q(env!("CARGO_PKG_VERSION"))),
        ("build", q(build_id())),
        ("commit", q(commit())),
    ];
    let body: Vec<String> = fields.iter().map(|(k, v)| format!("  {}: {v}", q(k))).collect();
    let path = dir.join("manifest.json");
    crate::table::write_atomic(&path, format!("{{\n{}\n}}\n", body.join(",\n")).as_bytes())?;
    Ok(path)
}

/// A time as `YYYY-MM-DDTHH:MM:SSZ`.
pub fn utc(t: std::time::SystemTime) -> String {
    let secs = t.duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let (days, rest) = ((secs / 86_400) as i64, secs % 86_400);
    // Days since 1970-01-01 to the civil date (Howard Hinnant's algorithm).
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}T{:02}:{:02}:{:02}Z", rest / 3600, rest % 3600 / 60, rest % 60)
}
