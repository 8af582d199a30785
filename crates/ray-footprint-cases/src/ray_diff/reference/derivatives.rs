//! References of the transfer and derivative sections: a family of rays moved by a differential,
//! re-intersected exactly in f64 with a plane or a triangle, and the central differences of what
//! the hits give (the point, its barycentrics, the area ratio of `w`, texture coordinates of an
//! affine map of the plane); the LODs' closed forms.

use super::super::{enclosure, BarycentricArgs};
use super::{components, listed, widths};
use crate::exact::{derivative, log_uniform, plane_hit, tangent, towards, triangle_hit, unit, Derivative};
use crate::reference::{Deviation, Kind, Reference, U};
use glam::{DMat2, DVec2, DVec3, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{Derivatives2, Derivatives3, RayDiff};
use shader_proptest::interval::Interval;

/// A vector of random direction and a length `10^[low, high)`.
fn vector(low: f64, high: f64) -> BoxedStrategy<DVec3> {
    (unit(), log_uniform(low, high))
        .prop_map(|(v, length)| v * length)
        .boxed()
}

/// A differential: origin changes `10^[-4, 0)` long, direction changes `10^[-4, -1)`.
fn differential() -> BoxedStrategy<RayDiff> {
    (
        vector(-4.0, 0.0),
        vector(-4.0, 0.0),
        vector(-4.0, -1.0),
        vector(-4.0, -1.0),
    )
        .prop_map(|(a, b, c, d)| RayDiff::new(a.as_vec3(), b.as_vec3(), c.as_vec3(), d.as_vec3()))
        .boxed()
}

/// The origin and direction changes of one axis (0: x, 1: y) of a differential.
fn axis(diff: &RayDiff, axis: usize) -> (DVec3, DVec3) {
    let (o, d) = (diff.d_origin(), diff.d_direction());
    if axis == 0 {
        (o.dx.as_dvec3(), d.dx.as_dvec3())
    } else {
        (o.dy.as_dvec3(), d.dy.as_dvec3())
    }
}

/// A step for the central differences of a family of rays moved by `h` times a differential: the
/// hit moves by `h (|dO| + t |dD|) / cos`, kept at `1e-4` of `scale`.
fn family_step(diff: &RayDiff, t: f64, cosine: f64, scale: f64) -> f64 {
    let moves = (0..2)
        .map(|a| {
            let (o, d) = axis(diff, a);
            o.length() + t * d.length()
        })
        .fold(0.0, f64::max);
    1.0e-4 * scale * cosine / moves.max(1.0e-300)
}

/// `rf_transfer`.
pub(in crate::ray_diff) fn transfer() -> Reference<(RayDiff, Vec3, f32, Vec3), RayDiff> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of the exact hit of the ray (h dO, D + h dD) on the plane through t D with normal N (Igehy's transfer); the direction changes pass unchanged",
        || (differential(), unit(), 0.01f64..1.0, 0.0f64..6.3, log_uniform(-2.0, 3.0)).boxed(),
        |&(diff, n, cosine, angle, t), transfer| {
            let direction = towards(n, cosine, angle).as_vec3();
            let (normal, t) = (n.as_vec3(), t as f32);
            let got = transfer((diff, direction, t, normal));
            let (d64, n64, t64) = (direction.as_dvec3(), normal.as_dvec3(), f64::from(t));
            let plane_point = d64 * t64;
            let step = family_step(&diff, t64, cosine, t64);
            let moved = |a: usize| {
                let (o, dd) = axis(&diff, a);
                derivative(|h| plane_hit(o * h, d64 + dd * h, plane_point, n64), step, 2.0 * t64)
            };
            let (dx, dy) = (moved(0), moved(1));
            let (ddx, ddy) = (axis(&diff, 0).1, axis(&diff, 1).1);
            let expected = listed(&[dx.value, dy.value, ddx, ddy], 1);
            let bounds = widths(&enclosure::transfer(&(diff, direction, t, normal)));
            let error = dx.error.max(dy.error);
            Some(components(got, &expected, |i| bounds[i] + if i < 8 { error } else { 0.0 }))
        },
    )
}

