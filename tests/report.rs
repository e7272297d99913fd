//! `report.html`: one self-contained page per output folder, the answer first, holding the
//! figures its tables hold. Read from a copy of the committed default sweep's folder
//! (`results/ballistic`): what is tested is the page written from it, not the tables.

use std::path::{Path, PathBuf};

use demsweep::table::Table;

fn copy_of_ballistic(tag: &str) -> PathBuf {
    let from = Path::new(env!("CARGO_MANIFEST_DIR")).join("results/ballistic");
    let to = std::env::temp_dir().join(format!("demsweep-report-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&to);
    std::fs::create_dir_all(&to).unwrap();
    for name in ["thresholds.csv", "runs.csv", "sweep.toml", "ballistic.png"] {
        std::fs::copy(from.join(name), to.join(name)).unwrap();
    }
    to
}

/// Standard base64 decoding, written here apart from the encoder it checks.
fn decode(text: &str) -> Vec<u8> {
    let value = |c: u8| match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        b'/' => 63,
        _ => panic!("not base64: {c}"),
    };
    let mut out = Vec::new();
    for quad in text.as_bytes().chunks(4) {
        let pad = quad.iter().filter(|&&c| c == b'=').count();
        let n = quad.iter().fold(0u32, |n, &c| (n << 6) | if c == b'=' { 0 } else { u32::from(value(c)) });
        out.extend_from_slice(&n.to_be_bytes()[1..4 - pad]);
    }
    out
}

#[test]
fn the_page_is_self_contained_and_its_images_are_the_folders() {
    let dir = copy_of_ballistic("self");
    let page = std::fs::read_to_string(demsweep::report::write(&dir).unwrap()).unwrap();
    for outside in ["http://", "https://", "<script", "<link", "@import", "url("] {
        assert!(!page.contains(outside), "the page reaches outside itself: {outside}");
    }
    let sources: Vec<&str> = page.split("src=\"").skip(1).map(|s| s.split('"').next().unwrap()).collect();
    assert!(!sources.is_empty());
    for s in &sources {
        assert!(s.starts_with("data:image/png;base64,"), "an image that is not inline: {}", &s[..s.len().min(60)]);
    }
    let plot = std::fs::read(dir.join("ballistic.png")).unwrap();
    assert!(sources.iter().any(|s| decode(&s["data:image/png;base64,".len()..]) == plot), "the plot inlined byte for byte");
    // The page's own screenshot beside it is a picture of the page, not of the results.
    let screenshot = Path::new(env!("CARGO_MANIFEST_DIR")).join("results/ballistic").join(demsweep::report::SCREENSHOT);
    std::fs::copy(&screenshot, dir.join(demsweep::report::SCREENSHOT)).unwrap();
    let page = std::fs::read_to_string(demsweep::report::write(&dir).unwrap()).unwrap();
    assert_eq!(page.matches("<img").count(), sources.len(), "the screenshot is not on the page it shows");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_answer_comes_first_and_every_figure_of_the_tables_is_on_the_page() {
    let dir = copy_of_ballistic("figures");
    let page = std::fs::read_to_string(demsweep::report::write(&dir).unwrap()).unwrap();
    let thresholds = Table::read_csv(&dir.join("thresholds.csv")).unwrap();
    let v50 = |which: &str| {
        let r = (0..thresholds.rows.len()).find(|&r| thresholds.get(r, "threshold") == Some(which) && thresholds.get(r, "method").unwrap().starts_with("v50")).unwrap();
        ["v_est_fps", "v_low_fps", "v_high_fps", "band_min_fps", "band_max_fps"].map(|c| thresholds.get(r, c).unwrap().to_string())
    };
    let first_table = page.find("<table").unwrap();
    let first_image = page.find("<img").unwrap();
    for which in ["scabbing", "perforation"] {
        let figures = v50(which);
        let answer = format!("<b>{which}: {} ft/s</b>", figures[0]);
        let at = page.find(&answer).unwrap_or_else(|| panic!("no answer line {answer}"));
        assert!(at < first_table && at < first_image, "the {which} answer is not at the top");
        let line = &page[at..at + page[at..].find("</p>").unwrap()];
        for f in &figures[1..] {
            assert!(line.contains(f.as_str()), "{which}: {f} missing from {line}");
        }
    }
    // Every estimate and every run.
    for r in 0..thresholds.rows.len() {
        let v = thresholds.get(r, "v_est_fps").unwrap();
        assert!(v.is_empty() || page.contains(&format!("<td>{v}</td>")), "{v} of row {r} missing");
    }
    let runs = Table::read_csv(&dir.join("runs.csv")).unwrap();
    for r in 0..runs.rows.len() {
        let id = demsweep::report::html::escape(runs.get(r, "run_id").unwrap());
        assert!(page.contains(&format!("<td>{id}</td>")), "run {id} missing");
    }
    // The scene file as text, and the provenance of the rows.
    let hash = runs.get(0, "scene_hash").unwrap();
    assert!(page.contains("[penetration]") && page.contains(&format!("<code>{hash}</code> ({} rows)", runs.rows.len())));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_folder_without_thresholds_or_not_a_folder() {
    let dir = copy_of_ballistic("sweep");
    std::fs::remove_file(dir.join("thresholds.csv")).unwrap();
    let page = std::fs::read_to_string(demsweep::report::write(&dir).unwrap()).unwrap();
    assert!(page.contains("demsweep: sweep") && !page.contains("class=\"answer\""));
    std::fs::remove_dir_all(&dir).unwrap();
    let e = demsweep::report::write(Path::new("/nonexistent/folder")).unwrap_err().to_string();
    assert!(e.contains("DIR") && e.contains("not a folder"), "{e}");
}

/// The first packing's slowest scabbed run is made again and drawn at its first scab; another
/// packing's slower run and a faster run are not; a table the run does not reproduce is refused.
#[test]
fn the_pictures_are_the_first_packings_first_outcomes_made_again() {
    use demsweep::scene::overrides::Override;
    use demsweep::scene_file::{SceneFile, load};
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("sweeps/penetration_ci.toml");
    let sets = |v: &str| vec![Override::parse("target.seed=1").unwrap(), Override::parse(&format!("projectile.v0_fps={v}")).unwrap()];
    let SceneFile::Penetration(s) = load(&scene, &sets("1000")).unwrap() else { panic!("a penetration scene") };
    let row = demsweep::penetration::run(&s, Default::default()).unwrap().row;
    let t = row.outcome.scab_time_s.expect("the CI scene scabs at 1000 ft/s (results/thresholds_ci.csv)");
    let table = |t: f64| Table {
        header: ["run_id", "v0_fps", "scabbed", "scab_time_s", "perforated", "perforation_time_s", "build"].map(String::from).to_vec(),
        rows: vec![
            ["target.seed=1;projectile.v0_fps=1000", "1000", "true", &format!("{t:.9e}"), "false", "", "b"].map(String::from).to_vec(),
            ["target.seed=1;projectile.v0_fps=1400", "1400", "true", "0.004", "false", "", "b"].map(String::from).to_vec(),
            ["target.seed=2;projectile.v0_fps=700", "700", "true", "0.004", "false", "", "b"].map(String::from).to_vec(),
        ],
    };
    let out = std::env::temp_dir().join(format!("demsweep-pictures-{}", std::process::id()));
    let drawn = demsweep::ballistic::pictures::draw(&scene, &table(t), &out).unwrap();
    let name = format!("first_scabbing_1000fps_seed1_{:.1}ms.png", t * 1e3);
    assert_eq!(drawn, vec![out.join("pictures").join(&name)]);
    assert!(std::fs::read(&drawn[0]).unwrap().starts_with(b"\x89PNG"));
    // A table of another physics: refused, and no picture left under its name.
    let e = demsweep::ballistic::pictures::draw(&scene, &table(t * 1.01), &out).unwrap_err().to_string();
    assert!(e.contains("made again") && e.contains("make the sweep again"), "{e}");
    assert!(std::fs::read_dir(out.join("pictures")).unwrap().next().is_none());
    std::fs::remove_dir_all(&out).unwrap();
}

/// `manifest.json` is JSON a reader parses, naming the command, the times, the machine and the
/// program that made the folder.
#[test]
fn the_manifest_names_what_made_the_folder() {
    let dir = std::env::temp_dir().join(format!("demsweep-manifest-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let started = std::time::SystemTime::now();
    let path = demsweep::provenance::write_manifest(&dir, started).unwrap();
    let m: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    assert_eq!(m["build"], demsweep::provenance::build_id());
    assert_eq!(m["commit"], demsweep::provenance::commit());
    assert_eq!(m["demsweep_version"], env!("CARGO_PKG_VERSION"));
    assert!(m["command"].as_array().is_some_and(|a| !a.is_empty()));
    assert!(m["cores"].as_u64().is_some_and(|n| n >= 1));
    let (s, e) = (m["started_utc"].as_str().unwrap(), m["ended_utc"].as_str().unwrap());
    assert!(s.len() == 20 && s.ends_with('Z') && s <= e, "{s} {e}");
    assert_eq!(s, demsweep::provenance::utc(started));
    // The report shows it.
    assert!(demsweep::report::page(&dir).unwrap().contains("manifest.json"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn utc_is_the_civil_date() {
    use std::time::{Duration, UNIX_EPOCH};
    assert_eq!(demsweep::provenance::utc(UNIX_EPOCH), "1970-01-01T00:00:00Z");
    // 2000-02-29 (a leap day of a century leap year) 12:34:56, and 2026-12-06.
    assert_eq!(demsweep::provenance::utc(UNIX_EPOCH + Duration::from_secs(951_827_696)), "2000-02-29T12:34:56Z");
    assert_eq!(demsweep::provenance::utc(UNIX_EPOCH + Duration::from_secs(1_796_515_200)), "2026-12-06T00:00:00Z");
}
