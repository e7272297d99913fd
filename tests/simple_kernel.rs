//! The simple kernel of `demsweep bench --laws` (linear springs, central differences) is the
//! yardstick of the full law's cost; the comparison is one of equal work only if both step the
//! same physics. On the benchmark block with no optional law (no bond reaches a plateau, none
//! breaks) both must follow the same trajectory to rounding.

use demsweep::bench::{self, Laws, simple::Simple};

#[test]
fn the_simple_kernel_follows_the_full_kernel_on_the_benchmark_block() {
    let mut full = bench::workload_with(40, 30, Laws::default()).unwrap();
    let mut plain = Simple::from_model(&full);
    assert_eq!(plain.bonds(), full.intact_bonds());
    let start = full.state.pos.clone();
    let steps = 400;
    for _ in 0..steps {
        plain.step();
    }
    full.run_steps(steps).unwrap();
    assert_eq!(full.intact_bonds(), plain.bonds(), "no bond may break on the block");
    // Displacements are of order |v| t ~ 0.5 m/s × 400 Δt; their difference must be rounding.
    let (mut worst, mut scale) = (0.0f64, 0.0f64);
    for ((s, f), p) in start.iter().zip(&full.state.pos).zip(&plain.pos) {
        for d in 0..2 {
            let (a, b) = (f[d] - s[d], p[d] - s[d]);
            worst = worst.max((a - b).abs());
            scale = scale.max(a.abs());
        }
    }
    eprintln!("largest displacement {scale:.3e} m, largest difference {worst:.3e} m");
    assert!(scale > 1e-6, "the block must move ({scale:.3e} m)");
    assert!(worst <= 1e-9 * scale, "the kernels differ by {worst:.3e} m on displacements of {scale:.3e} m");
    // And they are not trivially the same code: the full kernel's velocities match too.
    let dv = (0..start.len()).map(|e| (full.state.vel[e][1] - plain.vel[e][1]).abs()).fold(0.0, f64::max);
    assert!(dv <= 1e-9, "velocities differ by {dv:.3e} m/s");
}
