//! A box of held walls around a region: a floor, four sides and a lid, each a slab of
//! held polyhedron whose inner face lies on the region's boundary. The rockfill is dropped
//! and compacted in it (the lid moving down).

use nalgebra::Vector3;

use super::body::Body;
use super::kernel::ModelBuilder;
use super::shape::Polyhedron;

/// Thickness of each wall slab, as a fraction of the region's largest side.
const THICKNESS: f64 = 0.25;

/// The walls of the region `lo`–`hi` (m) added to `builder` as held bodies of kind `kind`:
/// the floor and four sides still, the lid at height `lid_m` (m) moving at `lid_velocity`
/// (m/s, along z). The lid's index is the last.
pub fn walls(builder: &mut ModelBuilder, kind: usize, lo: &Vector3<f64>, hi: &Vector3<f64>, lid_m: f64, lid_velocity: f64) -> usize {
    let size = hi - lo;
    let t = THICKNESS * size.max();
    let centre = (lo + hi) * 0.5;
    // Sides overhang the region by a wall's thickness so the corners stay closed.
    let slabs = [
        (Vector3::new(size.x + 2.0 * t, size.y + 2.0 * t, t), Vector3::new(centre.x, centre.y, lo.z - 0.5 * t)),
        (Vector3::new(t, size.y + 2.0 * t, 2.0 * size.z + t), Vector3::new(lo.x - 0.5 * t, centre.y, lo.z + size.z)),
        (Vector3::new(t, size.y + 2.0 * t, 2.0 * size.z + t), Vector3::new(hi.x + 0.5 * t, centre.y, lo.z + size.z)),
        (Vector3::new(size.x, t, 2.0 * size.z + t), Vector3::new(centre.x, lo.y - 0.5 * t, lo.z + size.z)),
        (Vector3::new(size.x, t, 2.0 * size.z + t), Vector3::new(centre.x, hi.y + 0.5 * t, lo.z + size.z)),
    ];
    for (extent, at) in slabs {
        let shape = Polyhedron::cuboid(&extent);
        let body = Body::new(&shape, 1.0, at, shape.rest_orientation);
        let s = builder.shape(shape);
        builder.held(s, kind, body, Vector3::zeros());
    }
    let lid = Polyhedron::cuboid(&Vector3::new(size.x, size.y, t));
    let body = Body::new(&lid, 1.0, Vector3::new(centre.x, centre.y, lid_m + 0.5 * t), lid.rest_orientation);
    let s = builder.shape(lid);
    builder.held(s, kind, body, Vector3::new(0.0, 0.0, lid_velocity))
}

/// A body of `shape` (in its body frame) placed so its corners sit where they were given
/// (`Polyhedron::rest_position`, `rest_orientation`), at rest.
pub fn as_given(shape: &Polyhedron, density: f64) -> Body {
    Body::new(shape, density, shape.rest_position, shape.rest_orientation)
}
