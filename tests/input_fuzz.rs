//! Inputs that cannot crash the tool: every scene file of `sweeps/`, mutated at random (a value
//! replaced by any TOML value or none, a key renamed, a line dropped or doubled, characters
//! inserted, the text cut short), and `--set` strings of any field and value, are read as the
//! command line reads them. Never a panic; a rejection is an input error that names a field (a
//! `--set`'s own when it caused it), and a syntax error says its line and column. The cheap CI
//! scenes that are accepted are also built, so a value that passes the checks but cannot be
//! built is found too.
//!
//! Cases per property: `DEMSWEEP_FUZZ_CASES` (default 2 000 for reading, 100 for building);
//! `scripts/fuzz.sh` runs many more, on new random cases, and prints the totals.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use demsweep::Error;
use demsweep::scene::overrides::Override;
use demsweep::scene_file::{SceneFile, load_text};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

fn sweeps() -> Vec<(PathBuf, String)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("sweeps");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).filter(|p| p.extension().is_some_and(|x| x == "toml")).collect();
    files.sort();
    assert!(files.len() >= 5, "the scene files of sweeps/");
    files.into_iter().map(|p| (p.clone(), std::fs::read_to_string(&p).unwrap())).collect()
}

fn cases(default: u32) -> u32 {
    std::env::var("DEMSWEEP_FUZZ_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

/// CI draws the same cases each run; `DEMSWEEP_FUZZ_RANDOM=1` (scripts/fuzz.sh) new ones.
fn runner(cases: u32) -> TestRunner {
    // No persistence file: a failure prints its minimal input, which becomes a named test.
    let config = Config { cases, failure_persistence: None, ..Config::default() };
    if std::env::var_os("DEMSWEEP_FUZZ_RANDOM").is_some() {
        TestRunner::new(config)
    } else {
        TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha))
    }
}

/// Any TOML value, and some that are not TOML.
fn value() -> impl Strategy<Value = String> {
    prop_oneof![
        8 => (-40i32..40).prop_map(|e| format!("1e{e}")),
        4 => (any::<bool>(), -300i32..300).prop_map(|(minus, e)| format!("{}3.7e{e}", if minus { "-" } else { "" })),
        1 => Just("nan".to_string()),
        1 => Just("inf".to_string()),
        1 => Just("-inf".to_string()),
        1 => Just("-0.0".to_string()),
        1 => Just("0".to_string()),
        1 => Just("1e308".to_string()),
        1 => Just("-1e308".to_string()),
        1 => Just("5e-324".to_string()),
        1 => Just("9223372036854775807".to_string()),
        1 => Just("-9223372036854775808".to_string()),
        1 => Just("18446744073709551616".to_string()),
        1 => Just("true".to_string()),
        1 => Just("[]".to_string()),
        1 => Just("[1.0, -2.0, 3]".to_string()),
        1 => Just("{ a = 1 }".to_string()),
        1 => Just("{}".to_string()),
        1 => Just("\"\"".to_string()),
        1 => Just("\"ogive\"".to_string()),
        1 => Just("1979-05-27T07:32:00Z".to_string()),
        1 => Just("0x1F".to_string()),
        1 => Just(String::new()),
        1 => Just("5e".to_string()),
        1 => Just("\"unterminated".to_string()),
        1 => any::<f64>().prop_map(|v| format!("{v:e}")),
        1 => (-1e6f64..1e6).prop_map(|v| format!("{v}")),
        1 => any::<i64>().prop_map(|v| v.to_string()),
        1 => (0u64..20).prop_map(|v| v.to_string()),
        1 => "\\PC{0,12}".prop_map(|s| format!("{s:?}")),
        1 => "\\PC{0,12}",
    ]
}

