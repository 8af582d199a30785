//! Records of `ray_cone`: Footprint and texture LOD.

use super::bound::{area_corners, clamped_cos, uv_area2_error, width_at_error, world_area2_error};
use super::strategy::{ray_cone, triangle_with_uvs};
use super::{enclosure, reference, TextureLodArgs, MODULE};
use crate::degenerate::{cone, grazing, mirror, same, value, HEAD_ON, INF, IN_PLANE, NAN};
use crate::record::Record;
use crate::special::Perturb;
use crate::strategy::{
    angle, distance, image_size, normal_and_direction, pixels, scalar, triangle, unit_vec3, uv_triangle,
    vec3, HUGE,
};
use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MIN_COS, MIN_MAGNITUDE, MIN_SQUARED_MAGNITUDE};
use shader_proptest::draw::uniform;
use shader_proptest::one_of;
use shader_proptest::tolerance::{dot_error, log2_error, ulps, ULP};
use shader_proptest::{Args, Value};

/// `rf_world_footprint`.
pub fn world_footprint() -> Record<impl Args + Perturb, impl Value> {
    let z = Vec3::Z;
    Record::new(
        MODULE,
        "world_footprint",
        |(cone, t, normal, direction)| rc::world_footprint(cone, t, normal, direction),
        || {
            (ray_cone(), distance(), normal_and_direction())
                .prop_map(|(c, t, (n, d))| (c, t, n, d))
                .boxed()
        },
    )
    // The width's error (as width_at) over |cos|, the division (3 ULP), and the dot's
    // rounding over |cos| as a relative error.
    .bound(|&(cone, t, normal, direction), _, expected| {
        let cos = clamped_cos(normal, direction);
        width_at_error(cone, t) / cos
            + ulps(3.0, expected)
            + expected.abs() * dot_error(normal, direction) / cos
    })
    .reference(reference::world_footprint())
    .fuzz(|d| (d.cone(), d.distance(), d.unit(), d.unit()))
    .range(0.0, f32::MAX, "footprint")
    .degenerate(vec![
        value(
            "ray in the surface plane (dot(n, d) = 0)",
            "|width + spread t| / MIN_COS",
            (cone(0.0, 0.001), 10.0, z, IN_PLANE),
            vec![(0.0f32 + 0.001 * 10.0).abs() / MIN_COS],
        ),
        same(
            "grazing (|dot(n, d)| = 1e-6)",
            "as dot(n, d) = 0",
            (cone(0.0, 0.001), 10.0, z, grazing()),
            (cone(0.0, 0.001), 10.0, z, IN_PLANE),
        ),
        value(
            "head-on (d = -n)",
            "|width + spread t|",
            (cone(0.0, 0.001), 10.0, z, HEAD_ON),
            vec![0.001 * 10.0],
        ),
        value(
            "t = 0",
            "|width| / |dot(n, d)|",
            (cone(-0.5, 0.001), 0.0, z, HEAD_ON),
            vec![0.5],
        ),
        mirror(
            "NaN in (t)",
            "CPU: NaN",
            (cone(0.0, 0.001), NAN, z, HEAD_ON),
            vec![NAN],
        ),
    ])
}

