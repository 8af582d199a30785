//! What the derivative functions share: the barycentric derivatives' arguments; and for their
//! references, a triangle hit by a family of rays that a differential moves, re-intersected
//! exactly, the bounds of texture derivatives from it, and texel gradients.

use crate::exact::{
    derivative, log_uniform, tangent, towards, triangle_hit, unit, Derivative, Differentiable,
};
use crate::ray_diff::family::{axis, differential, family_step, vector};
use glam::{DMat2, DVec2, DVec3, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{Derivatives2, RayDiff};

/// The arguments of `barycentric_derivatives`: differential, direction, t, the triangle.
pub type BarycentricArgs = (RayDiff, Vec3, f32, Vec3, Vec3, Vec3);

/// A triangle, a ray meeting its plane at `t`, a differential, and an affine texture map of the
/// plane: the family of rays the differential moves, re-intersected exactly.
#[derive(Clone, Debug)]
pub(crate) struct Hit {
    pub(crate) corners: [Vec3; 3],
    direction: Vec3,
    t: f32,
    diff: RayDiff,
    /// The hit on the plane of the f32 corners, in f64.
    point: DVec3,
    /// `|cos|` of the ray against the plane.
    cosine: f64,
    /// The plane's in-plane axes, and the texture map `uv = map q + offset` of in-plane
    /// coordinates `q` (from `corners[0]`).
    axes: [DVec3; 2],
    map: DMat2,
    offset: DVec2,
}

impl Hit {
    pub(crate) fn strategy() -> BoxedStrategy<Hit> {
        let corner = || (-1.0f64..1.0, -1.0f64..1.0).prop_map(|(x, y)| DVec2::new(x, y));
        (
            (
                (corner(), corner(), corner()),
                log_uniform(-1.0, 1.0),
                vector(-1.0, 1.0),
                unit(),
                0.0f64..6.3,
            ),
            (
                -0.5f64..1.5,
                -0.5f64..1.5,
                0.05f64..1.0,
                0.0f64..6.3,
                any::<bool>(),
            ),
            (log_uniform(-1.0, 2.0), differential()),
            (
                (-2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0),
                (-2.0f64..2.0, -2.0f64..2.0),
            ),
        )
            .prop_map(
                |((q, size, centre, normal, roll), (a, b, cosine, angle, behind), (t, diff), (m, o))| {
                    let u = tangent(normal, roll);
                    let v = normal.cross(u);
                    let corners = [q.0, q.1, q.2].map(|q| (centre + (u * q.x + v * q.y) * size).as_vec3());
                    let p = corners.map(Vec3::as_dvec3);
                    let point = p[0] + (p[1] - p[0]) * a + (p[2] - p[0]) * b;
                    let plane_normal = (p[1] - p[0]).cross(p[2] - p[0]).normalize();
                    let d = towards(plane_normal, cosine, angle);
                    let u_axis = (p[1] - p[0]).normalize();
                    Hit {
                        corners,
                        direction: (if behind { -d } else { d }).as_vec3(),
                        t: t as f32,
                        diff,
                        point,
                        cosine,
                        axes: [u_axis, plane_normal.cross(u_axis)],
                        map: DMat2::from_cols(DVec2::new(m.0, m.2), DVec2::new(m.1, m.3)),
                        offset: DVec2::new(o.0, o.1),
                    }
                },
            )
            .prop_filter("a sliver", |hit| {
                let p = hit.corners.map(Vec3::as_dvec3);
                let (e1, e2) = (p[1] - p[0], p[2] - p[0]);
                e1.cross(e2).length() > 0.1 * e1.length() * e2.length() && hit.map.determinant().abs() > 0.1
            })
            .boxed()
    }

    pub(crate) fn corners64(&self) -> [DVec3; 3] {
        self.corners.map(Vec3::as_dvec3)
    }

    pub(crate) fn arguments(&self) -> BarycentricArgs {
        let [p0, p1, p2] = self.corners;
        (self.diff, self.direction, self.t, p0, p1, p2)
    }

    /// The exact hit `(barycentrics (w, u, v), point)` of the ray of axis `a` moved by `h`: origin
    /// `O + h dO`, direction `D + h dD`, with `O = point - t D`.
    fn moved(&self, a: usize, h: f64) -> (DVec3, DVec3) {
        let (o, dd) = axis(&self.diff, a);
        let d = self.direction.as_dvec3();
        let origin = self.point - d * f64::from(self.t) + o * h;
        let direction = d + dd * h;
        let (b, s) = triangle_hit(origin, direction, self.corners64());
        (b, origin + direction * s)
    }

    /// Central differences of `f` of the moved hit along both axes.
    pub(crate) fn along<T: Differentiable>(&self, f: impl Fn((DVec3, DVec3)) -> T) -> [Derivative<T>; 2] {
        let size = (self.corners64()[1] - self.corners64()[0]).length();
        let step = family_step(&self.diff, f64::from(self.t), self.cosine, size);
        let scale = self.point.length() + size;
        [0, 1].map(|a| derivative(|h| f(self.moved(a, h)), step, scale))
    }

    /// The exact barycentric derivatives `(du, dv)` per axis, rounded to f32 as an input, and how
    /// far that input lies from the exact values.
    pub(crate) fn barycentric_input(&self) -> (Derivatives2, f64) {
        let [dx, dy] = self.along(|(b, _)| DVec2::new(b.y, b.z));
        let input = Derivatives2::new(dx.value.as_vec2(), dy.value.as_vec2());
        let off = (input.dx.as_dvec2() - dx.value)
            .length()
            .max((input.dy.as_dvec2() - dy.value).length());
        (input, off + dx.error.max(dy.error))
    }

    /// The texture coordinates of a point of the plane: the affine map of its in-plane coordinates.
    pub(crate) fn uv(&self, point: DVec3) -> DVec2 {
        let q = point - self.corners64()[0];
        self.map * DVec2::new(q.dot(self.axes[0]), q.dot(self.axes[1])) + self.offset
    }

    /// The corners' texture coordinates rounded to f32, and the largest rounding.
    pub(crate) fn corner_uvs(&self) -> ([Vec2; 3], f64) {
        let exact = self.corners64().map(|p| self.uv(p));
        let rounded = exact.map(DVec2::as_vec2);
        let rounding = (0..3)
            .map(|i| (rounded[i].as_dvec2() - exact[i]).length())
            .fold(0.0, f64::max);
        (rounded, rounding)
    }
}

/// The bounds of texture derivatives of `hit` from the mirror's rounding (`rounding`, per
/// component), the barycentric input's error (times the UV edges), the corner UVs' rounding
/// (times the barycentric changes) and the central differences (`error`), each times `scale`.
pub(crate) fn uv_bounds(
    hit: &Hit,
    uvs: [Vec2; 3],
    rounding: &[f64],
    errors: (f64, f64, f64),
    scale: Vec2,
) -> Vec<f64> {
    let (input_error, uv_rounding, difference_error) = errors;
    let g = uvs.map(Vec2::as_dvec2);
    let edges = (g[1] - g[0]).length() + (g[2] - g[0]).length();
    let (input, _) = hit.barycentric_input();
    let changes = [input.dx, input.dy].map(|b| f64::from(b.x.abs() + b.y.abs()));
    (0..4)
        .map(|i| {
            let base = input_error * edges + 2.0 * uv_rounding * changes[i / 2] + difference_error;
            rounding[i] + base * f64::from(scale[i % 2])
        })
        .collect()
}

/// Texel gradients: two vectors of random direction, `10^[-6, 4)` long.
pub(crate) fn texel_gradients() -> BoxedStrategy<Derivatives2> {
    let gradient =
        || (0.0f64..6.3, log_uniform(-6.0, 4.0)).prop_map(|(a, l)| (DVec2::from_angle(a) * l).as_vec2());
    (gradient(), gradient())
        .prop_map(|(dx, dy)| Derivatives2::new(dx, dy))
        .boxed()
}
