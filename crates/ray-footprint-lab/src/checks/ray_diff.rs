//! Agreement checks of the ray_diff module, one per function, in the module's order.
//!
//! Every tolerance is the width of an enclosure (`bound`): the check re-evaluates its function in
//! interval arithmetic on the same inputs, widening after each operation by the rounding error that
//! Vulkan's precision rules allow the device (and that the mirror makes), so both results lie inside.
//! The `b_*` functions below are those re-evaluations, one per shader function, in the module's
//! order of operations.

use super::edge::Edge;
use super::enclosed;
use super::strategy::{
    angle, distance, fov_y, magnitude, normal_and_direction, perspective_proj_inv, pixels, scalar,
    small_vec3, triangle, unit_vec3, uv_triangle, vec3,
};
use super::{registered_checks, Entry};
use glam::{Mat4, Quat, Vec2, Vec3, Vec4Swizzles};
use proptest::prelude::*;
use ray_footprint::ray_diff::{
    self as rd, Derivatives2, Derivatives3, GBufferSample, NeighbourDirections, RayDiff, DIFF_MAX_FOV_Y,
    DIFF_MAX_SHARPNESS, DIFF_MAX_VALUE, DIFF_MIN_COS, DIFF_MIN_MAGNITUDE, DIFF_MIN_SINE,
};
use ray_footprint::registry::Registered;
use ray_footprint::shaders::Module;
use shader_proptest::interval::{
    interval2 as v2, interval3 as v3, mat_vec, Interval as I, Interval2 as V2, Interval3 as V3,
    IntervalVec as V, F32,
};
use shader_proptest::{Args, FunctionCheck, Value};

// ---------------------------------------------------------------------------------------------
// Strategies
// ---------------------------------------------------------------------------------------------

/// A pixel inside an image (or, sometimes, outside it) and the image size (from [`pixels`]).
pub fn pixel_and_size() -> BoxedStrategy<(Vec2, Vec2)> {
    ((pixels(), pixels()), (0.0f32..1.0, 0.0f32..1.0), any::<bool>())
        .prop_map(|((w, h), (fx, fy), outside)| {
            let size = Vec2::new(w, h);
            let pixel = if outside {
                Vec2::new(fx, fy) * 40000.0 - 20000.0
            } else {
                (Vec2::new(fx, fy) * size.max(Vec2::ONE)).floor()
            };
            (pixel, size)
        })
        .boxed()
}

/// A rotation (axis-aligned ones included).
fn rotation() -> BoxedStrategy<Quat> {
    (unit_vec3(), 0.0f32..std::f32::consts::TAU)
        .prop_map(|(axis, angle)| Quat::from_axis_angle(axis, angle))
        .boxed()
}

/// A camera basis: right, up and view (towards the eye), orthonormal up to rounding.
pub fn camera_basis() -> BoxedStrategy<(Vec3, Vec3, Vec3)> {
    rotation()
        .prop_map(|q| (q * Vec3::X, q * Vec3::Y, q * Vec3::Z))
        .boxed()
}

/// A rigid transform with a translation from [`vec3`] (a camera-to-world matrix).
pub fn rigid() -> BoxedStrategy<Mat4> {
    (rotation(), vec3())
        .prop_map(|(q, t)| Mat4::from_rotation_translation(q, t))
        .boxed()
}

/// An inverse projection matrix: perspective (OpenGL or Vulkan, y-flipped), or arbitrary with
/// moderate entries.
pub fn proj_inv() -> BoxedStrategy<Mat4> {
    let arbitrary = prop::array::uniform16(-10.0f32..10.0).prop_map(|cols| Mat4::from_cols_array(&cols));
    prop_oneof![3 => perspective_proj_inv(), 1 => arbitrary].boxed()
}

/// A differential vector: ordinary, small (pixel-sized), or anywhere in the domain.
fn differential_vec3() -> BoxedStrategy<Vec3> {
    prop_oneof![
        3 => small_vec3(),
        2 => small_vec3().prop_map(|v| v * 1.0e-4),
        1 => vec3(),
        1 => Just(Vec3::ZERO),
    ]
    .boxed()
}

/// A ray differential: origin differentials from `differential_vec3`, direction differentials
/// ordinary or pixel-sized.
pub fn ray_diff() -> BoxedStrategy<RayDiff> {
    let direction = || prop_oneof![small_vec3(), small_vec3().prop_map(|v| v * 1.0e-4)];
    (differential_vec3(), differential_vec3(), direction(), direction())
        .prop_map(|(a, b, c, d)| RayDiff::new(a, b, c, d))
        .boxed()
}

/// `(du, dv)` derivatives: ordinary, tiny or huge.
fn derivatives2() -> BoxedStrategy<Derivatives2> {
    let component = || prop_oneof![3 => -10.0f32..10.0, 1 => scalar()];
    (component(), component(), component(), component())
        .prop_map(|(a, b, c, d)| Derivatives2::new(Vec2::new(a, b), Vec2::new(c, d)))
        .boxed()
}

