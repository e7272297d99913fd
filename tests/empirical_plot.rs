//! `--plot`: the PNG is written, decodes, has the documented size and shows curves.

use std::collections::HashSet;
use std::fs::File;

use demsweep::empirical::{Missile, Nose, Target, plot};

fn decode(path: &std::path::Path) -> (png::OutputInfo, Vec<u8>) {
    let decoder = png::Decoder::new(File::open(path).expect("PNG written"));
    let mut reader = decoder.read_info().expect("valid PNG header");
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).expect("valid PNG data");
    buf.truncate(info.buffer_size());
    (info, buf)
}

fn distinct_colours(info: &png::OutputInfo, pixels: &[u8]) -> usize {
    let channels = info.color_type.samples();
    pixels.chunks(channels).map(|p| p.to_vec()).collect::<HashSet<_>>().len()
}

#[test]
fn library_plot_has_the_size_and_many_colours() {
    let dir = std::env::temp_dir().join(format!("demsweep-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("curves.png");
    plot::draw(&path, &Missile::report(Nose::Spherical), &Target::report(), 500.0, 1500.0).unwrap();
    let (info, pixels) = decode(&path);
    assert_eq!((info.width, info.height), (plot::WIDTH_PX, plot::HEIGHT_PX));
    // White background, black target line and text, plus one colour per curve and their
    // anti-aliasing: a blank or single-curve image would have far fewer.
    let colours = distinct_colours(&info, &pixels);
    assert!(colours > 40, "only {colours} colours");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn cli_writes_the_plot_and_still_prints_the_table() {
    let dir = std::env::temp_dir().join(format!("demsweep-plot-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("fig.png");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_demsweep"))
        .args(["empirical", "--thresholds", "--format", "csv", "--plot"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8(out.stdout).unwrap().starts_with("formula,variant,v_scab_fps"));
    let (info, _) = decode(&path);
    assert_eq!((info.width, info.height), (plot::WIDTH_PX, plot::HEIGHT_PX));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn unwritable_plot_path_is_an_error() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_demsweep"))
        .args(["empirical", "--plot", "/nonexistent-dir/x.png"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("/nonexistent-dir/x.png"));
}
