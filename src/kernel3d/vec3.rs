//! Three-component vectors as plain arrays (what the state stores and checkpoints), with the
//! few operations the 3D laws and the update need.

/// A vector [x, y, z].
pub type V3 = [f64; 3];

/// a + b.
#[inline(always)]
pub fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// a − b.
#[inline(always)]
pub fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// s a.
#[inline(always)]
pub fn scale(s: f64, a: V3) -> V3 {
    [s * a[0], s * a[1], s * a[2]]
}

/// a · b.
#[inline(always)]
pub fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// a × b.
#[inline(always)]
pub fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// |a|.
#[inline(always)]
pub fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// The part of `a` in the plane normal to the unit vector `n`: a − (a·n) n.
#[inline(always)]
pub fn in_plane(a: V3, n: V3) -> V3 {
    sub(a, scale(dot(a, n), n))
}

/// A vector that lay in the plane normal to the old normal, carried into the plane normal to
/// the new one `n` with its length kept (projected, then rescaled): how a contact's shear
/// spring and rolling angle follow the contact as it turns.
#[inline(always)]
pub fn carried(a: V3, n: V3) -> V3 {
    let p = in_plane(a, n);
    let (la, lp) = (norm(a), norm(p));
    if lp > 0.0 { scale(la / lp, p) } else { [0.0; 3] }
}