/// A mutation of a scene text.
#[derive(Debug, Clone)]
enum Mutation {
    /// The value of the n-th `key = value` line.
    Value(usize, String),
    /// The key of the n-th `key = value` line.
    Key(usize, String),
    /// Drop the n-th line.
    Drop(usize),
    /// Write the n-th line twice.
    Double(usize),
    /// Insert text at a fraction of the length.
    Insert(f64, String),
    /// Cut the text at a fraction of the length.
    Cut(f64),
    /// A new `key = value` line after the n-th line (a key of the file, maybe in another table).
    Add(usize, usize, String),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        4 => (any::<usize>(), value()).prop_map(|(n, v)| Mutation::Value(n, v)),
        1 => (any::<usize>(), "[a-z_]{1,12}").prop_map(|(n, k)| Mutation::Key(n, k)),
        1 => any::<usize>().prop_map(Mutation::Drop),
        1 => any::<usize>().prop_map(Mutation::Double),
        1 => (0.0f64..1.0, "\\PC{1,6}|[\\[\\]={}\"'#.,\n]{1,4}").prop_map(|(at, s)| Mutation::Insert(at, s)),
        1 => (0.0f64..1.0).prop_map(Mutation::Cut),
        1 => (any::<usize>(), any::<usize>(), value()).prop_map(|(n, k, v)| Mutation::Add(n, k, v)),
    ]
}

/// Lines of `text` that give a value (`key = value`, not a comment or a table header).
fn value_lines(lines: &[&str]) -> Vec<usize> {
    (0..lines.len()).filter(|&i| { let l = lines[i].trim(); !l.starts_with('#') && !l.starts_with('[') && l.contains('=') }).collect()
}

fn at_char(text: &str, fraction: f64) -> usize {
    let mut at = ((text.len() as f64) * fraction) as usize;
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    at
}

fn mutate(text: &str, m: &Mutation) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let values = value_lines(&lines);
    let keys: Vec<&str> = values.iter().map(|&i| lines[i].split('=').next().unwrap().trim()).collect();
    let join = |lines: Vec<String>| lines.join("\n") + "\n";
    let owned = || lines.iter().map(|l| l.to_string()).collect::<Vec<String>>();
    match m {
        Mutation::Value(n, v) if !values.is_empty() => {
            let i = values[n % values.len()];
            let mut out = owned();
            out[i] = format!("{} = {v}", keys[n % values.len()]);
            join(out)
        }
        Mutation::Key(n, k) if !values.is_empty() => {
            let i = values[n % values.len()];
            let mut out = owned();
            out[i] = format!("{k} = {}", lines[i].split_once('=').unwrap().1.trim());
            join(out)
        }
        Mutation::Drop(n) if !lines.is_empty() => {
            let mut out = owned();
            out.remove(n % lines.len());
            join(out)
        }
        Mutation::Double(n) if !lines.is_empty() => {
            let mut out = owned();
            let i = n % lines.len();
            out.insert(i, lines[i].to_string());
            join(out)
        }
        Mutation::Insert(at, s) => {
            let at = at_char(text, *at);
            format!("{}{s}{}", &text[..at], &text[at..])
        }
        Mutation::Cut(at) => text[..at_char(text, *at)].to_string(),
        Mutation::Add(n, k, v) if !lines.is_empty() && !keys.is_empty() => {
            let mut out = owned();
            out.insert(n % lines.len() + 1, format!("{} = {v}", keys[k % keys.len()]));
            join(out)
        }
        _ => text.to_string(),
    }
}

/// Read `text` as the command line does; a panic fails, a rejection must be a clear input
/// error. Returns the scene when it was accepted.
fn read(origin: &Path, text: &str, sets: &[Override]) -> Result<Option<SceneFile>, TestCaseError> {
    let read = catch_unwind(AssertUnwindSafe(|| load_text(text, origin, sets)));
    let result = read.map_err(|_| TestCaseError::fail(format!("panic reading\n{text}\nwith {sets:?}")))?;
    match result {
        Ok(scene) => Ok(Some(scene)),
        Err(e) => {
            check_error(&e, text, sets)?;
            Ok(None)
        }
    }
}

