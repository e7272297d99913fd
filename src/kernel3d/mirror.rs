//! Symmetry planes: a model that is one half (one plane) or one quarter (two planes) of a
//! mirror-symmetric whole. A sphere near a plane meets the mirror images of its neighbours —
//! and its own — as it would meet the spheres there in the whole: an image contact
//! (`Contact::image`, a bit per plane) reads the far sphere reflected and hands it the
//! reflected reaction, so the model moves as its part of the whole, to rounding.
//!
//! A contact between a sphere and its own image stands for a pair of the whole whose other
//! half belongs to the mirrored part: it acts on its sphere once and books half its energy.
//! A contact between sphere i and the image of j ≠ i stands for two contacts of the whole
//! (i with j's image and j with i's), mirror images of each other: it acts on both.

use serde::{Deserialize, Serialize};

use super::vec3::V3;

/// One symmetry plane: `axis` (0 = x, 2 = z; 1 = y would cut the impact) held at `at_m`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Mirror {
    /// The plane's normal axis (0, 1 or 2).
    pub axis: usize,
    /// Where the plane lies along it, m.
    pub at_m: f64,
}

/// The symmetry planes of a model (none: the whole).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Mirrors(pub Vec<Mirror>);

impl Mirrors {
    /// True when the model is the whole.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// How many copies of the model the whole holds: 2 per plane.
    pub fn copies(&self) -> f64 {
        f64::from(1u32 << self.0.len())
    }

    /// The images: each non-empty set of planes, as a bit per plane.
    pub fn images(&self) -> impl Iterator<Item = u8> {
        1..(1u8 << self.0.len())
    }

    /// Point `p` (m) reflected through the planes of `image`.
    #[inline(always)]
    pub fn point(&self, p: V3, image: u8) -> V3 {
        let mut q = p;
        for (b, m) in self.0.iter().enumerate() {
            if image >> b & 1 == 1 {
                q[m.axis] = 2.0 * m.at_m - q[m.axis];
            }
        }
        q
    }

    /// A vector (velocity, force) reflected through the planes of `image`.
    #[inline(always)]
    pub fn vector(&self, v: V3, image: u8) -> V3 {
        let mut q = v;
        for (b, m) in self.0.iter().enumerate() {
            if image >> b & 1 == 1 {
                q[m.axis] = -q[m.axis];
            }
        }
        q
    }

    /// An axial vector (spin, moment) reflected through the planes of `image`: a reflection
    /// turns it as a vector and flips it (ω' = det(R) R ω).
    #[inline(always)]
    pub fn axial(&self, w: V3, image: u8) -> V3 {
        let q = self.vector(w, image);
        if image.count_ones() % 2 == 1 { [-q[0], -q[1], -q[2]] } else { q }
    }

    /// The share of a sphere of radius `r` (m) whose centre lies `d` (m) on the high side of a
    /// plane that lies on that side: 1 − the cap below over the volume (the product over two
    /// planes is exact away from their line).
    pub fn volume_share(d: f64, r: f64) -> f64 {
        let h = (r - d).clamp(0.0, 2.0 * r);
        1.0 - h * h * (3.0 * r - h) / (4.0 * r * r * r)
    }

    /// The weight of a contact's energy in the model's ledger: ½ for a sphere's contact with
    /// its own image, 1 otherwise.
    #[inline(always)]
    pub fn weight(i: u32, j: u32, image: u8) -> f64 {
        if image != 0 && i == j { 0.5 } else { 1.0 }
    }

