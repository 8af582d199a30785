//! Interval enclosures of the ray_diff functions: each `b_*` re-evaluates one shader function (or
//! a step of one) in interval arithmetic, in the same order of operations as `src/ray_diff.rs`,
//! widening after each operation by the rounding error that Vulkan's precision rules allow the
//! device (and that the mirror makes). The width of the result is the check's tolerance. Also here:
//! the conditioning tests that keep a check to inputs whose enclosure says something
//! ([`WELL_CONDITIONED`]).

use super::{BarycentricArgs, Camera, ConeGradientArgs, Matrices, OffsetArgs};
use glam::{Mat4, Vec2, Vec3, Vec4Swizzles};
use ray_footprint::ray_diff::{
    Derivatives2, Derivatives3, GBufferSample, RayDiff, DIFF_MAX_FOV_Y, DIFF_MAX_SHARPNESS, DIFF_MAX_VALUE,
    DIFF_MIN_COS, DIFF_MIN_MAGNITUDE, DIFF_MIN_SINE,
};
use shader_proptest::interval::{
    interval2 as v2, interval3 as v3, mat_vec, Interval as I, Interval2 as V2, Interval3 as V3,
    IntervalVec as V, F32,
};

pub(super) fn s(x: f32) -> I {
    I::exact(x)
}

fn zero3() -> V3 {
    V([I::c(0.0); 3])
}

/// A `RayDiff`'s 16 components, pads exactly 0.
fn b_ray_diff(o_dx: V3, o_dy: V3, d_dx: V3, d_dy: V3) -> Vec<I> {
    [o_dx, o_dy, d_dx, d_dy]
        .iter()
        .flat_map(|v| v.components().into_iter().chain([I::c(0.0)]))
        .collect()
}

pub(super) fn b_derivatives2(dx: V2, dy: V2) -> Vec<I> {
    [dx.components(), dy.components()].concat()
}

pub(super) fn b_derivatives3(dx: V3, dy: V3) -> Vec<I> {
    [dx.components(), dy.components()].concat()
}

fn b_eye_ray_extent(image_size: Vec2, fov_y: f32) -> V2 {
    let size = image_size.max(Vec2::ONE);
    let f = I::tan_exact(0.5 * fov_y.clamp(0.0, DIFF_MAX_FOV_Y));
    V([s(size.x) / s(size.y) * f, f])
}

fn b_pixel_ndc(pixel: Vec2, image_size: Vec2) -> V2 {
    let size = image_size.max(Vec2::ONE);
    V(std::array::from_fn(|i| {
        (s(pixel[i]) + I::c(0.5)) / s(size[i]) * I::c(2.0) - I::c(1.0)
    }))
}

pub(super) fn b_eye_ray_direction(&(pixel, size, fov, right, up, view): &Camera) -> V3 {
    let c = b_pixel_ndc(pixel, size);
    let extent = b_eye_ray_extent(size, fov);
    v3(right) * (c.0[0] * extent.0[0]) - v3(up) * (c.0[1] * extent.0[1]) - v3(view)
}

pub(super) fn b_normalized_derivative(v: V3, dv: V3) -> V3 {
    let length2 = v.dot(v).max_c(f64::from(DIFF_MIN_MAGNITUDE));
    (dv - v * (v.dot(dv) / length2)) / length2.sqrt()
}

/// The direction differentials of `eye_ray_diff` (its origin differentials are exactly 0).
pub fn b_eye_ray_direction_derivatives(camera: &Camera) -> (V3, V3) {
    let &(_, image_size, fov, right, up, _) = camera;
    let d = b_eye_ray_direction(camera);
    let size = image_size.max(Vec2::ONE);
    let extent = b_eye_ray_extent(image_size, fov);
    let dd_dx = v3(right) * (I::c(2.0) * extent.0[0] / s(size.x));
    let dd_dy = v3(up) * -(I::c(2.0) * extent.0[1] / s(size.y));
    (
        b_normalized_derivative(d, dd_dx),
        b_normalized_derivative(d, dd_dy),
    )
}

pub(super) fn b_eye_ray_diff(camera: &Camera) -> Vec<I> {
    let (dd_dx, dd_dy) = b_eye_ray_direction_derivatives(camera);
    b_ray_diff(zero3(), zero3(), dd_dx, dd_dy)
}