/// Vector derivatives from [`differential_vec3`].
fn derivatives3() -> BoxedStrategy<Derivatives3> {
    (differential_vec3(), differential_vec3())
        .prop_map(|(dx, dy)| Derivatives3::new(dx, dy))
        .boxed()
}

/// A hit's barycentrics `(w, u, v)`, inside the triangle or not, summing to 1 up to rounding.
fn hit_barycentrics() -> BoxedStrategy<Vec3> {
    (-1.0f32..2.0, -1.0f32..2.0)
        .prop_map(|(u, v)| Vec3::new(1.0 - u - v, u, v))
        .boxed()
}

/// A world-to-object matrix: rotation, uniform scale in `[1e-3, 1e3]`, translation up to
/// `10^max_exponent`.
fn world_to_object(max_exponent: f32) -> BoxedStrategy<Mat4> {
    (
        rotation(),
        -3.0f32..3.0,
        small_vec3(),
        -9.0f32..max_exponent + 1.0,
    )
        .prop_map(|(q, scale, t, e)| {
            Mat4::from_scale_rotation_translation(Vec3::splat(10f32.powf(scale)), q, t * 10f32.powf(e) / 10.0)
        })
        .boxed()
}

/// A world ray origin up to `10^max_exponent`.
fn world_origin(max_exponent: f32) -> BoxedStrategy<Vec3> {
    (small_vec3(), -12.0f32..max_exponent - 1.0)
        .prop_map(|(v, e)| v * 10f32.powf(e))
        .boxed()
}

/// A unit direction or a moderately scaled one (functions that take non-normalized directions).
fn any_direction() -> BoxedStrategy<Vec3> {
    prop_oneof![3 => unit_vec3(), 1 => small_vec3()].boxed()
}

/// A G-buffer pixel: unit eye direction, distance, unit normal.
fn gbuffer_sample() -> BoxedStrategy<GBufferSample> {
    (normal_and_direction(), distance())
        .prop_map(|((normal, eye_direction), distance)| GBufferSample {
            eye_direction,
            distance,
            normal,
        })
        .boxed()
}

// ---------------------------------------------------------------------------------------------
// Enclosures of the module's functions (same order of operations as src/ray_diff.rs)
// ---------------------------------------------------------------------------------------------

