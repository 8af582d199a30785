//! The degenerate-input rows of `ray_diff`.

use super::table::{direction_at, mirror, offset_args, parts, same, value, widest, INF, NAN, OFFSET};
use super::{Degenerate, Table};
use glam::{Mat4, Vec2, Vec3};
use ray_footprint::ray_diff::{
    self as rd, Derivatives2, Derivatives3, RayDiff, DIFF_MIN_COS, DIFF_MIN_MAGNITUDE,
};
use ray_footprint::shaders::Module;
use ray_footprint_lab::checks::ray_diff as diff_suite;
use shader_proptest::tolerance::{log2_error, tan_error, ulps};

pub fn tables() -> Vec<Box<dyn Degenerate>> {
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