fn check_error(e: &Error, text: &str, sets: &[Override]) -> Result<(), TestCaseError> {
    let shown = e.to_string();
    let Error::Input { field, message, .. } = e else {
        return Err(TestCaseError::fail(format!("not an input error: {shown}")));
    };
    prop_assert!(!field.trim().is_empty() && !message.trim().is_empty(), "an error without a field or a message: {shown}");
    // A text that is not TOML: where.
    if toml::from_str::<toml::Table>(text).is_err() {
        prop_assert!(message.starts_with("line ") && message.contains(", column "), "a syntax error without its line and column: {shown}");
    }
    // A field given by --set is named as given, the setting quoted.
    if let Some(o) = sets.iter().find(|o| field.starts_with(&o.field) && !message.contains("--set")) {
        prop_assert!(false, "an error of --set {}={} that does not say so: {shown}", o.field, o.value);
    }
    Ok(())
}

static READ: AtomicU64 = AtomicU64::new(0);

#[test]
fn mutated_scene_files_never_panic_and_name_the_field() {
    let files = sweeps();
    let mut runner = runner(cases(2_000));
    let strategy = (0..files.len(), proptest::collection::vec(mutation(), 1..4));
    runner
        .run(&strategy, |(f, ms)| {
            let (path, text) = &files[f];
            let text = ms.iter().fold(text.clone(), |t, m| mutate(&t, m));
            READ.fetch_add(1, Ordering::Relaxed);
            read(path, &text, &[]).map(|_| ())
        })
        .unwrap();
    eprintln!("input_fuzz: {} mutated scene files read", READ.load(Ordering::Relaxed));
}

/// Every dotted field of a document, tables included (`a`, `a.b`, `body[0].c`).
fn fields(prefix: &str, t: &toml::Table, out: &mut Vec<String>) {
    for (k, v) in t {
        let path = if prefix.is_empty() { k.clone() } else { format!("{prefix}.{k}") };
        out.push(path.clone());
        match v {
            toml::Value::Table(t) => fields(&path, t, out),
            toml::Value::Array(a) => {
                for (i, v) in a.iter().enumerate() {
                    if let toml::Value::Table(t) = v {
                        fields(&format!("{path}[{i}]"), t, out);
                    }
                }
            }
            _ => {}
        }
    }
}

static SET: AtomicU64 = AtomicU64::new(0);

#[test]
fn any_set_string_never_panics_and_names_itself() {
    let files = sweeps();
    let known: Vec<Vec<String>> = files
        .iter()
        .map(|(_, text)| {
            let mut out = vec![];
            fields("", &toml::from_str(text).unwrap(), &mut out);
            out
        })
        .collect();
    let mut runner = runner(cases(2_000));
    let field = prop_oneof![
        3 => any::<usize>().prop_map(Ok),
        1 => "[a-z_\\[\\]0-9.]{0,24}|\\PC{0,10}".prop_map(Err),
    ];
    let strategy = (0..files.len(), proptest::collection::vec((field, value()), 1..3));
    runner
        .run(&strategy, |(f, sets)| {
            let (path, text) = &files[f];
            let mut parsed = vec![];
            for (field, v) in sets {
                let field = match field {
                    Ok(n) => known[f][n % known[f].len()].clone(),
                    Err(s) => s,
                };
                let arg = format!("{field}={v}");
                SET.fetch_add(1, Ordering::Relaxed);
                match catch_unwind(|| Override::parse(&arg)) {
                    Err(_) => return Err(TestCaseError::fail(format!("panic parsing --set {arg}"))),
                    Ok(Err(e)) => prop_assert!(e.to_string().contains("--set"), "a bad --set that does not say so: {e}"),
                    Ok(Ok(o)) => parsed.push(o),
                }
            }
            read(path, text, &parsed).map(|_| ())
        })
        .unwrap();
    eprintln!("input_fuzz: {} --set strings read", SET.load(Ordering::Relaxed));
}

static BUILT: AtomicU64 = AtomicU64::new(0);