fn b_safe_normalize(v: V3) -> V3 {
    v / v.dot(v).max_c(f64::from(DIFF_MIN_MAGNITUDE)).sqrt()
}

fn b_matrix_ray_direction(ndc: V2, view_inv: Mat4, proj_inv: Mat4) -> V3 {
    let far_point = mat_vec(proj_inv, V([ndc.0[0], ndc.0[1], I::c(1.0)]), I::c(1.0), F32);
    mat_vec(view_inv, b_safe_normalize(far_point), I::c(0.0), F32)
}

pub(super) fn b_eye_ray_direction_from_matrices(&(pixel, size, view_inv, proj_inv): &Matrices) -> V3 {
    b_matrix_ray_direction(b_pixel_ndc(pixel, size), view_inv, proj_inv)
}

pub(super) fn b_eye_ray_diff_from_matrices(&(pixel, image_size, view_inv, proj_inv): &Matrices) -> Vec<I> {
    let size = image_size.max(Vec2::ONE);
    let ndc = b_pixel_ndc(pixel, image_size);
    let far_point = mat_vec(proj_inv, V([ndc.0[0], ndc.0[1], I::c(1.0)]), I::c(1.0), F32);
    let dfar_dx = v3(proj_inv.x_axis.xyz()) * (I::c(2.0) / s(size.x));
    let dfar_dy = v3(proj_inv.y_axis.xyz()) * (I::c(2.0) / s(size.y));
    let dd_dx = mat_vec(
        view_inv,
        b_normalized_derivative(far_point, dfar_dx),
        I::c(0.0),
        F32,
    );
    let dd_dy = mat_vec(
        view_inv,
        b_normalized_derivative(far_point, dfar_dy),
        I::c(0.0),
        F32,
    );
    b_ray_diff(zero3(), zero3(), dd_dx, dd_dy)
}

pub(super) fn b_pixel_directions(&(pixel, size, view_inv, proj_inv): &Matrices) -> Vec<I> {
    let ndc = b_pixel_ndc(pixel, size);
    let next = b_pixel_ndc(pixel + 1.0, size);
    let right = b_matrix_ray_direction(V([next.0[0], ndc.0[1]]), view_inv, proj_inv);
    let below = b_matrix_ray_direction(V([ndc.0[0], next.0[1]]), view_inv, proj_inv);
    b_derivatives3(right, below)
}

/// One origin differential transferred to the plane at `t` with normal `normal`; the differential
/// comes as intervals (from earlier operations), the ray and the plane are exact.
pub fn b_transferred_origin(d_origin: V3, d_direction: V3, direction: Vec3, t: f32, normal: Vec3) -> V3 {
    let cosine = v3(direction).dot(v3(normal));
    let q = d_origin + d_direction * s(t);
    let dt = (-q.dot(v3(normal))).div_away(cosine, f64::from(DIFF_MIN_COS));
    q + v3(direction) * dt
}

pub(super) fn b_transfer(&(diff, direction, t, normal): &(RayDiff, Vec3, f32, Vec3)) -> Vec<I> {
    b_ray_diff(
        b_transferred_origin(
            v3(diff.d_origin_dx),
            v3(diff.d_direction_dx),
            direction,
            t,
            normal,
        ),
        b_transferred_origin(
            v3(diff.d_origin_dy),
            v3(diff.d_direction_dy),
            direction,
            t,
            normal,
        ),
        v3(diff.d_direction_dx),
        v3(diff.d_direction_dy),
    )
}

/// `x / k` clamped to `DIFF_MAX_VALUE`, `k` clamped away from 0 to `DIFF_MIN_MAGNITUDE`.
fn b_barycentric_quotient(numerator: I, k: I) -> I {
    let max = f64::from(DIFF_MAX_VALUE);
    numerator
        .div_away(k, f64::from(DIFF_MIN_MAGNITUDE))
        .clamp_c(-max, max)
}