fn s(x: f32) -> I {
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

fn b_derivatives2(dx: V2, dy: V2) -> Vec<I> {
    [dx.components(), dy.components()].concat()
}

fn b_derivatives3(dx: V3, dy: V3) -> Vec<I> {
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

/// The arguments of the pinhole camera functions: pixel, image size, fov_y, right, up, view.
pub(crate) type Camera = (Vec2, Vec2, f32, Vec3, Vec3, Vec3);

fn b_eye_ray_direction(&(pixel, size, fov, right, up, view): &Camera) -> V3 {
    let c = b_pixel_ndc(pixel, size);
    let extent = b_eye_ray_extent(size, fov);
    v3(right) * (c.0[0] * extent.0[0]) - v3(up) * (c.0[1] * extent.0[1]) - v3(view)
}

fn b_normalized_derivative(v: V3, dv: V3) -> V3 {
    let length2 = v.dot(v).max_c(f64::from(DIFF_MIN_MAGNITUDE));
    (dv - v * (v.dot(dv) / length2)) / length2.sqrt()
}

/// The direction differentials of `eye_ray_diff` (its origin differentials are exactly 0).
pub(crate) fn b_eye_ray_direction_derivatives(camera: &Camera) -> (V3, V3) {
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

fn b_eye_ray_diff(camera: &Camera) -> Vec<I> {
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

/// The arguments of the matrix camera functions: pixel, image size, view_inv, proj_inv.
pub type Matrices = (Vec2, Vec2, Mat4, Mat4);

fn b_eye_ray_direction_from_matrices(&(pixel, size, view_inv, proj_inv): &Matrices) -> V3 {
    b_matrix_ray_direction(b_pixel_ndc(pixel, size), view_inv, proj_inv)
}

fn b_eye_ray_diff_from_matrices(&(pixel, image_size, view_inv, proj_inv): &Matrices) -> Vec<I> {
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

fn b_pixel_directions(&(pixel, size, view_inv, proj_inv): &Matrices) -> Vec<I> {
    let ndc = b_pixel_ndc(pixel, size);
    let next = b_pixel_ndc(pixel + 1.0, size);
    let right = b_matrix_ray_direction(V([next.0[0], ndc.0[1]]), view_inv, proj_inv);
    let below = b_matrix_ray_direction(V([ndc.0[0], next.0[1]]), view_inv, proj_inv);
    b_derivatives3(right, below)
}

/// One origin differential transferred to the plane at `t` with normal `normal`; the differential
/// comes as intervals (from earlier operations), the ray and the plane are exact.
pub(crate) fn b_transferred_origin(
    d_origin: V3,
    d_direction: V3,
    direction: Vec3,
    t: f32,
    normal: Vec3,
) -> V3 {
    let cosine = v3(direction).dot(v3(normal));
    let q = d_origin + d_direction * s(t);
    let dt = (-q.dot(v3(normal))).div_away(cosine, f64::from(DIFF_MIN_COS));
    q + v3(direction) * dt
}

fn b_transfer(&(diff, direction, t, normal): &(RayDiff, Vec3, f32, Vec3)) -> Vec<I> {
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

/// The arguments of `barycentric_derivatives`: differential, direction, t, the triangle.
pub type BarycentricArgs = (RayDiff, Vec3, f32, Vec3, Vec3, Vec3);

fn b_barycentric_derivatives(&(diff, direction, t, p0, p1, p2): &BarycentricArgs) -> Vec<I> {
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

fn b_texture_derivatives(b: Derivatives2, t0: Vec2, t1: Vec2, t2: Vec2) -> (V2, V2) {
    let g1 = v2(t1) - v2(t0);
    let g2 = v2(t2) - v2(t0);
    (g1 * s(b.dx.x) + g2 * s(b.dx.y), g1 * s(b.dy.x) + g2 * s(b.dy.y))
}

fn b_secondary_origin_derivatives(&(b, p0, p1, p2): &(Derivatives2, Vec3, Vec3, Vec3)) -> Vec<I> {
    let e1 = v3(p1) - v3(p0);
    let e2 = v3(p2) - v3(p0);
    b_derivatives3(e1 * s(b.dx.x) + e2 * s(b.dx.y), e1 * s(b.dy.x) + e2 * s(b.dy.y))
}

fn b_lod_isotropic(g: Derivatives2) -> I {
    let rho2 = v2(g.dx).dot(v2(g.dx)).max(v2(g.dy).dot(v2(g.dy)));
    I::c(0.5) * rho2.max_c(f64::from(DIFF_MIN_MAGNITUDE)).log2()
}

fn b_lod_box(g: Derivatives2) -> I {
    let extent = v2(g.dx).abs() + v2(g.dy).abs();
    extent.0[0]
        .max(extent.0[1])
        .max_c(f64::from(DIFF_MIN_MAGNITUDE))
        .log2()
}

type NormalArgs = (Vec3, Vec3, Vec3, Vec2, Derivatives2);

fn b_normal_derivatives(&(n0, n1, n2, uv, b): &NormalArgs) -> Vec<I> {
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
pub(crate) fn b_reflected_direction(dd: V3, direction: Vec3, normal: Vec3, dn: V3) -> V3 {
    let (d, n) = (v3(direction), v3(normal));
    let cosine = d.dot(n);
    dd - (dn * cosine + n * (dd.dot(n) + d.dot(dn))) * I::c(2.0)
}

type ReflectArgs = (RayDiff, Vec3, Vec3, Derivatives3);

fn b_reflect_ray_diff(&(diff, direction, normal, dn): &ReflectArgs) -> Vec<I> {
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
fn b_refraction_determinant(&(_, direction, normal, _, eta): &RefractArgs) -> I {
    let cosine = v3(direction).dot(v3(normal));
    I::c(1.0) - s(eta) * s(eta) * (I::c(1.0) - cosine * cosine)
}

/// Either branch, or the hull of both (flag `[0, 1]`) when `k`'s sign is uncertain.
fn b_refract_ray_diff(args: &RefractArgs) -> Vec<I> {
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

fn b_gbuffer_ray_diff(&(center, right, left, below, above, epsilon): &GBufferArgs) -> Vec<I> {
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

fn b_tangent_plane_offset(rd: Vec3, rd_neighbour: Vec3, t: f32, normal: Vec3) -> V3 {
    let (rd, rdn, n) = (v3(rd), v3(rd_neighbour), v3(normal));
    let ratio = rd.dot(n).div_away(rdn.dot(n), f64::from(DIFF_MIN_COS));
    (rdn * ratio - rd) * s(t)
}

fn b_triplanar_weights(normal: Vec3, sharpness: f32) -> Vec<I> {
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
fn b_determinant(direction: V3, p0: V3, p1: V3, p2: V3) -> I {
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
fn well_conditioned(k: I) -> bool {
    k.relative_width() <= WELL_CONDITIONED
}

fn b_intersect_triangle_plane(origin: V3, direction: V3, p0: V3, p1: V3, p2: V3) -> V3 {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let s0 = origin - p0;
    let k = b_determinant(direction, p0, p1, p2);
    let u = b_barycentric_quotient(e2.cross(direction).dot(s0), k);
    let v = b_barycentric_quotient(direction.cross(e1).dot(s0), k);
    V([I::c(1.0) - u - v, u, v])
}

/// The arguments of the re-intersection functions (here and in the f64 module).
pub type OffsetArgs = (Mat4, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3);

/// The object-space origin and the two neighbour directions of the re-intersection.
fn b_object_rays(&(w2o, origin, _, _, _, dir_x, dir_y, _): &OffsetArgs) -> (V3, V3, V3) {
    let transform = |p: V3| mat_vec(w2o, p, I::c(1.0), F32);
    let object_origin = transform(v3(origin));
    let object_x = transform(v3(origin) + v3(dir_x)) - object_origin;
    let object_y = transform(v3(origin) + v3(dir_y)) - object_origin;
    (object_origin, object_x, object_y)
}

fn b_barycentric_offsets(args: &OffsetArgs) -> (V3, V3) {
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
fn offsets_well_conditioned(args: &OffsetArgs) -> bool {
    let &(_, _, p0, p1, p2, _, _, _) = args;
    let (_, object_x, object_y) = b_object_rays(args);
    let (p0, p1, p2) = (v3(p0), v3(p1), v3(p2));
    [object_x, object_y]
        .iter()
        .all(|&d| direction_well_conditioned(d) && well_conditioned(b_determinant(d, p0, p1, p2)))
}

/// [`offset_args`] where both intersections are well-conditioned.
pub fn well_conditioned_offset_args(max_exponent: f32) -> BoxedStrategy<OffsetArgs> {
    offset_args(max_exponent)
        .prop_filter("an ill-conditioned re-intersection", offsets_well_conditioned)
        .boxed()
}

fn b_cone_barycentric_deltas(&(footprint, p0, p1, p2): &(f32, Vec3, Vec3, Vec3)) -> Vec<I> {
    let (p0, p1, p2) = (v3(p0), v3(p1), v3(p2));
    let area2 = b_scaled_length((p1 - p0).cross(p2 - p0)).max_c(f64::from(DIFF_MIN_MAGNITUDE));
    [p2 - p1, p2 - p0, p1 - p0]
        .iter()
        .map(|&edge| (s(footprint.abs()) * b_scaled_length(edge) / area2).min_c(f64::from(DIFF_MAX_VALUE)))
        .collect()
}

/// Largest exponent of the world origin and translation for the f32 re-intersection checks. Beyond
/// about 1e6 the f32 sum `O + direction` loses the unit direction entirely and both sides compute
/// rounding noise (the f64 variant exists for that range, and its checks go to 1e8).
pub const F32_ORIGIN_EXPONENT: f32 = 5.0;

/// Inputs of the re-intersection functions: a transform and a world origin up to
/// `10^max_exponent`, an object-space triangle, two unit neighbour directions and hit barycentrics.
pub fn offset_args(max_exponent: f32) -> BoxedStrategy<OffsetArgs> {
    (
        (world_to_object(max_exponent), world_origin(max_exponent)),
        triangle(),
        (unit_vec3(), unit_vec3()),
        hit_barycentrics(),
    )
        .prop_map(|((w2o, origin), p, (x, y), hit)| (w2o, origin, p[0], p[1], p[2], x, y, hit))
        .boxed()
}

fn camera() -> BoxedStrategy<Camera> {
    (pixel_and_size(), fov_y(), camera_basis())
        .prop_map(|((pixel, size), fov, (r, u, v))| (pixel, size, fov, r, u, v))
        .boxed()
}

/// Narrowest field of view the eye-ray differential checks use: below it Vulkan's allowance for
/// `tan` (2^-11 absolute, inherited from `sin / cos`) exceeds 2% of `tan(fov / 2)`, and a camera
/// whose field of view is clamped to 0 has no differential to compare; those cameras are checked
/// separately (the degenerate table, the edge-case suite).
const MIN_DIFFERENTIAL_FOV: f32 = 0.05;

/// [`camera`] with a field of view of at least [`MIN_DIFFERENTIAL_FOV`].
fn camera_with_a_view() -> BoxedStrategy<Camera> {
    camera()
        .prop_filter("a field of view of (nearly) 0", |&(_, _, fov, ..)| {
            fov >= MIN_DIFFERENTIAL_FOV
        })
        .boxed()
}

fn matrices() -> BoxedStrategy<Matrices> {
    (pixel_and_size(), rigid(), proj_inv())
        .prop_map(|((pixel, size), view_inv, proj_inv)| (pixel, size, view_inv, proj_inv))
        .boxed()
}

/// `rf_eye_ray_direction`.
pub fn eye_ray_direction() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "eye_ray_direction",
        camera,
        |(pixel, size, fov, r, u, v)| rd::eye_ray_direction(pixel, size, fov, r, u, v),
        |a| b_eye_ray_direction(a).components(),
    )
}

/// `rf_normalized_derivative`.
pub fn normalized_derivative() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "normalized_derivative",
        || (any_direction(), differential_vec3()).boxed(),
        |(v, dv)| rd::normalized_derivative(v, dv),
        |&(v, dv)| b_normalized_derivative(v3(v), v3(dv)).components(),
    )
}

/// `rf_eye_ray_diff`.
pub fn eye_ray_diff() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "eye_ray_diff",
        camera_with_a_view,
        |(pixel, size, fov, r, u, v)| rd::eye_ray_diff(pixel, size, fov, r, u, v),
        b_eye_ray_diff,
    )
}

/// `rf_eye_ray_direction_from_matrices`.
pub fn eye_ray_direction_from_matrices() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "eye_ray_direction_from_matrices",
        matrices,
        |(pixel, size, view_inv, proj_inv)| {
            rd::eye_ray_direction_from_matrices(pixel, size, view_inv, proj_inv)
        },
        |a| b_eye_ray_direction_from_matrices(a).components(),
    )
}

/// `rf_eye_ray_diff_from_matrices`: the enclosure of every component.
pub fn eye_ray_diff_from_matrices() -> FunctionCheck<Matrices, RayDiff> {
    enclosed(
        "eye_ray_diff_from_matrices",
        matrices,
        |(pixel, size, view_inv, proj_inv)| rd::eye_ray_diff_from_matrices(pixel, size, view_inv, proj_inv),
        b_eye_ray_diff_from_matrices,
    )
}

/// `rf_pixel_directions`: the enclosure of both directions.
pub fn pixel_directions() -> FunctionCheck<Matrices, NeighbourDirections> {
    enclosed(
        "pixel_directions",
        matrices,
        |(pixel, size, view_inv, proj_inv)| rd::pixel_directions(pixel, size, view_inv, proj_inv),
        b_pixel_directions,
    )
}

/// `rf_transfer`.
pub fn transfer() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "transfer",
        || {
            (ray_diff(), normal_and_direction(), distance())
                .prop_map(|(diff, (n, d), t)| (diff, d, t, n))
                .boxed()
        },
        |(diff, direction, t, normal)| rd::transfer(diff, direction, t, normal),
        b_transfer,
    )
}

/// `rf_barycentric_derivatives`: the enclosure of the four derivatives.
pub fn barycentric_derivatives() -> FunctionCheck<BarycentricArgs, Derivatives2> {
    enclosed(
        "barycentric_derivatives",
        || {
            (ray_diff(), any_direction(), distance(), triangle())
                .prop_map(|(diff, d, t, p)| (diff, d, t, p[0], p[1], p[2]))
                .prop_filter("an ill-conditioned determinant", |&(_, d, _, p0, p1, p2)| {
                    well_conditioned(b_determinant(v3(d), v3(p0), v3(p1), v3(p2)))
                })
                .boxed()
        },
        |(diff, d, t, p0, p1, p2)| rd::barycentric_derivatives(diff, d, t, p0, p1, p2),
        b_barycentric_derivatives,
    )
}

/// `rf_barycentric_w_derivatives`.
pub fn barycentric_w_derivatives() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "barycentric_w_derivatives",
        || derivatives2().prop_map(|b| (b,)).boxed(),
        |(b,)| rd::barycentric_w_derivatives(b),
        |&(b,)| {
            let (dx, dy) = (v2(b.dx), v2(b.dy));
            vec![-dx.0[0] - dx.0[1], -dy.0[0] - dy.0[1]]
        },
    )
}

/// `rf_texture_derivatives`: the enclosure of the UV gradients.
pub fn texture_derivatives() -> FunctionCheck<(Derivatives2, Vec2, Vec2, Vec2), Derivatives2> {
    enclosed(
        "texture_derivatives",
        || {
            (derivatives2(), uv_triangle())
                .prop_map(|(b, t)| (b, t[0], t[1], t[2]))
                .boxed()
        },
        |(b, t0, t1, t2)| rd::texture_derivatives(b, t0, t1, t2),
        |&(b, t0, t1, t2)| {
            let (dx, dy) = b_texture_derivatives(b, t0, t1, t2);
            b_derivatives2(dx, dy)
        },
    )
}

/// `rf_texel_derivatives`.
pub fn texel_derivatives() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "texel_derivatives",
        || {
            (derivatives2(), uv_triangle(), (pixels(), pixels()))
                .prop_map(|(b, t, (w, h))| (b, t[0], t[1], t[2], Vec2::new(w, h)))
                .boxed()
        },
        |(b, t0, t1, t2, size)| rd::texel_derivatives(b, t0, t1, t2, size),
        |&(b, t0, t1, t2, size)| {
            let (dx, dy) = b_texture_derivatives(b, t0, t1, t2);
            let size = v2(size.max(Vec2::ONE));
            b_derivatives2(dx * size, dy * size)
        },
    )
}