/// A triangle, a ray meeting its plane at `t`, a differential, and an affine texture map of the
/// plane: the family of rays the differential moves, re-intersected exactly.
#[derive(Clone, Debug)]
struct Hit {
    corners: [Vec3; 3],
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
    fn strategy() -> BoxedStrategy<Hit> {
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

    fn corners64(&self) -> [DVec3; 3] {
        self.corners.map(Vec3::as_dvec3)
    }

    fn arguments(&self) -> BarycentricArgs {
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
    fn along<T: crate::exact::Differentiable>(&self, f: impl Fn((DVec3, DVec3)) -> T) -> [Derivative<T>; 2] {
        let size = (self.corners64()[1] - self.corners64()[0]).length();
        let step = family_step(&self.diff, f64::from(self.t), self.cosine, size);
        let scale = self.point.length() + size;
        [0, 1].map(|a| derivative(|h| f(self.moved(a, h)), step, scale))
    }

    /// The exact barycentric derivatives `(du, dv)` per axis, rounded to f32 as an input, and how
    /// far that input lies from the exact values.
    fn barycentric_input(&self) -> (Derivatives2, f64) {
        let [dx, dy] = self.along(|(b, _)| DVec2::new(b.y, b.z));
        let input = Derivatives2::new(dx.value.as_vec2(), dy.value.as_vec2());
        let off = (input.dx.as_dvec2() - dx.value)
            .length()
            .max((input.dy.as_dvec2() - dy.value).length());
        (input, off + dx.error.max(dy.error))
    }

    /// The texture coordinates of a point of the plane: the affine map of its in-plane coordinates.
    fn uv(&self, point: DVec3) -> DVec2 {
        let q = point - self.corners64()[0];
        self.map * DVec2::new(q.dot(self.axes[0]), q.dot(self.axes[1])) + self.offset
    }

    /// The corners' texture coordinates rounded to f32, and the largest rounding.
    fn corner_uvs(&self) -> ([Vec2; 3], f64) {
        let exact = self.corners64().map(|p| self.uv(p));
        let rounded = exact.map(DVec2::as_vec2);
        let rounding = (0..3)
            .map(|i| (rounded[i].as_dvec2() - exact[i]).length())
            .fold(0.0, f64::max);
        (rounded, rounding)
    }
}

/// `rf_barycentric_derivatives`.
pub(in crate::ray_diff) fn barycentric_derivatives() -> Reference<BarycentricArgs, Derivatives2> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of the barycentrics (u, v) of the rays (O + h dO, D + h dD) re-intersected with the triangle's plane, a 3x3 system solved in f64 (RTG Eq. 12-19)",
        Hit::strategy,
        |hit, barycentric_derivatives| {
            let got = barycentric_derivatives(hit.arguments());
            let [dx, dy] = hit.along(|(b, _)| DVec2::new(b.y, b.z));
            let expected = [dx.value.x, dx.value.y, dy.value.x, dy.value.y];
            let bounds = widths(&enclosure::barycentric_derivatives(&hit.arguments()));
            Some(components(got, &expected, |i| bounds[i] + dx.error.max(dy.error)))
        },
    )
}

/// `rf_barycentric_w_derivatives`.
pub(in crate::ray_diff) fn barycentric_w_derivatives() -> Reference<(Derivatives2,), Vec2> {
    Reference::new(
        Kind::ClosedForm,
        "f64 central differences of w at the re-intersected hits computed as an area ratio, cross(p1 - P, p2 - P) . n / cross(e1, e2) . n, from the exact (du, dv) (RTG Eq. 20)",
        Hit::strategy,
        |hit, barycentric_w_derivatives| {
            let (input, input_error) = hit.barycentric_input();
            let got = barycentric_w_derivatives((input,));
            let p = hit.corners64();
            let n = (p[1] - p[0]).cross(p[2] - p[0]);
            let [dx, dy] = hit.along(|(_, point)| (p[1] - point).cross(p[2] - point).dot(n) / n.dot(n));
            // -du - dv: one rounding; the input's distance from the exact derivatives, twice.
            let bound = |b: Vec2, error: f64| U * f64::from((b.x + b.y).abs()) + 2.0 * input_error + error;
            let x = Deviation::within(f64::from(got.x), dx.value, bound(input.dx, dx.error));
            let y = Deviation::within(f64::from(got.y), dy.value, bound(input.dy, dy.error));
            Some(x.and(y))
        },
    )
}

