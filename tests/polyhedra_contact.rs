//! GJK/EPA contact features against a brute-force reference: for convex polyhedra the overlap
//! δ_M is the least, over the candidate separating axes (face normals of both, and cross
//! products of an edge of each), of the support of A ⊖ B along the axis; its argmin is n_M.

mod polyhedra_support;

use demsweep::polyhedra::{Placed, Polyhedron, contact};
use nalgebra::{UnitQuaternion, Vector3};
use polyhedra_support::Draw;

/// The support of A ⊖ B along unit `u`, m: how far B must move along u to clear A.
fn width(a: &Placed, b: &Placed, u: &Vector3<f64>) -> f64 {
    let top = a.shape.vertices.iter().map(|v| u.dot(&a.world(v))).fold(f64::NEG_INFINITY, f64::max);
    let bottom = b.shape.vertices.iter().map(|v| u.dot(&b.world(v))).fold(f64::INFINITY, f64::min);
    top - bottom
}

/// Every candidate axis (unit, both senses), world frame.
fn axes(a: &Placed, b: &Placed) -> Vec<Vector3<f64>> {
    let normals = |p: &Placed| p.shape.normals.iter().map(|n| p.orientation.transform_vector(n)).collect::<Vec<_>>();
    let edges = |p: &Placed| p.shape.edges.iter().map(|&(i, j)| p.orientation.transform_vector(&(p.shape.vertices[j] - p.shape.vertices[i]))).collect::<Vec<_>>();
    let mut out: Vec<Vector3<f64>> = normals(a).into_iter().chain(normals(b)).collect();
    for ea in edges(a) {
        for eb in edges(b) {
            let c = ea.cross(&eb);
            if c.norm() > 1e-9 * ea.norm() * eb.norm() {
                out.push(c.normalize());
            }
        }
    }
    out.iter().flat_map(|u| [*u, -u]).collect()
}

/// The separating-axis reference: every candidate axis with the support along it, least first;
/// the first is (depth, axis), depth negative when apart.
fn reference(a: &Placed, b: &Placed) -> Vec<(f64, Vector3<f64>)> {
    let mut all: Vec<(f64, Vector3<f64>)> = axes(a, b).into_iter().map(|u| (width(a, b, &u), u)).collect();
    all.sort_by(|x, y| x.0.total_cmp(&y.0));
    all
}

/// Whether world point `x` is inside `p` (within `tol`, m).
fn holds(p: &Placed, x: &Vector3<f64>, tol: f64) -> bool {
    let body = p.orientation.inverse_transform_vector(&(x - p.position));
    p.shape.faces.iter().zip(&p.shape.normals).all(|(f, n)| n.dot(&(body - p.shape.vertices[f[0]])) <= tol)
}

#[test]
fn random_pairs_agree_with_the_separating_axis_reference() {
    let mut draw = Draw(2021);
    let (mut overlapping, mut apart, mut unique) = (0, 0, 0);
    let (mut depth_err, mut normal_err, mut support_err, mut point_err): (f64, f64, f64, f64) = (0.0, 0.0, 0.0, 0.0);
    for trial in 0..3000 {
        let (ra, rb) = (draw.between(0.05, 0.3), draw.between(0.05, 0.3));
        let (sa, sb) = (draw.polyhedron(4 + trial % 17, ra), draw.polyhedron(4 + (trial / 17) % 17, rb));
        let a = Placed { shape: &sa, position: Vector3::new(draw.between(-1.0, 1.0), 0.0, 0.5), orientation: draw.orientation() };
        // B's centroid at a distance uniform up to the two bounding spheres' reach: overlaps and gaps.
        let reach = sa.radius() + sb.radius();
        let offset = draw.in_ball(1.0).normalize() * (reach * draw.unit());
        let b = Placed { shape: &sb, position: a.position + offset, orientation: draw.orientation() };
        let scale = reach;
        let all = reference(&a, &b);
        let (depth, axis) = all[0];
        let found = contact(&a, &b);
        if depth < -1e-9 * scale {
            apart += 1;
            assert!(found.is_none(), "trial {trial}: apart by {:e} m but reported in contact {found:?}", -depth);
            continue;
        }
        if depth < 1e-9 * scale {
            continue; // touching within rounding: either answer is right
        }
        overlapping += 1;
        let c = found.unwrap_or_else(|| panic!("trial {trial}: overlap {depth:e} m not found"));
        depth_err = depth_err.max((c.depth - depth).abs() / scale);
        // n_M attains the least support: it is a minimising axis even where several tie.
        support_err = support_err.max((width(&a, &b, &c.normal) - depth).abs() / scale);
        // c₁ − c₂ = δ_M n_M, c₁ in A and c₂ in B.
        point_err = point_err.max((c.on_a - c.on_b - c.normal * c.depth).norm() / scale);
        assert!(holds(&a, &c.on_a, 1e-9 * scale) && holds(&b, &c.on_b, 1e-9 * scale), "trial {trial}: contact points outside");
        // Where the minimising axis is unique (next axis not parallel to it at least 1e-6 deeper),
        // the normals must be the same.
        let next = all.iter().find(|(_, u)| u.dot(&axis) < 1.0 - 1e-9).map(|(d, _)| *d).unwrap();
        if next - depth > 1e-6 * scale {
            unique += 1;
            normal_err = normal_err.max((c.normal - axis).norm());
        }
    }
    println!(
        "3000 random pairs: {overlapping} overlapping ({unique} with a unique axis), {apart} apart, none apart reported in contact; \
         worst |δ_M − δ_SAT|/reach {depth_err:.1e}, |n_M − n_SAT| {normal_err:.1e}, support along n_M − δ {support_err:.1e}, \
         |c₁ − c₂ − δ n| {point_err:.1e}"
    );
    assert!(overlapping > 500 && apart > 500 && unique > 300, "the draws cover both cases");
    assert!(depth_err < 1e-10, "depth {depth_err:e}");
    assert!(support_err < 1e-10, "support {support_err:e}");
    assert!(normal_err < 1e-8, "normal {normal_err:e}");
    assert!(point_err < 1e-10, "points {point_err:e}");
}

