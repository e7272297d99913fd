//! `report.html`: an output folder of `ballistic`, `sweep` or `converge` as one self-contained
//! page a user can forward — the question and the answer first, then the plot, the tables, the
//! pictures, the scene file as text and the provenance of every row. It reads only the folder's
//! files (and the scene file its `sweep.toml` names), so it is written last and can be written
//! again at any time (`demsweep report DIR`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::scene_file::SceneFile;
use crate::table::{Table, write_atomic};

pub mod html;

use html::escape;

/// The columns of `runs.csv` a reader looks at first.
const RUN_COLUMNS: [&str; 13] =
    ["run_id", "purpose", "v0_fps", "depth_in", "scabbed", "scab_mass_lb", "perforated", "v_residual_fps", "end_reason", "elements", "wall_s", "build", "status"];

/// The page's own screenshot (`scripts/report_screenshot.sh`): a picture of the page, not of the
/// results, so never on it (the page would show itself, one screenshot older).
pub const SCREENSHOT: &str = "report.png";

/// Rows of a table shown before "N more rows in the CSV".
const MAX_ROWS: usize = 300;

/// Write `dir/report.html` (atomically) from the folder's tables; returns its path.
pub fn write(dir: &Path) -> Result<PathBuf> {
    let page = page(dir)?;
    let path = dir.join("report.html");
    write_atomic(&path, page.as_bytes())?;
    Ok(path)
}

/// The page for the folder `dir`.
pub fn page(dir: &Path) -> Result<String> {
    if !dir.is_dir() {
        return Err(Error::input("DIR", format!("{} is not a folder of results", dir.display())));
    }
    let read = |name: &str| -> Result<Option<Table>> { let p = dir.join(name); if p.is_file() { Table::read_csv(&p).map(Some) } else { Ok(None) } };
    let thresholds = read("thresholds.csv")?;
    let runs = read("runs.csv")?;
    // A chart's folder names its scene in chart.toml.
    let sweep_toml = std::fs::read_to_string(dir.join("sweep.toml")).or_else(|_| std::fs::read_to_string(dir.join("chart.toml"))).ok();
    let scene_path = sweep_toml.as_deref().and_then(scene_named);
    let scene_text = scene_path.as_ref().and_then(|p| std::fs::read_to_string(p).ok());
    let summaries = files(dir, |n| n.ends_with("_summary.csv"));

    let mut body = String::new();
    let what = if thresholds.is_some() {
        "ballistic limits"
    } else if dir.join("chart.csv").is_file() {
        "design chart"
    } else if !summaries.is_empty() {
        "mesh study"
    } else {
        "sweep"
    };
    body += &format!("<h1>demsweep: {what} — {}</h1>\n", escape(&dir.display().to_string()));
    body += &question(scene_path.as_deref());
    if let Some(t) = &thresholds {
        body += &answer(t);
    }
    if let Some(r) = &runs {
        body += &failures(r);
    }
    for s in &summaries {
        body += &format!("<h2>Convergence: {}</h2>\n", escape(&name(s)));
        body += &html::table(&Table::read_csv(s)?, &[], MAX_ROWS);
    }
    for png in files(dir, |n| n.ends_with(".png") && n != SCREENSHOT) {
        body += &html::figure(&std::fs::read(&png).map_err(|e| Error::io(&png, e))?, &caption(&png));
    }
    if let Some(t) = &thresholds {
        let (ours, formulas): (Vec<usize>, Vec<usize>) = (0..t.rows.len()).partition(|&r| !t.get(r, "method").unwrap_or("").starts_with("empirical"));
        let pick = |rows: &[usize]| Table { header: t.header.clone(), rows: rows.iter().map(|&r| t.rows[r].clone()).collect() };
        body += "<h2>Our estimates</h2>\n";
        body += &html::table(&pick(&ours), &["threshold", "method", "v_low_fps", "v_high_fps", "v_est_fps", "fit_a", "fit_p", "fit_rms_fps", "points", "note"], MAX_ROWS);
        body += "<h2>The empirical formulas for the same target and projectile</h2>\n";
        body += &html::table(&pick(&formulas), &["threshold", "method", "v_est_fps", "inside_band", "note"], MAX_ROWS);
    }
    body += &pictures(dir)?;
    for other in files(dir, |n| n.ends_with(".csv") && !["runs.csv", "thresholds.csv"].contains(&n) && !n.ends_with("_summary.csv")) {
        body += &format!("<h2>{}</h2>\n", escape(&name(&other)));
        body += &html::table(&Table::read_csv(&other)?, &[], MAX_ROWS);
    }
    if let Some(r) = &runs {
        body += &format!("<h2>Runs ({}; every column in runs.csv)</h2>\n", r.rows.len());
        body += &html::table(r, &RUN_COLUMNS, MAX_ROWS);
    }
    body += "<h2>The scene</h2>\n";
    body += &match (&scene_path, &scene_text) {
        (Some(p), Some(text)) => format!("<p><code>{}</code>, as read when this page was written:</p>\n<pre>{}</pre>\n", escape(&p.display().to_string()), escape(text)),
        (Some(p), None) => format!("<p class=\"note\">The scene file <code>{}</code> is not where the sweep read it from; its hash is in every row.</p>\n", escape(&p.display().to_string())),
        _ => "<p class=\"note\">No <code>sweep.toml</code> names a scene file in this folder.</p>\n".to_string(),
    };
    if let Some(t) = &sweep_toml {
        body += &format!("<p>The sweep's arguments (<code>sweep.toml</code>):</p>\n<pre>{}</pre>\n", escape(t));
    }
    body += &provenance(dir, runs.as_ref());
    Ok(format!(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>demsweep: {what}</title><style>{}</style></head><body>\n{body}</body></html>\n",
        html::STYLE
    ))
}

