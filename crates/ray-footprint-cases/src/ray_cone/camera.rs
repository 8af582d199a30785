//! Records of `ray_cone`: Camera cones: packing, the pixel spread angle and the cones of the camera models.

use super::bound::tan_ratio_error;
use super::strategy::{packed_ray_cone, proj_inv, ray_cone};
use super::{reference, PinholeRayConeForRayArgs, MODULE};
use crate::degenerate::{cone, mirror, same, value, vulkan_inverse_projection, INF, NAN};
use crate::record::Record;
use crate::special::Perturb;
use crate::strategy::{angle, fov_y, magnitude, normal_and_direction, one_argument, pixels, scalar};
use glam::{Mat4, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, PackedRayCone, RayCone, F16_MAX, MAX_FOV_Y, MIN_MAGNITUDE};
use shader_proptest::tolerance::{atan_error, dot_error, ulps};
use shader_proptest::{Args, Value};
use std::f32::consts::FRAC_PI_2;

/// `rf_pack_ray_cone`.
pub fn pack_ray_cone() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "pack_ray_cone",
        |(cone,)| rc::pack_ray_cone(cone),
        || one_argument(ray_cone()),
    )
    // The rounding mode of packHalf2x16 is the implementation's: one f16 ULP (2^-10
    // relative, 2^-24 absolute for f16 subnormals).
    .bound(|_, _, expected| (expected.abs() / 1024.0).max(1.0 / 16_777_216.0))
    .reference(reference::pack_ray_cone())
    .fuzz(|d| (d.cone(),))
    .range(-rc::F16_MAX, rc::F16_MAX, "unpacked half")
    .degenerate(vec![
        value(
            "values beyond f16 (1e9, -1e9)",
            "(F16_MAX, -F16_MAX), never infinite",
            (cone(1.0e9, -1.0e9),),
            vec![F16_MAX, -F16_MAX],
        ),
        value(
            "halfway between two f16 (1 + 2^-11)",
            "1 (ties to even)",
            (cone(1.0 + 1.0 / 2048.0, 0.0),),
            vec![1.0, 0.0],
        ),
        value(
            "below half the smallest f16 sub-normal (2^-26)",
            "0 (rounds to nearest)",
            (cone(1.0 / 67_108_864.0, -1.0 / 67_108_864.0),),
            vec![0.0, 0.0],
        ),
        mirror(
            "infinity in (width)",
            "CPU: (F16_MAX, spread)",
            (cone(INF, 0.5),),
            vec![F16_MAX, 0.5],
        ),
    ])
}

/// `rf_unpack_ray_cone`.
pub fn unpack_ray_cone() -> Record<impl Args + Perturb, impl Value> {
    // f16 to f32 is exact.
    Record::new(
        MODULE,
        "unpack_ray_cone",
        |(packed,)| rc::unpack_ray_cone(packed),
        || one_argument(packed_ray_cone()),
    )
    .reference(reference::unpack_ray_cone())
    .fuzz(|d| (d.packed_cone(),))
    .degenerate(vec![
        value("zero bits", "(0, 0)", (PackedRayCone(0),), vec![0.0, 0.0]),
        value(
            "largest finite f16 (0x7bff, 0xfbff)",
            "(F16_MAX, -F16_MAX)",
            (PackedRayCone(0xfbff_7bff),),
            vec![F16_MAX, -F16_MAX],
        ),
        value(
            "smallest f16 sub-normal (0x0001), negative zero (0x8000)",
            "(2^-24, -0), exact",
            (PackedRayCone(0x8000_0001),),
            vec![1.0 / 16_777_216.0, -0.0],
        ),
        mirror(
            "f16 infinity and NaN bits (0x7c00, 0x7e00)",
            "CPU: (inf, NaN)",
            (PackedRayCone(0x7e00_7c00),),
            vec![INF, NAN],
        ),
    ])
}

/// `rf_pixel_spread_angle`.
pub fn pixel_spread_angle() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "pixel_spread_angle",
        |(fov, height)| rc::pixel_spread_angle(fov, height),
        || (fov_y(), pixels()).boxed(),
    )
    // atan of the tan ratio: the ratio's error through atan, plus atan's 4096 ULP.
    .bound(|&(fov, height), _, _| {
        atan_error(
            rc::pixel_spread_angle_small(fov, height),
            tan_ratio_error(fov, height),
        )
    })
    .reference(reference::pixel_spread_angle())
    .fuzz(|d| (d.angle(), d.scalar()))
    .range(0.0, FRAC_PI_2, "spread angle")
    .degenerate(vec![
        same(
            "zero viewport (H = 0)",
            "as H = 1 (H is clamped to >= 1)",
            (1.0, 0.0),
            (1.0, 1.0),
        ),
        same(
            "negative viewport (H = -100)",
            "as H = 1",
            (1.0, -100.0),
            (1.0, 1.0),
        ),
        value("zero field of view", "0", (0.0, 1080.0), vec![0.0]),
        same(
            "fov_y = 4 (wider than MAX_FOV_Y)",
            "as fov_y = MAX_FOV_Y (3.1)",
            (4.0, 1080.0),
            (MAX_FOV_Y, 1080.0),
        ),
        mirror("NaN in (fov_y)", "CPU: NaN", (NAN, 1080.0), vec![NAN]),
        mirror("infinity in (H = +inf)", "CPU: 0", (1.0, INF), vec![0.0]),
    ])
}

