//! References of the footprint and texture-LOD section: the cone's boundary rays cut by the
//! surface, Heron's formula and the shoelace formula, triangles mapped to UV by a known affine
//! map, and the boundary rays of a cone on a latitude-longitude map.

use super::propagation::{signed_log, unit_excess, width_rounding};
use crate::exact::{heron_area2, log_uniform, plane_hit, towards, unit};
use crate::reference::{gamma, Deviation, Kind, Reference, U};
use crate::strategy::{triangle, uv_triangle};
use glam::{DMat2, DVec2, DVec3, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::RayCone;
use std::f64::consts::{LN_2, PI};

/// A unit normal and a unit direction meeting it at `|cos|` from 1e-3 to 1, from either side.
fn surface_hit() -> BoxedStrategy<(DVec3, DVec3)> {
    let cosine = prop_oneof![2 => 0.05f64..1.0, 1 => log_uniform(-3.0, 0.0)];
    (unit(), cosine, 0.0f64..6.3, any::<bool>())
        .prop_map(|(n, cosine, angle, behind)| {
            let d = towards(n, cosine, angle);
            (n, if behind { -d } else { d })
        })
        .boxed()
}

/// The length of the footprint that a cone of width `width` around the direction `d` leaves on
/// the plane with normal `n` through the hit: its two boundary rays, `width` apart across `d` in
/// the plane of `d` and `n`, intersected with the plane.
fn slanted_footprint(width: f64, n: DVec3, d: DVec3) -> f64 {
    let across = (n - d * n.dot(d))
        .try_normalize()
        .unwrap_or_else(|| d.any_orthonormal_vector());
    let hit = |side: f64| plane_hit(across * (side * 0.5 * width), d, DVec3::ZERO, n);
    (hit(1.0) - hit(-1.0)).length()
}

/// The relative error of `|dot(n, d)|` in f32 against the cosine of the unit vectors' angle: the
/// dot product's rounding (`gamma(3)` of its terms) and the inputs' distance from unit length.
fn cosine_error(n: Vec3, d: Vec3) -> f64 {
    let terms = (n.as_dvec3() * d.as_dvec3()).abs().element_sum();
    let cosine = n.as_dvec3().normalize().dot(d.as_dvec3().normalize()).abs();
    gamma(3) * terms / cosine + unit_excess(n, d)
}

/// `rf_world_footprint`.
pub(in crate::ray_cone) fn world_footprint() -> Reference<(RayCone, f32, Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the two boundary rays of the cone's cross-section at the hit (width |w + s t|, in the plane of incidence) intersected with the surface: |w + s t| / |cos|",
        || {
            let spread = prop_oneof![Just(0.0f64), signed_log(-5.0, -1.0)];
            (signed_log(-4.0, 1.0), spread, log_uniform(-2.0, 3.0), surface_hit()).boxed()
        },
        |&(w, s, t, (n, d)), world_footprint| {
            let (cone, t32, n32, d32) = (
                RayCone {
                    width: w as f32,
                    spread_angle: s as f32,
                },
                t as f32,
                n.as_vec3(),
                d.as_vec3(),
            );
            let got = world_footprint((cone, t32, n32, d32));
            let (w, s, t) = (f64::from(cone.width), f64::from(cone.spread_angle), f64::from(t32));
            let (n, d) = (n32.as_dvec3().normalize(), d32.as_dvec3().normalize());
            let exact = slanted_footprint(w + s * t, n, d);
            // The width's rounding over |cos|; the cosine's relative error and the division's.
            let bound = width_rounding(w, s, t) / n.dot(d).abs() + (cosine_error(n32, d32) + gamma(1)) * exact;
            Some(Deviation::within(f64::from(got), exact, 1.01 * bound))
        },
    )
}

/// The arguments of `rf_two_section_width`: tangential width, sagittal width, sagittal axis,
/// normal, direction.
type TwoSectionArgs = (f32, f32, Vec3, Vec3, Vec3);

