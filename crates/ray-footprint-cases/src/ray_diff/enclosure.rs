//! Interval enclosures of the ray_diff functions: each function here re-evaluates the shader
//! function of its name (or a step of one) in interval arithmetic, in the same order of operations
//! as `src/ray_diff.rs`, widening after each operation by the rounding error that Vulkan's
//! precision rules allow the device (and that the mirror makes). The width of the result is the
//! record's tolerance. Also here:
//! the conditioning tests that keep a check to inputs whose enclosure says something
//! ([`WELL_CONDITIONED`]).

use super::{BarycentricArgs, Camera, ConeGradientArgs, GBufferArgs, Matrices, OffsetArgs};
use glam::{Mat4, Vec2, Vec3, Vec4Swizzles};
use ray_footprint::ray_diff::{
    Derivatives2, Derivatives3, GBufferSample, RayDiff, DIFF_MAX_FOV_Y, DIFF_MAX_SHARPNESS, DIFF_MAX_VALUE,
    DIFF_MIN_COS, DIFF_MIN_MAGNITUDE, DIFF_MIN_SINE,
};
use shader_proptest::interval::{
    interval2, interval3, mat_vec, Interval, Interval2, Interval3, IntervalVec, F32,
};

fn zero3() -> Interval3 {
    IntervalVec([Interval::c(0.0); 3])
}

/// A `RayDiff`'s 16 components, pads exactly 0.
fn ray_diff(o_dx: Interval3, o_dy: Interval3, d_dx: Interval3, d_dy: Interval3) -> Vec<Interval> {
    [o_dx, o_dy, d_dx, d_dy]
        .iter()
        .flat_map(|v| v.components().into_iter().chain([Interval::c(0.0)]))
        .collect()
}

pub(super) fn derivatives2(dx: Interval2, dy: Interval2) -> Vec<Interval> {
    [dx.components(), dy.components()].concat()
}

pub(super) fn derivatives3(dx: Interval3, dy: Interval3) -> Vec<Interval> {
    [dx.components(), dy.components()].concat()
}

fn eye_ray_extent(image_size: Vec2, fov_y: f32) -> Interval2 {
    let size = image_size.max(Vec2::ONE);
    let f = Interval::tan_exact(0.5 * fov_y.clamp(0.0, DIFF_MAX_FOV_Y));
    IntervalVec([Interval::exact(size.x) / Interval::exact(size.y) * f, f])
}

fn pixel_ndc(pixel: Vec2, image_size: Vec2) -> Interval2 {
    let size = image_size.max(Vec2::ONE);
    IntervalVec(std::array::from_fn(|i| {
        (Interval::exact(pixel[i]) + Interval::c(0.5)) / Interval::exact(size[i]) * Interval::c(2.0)
            - Interval::c(1.0)
    }))
}

pub(super) fn eye_ray_direction(&(pixel, size, fov, right, up, view): &Camera) -> Interval3 {
    let c = pixel_ndc(pixel, size);
    let extent = eye_ray_extent(size, fov);
    interval3(right) * (c.0[0] * extent.0[0]) - interval3(up) * (c.0[1] * extent.0[1]) - interval3(view)
}

pub(super) fn normalized_derivative(v: Interval3, dv: Interval3) -> Interval3 {
    let length2 = v.dot(v).max_c(f64::from(DIFF_MIN_MAGNITUDE));
    (dv - v * (v.dot(dv) / length2)) / length2.sqrt()
}

/// The direction differentials of `eye_ray_diff` (its origin differentials are exactly 0).
pub fn eye_ray_direction_derivatives(camera: &Camera) -> (Interval3, Interval3) {
    let &(_, image_size, fov, right, up, _) = camera;
    let d = eye_ray_direction(camera);
    let size = image_size.max(Vec2::ONE);
    let extent = eye_ray_extent(image_size, fov);
    let dd_dx = interval3(right) * (Interval::c(2.0) * extent.0[0] / Interval::exact(size.x));
    let dd_dy = interval3(up) * -(Interval::c(2.0) * extent.0[1] / Interval::exact(size.y));
    (normalized_derivative(d, dd_dx), normalized_derivative(d, dd_dy))
}

