//! Voronoi cells by half-space cutting (seed eqs 26–27) and their shrinking (eq 29): the cells
//! tile their box, each corner is nearest its own seed, and a cell's mass properties agree with
//! the independent integration.

mod polyhedra_support;

use demsweep::polyhedra::hull::Hull;
use demsweep::polyhedra::mass::mass_properties;
use demsweep::polyhedra::voronoi::{cells, shrink};
use nalgebra::Vector3;
use polyhedra_support::{Draw, by_divergence};

/// Whether `x` is inside `cell` or on it (within `tol`, m).
fn holds(cell: &Hull, x: &Vector3<f64>, tol: f64) -> bool {
    cell.faces.iter().all(|f| {
        let n: Vector3<f64> = (0..f.len()).map(|k| cell.vertices[f[k]].cross(&cell.vertices[f[(k + 1) % f.len()]])).sum();
        n.normalize().dot(&(x - cell.vertices[f[0]])) <= tol
    })
}

#[test]
fn two_seeds_split_a_box_at_their_bisector() {
    let (lo, hi) = (Vector3::zeros(), Vector3::new(1.0, 2.0, 3.0));
    let seeds = [Vector3::new(0.2, 1.0, 1.5), Vector3::new(0.6, 1.0, 1.5)];
    let found = cells(&seeds, &lo, &hi, 1e-12);
    // The bisector x = 0.4: volumes 0.4 × 6 and 0.6 × 6.
    let volumes: Vec<f64> = found.iter().map(|c| { let c = c.as_ref().unwrap(); mass_properties(&c.vertices, &c.faces).volume }).collect();
    assert!((volumes[0] - 2.4).abs() < 1e-13 && (volumes[1] - 3.6).abs() < 1e-13, "{volumes:?}");
    assert_eq!(found[0].as_ref().unwrap().faces.len(), 6, "a box cut square is a box");
}

#[test]
fn random_cells_tile_their_box_and_keep_to_their_seeds() {
    let mut draw = Draw(26);
    let (lo, hi) = (Vector3::new(-0.3, 0.0, 0.1), Vector3::new(0.9, 0.9, 1.1));
    let seeds: Vec<Vector3<f64>> = (0..200).map(|_| Vector3::new(draw.between(lo.x, hi.x), draw.between(lo.y, hi.y), draw.between(lo.z, hi.z))).collect();
    let tol = 1e-12;
    let found = cells(&seeds, &lo, &hi, tol);
    let (mut total, mut nearest, mut integral): (f64, f64, f64) = (0.0, 0.0, 0.0);
    let mut faces = 0;
    for (i, cell) in found.iter().enumerate() {
        let cell = cell.as_ref().unwrap_or_else(|| panic!("seed {i} has no cell"));
        let props = mass_properties(&cell.vertices, &cell.faces);
        total += props.volume;
        faces += cell.faces.len();
        // Euler's formula: a closed convex surface.
        let edges: usize = cell.faces.iter().map(|f| f.len()).sum::<usize>() / 2;
        assert_eq!(cell.vertices.len() + cell.faces.len(), edges + 2, "cell {i}: V − E + F ≠ 2");
        assert!(holds(cell, &seeds[i], tol), "cell {i} does not hold its seed");
        // Eq 26: every corner is no nearer another seed than its own.
        for v in &cell.vertices {
            let own = (v - seeds[i]).norm();
            let other = seeds.iter().enumerate().filter(|&(j, _)| j != i).map(|(_, s)| (v - s).norm()).fold(f64::INFINITY, f64::min);
            nearest = nearest.max(own - other);
        }
        let (v, c, inertia) = by_divergence(&cell.vertices, &cell.faces);
        integral = integral.max((props.volume / v - 1.0).abs()).max((props.centroid - c).norm() / v.cbrt()).max((props.inertia - inertia).norm() / inertia.norm());
    }
    let box_volume = (hi - lo).iter().product::<f64>();
    println!(
        "200 cells, {:.1} faces each: Σ volumes / box − 1 = {:+.1e}; corners nearer another seed by at most {nearest:.1e} m; \
         mass properties against the divergence theorem {integral:.1e}",
        faces as f64 / 200.0,
        total / box_volume - 1.0
    );
    assert!((total / box_volume - 1.0).abs() < 1e-12, "the cells do not tile the box");
    assert!(nearest < 1e-12, "a corner is nearer another seed by {nearest:e} m");
    assert!(integral < 1e-12, "mass properties {integral:e}");
}

#[test]
fn shrinking_a_cell_scales_it_about_its_seed() {
    let mut draw = Draw(29);
    let (lo, hi) = (Vector3::zeros(), Vector3::new(1.0, 1.0, 1.0));
    let seeds: Vec<Vector3<f64>> = (0..30).map(|_| Vector3::new(draw.unit(), draw.unit(), draw.unit())).collect();
    let found = cells(&seeds, &lo, &hi, 1e-12);
    for (i, cell) in found.iter().enumerate() {
        let cell = cell.as_ref().unwrap();
        let q = draw.between(0.5, 0.95);
        let (before, after) = (mass_properties(&cell.vertices, &cell.faces), { let s = shrink(cell, &seeds[i], q); mass_properties(&s.vertices, &s.faces) });
        // Volume × q³, centroid pulled to the seed by q, inertia × q⁵.
        assert!((after.volume / (before.volume * q.powi(3)) - 1.0).abs() < 1e-12, "cell {i}: volume");
        assert!((after.centroid - (seeds[i] + (before.centroid - seeds[i]) * q)).norm() < 1e-12, "cell {i}: centroid");
        assert!((after.inertia - before.inertia * q.powi(5)).norm() < 1e-12 * before.inertia.norm(), "cell {i}: inertia");
    }
}