/// A two-section beam meeting a surface: widths from 1e-4 to 10 of either sign, a unit normal,
/// a unit direction meeting it at `|cos|` from 0.05 to 1, and the sagittal axis: a unit vector
/// across the ray turned by `turn` from the plane of incidence's normal `cross(d, n)`.
fn two_section_beam() -> BoxedStrategy<(f64, f64, f64, DVec3, DVec3)> {
    (
        signed_log(-4.0, 1.0),
        signed_log(-4.0, 1.0),
        0.0f64..6.3,
        unit(),
        0.05f64..1.0,
        0.0f64..6.3,
    )
        .prop_map(|(tangential, sagittal, turn, n, cosine, angle)| {
            (tangential, sagittal, turn, n, towards(n, cosine, angle))
        })
        .boxed()
}

/// The unit vectors across `d` (unit) that a turn of `turn` from `cross(d, n)` gives: the sagittal
/// axis and the tangential one, `cross(sagittal, d)`.
fn section_axes(n: DVec3, d: DVec3, turn: f64) -> (DVec3, DVec3) {
    let first = d
        .cross(n)
        .try_normalize()
        .unwrap_or_else(|| d.any_orthonormal_vector());
    let second = first.cross(d);
    let sagittal = first * turn.cos() + second * turn.sin();
    (sagittal, sagittal.cross(d))
}

/// The longer semi-axis of the footprint that the rays `p(phi) + s d` leave on the plane through
/// the origin with normal `n`, `p(phi) = a cos phi + b sin phi` across `d`: each ray intersected
/// with the plane ([`plane_hit`]), the distance from the origin maximized over `phi` by 3,600
/// samples and a ternary search about the best one (the distance squared is a sinusoid of
/// `2 phi`, with one maximum in every half turn).
fn sampled_longer_axis(a: DVec3, b: DVec3, n: DVec3, d: DVec3) -> f64 {
    let reach = |phi: f64| plane_hit(a * phi.cos() + b * phi.sin(), d, DVec3::ZERO, n).length();
    let step = PI / 3600.0;
    let (best, _) = (0..3600)
        .map(|k| f64::from(k) * step)
        .map(|phi| (phi, reach(phi)))
        .max_by(|x, y| x.1.total_cmp(&y.1))
        .unwrap_or((0.0, 0.0));
    let (mut low, mut high) = (best - step, best + step);
    for _ in 0..100 {
        let (left, right) = (low + (high - low) / 3.0, high - (high - low) / 3.0);
        if reach(left) < reach(right) {
            low = left;
        } else {
            high = right;
        }
    }
    reach(0.5 * (low + high))
}

/// The relative error of `rf_two_section_width` for the unit normal and direction `n`, `d`: the
/// f32 axis is off the exact one by its rounding (u), the unit inputs by theirs (`unit_excess`);
/// every term of the eigenvalue is at most twice the eigenvalue, so the evaluation's twenty-odd
/// roundings stay within 24 u of it, except the tilts' (`n . t`), whose absolute error (4 u)
/// becomes `4 u |tilt| / lambda <= 4 u / c` relative once squared; the square roots halve what is
/// left.
fn two_section_error(n: Vec3, d: Vec3) -> f64 {
    let cosine = n.as_dvec3().normalize().dot(d.as_dvec3().normalize()).abs();
    (24.0 + 8.0 / cosine) * U + 4.0 * unit_excess(n, d)
}