pub(super) fn eye_ray_diff(camera: &Camera) -> Vec<Interval> {
    let (dd_dx, dd_dy) = eye_ray_direction_derivatives(camera);
    ray_diff(zero3(), zero3(), dd_dx, dd_dy)
}

fn safe_normalize(v: Interval3) -> Interval3 {
    v / v.dot(v).max_c(f64::from(DIFF_MIN_MAGNITUDE)).sqrt()
}

fn matrix_ray_direction(ndc: Interval2, view_inv: Mat4, proj_inv: Mat4) -> Interval3 {
    let far_point = mat_vec(
        proj_inv,
        IntervalVec([ndc.0[0], ndc.0[1], Interval::c(1.0)]),
        Interval::c(1.0),
        F32,
    );
    mat_vec(view_inv, safe_normalize(far_point), Interval::c(0.0), F32)
}

pub(super) fn eye_ray_direction_from_matrices(&(pixel, size, view_inv, proj_inv): &Matrices) -> Interval3 {
    matrix_ray_direction(pixel_ndc(pixel, size), view_inv, proj_inv)
}

pub(super) fn eye_ray_diff_from_matrices(
    &(pixel, image_size, view_inv, proj_inv): &Matrices,
) -> Vec<Interval> {
    let size = image_size.max(Vec2::ONE);
    let ndc = pixel_ndc(pixel, image_size);
    let far_point = mat_vec(
        proj_inv,
        IntervalVec([ndc.0[0], ndc.0[1], Interval::c(1.0)]),
        Interval::c(1.0),
        F32,
    );
    let dfar_dx = interval3(proj_inv.x_axis.xyz()) * (Interval::c(2.0) / Interval::exact(size.x));
    let dfar_dy = interval3(proj_inv.y_axis.xyz()) * (Interval::c(2.0) / Interval::exact(size.y));
    let dd_dx = mat_vec(
        view_inv,
        normalized_derivative(far_point, dfar_dx),
        Interval::c(0.0),
        F32,
    );
    let dd_dy = mat_vec(
        view_inv,
        normalized_derivative(far_point, dfar_dy),
        Interval::c(0.0),
        F32,
    );
    ray_diff(zero3(), zero3(), dd_dx, dd_dy)
}

pub(super) fn pixel_directions(&(pixel, size, view_inv, proj_inv): &Matrices) -> Vec<Interval> {
    let ndc = pixel_ndc(pixel, size);
    let next = pixel_ndc(pixel + 1.0, size);
    let right = matrix_ray_direction(IntervalVec([next.0[0], ndc.0[1]]), view_inv, proj_inv);
    let below = matrix_ray_direction(IntervalVec([ndc.0[0], next.0[1]]), view_inv, proj_inv);
    derivatives3(right, below)
}

/// One origin differential transferred to the plane at `t` with normal `normal`; the differential
/// comes as intervals (from earlier operations), the ray and the plane are exact.
pub fn transferred_origin(
    d_origin: Interval3,
    d_direction: Interval3,
    direction: Vec3,
    t: f32,
    normal: Vec3,
) -> Interval3 {
    let cosine = interval3(direction).dot(interval3(normal));
    let q = d_origin + d_direction * Interval::exact(t);
    let dt = (-q.dot(interval3(normal))).div_away(cosine, f64::from(DIFF_MIN_COS));
    q + interval3(direction) * dt
}

pub(super) fn transfer(&(diff, direction, t, normal): &(RayDiff, Vec3, f32, Vec3)) -> Vec<Interval> {
    ray_diff(
        transferred_origin(
            interval3(diff.d_origin_dx),
            interval3(diff.d_direction_dx),
            direction,
            t,
            normal,
        ),
        transferred_origin(
            interval3(diff.d_origin_dy),
            interval3(diff.d_direction_dy),
            direction,
            t,
            normal,
        ),
        interval3(diff.d_direction_dx),
        interval3(diff.d_direction_dy),
    )
}