/// `rf_two_section_width`: the enclosure of the width.
pub fn two_section_width() -> Record<impl Args + Perturb, impl Value> {
    let z = Vec3::Z;
    let sixty_degrees = Vec3::new(0.866_025_4, 0.0, -0.5);
    Record::new(
        MODULE,
        "two_section_width",
        |(tangential, sagittal, axis, normal, direction)| {
            rc::two_section_width(tangential, sagittal, axis, normal, direction)
        },
        || {
            // The axis as a refraction leaves it (across the plane of incidence), any unit vector,
            // any vector, or none.
            let axis = one_of![
                3 => Just(None),
                2 => unit_vec3().prop_map(Some),
                1 => vec3().prop_map(Some),
                1 => Just(Some(Vec3::ZERO)),
            ];
            (scalar(), scalar(), axis, normal_and_direction())
                .prop_map(|(tangential, sagittal, axis, (n, d))| {
                    let axis = axis.unwrap_or_else(|| d.cross(n));
                    (tangential, sagittal, axis, n, d)
                })
                .boxed()
        },
    )
    .conditioned(
        "a width or the axis beyond the domain's magnitudes (1e12), where the enclosure's products \
         overflow, or an axis within 1e-4 of the ray's line, whose part across the ray is rounding \
         and points anywhere",
        |&(tangential, sagittal, axis, _, direction)| {
            let across = axis - axis.dot(direction) * direction;
            let in_domain =
                tangential.abs() <= HUGE && sagittal.abs() <= HUGE && axis.abs().max_element() <= HUGE;
            in_domain && across.length() >= 1.0e-4 * axis.length()
        },
    )
    .enclosure(|args| vec![enclosure::two_section_width(args)])
    .reference(reference::two_section_width_sampled())
    .reference(reference::two_section_width_limits())
    .fuzz(|d| (d.scalar(), d.scalar(), d.vec3(), d.unit(), d.unit()))
    .range(0.0, f32::MAX, "width")
    .degenerate(vec![
        value(
            "zero axis",
            "max(|w_t|, |w_s|)",
            (0.01, -0.03, Vec3::ZERO, z, sixty_degrees),
            vec![0.03],
        ),
        same(
            "axis along the ray",
            "as the zero axis",
            (0.01, -0.03, sixty_degrees, z, sixty_degrees),
            (0.01, -0.03, Vec3::ZERO, z, sixty_degrees),
        ),
        value(
            "both widths 0",
            "0",
            (0.0, 0.0, Vec3::Y, z, sixty_degrees),
            vec![0.0],
        ),
        value(
            "ray in the surface plane (dot(n, d) = 0), equal widths",
            "|w|: a round cone at any slant",
            (0.5, 0.5, Vec3::Y, z, IN_PLANE),
            vec![0.5],
        ),
        same(
            "grazing (|dot(n, d)| = 1e-6)",
            "as dot(n, d) = 0",
            (0.01, 0.03, Vec3::Y, z, grazing()),
            (0.01, 0.03, Vec3::Y, z, IN_PLANE),
        ),
        same(
            "axis not across the ray and not unit",
            "as its unit part across the ray",
            (0.01, 0.03, Vec3::new(1.0, 2.0, 0.0), z, HEAD_ON),
            (0.01, 0.03, Vec3::new(0.447_213_6, 0.894_427_2, 0.0), z, HEAD_ON),
        ),
        mirror(
            "NaN width",
            "CPU: NaN",
            (NAN, 0.01, Vec3::Y, z, HEAD_ON),
            vec![NAN],
        ),
    ])
}

/// `rf_triangle_world_area2`.
pub fn triangle_world_area2() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    Record::new(
        MODULE,
        "triangle_world_area2",
        |(p0, p1, p2)| rc::triangle_world_area2(p0, p1, p2),
        || triangle().prop_map(|p| (p[0], p[1], p[2])).boxed(),
    )
    .bound(|&(p0, p1, p2), _, _| world_area2_error([p0, p1, p2]))
    .reference(reference::triangle_world_area2())
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3()))
    .range(0.0, f32::MAX, "area")
    .degenerate(vec![
        value(
            "zero-area triangle (repeated vertex)",
            "0",
            (Vec3::ZERO, x, Vec3::ZERO),
            vec![0.0],
        ),
        value(
            "zero-area triangle (collinear vertices)",
            "0",
            (Vec3::ZERO, Vec3::ONE, Vec3::splat(2.0)),
            vec![0.0],
        ),
        mirror(
            "infinity in",
            "CPU: NaN (inf - inf in the cross product)",
            (Vec3::splat(INF), x, Vec3::Y),
            vec![NAN],
        ),
    ])
}

