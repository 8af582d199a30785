//! Input strategies shared by the agreement checks.
//!
//! The tested domain: every magnitude is 0 or lies in `[1e-12, 1e12]` (scene coordinates, distances,
//! widths, curvatures), unit vectors are unit length, angles are radians. Each strategy mixes the
//! ordinary range with the edges of that domain: zero, tiny and huge values, grazing angles and
//! degenerate triangles.
//!
//! Floats in a range are drawn with `shader_proptest::draw::uniform` and choices with
//! `shader_proptest::one_of!`, which cost a fraction of proptest's float ranges and `prop_oneof!`
//! (generating the cases is most of a check's work on a fast device).

use glam::{Mat4, Vec2, Vec3};
use proptest::prelude::*;
use proptest::strategy::BoxedStrategy;
use shader_proptest::draw::uniform;
use shader_proptest::one_of;
use std::fmt::Debug;

/// Largest magnitude in the tested domain.
pub const HUGE: f32 = 1.0e12;
/// Smallest non-zero magnitude in the tested domain.
pub const TINY: f32 = 1.0e-12;

fn signed(magnitude: BoxedStrategy<f32>) -> BoxedStrategy<f32> {
    (magnitude, any::<bool>())
        .prop_map(|(m, negative)| if negative { -m } else { m })
        .boxed()
}

/// A non-negative magnitude: mostly ordinary, sometimes 0, tiny or huge (log-uniform at the edges).
pub fn magnitude() -> BoxedStrategy<f32> {
    one_of![
        6 => uniform(0.0, 1.0e3),
        1 => Just(0.0f32),
        1 => uniform(-12.0, -3.0).prop_map(|e| 10f32.powf(e)),
        1 => uniform(3.0, 12.0).prop_map(|e| 10f32.powf(e)),
    ]
    .boxed()
}

/// A signed scalar over the whole domain.
pub fn scalar() -> BoxedStrategy<f32> {
    signed(magnitude())
}

/// A distance along a ray: non-negative, from 0 to huge.
pub fn distance() -> BoxedStrategy<f32> {
    magnitude()
}

/// An angle in radians: mostly small (pixel spreads), sometimes 0, large, or negative (converging).
pub fn angle() -> BoxedStrategy<f32> {
    one_of![
        4 => uniform(-9.0, -1.0).prop_map(|e| 10f32.powf(e)),
        2 => uniform(-3.2, 3.2),
        1 => Just(0.0f32),
        1 => uniform(-9.0, -1.0).prop_map(|e| -(10f32.powf(e))),
    ]
    .boxed()
}

/// A vertical field of view in radians, including 0, negative and wider-than-clamp values.
pub fn fov_y() -> BoxedStrategy<f32> {
    one_of![
        6 => uniform(0.05, 3.0),
        1 => Just(0.0f32),
        1 => uniform(-9.0, -2.0).prop_map(|e| 10f32.powf(e)),
        1 => uniform(3.0, 4.0),
        1 => uniform(-3.0, 0.0),
    ]
    .boxed()
}

/// An image or texture size in pixels: ordinary sizes, 0, 1, fractions and negatives (clamped).
pub fn pixels() -> BoxedStrategy<f32> {
    one_of![
        6 => (1u32..16384).prop_map(|h| h as f32),
        1 => Just(0.0f32),
        1 => Just(1.0f32),
        1 => uniform(-100.0, 1.0),
    ]
    .boxed()
}

/// An image or texture size: both sides from [`pixels`].
pub(crate) fn image_size() -> BoxedStrategy<Vec2> {
    vec2_of(pixels(), pixels())
}

/// A 2-vector with components drawn from `x` and `y`.
pub(crate) fn vec2_of(
    x: impl Strategy<Value = f32> + 'static,
    y: impl Strategy<Value = f32> + 'static,
) -> BoxedStrategy<Vec2> {
    (x, y).prop_map(|(x, y)| Vec2::new(x, y)).boxed()
}

/// A vector with components from [`scalar`].
pub fn vec3() -> BoxedStrategy<Vec3> {
    (scalar(), scalar(), scalar())
        .prop_map(|(x, y, z)| Vec3::new(x, y, z))
        .boxed()
}

/// A vector with ordinary components (a position or derivative of moderate size).
pub fn small_vec3() -> BoxedStrategy<Vec3> {
    (uniform(-10.0, 10.0), uniform(-10.0, 10.0), uniform(-10.0, 10.0))
        .prop_map(|(x, y, z)| Vec3::new(x, y, z))
        .boxed()
}

/// A unit vector (axis-aligned ones included).
pub fn unit_vec3() -> BoxedStrategy<Vec3> {
    one_of![
        8 => (uniform(-1.0, 1.0), uniform(0.0, std::f32::consts::TAU)).prop_map(|(z, phi)| {
            let r = (1.0 - z * z).max(0.0).sqrt();
            Vec3::new(r * phi.cos(), r * phi.sin(), z).normalize()
        }),
        1 => prop::sample::select(vec![Vec3::X, Vec3::Y, Vec3::Z, Vec3::NEG_X, Vec3::NEG_Y, Vec3::NEG_Z]),
    ]
    .boxed()
}