/// The bounds of texture derivatives of `hit` from the mirror's rounding (`rounding`, per
/// component), the barycentric input's error (times the UV edges), the corner UVs' rounding
/// (times the barycentric changes) and the central differences (`error`), each times `scale`.
fn uv_bounds(hit: &Hit, uvs: [Vec2; 3], rounding: &[f64], errors: (f64, f64, f64), scale: Vec2) -> Vec<f64> {
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

/// `rf_texture_derivatives`.
pub(in crate::ray_diff) fn texture_derivatives() -> Reference<(Derivatives2, Vec2, Vec2, Vec2), Derivatives2>
{
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of the texture coordinates, under an affine map of the plane, of the re-intersected hits, against the gradients from the exact (du, dv) and the corners' UVs (RTG Eq. 21)",
        Hit::strategy,
        |hit, texture_derivatives| {
            let (input, input_error) = hit.barycentric_input();
            let (uvs, uv_rounding) = hit.corner_uvs();
            let got = texture_derivatives((input, uvs[0], uvs[1], uvs[2]));
            let [dx, dy] = hit.along(|(_, point)| hit.uv(point));
            let (rx, ry) = enclosure::texture_derivatives(input, uvs[0], uvs[1], uvs[2]);
            let rounding = widths(&[rx.components(), ry.components()].concat());
            let bounds = uv_bounds(hit, uvs, &rounding, (input_error, uv_rounding, dx.error.max(dy.error)), Vec2::ONE);
            let expected = [dx.value.x, dx.value.y, dy.value.x, dy.value.y];
            Some(components(got, &expected, |i| bounds[i]))
        },
    )
}

/// `rf_texel_derivatives`.
pub(in crate::ray_diff) fn texel_derivatives(
) -> Reference<(Derivatives2, Vec2, Vec2, Vec2, Vec2), Derivatives2> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of the texel coordinates (UV of an affine map of the plane times the texture size) of the re-intersected hits (RTG Eq. 21)",
        || (Hit::strategy(), 1.0f32..4096.0, 1.0f32..4096.0).boxed(),
        |(hit, width, height), texel_derivatives| {
            let size = Vec2::new(*width, *height);
            let (input, input_error) = hit.barycentric_input();
            let (uvs, uv_rounding) = hit.corner_uvs();
            let got = texel_derivatives((input, uvs[0], uvs[1], uvs[2], size));
            let [dx, dy] = hit.along(|(_, point)| hit.uv(point) * size.as_dvec2());
            let (rx, ry) = enclosure::texture_derivatives(input, uvs[0], uvs[1], uvs[2]);
            let scaled = |r: Interval, s: f32| r * Interval::exact(s);
            let rounding = widths(&[
                scaled(rx.0[0], size.x),
                scaled(rx.0[1], size.y),
                scaled(ry.0[0], size.x),
                scaled(ry.0[1], size.y),
            ]);
            let bounds = uv_bounds(hit, uvs, &rounding, (input_error, uv_rounding, 0.0), size);
            let expected = [dx.value.x, dx.value.y, dy.value.x, dy.value.y];
            Some(components(got, &expected, |i| bounds[i] + dx.error.max(dy.error)))
        },
    )
}