/// The failed runs of a runs table (status `failed`), each with its message, right under the
/// answer: a threshold drawn without them must say so.
fn failures(runs: &Table) -> String {
    let failed: Vec<usize> = (0..runs.rows.len()).filter(|&r| runs.get(r, "status") == Some(crate::sweep::store::FAILED)).collect();
    if failed.is_empty() {
        return String::new();
    }
    let rows = Table { header: vec!["run_id".into(), "purpose".into(), "message".into()], rows: failed.iter().map(|&r| ["run_id", "purpose", "message"].iter().map(|c| runs.get(r, c).unwrap_or("").to_string()).collect()).collect() };
    format!(
        "<h2 class=\"failed\">Failed runs ({})</h2>\n<p class=\"note\">These runs ended in an error, not an outcome: the thresholds above were drawn without them, and a bisection that needed one stopped at the bracket it had. A rerun makes them again.</p>\n{}",
        failed.len(),
        html::table(&rows, &[], MAX_ROWS)
    )
}

/// The scene file a folder's `sweep.toml` (its text) names.
pub fn scene_named(sweep_toml: &str) -> Option<PathBuf> {
    sweep_toml.parse::<toml::Table>().ok()?.get("scene")?.as_str().map(PathBuf::from)
}

/// The tool's question, for the scene's projectile and target when the scene can be read.
fn question(scene: Option<&Path>) -> String {
    let mut out = String::from(
        "<p>At what impact velocity does this projectile start to scab the back face of this concrete target, and at what velocity does it go through?",
    );
    if let Some(Ok(SceneFile::Penetration(s))) = scene.map(|p| crate::scene_file::load(p, &[])) {
        let (p, t) = (&s.projectile, &s.target);
        let shape = if s.penetration.dim == 3 { format!("a {0} × {0} in slab", t.length_in) } else { format!("a {} in span (2D)", t.length_in) };
        out += &format!(
            " Here: a {} lb projectile, {} in in calibre, {:?} nose, at {}° from the normal, into {} of plain concrete {} in thick (f'c {} psi), mesh level {}.",
            p.weight_lb, p.width_in, p.nose, p.angle_deg, shape, t.depth_in, s.concrete.compressive_strength_psi, s.penetration.level
        );
    }
    out + "</p>\n"
}