/// `x / k` clamped to `DIFF_MAX_VALUE`, `k` clamped away from 0 to `DIFF_MIN_MAGNITUDE`.
fn barycentric_quotient(numerator: Interval, k: Interval) -> Interval {
    let max = f64::from(DIFF_MAX_VALUE);
    numerator
        .div_away(k, f64::from(DIFF_MIN_MAGNITUDE))
        .clamp_c(-max, max)
}

pub(super) fn barycentric_derivatives(&(diff, direction, t, p0, p1, p2): &BarycentricArgs) -> Vec<Interval> {
    let d = interval3(direction);
    let e1 = interval3(p1) - interval3(p0);
    let e2 = interval3(p2) - interval3(p0);
    let k = determinant(d, interval3(p0), interval3(p1), interval3(p2));
    let cu = e2.cross(d);
    let cv = d.cross(e1);
    let q = interval3(diff.d_origin_dx) + interval3(diff.d_direction_dx) * Interval::exact(t);
    let r = interval3(diff.d_origin_dy) + interval3(diff.d_direction_dy) * Interval::exact(t);
    let quotient = |n: Interval| barycentric_quotient(n, k);
    derivatives2(
        IntervalVec([quotient(cu.dot(q)), quotient(cv.dot(q))]),
        IntervalVec([quotient(cu.dot(r)), quotient(cv.dot(r))]),
    )
}

pub(super) fn texture_derivatives(b: Derivatives2, t0: Vec2, t1: Vec2, t2: Vec2) -> (Interval2, Interval2) {
    let g1 = interval2(t1) - interval2(t0);
    let g2 = interval2(t2) - interval2(t0);
    (
        g1 * Interval::exact(b.dx.x) + g2 * Interval::exact(b.dx.y),
        g1 * Interval::exact(b.dy.x) + g2 * Interval::exact(b.dy.y),
    )
}

pub(super) fn secondary_origin_derivatives(
    &(b, p0, p1, p2): &(Derivatives2, Vec3, Vec3, Vec3),
) -> Vec<Interval> {
    let e1 = interval3(p1) - interval3(p0);
    let e2 = interval3(p2) - interval3(p0);
    derivatives3(
        e1 * Interval::exact(b.dx.x) + e2 * Interval::exact(b.dx.y),
        e1 * Interval::exact(b.dy.x) + e2 * Interval::exact(b.dy.y),
    )
}

pub(super) fn lod_isotropic(g: Derivatives2) -> Interval {
    let rho2 = interval2(g.dx)
        .dot(interval2(g.dx))
        .max(interval2(g.dy).dot(interval2(g.dy)));
    Interval::c(0.5) * rho2.max_c(f64::from(DIFF_MIN_MAGNITUDE)).log2()
}

pub(super) fn lod_box(g: Derivatives2) -> Interval {
    let extent = interval2(g.dx).abs() + interval2(g.dy).abs();
    extent.0[0]
        .max(extent.0[1])
        .max_c(f64::from(DIFF_MIN_MAGNITUDE))
        .log2()
}

type NormalArgs = (Vec3, Vec3, Vec3, Vec2, Derivatives2);

pub(super) fn normal_derivatives(&(n0, n1, n2, uv, b): &NormalArgs) -> Vec<Interval> {
    let (n0, n1, n2) = (interval3(n0), interval3(n1), interval3(n2));
    let n = n0 * (Interval::c(1.0) - Interval::exact(uv.x) - Interval::exact(uv.y))
        + n1 * Interval::exact(uv.x)
        + n2 * Interval::exact(uv.y);
    let dn_dx = (n1 - n0) * Interval::exact(b.dx.x) + (n2 - n0) * Interval::exact(b.dx.y);
    let dn_dy = (n1 - n0) * Interval::exact(b.dy.x) + (n2 - n0) * Interval::exact(b.dy.y);
    derivatives3(normalized_derivative(n, dn_dx), normalized_derivative(n, dn_dy))
}

