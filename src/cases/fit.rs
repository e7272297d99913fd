//! Small post-processing fits.

/// Least-squares fit u(t) ≈ a sin ωt + b cos ωt + c over the samples; returns the amplitude
/// √(a² + b²) and the rms residual, both in the samples' unit.
pub fn sinusoid_amplitude(t: &[f64], u: &[f64], omega_rad_per_s: f64) -> (f64, f64) {
    let mut m = nalgebra::Matrix3::<f64>::zeros();
    let mut r = nalgebra::Vector3::<f64>::zeros();
    for (&ti, &ui) in t.iter().zip(u) {
        let phi = nalgebra::Vector3::new((omega_rad_per_s * ti).sin(), (omega_rad_per_s * ti).cos(), 1.0);
        m += phi * phi.transpose();
        r += phi * ui;
    }
    let x = m.lu().solve(&r).unwrap_or_else(nalgebra::Vector3::zeros);
    let rms = (t
        .iter()
        .zip(u)
        .map(|(&ti, &ui)| (x[0] * (omega_rad_per_s * ti).sin() + x[1] * (omega_rad_per_s * ti).cos() + x[2] - ui).powi(2))
        .sum::<f64>()
        / t.len().max(1) as f64)
        .sqrt();
    (x[0].hypot(x[1]), rms)
}

#[cfg(test)]
mod tests {
    #[test]
    fn recovers_a_shifted_sinusoid() {
        let w = 2.3;
        let t: Vec<f64> = (0..400).map(|k| 0.01 * k as f64).collect();
        let u: Vec<f64> = t.iter().map(|&x| 0.7 * (w * x + 0.4).sin() + 0.1).collect();
        let (a, rms) = super::sinusoid_amplitude(&t, &u, w);
        assert!((a - 0.7).abs() < 1e-12 && rms < 1e-12);
    }
}