/// `rf_pixel_spread_angle_small`.
pub fn pixel_spread_angle_small() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "pixel_spread_angle_small",
        |(fov, height)| rc::pixel_spread_angle_small(fov, height),
        || (fov_y(), pixels()).boxed(),
    )
    // tan's error (inherited from sin / cos) scaled by 2 / H.
    .bound(|&(fov, height), _, _| tan_ratio_error(fov, height))
    .reference(reference::pixel_spread_angle_small())
    .reference(reference::pixel_spread_angle_small_approximation())
    .fuzz(|d| (d.angle(), d.scalar()))
    .range(0.0, f32::MAX, "spread angle")
    .degenerate(vec![
        same("zero viewport (H = 0)", "as H = 1", (1.0, 0.0), (1.0, 1.0)),
        mirror(
            "NaN in (H)",
            "CPU: as H = 1 (Rust's `max` ignores NaN)",
            (1.0, NAN),
            vec![rc::pixel_spread_angle_small(1.0, 1.0)],
        ),
        mirror(
            "infinity in (fov_y = +inf)",
            "CPU: as fov_y = MAX_FOV_Y",
            (INF, 1080.0),
            vec![rc::pixel_spread_angle_small(MAX_FOV_Y, 1080.0)],
        ),
    ])
}

/// `rf_pixel_spread_angle_from_proj_inv`.
pub fn pixel_spread_angle_from_proj_inv() -> Record<impl Args + Perturb, impl Value> {
    let inverse_projection = vulkan_inverse_projection();
    Record::new(
        MODULE,
        "pixel_spread_angle_from_proj_inv",
        |(inverse_projection, height)| rc::pixel_spread_angle_from_proj_inv(inverse_projection, height),
        || (proj_inv(), pixels()).boxed(),
    )
    // The ratio 2|m|/H has one division (2.5 ULP) and the mirror's rounding; then atan.
    .bound(|&(inverse_projection, height), _, _| {
        let ratio = 2.0 * inverse_projection.y_axis.y.abs() / height.max(1.0);
        atan_error(ratio, ulps(3.5, ratio))
    })
    .reference(reference::pixel_spread_angle_from_proj_inv())
    .fuzz(|d| (d.mat4(), d.scalar()))
    .range(0.0, FRAC_PI_2, "spread angle")
    .degenerate(vec![
        same(
            "zero viewport (H = 0)",
            "as H = 1",
            (inverse_projection, 0.0),
            (inverse_projection, 1.0),
        ),
        value("zero matrix", "0", (Mat4::ZERO, 1080.0), vec![0.0]),
        mirror(
            "infinity in (`proj_inv[1][1]`)",
            "CPU: pi / 2",
            (Mat4::from_diagonal(glam::Vec4::new(1.0, INF, 1.0, 1.0)), 1080.0),
            vec![std::f32::consts::FRAC_PI_2],
        ),
    ])
}

/// `rf_pinhole_ray_cone`.
pub fn pinhole_ray_cone() -> Record<impl Args + Perturb, impl Value> {
    // No arithmetic.
    Record::new(
        MODULE,
        "pinhole_ray_cone",
        |(spread,)| rc::pinhole_ray_cone(spread),
        || one_argument(angle()),
    )
    .reference(reference::pinhole_ray_cone())
    .fuzz(|d| (d.angle(),))
    .degenerate(vec![
        value("zero spread", "(0, 0)", (0.0,), vec![0.0, 0.0]),
        value(
            "negative spread (-0.01)",
            "(0, -0.01), kept",
            (-0.01,),
            vec![0.0, -0.01],
        ),
        mirror("NaN in", "CPU: (0, NaN)", (NAN,), vec![0.0, NAN]),
    ])
}