#[test]
fn aligned_boxes_with_coplanar_faces_and_tied_axes_agree_with_the_reference() {
    // The degenerate cases random shapes miss: parallel faces, tied axes, the origin on a face
    // of GJK's simplex. Boxes turned by quarter turns only, offsets on a coarse grid.
    let mut draw = Draw(7);
    let quarter = |k: u64| UnitQuaternion::from_axis_angle(&[Vector3::x_axis(), Vector3::y_axis(), Vector3::z_axis()][(k % 3) as usize], std::f64::consts::FRAC_PI_2 * (k / 3) as f64);
    let (mut overlapping, mut apart, mut depth_err, mut support_err): (usize, usize, f64, f64) = (0, 0, 0.0, 0.0);
    for trial in 0..2000 {
        let size = |d: &mut Draw| Vector3::new((d.between(1.0, 5.0)).round() * 0.1, (d.between(1.0, 5.0)).round() * 0.1, (d.between(1.0, 5.0)).round() * 0.1);
        let (ea, eb) = (size(&mut draw), size(&mut draw));
        let corners = |e: Vector3<f64>| (0..8).map(|k| Vector3::new(if k & 1 == 0 { -e.x } else { e.x }, if k & 2 == 0 { -e.y } else { e.y }, if k & 4 == 0 { -e.z } else { e.z }) * 0.5).collect::<Vec<_>>();
        let (sa, sb) = (Polyhedron::from_points(&corners(ea), 1e-12).unwrap(), Polyhedron::from_points(&corners(eb), 1e-12).unwrap());
        let a = Placed { shape: &sa, position: Vector3::zeros(), orientation: quarter((draw.unit() * 12.0) as u64) * sa.rest_orientation };
        let grid = |d: &mut Draw| (d.between(-6.0, 6.0)).round() * 0.05;
        let b = Placed { shape: &sb, position: Vector3::new(grid(&mut draw), grid(&mut draw), grid(&mut draw)), orientation: quarter((draw.unit() * 12.0) as u64) * sb.rest_orientation };
        let scale = sa.radius() + sb.radius();
        let depth = reference(&a, &b)[0].0;
        let found = contact(&a, &b);
        if depth < -1e-9 * scale {
            apart += 1;
            assert!(found.is_none(), "trial {trial}: apart by {:e} m but reported in contact {found:?}", -depth);
        } else if depth > 1e-9 * scale {
            overlapping += 1;
            let c = found.unwrap_or_else(|| panic!("trial {trial}: overlap {depth:e} m not found"));
            depth_err = depth_err.max((c.depth - depth).abs() / scale);
            support_err = support_err.max((width(&a, &b, &c.normal) - depth).abs() / scale);
        } else if let Some(c) = found {
            // Touching: if reported at all, with no overlap to speak of.
            assert!(c.depth <= 1e-9 * scale, "trial {trial}: touching but {:e} m deep", c.depth);
        }
    }
    println!("2000 aligned box pairs: {overlapping} overlapping, {apart} apart; worst |δ_M − δ_SAT|/reach {depth_err:.1e}, support along n_M − δ {support_err:.1e}");
    assert!(overlapping > 300 && apart > 300, "the draws cover both cases");
    assert!(depth_err < 1e-10 && support_err < 1e-10, "depth {depth_err:e}, support {support_err:e}");
}