/// `rf_two_section_width`: the ellipse's rays intersected with the surface.
pub(in crate::ray_cone) fn two_section_width_sampled() -> Reference<TwoSectionArgs, f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the beam's rays around its two sections (a = w_t t, b = w_s s across the ray) each intersected with the surface in f64, the longest distance from the hit found by sampling and a ternary search; times |cos|",
        two_section_beam,
        |&(tangential, sagittal, turn, n, d), two_section_width| {
            let (sagittal_axis, _) = section_axes(n, d, turn);
            let args = (tangential as f32, sagittal as f32, sagittal_axis.as_vec3(), n.as_vec3(), d.as_vec3());
            let got = two_section_width(args);
            let (n, d) = (args.3.as_dvec3().normalize(), args.4.as_dvec3().normalize());
            let (sagittal_axis, tangential_axis) = section_axes(n, d, turn);
            let (w_t, w_s) = (f64::from(args.0), f64::from(args.1));
            let exact = n.dot(d).abs() * sampled_longer_axis(tangential_axis * w_t, sagittal_axis * w_s, n, d);
            // 1.01 for the search's own error.
            let relative = two_section_error(args.3, args.4);
            Some(Deviation::within(f64::from(got), exact, 1.01 * relative * exact))
        },
    )
}

/// `rf_two_section_width`: what a round beam, a head-on beam and the same beam described the
/// other way round give.
pub(in crate::ray_cone) fn two_section_width_limits() -> Reference<TwoSectionArgs, f32> {
    Reference::new(
        Kind::Identity,
        "equal widths are a round cone (|w| at any slant); head on the larger width; the sections swapped with the axis turned a quarter turn are the same beam, the same width",
        two_section_beam,
        |&(tangential, sagittal, turn, n, d), two_section_width| {
            let (sagittal_axis, tangential_axis) = section_axes(n, d, turn);
            let (n32, d32, w_t, w_s) = (n.as_vec3(), d.as_vec3(), tangential as f32, sagittal as f32);
            let round = two_section_width((w_t, w_t, sagittal_axis.as_vec3(), n32, d32));
            let head_on = two_section_width((w_t, w_s, sagittal_axis.as_vec3(), n32, -n32));
            let given = two_section_width((w_t, w_s, sagittal_axis.as_vec3(), n32, d32));
            let swapped = two_section_width((w_s, w_t, tangential_axis.as_vec3(), n32, d32));
            // Twice the error for the swap (both sides round); head on every tilt is within 4 u
            // of 0.
            let relative = two_section_error(n32, d32);
            let larger = f64::from(w_t.abs().max(w_s.abs()));
            let round = Deviation::within(f64::from(round), f64::from(w_t.abs()), relative * f64::from(w_t.abs()));
            let head_on = Deviation::within(f64::from(head_on), larger, 32.0 * U * larger);
            let swap = Deviation::within(f64::from(swapped), f64::from(given), 2.0 * relative * f64::from(given));
            Some(round.and(head_on).and(swap))
        },
    )
}

/// `rf_triangle_world_area2`.
pub(in crate::ray_cone) fn triangle_world_area2() -> Reference<(Vec3, Vec3, Vec3), f32> {
    Reference::new(
        Kind::ClosedForm,
        "Heron's formula (Kahan's stable form) from the three side lengths in f64, over ordinary, huge, tiny, sliver and degenerate triangles",
        triangle,
        |&[p0, p1, p2], triangle_world_area2| {
            let got = triangle_world_area2((p0, p1, p2));
            let exact = heron_area2([p0, p1, p2].map(Vec3::as_dvec3));
            // The edges round (u each, 2 u |e1| |e2| in the cross product), each cross component
            // a b - c d by gamma(2) (|a b| + |c d|) (at most sqrt(2) gamma(2) |e1| |e2| in all),
            // the scaled length by gamma(5) of the result.
            let (e1, e2) = ((p1 - p0).as_dvec3(), (p2 - p0).as_dvec3());
            let bound = gamma(6) * (e1.length() * e2.length() + exact);
            Some(Deviation::within(f64::from(got), exact, bound))
        },
    )
}

