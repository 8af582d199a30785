//! The data of the degenerate-input table: per function, the degenerate inputs and the documented
//! outputs. Rendered into `src/degenerate.md` and asserted on the CPU and the GPU by `main.rs`.

use super::{Degenerate, Expect, Row, Table};
use glam::{DVec3, Mat4, Vec2, Vec3};
use ray_footprint::ray_cone::{
    self as rc, RayCone, MAX_FOV_Y, MAX_INCIDENCE_ANGLE, MAX_NORMAL_SPREAD, MIN_COS, MIN_MAGNITUDE,
    MIN_ROUGHNESS_DENOMINATOR,
};
use ray_footprint::ray_diff::{
    self as rd, Derivatives2, Derivatives3, RayDiff, DIFF_MIN_COS, DIFF_MIN_MAGNITUDE,
};
use ray_footprint::ray_diff_f64 as rd64;
use ray_footprint::shaders::Module;
use ray_footprint::wireframe::{self as wf, WireframeSettings, WireframeSettingsIo, WIREFRAME_DEFAULT};
use ray_footprint_lab::checks::{ray_cone as cone_suite, ray_diff as diff_suite};
use shader_proptest::tolerance::{log2_error, tan_error, ulps};
use shader_proptest::{Args, FunctionCheck, Value};

const NAN: f32 = f32::NAN;
const INF: f32 = f32::INFINITY;

fn value<A>(input: &'static str, output: &'static str, args: A, values: Vec<f32>) -> Row<A> {
    Row {
        input,
        output,
        args,
        expect: Expect::Values(values),
    }
}

fn same<A>(input: &'static str, output: &'static str, args: A, other: A) -> Row<A> {
    Row {
        input,
        output,
        args,
        expect: Expect::SameAs(other),
    }
}

fn mirror<A>(input: &'static str, output: &'static str, args: A, values: Vec<f32>) -> Row<A> {
    Row {
        input,
        output,
        args,
        expect: Expect::Mirror(values),
    }
}

/// The components of a value as the harness compares them.
fn parts<R: Value>(value: R) -> Vec<f32> {
    let mut out = Vec::new();
    value.components(&mut out);
    out
}

fn cone(width: f32, spread_angle: f32) -> RayCone {
    RayCone { width, spread_angle }
}

/// A unit direction at `cos` to +Z (in the xz plane, pointing down when `cos > 0` is towards -Z).
fn direction_at(cos: f32) -> Vec3 {
    Vec3::new((1.0 - cos * cos).sqrt(), 0.0, -cos)
}

/// The tables of `module`, in the module's function order.
pub fn tables(module: Module) -> Vec<Box<dyn Degenerate>> {
    match module {
        Module::RayCone => ray_cone(),
        Module::RayDiff => ray_diff(),
        Module::RayDiffF64 => ray_diff_f64(),
        Module::Wireframe => wireframe(),
    }
}

/// Error of `2 tan(fov / 2) / H` (sin / cos of the clamped half angle) plus 4100 ULP of the
/// result (atan's 4096 and the rest).
fn spread_tolerance(fov: f32, height: f32, expected: f32) -> f32 {
    2.0 * tan_error(0.5 * fov.clamp(0.0, MAX_FOV_Y)) / height.max(1.0) + ulps(4100.0, expected)
}