/// `rf_triangle_uv_area2`.
pub fn triangle_uv_area2() -> Record<impl Args + Perturb, impl Value> {
    let unit_uv = (Vec2::ZERO, Vec2::X, Vec2::Y);
    let collinear_uv = (Vec2::ZERO, Vec2::splat(0.5), Vec2::ONE);
    Record::new(
        MODULE,
        "triangle_uv_area2",
        |(uv0, uv1, uv2)| rc::triangle_uv_area2(uv0, uv1, uv2),
        || uv_triangle().prop_map(|uv| (uv[0], uv[1], uv[2])).boxed(),
    )
    .bound(|&(uv0, uv1, uv2), _, _| uv_area2_error([uv0, uv1, uv2]))
    .reference(reference::triangle_uv_area2())
    .fuzz(|d| (d.vec2(), d.vec2(), d.vec2()))
    .range(0.0, f32::MAX, "area")
    .degenerate(vec![
        value("collinear UVs", "0", collinear_uv, vec![0.0]),
        value(
            "repeated vertex",
            "0",
            (Vec2::ZERO, Vec2::X, Vec2::ZERO),
            vec![0.0],
        ),
        value("unit right triangle", "1", unit_uv, vec![1.0]),
        value(
            "clockwise unit right triangle",
            "1 (the absolute value)",
            (Vec2::ZERO, Vec2::Y, Vec2::X),
            vec![1.0],
        ),
    ])
}

/// A triangle's vertices and UVs, the arguments of `texel_density` and `triangle_base_lod`.
type TriangleWithUvs = (Vec3, Vec3, Vec3, Vec2, Vec2, Vec2);

/// A zero-area triangle (a repeated vertex) with the unit right triangle's UVs.
const ZERO_AREA: TriangleWithUvs = (Vec3::ZERO, Vec3::X, Vec3::ZERO, Vec2::ZERO, Vec2::X, Vec2::Y);

/// The unit right triangle with collinear UVs.
const COLLINEAR_UVS: TriangleWithUvs = (
    Vec3::ZERO,
    Vec3::X,
    Vec3::Y,
    Vec2::ZERO,
    Vec2::splat(0.5),
    Vec2::ONE,
);

/// A zero-area triangle with collinear UVs.
const ZERO_AREA_AND_COLLINEAR_UVS: TriangleWithUvs = (
    Vec3::ZERO,
    Vec3::X,
    Vec3::ZERO,
    Vec2::ZERO,
    Vec2::splat(0.5),
    Vec2::ONE,
);

/// The unit right triangle in both spaces.
const UNIT_RIGHT_TRIANGLES: TriangleWithUvs = (Vec3::ZERO, Vec3::X, Vec3::Y, Vec2::ZERO, Vec2::X, Vec2::Y);

/// `rf_texel_density`.
pub fn texel_density() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "texel_density",
        |(p0, p1, p2, uv0, uv1, uv2)| rc::texel_density(p0, p1, p2, uv0, uv1, uv2),
        triangle_with_uvs,
    )
    // The areas' errors through sqrt(uv) / sqrt(max(world, MIN)), plus two square roots
    // (4.5 ULP each), the division (2.5) and the mirror's 3.
    .bound(|&(p0, p1, p2, uv0, uv1, uv2), _, expected| {
        let min = f64::from(MIN_SQUARED_MAGNITUDE);
        area_corners([p0, p1, p2], [uv0, uv1, uv2], |uv, world| {
            uv.sqrt() / world.max(min).sqrt()
        }) + ulps(14.5, expected)
    })
    .reference(reference::texel_density())
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3(), d.vec2(), d.vec2(), d.vec2()))
    .range(0.0, f32::MAX, "density")
    .degenerate(vec![
        value(
            "zero-area triangle",
            "sqrt(uv_area2) / sqrt(MIN_SQUARED_MAGNITUDE)",
            ZERO_AREA,
            vec![1.0 / MIN_SQUARED_MAGNITUDE.sqrt()],
        ),
        value("collinear UVs", "0", COLLINEAR_UVS, vec![0.0]),
        value(
            "zero-area triangle and collinear UVs",
            "0 (0 / sqrt(MIN_SQUARED_MAGNITUDE))",
            ZERO_AREA_AND_COLLINEAR_UVS,
            vec![0.0],
        ),
        value(
            "unit right triangle in both spaces",
            "1",
            UNIT_RIGHT_TRIANGLES,
            vec![1.0],
        ),
    ])
}