/// `rf_triangle_uv_area2`.
pub(in crate::ray_cone) fn triangle_uv_area2() -> Reference<(Vec2, Vec2, Vec2), f32> {
    Reference::new(
        Kind::ClosedForm,
        "the shoelace formula over the three corners in f64, |x0 (y1 - y2) + x1 (y2 - y0) + x2 (y0 - y1)|",
        uv_triangle,
        |&[a, b, c], triangle_uv_area2| {
            let got = triangle_uv_area2((a, b, c));
            let [a, b, c] = [a, b, c].map(Vec2::as_dvec2);
            let exact = (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y)).abs();
            // The edges round (2 u |g1| |g2|), the cross product by gamma(2) of its terms.
            let bound = gamma(4) * (b - a).length() * (c - a).length()
                + 8.0 * f64::EPSILON * (a.length() + b.length() + c.length()).powi(2);
            Some(Deviation::within(f64::from(got), exact, bound))
        },
    )
}

/// How far a doubled triangle area moves when its corners move by `deltas`, the sides opposite
/// them being `sides` long: `sum delta_i side_i + 3 max delta^2` (each corner moves the area by at
/// most its displacement times the opposite side, and the products of two displacements add the
/// rest).
fn moved(deltas: [f64; 3], sides: [f64; 3]) -> f64 {
    let largest = deltas.iter().copied().fold(0.0, f64::max);
    deltas.iter().zip(sides).map(|(d, side)| d * side).sum::<f64>() + 3.0 * largest * largest
}

/// A triangle in a random plane mapped to UV by the affine map `uv = M q + o` of its in-plane
/// coordinates `q`: its texel density is `sqrt(|det M|)` whatever the triangle.
#[derive(Clone, Debug)]
struct Mapped {
    points: [DVec3; 3],
    uvs: [DVec2; 3],
    map: DMat2,
}

impl Mapped {
    fn strategy() -> BoxedStrategy<Mapped> {
        let corner = || (-1.0f64..1.0, -1.0f64..1.0).prop_map(|(x, y)| DVec2::new(x, y));
        let entry = || prop_oneof![4 => -2.0f64..2.0, 1 => signed_log(-3.0, 3.0)];
        (
            (corner(), corner(), corner()),
            log_uniform(-3.0, 3.0),
            (
                (-10.0f64..10.0, -10.0f64..10.0, -10.0f64..10.0),
                unit(),
                0.0f64..6.3,
            ),
            (entry(), entry(), entry(), entry()),
            (-5.0f64..5.0, -5.0f64..5.0),
        )
            .prop_map(
                |((a, b, c), size, ((x, y, z), normal, angle), (m00, m01, m10, m11), (ox, oy))| {
                    // The triangle lies within 10 of its own size from the origin, its UVs within 5
                    // of their own size: every input keeps its precision relative to the triangle.
                    let u = crate::exact::tangent(normal, angle);
                    let v = normal.cross(u);
                    let centre = DVec3::new(x, y, z) * size;
                    let q = [a, b, c].map(|q| q * size);
                    let map = DMat2::from_cols(DVec2::new(m00, m10), DVec2::new(m01, m11));
                    let uv_size = size * (m00.abs() + m01.abs() + m10.abs() + m11.abs());
                    Mapped {
                        points: q.map(|q| centre + u * q.x + v * q.y),
                        uvs: q.map(|q| map * q + DVec2::new(ox, oy) * uv_size),
                        map,
                    }
                },
            )
            .prop_filter("a triangle of (nearly) no area", |mapped| {
                let edges = |p: [DVec3; 3]| (p[1] - p[0]).length() * (p[2] - p[0]).length();
                heron_area2(mapped.points) > 1.0e-3 * edges(mapped.points)
                    && mapped.map.determinant().abs()
                        > 1.0e-3 * mapped.map.to_cols_array().iter().map(|m| m * m).sum::<f64>()
            })
            .boxed()
    }

    /// The f32 arguments: corners and UVs.
    fn arguments(&self) -> (Vec3, Vec3, Vec3, Vec2, Vec2, Vec2) {
        let [p0, p1, p2] = self.points.map(DVec3::as_vec3);
        let [t0, t1, t2] = self.uvs.map(DVec2::as_vec2);
        (p0, p1, p2, t0, t1, t2)
    }