/// One direction differential reflected at a hit; the differentials come as intervals, the ray
/// and the normal are exact.
pub fn reflected_direction(dd: Interval3, direction: Vec3, normal: Vec3, dn: Interval3) -> Interval3 {
    let (d, n) = (interval3(direction), interval3(normal));
    let cosine = d.dot(n);
    dd - (dn * cosine + n * (dd.dot(n) + d.dot(dn))) * Interval::c(2.0)
}

type ReflectArgs = (RayDiff, Vec3, Vec3, Derivatives3);

pub(super) fn reflect_ray_diff(&(diff, direction, normal, dn): &ReflectArgs) -> Vec<Interval> {
    ray_diff(
        interval3(diff.d_origin_dx),
        interval3(diff.d_origin_dy),
        reflected_direction(
            interval3(diff.d_direction_dx),
            direction,
            normal,
            interval3(dn.dx),
        ),
        reflected_direction(
            interval3(diff.d_direction_dy),
            direction,
            normal,
            interval3(dn.dy),
        ),
    )
}

type RefractArgs = (RayDiff, Vec3, Vec3, Derivatives3, f32);

/// The refracted branch, for the part of `k`'s interval that is `>= 0`.
fn refracted(&(diff, direction, normal, dn, eta): &RefractArgs, k: Interval) -> Vec<Interval> {
    let (d, n, eta) = (interval3(direction), interval3(normal), Interval::exact(eta));
    let cosine = d.dot(n);
    let root = Interval {
        lo: k.lo.max(0.0),
        ..k
    }
    .sqrt();
    // A magnitude with the sign of `cosine`: both signs where `cosine` straddles 0.
    let with_cosine_sign = |magnitude: Interval| {
        if cosine.hi <= 0.0 {
            -magnitude
        } else if cosine.lo > 0.0 {
            magnitude
        } else {
            magnitude.hull(-magnitude)
        }
    };
    let transmitted_cos = with_cosine_sign(root);
    let mu = eta * cosine - transmitted_cos;
    let clamped_cos = with_cosine_sign(root.max_c(f64::from(DIFF_MIN_COS)));
    let rate = eta - (eta * eta * cosine).div_away(clamped_cos, f64::from(DIFF_MIN_COS));
    let refracted = |dd: Vec3, dnormal: Vec3| {
        let (dd, dnormal) = (interval3(dd), interval3(dnormal));
        let d_cos = dd.dot(n) + d.dot(dnormal);
        dd * eta - (dnormal * mu + n * (rate * d_cos))
    };
    ray_diff(
        interval3(diff.d_origin_dx),
        interval3(diff.d_origin_dy),
        refracted(diff.d_direction_dx, dn.dx),
        refracted(diff.d_direction_dy, dn.dy),
    )
}

/// `k = 1 - eta^2 (1 - dot(D, N)^2)`: negative for total internal reflection.
pub(super) fn refraction_determinant(&(_, direction, normal, _, eta): &RefractArgs) -> Interval {
    let cosine = interval3(direction).dot(interval3(normal));
    Interval::c(1.0) - Interval::exact(eta) * Interval::exact(eta) * (Interval::c(1.0) - cosine * cosine)
}

/// Either branch, or the hull of both (flag `[0, 1]`) when `k`'s sign is uncertain.
pub(super) fn refract_ray_diff(args: &RefractArgs) -> Vec<Interval> {
    let &(diff, direction, normal, dn, _) = args;
    let k = refraction_determinant(args);
    let reflected = || {
        [
            reflect_ray_diff(&(diff, direction, normal, dn)),
            vec![Interval::c(1.0)],
        ]
        .concat()
    };
    let refracted = || [refracted(args, k), vec![Interval::c(0.0)]].concat();
    if k.hi < 0.0 {
        reflected()
    } else if k.lo >= 0.0 {
        refracted()
    } else {
        reflected()
            .into_iter()
            .zip(refracted())
            .map(|(a, b)| a.hull(b))
            .collect()
    }
}