pub(super) fn b_barycentric_derivatives(&(diff, direction, t, p0, p1, p2): &BarycentricArgs) -> Vec<I> {
    let d = v3(direction);
    let e1 = v3(p1) - v3(p0);
    let e2 = v3(p2) - v3(p0);
    let k = b_determinant(d, v3(p0), v3(p1), v3(p2));
    let cu = e2.cross(d);
    let cv = d.cross(e1);
    let q = v3(diff.d_origin_dx) + v3(diff.d_direction_dx) * s(t);
    let r = v3(diff.d_origin_dy) + v3(diff.d_direction_dy) * s(t);
    let quotient = |n: I| b_barycentric_quotient(n, k);
    b_derivatives2(
        V([quotient(cu.dot(q)), quotient(cv.dot(q))]),
        V([quotient(cu.dot(r)), quotient(cv.dot(r))]),
    )
}

pub(super) fn b_texture_derivatives(b: Derivatives2, t0: Vec2, t1: Vec2, t2: Vec2) -> (V2, V2) {
    let g1 = v2(t1) - v2(t0);
    let g2 = v2(t2) - v2(t0);
    (g1 * s(b.dx.x) + g2 * s(b.dx.y), g1 * s(b.dy.x) + g2 * s(b.dy.y))
}

pub(super) fn b_secondary_origin_derivatives(&(b, p0, p1, p2): &(Derivatives2, Vec3, Vec3, Vec3)) -> Vec<I> {
    let e1 = v3(p1) - v3(p0);
    let e2 = v3(p2) - v3(p0);
    b_derivatives3(e1 * s(b.dx.x) + e2 * s(b.dx.y), e1 * s(b.dy.x) + e2 * s(b.dy.y))
}

pub(super) fn b_lod_isotropic(g: Derivatives2) -> I {
    let rho2 = v2(g.dx).dot(v2(g.dx)).max(v2(g.dy).dot(v2(g.dy)));
    I::c(0.5) * rho2.max_c(f64::from(DIFF_MIN_MAGNITUDE)).log2()
}

pub(super) fn b_lod_box(g: Derivatives2) -> I {
    let extent = v2(g.dx).abs() + v2(g.dy).abs();
    extent.0[0]
        .max(extent.0[1])
        .max_c(f64::from(DIFF_MIN_MAGNITUDE))
        .log2()
}

type NormalArgs = (Vec3, Vec3, Vec3, Vec2, Derivatives2);

pub(super) fn b_normal_derivatives(&(n0, n1, n2, uv, b): &NormalArgs) -> Vec<I> {
    let (n0, n1, n2) = (v3(n0), v3(n1), v3(n2));
    let n = n0 * (I::c(1.0) - s(uv.x) - s(uv.y)) + n1 * s(uv.x) + n2 * s(uv.y);
    let dn_dx = (n1 - n0) * s(b.dx.x) + (n2 - n0) * s(b.dx.y);
    let dn_dy = (n1 - n0) * s(b.dy.x) + (n2 - n0) * s(b.dy.y);
    b_derivatives3(
        b_normalized_derivative(n, dn_dx),
        b_normalized_derivative(n, dn_dy),
    )
}

/// One direction differential reflected at a hit; the differentials come as intervals, the ray
/// and the normal are exact.
pub fn b_reflected_direction(dd: V3, direction: Vec3, normal: Vec3, dn: V3) -> V3 {
    let (d, n) = (v3(direction), v3(normal));
    let cosine = d.dot(n);
    dd - (dn * cosine + n * (dd.dot(n) + d.dot(dn))) * I::c(2.0)
}

type ReflectArgs = (RayDiff, Vec3, Vec3, Derivatives3);

pub(super) fn b_reflect_ray_diff(&(diff, direction, normal, dn): &ReflectArgs) -> Vec<I> {
    b_ray_diff(
        v3(diff.d_origin_dx),
        v3(diff.d_origin_dy),
        b_reflected_direction(v3(diff.d_direction_dx), direction, normal, v3(dn.dx)),
        b_reflected_direction(v3(diff.d_direction_dy), direction, normal, v3(dn.dy)),
    )
}

type RefractArgs = (RayDiff, Vec3, Vec3, Derivatives3, f32);

