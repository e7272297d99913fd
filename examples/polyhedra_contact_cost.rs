//! The cost of one GJK/EPA contact query between two rock-like convex cells (hulls of random
//! points in a ball), overlapping and apart, on one core.
//!
//! usage: cargo run --release --example polyhedra_contact_cost -- [CORNERS] [PAIRS]
//!   CORNERS  points drawn per cell before the hull (default 20)
//!   PAIRS    pairs drawn (default 2000); each queried 100 times
//!
//! Prints the mean time per query for the overlapping pairs (GJK then EPA) and the apart ones
//! (GJK only), and the cells' mean number of corners.

use std::time::Instant;

use demsweep::polyhedra::{Placed, Polyhedron, contact};
use nalgebra::{UnitQuaternion, Vector3};

/// A seeded 64-bit generator (an LCG step with a mixing output), uniform in [0, 1).
struct Draw(u64);

impl Draw {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        let x = (self.0 ^ (self.0 >> 33)).wrapping_mul(0xff51_afd7_ed55_8ccd);
        ((x ^ (x >> 33)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn point(&mut self, r: f64) -> Vector3<f64> {
        loop {
            let p = Vector3::new(self.unit() * 2.0 - 1.0, self.unit() * 2.0 - 1.0, self.unit() * 2.0 - 1.0);
            if p.norm_squared() <= 1.0 {
                return p * r;
            }
        }
    }
}

fn main() {
    let args: Vec<usize> = std::env::args().skip(1).map(|s| s.parse().expect("usage: polyhedra_contact_cost [CORNERS] [PAIRS]")).collect();
    let (corners, pairs) = (args.first().copied().unwrap_or(20), args.get(1).copied().unwrap_or(2000));
    let mut draw = Draw(61);
    let cell = |d: &mut Draw| Polyhedron::from_points(&(0..corners).map(|_| d.point(0.1)).collect::<Vec<_>>(), 1e-13).unwrap();
    let shapes: Vec<(Polyhedron, Polyhedron)> = (0..pairs).map(|_| (cell(&mut draw), cell(&mut draw))).collect();
    let mean_corners = shapes.iter().map(|(a, b)| a.vertices.len() + b.vertices.len()).sum::<usize>() as f64 / (2 * pairs) as f64;
    let (mut time, mut count) = ([0.0f64; 2], [0usize; 2]);
    for (sa, sb) in &shapes {
        let turn = |d: &mut Draw| UnitQuaternion::from_scaled_axis(d.point(3.0));
        let a = Placed { shape: sa, position: Vector3::zeros(), orientation: turn(&mut draw) };
        let b = Placed { shape: sb, position: draw.point(1.0).normalize() * ((sa.radius() + sb.radius()) * draw.unit()), orientation: turn(&mut draw) };
        let start = Instant::now();
        let mut found = None;
        for _ in 0..100 {
            found = std::hint::black_box(contact(std::hint::black_box(&a), std::hint::black_box(&b)));
        }
        let k = found.is_some() as usize;
        time[k] += start.elapsed().as_secs_f64() / 100.0;
        count[k] += 1;
    }
    println!("cells of {mean_corners:.1} corners on average (hulls of {corners} points)");
    println!("apart:       {:5} pairs, {:.2} µs per query (GJK)", count[0], 1e6 * time[0] / count[0] as f64);
    println!("overlapping: {:5} pairs, {:.2} µs per query (GJK + EPA)", count[1], 1e6 * time[1] / count[1] as f64);
}
