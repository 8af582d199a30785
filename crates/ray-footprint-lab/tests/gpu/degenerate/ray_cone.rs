//! The degenerate-input rows of `ray_cone`.

use super::table::{cone, direction_at, mirror, same, value, widest, INF, NAN};
use super::{register, Degenerate};
use glam::{Mat4, Vec2, Vec3};
use ray_footprint::ray_cone::{
    self as rc, PackedRayCone, F16_MAX, MAX_FOV_Y, MAX_INCIDENCE_ANGLE, MAX_NORMAL_SPREAD, MIN_COS,
    MIN_MAGNITUDE, MIN_ROUGHNESS_DENOMINATOR,
};
use ray_footprint::registry::Registered;
use ray_footprint::shaders::Module;
use ray_footprint_lab::checks::ray_cone as cone_suite;
use shader_proptest::tolerance::{log2_error, tan_error, ulps};

/// Error of `2 tan(fov / 2) / H` (sin / cos of the clamped half angle) plus 4100 ULP of the
/// result (atan's 4096 and the rest).
fn spread_tolerance(fov: f32, height: f32, expected: f32) -> f32 {
    2.0 * tan_error(0.5 * fov.clamp(0.0, MAX_FOV_Y)) / height.max(1.0) + ulps(4100.0, expected)
}

