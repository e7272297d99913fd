//! The VTK side of a picture series: one XML unstructured grid per frame (a vertex per element
//! with its radius, damage, body and velocity; in ParaView draw it with "Point Gaussian",
//! scaled by `radius_m`), and the `.pvd` collection that orders the frames in time. A frame
//! reads the model through `simulation::Bodies`, so the 2D discs and the 3D spheres are written
//! alike.

use std::ops::Range;

use vtkio::model::{Attribute, Attributes, ByteOrder, CellType, Cells, DataSet, UnstructuredGridPiece, Version, VertexNumbers, Vtk};

use std::path::{Path, PathBuf};

use super::Damage;
use crate::error::{Error, Result};
use crate::simulation::Bodies;
use crate::table::write_atomic;

/// A VTK series being written into one folder: `frame_NNNNN.vtu` and the `series.pvd` index,
/// rewritten after each frame.
pub struct Series {
    dir: PathBuf,
    damage: Option<Damage>,
    projectile: Range<usize>,
    frames: Vec<(f64, String)>,
}

impl Series {
    /// A series in `dir` (created).
    pub fn new(dir: &Path) -> Result<Series> {
        std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
        Ok(Series { dir: dir.to_path_buf(), damage: None, projectile: 0..0, frames: Vec::new() })
    }

    /// Frames written so far: (time s, `.vtu` file name).
    pub fn frames(&self) -> &[(f64, String)] {
        &self.frames
    }

    /// The elements of the body named `projectile` (none before the first frame).
    pub fn projectile(&self) -> Range<usize> {
        self.projectile.clone()
    }

    /// Write the model as the next frame unless its time was the last frame's (the first call
    /// must be at t = 0: it records the initial bonds); the bonds damage is counted from.
    pub fn frame(&mut self, m: &(impl Bodies + ?Sized)) -> Result<Option<&Damage>> {
        if self.frames.last().is_some_and(|f| f.0 == m.time_s()) {
            return Ok(None);
        }
        if self.damage.is_none() {
            self.damage = Some(Damage::new(m));
            self.projectile = m.body("projectile").unwrap_or(0..0);
        }
        let damage = self.damage.as_ref().expect("set above");
        let vtu = format!("frame_{:05}.vtu", self.frames.len());
        write_atomic(&self.dir.join(&vtu), &unstructured(m, &damage.now(m).0, self.projectile.clone())?)?;
        self.frames.push((m.time_s(), vtu));
        write_atomic(&self.dir.join("series.pvd"), collection(&self.frames).as_bytes())?;
        Ok(Some(damage))
    }
}

/// The frame as `.vtu` bytes: `damage` per element, `projectile` the elements flagged as it.
pub fn unstructured(m: &(impl Bodies + ?Sized), damage: &[f64], projectile: Range<usize>) -> Result<Vec<u8>> {
    let n = m.element_count();
    let points: Vec<f64> = (0..n).flat_map(|e| m.position_m(e)).collect();
    let velocity: Vec<f64> = (0..n).flat_map(|e| m.velocity_mps(e)).collect();
    let radius: Vec<f64> = (0..n).map(|e| m.radius_m(e)).collect();
    let body: Vec<i32> = (0..n).map(|e| i32::from(projectile.contains(&e))).collect();
    let supported: Vec<i32> = (0..n).map(|e| i32::from(m.held(e))).collect();
    let piece = UnstructuredGridPiece {
        points: points.into(),
        cells: Cells {
            cell_verts: VertexNumbers::XML { connectivity: (0..n as u64).collect(), offsets: (1..=n as u64).collect() },
            types: vec![CellType::Vertex; n],
        },
        data: Attributes {
            point: vec![
                Attribute::scalars("radius_m", 1).with_data(radius),
                Attribute::scalars("damage", 1).with_data(damage.to_vec()),
                Attribute::scalars("projectile", 1).with_data(body),
                Attribute::scalars("supported", 1).with_data(supported),
                Attribute::vectors("velocity_mps").with_data(velocity),
            ],
            cell: vec![],
        },
    };
    let vtk = Vtk {
        version: Version::new_xml(1, 0),
        title: format!("demsweep t = {:.6e} s", m.time_s()),
        byte_order: ByteOrder::LittleEndian,
        data: DataSet::inline(piece),
        file_path: None,
    };
    let mut out = Vec::new();
    vtk.write_xml(&mut out).map_err(|e| Error::input("vtk", format!("could not encode the frame: {e}")))?;
    Ok(out)
}

/// The `.pvd` index of `frames` (time s, `.vtu` name).
pub fn collection(frames: &[(f64, String)]) -> String {
    let mut s = String::from("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n");
    for (t, vtu) in frames {
        s.push_str(&format!("    <DataSet timestep=\"{t:.9e}\" group=\"\" part=\"0\" file=\"{vtu}\"/>\n"));
    }
    s.push_str("  </Collection>\n</VTKFile>\n");
    s
}