/// The refracted branch, for the part of `k`'s interval that is `>= 0`.
fn b_refracted(&(diff, direction, normal, dn, eta): &RefractArgs, k: I) -> Vec<I> {
    let (d, n, eta) = (v3(direction), v3(normal), s(eta));
    let cosine = d.dot(n);
    let root = I {
        lo: k.lo.max(0.0),
        ..k
    }
    .sqrt();
    // A magnitude with the sign of `cosine`: both signs where `cosine` straddles 0.
    let with_cosine_sign = |magnitude: I| {
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
        let (dd, dnormal) = (v3(dd), v3(dnormal));
        let d_cos = dd.dot(n) + d.dot(dnormal);
        dd * eta - (dnormal * mu + n * (rate * d_cos))
    };
    b_ray_diff(
        v3(diff.d_origin_dx),
        v3(diff.d_origin_dy),
        refracted(diff.d_direction_dx, dn.dx),
        refracted(diff.d_direction_dy, dn.dy),
    )
}

/// `k = 1 - eta^2 (1 - dot(D, N)^2)`: negative for total internal reflection.
pub(super) fn b_refraction_determinant(&(_, direction, normal, _, eta): &RefractArgs) -> I {
    let cosine = v3(direction).dot(v3(normal));
    I::c(1.0) - s(eta) * s(eta) * (I::c(1.0) - cosine * cosine)
}

