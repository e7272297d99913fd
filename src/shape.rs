//! Shaped bodies: a projectile with a nose (flat, hemispherical, or tangent ogive of a given
//! calibre-radius-head, CRH), built on any lattice and pointing any way.
//!
//! The lattice is generated in the projectile's own frame (x across, from −W/2 to W/2; y along
//! the axis, from the tail at 0 to the nose tip at L), its rows centred on the axis, keeping the
//! elements whose disks lie wholly inside the outline (so the outline's width and length are the
//! body's), then turned
//! so that its axis points along `axis` and moved so that its tail is at `tail_m`. Bonds are
//! found after the cut, between the elements that remain.
//!
//! Tangent ogive (the usual definition): the nose is bounded by two arcs of radius s = CRH × W,
//! centred on the nose's base line at ±(s − W/2) from the axis, tangent to the body; its length
//! is W/2 √(4 CRH − 1). CRH = 1/2 is the hemisphere.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::lattice::{self, Lattice, Rect};
use crate::material::Arrangement;

/// The nose of a projectile.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Nose {
    /// A flat front.
    Flat,
    /// A half disk of the projectile's width.
    Hemispherical,
    /// A tangent ogive of calibre-radius-head [`Projectile::crh`].
    Ogive,
}

/// A projectile's outline.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Projectile {
    /// The point of the axis at the tail, m.
    pub tail_m: [f64; 2],
    /// Direction of the axis from the tail to the nose (normalised when used).
    pub axis: [f64; 2],
    /// Width (calibre) W, m.
    pub width_m: f64,
    /// Length from the tail to the nose tip L, m.
    pub length_m: f64,
    /// Nose shape.
    pub nose: Nose,
    /// Calibre-radius-head of an ogive nose (≥ 0.5).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crh: Option<f64>,
}

