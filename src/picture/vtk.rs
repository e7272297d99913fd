//! The VTK side of a picture series: one XML unstructured grid per frame (a vertex per element
//! with its radius, damage, body and velocity; in ParaView draw it with "Point Gaussian",
//! scaled by `radius_m`), and the `.pvd` collection that orders the frames in time. A frame
//! reads the model through `simulation::Bodies`, so the 2D discs and the 3D spheres are written
//! alike.

use std::ops::Range;

use vtkio::model::{Attribute, Attributes, ByteOrder, CellType, Cells, DataSet, UnstructuredGridPiece, Version, VertexNumbers, Vtk};

use crate::error::{Error, Result};
use crate::simulation::Bodies;

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

/// The `.pvd` index of `frames` (time s, PNG name; the `.vtu` has the same stem).
pub fn collection(frames: &[(f64, String)]) -> String {
    let mut s = String::from("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n");
    for (t, png) in frames {
        let vtu = png.replace(".png", ".vtu");
        s.push_str(&format!("    <DataSet timestep=\"{t:.9e}\" group=\"\" part=\"0\" file=\"{vtu}\"/>\n"));
    }
    s.push_str("  </Collection>\n</VTKFile>\n");
    s
}
