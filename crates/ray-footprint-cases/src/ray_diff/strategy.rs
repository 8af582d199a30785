//! Case strategies of the ray_diff checks: pixels and cameras, differentials and derivatives,
//! hits, G-buffer samples and the re-intersection inputs, each drawn where the function is
//! well-conditioned (ill-conditioned inputs are the edge-case suite's).

use super::enclosure::{
    determinant_well_conditioned, offsets_well_conditioned, PARALLEL_WITHIN_ROUNDING,
    REINTERSECTION_ILL_CONDITIONED,
};
use super::{Camera, Matrices, OffsetArgs};
use crate::strategy::{
    distance, fov_y, image_size, normal_and_direction, perspective_proj_inv, scalar, small_vec3, triangle,
    unit_vec3, vec2_of, vec3,
};
use glam::{Mat4, Quat, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{Derivatives2, Derivatives3, GBufferSample, RayDiff};
use shader_proptest::draw::uniform;
use shader_proptest::one_of;

/// A pixel inside an image (or, sometimes, outside it) and the image size (from [`image_size`]).
fn pixel_and_size() -> BoxedStrategy<(Vec2, Vec2)> {
    (
        image_size(),
        vec2_of(uniform(0.0, 1.0), uniform(0.0, 1.0)),
        any::<bool>(),
    )
        .prop_map(|(size, fraction, outside)| {
            let pixel = if outside {
                fraction * 40000.0 - 20000.0
            } else {
                (fraction * size.max(Vec2::ONE)).floor()
            };
            (pixel, size)
        })
        .boxed()
}

/// A rotation (axis-aligned ones included).
fn rotation() -> BoxedStrategy<Quat> {
    (unit_vec3(), uniform(0.0, std::f32::consts::TAU))
        .prop_map(|(axis, angle)| Quat::from_axis_angle(axis, angle))
        .boxed()
}

/// A camera basis: right, up and view (towards the eye), orthonormal up to rounding.
fn camera_basis() -> BoxedStrategy<(Vec3, Vec3, Vec3)> {
    rotation()
        .prop_map(|q| (q * Vec3::X, q * Vec3::Y, q * Vec3::Z))
        .boxed()
}

/// A rigid transform with a translation from [`vec3`] (a camera-to-world matrix).
fn rigid() -> BoxedStrategy<Mat4> {
    (rotation(), vec3())
        .prop_map(|(q, t)| Mat4::from_rotation_translation(q, t))
        .boxed()
}

/// An inverse projection matrix: perspective (OpenGL or Vulkan, y-flipped), or arbitrary with
/// moderate entries.
fn proj_inv() -> BoxedStrategy<Mat4> {
    let arbitrary =
        prop::array::uniform16(uniform(-10.0, 10.0)).prop_map(|cols| Mat4::from_cols_array(&cols));
    one_of![3 => perspective_proj_inv(), 1 => arbitrary].boxed()
}

/// A differential vector: ordinary, small (pixel-sized), or anywhere in the domain.
pub(super) fn differential_vec3() -> BoxedStrategy<Vec3> {
    one_of![
        3 => small_vec3(),
        2 => small_vec3().prop_map(|v| v * 1.0e-4),
        1 => vec3(),
        1 => Just(Vec3::ZERO),
    ]
    .boxed()
}

/// A ray differential: origin differentials from `differential_vec3`, direction differentials
/// ordinary or pixel-sized.
pub(super) fn ray_diff() -> BoxedStrategy<RayDiff> {
    let direction = || one_of![small_vec3(), small_vec3().prop_map(|v| v * 1.0e-4)];
    (differential_vec3(), differential_vec3(), direction(), direction())
        .prop_map(|(a, b, c, d)| RayDiff::new(a, b, c, d))
        .boxed()
}

/// `(du, dv)` derivatives: ordinary, tiny or huge.
pub(super) fn derivatives2() -> BoxedStrategy<Derivatives2> {
    let component = || one_of![3 => uniform(-10.0, 10.0), 1 => scalar()];
    (
        vec2_of(component(), component()),
        vec2_of(component(), component()),
    )
        .prop_map(|(dx, dy)| Derivatives2::new(dx, dy))
        .boxed()
}

/// Vector derivatives from [`differential_vec3`].
pub(super) fn derivatives3() -> BoxedStrategy<Derivatives3> {
    (differential_vec3(), differential_vec3())
        .prop_map(|(dx, dy)| Derivatives3::new(dx, dy))
        .boxed()
}

/// A hit's barycentrics `(w, u, v)`, inside the triangle or not, summing to 1 up to rounding.
fn hit_barycentrics() -> BoxedStrategy<Vec3> {
    (uniform(-1.0, 2.0), uniform(-1.0, 2.0))
        .prop_map(|(u, v)| Vec3::new(1.0 - u - v, u, v))
        .boxed()
}

/// A world-to-object matrix: rotation, uniform scale in `[1e-3, 1e3]`, translation up to
/// `10^max_exponent`.
fn world_to_object(max_exponent: f32) -> BoxedStrategy<Mat4> {
    (
        rotation(),
        uniform(-3.0, 3.0),
        small_vec3(),
        uniform(-9.0, max_exponent + 1.0),
    )
        .prop_map(|(q, scale, t, e)| {
            Mat4::from_scale_rotation_translation(Vec3::splat(10f32.powf(scale)), q, t * 10f32.powf(e) / 10.0)
        })
        .boxed()
}

/// A world ray origin up to `10^max_exponent`.
fn world_origin(max_exponent: f32) -> BoxedStrategy<Vec3> {
    (small_vec3(), uniform(-12.0, max_exponent - 1.0))
        .prop_map(|(v, e)| v * 10f32.powf(e))
        .boxed()
}

/// The arguments of `intersect_triangle_plane`: an origin and a direction (unit or not) from the
/// whole domain, and a triangle, whose determinant is well-conditioned.
pub(super) fn plane_intersections() -> BoxedStrategy<(Vec3, Vec3, Vec3, Vec3, Vec3)> {
    (vec3(), any_direction(), triangle())
        .prop_map(|(o, d, p)| (o, d, p[0], p[1], p[2]))
        .prop_filter(PARALLEL_WITHIN_ROUNDING, |&(_, d, p0, p1, p2)| {
            determinant_well_conditioned(d, p0, p1, p2)
        })
        .boxed()
}

/// A unit direction or a moderately scaled one (functions that take non-normalized directions).
pub(super) fn any_direction() -> BoxedStrategy<Vec3> {
    one_of![3 => unit_vec3(), 1 => small_vec3()].boxed()
}

/// A G-buffer pixel: unit eye direction, distance, unit normal.
pub(super) fn gbuffer_sample() -> BoxedStrategy<GBufferSample> {
    (normal_and_direction(), distance())
        .prop_map(|((normal, eye_direction), distance)| GBufferSample {
            eye_direction,
            distance,
            normal,
        })
        .boxed()
}

/// [`offset_args`] where both intersections are well-conditioned.
pub(super) fn well_conditioned_offset_args(max_exponent: f32) -> BoxedStrategy<OffsetArgs> {
    offset_args(max_exponent)
        .prop_filter(REINTERSECTION_ILL_CONDITIONED, offsets_well_conditioned)
        .boxed()
}

/// Largest exponent of the world origin and translation for the f32 re-intersection checks. Beyond
/// about 1e6 the f32 sum `O + direction` loses the unit direction entirely and both sides compute
/// rounding noise (the f64 variant exists for that range, and its checks go to 1e8).
pub(super) const F32_ORIGIN_EXPONENT: f32 = 5.0;

/// Inputs of the re-intersection functions: a transform and a world origin up to
/// `10^max_exponent`, an object-space triangle, two unit neighbour directions and hit barycentrics.
pub(crate) fn offset_args(max_exponent: f32) -> BoxedStrategy<OffsetArgs> {
    (
        (world_to_object(max_exponent), world_origin(max_exponent)),
        triangle(),
        (unit_vec3(), unit_vec3()),
        hit_barycentrics(),
    )
        .prop_map(|((w2o, origin), p, (x, y), hit)| (w2o, origin, p[0], p[1], p[2], x, y, hit))
        .boxed()
}

pub(super) fn camera() -> BoxedStrategy<Camera> {
    (pixel_and_size(), fov_y(), camera_basis())
        .prop_map(|((pixel, size), fov, (r, u, v))| (pixel, size, fov, r, u, v))
        .boxed()
}

/// Narrowest field of view the eye-ray differential checks use: below it Vulkan's allowance for
/// `tan` (2^-11 absolute, inherited from `sin / cos`) exceeds 2% of `tan(fov / 2)`, and a camera
/// whose field of view is clamped to 0 has no differential to compare; those cameras are checked
/// separately (the degenerate table, the edge-case suite).
const MIN_DIFFERENTIAL_FOV: f32 = 0.05;

/// Why a camera is left out of the eye-ray differential checks ([`has_a_view`]).
pub(super) const NARROW_VIEW: &str = "a field of view below MIN_DIFFERENTIAL_FOV (0.05), clamped to 0 or \
     so narrow that Vulkan's tan allowance exceeds 2% of tan(fov_y / 2)";

/// Whether a camera's field of view is at least [`MIN_DIFFERENTIAL_FOV`].
pub(super) fn has_a_view(&(_, _, fov, ..): &Camera) -> bool {
    fov >= MIN_DIFFERENTIAL_FOV
}

pub(super) fn matrices() -> BoxedStrategy<Matrices> {
    (pixel_and_size(), rigid(), proj_inv())
        .prop_map(|((pixel, size), view_inv, proj_inv)| (pixel, size, view_inv, proj_inv))
        .boxed()
}

/// A triangle and a unit direction: random, or meeting the triangle's plane at a cosine from
/// head-on to grazing.
pub(super) fn triangle_and_direction() -> BoxedStrategy<([Vec3; 3], Vec3)> {
    let cosine = one_of![
        3 => uniform(0.0, 1.0),
        1 => uniform(-6.0, -2.0).prop_map(|e| 10f32.powf(e)),
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