/// `rf_triangle_base_lod`.
pub fn triangle_base_lod() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "triangle_base_lod",
        |(p0, p1, p2, uv0, uv1, uv2)| rc::triangle_base_lod(p0, p1, p2, uv0, uv1, uv2),
        triangle_with_uvs,
    )
    // The areas' errors through 0.5 * (log2 uv - log2 world) with the clamps, half of each
    // log2's error, and the subtraction and halving (2 ULP).
    .bound(|&(p0, p1, p2, uv0, uv1, uv2), _, expected| {
        let min = f64::from(MIN_SQUARED_MAGNITUDE);
        let uv_area2 = rc::triangle_uv_area2(uv0, uv1, uv2).max(MIN_SQUARED_MAGNITUDE);
        let world_area2 = rc::triangle_world_area2(p0, p1, p2).max(MIN_SQUARED_MAGNITUDE);
        area_corners([p0, p1, p2], [uv0, uv1, uv2], |uv, world| {
            0.5 * (uv.max(min).log2() - world.max(min).log2())
        }) + 0.5 * (log2_error(uv_area2.log2()) + log2_error(world_area2.log2()))
            + ulps(2.0, expected)
    })
    .reference(reference::triangle_base_lod())
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3(), d.vec2(), d.vec2(), d.vec2()))
    .degenerate(vec![
        value(
            "zero-area triangle",
            "0.5 (log2(uv_area2) - log2(MIN_SQUARED_MAGNITUDE))",
            ZERO_AREA,
            vec![0.5 * (0.0 - MIN_SQUARED_MAGNITUDE.log2())],
        ),
        value(
            "collinear UVs",
            "0.5 (log2(MIN_SQUARED_MAGNITUDE) - log2(world_area2))",
            COLLINEAR_UVS,
            vec![0.5 * (MIN_SQUARED_MAGNITUDE.log2() - 0.0)],
        ),
        value(
            "zero-area triangle and collinear UVs",
            "0",
            ZERO_AREA_AND_COLLINEAR_UVS,
            vec![0.0],
        ),
    ])
}

/// The check of `rf_texture_lod` (also measured by the harness benchmark).
pub fn texture_lod() -> Record<TextureLodArgs, f32> {
    let z = Vec3::Z;
    Record::new(
        MODULE,
        "texture_lod",
        |(base, width, size, normal, direction)| rc::texture_lod(base, width, size, normal, direction),
        || {
            (
                uniform(-20.0, 20.0),
                scalar(),
                image_size(),
                normal_and_direction(),
            )
                .prop_map(|(base, width, size, (n, d))| (base, width, size, n, d))
                .boxed()
        },
    )
    // Four log2 (their own errors), the dot's rounding through log2 (relative error / ln 2),
    // and four additions (4 ULP of the sum of term magnitudes).
    .bound(|&(base, width, size, normal, direction), _, _| {
        let size = size.max(Vec2::ONE);
        let logs = [
            width.abs().max(MIN_MAGNITUDE).log2(),
            size.x.log2(),
            size.y.log2(),
        ];
        let cos = clamped_cos(normal, direction);
        let log_cos = cos.log2();
        log2_error(logs[0])
            + 0.5 * (log2_error(logs[1]) + log2_error(logs[2]))
            + log2_error(log_cos)
            + dot_error(normal, direction) / cos / std::f32::consts::LN_2
            + ulps(
                4.0,
                base.abs() + logs[0].abs() + 0.5 * (logs[1] + logs[2]) + log_cos.abs(),
            )
    })
    .reference(reference::texture_lod())
    .fuzz(|d| (d.scalar(), d.scalar(), d.vec2(), d.unit(), d.unit()))
    .degenerate(vec![
        value(
            "zero width",
            "base + log2(MIN_MAGNITUDE) + 0.5 (log2 W + log2 H) - log2 |dot|",
            (0.0, 0.0, Vec2::splat(1024.0), z, HEAD_ON),
            vec![0.0 + MIN_MAGNITUDE.log2() + 0.5 * (10.0 + 10.0) - 0.0],
        ),
        same(
            "zero texture size",
            "as a 1 x 1 texture (W, H clamped to >= 1)",
            (0.0, 1.0, Vec2::ZERO, z, HEAD_ON),
            (0.0, 1.0, Vec2::ONE, z, HEAD_ON),
        ),
        value(
            "ray in the surface plane (dot(n, d) = 0)",
            "base + log2 |width| + 0.5 (log2 W + log2 H) - log2(MIN_COS)",
            (0.0, 1.0, Vec2::ONE, z, IN_PLANE),
            vec![-MIN_COS.log2()],
        ),
        same(
            "grazing (|dot(n, d)| = 1e-6)",
            "as dot(n, d) = 0",
            (0.0, 1.0, Vec2::ONE, z, grazing()),
            (0.0, 1.0, Vec2::ONE, z, IN_PLANE),
        ),
        mirror(
            "NaN in (width)",
            "CPU: as width 0 (Rust's `max` ignores NaN)",
            (0.0, NAN, Vec2::splat(1024.0), z, HEAD_ON),
            vec![MIN_MAGNITUDE.log2() + 10.0],
        ),
    ])
}