/// `rf_secondary_origin_derivatives`.
pub fn secondary_origin_derivatives() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "secondary_origin_derivatives",
        || {
            (derivatives2(), triangle())
                .prop_map(|(b, p)| (b, p[0], p[1], p[2]))
                .boxed()
        },
        |(b, p0, p1, p2)| rd::secondary_origin_derivatives(b, p0, p1, p2),
        b_secondary_origin_derivatives,
    )
}

/// `rf_lod_isotropic`: the enclosure of the LOD.
pub fn lod_isotropic() -> FunctionCheck<(Derivatives2,), f32> {
    enclosed(
        "lod_isotropic",
        || derivatives2().prop_map(|g| (g,)).boxed(),
        |(g,)| rd::lod_isotropic(g),
        |&(g,)| vec![b_lod_isotropic(g)],
    )
}

/// `rf_lod_box`.
pub fn lod_box() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "lod_box",
        || derivatives2().prop_map(|g| (g,)).boxed(),
        |(g,)| rd::lod_box(g),
        |&(g,)| vec![b_lod_box(g)],
    )
}

/// `rf_sample_grad_gradients`.
pub fn sample_grad_gradients() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "sample_grad_gradients",
        || (derivatives2(), -1.0f32..4.0).boxed(),
        |(g, scale)| rd::sample_grad_gradients(g, scale),
        |&(g, scale)| {
            let scale = s(scale.max(0.0));
            b_derivatives2(v2(g.dx) * scale, v2(g.dy) * scale)
        },
    )
}