/// The answer: each threshold's V50 with its interval (or bisection bracket) beside the
/// formulas' band.
fn answer(t: &Table) -> String {
    let mut out = String::from("<div class=\"answer\">\n");
    for threshold in ["scabbing", "perforation"] {
        let method = |r: &usize| t.get(*r, "method").unwrap_or("");
        let best = crate::ballistic::thresholds::best_row(t, threshold);
        let cell = |r: usize, c: &str| t.get(r, c).unwrap_or("").to_string();
        let line = match best {
            Some(r) if !cell(r, "v_est_fps").is_empty() => format!(
                "<b>{threshold}: {} ft/s</b> ({}: {}–{} ft/s); the formulas valid here give {}–{} ft/s ({}).",
                cell(r, "v_est_fps"),
                escape(method(&r)),
                cell(r, "v_low_fps"),
                cell(r, "v_high_fps"),
                cell(r, "band_min_fps"),
                cell(r, "band_max_fps"),
                if cell(r, "inside_band") == "true" { "inside" } else { "outside" }
            ),
            Some(r) => format!("<b>{threshold}: not found</b> in the range swept ({}).", escape(&cell(r, "note"))),
            None => format!("<b>{threshold}: not estimated</b> (no row in thresholds.csv)."),
        };
        out += &format!("<p>{line}</p>\n");
    }
    out + "<p class=\"note\">Intervals are over the packings (the random arrangements of elements); the band spans the empirical formulas within their stated validity (the rows below).</p>\n</div>\n"
}

/// Pictures in `dir/pictures/` (the sections at first scabbing and first perforation).
fn pictures(dir: &Path) -> Result<String> {
    let found = files(&dir.join("pictures"), |n| n.ends_with(".png"));
    if found.is_empty() {
        return Ok("<h2>Pictures</h2>\n<p class=\"note\">None in <code>pictures/</code>: <code>demsweep run SCENE --set projectile.v0_fps=V --snapshots DIR</code> draws a run's sections (and a VTK series for ParaView).</p>\n".to_string());
    }
    let mut out = String::from("<h2>Pictures</h2>\n");
    for p in found {
        out += &html::figure(&std::fs::read(&p).map_err(|e| Error::io(&p, e))?, &caption(&p));
    }
    Ok(out)
}

/// Which programs and scenes made the rows, and who wrote the page.
fn provenance(dir: &Path, runs: Option<&Table>) -> String {
    let mut out = String::from("<h2>Provenance</h2>\n<ul>\n");
    if let Some(r) = runs {
        for column in ["build", "scene_hash"] {
            let mut counts: BTreeMap<&str, usize> = BTreeMap::new();
            if let Some(k) = r.column(column) {
                for row in &r.rows {
                    *counts.entry(row[k].as_str()).or_default() += 1;
                }
            }
            let list: Vec<String> = counts.iter().map(|(v, n)| format!("<code>{}</code> ({n} rows)", escape(v))).collect();
            out += &format!("<li>{column}: {}</li>\n", if list.is_empty() { "not recorded".into() } else { list.join(", ") });
        }
    }
    out += &format!(
        "<li>page written by demsweep {} (build <code>{}</code>, commit <code>{}</code>) at {}</li>\n</ul>\n",
        env!("CARGO_PKG_VERSION"),
        crate::provenance::build_id(),
        crate::provenance::commit(),
        crate::provenance::utc(std::time::SystemTime::now())
    );
    if let Ok(m) = std::fs::read_to_string(dir.join("manifest.json")) {
        out += &format!("<p>What made the folder (<code>manifest.json</code>):</p>\n<pre>{}</pre>\n", escape(&m));
    }
    out
}

/// Files of `dir` whose names pass `keep`, sorted.
fn files(dir: &Path, keep: impl Fn(&str) -> bool) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|d| d.filter_map(|e| e.ok()).map(|e| e.path()).filter(|p| p.is_file() && p.file_name().and_then(|n| n.to_str()).is_some_and(&keep)).collect())
        .unwrap_or_default();
    out.sort();
    out
}

fn name(p: &Path) -> String {
    p.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default()
}

/// A picture's caption: its file name, read as words.
fn caption(p: &Path) -> String {
    name(p).trim_end_matches(".png").replace('_', " ")
}