impl Projectile {
    /// Check the outline; `field` names it in messages.
    pub fn validate(&self, field: &str) -> Result<()> {
        let finite = self.tail_m.iter().chain(&self.axis).all(|v| v.is_finite());
        if !finite || self.axis[0].hypot(self.axis[1]) == 0.0 {
            return Err(Error::input(format!("{field}.axis"), "needs a finite, non-zero direction and a finite tail point"));
        }
        for (name, v) in [("width_m", self.width_m), ("length_m", self.length_m)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::input(format!("{field}.{name}"), format!("must be a finite number > 0, got {v}")));
            }
        }
        match (self.nose, self.crh) {
            (Nose::Ogive, None) => return Err(Error::input(format!("{field}.crh"), "an ogive nose needs its calibre-radius-head")),
            (Nose::Ogive, Some(c)) if !(c.is_finite() && c >= 0.5) => {
                return Err(Error::input(format!("{field}.crh"), format!("must be ≥ 0.5 (0.5 is a hemisphere), got {c}")));
            }
            (Nose::Flat | Nose::Hemispherical, Some(_)) => {
                return Err(Error::input(format!("{field}.crh"), "only an ogive nose takes a calibre-radius-head"));
            }
            _ => {}
        }
        if self.nose_length_m() > self.length_m {
            return Err(Error::input(
                format!("{field}.length_m"),
                format!("{} m is shorter than the nose ({} m)", self.length_m, self.nose_length_m()),
            ));
        }
        Ok(())
    }

    /// Length of the nose along the axis, m.
    pub fn nose_length_m(&self) -> f64 {
        let w = self.width_m;
        match self.nose {
            Nose::Flat => 0.0,
            Nose::Hemispherical => 0.5 * w,
            Nose::Ogive => 0.5 * w * (4.0 * self.crh.unwrap_or(0.5) - 1.0).sqrt(),
        }
    }

    /// Area of the outline, m².
    pub fn area_m2(&self) -> f64 {
        let w = self.width_m;
        let body = w * (self.length_m - self.nose_length_m());
        body + match self.nose {
            Nose::Flat => 0.0,
            Nose::Hemispherical => std::f64::consts::PI * w * w / 8.0,
            Nose::Ogive => {
                // Two circular segments cut by the axis: 2 ∫ (√(s² − z²) − (s − W/2)) dz over
                // the nose length.
                let s = self.crh.unwrap_or(0.5) * w;
                let (l, off) = (self.nose_length_m(), s - 0.5 * w);
                let integral = 0.5 * (l * (s * s - l * l).sqrt() + s * s * (l / s).asin());
                2.0 * (integral - off * l)
            }
        }
    }

    /// True when a disk of radius `r` centred at (x, y) in the projectile's frame lies inside
    /// (x across, y along the axis from the tail; in 3D, x is the distance from the axis).
    pub(crate) fn holds(&self, x: f64, y: f64, r: f64) -> bool {
        let (w, l) = (self.width_m, self.length_m);
        if x.abs() > 0.5 * w - r + 1e-12 * w || y < r - 1e-12 * l || y > l - r + 1e-12 * l {
            return false;
        }
        let base = l - self.nose_length_m();
        if y <= base {
            return true;
        }
        match self.nose {
            Nose::Flat => true,
            Nose::Hemispherical => x.hypot(y - base) <= 0.5 * w - r + 1e-12 * w,
            Nose::Ogive => {
                let s = self.crh.unwrap_or(0.5) * w;
                let off = s - 0.5 * w;
                (x + off).hypot(y - base) <= s - r + 1e-12 * w && (x - off).hypot(y - base) <= s - r + 1e-12 * w
            }
        }
    }

    /// A point of the projectile's frame in the model's, m.
    pub fn to_world(&self, x: f64, y: f64) -> [f64; 2] {
        let n = self.axis[0].hypot(self.axis[1]);
        let (ax, ay) = (self.axis[0] / n, self.axis[1] / n);
        // Frame: y along the axis, x to its right.
        [self.tail_m[0] + y * ax + x * ay, self.tail_m[1] + y * ay - x * ax]
    }

    /// A point of the model's frame in the projectile's, m.
    pub fn to_local(&self, p: [f64; 2]) -> [f64; 2] {
        let n = self.axis[0].hypot(self.axis[1]);
        let (ax, ay) = (self.axis[0] / n, self.axis[1] / n);
        let (dx, dy) = (p[0] - self.tail_m[0], p[1] - self.tail_m[1]);
        [dx * ay - dy * ax, dx * ax + dy * ay]
    }

    /// The nose tip in the model's frame, m.
    pub fn tip_m(&self) -> [f64; 2] {
        self.to_world(0.0, self.length_m)
    }

    /// The projectile as a lattice of elements of radius `radius_m` (`seed` and
    /// `bond_gap_ratio` for an irregular packing).
    pub fn lattice(&self, arrangement: Arrangement, radius_m: f64, seed: u64, bond_gap_ratio: f64) -> Result<Lattice> {
        let r = radius_m;
        let local = Rect { x_min_m: -0.5 * self.width_m, x_max_m: 0.5 * self.width_m, y_min_m: 0.0, y_max_m: self.length_m };
        let full = match arrangement {
            Arrangement::SimpleCubic => lattice::simple_cubic(&local, r)?,
            Arrangement::ClosePacked => lattice::close_packed(&local, r)?,
            Arrangement::Irregular => lattice::irregular(&local, r, seed, bond_gap_ratio)?,
        };
        // Centre a regular lattice's rows on the axis (the generators start at the left edge),
        // so that the body is symmetric and a normal impact stays normal.
        let shift = match arrangement {
            Arrangement::Irregular => 0.0,
            _ => {
                let y0 = full.centres[0][1];
                let row = full.centres.iter().filter(|c| (c[1] - y0).abs() < 1e-9 * r);
                let (lo, hi) = row.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| (a.min(c[0]), b.max(c[0])));
                -0.5 * (lo + hi)
            }
        };
        let centres: Vec<[f64; 2]> = full
            .centres
            .iter()
            .map(|c| [c[0] + shift, c[1]])
            .filter(|c| self.holds(c[0], c[1], r))
            .map(|c| self.to_world(c[0], c[1]))
            .collect();
        if centres.is_empty() {
            return Err(Error::input("element_radius_m", format!("{r} m leaves no element inside the projectile")));
        }
        let gap = if arrangement == Arrangement::Irregular { bond_gap_ratio } else { lattice::TOUCH };
        let bonds = lattice::bonds_within(&centres, r, 2.0 * r * gap);
        Ok(Lattice { centres, radius_m: r, area_per_element_m2: full.area_per_element_m2, bonds })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn projectile(nose: Nose, crh: Option<f64>, axis: [f64; 2]) -> Projectile {
        Projectile { tail_m: [0.3, 0.5], axis, width_m: 0.0889, length_m: 0.2228, nose, crh }
    }

    #[test]
    fn every_disk_lies_inside_the_outline_and_the_lattice_fills_it() {
        let r = 0.0039484;
        for (nose, crh) in [(Nose::Flat, None), (Nose::Hemispherical, None), (Nose::Ogive, Some(3.0))] {
            let p = projectile(nose, crh, [0.0, -1.0]);
            p.validate("p").unwrap();
            let l = p.lattice(Arrangement::ClosePacked, r, 0, 0.0).unwrap();
            // Back in the projectile's frame, every disk is inside.
            for c in &l.centres {
                let [x, y] = p.to_local(*c);
                assert!(p.holds(x, y, r * (1.0 - 1e-9)), "{nose:?}: disk at {c:?} pokes out");
                let back = p.to_world(x, y);
                assert!((back[0] - c[0]).abs() < 1e-15 && (back[1] - c[1]).abs() < 1e-15);
            }
            // The elements fill the outline to within the lattice's boundary layer.
            let filled = l.centres.len() as f64 * l.area_per_element_m2 / p.area_m2();
            assert!((0.85..1.02).contains(&filled), "{nose:?}: {} elements fill {filled:.3} of the outline", l.centres.len());
            // Symmetric about the axis (x → −x in the frame, the axis pointing down).
            let mirror = |c: &[f64; 2]| [2.0 * p.tail_m[0] - c[0], c[1]];
            for c in &l.centres {
                let m = mirror(c);
                assert!(l.centres.iter().any(|q| (q[0] - m[0]).abs() < 1e-9 && (q[1] - m[1]).abs() < 1e-9), "{nose:?}: not symmetric at {c:?}");
            }
            // The nose reaches the tip: the lowest disk within one diameter of a blunt tip, and
            // inside the nose of a sharp one (whose point is narrower than a disk).
            let lowest = l.centres.iter().map(|c| c[1]).fold(f64::INFINITY, f64::min) - r;
            let reach = if nose == Nose::Ogive { p.nose_length_m() } else { 2.0 * r };
            assert!(lowest - p.tip_m()[1] < reach && lowest >= p.tip_m()[1] - 1e-12, "{nose:?}: lowest disk {lowest}, tip {:?}", p.tip_m());
        }
        // A sharper nose holds fewer elements.
        let count = |n, c| projectile(n, c, [0.0, -1.0]).lattice(Arrangement::ClosePacked, r, 0, 0.0).unwrap().centres.len();
        assert!(count(Nose::Flat, None) > count(Nose::Hemispherical, None) && count(Nose::Hemispherical, None) > count(Nose::Ogive, Some(3.0)));
    }

    #[test]
    fn turning_the_axis_turns_the_body_rigidly() {
        let r = 0.0039484;
        let down = projectile(Nose::Ogive, Some(2.0), [0.0, -1.0]).lattice(Arrangement::ClosePacked, r, 0, 0.0).unwrap();
        let oblique = projectile(Nose::Ogive, Some(2.0), [1.0, -1.0]).lattice(Arrangement::ClosePacked, r, 0, 0.0).unwrap();
        assert_eq!(down.centres.len(), oblique.centres.len());
        assert_eq!(down.bonds, oblique.bonds);
        let d = |l: &Lattice, (i, j): (u32, u32)| {
            let (p, q) = (l.centres[i as usize], l.centres[j as usize]);
            (q[0] - p[0]).hypot(q[1] - p[1])
        };
        for &b in &down.bonds {
            assert!((d(&down, b) - d(&oblique, b)).abs() < 1e-12);
        }
    }

    #[test]
    fn ogive_geometry_and_bad_outlines() {
        let p = projectile(Nose::Ogive, Some(0.5), [0.0, 1.0]);
        let h = projectile(Nose::Hemispherical, None, [0.0, 1.0]);
        assert!((p.nose_length_m() - h.nose_length_m()).abs() < 1e-15 && (p.area_m2() - h.area_m2()).abs() < 1e-12);
        // CRH 3: l = W/2 √11.
        let o = projectile(Nose::Ogive, Some(3.0), [0.0, 1.0]);
        assert!((o.nose_length_m() - 0.5 * 0.0889 * 11f64.sqrt()).abs() < 1e-15);
        let e = |p: Projectile| p.validate("body[1].shape").unwrap_err().to_string();
        assert!(e(Projectile { crh: None, ..o }).contains("body[1].shape.crh"));
        assert!(e(Projectile { crh: Some(0.3), ..o }).contains("≥ 0.5"));
        assert!(e(Projectile { length_m: 0.01, ..o }).contains("shorter than the nose"));
        assert!(e(Projectile { axis: [0.0, 0.0], ..o }).contains("axis"));
    }
}
