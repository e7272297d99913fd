//! The seed's projectile (Fig. 5: H = 800 mm, R = 500 mm, D = 150 mm, 12 × 36 divisions) as a
//! convex polyhedron, its mass properties against the closed forms of its own solid: along the
//! axis, a stack of frusta whose sections are regular polygons.

use demsweep::polyhedra::projectile::Ogive;

#[test]
fn the_seed_projectile_is_a_closed_convex_polyhedron() {
    let p = Ogive::seed().polyhedron();
    // A tip, 13 rings of 36; 36 tip triangles, 12 × 36 quads and the base.
    assert_eq!((p.vertices.len(), p.faces.len(), p.edges.len()), (469, 469, 936));
    for (f, n) in p.faces.iter().zip(&p.normals) {
        assert!(p.vertices.iter().all(|v| n.dot(&(v - p.vertices[f[0]])) <= 1e-12), "not convex at a face");
    }
    assert!((Ogive::seed().nose_length() - (0.25f64 - 0.425 * 0.425).sqrt()).abs() < 1e-15);
}

#[test]
fn its_mass_properties_match_the_stacked_frusta() {
    for shape in [Ogive::seed(), Ogive { length: 0.5, ogive_radius: 0.2, calibre: 0.1, head_divisions: 5, around: 7 }] {
        let p = shape.polyhedron();
        let n = shape.around as f64;
        let (s, c) = ((std::f64::consts::TAU / n).sin(), (std::f64::consts::TAU / n).cos());
        // A regular n-gon of circumradius r: area (n/2) sin(2π/n) r², polar moment
        // (n/12) sin(2π/n) (2 + cos(2π/n)) r⁴; r linear along each frustum.
        let (mut volume, mut first, mut polar) = (0.0, 0.0, 0.0);
        for w in shape.profile().windows(2) {
            let ((x1, r1), (x2, r2)) = (w[0], w[1]);
            let (h, d) = (x2 - x1, r2 - r1);
            volume += 0.5 * n * s * h * (r1 * r1 + r1 * d + d * d / 3.0);
            first += 0.5 * n * s * h * (x1 * (r1 * r1 + r1 * d + d * d / 3.0) + h * (r1 * r1 / 2.0 + 2.0 * r1 * d / 3.0 + d * d / 4.0));
            polar += n / 12.0 * s * (2.0 + c) * h * (r1.powi(4) + r1.powi(3) * r2 + r1 * r1 * r2 * r2 + r1 * r2.powi(3) + r2.powi(4)) / 5.0;
        }
        let errors = [p.volume / volume - 1.0, p.rest_position.x / (first / volume) - 1.0, p.principal[0] / polar - 1.0];
        println!("{}-by-{} projectile: volume {:.6e} m³, centroid {:.6} m from the tip, axial moment {:.6e} m⁵; errors {:.1e} {:.1e} {:.1e}", shape.head_divisions, shape.around, p.volume, p.rest_position.x, p.principal[0], errors[0], errors[1], errors[2]);
        assert!(errors.iter().all(|e| e.abs() < 1e-12), "{errors:?}");
        // The axis is the first principal axis.
        assert!((p.rest_orientation.transform_vector(&nalgebra::Vector3::x()).x.abs() - 1.0).abs() < 1e-12);
    }
}

#[test]
fn each_bad_field_of_a_projectile_is_refused_by_name() {
    let good = Ogive::seed();
    assert!(good.check("projectile").is_ok());
    let cases: [(&str, Ogive); 5] = [
        ("calibre", Ogive { calibre: 0.0, ..good }),
        ("ogive_radius", Ogive { ogive_radius: 0.05, ..good }),
        ("length", Ogive { length: 0.2, ..good }),
        ("head_divisions", Ogive { head_divisions: 0, ..good }),
        ("around", Ogive { around: 2, ..good }),
    ];
    for (field, bad) in cases {
        let message = format!("{:?}", bad.check("projectile").unwrap_err());
        assert!(message.contains(&format!("projectile.{field}")), "{field}: {message}");
    }
}
