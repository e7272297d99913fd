//! The Lambert–Jonas relation V_r = a (V^p − V_bl^p)^(1/p) (Lambert & Jonas, BRL-R-1852, 1976)
//! fitted to the perforating runs by least squares, a second estimate of the ballistic limit
//! V_bl beside the bisection; and its Recht–Ipson form (Recht & Ipson, J. Appl. Mech. 30, 1963:
//! p = 2, a = m_p/(m_p + m_plug) for a plug).
//!
//! For given V_bl and p the best a is linear (a = Σ g V_r / Σ g², g = (V^p − V_bl^p)^(1/p)), so
//! the search is over (V_bl, p) only: V_bl inside [lower, upper] (the last velocity that did not
//! perforate and the first that did: the fit may not contradict the runs), p in [1, 10]; a grid,
//! then two finer grids around its best point. Deterministic, no starting guess.

/// A fitted relation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fit {
    /// Ballistic limit V_bl, ft/s.
    pub v_bl_fps: f64,
    /// a (dimensionless).
    pub a: f64,
    /// p (dimensionless).
    pub p: f64,
    /// RMS residual of V_r, ft/s.
    pub rms_fps: f64,
    /// Points fitted.
    pub points: usize,
}

/// V_r of the relation at `v`, ft/s (0 at or below V_bl).
pub fn residual_velocity(a: f64, p: f64, v_bl: f64, v: f64) -> f64 {
    if v <= v_bl { 0.0 } else { a * (v.powf(p) - v_bl.powf(p)).powf(1.0 / p) }
}

fn best_a(points: &[(f64, f64)], p: f64, v_bl: f64) -> (f64, f64) {
    let (mut gv, mut gg) = (0.0, 0.0);
    for &(v, vr) in points {
        let g = residual_velocity(1.0, p, v_bl, v);
        gv += g * vr;
        gg += g * g;
    }
    let a = if gg > 0.0 { gv / gg } else { 0.0 };
    let sse: f64 = points.iter().map(|&(v, vr)| (a * residual_velocity(1.0, p, v_bl, v) - vr).powi(2)).sum();
    (a, sse)
}

/// Least-squares fit to `points` (V, V_r), ft/s, with V_bl in [lower, upper]; `p` fixed if
/// given (Recht–Ipson: 2). `None` with fewer points than free parameters.
pub fn fit(points: &[(f64, f64)], lower_fps: f64, upper_fps: f64, p: Option<f64>) -> Option<Fit> {
    let free = if p.is_some() { 2 } else { 3 };
    if points.len() < free || upper_fps < lower_fps || upper_fps.is_nan() || lower_fps.is_nan() {
        return None;
    }
    let (mut p_lo, mut p_hi) = p.map_or((1.0, 10.0), |p| (p, p));
    let (mut v_lo, mut v_hi) = (lower_fps, upper_fps);
    let n = 60;
    let mut best = (f64::INFINITY, lower_fps, p_lo, 0.0);
    for _ in 0..3 {
        for i in 0..=n {
            let v_bl = v_lo + (v_hi - v_lo) * i as f64 / n as f64;
            for j in 0..=n {
                let pp = p_lo + (p_hi - p_lo) * j as f64 / n as f64;
                let (a, sse) = best_a(points, pp, v_bl);
                if sse < best.0 {
                    best = (sse, v_bl, pp, a);
                }
            }
        }
        let (dv, dp) = (2.0 * (v_hi - v_lo) / n as f64, 2.0 * (p_hi - p_lo) / n as f64);
        (v_lo, v_hi) = ((best.1 - dv).max(lower_fps), (best.1 + dv).min(upper_fps));
        (p_lo, p_hi) = ((best.2 - dp).max(1.0), (best.2 + dp).min(10.0));
        if p.is_some() {
            (p_lo, p_hi) = (best.2, best.2);
        }
    }
    let (sse, v_bl_fps, p, a) = best;
    Some(Fit { v_bl_fps, a, p, rms_fps: (sse / points.len() as f64).sqrt(), points: points.len() })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recovers_the_parameters_of_exact_data() {
        let (a, p, v_bl) = (0.8, 2.5, 640.0);
        let pts: Vec<(f64, f64)> = (0..8).map(|k| 650.0 + 100.0 * k as f64).map(|v| (v, residual_velocity(a, p, v_bl, v))).collect();
        let f = fit(&pts, 600.0, 650.0, None).unwrap();
        assert!((f.v_bl_fps - v_bl).abs() < 0.5, "{f:?}");
        assert!((f.p - p).abs() < 0.05 && (f.a - a).abs() < 0.01 && f.rms_fps < 0.5, "{f:?}");
        let ri = fit(&pts, 600.0, 650.0, Some(2.0)).unwrap();
        assert_eq!(ri.p, 2.0);
        assert!(ri.rms_fps > f.rms_fps, "a worse form fits worse");
    }

    #[test]
    fn the_limit_stays_inside_the_runs_and_too_few_points_give_none() {
        let pts = [(700.0, 100.0), (800.0, 300.0), (900.0, 450.0)];
        let f = fit(&pts, 650.0, 700.0, None).unwrap();
        assert!((650.0..=700.0).contains(&f.v_bl_fps));
        assert!(fit(&pts[..2], 650.0, 700.0, None).is_none());
        assert!(fit(&pts[..1], 650.0, 700.0, Some(2.0)).is_none());
    }
}