/// `rf_pinhole_ray_cone_for_ray` (also used by the ray-tracing pipeline's test).
pub fn pinhole_ray_cone_for_ray() -> Record<PinholeRayConeForRayArgs, RayCone> {
    let x = Vec3::X;
    let z = Vec3::Z;
    let head_on = Vec3::NEG_Z;
    Record::new(
        MODULE,
        "pinhole_ray_cone_for_ray",
        |(spread, direction, view_axis)| rc::pinhole_ray_cone_for_ray(spread, direction, view_axis),
        // A view axis and a ray from on the axis to 90 degrees off it, or behind the camera.
        || {
            (angle(), normal_and_direction(), any::<bool>())
                .prop_map(|(spread, (normal, direction), behind)| {
                    (spread, direction, if behind { normal } else { -normal })
                })
                .boxed()
        },
    )
    // Width: exact. Spread: the dot product's rounding, through the clamp (which cannot widen
    // it), times |spread|, and the product's rounding on the device and in the mirror.
    .bound(|&(spread, direction, view_axis), index, expected| {
        if index == 0 {
            0.0
        } else {
            spread.abs() * dot_error(direction, view_axis) + ulps(2.0, expected)
        }
    })
    .reference(reference::pinhole_ray_cone_for_ray())
    .fuzz(|d| (d.angle(), d.unit(), d.unit()))
    .range(-3.2, 3.2, "width and spread")
    .degenerate(vec![
        value(
            "ray along the view axis",
            "(0, alpha)",
            (0.01, head_on, head_on),
            vec![0.0, 0.01],
        ),
        value(
            "ray at 90 degrees to the view axis",
            "(0, 0)",
            (0.01, x, head_on),
            vec![0.0, 0.0],
        ),
        same(
            "ray behind the camera (dot(d, axis) = -1)",
            "as at 90 degrees: the cosine is clamped to [0, 1]",
            (0.01, z, head_on),
            (0.01, x, head_on),
        ),
        same(
            "direction and axis of length 2 (dot = 4)",
            "as along the axis: never wider than alpha",
            (0.01, 2.0 * head_on, 2.0 * head_on),
            (0.01, head_on, head_on),
        ),
        value(
            "zero direction",
            "(0, 0)",
            (0.01, Vec3::ZERO, head_on),
            vec![0.0, 0.0],
        ),
        mirror(
            "NaN in (direction)",
            "CPU: (0, NaN) (Rust's `clamp` keeps NaN)",
            (0.01, Vec3::new(NAN, 0.0, -1.0), head_on),
            vec![0.0, NAN],
        ),
    ])
}

/// `rf_orthographic_ray_cone`.
pub fn orthographic_ray_cone() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "orthographic_ray_cone",
        |(view_height, height)| rc::orthographic_ray_cone(view_height, height),
        || (magnitude(), pixels()).boxed(),
    )
    // One division: 2.5 ULP on the device, 0.5 in the mirror.
    .bound(|_, _, expected| ulps(3.0, expected))
    .reference(reference::orthographic_ray_cone())
    .fuzz(|d| (d.scalar(), d.scalar()))
    .degenerate(vec![
        value(
            "zero viewport (H = 0)",
            "(view_height, 0): H is clamped to >= 1",
            (2.0, 0.0),
            vec![2.0, 0.0],
        ),
        same("negative viewport (H = -5)", "as H = 1", (2.0, -5.0), (2.0, 1.0)),
        value("zero view height", "(0, 0)", (0.0, 1080.0), vec![0.0, 0.0]),
        mirror(
            "infinity in (view_height)",
            "CPU: (inf, 0)",
            (INF, 1080.0),
            vec![INF, 0.0],
        ),
    ])
}

/// `rf_thin_lens_ray_cone`.
pub fn thin_lens_ray_cone() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "thin_lens_ray_cone",
        |(spread, aperture, focus)| rc::thin_lens_ray_cone(spread, aperture, focus),
        || (angle(), magnitude(), scalar()).boxed(),
    )
    // Width: a copy. Spread: a division (2.5 ULP + 0.5) then a subtraction (0.5 + 0.5 ULP
    // of the larger operand).
    .bound(|&(spread, aperture, focus), index, _| {
        let quotient = aperture / focus.max(MIN_MAGNITUDE);
        if index == 0 {
            0.0
        } else {
            ulps(4.0, spread.abs() + quotient.abs())
        }
    })
    .reference(reference::thin_lens_ray_cone())
    .fuzz(|d| (d.angle(), d.scalar(), d.distance()))
    .degenerate(vec![
        value(
            "zero focus distance",
            "(A, alpha - A / MIN_MAGNITUDE)",
            (0.001, 0.01, 0.0),
            vec![0.01, 0.001 - 0.01 / MIN_MAGNITUDE],
        ),
        value(
            "zero aperture",
            "(0, alpha): a pinhole",
            (0.001, 0.0, 5.0),
            vec![0.0, 0.001],
        ),
        mirror(
            "NaN in (focus distance)",
            "CPU: as focus distance 0 (Rust's `max` ignores NaN)",
            (0.001, 0.01, NAN),
            vec![0.01, 0.001 - 0.01 / MIN_MAGNITUDE],
        ),
    ])
}

/// This section's records, in the module's order.
pub(super) fn records() -> Vec<Box<dyn crate::Function>> {
    records![
        pack_ray_cone,
        unpack_ray_cone,
        pixel_spread_angle,
        pixel_spread_angle_small,
        pixel_spread_angle_from_proj_inv,
        pinhole_ray_cone,
        pinhole_ray_cone_for_ray,
        orthographic_ray_cone,
        thin_lens_ray_cone
    ]
}