    /// The exact doubled areas `(uv, world)` and the bounds of the f32 ones' errors: the corners
    /// rounded to f32 move a doubled area by at most `sum |delta_i| |opposite edge_i| + 3 max
    /// |delta|^2`, and the mirror's own rounding adds `gamma(6) (|e1| |e2| + area)` (world, as in
    /// `triangle_world_area2`) or `gamma(4) |g1| |g2|` (UV).
    fn areas(&self) -> ((f64, f64), (f64, f64)) {
        let (p0, p1, p2, t0, t1, t2) = self.arguments();
        let world = heron_area2(self.points);
        let uv = (self.map.determinant() * world).abs();
        let world_moved = moved(
            [0, 1, 2].map(|i| ([p0, p1, p2][i].as_dvec3() - self.points[i]).length()),
            [0, 1, 2].map(|i| (self.points[(i + 2) % 3] - self.points[(i + 1) % 3]).length()),
        );
        let uv_moved = moved(
            [0, 1, 2].map(|i| ([t0, t1, t2][i].as_dvec2() - self.uvs[i]).length()),
            [0, 1, 2].map(|i| (self.uvs[(i + 2) % 3] - self.uvs[(i + 1) % 3]).length()),
        );
        let e = (self.points[1] - self.points[0]).length() * (self.points[2] - self.points[0]).length();
        let g = (self.uvs[1] - self.uvs[0]).length() * (self.uvs[2] - self.uvs[0]).length();
        (
            (uv, uv_moved + gamma(4) * g),
            (world, world_moved + gamma(6) * (e + world)),
        )
    }

    /// The largest change of `f(uv_area2, world_area2)` with each area moved within its error;
    /// `f` is monotonic in each, so at the corners.
    fn corners(&self, f: impl Fn(f64, f64) -> f64) -> f64 {
        let ((uv, uv_error), (world, world_error)) = self.areas();
        let centre = f(uv, world);
        [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)]
            .iter()
            .map(|(a, b)| {
                (f((uv + a * uv_error).max(0.0), (world + b * world_error).max(0.0)) - centre).abs()
            })
            .fold(0.0, f64::max)
    }
}

/// `rf_texel_density`.
pub(in crate::ray_cone) fn texel_density() -> Reference<(Vec3, Vec3, Vec3, Vec2, Vec2, Vec2), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "triangles in random planes mapped to UV by a known affine map M of their in-plane coordinates: the density is sqrt(|det M|), whatever the triangle",
        Mapped::strategy,
        |mapped, texel_density| {
            let got = texel_density(mapped.arguments());
            let expected = mapped.map.determinant().abs().sqrt();
            // The areas within their errors; two square roots and a division (gamma(3)).
            let bound = mapped.corners(|uv, world| (uv / world).sqrt()) + gamma(3) * expected;
            Some(Deviation::within(f64::from(got), expected, 1.01 * bound))
        },
    )
}

/// `rf_triangle_base_lod`.
pub(in crate::ray_cone) fn triangle_base_lod() -> Reference<(Vec3, Vec3, Vec3, Vec2, Vec2, Vec2), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "triangles in random planes mapped to UV by a known affine map M: the base LOD is log2(sqrt(|det M|)) = 0.5 log2 |det M| (RTG Eq. 4)",
        Mapped::strategy,
        |mapped, triangle_base_lod| {
            let got = triangle_base_lod(mapped.arguments());
            let expected = 0.5 * mapped.map.determinant().abs().log2();
            // The areas within their errors; each log2 within 2 ULP of its result (4 u), the
            // difference rounds once, the halving is exact.
            let ((uv, _), (world, _)) = mapped.areas();
            let logs = uv.log2().abs() + world.log2().abs();
            let bound = mapped.corners(|uv, world| 0.5 * (uv.log2() - world.log2())) + gamma(5) * logs;
            Some(Deviation::within(f64::from(got), expected, 1.01 * bound))
        },
    )
}