/// `rf_normal_derivatives`.
pub fn normal_derivatives() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "normal_derivatives",
        || {
            (
                (unit_vec3(), unit_vec3(), unit_vec3()),
                (-1.0f32..2.0, -1.0f32..2.0),
                derivatives2(),
            )
                .prop_map(|((n0, n1, n2), (u, v), b)| (n0, n1, n2, Vec2::new(u, v), b))
                .boxed()
        },
        |(n0, n1, n2, uv, b)| rd::normal_derivatives(n0, n1, n2, uv, b),
        b_normal_derivatives,
    )
}

/// `rf_reflect_ray_diff`.
pub fn reflect_ray_diff() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "reflect_ray_diff",
        || {
            (ray_diff(), normal_and_direction(), derivatives3())
                .prop_map(|(diff, (n, d), dn)| (diff, d, n, dn))
                .boxed()
        },
        |(diff, d, n, dn)| rd::reflect_ray_diff(diff, d, n, dn),
        b_reflect_ray_diff,
    )
}

/// `rf_refract_ray_diff`.
pub fn refract_ray_diff() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "refract_ray_diff",
        // Within rounding of the critical angle (the enclosure of `k` contains 0) either branch is
        // right and the flag's tolerance would be vacuous: those cases are checked separately.
        || {
            let eta = prop_oneof![4 => 0.3f32..3.0, 1 => Just(1.0f32), 1 => Just(0.0f32), 1 => 0.0f32..0.01];
            (ray_diff(), normal_and_direction(), derivatives3(), eta)
                .prop_map(|(diff, (n, d), dn, eta)| (diff, d, n, dn, eta))
                .prop_filter("within rounding of the critical angle", |args| {
                    !b_refraction_determinant(args).contains_zero()
                })
                .boxed()
        },
        |(diff, d, n, dn, eta)| rd::refract_ray_diff(diff, d, n, dn, eta),
        b_refract_ray_diff,
    )
}

