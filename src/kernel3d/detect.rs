//! Contact detection: the pairs closer than their radii plus a skin, found on a cell grid, and
//! merged into the contact list so that every contact keeps its history. Searched again only
//! when a sphere has moved half the skin since the last search (no pair can then have closed
//! the gap unseen). Which pairs are candidates changes the cost, never the result: a candidate
//! apart carries nothing, and a contact's history lives until it comes apart.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

use super::contact::{Bond, Contact};
use super::vec3::{V3, norm, scale, sub};

/// A hasher for cell keys: a multiply and rotate per 8 bytes. The std hasher (SipHash, made to
/// resist crafted keys, which a grid of one's own spheres never meets) took 44 % of the search
/// (sweeps/impact3d.toml, 300 steps: 611e6 of 1389e6 instructions).
#[derive(Default)]
struct CellHasher(u64);

impl Hasher for CellHasher {
    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8) {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            self.0 = (self.0 ^ u64::from_le_bytes(word)).wrapping_mul(0x9E37_79B9_7F4A_7C15).rotate_left(31);
        }
    }

    fn finish(&self) -> u64 {
        self.0
    }
}

/// The pairs (i < j, sorted) whose gap is below `skin_m`, searched on the pool when `parallel`
/// (the same pairs either way).
///
/// Each pair is found from its larger sphere (ties: from the lower index), which looks within
/// 2 r + skin of its centre, on the grid whose cells that reach fits: in a graded packing a
/// fine sphere then checks its own neighbourhood, not a coarse sphere's (one grid sized for the
/// largest took 20 % of a level-1 impact step, its fine cells holding about a hundred spheres).
pub fn candidates(pos_m: &[V3], radius_m: &[f64], skin_m: f64, parallel: bool) -> Vec<(u32, u32)> {
    let (r_min, r_max) = radius_m.iter().fold((f64::INFINITY, 0.0f64), |(a, b), &r| (a.min(r), b.max(r)));
    // Grids of cells 2 r_min + skin, twice that, ... up to one a largest sphere's reach wide;
    // every sphere is in each, and searches the 27 cells of the finest grid its reach fits.
    let mut cells = vec![2.0 * r_min + skin_m];
    while cells[cells.len() - 1] < 2.0 * r_max + skin_m {
        cells.push(2.0 * cells[cells.len() - 1]);
    }
    let key = |p: V3, cell: f64| [(p[0] / cell).floor() as i64, (p[1] / cell).floor() as i64, (p[2] / cell).floor() as i64];
    // Cells by key; only looked up, never iterated, so the result does not depend on the map.
    let grids: Vec<HashMap<[i64; 3], Vec<u32>, BuildHasherDefault<CellHasher>>> = cells
        .iter()
        .map(|&cell| {
            let mut grid: HashMap<_, Vec<u32>, _> = HashMap::default();
            for (e, &p) in pos_m.iter().enumerate() {
                grid.entry(key(p, cell)).or_default().push(e as u32);
            }
            grid
        })
        .collect();
    let from = |i: usize, pairs: &mut Vec<(u32, u32)>| {
        let (p, ri) = (pos_m[i], radius_m[i]);
        let level = cells.iter().position(|&c| c >= 2.0 * ri + skin_m).unwrap_or(cells.len() - 1);
        let k = key(p, cells[level]);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    let Some(list) = grids[level].get(&[k[0] + dx, k[1] + dy, k[2] + dz]) else { continue };
                    for &j in list {
                        let rj = radius_m[j as usize];
                        if rj > ri || (rj == ri && j as usize <= i) {
                            continue;
                        }
                        if norm(sub(pos_m[j as usize], p)) < ri + rj + skin_m {
                            pairs.push(if (j as usize) < i { (j, i as u32) } else { (i as u32, j) });
                        }
                    }
                }
            }
        }
    };
    let mut pairs = if parallel {
        use rayon::prelude::*;
        (0..pos_m.len())
            .into_par_iter()
            .fold(Vec::new, |mut v, i| {
                from(i, &mut v);
                v
            })
            .reduce(Vec::new, |mut a, mut b| {
                a.append(&mut b);
                a
            })
    } else {
        let mut v = Vec::new();
        (0..pos_m.len()).for_each(|i| from(i, &mut v));
        v
    };
    pairs.sort_unstable();
    pairs
}

/// The contact list after a search: the old contacts that are bonds or still candidates, in
/// order, and a fresh frictional contact for each new candidate (i, j, image) (`class(i, j)`,
/// rest length r_i + r_j, normal along the centres, j seen through `image`'s planes:
/// `reflect(p, image)`, `mirror::Mirrors::point`).
pub fn merge(old: Vec<Contact>, pairs: &[(u32, u32, u8)], pos_m: &[V3], radius_m: &[f64], reflect: impl Fn(V3, u8) -> V3, class: impl Fn(u32, u32) -> u16) -> Vec<Contact> {
    let mut out = Vec::with_capacity(pairs.len());
    let mut old = old.into_iter().peekable();
    let mut fresh = pairs.iter().peekable();
    loop {
        let key_old = old.peek().map(|c| (c.i, c.j, c.image));
        let key_new = fresh.peek().map(|&&p| p);
        match (key_old, key_new) {
            (None, None) => break,
            (Some(a), Some(b)) if a == b => {
                out.push(old.next().expect("peeked"));
                fresh.next();
            }
            (Some(a), b) if b.is_none_or(|b| a < b) => {
                // No longer a candidate: a frictional contact this far apart holds nothing.
                let c = old.next().expect("peeked");
                if c.bond == Bond::Intact {
                    out.push(c);
                }
            }
            (_, Some((i, j, image))) => {
                let (iu, ju) = (i as usize, j as usize);
                let dx = sub(reflect(pos_m[ju], image), pos_m[iu]);
                let n = scale(1.0 / norm(dx), dx);
                let mut c = Contact::new(i, j, class(i, j), Bond::Frictional, radius_m[iu] + radius_m[ju], n);
                c.image = image;
                out.push(c);
                fresh.next();
            }
            (Some(_), None) => unreachable!("an old contact with no candidate left is taken above"),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grid_finds_exactly_the_pairs_a_full_search_finds() {
        // A jittered cube of 125 spheres of radii 0.4–0.6, and a few of 1.5 among them (a
        // graded packing's coarse spheres beside fine ones), two of equal radius.
        let mut pos = Vec::new();
        let mut radius = Vec::new();
        let mut s = 12345u64;
        let mut rnd = || {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        for x in 0..5 {
            for y in 0..5 {
                for z in 0..5 {
                    pos.push([x as f64 + 0.3 * rnd(), y as f64 + 0.3 * rnd(), z as f64 + 0.3 * rnd()]);
                    radius.push(0.4 + 0.2 * rnd());
                }
            }
        }
        for (k, r) in [(7, 1.5), (62, 1.5), (100, 1.2), (31, 0.45), (32, 0.45)] {
            radius[k] = r;
        }
        let skin = 0.1;
        let mut brute = Vec::new();
        for i in 0..pos.len() {
            for j in i + 1..pos.len() {
                if norm(sub(pos[j], pos[i])) < radius[i] + radius[j] + skin {
                    brute.push((i as u32, j as u32));
                }
            }
        }
        assert!(brute.len() > 200, "{}", brute.len());
        assert_eq!(candidates(&pos, &radius, skin, false), brute);
        assert_eq!(candidates(&pos, &radius, skin, true), brute);
    }
}