/// `rf_texture_lod`.
pub(in crate::ray_cone) fn texture_lod() -> Reference<(f32, f32, Vec2, Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the log2 of the cone's slanted footprint in texels: its boundary rays intersected with the surface, |w| / |cos|, times the density 2^base_lod and sqrt(W H) (RTG Eq. 34)",
        || {
            let side = || prop_oneof![(1u32..16384).prop_map(f64::from), 1.0f64..16384.0];
            (-10.0f64..10.0, signed_log(-6.0, 1.0), (side(), side()), surface_hit()).boxed()
        },
        |&(base, w, (width, height), (n, d)), texture_lod| {
            let (base, w, size, n32, d32) = (base as f32, w as f32, DVec2::new(width, height).as_vec2(), n.as_vec3(), d.as_vec3());
            let got = texture_lod((base, w, size, n32, d32));
            let (n, d) = (n32.as_dvec3().normalize(), d32.as_dvec3().normalize());
            let footprint = slanted_footprint(f64::from(w), n, d);
            let texels = footprint * f64::from(base).exp2() * (f64::from(size.x) * f64::from(size.y)).sqrt();
            let expected = texels.log2();
            // Each log2 within 2 ULP of its result (4 u); the cosine's relative error through
            // log2 (over ln 2); four sums and a halving round within gamma(4) of the terms.
            let logs = [f64::from(w).abs().log2(), f64::from(size.x).log2(), f64::from(size.y).log2(), n.dot(d).abs().log2()];
            let terms = f64::from(base).abs() + logs.iter().map(|l| l.abs()).sum::<f64>();
            let bound = gamma(4) * terms + 4.0 * U * terms + 1.01 * cosine_error(n32, d32) / LN_2;
            Some(Deviation::within(f64::from(got), expected, bound))
        },
    )
}

/// `rf_texture_gradient`.
pub(in crate::ray_cone) fn texture_gradient() -> Reference<(f32, f32), f32> {
    Reference::new(
        Kind::ClosedForm,
        "the diameter of the UV footprint circle, |footprint|, times max(tex_grad_scale, 0): mip 0 for a scale of 0 or below",
        || (signed_log(-6.0, 3.0), prop_oneof![-1.0f64..4.0, Just(0.0), Just(1.0)]).boxed(),
        |&(footprint, scale), texture_gradient| {
            let (footprint, scale) = (footprint as f32, scale as f32);
            let got = texture_gradient((footprint, scale));
            let expected = f64::from(footprint).abs() * f64::from(scale).max(0.0);
            Some(Deviation::within(f64::from(got), expected, U * expected))
        },
    )
}

/// `rf_environment_lod`.
pub(in crate::ray_cone) fn environment_lod() -> Reference<(f32, f32), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the latitudes of a cone's two boundary rays in its vertical plane (atan2 of the f64 directions): the log2 of the texel rows of pi / H between them on a latitude-longitude map",
        || (signed_log(-6.0, 0.0), 1.0f64..8192.0, -1.0f64..1.0, 0.0f64..6.3).boxed(),
        |&(spread, height, latitude, azimuth), environment_lod| {
            let (spread, height) = (spread as f32, height as f32);
            let got = environment_lod((spread, height));
            let (s, h) = (f64::from(spread), f64::from(height));
            // The central direction's latitude keeps both boundary rays off the poles.
            let centre = latitude * (0.5 * PI - 0.5 * s.abs() - 1.0e-3);
            let boundary = |side: f64| {
                let phi = centre + side * 0.5 * s;
                DVec3::new(phi.cos() * azimuth.cos(), phi.sin(), phi.cos() * azimuth.sin())
            };
            let latitude_of = |v: DVec3| v.y.atan2(DVec2::new(v.x, v.z).length());
            let rows = (latitude_of(boundary(1.0)) - latitude_of(boundary(-1.0))).abs() / (PI / h);
            let expected = rows.log2();
            // |s| H / pi: two roundings and f32's pi (within u / 2); log2 within 2 ULP (4 u).
            let bound = gamma(3) / LN_2 + 4.0 * U * expected.abs() + 1.0e-12;
            Some(Deviation::within(f64::from(got), expected, bound))
        },
    )
}