fn cube(a: f64) -> Polyhedron {
    let corners: Vec<Vector3<f64>> = (0..8).map(|k| Vector3::new(if k & 1 == 0 { -a } else { a }, if k & 2 == 0 { -a } else { a }, if k & 4 == 0 { -a } else { a }) * 0.5).collect();
    Polyhedron::from_points(&corners, 1e-12).unwrap()
}

/// The contact of a unit-orientation cube A at the origin with cube B placed by `(at, turn)`.
fn cubes(at: Vector3<f64>, turn: UnitQuaternion<f64>) -> Option<demsweep::polyhedra::Contact> {
    let c = cube(1.0);
    // A cube's principal axes are degenerate: place by the rest pose so B is the cube as given.
    let a = Placed { shape: &c, position: Vector3::zeros(), orientation: c.rest_orientation };
    let b = Placed { shape: &c, position: at, orientation: turn * c.rest_orientation };
    contact(&a, &b)
}

#[test]
fn unit_cubes_meet_face_to_face_edge_to_face_and_vertex_to_face_at_their_closed_forms() {
    // Face to face: B one side minus 1 cm along x.
    let f = cubes(Vector3::new(0.99, 0.1, -0.2), UnitQuaternion::identity()).unwrap();
    assert!((f.depth - 0.01).abs() < 1e-12 && (f.normal - Vector3::x()).norm() < 1e-12, "face: {f:?}");
    // Edge to face: B turned 45° about z reaches √2/2 from its centre along x.
    let edge = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_4);
    let e = cubes(Vector3::new(0.5 + 0.5f64.sqrt() - 0.02, 0.0, 0.1), edge).unwrap();
    assert!((e.depth - 0.02).abs() < 1e-12 && (e.normal - Vector3::x()).norm() < 1e-12, "edge: {e:?}");
    assert!((e.on_b.x - 0.48).abs() < 1e-12, "edge's contact point on B lies on its edge: {e:?}");
    // Vertex to face: B's body diagonal along x reaches √3/2.
    let vertex = UnitQuaternion::rotation_between(&Vector3::new(-1.0, -1.0, -1.0), &-Vector3::x()).unwrap();
    let v = cubes(Vector3::new(0.5 + 0.75f64.sqrt() - 0.03, 0.05, 0.0), vertex).unwrap();
    assert!((v.depth - 0.03).abs() < 1e-12 && (v.normal - Vector3::x()).norm() < 1e-12, "vertex: {v:?}");
    assert!((v.on_b - Vector3::new(0.47, 0.05, 0.0)).norm() < 1e-12, "the vertex is B's contact point: {v:?}");
    // The same vertex 1 mm short of the face: no contact.
    assert!(cubes(Vector3::new(0.5 + 0.75f64.sqrt() + 0.001, 0.05, 0.0), vertex).is_none());
}

#[test]
fn a_flat_contact_acts_at_the_centre_of_its_patch() {
    use demsweep::polyhedra::patch::contact_centre;
    let c = cube(1.0);
    let a = Placed { shape: &c, position: Vector3::zeros(), orientation: c.rest_orientation };
    // Face on face: B's face over y ∈ [−0.2, 0.8], z ∈ [−0.7, 0.3], A's over [−0.5, 0.5]²; the
    // patch's centre (0.15, −0.1), midway between the two faces at x = 0.5 and 0.49.
    let b = Placed { shape: &c, position: Vector3::new(0.99, 0.3, -0.2), orientation: c.rest_orientation };
    let at = contact_centre(&a, &b, &contact(&a, &b).unwrap());
    assert!((at - Vector3::new(0.495, 0.15, -0.1)).norm() < 1e-12, "face on face: {at}");
    // Edge on face: B's edge along z over [−0.4, 0.6], cut by A's face to [−0.4, 0.5].
    let edge = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_4);
    let b = Placed { shape: &c, position: Vector3::new(0.5 + 0.5f64.sqrt() - 0.02, 0.0, 0.1), orientation: edge * c.rest_orientation };
    let at = contact_centre(&a, &b, &contact(&a, &b).unwrap());
    assert!((at - Vector3::new(0.49, 0.0, 0.05)).norm() < 1e-12, "edge on face: {at}");
    // A corner on a face: the seed's c_M itself.
    let vertex = UnitQuaternion::rotation_between(&Vector3::new(-1.0, -1.0, -1.0), &-Vector3::x()).unwrap();
    let b = Placed { shape: &c, position: Vector3::new(0.5 + 0.75f64.sqrt() - 0.03, 0.05, 0.0), orientation: vertex * c.rest_orientation };
    let found = contact(&a, &b).unwrap();
    assert!((contact_centre(&a, &b, &found) - found.point()).norm() < 1e-15, "a corner's contact is c_M");
}