/// `rf_gbuffer_ray_diff`.
pub fn gbuffer_ray_diff() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "gbuffer_ray_diff",
        // The neighbour choice compares correctly rounded differences: the device makes the same
        // choice as the mirror, so only the chosen branch is enclosed.
        || {
            (
                gbuffer_sample(),
                (gbuffer_sample(), gbuffer_sample()),
                (gbuffer_sample(), gbuffer_sample()),
                magnitude(),
            )
                .prop_map(|(c, (r, l), (b, a), eps)| (c, r, l, b, a, eps))
                .boxed()
        },
        |(c, r, l, b, a, eps)| rd::gbuffer_ray_diff(c, r, l, b, a, eps),
        b_gbuffer_ray_diff,
    )
}

/// `rf_tangent_plane_offsets`.
pub fn tangent_plane_offsets() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "tangent_plane_offsets",
        || {
            (normal_and_direction(), (unit_vec3(), unit_vec3()), distance())
                .prop_map(|((n, rd), (rdx, rdy), t)| (rd, rdx, rdy, t, n))
                .boxed()
        },
        |(rd, rdx, rdy, t, n)| rd::tangent_plane_offsets(rd, rdx, rdy, t, n),
        |&(r, rdx, rdy, t, n)| {
            let dx = b_tangent_plane_offset(r, rdx, t, n);
            let dy = b_tangent_plane_offset(r, rdy, t, n);
            b_derivatives3(dx, dy)
        },
    )
}

/// `rf_planar_mapping_gradients`.
pub fn planar_mapping_gradients() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "planar_mapping_gradients",
        || {
            (derivatives3(), (-10.0f32..10.0, -10.0f32..10.0))
                .prop_map(|(dp, (a, b))| (dp, Vec2::new(a, b)))
                .boxed()
        },
        |(dp, scale)| rd::planar_mapping_gradients(dp, scale),
        |&(dp, scale)| {
            let project = |v: Vec3| v2(Vec2::new(v.x, v.z)) * v2(scale);
            b_derivatives2(project(dp.dx), project(dp.dy))
        },
    )
}

/// `rf_triplanar_weights`.
pub fn triplanar_weights() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "triplanar_weights",
        || {
            let normal = prop_oneof![8 => unit_vec3(), 1 => Just(Vec3::ZERO)];
            (normal, prop_oneof![4 => 0.0f32..16.0, 1 => -2.0f32..100.0]).boxed()
        },
        |(normal, sharpness)| rd::triplanar_weights(normal, sharpness),
        |&(normal, sharpness)| b_triplanar_weights(normal, sharpness),
    )
}

