//! Pictures of a run: PNG frames of the beam like the source's Figures 7.2, 7.4 and 7.6, and a
//! VTK series for ParaView (`frame_NNNNN.vtu` with a `series.pvd` index).
//!
//! What a frame shows, per target element: its **damage**, the fraction of the bonds it started
//! with that have broken (0 grey, through yellow, to 1 dark red); each **broken bond** as a short
//! black crack across the bond at the contact point; the supports darker; the projectile steel
//! blue. The view is fixed by the scene (so frames line up), with a 12 in scale bar.
//!
//! Every file is written whole (temporary file and rename), the index after each frame, so an
//! interrupted run leaves a readable series of the frames it reached. A 3D kernel scene writes
//! the VTK series alone ([`vtk::Series`]); a 3D penetration run's PNG frames show its section
//! through the impact point.

pub mod font;
mod frame;
pub mod vtk;

use std::path::{Path, PathBuf};

use crate::penetration::scene::PenetrationScene;
use crate::error::{Error, Result};
use crate::simulation::Bodies;
use crate::table::write_atomic;

pub use frame::{View, render_png};

/// What the frames share: the bonds each element started with.
#[derive(Debug, Clone)]
pub struct Damage {
    /// Initially bonded pairs (i < j).
    pub initial_bonds: Vec<(u32, u32)>,
    /// Per element, the bonds it started with.
    pub initial_count: Vec<u32>,
}

impl Damage {
    /// From the model at t = 0 (either kernel).
    pub fn new(m: &(impl Bodies + ?Sized)) -> Damage {
        let mut initial_bonds = Vec::new();
        m.each_bond(&mut |i, j| initial_bonds.push((i.min(j) as u32, i.max(j) as u32)));
        let mut initial_count = vec![0u32; m.element_count()];
        for &(i, j) in &initial_bonds {
            initial_count[i as usize] += 1;
            initial_count[j as usize] += 1;
        }
        Damage { initial_bonds, initial_count }
    }

    /// Per element, the fraction of its initial bonds that are broken; and the broken pairs.
    pub fn now(&self, m: &(impl Bodies + ?Sized)) -> (Vec<f64>, Vec<(u32, u32)>) {
        let mut intact = vec![0u32; m.element_count()];
        let mut alive = std::collections::HashSet::with_capacity(self.initial_bonds.len());
        m.each_bond(&mut |i, j| {
            intact[i] += 1;
            intact[j] += 1;
            alive.insert((i.min(j) as u32, i.max(j) as u32));
        });
        let damage = self
            .initial_count
            .iter()
            .zip(&intact)
            .map(|(&n0, &n)| if n0 == 0 { 0.0 } else { 1.0 - n as f64 / n0 as f64 })
            .collect();
        let broken = self.initial_bonds.iter().copied().filter(|p| !alive.contains(p)).collect();
        (damage, broken)
    }
}

/// A series of pictures of a penetration run being written into one folder: PNG frames beside
/// the VTK series.
pub struct Series {
    dir: PathBuf,
    view: View,
    vtk: vtk::Series,
    frames: Vec<(f64, String)>,
}

impl Series {
    /// A series for `scene` in `dir` (created; frames of an earlier series there are replaced).
    pub fn new(dir: &Path, scene: &PenetrationScene) -> Result<Series> {
        Ok(Series { dir: dir.to_path_buf(), view: View::of(scene)?, vtk: vtk::Series::new(dir)?, frames: Vec::new() })
    }

    /// Frames written so far: (time s, PNG file name).
    pub fn frames(&self) -> &[(f64, String)] {
        &self.frames
    }

    /// Draw the model (the first call must be at t = 0: it records the initial bonds).
    pub fn frame(&mut self, m: &(impl Bodies + ?Sized)) -> Result<()> {
        let Some(damage) = self.vtk.frame(m)? else {
            return Ok(());
        };
        let (d, broken) = damage.now(m);
        let png = format!("frame_{:05}.png", self.frames.len());
        let bytes = render_png(&self.view, m, &d, &broken, self.vtk.projectile()).map_err(|e| Error::io(self.dir.join(&png), e))?;
        write_atomic(&self.dir.join(&png), &bytes)?;
        self.frames.push((m.time_s(), png));
        Ok(())
    }

    /// The last frame (if the run's end was not drawn yet), and `final.png`, a copy of it.
    pub fn finish(&mut self, m: &(impl Bodies + ?Sized)) -> Result<PathBuf> {
        self.frame(m)?;
        let last = self.dir.join(&self.frames.last().expect("one frame at least").1);
        let bytes = std::fs::read(&last).map_err(|e| Error::io(&last, e))?;
        let out = self.dir.join("final.png");
        write_atomic(&out, &bytes)?;
        Ok(out)
    }
}

/// One picture of a penetration run: the first record at or after `at_s` (a sweep's first scab
/// or first perforation, drawn again for its report), as `frame` would draw it.
pub struct Moment {
    path: PathBuf,
    view: View,
    at_s: f64,
    damage: Option<Damage>,
    projectile: std::ops::Range<usize>,
    drawn_s: Option<f64>,
}

impl Moment {
    /// A picture of `scene` at `at_s` into `path` (PNG).
    pub fn new(path: &Path, scene: &PenetrationScene, at_s: f64) -> Result<Moment> {
        Ok(Moment { path: path.to_path_buf(), view: View::of(scene)?, at_s, damage: None, projectile: 0..0, drawn_s: None })
    }

    /// Look at the model (the first call must be at t = 0: it records the initial bonds); draws
    /// once, at the first look at or after the moment.
    pub fn frame(&mut self, m: &(impl Bodies + ?Sized)) -> Result<()> {
        if self.damage.is_none() {
            self.damage = Some(Damage::new(m));
            self.projectile = m.body("projectile").unwrap_or(0..0);
        }
        if self.drawn_s.is_some() || m.time_s() < self.at_s {
            return Ok(());
        }
        let (d, broken) = self.damage.as_ref().expect("set above").now(m);
        let bytes = render_png(&self.view, m, &d, &broken, self.projectile.clone()).map_err(|e| Error::io(&self.path, e))?;
        write_atomic(&self.path, &bytes)?;
        self.drawn_s = Some(m.time_s());
        Ok(())
    }

    /// When it was drawn, s (None: the run ended first).
    pub fn drawn_s(&self) -> Option<f64> {
        self.drawn_s
    }
}

/// An RGB buffer (8 bit, row-major) as PNG bytes.
pub fn png_bytes(rgb: &[u8], w: u32, h: u32) -> std::result::Result<Vec<u8>, String> {
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, w, h);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        let mut writer = enc.write_header().map_err(|e| e.to_string())?;
        writer.write_image_data(rgb).map_err(|e| e.to_string())?;
    }
    Ok(out)
}

/// Write an RGB buffer to `path` as a PNG, whole (atomically).
pub fn encode_png(path: &Path, rgb: &[u8], w: u32, h: u32) -> Result<()> {
    let bytes = png_bytes(rgb, w, h).map_err(|e| crate::error::Error::io(path, std::io::Error::other(e)))?;
    crate::table::write_atomic(path, &bytes)
}
