//! The house's rules, read from the sources: no circle of imports between the top-level rooms
//! of `src/`; the layers above a kernel name only its contract (`simulation`); the motion stage
//! names only the execution room's front door; `unsafe` only in the lane module.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// Each source under `src/` (path relative to it, with '/') and its code without comments.
fn code() -> Vec<(String, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&root, &mut files);
    files.sort();
    files
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            let code: Vec<&str> = text.lines().map(|l| l.split("//").next().unwrap()).collect();
            (p.strip_prefix(&root).unwrap().to_string_lossy().replace('\\', "/"), code.join("\n"))
        })
        .collect()
}

/// The names `text` gives after `prefix` (`crate::` → the rooms it names).
fn after(text: &str, prefix: &str) -> BTreeSet<String> {
    text.match_indices(prefix).map(|(k, _)| text[k + prefix.len()..].chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect()).collect()
}

/// The rooms `text` names as `crate::<room>`.
fn named(text: &str) -> BTreeSet<String> {
    after(text, "crate::")
}

/// A circle in `edges`, if there is one, as the path around it.
fn circle(edges: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    // Depth-first search; a node met again on the current path closes a circle.
    fn visit(r: &str, edges: &BTreeMap<String, BTreeSet<String>>, path: &mut Vec<String>, done: &mut BTreeSet<String>) -> Option<Vec<String>> {
        if let Some(k) = path.iter().position(|p| p == r) {
            return Some(path[k..].iter().cloned().chain([r.to_string()]).collect());
        }
        if !done.insert(r.to_string()) {
            return None;
        }
        path.push(r.to_string());
        for n in edges.get(r).into_iter().flatten() {
            if let Some(c) = visit(n, edges, path, done) {
                return Some(c);
            }
        }
        path.pop();
        None
    }
    let mut done = BTreeSet::new();
    edges.keys().find_map(|r| visit(r, edges, &mut Vec::new(), &mut done))
}

fn room(path: &str) -> String {
    path.split('/').next().unwrap().trim_end_matches(".rs").to_string()
}

#[test]
fn no_circle_of_imports_between_rooms() {
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (path, text) in code() {
        let from = room(&path);
        if from == "lib" || from == "main" {
            continue;
        }
        let to: Vec<String> = named(&text).into_iter().filter(|r| *r != from && !r.is_empty()).collect();
        edges.entry(from).or_default().extend(to);
    }
    assert!(edges.len() > 20, "the rooms were read: {:?}", edges.keys());
    let found = circle(&edges);
    assert!(found.is_none(), "a circle between rooms: {}", found.unwrap().join(" → "));
}

#[test]
fn no_circle_of_imports_inside_either_kernel() {
    for kernel in ["kernel", "kernel3d"] {
        let files: Vec<(String, String)> = code().into_iter().filter(|(p, _)| p.starts_with(&format!("{kernel}/"))).collect();
        // The kernel's modules: the files and folders right under it.
        let modules: BTreeSet<String> = files.iter().map(|(p, _)| room(&p[kernel.len() + 1..])).filter(|m| m != "mod").collect();
        let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for (path, text) in &files {
            let from = room(&path[kernel.len() + 1..]);
            let to = after(text, "super::").into_iter().chain(after(text, &format!("crate::{kernel}::")));
            let to: Vec<String> = to.filter(|m| *m != from && modules.contains(m)).collect();
            edges.entry(from).or_default().extend(to);
        }
        assert!(edges.len() > 8, "{kernel}'s modules were read: {:?}", edges.keys());
        let found = circle(&edges);
        assert!(found.is_none(), "a circle inside {kernel}/: {}", found.unwrap().join(" → "));
    }
}

#[test]
fn the_layers_above_a_kernel_name_only_its_contract() {
    let above = ["sweep/", "ballistic/", "converge/", "calibrate.rs", "run.rs", "penetration/outcome.rs", "penetration/fragments.rs"];
    let mut checked = 0;
    for (path, text) in code().iter().filter(|(p, _)| above.iter().any(|a| p.starts_with(a))) {
        checked += 1;
        assert!(!named(text).contains("kernel"), "{path} names the kernel; it should read the model through crate::simulation");
    }
    assert!(checked >= 20, "only {checked} files read");
}

#[test]
fn the_motion_stage_names_only_the_front_door_of_exec() {
    let (_, integrate) = code().into_iter().find(|(p, _)| p == "kernel/integrate.rs").unwrap();
    assert!(integrate.contains("exec::"), "integrate takes its chunks' sums from exec");
    for inner in ["exec::pieces", "exec::spans", "exec::scatter", "exec::awake"] {
        assert!(!integrate.contains(inner), "kernel/integrate.rs names {inner}");
    }
}

#[test]
fn unsafe_code_lives_only_in_the_lane_module() {
    for (path, text) in code() {
        if !path.starts_with("kernel/lanes/") {
            assert!(!text.contains("unsafe"), "{path} has unsafe code");
        }
    }
}