/// The CI scenes with a value changed to a nearby or absurd one: accepted means buildable.
#[test]
fn accepted_ci_scenes_build_without_a_panic() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("sweeps");
    let files: Vec<(PathBuf, String)> = ["penetration_ci.toml", "penetration3d_ci.toml"]
        .iter()
        .map(|f| (dir.join(f), std::fs::read_to_string(dir.join(f)).unwrap()))
        .collect();
    // Fields a user sets on these scenes, with the scale of the change.
    let fields = [
        "target.length_in",
        "target.depth_in",
        "target.support_length_in",
        "target.seed",
        "projectile.v0_fps",
        "projectile.angle_deg",
        "projectile.weight_lb",
        "projectile.width_in",
        "projectile.length_in",
        "projectile.standoff_in",
        "projectile.impact_x_in",
        "projectile.crh",
        "projectile.nose",
        "concrete.poisson_ratio",
        "concrete.strength_factor",
        "penetration.level",
        "slab.element_radius_in",
        "slab.max_element_radius_in",
        "slab.fine_radius_in",
        "slab.radius_growth",
        "slab.edges",
        "slab.obliquity_deg",
        "slab.projectile_element_radius_in",
    ];
    let v = prop_oneof![
        (-3.0f64..3.0).prop_map(|e| format!("{}", 10f64.powf(e))),
        (-100.0f64..100.0).prop_map(|x| format!("{x}")),
        (0u64..6).prop_map(|n| n.to_string()),
        Just("\"ogive\"".to_string()),
        Just("\"simply_supported\"".to_string()),
        Just("nan".to_string()),
    ];
    let mut runner = runner(cases(100));
    runner
        .run(&(0..files.len(), 0..fields.len(), v), |(f, k, v)| {
            let (path, text) = &files[f];
            let set = Override::parse(&format!("{}={v}", fields[k])).unwrap();
            let Some(SceneFile::Penetration(scene)) = read(path, text, std::slice::from_ref(&set))? else { return Ok(()) };
            // Not too big to build in a test (a user may build it; it is just slow).
            if scene.element_estimates().iter().any(|(n, _)| *n > 20_000.0) {
                return Ok(());
            }
            BUILT.fetch_add(1, Ordering::Relaxed);
            let built = catch_unwind(AssertUnwindSafe(|| match scene.penetration.dim {
                3 => scene.build3().map(|_| ()),
                _ => scene.to_scene().and_then(|(s, _)| s.build()).map(|_| ()),
            }));
            match built {
                Err(_) => Err(TestCaseError::fail(format!("panic building {} with --set {}={v}", path.display(), fields[k]))),
                Ok(Err(e)) => check_error(&e, text, &[set]).or_else(|_| {
                    // The model may refuse a material or a step too; any clear error, no panic.
                    prop_assert!(!e.to_string().is_empty());
                    Ok(())
                }),
                Ok(Ok(())) => Ok(()),
            }
        })
        .unwrap();
    eprintln!("input_fuzz: {} accepted CI scenes built", BUILT.load(Ordering::Relaxed));
}

#[test]
fn a_syntax_error_gives_its_line_and_column() {
    let text = "[penetration]\nname = \"x\"\ndim = 3\n[target\nlength_in = 60\n";
    let e = load_text(text, Path::new("bad.toml"), &[]).unwrap_err().to_string();
    assert!(e.contains("line 4, column"), "{e}");
    // A value of the wrong type: where it is.
    let text = "[penetration]\nname = \"x\"\n\n[projectile]\nv0_fps = \"fast\"\n";
    let e = load_text(text, Path::new("bad.toml"), &[]).unwrap_err().to_string();
    assert!(e.contains("projectile.v0_fps") && e.contains("line 5, column 10"), "{e}");
    // Given by --set, the line of the program's own rewrite is not shown; the setting is.
    let set = Override::parse("projectile.v0_fps=\"fast\"").unwrap();
    let e = load_text("[penetration]\nname = \"x\"\n", Path::new("ok.toml"), &[set]).unwrap_err().to_string();
    assert!(!e.contains("line ") && e.contains("--set projectile.v0_fps"), "{e}");
}
