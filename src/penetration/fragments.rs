//! Fragments: the connected sets of a body's elements over intact bonds (union-find), with
//! what the outcome definitions need of each: mass, momentum, extent, and whether it holds a
//! supported element or elements that started on a face.

use crate::simulation::Bodies;

/// Union-find with path halving and union by size.
#[derive(Debug, Clone, Default)]
pub struct UnionFind {
    parent: Vec<u32>,
    size: Vec<u32>,
}

impl UnionFind {
    /// `n` singletons.
    pub fn new(n: usize) -> UnionFind {
        UnionFind { parent: (0..n as u32).collect(), size: vec![1; n] }
    }

    /// The representative of `a`'s set.
    pub fn find(&mut self, mut a: u32) -> u32 {
        while self.parent[a as usize] != a {
            let p = self.parent[a as usize];
            self.parent[a as usize] = self.parent[p as usize];
            a = p;
        }
        a
    }

    /// Join the sets of `a` and `b`.
    pub fn union(&mut self, a: u32, b: u32) {
        let (mut a, mut b) = (self.find(a), self.find(b));
        if a == b {
            return;
        }
        if self.size[a as usize] < self.size[b as usize] {
            std::mem::swap(&mut a, &mut b);
        }
        self.parent[b as usize] = a;
        self.size[a as usize] += self.size[b as usize];
    }
}

/// One connected set of elements.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Fragment {
    /// Elements in it.
    pub elements: u32,
    /// Mass, kg (per the model's slice).
    pub mass_kg: f64,
    /// Momentum [x, y, z], kg·m/s (z = 0 in 2D).
    pub momentum: [f64; 3],
    /// Mass-weighted centre [x, y, z], kg·m (divide by the mass).
    pub moment: [f64; 3],
    /// Holds an element of a support (held, or tied to what lies beyond by a boundary dashpot).
    pub supported: bool,
    /// Holds an element that started on the back face.
    pub back: bool,
    /// Holds an element that started on the front face.
    pub front: bool,
}

impl Fragment {
    /// Velocity of its centre of mass [x, y, z], m/s.
    pub fn velocity_mps(&self) -> [f64; 3] {
        self.momentum.map(|p| p / self.mass_kg)
    }

    /// Centre of mass [x, y, z], m.
    pub fn centre_m(&self) -> [f64; 3] {
        self.moment.map(|p| p / self.mass_kg)
    }
}

/// The fragments of the elements `range` of `model` over its intact bonds; `face(e)` says
/// whether element e started on the (back, front) face. Returns the fragments and, per element
/// of the range, the index of its fragment.
pub fn fragments(model: &(impl Bodies + ?Sized), range: std::ops::Range<usize>, face: impl Fn(usize) -> (bool, bool)) -> (Vec<Fragment>, Vec<u32>) {
    let n = range.len();
    let mut uf = UnionFind::new(n);
    model.each_bond(&mut |i, j| {
        if range.contains(&i) && range.contains(&j) {
            uf.union((i - range.start) as u32, (j - range.start) as u32);
        }
    });
    let mut index = vec![u32::MAX; n];
    let mut out: Vec<Fragment> = Vec::new();
    for k in 0..n {
        let root = uf.find(k as u32) as usize;
        if index[root] == u32::MAX {
            index[root] = out.len() as u32;
            out.push(Fragment::default());
        }
        let f = &mut out[index[root] as usize];
        let e = range.start + k;
        let (m, p, v) = (model.mass_kg(e), model.position_m(e), model.velocity_mps(e));
        let (back, front) = face(e);
        f.elements += 1;
        f.mass_kg += m;
        for k in 0..3 {
            f.momentum[k] += m * v[k];
            f.moment[k] += m * p[k];
        }
        f.supported |= model.held(e);
        f.back |= back;
        f.front |= front;
    }
    let of = (0..n).map(|k| index[uf.find(k as u32) as usize]).collect();
    (out, of)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn union_find_joins_chains_and_keeps_the_rest_apart() {
        let mut uf = UnionFind::new(6);
        uf.union(0, 1);
        uf.union(2, 1);
        uf.union(4, 5);
        assert_eq!(uf.find(0), uf.find(2));
        assert_ne!(uf.find(0), uf.find(3));
        assert_eq!(uf.find(4), uf.find(5));
        assert_ne!(uf.find(3), uf.find(5));
    }
}