fn ray_cone() -> Vec<Box<dyn Degenerate>> {
    let proj_inv = glam::camera::rh::proj::vulkan::perspective(1.0, 1.5, 0.1, 100.0).inverse();
    let (x, z) = (Vec3::X, Vec3::Z);
    let (head_on, in_plane, grazing) = (Vec3::NEG_Z, Vec3::X, direction_at(1.0e-6));
    let thirty_degrees = Vec3::new(0.5, 0.0, -0.866_025_4);
    let unit_world = (Vec3::ZERO, Vec3::X, Vec3::Y);
    let unit_uv = (Vec2::ZERO, Vec2::X, Vec2::Y);
    let collinear_uv = (Vec2::ZERO, Vec2::splat(0.5), Vec2::ONE);
    vec![
        Box::new(Table {
            module: Module::RayCone,
            function: "pack_ray_cone",
            mirror: |(c,)| rc::pack_ray_cone(c),
            // Compared unpacked; packHalf2x16's rounding is the implementation's (one f16 ULP).
            tolerance: |_, e| e.abs() / 1024.0,
            rows: vec![
                value(
                    "values beyond f16 (1e9, -1e9)",
                    "(F16_MAX, -F16_MAX), never infinite",
                    (cone(1.0e9, -1.0e9),),
                    vec![rc::F16_MAX, -rc::F16_MAX],
                ),
                mirror(
                    "infinity in (width)",
                    "CPU: (F16_MAX, spread)",
                    (cone(INF, 0.5),),
                    vec![rc::F16_MAX, 0.5],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "pixel_spread_angle",
            mirror: |(fov, h)| rc::pixel_spread_angle(fov, h),
            tolerance: |&(fov, h), e| spread_tolerance(fov, h, e),
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "pixel_spread_angle_small",
            mirror: |(fov, h)| rc::pixel_spread_angle_small(fov, h),
            tolerance: |&(fov, h), e| spread_tolerance(fov, h, e),
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "pixel_spread_angle_from_proj_inv",
            mirror: |(m, h)| rc::pixel_spread_angle_from_proj_inv(m, h),
            // atan (4096 ULP) of 2 |m11| / H (2.5 ULP division).
            tolerance: |&(m, h), e| ulps(4100.0, e) + ulps(3.0, 2.0 * m.y_axis.y.abs() / h.max(1.0)),
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "pinhole_ray_cone",
            mirror: |(alpha,)| rc::pinhole_ray_cone(alpha),
            tolerance: |_, _| 0.0,
            rows: vec![
                value("zero spread", "(0, 0)", (0.0,), vec![0.0, 0.0]),
                value(
                    "negative spread (-0.01)",
                    "(0, -0.01), kept",
                    (-0.01,),
                    vec![0.0, -0.01],
                ),
                mirror("NaN in", "CPU: (0, NaN)", (NAN,), vec![0.0, NAN]),
            ],
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "pinhole_ray_cone_for_ray",
            mirror: |(alpha, d, axis)| rc::pinhole_ray_cone_for_ray(alpha, d, axis),
            // One product; the dot product is exact at these inputs.
            tolerance: |_, e| ulps(1.0, e),
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "orthographic_ray_cone",
            mirror: |(view_height, h)| rc::orthographic_ray_cone(view_height, h),
            tolerance: |_, e| ulps(2.5, e),
            rows: vec![
                value(
                    "zero viewport (H = 0)",
                    "(view_height, 0): H is clamped to >= 1",
                    (2.0, 0.0),
                    vec![2.0, 0.0],
                ),
                mirror(
                    "infinity in (view_height)",
                    "CPU: (inf, 0)",
                    (INF, 1080.0),
                    vec![INF, 0.0],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "thin_lens_ray_cone",
            mirror: |(alpha, aperture, focus)| rc::thin_lens_ray_cone(alpha, aperture, focus),
            tolerance: |_, e| ulps(3.5, e),
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "width_at",
            mirror: |(c, t)| rc::width_at(c, t),
            // A possibly fused multiply-add: 2 ULP of its terms.
            tolerance: |&(c, t), _| ulps(2.0, c.width.abs() + (c.spread_angle * t).abs()),
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "propagate",
            mirror: |(c, t, beta)| rc::propagate(c, t, beta),
            tolerance: |&(c, t, beta), _| {
                ulps(
                    2.0,
                    c.width.abs() + (c.spread_angle * t).abs() + c.spread_angle.abs() + beta.abs(),
                )
            },
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "normal_spread_angle",
            mirror: |(dx, dy)| rc::normal_spread_angle(dx, dy),
            tolerance: |_, e| ulps(4100.0, e),
            rows: vec![
                value(
                    "zero normal derivatives (flat)",
                    "0",
                    (Vec3::ZERO, Vec3::ZERO),
                    vec![0.0],
                ),
                mirror(
                    "infinity in",
                    "CPU: pi (2 atan(inf))",
                    (Vec3::new(INF, 0.0, 0.0), Vec3::ZERO),
                    vec![std::f32::consts::PI],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "curvature_sign",
            mirror: |(a, b, c, d)| rc::curvature_sign(a, b, c, d),
            tolerance: |_, _| 0.0,
            rows: vec![
                value(
                    "zero derivatives",
                    "-1 (sign(0) = -1)",
                    (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO),
                    vec![-1.0],
                ),
                mirror(
                    "NaN in",
                    "CPU: -1 (NaN > 0 is false)",
                    (Vec3::splat(NAN), x, x, x),
                    vec![-1.0],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "edge_curvature",
            mirror: |(pi, pj, ni, nj)| rc::edge_curvature(pi, pj, ni, nj),
            tolerance: |_, e| ulps(6.0, e),
            rows: vec![value("zero-length edge", "0", (x, x, z, x), vec![0.0])],
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "triangle_curvature",
            mirror: |(p0, p1, p2, n0, n1, n2)| rc::triangle_curvature(p0, p1, p2, n0, n1, n2),
            // Three curvatures (dot 3 ULP, division 2.5 ULP) of magnitude <= 1, summed and divided.
            tolerance: |_, _| ulps(10.0, 1.0),
            rows: vec![value(
                "zero-area triangle (p2 = p0)",
                "the mean of the two real edges' curvatures (the zero edge counts 0): 2/3 here",
                (Vec3::ZERO, x, Vec3::ZERO, z, x, z),
                vec![(1.0 + 1.0 + 0.0) / 3.0],
            )],
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "curvature_spread_angle",
            mirror: |(k, w, n, d)| rc::curvature_spread_angle(k, w, n, d),
            // Two products and a division (5 ULP); dn is exact here (+-1 or clamped).
            tolerance: |_, e| ulps(5.0, e),
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "world_footprint",
            mirror: |(c, t, n, d)| rc::world_footprint(c, t, n, d),
            tolerance: |&(c, t, n, d), e| {
                ulps(2.0, c.width.abs() + (c.spread_angle * t).abs()) / n.dot(d).abs().max(MIN_COS)
                    + ulps(3.0, e)
            },
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "triangle_world_area2",
            mirror: |(p0, p1, p2)| rc::triangle_world_area2(p0, p1, p2),
            tolerance: |_, e| ulps(11.0, e),
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "triangle_uv_area2",
            mirror: |(a, b, c)| rc::triangle_uv_area2(a, b, c),
            tolerance: |_, e| ulps(2.0, e),
            rows: vec![value("collinear UVs", "0", collinear_uv, vec![0.0])],
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "texel_density",
            mirror: |(p0, p1, p2, t0, t1, t2)| rc::texel_density(p0, p1, p2, t0, t1, t2),
            // Two square roots (3 ULP each) and a division (2.5 ULP).
            tolerance: |_, e| ulps(9.0, e),
            rows: vec![
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
            ],
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "triangle_base_lod",
            mirror: |(p0, p1, p2, t0, t1, t2)| rc::triangle_base_lod(p0, p1, p2, t0, t1, t2),
            // Half a difference of two log2 (3 ULP each); here one term is 0 (log2 1) or both are
            // the same clamped value, so the larger term is 2 |expected|.
            tolerance: |_, e| log2_error(2.0 * e) + ulps(1.0, e),
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "texture_lod",
            mirror: |(base, w, size, n, d)| rc::texture_lod(base, w, size, n, d),
            // Four log2 (3 ULP of each term, 2^-21 near 0) and the sum's roundings.
            tolerance: |&(base, w, size, n, d), _| {
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
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "texture_gradient",
            mirror: |(footprint, scale)| rc::texture_gradient(footprint, scale),
            tolerance: |_, e| ulps(1.0, e),
            rows: vec![
                value(
                    "negative scale",
                    "0 (scale clamped to >= 0)",
                    (0.5, -2.0),
                    vec![0.0],
                ),
                value("negative footprint", "|footprint| scale", (-0.5, 2.0), vec![1.0]),
            ],
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "environment_lod",
            mirror: |(spread, h)| rc::environment_lod(spread, h),
            // log2 of a product and a division (3.5 ULP relative, 3.5 / ln 2 ULP absolute after log2).
            tolerance: |_, e| log2_error(e) + ulps(5.0, 1.0),
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "refract_ray_cone",
            mirror: |(c, n, d, beta, eta)| rc::refract_ray_cone(c, n, d, beta, eta),
            // The agreement check's enclosure, widest over the three components.
            tolerance: |a, _| widest(cone_suite::refract_ray_cone(), a),
            rows: vec![
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
        }),
        Box::new(Table {
            module: Module::RayCone,
            function: "roughness_spread_angle",
            mirror: |(r,)| rc::roughness_spread_angle(r),
            // The agreement check's enclosure.
            tolerance: |a, e| cone_suite::roughness_spread_angle().bounds(a, &e)[0],
            rows: vec![
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
        }),
    ]
}

fn ray_diff() -> Vec<Box<dyn Degenerate>> {
    let (x, y, z) = (Vec3::X, Vec3::Y, Vec3::Z);
    let proj_inv = glam::camera::rh::proj::vulkan::perspective(1.0, 1.5, 0.1, 100.0).inverse();
    let camera = |size: Vec2, fov: f32| (Vec2::ZERO, size, fov, x, y, z);
    let zero_diff_dx = |d_origin_dx: Vec3| RayDiff::new(d_origin_dx, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);
    let direction_dx =
        |d_direction_dx: Vec3| RayDiff::new(Vec3::ZERO, Vec3::ZERO, d_direction_dx, Vec3::ZERO);
    let g = Derivatives2::new(Vec2::X, Vec2::ZERO);
    let flat = Derivatives3::default();
    let in_plane_cos = -1.0 / DIFF_MIN_COS;
    vec![
        Box::new(Table {
            module: Module::RayDiff,
            function: "eye_ray_direction",
            mirror: |(p, s, fov, r, u, v)| rd::eye_ray_direction(p, s, fov, r, u, v),
            tolerance: |&(_, s, fov, ..), _| {
                2.0 * tan_error(0.5 * fov.clamp(0.0, 3.1)) * s.x.max(1.0) / s.y.max(1.0) + ulps(8.0, 1.0)
            },
            rows: vec![
                value(
                    "zero viewport (0 x 0)",
                    "-view (a 1 x 1 image: the centre ray)",
                    camera(Vec2::ZERO, 1.0),
                    vec![0.0, 0.0, -1.0],
                ),
                value(
                    "zero field of view",
                    "-view for every pixel",
                    (Vec2::new(10.0, 5.0), Vec2::new(100.0, 50.0), 0.0, x, y, z),
                    vec![0.0, 0.0, -1.0],
                ),
                mirror(
                    "NaN in (fov_y)",
                    "CPU: NaN",
                    camera(Vec2::splat(64.0), NAN),
                    vec![NAN; 3],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "normalized_derivative",
            mirror: |(v, dv)| rd::normalized_derivative(v, dv),
            tolerance: |_, e| ulps(6.0, e),
            rows: vec![value(
                "zero vector",
                "dv / sqrt(DIFF_MIN_MAGNITUDE)",
                (Vec3::ZERO, z),
                vec![0.0, 0.0, 1.0 / DIFF_MIN_MAGNITUDE.sqrt()],
            )],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "eye_ray_diff",
            mirror: |(p, s, fov, r, u, v)| rd::eye_ray_diff(p, s, fov, r, u, v),
            tolerance: |&(_, s, fov, ..), _| {
                4.0 * tan_error(0.5 * fov.clamp(0.0, 3.1)) / s.min_element().max(1.0) + ulps(16.0, 1.0)
            },
            rows: vec![
                same(
                    "zero viewport (0 x 0)",
                    "as a 1 x 1 image",
                    camera(Vec2::ZERO, 1.0),
                    camera(Vec2::ONE, 1.0),
                ),
                value(
                    "zero field of view",
                    "0",
                    camera(Vec2::splat(64.0), 0.0),
                    parts(RayDiff::ZERO),
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "eye_ray_direction_from_matrices",
            mirror: |(p, s, v, pr)| rd::eye_ray_direction_from_matrices(p, s, v, pr),
            tolerance: |_, _| ulps(8.0, 1.0),
            rows: vec![
                same(
                    "zero viewport (0 x 0)",
                    "as a 1 x 1 image",
                    (Vec2::ZERO, Vec2::ZERO, Mat4::IDENTITY, proj_inv),
                    (Vec2::ZERO, Vec2::ONE, Mat4::IDENTITY, proj_inv),
                ),
                value(
                    "zero inverse projection",
                    "0 (the zero vector is not normalized)",
                    (Vec2::ZERO, Vec2::splat(64.0), Mat4::IDENTITY, Mat4::ZERO),
                    vec![0.0; 3],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "eye_ray_diff_from_matrices",
            mirror: |(p, s, v, pr)| rd::eye_ray_diff_from_matrices(p, s, v, pr),
            tolerance: |_, _| ulps(16.0, 1.0),
            rows: vec![
                same(
                    "zero viewport (0 x 0)",
                    "as a 1 x 1 image",
                    (Vec2::ZERO, Vec2::ZERO, Mat4::IDENTITY, proj_inv),
                    (Vec2::ZERO, Vec2::ONE, Mat4::IDENTITY, proj_inv),
                ),
                value(
                    "zero inverse projection",
                    "0",
                    (Vec2::ZERO, Vec2::splat(64.0), Mat4::IDENTITY, Mat4::ZERO),
                    parts(RayDiff::ZERO),
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "pixel_directions",
            mirror: |(p, s, v, pr)| rd::pixel_directions(p, s, v, pr),
            tolerance: |_, _| ulps(8.0, 1.0),
            rows: vec![
                same(
                    "zero viewport (0 x 0)",
                    "as a 1 x 1 image",
                    (Vec2::ZERO, Vec2::ZERO, Mat4::IDENTITY, proj_inv),
                    (Vec2::ZERO, Vec2::ONE, Mat4::IDENTITY, proj_inv),
                ),
                value(
                    "zero inverse projection",
                    "0",
                    (Vec2::ZERO, Vec2::splat(64.0), Mat4::IDENTITY, Mat4::ZERO),
                    vec![0.0; 6],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "transfer",
            mirror: |(diff, d, t, n)| rd::transfer(diff, d, t, n),
            tolerance: |_, e| ulps(8.0, e),
            rows: vec![
                value(
                    "ray in the plane (dot(D, N) = 0)",
                    "dot(D, N) clamped to +DIFF_MIN_COS: dP = q - dot(q, N) / DIFF_MIN_COS * D",
                    (zero_diff_dx(z), x, 1.0, z),
                    parts(RayDiff::new(
                        Vec3::new(in_plane_cos, 0.0, 1.0),
                        Vec3::ZERO,
                        Vec3::ZERO,
                        Vec3::ZERO,
                    )),
                ),
                value(
                    "t = 0",
                    "dO moved along D onto the plane",
                    (zero_diff_dx(Vec3::new(1.0, 0.0, 1.0)), Vec3::NEG_Z, 0.0, z),
                    parts(RayDiff::new(x, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO)),
                ),
                value(
                    "huge t (1e12)",
                    "t dD (finite)",
                    (direction_dx(Vec3::new(1.0e-3, 0.0, 0.0)), Vec3::NEG_Z, 1.0e12, z),
                    parts(RayDiff::new(
                        Vec3::new(1.0e-3 * 1.0e12, 0.0, 0.0),
                        Vec3::ZERO,
                        Vec3::new(1.0e-3, 0.0, 0.0),
                        Vec3::ZERO,
                    )),
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "barycentric_derivatives",
            mirror: |(diff, d, t, p0, p1, p2)| rd::barycentric_derivatives(diff, d, t, p0, p1, p2),
            tolerance: |_, e| ulps(3.0, e),
            rows: vec![
                value(
                    "zero-area triangle (p1 = p2)",
                    "k clamped to DIFF_MIN_MAGNITUDE, results clamped to +-DIFF_MAX_VALUE",
                    (zero_diff_dx(y), Vec3::NEG_Z, 0.0, Vec3::ZERO, x, x),
                    vec![rd::DIFF_MAX_VALUE, -rd::DIFF_MAX_VALUE, 0.0, 0.0],
                ),
                value(
                    "t = 0, dO = 0",
                    "0",
                    (direction_dx(x), Vec3::NEG_Z, 0.0, Vec3::ZERO, x, y),
                    vec![0.0; 4],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "texture_derivatives",
            mirror: |(b, t0, t1, t2)| rd::texture_derivatives(b, t0, t1, t2),
            tolerance: |_, e| ulps(2.0, e),
            rows: vec![value(
                "collinear UVs",
                "finite, parallel gradients",
                (
                    Derivatives2::new(Vec2::X, Vec2::Y),
                    Vec2::ZERO,
                    Vec2::ONE,
                    Vec2::splat(2.0),
                ),
                vec![1.0, 1.0, 2.0, 2.0],
            )],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "texel_derivatives",
            mirror: |(b, t0, t1, t2, size)| rd::texel_derivatives(b, t0, t1, t2, size),
            tolerance: |_, e| ulps(2.0, e),
            rows: vec![same(
                "zero texture size",
                "as a 1 x 1 texture",
                (g, Vec2::ZERO, Vec2::X, Vec2::Y, Vec2::ZERO),
                (g, Vec2::ZERO, Vec2::X, Vec2::Y, Vec2::ONE),
            )],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "lod_isotropic",
            mirror: |(g,)| rd::lod_isotropic(g),
            tolerance: |_, e| 0.5 * log2_error(2.0 * e) + ulps(1.0, e),
            rows: vec![
                value(
                    "zero gradients",
                    "0.5 log2(DIFF_MIN_MAGNITUDE)",
                    (Derivatives2::default(),),
                    vec![0.5 * DIFF_MIN_MAGNITUDE.log2()],
                ),
                mirror(
                    "infinity in",
                    "CPU: inf",
                    (Derivatives2::new(Vec2::new(INF, 0.0), Vec2::ZERO),),
                    vec![INF],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "lod_box",
            mirror: |(g,)| rd::lod_box(g),
            tolerance: |_, e| log2_error(e),
            rows: vec![
                value(
                    "zero gradients",
                    "log2(DIFF_MIN_MAGNITUDE)",
                    (Derivatives2::default(),),
                    vec![DIFF_MIN_MAGNITUDE.log2()],
                ),
                mirror(
                    "NaN in",
                    "CPU: log2 of the other components' extent (Rust's `max` ignores NaN)",
                    (Derivatives2::new(Vec2::new(NAN, 1.0), Vec2::ZERO),),
                    vec![0.0],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "sample_grad_gradients",
            mirror: |(g, scale)| rd::sample_grad_gradients(g, scale),
            tolerance: |_, _| 0.0,
            rows: vec![value(
                "negative scale",
                "0 (scale clamped to >= 0)",
                (Derivatives2::new(Vec2::ONE, Vec2::ONE), -1.0),
                vec![0.0; 4],
            )],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "normal_derivatives",
            mirror: |(n0, n1, n2, uv, b)| rd::normal_derivatives(n0, n1, n2, uv, b),
            tolerance: |_, e| ulps(6.0, e),
            rows: vec![value(
                "interpolated normal of length 0 (opposite vertex normals)",
                "dn / sqrt(DIFF_MIN_MAGNITUDE)",
                (z, -z, z, Vec2::new(0.5, 0.0), g),
                vec![0.0, 0.0, -2.0 / DIFF_MIN_MAGNITUDE.sqrt(), 0.0, 0.0, 0.0],
            )],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "reflect_ray_diff",
            mirror: |(diff, d, n, dn)| rd::reflect_ray_diff(diff, d, n, dn),
            tolerance: |_, e| ulps(4.0, e),
            rows: vec![value(
                "ray in the surface plane, flat surface",
                "dD - 2 dot(dD, N) N",
                (direction_dx(z), x, z, flat),
                parts(direction_dx(-z)),
            )],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "refract_ray_diff",
            mirror: |(diff, d, n, dn, eta)| rd::refract_ray_diff(diff, d, n, dn, eta),
            tolerance: |_, e| ulps(8.0, e),
            rows: vec![
                value(
                    "ray in the surface plane, eta = 1",
                    "dot(T, N) = 0 clamped to DIFF_MIN_COS: dT = 0 here, no reflection",
                    (direction_dx(z), x, z, flat, 1.0),
                    [parts(RayDiff::ZERO), vec![0.0]].concat(),
                ),
                value(
                    "ray in the surface plane, eta = 1.5",
                    "total internal reflection: flag set, the reflected differential",
                    (direction_dx(z), x, z, flat, 1.5),
                    [parts(direction_dx(-z)), vec![1.0]].concat(),
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "tangent_plane_offsets",
            mirror: |(r, rx, ry, t, n)| rd::tangent_plane_offsets(r, rx, ry, t, n),
            tolerance: |_, e| ulps(4.0, e),
            rows: vec![
                value("t = 0", "0", (-z, x, -z, 0.0, z), vec![0.0; 6]),
                value(
                    "neighbour ray in the tangent plane",
                    "dot(rdx, n) clamped to +DIFF_MIN_COS",
                    (-z, x, -z, 1.0, z),
                    vec![in_plane_cos, 0.0, 1.0, 0.0, 0.0, 0.0],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "triplanar_weights",
            mirror: |(n, k)| rd::triplanar_weights(n, k),
            tolerance: |_, e| ulps(8.0, e),
            rows: vec![
                value(
                    "zero normal, sharpness 1",
                    "1/3 each",
                    (Vec3::ZERO, 1.0),
                    vec![DIFF_MIN_MAGNITUDE / (3.0 * DIFF_MIN_MAGNITUDE); 3],
                ),
                value(
                    "zero normal, sharpness 4",
                    "0 each (DIFF_MIN_MAGNITUDE^4 underflows)",
                    (Vec3::ZERO, 4.0),
                    vec![0.0; 3],
                ),
                value(
                    "sharpness 0",
                    "1/3 each",
                    (Vec3::new(0.6, 0.0, 0.8), 0.0),
                    vec![1.0 / 3.0; 3],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "intersect_triangle_plane",
            mirror: |(o, d, p0, p1, p2)| rd::intersect_triangle_plane(o, d, p0, p1, p2),
            tolerance: |_, e| ulps(3.0, e),
            rows: vec![
                value(
                    "ray parallel to the plane",
                    "k clamped, u and v clamped to +-DIFF_MAX_VALUE",
                    (z, x, Vec3::ZERO, x, y),
                    vec![rd::DIFF_MAX_VALUE, -rd::DIFF_MAX_VALUE, 0.0],
                ),
                value(
                    "zero-area triangle (one point)",
                    "(1, 0, 0)",
                    (z, -z, x, x, x),
                    vec![1.0, 0.0, 0.0],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "barycentric_offsets",
            mirror: |(m, o, p0, p1, p2, dx, dy, hit)| rd::barycentric_offsets(m, o, p0, p1, p2, dx, dy, hit),
            tolerance: |_, e| ulps(3.0, e),
            rows: vec![value(
                "zero-area triangle (one point)",
                "(1, 0, 0) - hit, both ways",
                offset_args(),
                [OFFSET; 2].concat(),
            )],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "barycentric_deltas",
            mirror: |(m, o, p0, p1, p2, dx, dy, hit)| rd::barycentric_deltas(m, o, p0, p1, p2, dx, dy, hit),
            tolerance: |_, e| ulps(3.0, e),
            rows: vec![value(
                "zero-area triangle (one point)",
                "2 |(1, 0, 0) - hit|",
                offset_args(),
                OFFSET.map(|v| 2.0 * v.abs()).to_vec(),
            )],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "cone_barycentric_deltas",
            mirror: |(footprint, p0, p1, p2)| rd::cone_barycentric_deltas(footprint, p0, p1, p2),
            tolerance: |_, e| ulps(3.0, e),
            rows: vec![
                value(
                    "zero-area triangle",
                    "DIFF_MAX_VALUE each",
                    (1.0, Vec3::ZERO, x, 2.0 * x),
                    vec![rd::DIFF_MAX_VALUE; 3],
                ),
                value(
                    "zero-area triangle, zero footprint",
                    "0",
                    (0.0, Vec3::ZERO, x, 2.0 * x),
                    vec![0.0; 3],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "anisotropic_cone_axes",
            mirror: |(w, n, d)| rd::anisotropic_cone_axes(w, n, d),
            tolerance: |a, _| widest(diff_suite::anisotropic_cone_axes(), a),
            rows: vec![
                value(
                    "normal incidence (d = -n)",
                    "a circle: |width| along Duff et al.'s tangent of n and along cross(n, tangent)",
                    (0.5, z, -z),
                    vec![0.5, 0.0, 0.0, 0.0, 0.5, 0.0],
                ),
                value(
                    "ray in the surface plane",
                    "major axis |width| / DIFF_MIN_COS along d, minor |width|",
                    (0.5, z, x),
                    vec![0.5 / DIFF_MIN_COS, 0.0, 0.0, 0.0, 0.5, 0.0],
                ),
                value(
                    "grazing (|dot(n, d)| = 1e-6)",
                    "as the ray in the surface plane (|cos| clamped to DIFF_MIN_COS)",
                    (0.5, z, direction_at(1.0e-6)),
                    vec![0.5 / DIFF_MIN_COS, 0.0, 0.0, 0.0, 0.5, 0.0],
                ),
                value("zero width", "zero axes", (0.0, z, -z), vec![0.0; 6]),
                same("negative width", "as |width|", (-0.5, z, -z), (0.5, z, -z)),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "anisotropic_cone_gradients",
            mirror: |(w, d, p0, p1, p2, uv0, uv1, uv2)| {
                rd::anisotropic_cone_gradients(w, d, p0, p1, p2, uv0, uv1, uv2)
            },
            tolerance: |a, _| widest(diff_suite::anisotropic_cone_gradients(), a),
            rows: vec![
                value(
                    "normal incidence, unit triangle, uv = xy",
                    "(|width|, 0), (0, |width|)",
                    (0.5, -z, Vec3::ZERO, x, y, Vec2::ZERO, Vec2::X, Vec2::Y),
                    vec![0.5, 0.0, 0.0, 0.5],
                ),
                value(
                    "ray in the triangle's plane",
                    "(|width| / DIFF_MIN_COS, 0), (0, |width|)",
                    (0.5, x, Vec3::ZERO, x, y, Vec2::ZERO, Vec2::X, Vec2::Y),
                    vec![0.5 / DIFF_MIN_COS, 0.0, 0.0, 0.5],
                ),
                value(
                    "zero-area triangle (repeated vertex)",
                    "zero gradients (the unit normal is 0)",
                    (0.5, -z, Vec3::ZERO, x, Vec3::ZERO, Vec2::ZERO, Vec2::X, Vec2::Y),
                    vec![0.0; 4],
                ),
                value(
                    "zero width",
                    "zero gradients",
                    (0.0, -z, Vec3::ZERO, x, y, Vec2::ZERO, Vec2::X, Vec2::Y),
                    vec![0.0; 4],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "ray_diff_from_cone",
            mirror: |(c, d)| rd::ray_diff_from_cone(c, d),
            tolerance: |a, _| widest(diff_suite::ray_diff_from_cone(), a),
            rows: vec![
                value("zero cone", "zero differential", (Vec2::ZERO, -z), vec![0.0; 16]),
                value(
                    "direction -Z",
                    "u = (1, 0, 0), v = (0, -1, 0)",
                    (Vec2::new(0.5, 0.25), -z),
                    parts(RayDiff::new(0.5 * x, -0.5 * y, 0.25 * x, -0.25 * y)),
                ),
                value(
                    "direction +Z",
                    "u = (1, 0, 0), v = (0, 1, 0)",
                    (Vec2::new(0.5, 0.25), z),
                    parts(RayDiff::new(0.5 * x, 0.5 * y, 0.25 * x, 0.25 * y)),
                ),
                value(
                    "zero direction",
                    "u = (1, 0, 0), v = 0: the y differentials vanish",
                    (Vec2::new(0.5, 0.25), Vec3::ZERO),
                    parts(RayDiff::new(0.5 * x, Vec3::ZERO, 0.25 * x, Vec3::ZERO)),
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiff,
            function: "cone_from_ray_diff",
            mirror: |(diff, d)| rd::cone_from_ray_diff(diff, d),
            tolerance: |a, _| widest(diff_suite::cone_from_ray_diff(), a),
            rows: vec![
                value("zero differential", "(0, 0)", (RayDiff::ZERO, -z), vec![0.0, 0.0]),
                value(
                    "pinhole eye ray (dO = 0), |dD/dx| = 0.01, |dD/dy| = 0.02",
                    "(0, mean spread 0.015), diverging",
                    (RayDiff::new(Vec3::ZERO, Vec3::ZERO, 0.01 * x, 0.02 * y), -z),
                    vec![0.0, 0.5 * (0.01 + 0.02)],
                ),
                value(
                    "origin and direction changes pointing apart",
                    "negative spread (converging)",
                    (RayDiff::new(x, y, -0.5 * x, -0.5 * y), -z),
                    vec![1.0, -0.5],
                ),
                value(
                    "changes along the ray only",
                    "(0, 0): only the parts across the ray count",
                    (RayDiff::new(2.0 * z, 2.0 * z, z, z), -z),
                    vec![0.0, 0.0],
                ),
            ],
        }),
    ]
}

/// The widest of an agreement check's per-component tolerances for `args`.
fn widest<A: Args, R: Value>(check: FunctionCheck<A, R>, args: &A) -> f32 {
    check
        .bounds(args, &check.mirror(args.clone()))
        .into_iter()
        .fold(0.0, f32::max)
}

/// `(1, 0, 0) - hit` for the hit of [`offset_args`]: what a zero-area triangle gives.
const OFFSET: [f32; 3] = [0.75, -0.25, -0.5];

type OffsetArgs = (Mat4, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3);

/// Re-intersection arguments with a triangle collapsed to one point and hit `(0.25, 0.25, 0.5)`.
fn offset_args() -> OffsetArgs {
    let point = Vec3::new(0.0, 0.0, -5.0);
    (
        Mat4::IDENTITY,
        Vec3::ZERO,
        point,
        point,
        point,
        Vec3::X * 0.01 - Vec3::Z,
        Vec3::Y * 0.01 - Vec3::Z,
        Vec3::new(0.25, 0.25, 0.5),
    )
}

fn ray_diff_f64() -> Vec<Box<dyn Degenerate>> {
    let (x, y, z) = (Vec3::X, Vec3::Y, Vec3::Z);
    let max = rd64::F64_MAX_VALUE as f32;
    let offset = (DVec3::X - DVec3::new(0.25, 0.25, 0.5)).as_vec3();
    assert_eq!(offset.to_array(), OFFSET, "the offsets are exact in f32 and f64");
    vec![
        Box::new(Table {
            module: Module::RayDiffF64,
            function: "intersect_triangle_plane_f64",
            mirror: |(o, d, p0, p1, p2)| rd64::intersect_triangle_plane_f64(o, d, p0, p1, p2),
            tolerance: |_, e| ulps(1.0, e),
            rows: vec![
                value(
                    "ray parallel to the plane",
                    "k clamped, u and v clamped to +-F64_MAX_VALUE",
                    (z, x, Vec3::ZERO, x, y),
                    vec![max, -max, 0.0],
                ),
                value(
                    "zero-area triangle (one point)",
                    "(1, 0, 0)",
                    (z, -z, x, x, x),
                    vec![1.0, 0.0, 0.0],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::RayDiffF64,
            function: "barycentric_offsets_f64",
            mirror: |(m, o, p0, p1, p2, dx, dy, hit)| {
                rd64::barycentric_offsets_f64(m, o, p0, p1, p2, dx, dy, hit)
            },
            tolerance: |_, e| ulps(1.0, e),
            rows: vec![value(
                "zero-area triangle (one point)",
                "(1, 0, 0) - hit, both ways",
                offset_args(),
                [OFFSET; 2].concat(),
            )],
        }),
        Box::new(Table {
            module: Module::RayDiffF64,
            function: "barycentric_deltas_f64",
            mirror: |(m, o, p0, p1, p2, dx, dy, hit)| {
                rd64::barycentric_deltas_f64(m, o, p0, p1, p2, dx, dy, hit)
            },
            tolerance: |_, e| ulps(1.0, e),
            rows: vec![value(
                "zero-area triangle (one point)",
                "2 |(1, 0, 0) - hit|",
                offset_args(),
                OFFSET.map(|v| 2.0 * v.abs()).to_vec(),
            )],
        }),
    ]
}

fn settings(f: impl FnOnce(&mut WireframeSettings)) -> WireframeSettings {
    let mut settings = WIREFRAME_DEFAULT;
    f(&mut settings);
    settings
}

fn wireframe() -> Vec<Box<dyn Degenerate>> {
    let on_edge = Vec3::new(0.0, 0.5, 0.5);
    let near_edge = Vec3::new(0.004, 0.496, 0.5);
    let deltas = Vec3::splat(0.01);
    let io = WireframeSettingsIo {
        stipple: 7,
        ..WIREFRAME_DEFAULT.pack()
    };
    vec![
        Box::new(Table {
            module: Module::Wireframe,
            function: "unpack_wireframe_settings",
            mirror: |(io,)| wf::unpack_wireframe_settings(io),
            tolerance: |_, _| 0.0,
            rows: vec![
                value(
                    "flag 7 (any non-zero)",
                    "true (packed again as 1)",
                    (io,),
                    parts(WireframeSettings {
                        stipple: true,
                        ..WIREFRAME_DEFAULT
                    }),
                ),
                mirror(
                    "NaN in (thickness)",
                    "CPU: kept",
                    (WireframeSettingsIo {
                        thickness: NAN,
                        ..WIREFRAME_DEFAULT.pack()
                    },),
                    parts(WireframeSettings {
                        thickness: NAN,
                        ..WIREFRAME_DEFAULT
                    }),
                ),
            ],
        }),
        Box::new(Table {
            module: Module::Wireframe,
            function: "edge_position",
            mirror: |(b,)| wf::edge_position(b),
            tolerance: |_, _| 0.0,
            rows: vec![mirror(
                "NaN in (b.x)",
                "CPU: max(b.y, b.z) (Rust's `max` ignores NaN)",
                (Vec3::new(NAN, 0.2, 0.3),),
                vec![0.3],
            )],
        }),
        Box::new(Table {
            module: Module::Wireframe,
            function: "edge_thickness",
            mirror: |(var, e)| wf::edge_thickness(var, e),
            tolerance: |_, e| ulps(4.0, e),
            rows: vec![
                same(
                    "edge position 2",
                    "as edge position 1 (clamped to `[0, 1]`)",
                    (Vec2::new(0.5, 2.0), 2.0),
                    (Vec2::new(0.5, 2.0), 1.0),
                ),
                same(
                    "edge position -1",
                    "as edge position 0",
                    (Vec2::new(0.5, 2.0), -1.0),
                    (Vec2::new(0.5, 2.0), 0.0),
                ),
                same(
                    "negative thickness_var",
                    "as 0",
                    (Vec2::new(-1.0, 2.0), 0.5),
                    (Vec2::new(0.0, 2.0), 0.5),
                ),
            ],
        }),
        Box::new(Table {
            module: Module::Wireframe,
            function: "stipple",
            mirror: |(repeats, length, e)| wf::stipple(repeats, length, e),
            tolerance: |_, _| 0.0,
            rows: vec![
                value("repeats 0", "1 (no dashes)", (0, 0.5, 0.3), vec![1.0]),
                value("negative repeats", "1 (no dashes)", (-3, 0.5, 0.3), vec![1.0]),
                value("stipple length 0", "0 (nothing drawn)", (5, 0.0, 0.3), vec![0.0]),
                mirror(
                    "NaN in (stipple length)",
                    "CPU: 0 (pattern < NaN is false)",
                    (5, NAN, 0.3),
                    vec![0.0],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::Wireframe,
            function: "edge_ramp",
            mirror: |(v, start, width)| wf::edge_ramp(v, start, width),
            tolerance: |_, e| ulps(4.0, e),
            rows: vec![
                value(
                    "zero ramp width, x = start",
                    "1 (hard step)",
                    (Vec3::splat(0.5), Vec3::splat(0.5), Vec3::ZERO),
                    vec![1.0; 3],
                ),
                value(
                    "zero ramp width, x < start",
                    "0 (hard step)",
                    (Vec3::splat(0.4), Vec3::splat(0.5), Vec3::ZERO),
                    vec![0.0; 3],
                ),
                mirror(
                    "NaN in (x)",
                    "CPU: 1 (NaN < start is false, Rust's `min` ignores NaN)",
                    (Vec3::splat(NAN), Vec3::splat(0.5), Vec3::ONE),
                    vec![1.0; 3],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::Wireframe,
            function: "line_width",
            mirror: |(d, th, sm, b)| wf::line_width(d, th, sm, b),
            tolerance: |_, e| ulps(4.0, e),
            rows: vec![
                value(
                    "smoothing 0, inside the line",
                    "1 (hard step)",
                    (deltas, 1.0, 0.0, near_edge),
                    vec![1.0],
                ),
                value(
                    "smoothing 0, outside the line",
                    "0 (hard step)",
                    (deltas, 0.1, 0.0, near_edge),
                    vec![0.0],
                ),
                value(
                    "zero deltas",
                    "0 (a line of zero width)",
                    (Vec3::ZERO, 1.0, 1.0, near_edge),
                    vec![0.0],
                ),
            ],
        }),
        Box::new(Table {
            module: Module::Wireframe,
            function: "process_wireframe",
            mirror: |(s, b, d)| wf::process_wireframe(s, b, d),
            tolerance: |_, e| ulps(8.0, e),
            rows: vec![
                value(
                    "smoothing 0, on an edge",
                    "1 (hard step)",
                    (settings(|s| s.smoothing = 0.0), on_edge, deltas),
                    vec![1.0],
                ),
                same(
                    "stipple on, repeats 0",
                    "as stipple off",
                    (
                        settings(|s| {
                            s.stipple = true;
                            s.stipple_repeats = 0
                        }),
                        near_edge,
                        deltas,
                    ),
                    (WIREFRAME_DEFAULT, near_edge, deltas),
                ),
                value(
                    "thickness 0, on an edge",
                    "0 (no line)",
                    (settings(|s| s.thickness = 0.0), on_edge, deltas),
                    vec![0.0],
                ),
                mirror(
                    "NaN in (thickness)",
                    "CPU: 0 (the ramp's NaN bounds compare false)",
                    (settings(|s| s.thickness = NAN), near_edge, deltas),
                    vec![0.0],
                ),
            ],
        }),
    ]
}