/// Either branch, or the hull of both (flag `[0, 1]`) when `k`'s sign is uncertain.
pub(super) fn b_refract_ray_diff(args: &RefractArgs) -> Vec<I> {
    let &(diff, direction, normal, dn, _) = args;
    let k = b_refraction_determinant(args);
    let reflected = || {
        [
            b_reflect_ray_diff(&(diff, direction, normal, dn)),
            vec![I::c(1.0)],
        ]
        .concat()
    };
    let refracted = || [b_refracted(args, k), vec![I::c(0.0)]].concat();
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

fn b_gbuffer_steps(start: GBufferSample, end: GBufferSample) -> (V3, V3) {
    let reflect = |g: GBufferSample| {
        let (e, n) = (v3(g.eye_direction), v3(g.normal));
        e - n * (I::c(2.0) * n.dot(e))
    };
    (
        v3(end.eye_direction) * s(end.distance) - v3(start.eye_direction) * s(start.distance),
        reflect(end) - reflect(start),
    )
}

type GBufferArgs = (
    GBufferSample,
    GBufferSample,
    GBufferSample,
    GBufferSample,
    GBufferSample,
    f32,
);

pub(super) fn b_gbuffer_ray_diff(&(center, right, left, below, above, epsilon): &GBufferArgs) -> Vec<I> {
    let pair = |forward, backward| {
        if use_backward(center, forward, backward, epsilon) {
            b_gbuffer_steps(backward, center)
        } else {
            b_gbuffer_steps(center, forward)
        }
    };
    let (x, y) = (pair(right, left), pair(below, above));
    b_ray_diff(x.0, y.0, x.1, y.1)
}

pub(super) fn b_tangent_plane_offset(rd: Vec3, rd_neighbour: Vec3, t: f32, normal: Vec3) -> V3 {
    let (rd, rdn, n) = (v3(rd), v3(rd_neighbour), v3(normal));
    let ratio = rd.dot(n).div_away(rdn.dot(n), f64::from(DIFF_MIN_COS));
    (rdn * ratio - rd) * s(t)
}

pub(super) fn b_triplanar_weights(normal: Vec3, sharpness: f32) -> Vec<I> {
    let k = sharpness.clamp(0.0, DIFF_MAX_SHARPNESS);
    let size = normal.abs();
    let largest = s(size.x.max(size.y).max(size.z.max(DIFF_MIN_MAGNITUDE)));
    let m: [I; 3] =
        std::array::from_fn(|i| (s(size[i]) / largest).max_c(f64::from(DIFF_MIN_MAGNITUDE)).pow(k));
    let sum = (m[0] + m[1] + m[2]).max_c(f64::from(DIFF_MIN_MAGNITUDE));
    m.iter().map(|&x| x / sum).collect()
}

fn b_scaled_length(v: V3) -> I {
    let a = v.abs();
    let m = a.0[0]
        .max(a.0[1])
        .max(a.0[2].max_c(f64::from(DIFF_MIN_MAGNITUDE)));
    let unit = v / m;
    m * unit.dot(unit).sqrt()
}

/// The determinant `k = dot(cross(e1, e2), direction)` of a ray against a triangle's plane (RTG
/// Eq. 12-20): the divisor of every barycentric quotient.
pub(super) fn b_determinant(direction: V3, p0: V3, p1: V3, p2: V3) -> I {
    (p1 - p0).cross(p2 - p0).dot(direction)
}

/// Bits to which a divisor must be known for its quotient to be well-conditioned: a relative
/// width of the divisor's enclosure of at most 2^-10. Beyond that (a ray parallel to the triangle
/// within rounding, a sliver, an object-space direction lost to the cancellation of a far origin)
/// the clamped quotient's enclosure is as wide as the outputs themselves, so those inputs are
/// checked separately, for finite outputs within the documented clamp (the edge-case suite).
pub const WELL_CONDITIONED: f64 = 1.0 / 1024.0;

/// Whether a quotient by `k` is well-conditioned ([`WELL_CONDITIONED`]); an exact 0 is, since both
/// sides then take the clamp.
pub(super) fn well_conditioned(k: I) -> bool {
    k.relative_width() <= WELL_CONDITIONED
}

pub(super) fn b_intersect_triangle_plane(origin: V3, direction: V3, p0: V3, p1: V3, p2: V3) -> V3 {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let s0 = origin - p0;
    let k = b_determinant(direction, p0, p1, p2);
    let u = b_barycentric_quotient(e2.cross(direction).dot(s0), k);
    let v = b_barycentric_quotient(direction.cross(e1).dot(s0), k);
    V([I::c(1.0) - u - v, u, v])
}

/// The object-space origin and the two neighbour directions of the re-intersection.
fn b_object_rays(&(w2o, origin, _, _, _, dir_x, dir_y, _): &OffsetArgs) -> (V3, V3, V3) {
    let transform = |p: V3| mat_vec(w2o, p, I::c(1.0), F32);
    let object_origin = transform(v3(origin));
    let object_x = transform(v3(origin) + v3(dir_x)) - object_origin;
    let object_y = transform(v3(origin) + v3(dir_y)) - object_origin;
    (object_origin, object_x, object_y)
}

pub(super) fn b_barycentric_offsets(args: &OffsetArgs) -> (V3, V3) {
    let &(_, _, p0, p1, p2, _, _, hit) = args;
    let (object_origin, object_x, object_y) = b_object_rays(args);
    let (p0, p1, p2) = (v3(p0), v3(p1), v3(p2));
    (
        b_intersect_triangle_plane(object_origin, object_x, p0, p1, p2) - v3(hit),
        b_intersect_triangle_plane(object_origin, object_y, p0, p1, p2) - v3(hit),
    )
}

/// Whether a direction is known to [`WELL_CONDITIONED`]: its widest component's enclosure is at
/// most that fraction of its largest component (an object-space neighbour direction is not, when
/// the origin is so far from the object that `T(O + d) - T(O)` cancels most of its bits).
pub fn direction_well_conditioned(direction: V3) -> bool {
    let width = direction.0.iter().map(|c| c.hi - c.lo).fold(0.0, f64::max);
    let magnitude = direction.0.iter().map(|c| c.magnitude()).fold(0.0, f64::max);
    width <= WELL_CONDITIONED * magnitude
}

/// Whether both neighbour rays' intersections are well-conditioned ([`WELL_CONDITIONED`]): the
/// object-space directions and their determinants against the triangle.
pub(super) fn offsets_well_conditioned(args: &OffsetArgs) -> bool {
    let &(_, _, p0, p1, p2, _, _, _) = args;
    let (_, object_x, object_y) = b_object_rays(args);
    let (p0, p1, p2) = (v3(p0), v3(p1), v3(p2));
    [object_x, object_y]
        .iter()
        .all(|&d| direction_well_conditioned(d) && well_conditioned(b_determinant(d, p0, p1, p2)))
}

pub(super) fn b_cone_barycentric_deltas(&(footprint, p0, p1, p2): &(f32, Vec3, Vec3, Vec3)) -> Vec<I> {
    let (p0, p1, p2) = (v3(p0), v3(p1), v3(p2));
    let area2 = b_scaled_length((p1 - p0).cross(p2 - p0)).max_c(f64::from(DIFF_MIN_MAGNITUDE));
    [p2 - p1, p2 - p0, p1 - p0]
        .iter()
        .map(|&edge| (s(footprint.abs()) * b_scaled_length(edge) / area2).min_c(f64::from(DIFF_MAX_VALUE)))
        .collect()
}

/// Componentwise hull of two vectors.
fn hull3(a: V3, b: V3) -> V3 {
    a.zip(b, |x, y| x.hull(y))
}

fn b_orthonormal_tangent(n: V3) -> V3 {
    let branch = |sign: f64| {
        let [x, y, z] = n.0;
        let s = I::c(sign);
        let a = I::c(-1.0) / (s + z);
        V([I::c(1.0) + s * x * x * a, s * x * y * a, I::c(-sign) * x])
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
pub(super) fn b_anisotropic_cone_axes(width: f32, normal: V3, direction: V3) -> (V3, V3) {
    let across = normal.cross(direction);
    let length2 = across.dot(across);
    let min2 = f64::from(DIFF_MIN_SINE * DIFF_MIN_SINE);
    let fixed = || normal.cross(b_orthonormal_tangent(normal));
    let measured = || {
        across
            / I {
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
    let size = s(width.abs());
    let cosine = normal.dot(direction).abs().max_c(f64::from(DIFF_MIN_COS));
    (minor.cross(normal) * (size / cosine), minor * size)
}

pub(super) fn b_anisotropic_cone_gradients(
    &(width, direction, p0, p1, p2, uv0, uv1, uv2): &ConeGradientArgs,
) -> Vec<I> {
    let (p0, p1, p2) = (v3(p0), v3(p1), v3(p2));
    let (e1, e2) = (p1 - p0, p2 - p0);
    let area_normal = e1.cross(e2);
    let normal = area_normal / b_scaled_length(area_normal).max_c(f64::from(DIFF_MIN_MAGNITUDE));
    let (major, minor) = b_anisotropic_cone_axes(width, normal, v3(direction));
    let k = e1.cross(e2).dot(normal);
    let (cu, cv) = (e2.cross(normal), normal.cross(e1));
    let barycentric = |offset: V3| {
        [
            b_barycentric_quotient(cu.dot(offset), k),
            b_barycentric_quotient(cv.dot(offset), k),
        ]
    };
    let (g1, g2) = (v2(uv1) - v2(uv0), v2(uv2) - v2(uv0));
    let uv = |[du, dv]: [I; 2]| g1 * du + g2 * dv;
    b_derivatives2(uv(barycentric(major)), uv(barycentric(minor)))
}

pub(super) fn b_ray_diff_from_cone(&(cone, direction): &(Vec2, Vec3)) -> Vec<I> {
    let d = v3(direction);
    let u = b_orthonormal_tangent(d);
    let v = d.cross(u);
    let (width, spread) = (s(cone.x), s(cone.y));
    b_ray_diff(u * width, v * width, u * spread, v * spread)
}

/// One axis; the sign of the spread is exact when the origin change is exactly 0 (then the dot
/// product is exactly 0 on every implementation), else the hull of both where rounding leaves it
/// open.
fn b_transverse_cone(d_origin: Vec3, d_direction: Vec3, direction: Vec3) -> [I; 2] {
    let d = v3(direction);
    let across = |v: Vec3| v3(v) - d * v3(v).dot(d);
    let (origin, turn) = (across(d_origin), across(d_direction));
    let spread = b_scaled_length(turn);
    let alignment = origin.dot(turn);
    let signed = if alignment.lo >= 0.0 || d_origin == Vec3::ZERO {
        spread
    } else if alignment.hi < 0.0 {
        -spread
    } else {
        spread.hull(-spread)
    };
    [b_scaled_length(origin), signed]
}

pub(super) fn b_cone_from_ray_diff(&(diff, direction): &(RayDiff, Vec3)) -> Vec<I> {
    let x = b_transverse_cone(diff.d_origin_dx, diff.d_direction_dx, direction);
    let y = b_transverse_cone(diff.d_origin_dy, diff.d_direction_dy, direction);
    vec![I::c(0.5) * (x[0] + y[0]), I::c(0.5) * (x[1] + y[1])]
}
