//! `slab.symmetry`: the 3D slab modelled as a half or a quarter with mirror planes through the
//! impact axis (`kernel3d::mirror`), cut from the whole's packing.

use demsweep::penetration::scene::PenetrationScene;
use demsweep::penetration::slab::{Slab, Symmetry};
use demsweep::simulation::{Bodies, Simulation};
use demsweep::units::M_PER_IN;

/// The 3D scene of the defaults at level 0, 40 in square and 20 in thick.
fn scene(symmetry: Symmetry, angle_deg: f64) -> PenetrationScene {
    let mut s = PenetrationScene::with_name("symmetry3d");
    s.penetration.dim = 3;
    s.penetration.level = 0;
    s.target.length_in = 40.0;
    s.target.depth_in = 20.0;
    s.projectile.angle_deg = angle_deg;
    s.slab = Some(Slab { symmetry, ..Slab::default() });
    s
}

fn mass_kg(m: &impl Bodies, body: &str) -> f64 {
    m.body(body).unwrap().map(|e| m.mass_kg(e)).sum()
}

#[test]
fn a_quarter_and_a_half_weigh_their_share_of_the_whole_and_sit_on_its_side_of_the_planes() {
    let (full, _) = scene(Symmetry::Full, 0.0).build3().unwrap();
    let whole = (mass_kg(&full.model, "target"), mass_kg(&full.model, "projectile"));
    for (symmetry, planes) in [(Symmetry::Half, 1usize), (Symmetry::Quarter, 2)] {
        let (part, layout) = scene(symmetry, 0.0).build3().unwrap();
        let m = &part.model;
        assert_eq!(m.mirrors.0.len(), planes);
        assert_eq!(layout.copies(), (1u32 << planes) as f64);
        // The whole's masses: the concrete's density over the slab, the projectile's 15 lb.
        for (body, w) in [("target", whole.0), ("projectile", whole.1)] {
            let got = layout.copies() * mass_kg(m, body);
            assert!((got / w - 1.0).abs() < 1e-12, "{symmetry:?} {body}: {got} kg × copies against the whole's {w} kg");
        }
        // Every centre on the high side of each plane, some spheres cut by one.
        let (mut cut, n) = (0, m.element_count());
        for e in 0..n {
            for p in &m.mirrors.0 {
                let d = m.initial_m(e)[p.axis] - p.at_m;
                assert!(d >= 0.0, "{symmetry:?}: sphere {e} lies {d} m on the low side");
                cut += usize::from(d < m.radius_m(e));
            }
        }
        assert!(cut > 10, "{symmetry:?}: {cut} spheres cut by a plane");
        // The projectile's lowest sphere clears the face by the standoff (the part's own).
        let lowest = m.body("projectile").unwrap().map(|e| m.position_m(e)[1] - m.radius_m(e)).fold(f64::INFINITY, f64::min);
        assert!((lowest - layout.front_y_m - 0.01 * M_PER_IN).abs() < 1e-9);
        // Fewer spheres: at most the share of the whole's, and not far below it.
        let share = n as f64 * layout.copies() / full.model.element_count() as f64;
        assert!((0.95..1.15).contains(&share), "{symmetry:?}: {n} spheres, {share} of the whole's share");
        assert!(part.model.tally().energy_in_j > 0.0);
        assert!((part.model.tally().energy_in_j / full.model.tally().energy_in_j - 1.0).abs() < 1e-9, "the whole's impact energy");
    }
}

#[test]
fn a_quarter_needs_a_normal_impact_and_a_half_takes_an_oblique_one() {
    let e = scene(Symmetry::Quarter, 30.0).build3().err().expect("a quarter at 30° refused").to_string();
    assert!(e.contains("slab.symmetry"), "{e}");
    let (half, layout) = scene(Symmetry::Half, 30.0).build3().unwrap();
    assert_eq!(half.model.mirrors.0.len(), 1);
    assert_eq!(half.model.mirrors.0[0].axis, 2, "the plane of obliquity, normal to z");
    assert!((half.model.mirrors.0[0].at_m - layout.impact_z_m).abs() < 1e-15);
}