    /// The candidate pairs (sorted) whose gap is below `skin_m`: the model's own (i < j,
    /// image 0) and the image pairs (i ≤ j, sphere i against the image of j). Each sphere
    /// within reach of a plane is reflected, the spheres and their images searched together
    /// (`detect::candidates`), and a pair of a sphere with an image kept once: i with j's
    /// image is j with i's.
    pub fn candidates(&self, pos_m: &[V3], radius_m: &[f64], skin_m: f64, parallel: bool) -> Vec<(u32, u32, u8)> {
        if self.is_empty() {
            return super::detect::candidates(pos_m, radius_m, skin_m, parallel).into_iter().map(|(i, j)| (i, j, 0)).collect();
        }
        let r_max = radius_m.iter().copied().fold(0.0, f64::max);
        let n = pos_m.len();
        let (mut pos, mut radius, mut source) = (pos_m.to_vec(), radius_m.to_vec(), Vec::new());
        for image in self.images() {
            for e in 0..n {
                // Reach of the image of e: within r_e + r_max + skin of every plane it crosses.
                let near = self.0.iter().enumerate().filter(|(b, _)| image >> b & 1 == 1).all(|(_, m)| (pos_m[e][m.axis] - m.at_m).abs() < radius_m[e] + r_max + skin_m);
                if near {
                    pos.push(self.point(pos_m[e], image));
                    radius.push(radius_m[e]);
                    source.push((e as u32, image));
                }
            }
        }
        let mut out: Vec<(u32, u32, u8)> = super::detect::candidates(&pos, &radius, skin_m, parallel)
            .into_iter()
            .filter(|&(a, _)| (a as usize) < n)
            .map(|(a, b)| match (b as usize).checked_sub(n) {
                None => (a, b, 0),
                Some(k) => {
                    let (j, image) = source[k];
                    (a.min(j), a.max(j), image)
                }
            })
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel3d::vec3::{norm, sub};

    #[test]
    fn image_pairs_are_the_pairs_of_the_whole_across_the_planes() {
        // Spheres in the quarter x > 1, z > 2 of a jittered cube; the whole is it and its three
        // images. Every pair of the whole within the quarter or between it and an image (counted
        // once up to the symmetry) is a candidate of the quarter, and nothing else.
        let mirrors = Mirrors(vec![Mirror { axis: 0, at_m: 1.0 }, Mirror { axis: 2, at_m: 2.0 }]);
        let mut s = 99u64;
        let mut rnd = || {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut pos, mut radius) = (Vec::new(), Vec::new());
        for x in 0..4 {
            for y in 0..3 {
                for z in 0..4 {
                    let r = 0.35 + 0.1 * rnd();
                    pos.push([1.0 + r + 0.01 * rnd() + x as f64 * 0.9, y as f64 * 0.9 + 0.2 * rnd(), 2.0 + r + 0.01 * rnd() + z as f64 * 0.9]);
                    radius.push(r);
                }
            }
        }
        // One sphere cut by both planes (it meets all three of its images).
        pos[0] = [1.2, pos[0][1], 2.2];
        let skin = 0.05;
        let mut brute = Vec::new();
        for i in 0..pos.len() {
            for j in i..pos.len() {
                for image in (0..4).filter(|&k| k != 0 || j > i) {
                    if norm(sub(mirrors.point(pos[j], image), pos[i])) < radius[i] + radius[j] + skin {
                        brute.push((i as u32, j as u32, image));
                    }
                }
            }
        }
        brute.sort_unstable();
        assert!(brute.iter().filter(|p| p.0 == p.1).count() >= 16 && brute.iter().any(|p| p.2 == 3), "{brute:?}");
        assert_eq!(mirrors.candidates(&pos, &radius, skin, false), brute);
        assert_eq!(mirrors.candidates(&pos, &radius, skin, true), brute);
    }

    #[test]
    fn an_axial_vector_turns_with_the_handedness_of_the_reflection() {
        // ω = a × b for vectors a, b: the reflected pair's cross product is the reflected ω.
        let m = Mirrors(vec![Mirror { axis: 0, at_m: 0.3 }, Mirror { axis: 2, at_m: -1.0 }]);
        let (a, b) = ([0.3, -1.2, 0.7], [2.0, 0.4, -0.9]);
        let cross = |u: V3, v: V3| [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
        for image in m.images() {
            assert_eq!(m.axial(cross(a, b), image), cross(m.vector(a, image), m.vector(b, image)), "image {image}");
        }
    }
}
