//! Mass properties of convex polyhedra: closed forms for a cube, a box and a regular
//! tetrahedron, and, for random convex cells, the library's tetrahedral decomposition against an
//! independent integration (divergence theorem over the faces, each face by an exact quadrature).

mod polyhedra_support;

use demsweep::polyhedra::Polyhedron;
use demsweep::polyhedra::hull::hull;
use demsweep::polyhedra::mass::mass_properties;
use nalgebra::{Matrix3, Vector3};
use polyhedra_support::{Draw, by_divergence};

const TOL: f64 = 1e-12;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// The inertia tensor (per unit density, m⁵) in the frame the vertices were given in.
fn input_frame_inertia(p: &Polyhedron) -> Matrix3<f64> {
    let r = p.rest_orientation.to_rotation_matrix().into_inner();
    r * Matrix3::from_diagonal(&p.principal) * r.transpose()
}

/// Checks a shape given by its corners (in a box frame, then moved by `shift` and turned) against
/// the closed-form volume and principal moments; returns the worst relative error.
fn against_closed_form(corners: &[Vector3<f64>], volume: f64, principal: [f64; 3], draw: &mut Draw) -> f64 {
    let turn = draw.orientation();
    let shift = Vector3::new(draw.between(-5.0, 5.0), draw.between(-5.0, 5.0), draw.between(-5.0, 5.0));
    let centroid = corners.iter().sum::<Vector3<f64>>() / corners.len() as f64;
    let moved: Vec<Vector3<f64>> = corners.iter().map(|c| shift + turn.transform_vector(c)).collect();
    let p = Polyhedron::from_points(&moved, 1e-12).unwrap();
    let mut worst = rel(p.volume, volume);
    for (got, want) in p.principal.iter().zip(principal) {
        worst = worst.max(rel(*got, want));
    }
    // The body frame sits at the centroid: the corners' mean for these symmetric shapes.
    worst = worst.max((p.rest_position - (shift + turn.transform_vector(&centroid))).norm() / volume.cbrt());
    // Every input corner is the body corner carried back by the rest pose.
    for (body, input) in p.vertices.iter().zip(p.vertices.iter().map(|v| p.rest_position + p.rest_orientation.transform_vector(v))) {
        assert!(moved.iter().any(|m| (m - input).norm() < 1e-12 * volume.cbrt()), "corner {body} not carried back");
    }
    worst
}

fn box_corners(a: f64, b: f64, c: f64) -> Vec<Vector3<f64>> {
    (0..8).map(|k| Vector3::new(if k & 1 == 0 { 0.0 } else { a }, if k & 2 == 0 { 0.0 } else { b }, if k & 4 == 0 { 0.0 } else { c })).collect()
}

#[test]
fn a_cube_has_its_closed_form_volume_and_inertia() {
    let a: f64 = 0.3;
    // Uniform cube: I = m a²/6 about any centroidal axis.
    let (v, i) = (a * a * a, a.powi(5) / 6.0);
    let worst = against_closed_form(&box_corners(a, a, a), v, [i, i, i], &mut Draw(1));
    println!("cube: worst relative error {worst:.2e}");
    assert!(worst < TOL, "cube: {worst:e}");
    let h = hull(&box_corners(a, a, a), 1e-12).unwrap();
    assert_eq!((h.vertices.len(), h.faces.len()), (8, 6), "a cube's hull is 8 corners and 6 squares");
    assert!(h.faces.iter().all(|f| f.len() == 4));
}

#[test]
fn a_box_has_its_closed_form_volume_and_inertia() {
    let (a, b, c) = (0.1, 0.25, 0.4);
    let v = a * b * c;
    // I_x = m (b² + c²)/12 and so on; ascending: about the longest side first.
    let worst = against_closed_form(&box_corners(a, b, c), v, [v * (a * a + b * b) / 12.0, v * (a * a + c * c) / 12.0, v * (b * b + c * c) / 12.0], &mut Draw(2));
    println!("box: worst relative error {worst:.2e}");
    assert!(worst < TOL, "box: {worst:e}");
}

#[test]
fn a_regular_tetrahedron_has_its_closed_form_volume_and_inertia() {
    let a: f64 = 0.7;
    // Corners of a regular tetrahedron of edge a: alternate corners of a cube of side a/√2.
    let s = a / 2f64.sqrt();
    let corners = [Vector3::new(0.0, 0.0, 0.0), Vector3::new(s, s, 0.0), Vector3::new(s, 0.0, s), Vector3::new(0.0, s, s)];
    // V = a³/(6√2); I = m a²/20 about any centroidal axis.
    let v = a.powi(3) / (6.0 * 2f64.sqrt());
    let i = v * a * a / 20.0;
    let worst = against_closed_form(&corners, v, [i, i, i], &mut Draw(3));
    println!("regular tetrahedron: worst relative error {worst:.2e}");
    assert!(worst < TOL, "tetrahedron: {worst:e}");
}

#[test]
fn random_cells_agree_with_an_independent_integration() {
    let mut draw = Draw(61);
    let mut worst: f64 = 0.0;
    for trial in 0..50 {
        let count = 5 + trial % 30;
        let r = draw.between(0.05, 0.3);
        let centre = Vector3::new(draw.between(-2.0, 2.0), draw.between(-2.0, 2.0), draw.between(-2.0, 2.0));
        let points: Vec<Vector3<f64>> = (0..count).map(|_| centre + draw.in_ball(r)).collect();
        let h = hull(&points, 1e-12 * r).unwrap();
        // Euler's formula for a closed convex surface.
        let edges: usize = h.faces.iter().map(|f| f.len()).sum::<usize>() / 2;
        assert_eq!(h.vertices.len() + h.faces.len(), edges + 2, "trial {trial}: V − E + F ≠ 2");
        // Every input point inside or on the hull.
        let p = Polyhedron::from_faces(&h.vertices, h.faces.clone());
        let (v, c, i) = by_divergence(&h.vertices, &h.faces);
        let tensor = input_frame_inertia(&p);
        let err = [rel(p.volume, v), (p.rest_position - c).norm() / r, (tensor - i).norm() / i.norm(), (mass_properties(&h.vertices, &h.faces).inertia - i).norm() / i.norm()];
        worst = err.iter().fold(worst, |w, e| w.max(*e));
        for q in &points {
            let body = p.rest_orientation.inverse_transform_vector(&(q - p.rest_position));
            assert!(p.faces.iter().zip(&p.normals).all(|(f, n)| n.dot(&(body - p.vertices[f[0]])) <= 1e-12 * r), "trial {trial}: a point outside its hull");
        }
    }
    println!("random cells: worst relative error of volume, centroid, inertia {worst:.2e}");
    assert!(worst < TOL, "random cells: {worst:e}");
}