/// The neighbour choice, in f32 exactly as the device makes it (a correctly rounded subtraction and
/// comparisons: no rounding freedom).
fn use_backward(
    center: GBufferSample,
    forward: GBufferSample,
    backward: GBufferSample,
    epsilon: f32,
) -> bool {
    let forward_step = (forward.distance - center.distance).abs();
    let backward_step = (backward.distance - center.distance).abs();
    forward_step > epsilon && backward_step < forward_step
}

fn gbuffer_steps(start: GBufferSample, end: GBufferSample) -> (Interval3, Interval3) {
    let reflect = |g: GBufferSample| {
        let (e, n) = (interval3(g.eye_direction), interval3(g.normal));
        e - n * (Interval::c(2.0) * n.dot(e))
    };
    (
        interval3(end.eye_direction) * Interval::exact(end.distance)
            - interval3(start.eye_direction) * Interval::exact(start.distance),
        reflect(end) - reflect(start),
    )
}

pub(super) fn gbuffer_ray_diff(&(center, right, left, below, above, epsilon): &GBufferArgs) -> Vec<Interval> {
    let pair = |forward, backward| {
        if use_backward(center, forward, backward, epsilon) {
            gbuffer_steps(backward, center)
        } else {
            gbuffer_steps(center, forward)
        }
    };
    let (x, y) = (pair(right, left), pair(below, above));
    ray_diff(x.0, y.0, x.1, y.1)
}

pub(super) fn tangent_plane_offset(rd: Vec3, rd_neighbour: Vec3, t: f32, normal: Vec3) -> Interval3 {
    let (rd, rdn, n) = (interval3(rd), interval3(rd_neighbour), interval3(normal));
    let ratio = rd.dot(n).div_away(rdn.dot(n), f64::from(DIFF_MIN_COS));
    (rdn * ratio - rd) * Interval::exact(t)
}

pub(super) fn triplanar_weights(normal: Vec3, sharpness: f32) -> Vec<Interval> {
    let k = sharpness.clamp(0.0, DIFF_MAX_SHARPNESS);
    let size = normal.abs();
    let largest = Interval::exact(size.x.max(size.y).max(size.z.max(DIFF_MIN_MAGNITUDE)));
    let m: [Interval; 3] = std::array::from_fn(|i| {
        (Interval::exact(size[i]) / largest)
            .max_c(f64::from(DIFF_MIN_MAGNITUDE))
            .pow(k)
    });
    let sum = (m[0] + m[1] + m[2]).max_c(f64::from(DIFF_MIN_MAGNITUDE));
    m.iter().map(|&x| x / sum).collect()
}

fn scaled_length(v: Interval3) -> Interval {
    let a = v.abs();
    let m = a.0[0]
        .max(a.0[1])
        .max(a.0[2].max_c(f64::from(DIFF_MIN_MAGNITUDE)));
    let unit = v / m;
    m * unit.dot(unit).sqrt()
}

/// The determinant `k = dot(cross(e1, e2), direction)` of a ray against a triangle's plane (RTG
/// Eq. 12-20): the divisor of every barycentric quotient.
pub(crate) fn determinant(direction: Interval3, p0: Interval3, p1: Interval3, p2: Interval3) -> Interval {
    (p1 - p0).cross(p2 - p0).dot(direction)
}

pub use crate::conditioning::{well_conditioned, WELL_CONDITIONED};

/// Why a ray against a triangle is left out of a check ([`determinant_well_conditioned`]).
pub(super) const PARALLEL_WITHIN_ROUNDING: &str =
    "the ray is parallel to the triangle's plane within rounding, or the \
     triangle a sliver (the determinant k is not known to 2^-10): the clamped quotients may take \
     either +-DIFF_MAX_VALUE";

