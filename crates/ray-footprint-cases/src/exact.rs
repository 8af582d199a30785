//! What the independent references compute in f64 ([`crate::reference`]): derivatives by central
//! differences with an estimate of their error, Snell's law, ray-plane and ray-triangle
//! intersections solved as linear systems, angles between vectors, and the strategies of their
//! geometric cases.

use glam::{DMat3, DVec2, DVec3, Vec3};
use proptest::prelude::*;
use proptest::strategy::BoxedStrategy;
use std::ops::{Add, Mul, Sub};

/// A value of which [`derivative`] can take central differences: a scalar or a vector.
pub trait Differentiable: Copy + Add<Output = Self> + Sub<Output = Self> + Mul<f64, Output = Self> {
    /// The Euclidean length (the magnitude of a scalar).
    fn size(self) -> f64;
}

impl Differentiable for f64 {
    fn size(self) -> f64 {
        self.abs()
    }
}

impl Differentiable for DVec2 {
    fn size(self) -> f64 {
        self.length()
    }
}

impl Differentiable for DVec3 {
    fn size(self) -> f64 {
        self.length()
    }
}

/// A derivative and a bound of its error.
#[derive(Clone, Copy, Debug)]
pub struct Derivative<T> {
    /// The central difference `(f(h) - f(-h)) / 2h`.
    pub value: T,
    /// A bound of `|value - f'(0)|`: the truncation error estimated from a second step (below) plus
    /// the rounding of the differences.
    pub error: f64,
}

/// `f'(0)` by central differences with step `step`, and its error.
///
/// The central difference `D(h)` is `f'(0) + h^2 f'''(0) / 6 + O(h^4)`, so
/// `D(h) - D(2h) = -3 h^2 f'''(0) / 6 + O(h^4)`: three times `D(h)`'s truncation error, which
/// `|D(h) - D(2h)|` therefore bounds with room. Each evaluation of `f` is off by its f64 rounding,
/// at most 64 f64 ULP of `scale` (the largest magnitude `f`'s computation handles, given by the
/// caller), which the difference divides by `2h`.
pub fn derivative<T: Differentiable>(f: impl Fn(f64) -> T, step: f64, scale: f64) -> Derivative<T> {
    let difference = |h: f64| (f(h) - f(-h)) * (0.5 / h);
    let (fine, coarse) = (difference(step), difference(2.0 * step));
    Derivative {
        value: fine,
        error: (fine - coarse).size() + 64.0 * f64::EPSILON * scale / step,
    }
}