/// `rf_texture_gradient`.
pub fn texture_gradient() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "texture_gradient",
        |(uv_footprint, scale)| rc::texture_gradient(uv_footprint, scale),
        || (scalar(), uniform(-1.0, 4.0)).boxed(),
    )
    // One correctly rounded product.
    .bound(|_, _, _| f32::MIN_POSITIVE)
    .reference(reference::texture_gradient())
    .fuzz(|d| (d.scalar(), d.scalar()))
    .range(0.0, f32::MAX, "gradient")
    .degenerate(vec![
        value(
            "negative scale",
            "0 (scale clamped to >= 0)",
            (0.5, -2.0),
            vec![0.0],
        ),
        value("negative footprint", "|footprint| scale", (-0.5, 2.0), vec![1.0]),
        value("scale 0", "0 (samples mip 0)", (0.5, 0.0), vec![0.0]),
        value("zero footprint", "0", (0.0, 2.0), vec![0.0]),
    ])
}

/// `rf_environment_lod`.
pub fn environment_lod() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        MODULE,
        "environment_lod",
        |(spread, height)| rc::environment_lod(spread, height),
        || (angle(), pixels()).boxed(),
    )
    // A product and a division (3.5 ULP + the mirror's 1) through log2 (/ ln 2), plus log2's
    // own error.
    .bound(|_, _, expected| 4.5 * ULP / std::f32::consts::LN_2 + log2_error(expected))
    .reference(reference::environment_lod())
    .fuzz(|d| (d.angle(), d.scalar()))
    .range(rc::MIN_MAGNITUDE.log2(), f32::MAX, "environment LOD")
    .degenerate(vec![
        value(
            "zero spread",
            "log2(MIN_MAGNITUDE)",
            (0.0, 1024.0),
            vec![MIN_MAGNITUDE.log2()],
        ),
        same("negative spread", "as |spread|", (-0.01, 1024.0), (0.01, 1024.0)),
        same("zero map height", "as height 1", (0.01, 0.0), (0.01, 1.0)),
        mirror(
            "NaN in (spread)",
            "CPU: log2(MIN_MAGNITUDE) (Rust's `max` ignores NaN)",
            (NAN, 1024.0),
            vec![MIN_MAGNITUDE.log2()],
        ),
    ])
}

/// This section's records, in the module's order.
pub(super) fn records() -> Vec<Box<dyn crate::Function>> {
    records![
        world_footprint,
        two_section_width,
        triangle_world_area2,
        triangle_uv_area2,
        texel_density,
        triangle_base_lod,
        texture_lod,
        texture_gradient,
        environment_lod
    ]
}