/// Whether the determinant of `direction` against the triangle `p0 p1 p2` is well-conditioned
/// ([`WELL_CONDITIONED`]).
pub(super) fn determinant_well_conditioned(direction: Vec3, p0: Vec3, p1: Vec3, p2: Vec3) -> bool {
    well_conditioned(determinant(
        interval3(direction),
        interval3(p0),
        interval3(p1),
        interval3(p2),
    ))
}

/// Why a re-intersection is left out of a check ([`offsets_well_conditioned`]).
pub(super) const REINTERSECTION_ILL_CONDITIONED: &str =
    "a neighbour ray is parallel to the triangle's plane \
     within rounding, or its object-space direction is lost to the cancellation of a far origin \
     (not known to 2^-10): the clamped barycentrics may take either +-DIFF_MAX_VALUE";

pub(super) fn intersect_triangle_plane(
    origin: Interval3,
    direction: Interval3,
    p0: Interval3,
    p1: Interval3,
    p2: Interval3,
) -> Interval3 {
    plane_barycentrics(origin, direction, [p0, p1, p2], barycentric_quotient)
}

/// The barycentrics `(1 - u - v, u, v)` of the ray's hit on the plane of the triangle `p`, in the
/// arithmetic of the inputs (f32, or f64 for the `ray_diff_f64` module), in the order of
/// operations of `intersect_triangle_plane` (RTG Eq. 13): `u = dot(e2 x d, s0) / k` and
/// `v = dot(d x e1, s0) / k`, each divided by `quotient(numerator, k)`, the module's clamped
/// division.
pub(crate) fn plane_barycentrics(
    origin: Interval3,
    direction: Interval3,
    [p0, p1, p2]: [Interval3; 3],
    quotient: impl Fn(Interval, Interval) -> Interval,
) -> Interval3 {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let s0 = origin - p0;
    let k = determinant(direction, p0, p1, p2);
    let u = quotient(e2.cross(direction).dot(s0), k);
    let v = quotient(direction.cross(e1).dot(s0), k);
    // The exact 1 in the determinant's arithmetic.
    let one = Interval {
        lo: 1.0,
        hi: 1.0,
        p: k.p,
    };
    IntervalVec([one - u - v, u, v])
}

/// The object-space origin and the two neighbour directions of the re-intersection.
fn object_rays(&(w2o, origin, _, _, _, dir_x, dir_y, _): &OffsetArgs) -> (Interval3, Interval3, Interval3) {
    let transform = |p: Interval3| mat_vec(w2o, p, Interval::c(1.0), F32);
    let object_origin = transform(interval3(origin));
    let object_x = transform(interval3(origin) + interval3(dir_x)) - object_origin;
    let object_y = transform(interval3(origin) + interval3(dir_y)) - object_origin;
    (object_origin, object_x, object_y)
}

pub(super) fn barycentric_offsets(args: &OffsetArgs) -> (Interval3, Interval3) {
    let &(_, _, p0, p1, p2, _, _, hit) = args;
    let (object_origin, object_x, object_y) = object_rays(args);
    let (p0, p1, p2) = (interval3(p0), interval3(p1), interval3(p2));
    (
        intersect_triangle_plane(object_origin, object_x, p0, p1, p2) - interval3(hit),
        intersect_triangle_plane(object_origin, object_y, p0, p1, p2) - interval3(hit),
    )
}

/// Whether a direction is known to [`WELL_CONDITIONED`]: its widest component's enclosure is at
/// most that fraction of its largest component (an object-space neighbour direction is not, when
/// the origin is so far from the object that `T(O + d) - T(O)` cancels most of its bits).
pub fn direction_well_conditioned(direction: Interval3) -> bool {
    let width = direction.0.iter().map(|c| c.hi - c.lo).fold(0.0, f64::max);
    let magnitude = direction.0.iter().map(|c| c.magnitude()).fold(0.0, f64::max);
    width <= WELL_CONDITIONED * magnitude
}