/// A unit normal and a unit ray direction, from head-on to grazing (|dot| down to 0).
pub fn normal_and_direction() -> BoxedStrategy<(Vec3, Vec3)> {
    let cosine = one_of![
        4 => uniform(0.0, 1.0),
        2 => uniform(-8.0, -2.0).prop_map(|e| 10f32.powf(e)),
        1 => Just(0.0f32),
        1 => Just(1.0f32),
    ];
    (unit_vec3(), unit_vec3(), cosine)
        .prop_map(|(normal, other, cosine)| {
            let tangent = normal
                .cross(other)
                .try_normalize()
                .unwrap_or_else(|| normal.any_orthonormal_vector());
            let sine = (1.0 - cosine * cosine).max(0.0).sqrt();
            (normal, (tangent * sine - normal * cosine).normalize())
        })
        .boxed()
}

/// A triangle: ordinary, huge, tiny, a sliver, or with a repeated vertex (zero area).
pub fn triangle() -> BoxedStrategy<[Vec3; 3]> {
    let ordinary = (small_vec3(), small_vec3(), small_vec3()).prop_map(|(a, b, c)| [a, b, c]);
    let scaled = (
        ordinary.clone(),
        one_of![Just(TINY), Just(1.0e-6f32), Just(1.0e6f32), Just(1.0e11f32)],
    )
        .prop_map(|(t, s)| t.map(|p| p * s));
    let sliver = (small_vec3(), small_vec3(), uniform(0.0, 1.0), uniform(-6.0, -2.0))
        .prop_map(|(a, b, along, e)| [a, b, a.lerp(b, along) + Vec3::splat(10f32.powf(e))]);
    let degenerate = (small_vec3(), small_vec3()).prop_map(|(a, b)| [a, b, a]);
    one_of![5 => ordinary, 1 => scaled, 1 => sliver, 1 => degenerate].boxed()
}

/// A triangle and a unit direction: random, or meeting the triangle's plane at a cosine from
/// head-on to grazing.
pub fn triangle_and_direction() -> BoxedStrategy<([Vec3; 3], Vec3)> {
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

/// UV coordinates of a triangle: ordinary, tiny, collinear or all equal.
pub fn uv_triangle() -> BoxedStrategy<[Vec2; 3]> {
    let uv = || (uniform(-2.0, 2.0), uniform(-2.0, 2.0)).prop_map(|(u, v)| Vec2::new(u, v));
    let ordinary = (uv(), uv(), uv()).prop_map(|(a, b, c)| [a, b, c]);
    let tiny = (uv(), uv(), uv()).prop_map(|(a, b, c)| [a, a + (b - a) * 1.0e-6, a + (c - a) * 1.0e-6]);
    let collinear = (uv(), uv(), uniform(0.0, 1.0)).prop_map(|(a, b, t)| [a, b, a.lerp(b, t)]);
    let equal = uv().prop_map(|a| [a, a, a]);
    one_of![5 => ordinary, 1 => tiny, 1 => collinear, 1 => equal].boxed()
}

/// The inverse projection matrix of a perspective camera, OpenGL's or Vulkan's (y-flipped): field of
/// view, aspect ratio and near plane drawn, the far plane at 1000 times the near one.
pub fn perspective_proj_inv() -> BoxedStrategy<Mat4> {
    (
        uniform(0.05, 3.0),
        uniform(0.2, 5.0),
        uniform(0.01, 10.0),
        any::<bool>(),
    )
        .prop_map(|(fov, aspect, near, vulkan)| {
            let projection = if vulkan {
                glam::camera::rh::proj::vulkan::perspective(fov, aspect, near, near * 1000.0)
            } else {
                glam::camera::rh::proj::opengl::perspective(fov, aspect, near, near * 1000.0)
            };
            projection.inverse()
        })
        .boxed()
}

/// The arguments of a function of one parameter: a 1-tuple of `strategy`'s values.
pub(crate) fn one_argument<T: Debug + 'static>(
    strategy: impl Strategy<Value = T> + 'static,
) -> BoxedStrategy<(T,)> {
    strategy.prop_map(|value| (value,)).boxed()
}

/// `first`, then the three corners of a triangle drawn from `corners` ([`triangle`]'s vertices,
/// [`uv_triangle`]'s UVs) as three arguments.
pub(crate) fn with_corners<T: Debug + 'static, C: Copy + Debug + 'static>(
    first: impl Strategy<Value = T> + 'static,
    corners: BoxedStrategy<[C; 3]>,
) -> BoxedStrategy<(T, C, C, C)> {
    (first, corners)
        .prop_map(|(first, c)| (first, c[0], c[1], c[2]))
        .boxed()
}