pub fn tables() -> Vec<Registered<Box<dyn Degenerate>>> {
    let proj_inv = glam::camera::rh::proj::vulkan::perspective(1.0, 1.5, 0.1, 100.0).inverse();
    let (x, z) = (Vec3::X, Vec3::Z);
    let (head_on, in_plane, grazing) = (Vec3::NEG_Z, Vec3::X, direction_at(1.0e-6));
    let thirty_degrees = Vec3::new(0.5, 0.0, -0.866_025_4);
    let unit_world = (Vec3::ZERO, Vec3::X, Vec3::Y);
    let unit_uv = (Vec2::ZERO, Vec2::X, Vec2::Y);
    let collinear_uv = (Vec2::ZERO, Vec2::splat(0.5), Vec2::ONE);
    // Rows of both normal spread angles (exact and small-angle): 0 for a flat surface and when the
    // squares of the derivatives underflow.
    let flat_normal = || {
        value(
            "zero normal derivatives (flat)",
            "0",
            (Vec3::ZERO, Vec3::ZERO),
            vec![0.0],
        )
    };
    let sub_normal_derivatives = || {
        value(
            "sub-normal derivatives (1e-40 each)",
            "0 (the squares underflow)",
            (Vec3::splat(1.0e-40), Vec3::splat(-1.0e-40)),
            vec![0.0],
        )
    };
    vec![
        register(
            Module::RayCone,
            "pack_ray_cone",
            |(c,)| rc::pack_ray_cone(c),
            // Compared unpacked; packHalf2x16's rounding is the implementation's (one f16 ULP:
            // 2^-10 relative, 2^-24 absolute for f16 sub-normals).
            |_, e| (e.abs() / 1024.0).max(1.0 / 16_777_216.0),
            vec![
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
            ],
        ),
        register(
            Module::RayCone,
            "unpack_ray_cone",
            |(packed,)| rc::unpack_ray_cone(packed),
            // f16 to f32 is exact.
            |_, _| 0.0,
            vec![
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
            ],
        ),
        register(
            Module::RayCone,
            "pixel_spread_angle",
            |(fov, h)| rc::pixel_spread_angle(fov, h),
            |&(fov, h), e| spread_tolerance(fov, h, e),
            vec![
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
            ],
        ),
        register(
            Module::RayCone,
            "pixel_spread_angle_small",
            |(fov, h)| rc::pixel_spread_angle_small(fov, h),
            |&(fov, h), e| spread_tolerance(fov, h, e),
            vec![
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
            ],
        ),
        register(
            Module::RayCone,
            "pixel_spread_angle_from_proj_inv",
            |(m, h)| rc::pixel_spread_angle_from_proj_inv(m, h),
            // atan (4096 ULP) of 2 |m11| / H (2.5 ULP division).
            |&(m, h), e| ulps(4100.0, e) + ulps(3.0, 2.0 * m.y_axis.y.abs() / h.max(1.0)),
            vec![
                same(
                    "zero viewport (H = 0)",
                    "as H = 1",
                    (proj_inv, 0.0),
                    (proj_inv, 1.0),
                ),
                value("zero matrix", "0", (Mat4::ZERO, 1080.0), vec![0.0]),
                mirror(
                    "infinity in (`proj_inv[1][1]`)",
                    "CPU: pi / 2",
                    (Mat4::from_diagonal(glam::Vec4::new(1.0, INF, 1.0, 1.0)), 1080.0),
                    vec![std::f32::consts::FRAC_PI_2],
                ),
            ],
        ),
        register(
            Module::RayCone,
            "pinhole_ray_cone",
            |(alpha,)| rc::pinhole_ray_cone(alpha),
            |_, _| 0.0,
            vec![
                value("zero spread", "(0, 0)", (0.0,), vec![0.0, 0.0]),
                value(
                    "negative spread (-0.01)",
                    "(0, -0.01), kept",
                    (-0.01,),
                    vec![0.0, -0.01],
                ),
                mirror("NaN in", "CPU: (0, NaN)", (NAN,), vec![0.0, NAN]),
            ],
        ),
        register(
            Module::RayCone,
            "pinhole_ray_cone_for_ray",
            |(alpha, d, axis)| rc::pinhole_ray_cone_for_ray(alpha, d, axis),
            // One product; the dot product is exact at these inputs.
            |_, e| ulps(1.0, e),
            vec![
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
            ],
        ),
        register(
            Module::RayCone,
            "orthographic_ray_cone",
            |(view_height, h)| rc::orthographic_ray_cone(view_height, h),
            |_, e| ulps(2.5, e),
            vec![
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
            ],
        ),
        register(
            Module::RayCone,
            "thin_lens_ray_cone",
            |(alpha, aperture, focus)| rc::thin_lens_ray_cone(alpha, aperture, focus),
            |_, e| ulps(3.5, e),
            vec![
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
            ],
        ),
        register(
            Module::RayCone,
            "width_at",
            |(c, t)| rc::width_at(c, t),
            // A possibly fused multiply-add: 2 ULP of its terms.
            |&(c, t), _| ulps(2.0, c.width.abs() + (c.spread_angle * t).abs()),
            vec![
                value("t = 0", "width", (cone(0.5, 0.001), 0.0), vec![0.5]),
                value(
                    "huge t (1e12)",
                    "width + spread * 1e12",
                    (cone(0.5, 0.001), 1.0e12),
                    vec![0.5 + 0.001 * 1.0e12],
                ),
                value(
                    "negative spread past the apex",
                    "negative (signed width; footprints use |width|)",
                    (cone(1.0, -0.01), 200.0),
                    vec![1.0 - 0.01 * 200.0],
                ),
                mirror("NaN in (t)", "CPU: NaN", (cone(0.5, 0.001), NAN), vec![NAN]),
                mirror("infinity in (t)", "CPU: inf", (cone(0.5, 0.001), INF), vec![INF]),
            ],
        ),
        register(
            Module::RayCone,
            "propagate",
            |(c, t, beta)| rc::propagate(c, t, beta),
            |&(c, t, beta), _| {
                ulps(
                    2.0,
                    c.width.abs() + (c.spread_angle * t).abs() + c.spread_angle.abs() + beta.abs(),
                )
            },
            vec![
                value(
                    "t = 0",
                    "(width, spread + beta)",
                    (cone(0.5, 0.001), 0.0, 0.25),
                    vec![0.5, 0.001 + 0.25],
                ),
                value(
                    "huge t (1e12)",
                    "(width + spread * 1e12, spread + beta)",
                    (cone(0.5, 0.001), 1.0e12, 0.0),
                    vec![0.5 + 0.001 * 1.0e12, 0.001],
                ),
                mirror(
                    "infinity in (beta)",
                    "CPU: (width + spread * t, inf)",
                    (cone(0.5, 0.001), 1.0, INF),
                    vec![0.5 + 0.001, INF],
                ),
            ],
        ),
        register(
            Module::RayCone,
            "normal_spread_angle",
            |(dx, dy)| rc::normal_spread_angle(dx, dy),
            |_, e| ulps(4100.0, e),
            vec![
                flat_normal(),
                value(
                    "one derivative zero, the other of length 2",
                    "2 atan(1) = pi / 2",
                    (Vec3::ZERO, Vec3::new(0.0, 0.0, -2.0)),
                    vec![std::f32::consts::FRAC_PI_2],
                ),
                sub_normal_derivatives(),
                mirror(
                    "infinity in",
                    "CPU: pi (2 atan(inf))",
                    (Vec3::new(INF, 0.0, 0.0), Vec3::ZERO),
                    vec![std::f32::consts::PI],
                ),
            ],
        ),
        register(
            Module::RayCone,
            "normal_spread_angle_small",
            |(dx, dy)| rc::normal_spread_angle_small(dx, dy),
            // A sum of squares (3 roundings, 1.5 after the root) and a square root (inherited from
            // inversesqrt and a division: 4.5 ULP).
            |_, e| ulps(6.0, e),
            vec![
                flat_normal(),
                value(
                    "derivatives (3, 0, 0) and (0, -4, 0)",
                    "5, the length of both together",
                    (Vec3::new(3.0, 0.0, 0.0), Vec3::new(0.0, -4.0, 0.0)),
                    vec![5.0],
                ),
                sub_normal_derivatives(),
            ],
        ),
        register(
            Module::RayCone,
            "curvature_sign",
            |(a, b, c, d)| rc::curvature_sign(a, b, c, d),
            |_, _| 0.0,
            vec![
                value(
                    "zero derivatives",
                    "-1 (sign(0) = -1)",
                    (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO),
                    vec![-1.0],
                ),
                value(
                    "convex (dot(dp_dx, dn_dx) = 1)",
                    "1",
                    (x, Vec3::ZERO, x, Vec3::ZERO),
                    vec![1.0],
                ),
                value(
                    "terms cancelling to exactly 0 (1 - 1)",
                    "-1 (sign(0) = -1)",
                    (x, Vec3::Y, x, Vec3::NEG_Y),
                    vec![-1.0],
                ),
                mirror(
                    "NaN in",
                    "CPU: -1 (NaN > 0 is false)",
                    (Vec3::splat(NAN), x, x, x),
                    vec![-1.0],
                ),
            ],
        ),
        register(
            Module::RayCone,
            "surface_spread_angle",
            |(phi, s, k1, k2)| rc::surface_spread_angle(phi, s, k1, k2),
            // Three products and a sum: 4 roundings of the terms.
            |&(phi, s, k1, k2), _| ulps(4.0, (2.0 * k1 * s * phi).abs() + k2.abs()),
            vec![
                value(
                    "flat (phi = 0), RTG's k1 = 1, k2 = 0",
                    "0",
                    (0.0, 1.0, 1.0, 0.0),
                    vec![0.0],
                ),
                value(
                    "concave (s = -1), phi = 0.25",
                    "-2 phi = -0.5: the cone narrows",
                    (0.25, -1.0, 1.0, 0.0),
                    vec![-0.5],
                ),
                value(
                    "k1 = 0",
                    "k2: the curvature is ignored",
                    (0.25, 1.0, 0.0, 0.125),
                    vec![0.125],
                ),
            ],
        ),
        register(
            Module::RayCone,
            "edge_curvature",
            |(pi, pj, ni, nj)| rc::edge_curvature(pi, pj, ni, nj),
            |_, e| ulps(6.0, e),
            vec![
                value("zero-length edge", "0", (x, x, z, x), vec![0.0]),
                value(
                    "edge of the unit sphere (p = n: x, then y)",
                    "1 (1 / R)",
                    (x, Vec3::Y, x, Vec3::Y),
                    vec![1.0],
                ),
                value("equal normals (flat)", "0", (Vec3::ZERO, x, z, z), vec![0.0]),
                value(
                    "edge of length 1e-12 (|edge|^2 below MIN_MAGNITUDE)",
                    "dot(n_j - n_i, edge) / MIN_MAGNITUDE",
                    (Vec3::ZERO, Vec3::new(1.0e-12, 0.0, 0.0), Vec3::ZERO, x),
                    vec![1.0e-12 / MIN_MAGNITUDE],
                ),
            ],
        ),
        register(
            Module::RayCone,
            "triangle_curvature",
            |(p0, p1, p2, n0, n1, n2)| rc::triangle_curvature(p0, p1, p2, n0, n1, n2),
            // Three curvatures (dot 3 ULP, division 2.5 ULP) of magnitude <= 1, summed and divided.
            |_, _| ulps(10.0, 1.0),
            vec![
                value(
                    "zero-area triangle (p2 = p0)",
                    "the mean of the two real edges' curvatures (the zero edge counts 0): 2/3 here",
                    (Vec3::ZERO, x, Vec3::ZERO, z, x, z),
                    vec![(1.0 + 1.0 + 0.0) / 3.0],
                ),
                value(
                    "flat (equal vertex normals)",
                    "0",
                    (Vec3::ZERO, x, Vec3::Y, z, z, z),
                    vec![0.0],
                ),
                value(
                    "vertices and outward normals x, y, z of the unit sphere",
                    "1 (each edge 1 / R)",
                    (x, Vec3::Y, z, x, Vec3::Y, z),
                    vec![1.0],
                ),
                value(
                    "all three vertices at one point",
                    "0 (three zero-length edges)",
                    (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, z, x, Vec3::Y),
                    vec![0.0],
                ),
            ],
        ),
        register(
            Module::RayCone,
            "curvature_spread_angle",
            |(k, w, n, d)| rc::curvature_spread_angle(k, w, n, d),
            // Two products and a division (5 ULP); dn is exact here (+-1 or clamped).
            |_, e| ulps(5.0, e),
            vec![
                value(
                    "ray in the surface plane (dot(n, d) = +0)",
                    "2 k width / MIN_COS: dn = 0 counts as the normal's side",
                    (0.5, 0.01, z, in_plane),
                    vec![2.0 * 0.5 * 0.01 / MIN_COS],
                ),
                same(
                    "ray in the surface plane (dot(n, d) = -0)",
                    "as dot(n, d) = +0: either zero gives dn = +MIN_COS",
                    (0.5, 0.01, z, Vec3::new(-1.0, -0.0, -0.0)),
                    (0.5, 0.01, z, in_plane),
                ),
                same(
                    "grazing on the normal's side (dot(n, d) = -1e-6)",
                    "as dot(n, d) = 0 (dn clamped to MIN_COS)",
                    (0.5, 0.01, z, grazing),
                    (0.5, 0.01, z, in_plane),
                ),
                value(
                    "grazing behind the normal (dot(n, d) = +1e-6)",
                    "-2 k width / MIN_COS (dn clamped to -MIN_COS, its sign kept)",
                    (0.5, 0.01, z, direction_at(-1.0e-6)),
                    vec![-2.0 * 0.5 * 0.01 / MIN_COS],
                ),
                value(
                    "head-on (d = -n)",
                    "2 k width",
                    (0.5, 0.01, z, head_on),
                    vec![2.0 * 0.5 * 0.01],
                ),
                value(
                    "head-on from behind the normal (d = n)",
                    "-2 k width: the surface's normals point away from the ray",
                    (0.5, 0.01, z, z),
                    vec![-2.0 * 0.5 * 0.01],
                ),
                value(
                    "negative width (past a focus)",
                    "2 k width, negative: widens the inverted cone on a convex mirror",
                    (0.5, -0.01, z, head_on),
                    vec![-2.0 * 0.5 * 0.01],
                ),
                value("zero width (at a focus)", "0", (0.5, 0.0, z, head_on), vec![0.0]),
            ],
        ),
        register(
            Module::RayCone,
            "world_footprint",
            |(c, t, n, d)| rc::world_footprint(c, t, n, d),
            |&(c, t, n, d), e| {
                ulps(2.0, c.width.abs() + (c.spread_angle * t).abs()) / n.dot(d).abs().max(MIN_COS)
                    + ulps(3.0, e)
            },
            vec![
                value(
                    "ray in the surface plane (dot(n, d) = 0)",
                    "|width + spread t| / MIN_COS",
                    (cone(0.0, 0.001), 10.0, z, in_plane),
                    vec![(0.0f32 + 0.001 * 10.0).abs() / MIN_COS],
                ),
                same(
                    "grazing (|dot(n, d)| = 1e-6)",
                    "as dot(n, d) = 0",
                    (cone(0.0, 0.001), 10.0, z, grazing),
                    (cone(0.0, 0.001), 10.0, z, in_plane),
                ),
                value(
                    "head-on (d = -n)",
                    "|width + spread t|",
                    (cone(0.0, 0.001), 10.0, z, head_on),
                    vec![0.001 * 10.0],
                ),
                value(
                    "t = 0",
                    "|width| / |dot(n, d)|",
                    (cone(-0.5, 0.001), 0.0, z, head_on),
                    vec![0.5],
                ),
                mirror(
                    "NaN in (t)",
                    "CPU: NaN",
                    (cone(0.0, 0.001), NAN, z, head_on),
                    vec![NAN],
                ),
            ],
        ),
        register(
            Module::RayCone,
            "triangle_world_area2",
            |(p0, p1, p2)| rc::triangle_world_area2(p0, p1, p2),
            |_, e| ulps(11.0, e),
            vec![
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
            ],
        ),
        register(
            Module::RayCone,
            "triangle_uv_area2",
            |(a, b, c)| rc::triangle_uv_area2(a, b, c),
            |_, e| ulps(2.0, e),
            vec![
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
            ],
        ),
        register(
            Module::RayCone,
            "texel_density",
            |(p0, p1, p2, t0, t1, t2)| rc::texel_density(p0, p1, p2, t0, t1, t2),
            // Two square roots (3 ULP each) and a division (2.5 ULP).
            |_, e| ulps(9.0, e),
            vec![
                value(
                    "zero-area triangle",
                    "sqrt(uv_area2) / sqrt(MIN_MAGNITUDE)",
                    (Vec3::ZERO, x, Vec3::ZERO, unit_uv.0, unit_uv.1, unit_uv.2),
                    vec![1.0 / MIN_MAGNITUDE.sqrt()],
                ),
                value(
                    "collinear UVs",
                    "0",
                    (
                        unit_world.0,
                        unit_world.1,
                        unit_world.2,
                        collinear_uv.0,
                        collinear_uv.1,
                        collinear_uv.2,
                    ),
                    vec![0.0],
                ),
                value(
                    "zero-area triangle and collinear UVs",
                    "0 (0 / sqrt(MIN_MAGNITUDE))",
                    (
                        Vec3::ZERO,
                        x,
                        Vec3::ZERO,
                        collinear_uv.0,
                        collinear_uv.1,
                        collinear_uv.2,
                    ),
                    vec![0.0],
                ),
                value(
                    "unit right triangle in both spaces",
                    "1",
                    (
                        unit_world.0,
                        unit_world.1,
                        unit_world.2,
                        unit_uv.0,
                        unit_uv.1,
                        unit_uv.2,
                    ),
                    vec![1.0],
                ),
            ],
        ),
        register(
            Module::RayCone,
            "triangle_base_lod",
            |(p0, p1, p2, t0, t1, t2)| rc::triangle_base_lod(p0, p1, p2, t0, t1, t2),
            // Half a difference of two log2 (3 ULP each); here one term is 0 (log2 1) or both are
            // the same clamped value, so the larger term is 2 |expected|.
            |_, e| log2_error(2.0 * e) + ulps(1.0, e),
            vec![
                value(
                    "zero-area triangle",
                    "0.5 (log2(uv_area2) - log2(MIN_MAGNITUDE))",
                    (Vec3::ZERO, x, Vec3::ZERO, unit_uv.0, unit_uv.1, unit_uv.2),
                    vec![0.5 * (0.0 - MIN_MAGNITUDE.log2())],
                ),
                value(
                    "collinear UVs",
                    "0.5 (log2(MIN_MAGNITUDE) - log2(world_area2))",
                    (
                        unit_world.0,
                        unit_world.1,
                        unit_world.2,
                        collinear_uv.0,
                        collinear_uv.1,
                        collinear_uv.2,
                    ),
                    vec![0.5 * (MIN_MAGNITUDE.log2() - 0.0)],
                ),
                value(
                    "zero-area triangle and collinear UVs",
                    "0",
                    (
                        Vec3::ZERO,
                        x,
                        Vec3::ZERO,
                        collinear_uv.0,
                        collinear_uv.1,
                        collinear_uv.2,
                    ),
                    vec![0.0],
                ),
            ],
        ),
        register(
            Module::RayCone,
            "texture_lod",
            |(base, w, size, n, d)| rc::texture_lod(base, w, size, n, d),
            // Four log2 (3 ULP of each term, 2^-21 near 0) and the sum's roundings.
            |&(base, w, size, n, d), _| {
                let size = size.max(Vec2::ONE);
                let terms = [
                    w.abs().max(MIN_MAGNITUDE).log2(),
                    size.x.log2(),
                    size.y.log2(),
                    n.dot(d).abs().max(MIN_COS).log2(),
                ];
                terms.iter().map(|&t| log2_error(t)).sum::<f32>()
                    + ulps(4.0, base.abs() + terms.iter().map(|t| t.abs()).sum::<f32>())
            },
            vec![
                value(
                    "zero width",
                    "base + log2(MIN_MAGNITUDE) + 0.5 (log2 W + log2 H) - log2 |dot|",
                    (0.0, 0.0, Vec2::splat(1024.0), z, head_on),
                    vec![0.0 + MIN_MAGNITUDE.log2() + 0.5 * (10.0 + 10.0) - 0.0],
                ),
                same(
                    "zero texture size",
                    "as a 1 x 1 texture (W, H clamped to >= 1)",
                    (0.0, 1.0, Vec2::ZERO, z, head_on),
                    (0.0, 1.0, Vec2::ONE, z, head_on),
                ),
                value(
                    "ray in the surface plane (dot(n, d) = 0)",
                    "base + log2 |width| + 0.5 (log2 W + log2 H) - log2(MIN_COS)",
                    (0.0, 1.0, Vec2::ONE, z, in_plane),
                    vec![-MIN_COS.log2()],
                ),
                same(
                    "grazing (|dot(n, d)| = 1e-6)",
                    "as dot(n, d) = 0",
                    (0.0, 1.0, Vec2::ONE, z, grazing),
                    (0.0, 1.0, Vec2::ONE, z, in_plane),
                ),
                mirror(
                    "NaN in (width)",
                    "CPU: as width 0 (Rust's `max` ignores NaN)",
                    (0.0, NAN, Vec2::splat(1024.0), z, head_on),
                    vec![MIN_MAGNITUDE.log2() + 10.0],
                ),
            ],
        ),
        register(
            Module::RayCone,
            "texture_gradient",
            |(footprint, scale)| rc::texture_gradient(footprint, scale),
            |_, e| ulps(1.0, e),
            vec![
                value(
                    "negative scale",
                    "0 (scale clamped to >= 0)",
                    (0.5, -2.0),
                    vec![0.0],
                ),
                value("negative footprint", "|footprint| scale", (-0.5, 2.0), vec![1.0]),
                value("scale 0", "0 (samples mip 0)", (0.5, 0.0), vec![0.0]),
                value("zero footprint", "0", (0.0, 2.0), vec![0.0]),
            ],
        ),
        register(
            Module::RayCone,
            "environment_lod",
            |(spread, h)| rc::environment_lod(spread, h),
            // log2 of a product and a division (3.5 ULP relative, 3.5 / ln 2 ULP absolute after log2).
            |_, e| log2_error(e) + ulps(5.0, 1.0),
            vec![
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
            ],
        ),
        register(
            Module::RayCone,
            "refract_ray_cone",
            |(c, n, d, beta, eta)| rc::refract_ray_cone(c, n, d, beta, eta),
            // The agreement check's enclosure, widest over the three components.
            |a, _| widest(cone_suite::refract_ray_cone(), a),
            vec![
                value(
                    "normal incidence, flat, no spread (eta 1.5)",
                    "(width, 0), not reflected",
                    (cone(0.5, 0.0), z, head_on, 0.0, 1.5),
                    vec![0.5, 0.0, 0.0],
                ),
                value(
                    "zero cone",
                    "zero cone",
                    (cone(0.0, 0.0), z, thirty_degrees, 0.0, 1.5),
                    vec![0.0, 0.0, 0.0],
                ),
                value(
                    "central ray past the critical angle (sin i = 0.8, eta 1.5)",
                    "the reflected cone (width, spread + 2 beta), flag set",
                    (cone(0.25, 0.125), z, Vec3::new(0.8, 0.0, -0.6), 0.0625, 1.5),
                    vec![0.25, 0.25, 1.0],
                ),
                same(
                    "normal facing away from the ray (dot(n, d) > 0)",
                    "as the flipped normal with the negated normal spread",
                    (cone(0.01, 0.002), -z, thirty_degrees, 0.01, 1.5),
                    (cone(0.01, 0.002), z, thirty_degrees, -0.01, 1.5),
                ),
                same(
                    "grazing (|dot(n, d)| = 1e-6), eta 0.5",
                    "as a direction in the surface plane: both boundary rays land at |cos| = MIN_COS",
                    (cone(0.01, 0.002), z, grazing, 0.0, 0.5),
                    (cone(0.01, 0.002), z, in_plane, 0.0, 0.5),
                ),
                same(
                    "spread wider than the surface allows (3.5 at normal incidence)",
                    "as spread 2 MAX_INCIDENCE_ANGLE (both boundary rays graze)",
                    (cone(0.01, 3.5), z, head_on, 0.0, 1.5),
                    (cone(0.01, 2.0 * MAX_INCIDENCE_ANGLE), z, head_on, 0.0, 1.5),
                ),
                same(
                    "normal spread 10",
                    "as MAX_NORMAL_SPREAD",
                    (cone(0.01, 0.002), z, thirty_degrees, 10.0, 1.5),
                    (cone(0.01, 0.002), z, thirty_degrees, MAX_NORMAL_SPREAD, 1.5),
                ),
                same(
                    "negative eta",
                    "as eta 0",
                    (cone(0.01, 0.002), z, thirty_degrees, 0.0, -2.0),
                    (cone(0.01, 0.002), z, thirty_degrees, 0.0, 0.0),
                ),
                same(
                    "zero direction",
                    "as normal incidence (d = -n)",
                    (cone(0.5, 0.01), z, Vec3::ZERO, 0.0, 1.5),
                    (cone(0.5, 0.01), z, head_on, 0.0, 1.5),
                ),
            ],
        ),
        register(
            Module::RayCone,
            "roughness_spread_angle",
            |(r,)| rc::roughness_spread_angle(r),
            // The agreement check's enclosure.
            |a, e| cone_suite::roughness_spread_angle().bounds(a, &e)[0],
            vec![
                value("roughness 0", "0", (0.0,), vec![0.0]),
                value(
                    "roughness 1",
                    "2 sqrt(0.5 / MIN_ROUGHNESS_DENOMINATOR), about 141.4",
                    (1.0,),
                    vec![2.0 * (0.5 / MIN_ROUGHNESS_DENOMINATOR).sqrt()],
                ),
                same("negative roughness", "as roughness 0", (-0.5,), (0.0,)),
                same("roughness 2", "as roughness 1", (2.0,), (1.0,)),
            ],
        ),
    ]
}