/// Whether both neighbour rays' intersections are well-conditioned ([`WELL_CONDITIONED`]): the
/// object-space directions and their determinants against the triangle.
pub(super) fn offsets_well_conditioned(args: &OffsetArgs) -> bool {
    let &(_, _, p0, p1, p2, _, _, _) = args;
    let (_, object_x, object_y) = object_rays(args);
    let (p0, p1, p2) = (interval3(p0), interval3(p1), interval3(p2));
    [object_x, object_y]
        .iter()
        .all(|&d| direction_well_conditioned(d) && well_conditioned(determinant(d, p0, p1, p2)))
}

/// The enclosure of twice the area of the triangle `p0 p1 p2`, `|cross(p1 - p0, p2 - p0)|`.
fn doubled_area(p0: Interval3, p1: Interval3, p2: Interval3) -> Interval {
    scaled_length((p1 - p0).cross(p2 - p0))
}

/// Whether the doubled area of the triangle is known to [`WELL_CONDITIONED`] (an exact 0 is).
pub(super) fn area_well_conditioned(&(_, p0, p1, p2): &(f32, Vec3, Vec3, Vec3)) -> bool {
    well_conditioned(doubled_area(interval3(p0), interval3(p1), interval3(p2)))
}

pub(super) fn cone_barycentric_deltas(&(footprint, p0, p1, p2): &(f32, Vec3, Vec3, Vec3)) -> Vec<Interval> {
    let (p0, p1, p2) = (interval3(p0), interval3(p1), interval3(p2));
    let area2 = doubled_area(p0, p1, p2).max_c(f64::from(DIFF_MIN_MAGNITUDE));
    [p2 - p1, p2 - p0, p1 - p0]
        .iter()
        .map(|&edge| {
            (Interval::exact(footprint.abs()) * scaled_length(edge) / area2).min_c(f64::from(DIFF_MAX_VALUE))
        })
        .collect()
}

/// Componentwise hull of two vectors.
fn hull3(a: Interval3, b: Interval3) -> Interval3 {
    a.zip(b, |x, y| x.hull(y))
}

fn orthonormal_tangent(n: Interval3) -> Interval3 {
    let branch = |sign: f64| {
        let [x, y, z] = n.0;
        let s = Interval::c(sign);
        let a = Interval::c(-1.0) / (s + z);
        IntervalVec([
            Interval::c(1.0) + s * x * x * a,
            s * x * y * a,
            Interval::c(-sign) * x,
        ])
    };
    let z = n.0[2];
    if z.lo >= 0.0 {
        branch(1.0)
    } else if z.hi < 0.0 {
        branch(-1.0)
    } else {
        hull3(branch(1.0), branch(-1.0))
    }
}

/// The major and the minor axis; the hull of both choices of the minor axis where `|cross(n, d)|^2`
/// is within rounding of `DIFF_MIN_SINE^2`.
pub(super) fn anisotropic_cone_axes(
    width: f32,
    normal: Interval3,
    direction: Interval3,
) -> (Interval3, Interval3) {
    let across = normal.cross(direction);
    let length2 = across.dot(across);
    let min2 = f64::from(DIFF_MIN_SINE * DIFF_MIN_SINE);
    let fixed = || normal.cross(orthonormal_tangent(normal));
    let measured = || {
        across
            / Interval {
                lo: length2.lo.max(min2),
                ..length2
            }
            .sqrt()
    };
    let minor = if length2.hi < min2 {
        fixed()
    } else if length2.lo >= min2 {
        measured()
    } else {
        hull3(fixed(), measured())
    };
    let size = Interval::exact(width.abs());
    let cosine = normal.dot(direction).abs().max_c(f64::from(DIFF_MIN_COS));
    (minor.cross(normal) * (size / cosine), minor * size)
}