/// `rf_triplanar_gradients`.
pub fn triplanar_gradients() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "triplanar_gradients",
        || (derivatives3(), -10.0f32..10.0).boxed(),
        |(dp, scale)| rd::triplanar_gradients(dp, scale),
        |&(dp, scale)| {
            let (dx, dy) = (v3(dp.dx) * s(scale), v3(dp.dy) * s(scale));
            let pick = |v: V3, a: usize, b: usize| V([v.0[a], v.0[b]]);
            let planes = [(1, 2), (2, 0), (0, 1)];
            let all: Vec<I> = planes
                .iter()
                .flat_map(|&(a, b)| b_derivatives2(pick(dx, a, b), pick(dy, a, b)))
                .collect();
            all
        },
    )
}

/// `rf_intersect_triangle_plane`.
pub fn intersect_triangle_plane() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "intersect_triangle_plane",
        || {
            (vec3(), any_direction(), triangle())
                .prop_map(|(o, d, p)| (o, d, p[0], p[1], p[2]))
                .prop_filter("an ill-conditioned determinant", |&(_, d, p0, p1, p2)| {
                    well_conditioned(b_determinant(v3(d), v3(p0), v3(p1), v3(p2)))
                })
                .boxed()
        },
        |(o, d, p0, p1, p2)| rd::intersect_triangle_plane(o, d, p0, p1, p2),
        |&(o, d, p0, p1, p2)| b_intersect_triangle_plane(v3(o), v3(d), v3(p0), v3(p1), v3(p2)).components(),
    )
}

/// `rf_barycentric_offsets`: the enclosure of the signed differences.
pub fn barycentric_offsets() -> FunctionCheck<OffsetArgs, Derivatives3> {
    enclosed(
        "barycentric_offsets",
        // Where a neighbour ray is parallel to the triangle plane within rounding (its determinant
        // `k` encloses 0), the device and the mirror may clamp to opposite +-DIFF_MAX_VALUE, and
        // the enclosure (clamped to that range) is 2 * DIFF_MAX_VALUE wide: either side is right.
        // Those cases are checked separately; here both determinants are well-conditioned, and
        // origins stay below 1e5 (`F32_ORIGIN_EXPONENT`), where `O + direction` keeps the
        // direction; beyond, the ray_diff_f64 module is the tool.
        || well_conditioned_offset_args(F32_ORIGIN_EXPONENT),
        |(m, o, p0, p1, p2, x, y, b)| rd::barycentric_offsets(m, o, p0, p1, p2, x, y, b),
        |a| {
            let (dx, dy) = b_barycentric_offsets(a);
            b_derivatives3(dx, dy)
        },
    )
}

/// `rf_barycentric_deltas`: the enclosure of the deltas.
pub fn barycentric_deltas() -> FunctionCheck<OffsetArgs, Vec3> {
    enclosed(
        "barycentric_deltas",
        || well_conditioned_offset_args(F32_ORIGIN_EXPONENT),
        |(m, o, p0, p1, p2, x, y, b)| rd::barycentric_deltas(m, o, p0, p1, p2, x, y, b),
        |a| {
            let (dx, dy) = b_barycentric_offsets(a);
            (dx.abs() + dy.abs()).components()
        },
    )
}

/// `rf_uv_gradients_from_offsets`: the enclosure of the UV gradients.
pub fn uv_gradients_from_offsets() -> FunctionCheck<(Derivatives3, Vec2, Vec2, Vec2), Derivatives2> {
    enclosed(
        "uv_gradients_from_offsets",
        || {
            (derivatives3(), uv_triangle())
                .prop_map(|(o, uv)| (o, uv[0], uv[1], uv[2]))
                .boxed()
        },
        |(o, uv0, uv1, uv2)| rd::uv_gradients_from_offsets(o, uv0, uv1, uv2),
        |&(o, uv0, uv1, uv2)| {
            let sum = |w: Vec3| v2(uv0) * s(w.x) + v2(uv1) * s(w.y) + v2(uv2) * s(w.z);
            b_derivatives2(sum(o.dx), sum(o.dy))
        },
    )
}