/// `rf_secondary_origin_derivatives`.
pub(in crate::ray_diff) fn secondary_origin_derivatives(
) -> Reference<(Derivatives2, Vec3, Vec3, Vec3), Derivatives3> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of the re-intersected hit points themselves (origin + s direction, not through barycentrics), against the origins from the exact (du, dv) (RTG Eq. 22)",
        Hit::strategy,
        |hit, secondary_origin_derivatives| {
            let (input, input_error) = hit.barycentric_input();
            let [p0, p1, p2] = hit.corners;
            let got = secondary_origin_derivatives((input, p0, p1, p2));
            let [dx, dy] = hit.along(|(_, point)| point);
            let p = hit.corners64();
            let edges = (p[1] - p[0]).length() + (p[2] - p[0]).length();
            let rounding = widths(&enclosure::secondary_origin_derivatives(&(input, p0, p1, p2)));
            let expected = listed(&[dx.value, dy.value], 0);
            let error = dx.error.max(dy.error) + input_error * edges;
            Some(components(got, &expected, |i| rounding[i] + error))
        },
    )
}

/// Texel gradients: two vectors of random direction, `10^[-6, 4)` long.
fn texel_gradients() -> BoxedStrategy<Derivatives2> {
    let gradient =
        || (0.0f64..6.3, log_uniform(-6.0, 4.0)).prop_map(|(a, l)| (DVec2::from_angle(a) * l).as_vec2());
    (gradient(), gradient())
        .prop_map(|(dx, dy)| Derivatives2::new(dx, dy))
        .boxed()
}

/// `rf_lod_isotropic`.
pub(in crate::ray_diff) fn lod_isotropic() -> Reference<(Derivatives2,), f32> {
    Reference::new(
        Kind::ClosedForm,
        "log2 of the longer texel gradient, each length an f64 hypot, the log as ln / ln 2 (RTG Eq. 1-2)",
        texel_gradients,
        |&g, lod_isotropic| {
            let got = lod_isotropic((g,));
            let longer = f64::from(g.dx.x)
                .hypot(f64::from(g.dx.y))
                .max(f64::from(g.dy.x).hypot(f64::from(g.dy.y)));
            let expected = longer.ln() / std::f64::consts::LN_2;
            let bound = enclosure::lod_isotropic(g);
            Some(Deviation::within(f64::from(got), expected, bound.hi - bound.lo))
        },
    )
}

/// `rf_lod_box`.
pub(in crate::ray_diff) fn lod_box() -> Reference<(Derivatives2,), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "log2 of the larger side of the axis-aligned box around the footprint parallelogram, from its four corners 0, dx, dy, dx + dy (RTG Sec. 20.1)",
        texel_gradients,
        |&g, lod_box| {
            let got = lod_box((g,));
            let corners = [DVec2::ZERO, g.dx.as_dvec2(), g.dy.as_dvec2(), (g.dx.as_dvec2() + g.dy.as_dvec2())];
            let side = |axis: usize| {
                let values = corners.map(|c| c[axis]);
                values.iter().copied().fold(f64::MIN, f64::max) - values.iter().copied().fold(f64::MAX, f64::min)
            };
            let expected = side(0).max(side(1)).log2();
            let bound = enclosure::lod_box(g);
            Some(Deviation::within(f64::from(got), expected, bound.hi - bound.lo + 1.0e-15))
        },
    )
}

/// `rf_sample_grad_gradients`.
pub(in crate::ray_diff) fn sample_grad_gradients() -> Reference<(Derivatives2, f32), Derivatives2> {
    Reference::new(
        Kind::ClosedForm,
        "the UV gradients scaled in f64 by max(tex_grad_scale, 0): mip 0 for a scale of 0 or below, the footprint blurred above 1",
        || (texel_gradients(), prop_oneof![-1.0f32..4.0, Just(0.0f32), Just(1.0f32)]).boxed(),
        |&(g, scale), sample_grad_gradients| {
            let got = sample_grad_gradients((g, scale));
            let s = f64::from(scale).max(0.0);
            let expected = [g.dx.x, g.dx.y, g.dy.x, g.dy.y].map(|c| f64::from(c) * s);
            // One product each.
            Some(components(got, &expected, |i| U * expected[i].abs()))
        },
    )
}