/// The angle between two vectors, `atan2(|a x b|, a . b)`: accurate at every angle.
pub fn angle_between(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

/// The unit ray `d` refracted by Snell's law (`eta = n_incident / n_transmitted`) at the unit
/// normal `n` on either side, as GLSL's `refract` with the normal turned to face the ray; `None`
/// on total internal reflection.
pub fn snell(d: DVec3, n: DVec3, eta: f64) -> Option<DVec3> {
    let facing = if d.dot(n) > 0.0 { -n } else { n };
    let cosine = d.dot(facing);
    let k = 1.0 - eta * eta * (1.0 - cosine * cosine);
    (k >= 0.0).then(|| d * eta - facing * (eta * cosine + k.sqrt()))
}

/// `v` mirrored at the plane with unit normal `n`: `v - 2 (v . n) n`, a direction's reflection.
pub fn mirrored(v: DVec3, n: DVec3) -> DVec3 {
    v - n * (2.0 * v.dot(n))
}

/// Where the ray `origin + s direction` meets the plane through `point` with normal `normal`.
pub fn plane_hit(origin: DVec3, direction: DVec3, point: DVec3, normal: DVec3) -> DVec3 {
    origin + direction * ((point - origin).dot(normal) / direction.dot(normal))
}

/// Barycentrics `(w, u, v)` and the distance `s` of the point where the ray `origin + s direction`
/// meets the plane of the triangle `p`, solving `p0 + u e1 + v e2 = origin + s direction` as a
/// 3x3 linear system (the matrix inverted in f64).
pub fn triangle_hit(origin: DVec3, direction: DVec3, p: [DVec3; 3]) -> (DVec3, f64) {
    let system = DMat3::from_cols(p[1] - p[0], p[2] - p[0], -direction);
    let solution = system.inverse() * (origin - p[0]);
    (
        DVec3::new(1.0 - solution.x - solution.y, solution.x, solution.y),
        solution.z,
    )
}

/// Twice the area of a triangle from its side lengths (Heron's formula in Kahan's stable form:
/// the sides sorted `a >= b >= c`, `sqrt((a + (b + c)) (c - (a - b)) (c + (a - b)) (a + (b - c))) / 2`).
pub fn heron_area2(p: [DVec3; 3]) -> f64 {
    let mut sides = [
        (p[1] - p[0]).length(),
        (p[2] - p[1]).length(),
        (p[0] - p[2]).length(),
    ];
    sides.sort_by(|x, y| y.total_cmp(x));
    let [a, b, c] = sides;
    let product = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
    0.5 * product.max(0.0).sqrt()
}

/// A unit vector uniform on the sphere, in f64.
pub fn unit() -> BoxedStrategy<DVec3> {
    (-1.0f64..1.0, 0.0f64..std::f64::consts::TAU)
        .prop_map(|(z, phi)| {
            let r = (1.0 - z * z).sqrt();
            DVec3::new(r * phi.cos(), r * phi.sin(), z)
        })
        .boxed()
}

/// `10^e` for `e` uniform in `[low, high)`.
pub fn log_uniform(low: f64, high: f64) -> BoxedStrategy<f64> {
    (low..high).prop_map(|e| 10f64.powf(e)).boxed()
}

/// `sign * 10^e` for `e` uniform in `[low, high)` and either sign.
pub fn signed_log(low: f64, high: f64) -> BoxedStrategy<f64> {
    (log_uniform(low, high), any::<bool>())
        .prop_map(|(m, negative)| if negative { -m } else { m })
        .boxed()
}

/// A unit vector `tangent` perpendicular to the unit `normal`, turned about it by `angle` from a
/// fixed one.
pub fn tangent(normal: DVec3, angle: f64) -> DVec3 {
    let u = normal.any_orthonormal_vector();
    let v = normal.cross(u);
    u * angle.cos() + v * angle.sin()
}

/// A unit direction that meets the unit `normal` at `|cos| = cosine` from the side it points to,
/// its tangential part along [`tangent`]`(normal, angle)`.
pub fn towards(normal: DVec3, cosine: f64, angle: f64) -> DVec3 {
    tangent(normal, angle) * (1.0 - cosine * cosine).sqrt() - normal * cosine
}

/// The f32 vector nearest to `v`, back in f64 (the value a mirror receives).
pub fn rounded(v: DVec3) -> Vec3 {
    v.as_vec3()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derivatives_and_their_error() {
        let d = derivative(|x| (1.0 + x).powi(3), 1.0e-3, 1.0);
        assert!((d.value - 3.0).abs() <= d.error && d.error < 1.0e-5, "{d:?}");
    }

    #[test]
    fn intersections_and_areas() {
        let p = [DVec3::ZERO, DVec3::X, DVec3::Y];
        let (b, s) = triangle_hit(DVec3::new(0.25, 0.5, 2.0), DVec3::NEG_Z, p);
        assert_eq!((b, s), (DVec3::new(0.25, 0.25, 0.5), 2.0));
        assert!((heron_area2(p) - 1.0).abs() < 1.0e-15);
        let hit = plane_hit(DVec3::Z, DVec3::new(1.0, 0.0, -1.0), DVec3::ZERO, DVec3::Z);
        assert_eq!(hit, DVec3::X);
        assert!((angle_between(DVec3::X, DVec3::Y) - std::f64::consts::FRAC_PI_2).abs() < 1.0e-15);
    }
}