/// `rf_cone_barycentric_deltas`: the enclosure of the deltas.
pub fn cone_barycentric_deltas() -> FunctionCheck<(f32, Vec3, Vec3, Vec3), Vec3> {
    enclosed(
        "cone_barycentric_deltas",
        || {
            (scalar(), triangle())
                .prop_map(|(f, p)| (f, p[0], p[1], p[2]))
                .boxed()
        },
        |(f, p0, p1, p2)| rd::cone_barycentric_deltas(f, p0, p1, p2),
        b_cone_barycentric_deltas,
    )
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
fn b_anisotropic_cone_axes(width: f32, normal: V3, direction: V3) -> (V3, V3) {
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

/// The arguments of `anisotropic_cone_gradients`: width, direction, the triangle, its UVs.
pub type ConeGradientArgs = (f32, Vec3, Vec3, Vec3, Vec3, Vec2, Vec2, Vec2);

fn b_anisotropic_cone_gradients(&(width, direction, p0, p1, p2, uv0, uv1, uv2): &ConeGradientArgs) -> Vec<I> {
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

fn b_ray_diff_from_cone(&(cone, direction): &(Vec2, Vec3)) -> Vec<I> {
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

fn b_cone_from_ray_diff(&(diff, direction): &(RayDiff, Vec3)) -> Vec<I> {
    let x = b_transverse_cone(diff.d_origin_dx, diff.d_direction_dx, direction);
    let y = b_transverse_cone(diff.d_origin_dy, diff.d_direction_dy, direction);
    vec![I::c(0.5) * (x[0] + y[0]), I::c(0.5) * (x[1] + y[1])]
}

/// A triangle and a unit direction: random, or meeting the triangle's plane at a cosine from
/// head-on to grazing.
fn triangle_and_direction() -> BoxedStrategy<([Vec3; 3], Vec3)> {
    let cosine = prop_oneof![
        3 => 0.0f32..1.0,
        1 => (-6.0f32..-2.0).prop_map(|e| 10f32.powf(e)),
        1 => Just(0.0f32),
        1 => Just(1.0f32),
    ];
    (triangle(), unit_vec3(), cosine, any::<bool>())
        .prop_map(|(p, random, cosine, relative)| {
            let normal = (p[1] - p[0]).cross(p[2] - p[0]).try_normalize();
            let direction = match normal {
                Some(n) if relative => {
                    let tangent = n
                        .cross(random)
                        .try_normalize()
                        .unwrap_or_else(|| n.any_orthonormal_vector());
                    (tangent * (1.0 - cosine * cosine).max(0.0).sqrt() - n * cosine).normalize()
                }
                _ => random,
            };
            (p, direction)
        })
        .boxed()
}

/// `rf_anisotropic_cone_axes`: the enclosure of the axes.
pub fn anisotropic_cone_axes() -> FunctionCheck<(f32, Vec3, Vec3), Derivatives3> {
    enclosed(
        "anisotropic_cone_axes",
        || {
            (scalar(), normal_and_direction(), any::<bool>())
                .prop_map(|(width, (n, d), behind)| (width, if behind { -n } else { n }, d))
                .boxed()
        },
        |(width, n, d)| rd::anisotropic_cone_axes(width, n, d),
        |&(width, n, d)| {
            let (major, minor) = b_anisotropic_cone_axes(width, v3(n), v3(d));
            b_derivatives3(major, minor)
        },
    )
}

/// `rf_anisotropic_cone_gradients`: the enclosure of the UV gradients.
pub fn anisotropic_cone_gradients() -> FunctionCheck<ConeGradientArgs, Derivatives2> {
    enclosed(
        "anisotropic_cone_gradients",
        || {
            (scalar(), triangle_and_direction(), uv_triangle())
                .prop_map(|(w, (p, d), uv)| (w, d, p[0], p[1], p[2], uv[0], uv[1], uv[2]))
                .boxed()
        },
        |(w, d, p0, p1, p2, uv0, uv1, uv2)| rd::anisotropic_cone_gradients(w, d, p0, p1, p2, uv0, uv1, uv2),
        b_anisotropic_cone_gradients,
    )
}

/// `rf_ray_diff_from_cone`: the enclosure of the differential.
pub fn ray_diff_from_cone() -> FunctionCheck<(Vec2, Vec3), RayDiff> {
    enclosed(
        "ray_diff_from_cone",
        || {
            ((scalar(), angle()), unit_vec3())
                .prop_map(|((w, a), d)| (Vec2::new(w, a), d))
                .boxed()
        },
        |(cone, d)| rd::ray_diff_from_cone(cone, d),
        b_ray_diff_from_cone,
    )
}

/// `rf_cone_from_ray_diff`: the enclosure of the cone.
pub fn cone_from_ray_diff() -> FunctionCheck<(RayDiff, Vec3), Vec2> {
    enclosed(
        "cone_from_ray_diff",
        || (ray_diff(), unit_vec3()).boxed(),
        |(diff, d)| rd::cone_from_ray_diff(diff, d),
        b_cone_from_ray_diff,
    )
}

/// Every function's checks, in the module's function order.
pub fn entries() -> Vec<Registered<Entry>> {
    registered_checks!(
        Module::RayDiff,
        [
            eye_ray_direction,
            normalized_derivative,
            eye_ray_diff,
            eye_ray_direction_from_matrices,
            eye_ray_diff_from_matrices,
            pixel_directions,
            transfer,
            barycentric_derivatives,
            barycentric_w_derivatives,
            texture_derivatives,
            texel_derivatives,
            secondary_origin_derivatives,
            lod_isotropic,
            lod_box,
            sample_grad_gradients,
            normal_derivatives,
            reflect_ray_diff,
            refract_ray_diff,
            gbuffer_ray_diff,
            tangent_plane_offsets,
            planar_mapping_gradients,
            triplanar_weights,
            triplanar_gradients,
            intersect_triangle_plane,
            barycentric_offsets,
            barycentric_deltas,
            uv_gradients_from_offsets,
            cone_barycentric_deltas,
            anisotropic_cone_axes,
            anisotropic_cone_gradients,
            ray_diff_from_cone,
            cone_from_ray_diff
        ]
    )
}
