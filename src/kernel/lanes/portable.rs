//! The portable lanes: four f64 in an array, each operation the scalar one per lane (with
//! `min` as x86's `minpd` takes it), for processors without AVX and for the tests everywhere.

use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

use super::{Lanes, Mask, Real};

/// Four f64 lanes, lane l at index l.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Portable(pub [f64; 4]);

/// Four truth values, lane l at index l.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mask4(pub [bool; 4]);

/// Lane by lane.
#[inline(always)]
fn each(f: impl Fn(usize) -> f64) -> Portable {
    Portable(std::array::from_fn(f))
}

/// Lane by lane.
#[inline(always)]
fn test(f: impl Fn(usize) -> bool) -> Mask4 {
    Mask4(std::array::from_fn(f))
}

macro_rules! binary {
    ($($tr:ident $f:ident $op:tt),*) => {$(
        impl $tr for Portable {
            type Output = Portable;
            #[inline(always)]
            fn $f(self, o: Portable) -> Portable {
                each(|l| self.0[l] $op o.0[l])
            }
        }
    )*};
}
binary!(Add add +, Sub sub -, Mul mul *, Div div /);

impl Neg for Portable {
    type Output = Portable;
    #[inline(always)]
    fn neg(self) -> Portable {
        each(|l| -self.0[l])
    }
}

impl BitAnd for Mask4 {
    type Output = Mask4;
    #[inline(always)]
    fn bitand(self, o: Mask4) -> Mask4 {
        test(|l| self.0[l] & o.0[l])
    }
}

impl BitOr for Mask4 {
    type Output = Mask4;
    #[inline(always)]
    fn bitor(self, o: Mask4) -> Mask4 {
        test(|l| self.0[l] | o.0[l])
    }
}

impl Not for Mask4 {
    type Output = Mask4;
    #[inline(always)]
    fn not(self) -> Mask4 {
        test(|l| !self.0[l])
    }
}

impl Mask for Mask4 {
    #[inline(always)]
    fn all(self) -> bool {
        self.0.iter().all(|&b| b)
    }
    #[inline(always)]
    fn any(self) -> bool {
        self.0.iter().any(|&b| b)
    }
}

impl Real for Portable {
    type Mask = Mask4;
    const LANES: usize = 4;
    #[inline(always)]
    fn splat(x: f64) -> Portable {
        Portable([x; 4])
    }
    #[inline(always)]
    fn sqrt(self) -> Portable {
        each(|l| self.0[l].sqrt())
    }
    #[inline(always)]
    fn abs(self) -> Portable {
        each(|l| self.0[l].abs())
    }
    #[inline(always)]
    fn min(self, o: Portable) -> Portable {
        each(|l| if self.0[l] < o.0[l] { self.0[l] } else { o.0[l] })
    }
    #[inline(always)]
    fn copysign(self, sign: Portable) -> Portable {
        each(|l| self.0[l].copysign(sign.0[l]))
    }
    #[inline(always)]
    fn le(self, o: Portable) -> Mask4 {
        test(|l| self.0[l] <= o.0[l])
    }
    #[inline(always)]
    fn ge(self, o: Portable) -> Mask4 {
        test(|l| self.0[l] >= o.0[l])
    }
    #[inline(always)]
    fn gt(self, o: Portable) -> Mask4 {
        test(|l| self.0[l] > o.0[l])
    }
    #[inline(always)]
    fn eq(self, o: Portable) -> Mask4 {
        test(|l| self.0[l] == o.0[l])
    }
    #[inline(always)]
    fn ne(self, o: Portable) -> Mask4 {
        test(|l| self.0[l] != o.0[l])
    }
    #[inline(always)]
    fn select(m: Mask4, a: Portable, b: Portable) -> Portable {
        each(|l| if m.0[l] { a.0[l] } else { b.0[l] })
    }
    #[inline(always)]
    fn keep(self, m: Mask4) -> Portable {
        each(|l| if m.0[l] { self.0[l] } else { 0.0 })
    }
    #[inline(always)]
    fn load(a: &[f64]) -> Portable {
        Portable(a[..4].try_into().expect("four numbers"))
    }
    #[inline(always)]
    fn store(self, a: &mut [f64]) {
        a[..4].copy_from_slice(&self.0);
    }
    #[inline(always)]
    fn columns(a: Portable, b: Portable, c: Portable) -> (Portable, Portable, Portable) {
        let flat = [a.0, b.0, c.0];
        let at = |k: usize| flat[k / 4][k % 4];
        (each(|l| at(3 * l)), each(|l| at(3 * l + 1)), each(|l| at(3 * l + 2)))
    }
    #[inline(always)]
    fn rows_xy(a: &[[f64; 2]]) -> (Portable, Portable) {
        (each(|l| a[l][0]), each(|l| a[l][1]))
    }
}

impl Lanes for Portable {
    #[inline(always)]
    fn gather(f: impl Fn(usize) -> f64) -> Portable {
        each(f)
    }
    #[inline(always)]
    fn xy(a: &[[f64; 3]], row: impl Fn(usize) -> usize) -> (Portable, Portable) {
        (each(|l| a[row(l)][0]), each(|l| a[row(l)][1]))
    }
    #[inline(always)]
    fn mask(f: impl Fn(usize) -> bool) -> Mask4 {
        test(f)
    }
    #[inline(always)]
    fn to_array(self) -> [f64; 4] {
        self.0
    }
}