pub(super) fn anisotropic_cone_gradients(
    &(width, direction, p0, p1, p2, uv0, uv1, uv2): &ConeGradientArgs,
) -> Vec<Interval> {
    let (p0, p1, p2) = (interval3(p0), interval3(p1), interval3(p2));
    let (e1, e2) = (p1 - p0, p2 - p0);
    let area_normal = e1.cross(e2);
    let normal = area_normal / scaled_length(area_normal).max_c(f64::from(DIFF_MIN_MAGNITUDE));
    let (major, minor) = anisotropic_cone_axes(width, normal, interval3(direction));
    let k = e1.cross(e2).dot(normal);
    let (cu, cv) = (e2.cross(normal), normal.cross(e1));
    let barycentric = |offset: Interval3| {
        [
            barycentric_quotient(cu.dot(offset), k),
            barycentric_quotient(cv.dot(offset), k),
        ]
    };
    let (g1, g2) = (interval2(uv1) - interval2(uv0), interval2(uv2) - interval2(uv0));
    let uv = |[du, dv]: [Interval; 2]| g1 * du + g2 * dv;
    derivatives2(uv(barycentric(major)), uv(barycentric(minor)))
}

pub(super) fn ray_diff_from_cone(&(cone, direction): &(Vec2, Vec3)) -> Vec<Interval> {
    let d = interval3(direction);
    let u = orthonormal_tangent(d);
    let v = d.cross(u);
    let (width, spread) = (Interval::exact(cone.x), Interval::exact(cone.y));
    ray_diff(u * width, v * width, u * spread, v * spread)
}

/// The parts of one axis's origin and direction changes across the ray, and their alignment.
fn transverse_parts(d_origin: Vec3, d_direction: Vec3, direction: Vec3) -> (Interval3, Interval3, Interval) {
    let d = interval3(direction);
    let across = |v: Vec3| interval3(v) - d * interval3(v).dot(d);
    let (origin, turn) = (across(d_origin), across(d_direction));
    (origin, turn, origin.dot(turn))
}

/// Whether each axis of the cone is well-conditioned: the origin and direction changes across the
/// ray are known to [`WELL_CONDITIONED`] ([`direction_well_conditioned`]; not a change along the
/// ray within rounding), and the sign of the spread is decided (their alignment does not enclose
/// 0, or the origin change is exactly 0).
pub(super) fn transverse_well_conditioned(&(diff, direction): &(RayDiff, Vec3)) -> bool {
    let decided = |d_origin: Vec3, d_direction: Vec3| {
        let (origin, turn, alignment) = transverse_parts(d_origin, d_direction, direction);
        let sign_decided = d_origin == Vec3::ZERO || alignment.lo >= 0.0 || alignment.hi < 0.0;
        sign_decided && direction_well_conditioned(origin) && direction_well_conditioned(turn)
    };
    decided(diff.d_origin_dx, diff.d_direction_dx) && decided(diff.d_origin_dy, diff.d_direction_dy)
}

/// One axis; the sign of the spread is exact when the origin change is exactly 0 (then the dot
/// product is exactly 0 on every implementation), else the hull of both where rounding leaves it
/// open.
fn transverse_cone(d_origin: Vec3, d_direction: Vec3, direction: Vec3) -> [Interval; 2] {
    let (origin, turn, alignment) = transverse_parts(d_origin, d_direction, direction);
    let spread = scaled_length(turn);
    let signed = if alignment.lo >= 0.0 || d_origin == Vec3::ZERO {
        spread
    } else if alignment.hi < 0.0 {
        -spread
    } else {
        spread.hull(-spread)
    };
    [scaled_length(origin), signed]
}

pub(super) fn cone_from_ray_diff(&(diff, direction): &(RayDiff, Vec3)) -> Vec<Interval> {
    let x = transverse_cone(diff.d_origin_dx, diff.d_direction_dx, direction);
    let y = transverse_cone(diff.d_origin_dy, diff.d_direction_dy, direction);
    vec![Interval::c(0.5) * (x[0] + y[0]), Interval::c(0.5) * (x[1] + y[1])]
}
