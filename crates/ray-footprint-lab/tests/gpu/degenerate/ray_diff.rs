//! The degenerate-input rows of `ray_diff`.

use super::table::{
    delta_rows, direction_at, mirror, offset_rows, parts, plane_intersection_rows, same, value, widest, INF,
    NAN, OFFSET,
};
use super::{register, Degenerate, Row};
use glam::{Mat4, Vec2, Vec3};
use ray_footprint::ray_diff::{
    self as rd, Derivatives2, Derivatives3, GBufferSample, RayDiff, TriplanarGradients, DIFF_MAX_FOV_Y,
    DIFF_MAX_VALUE, DIFF_MIN_COS, DIFF_MIN_MAGNITUDE,
};
use ray_footprint::registry::Registered;
use ray_footprint::shaders::Module;
use ray_footprint_lab::checks::ray_diff as diff_suite;
use shader_proptest::tolerance::{log2_error, tan_error, ulps};

pub fn tables() -> Vec<Registered<Box<dyn Degenerate>>> {
    let (x, y, z) = (Vec3::X, Vec3::Y, Vec3::Z);
    let proj_inv = glam::camera::rh::proj::vulkan::perspective(1.0, 1.5, 0.1, 100.0).inverse();
    let camera = |size: Vec2, fov: f32| (Vec2::ZERO, size, fov, x, y, z);
    let zero_diff_dx = |d_origin_dx: Vec3| RayDiff::new(d_origin_dx, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);
    let direction_dx =
        |d_direction_dx: Vec3| RayDiff::new(Vec3::ZERO, Vec3::ZERO, d_direction_dx, Vec3::ZERO);
    let g = Derivatives2::new(Vec2::X, Vec2::ZERO);
    let flat = Derivatives3::default();
    let in_plane_cos = -1.0 / DIFF_MIN_COS;
    let max = DIFF_MAX_VALUE;
    let sample = |distance: f32| GBufferSample {
        eye_direction: -z,
        distance,
        normal: z,
    };
    vec![
        register(
            Module::RayDiff,
            "eye_ray_direction",
            |(p, s, fov, r, u, v)| rd::eye_ray_direction(p, s, fov, r, u, v),
            |&(_, s, fov, ..), _| {
                2.0 * tan_error(0.5 * fov.clamp(0.0, 3.1)) * s.x.max(1.0) / s.y.max(1.0) + ulps(8.0, 1.0)
            },
            vec![
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
        ),
        register(
            Module::RayDiff,
            "normalized_derivative",
            |(v, dv)| rd::normalized_derivative(v, dv),
            // dv less its part along v (each at most |dv|), divided by |v|: 6 roundings of the
            // result and of the terms, 2 |dv| / |v| (|v| clamped as the function clamps it).
            |&(v, dv), e| {
                ulps(
                    6.0,
                    e.abs() + 2.0 * dv.length() / v.length().max(DIFF_MIN_MAGNITUDE.sqrt()),
                )
            },
            vec![
                value(
                    "zero vector",
                    "dv / sqrt(DIFF_MIN_MAGNITUDE)",
                    (Vec3::ZERO, z),
                    vec![0.0, 0.0, 1.0 / DIFF_MIN_MAGNITUDE.sqrt()],
                ),
                value(
                    "dv parallel to v (v = (2, 0, 0), dv = (1, 0, 0))",
                    "0: the length changes, the direction does not",
                    (2.0 * x, x),
                    vec![0.0; 3],
                ),
                value(
                    "v of length 2, dv perpendicular",
                    "dv / |v|",
                    (2.0 * z, x),
                    vec![0.5, 0.0, 0.0],
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "eye_ray_diff",
            |(p, s, fov, r, u, v)| rd::eye_ray_diff(p, s, fov, r, u, v),
            |&(_, s, fov, ..), _| {
                4.0 * tan_error(0.5 * fov.clamp(0.0, 3.1)) / s.min_element().max(1.0) + ulps(16.0, 1.0)
            },
            vec![
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
                same(
                    "fov_y = 4 (wider than DIFF_MAX_FOV_Y)",
                    "as fov_y = DIFF_MAX_FOV_Y (3.1)",
                    camera(Vec2::splat(64.0), 4.0),
                    camera(Vec2::splat(64.0), DIFF_MAX_FOV_Y),
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "eye_ray_direction_from_matrices",
            |(p, s, v, pr)| rd::eye_ray_direction_from_matrices(p, s, v, pr),
            |_, _| ulps(8.0, 1.0),
            matrix_rows(proj_inv, "0 (the zero vector is not normalized)", vec![0.0; 3]),
        ),
        register(
            Module::RayDiff,
            "eye_ray_diff_from_matrices",
            |(p, s, v, pr)| rd::eye_ray_diff_from_matrices(p, s, v, pr),
            |_, _| ulps(16.0, 1.0),
            matrix_rows(proj_inv, "0", parts(RayDiff::ZERO)),
        ),
        register(
            Module::RayDiff,
            "pixel_directions",
            |(p, s, v, pr)| rd::pixel_directions(p, s, v, pr),
            |_, _| ulps(8.0, 1.0),
            matrix_rows(proj_inv, "0", vec![0.0; 6]),
        ),
        register(
            Module::RayDiff,
            "transfer",
            |(diff, d, t, n)| rd::transfer(diff, d, t, n),
            |_, e| ulps(8.0, e),
            vec![
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
        ),
        register(
            Module::RayDiff,
            "barycentric_derivatives",
            |(diff, d, t, p0, p1, p2)| rd::barycentric_derivatives(diff, d, t, p0, p1, p2),
            |_, e| ulps(3.0, e),
            vec![
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
                value(
                    "ray in the triangle's plane (k = 0), dO off the plane",
                    "du/dx = -1 / DIFF_MIN_MAGNITUDE clamped to -DIFF_MAX_VALUE; the rest 0",
                    (zero_diff_dx(z), x, 0.0, Vec3::ZERO, x, y),
                    vec![-max, 0.0, 0.0, 0.0],
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "barycentric_w_derivatives",
            |(b,)| rd::barycentric_w_derivatives(b),
            // Negations are exact; one rounding of the difference.
            |&(b,), _| ulps(1.0, (b.dx.abs() + b.dy.abs()).max_element()),
            vec![
                value("zero", "0", (Derivatives2::default(),), vec![0.0; 2]),
                value(
                    "du = -dv",
                    "0: w does not change",
                    (Derivatives2::new(Vec2::new(1.0, -1.0), Vec2::new(0.5, -0.5)),),
                    vec![0.0; 2],
                ),
                value(
                    "clamped differentials (+-DIFF_MAX_VALUE)",
                    "(-2 DIFF_MAX_VALUE, 0): finite",
                    (Derivatives2::new(Vec2::splat(max), Vec2::new(max, -max)),),
                    vec![-2.0 * max, 0.0],
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "texture_derivatives",
            |(b, t0, t1, t2)| rd::texture_derivatives(b, t0, t1, t2),
            |_, e| ulps(2.0, e),
            vec![
                value(
                    "collinear UVs",
                    "finite, parallel gradients",
                    (
                        Derivatives2::new(Vec2::X, Vec2::Y),
                        Vec2::ZERO,
                        Vec2::ONE,
                        Vec2::splat(2.0),
                    ),
                    vec![1.0, 1.0, 2.0, 2.0],
                ),
                value(
                    "all UVs equal",
                    "0",
                    (
                        Derivatives2::new(Vec2::X, Vec2::Y),
                        Vec2::splat(0.5),
                        Vec2::splat(0.5),
                        Vec2::splat(0.5),
                    ),
                    vec![0.0; 4],
                ),
                value(
                    "clamped barycentric differentials (DIFF_MAX_VALUE), unit UVs",
                    "finite: (DIFF_MAX_VALUE, 0), (0, DIFF_MAX_VALUE)",
                    (
                        Derivatives2::new(Vec2::new(max, 0.0), Vec2::new(0.0, max)),
                        Vec2::ZERO,
                        Vec2::X,
                        Vec2::Y,
                    ),
                    vec![max, 0.0, 0.0, max],
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "texel_derivatives",
            |(b, t0, t1, t2, size)| rd::texel_derivatives(b, t0, t1, t2, size),
            |_, e| ulps(2.0, e),
            vec![
                same(
                    "zero texture size",
                    "as a 1 x 1 texture",
                    (g, Vec2::ZERO, Vec2::X, Vec2::Y, Vec2::ZERO),
                    (g, Vec2::ZERO, Vec2::X, Vec2::Y, Vec2::ONE),
                ),
                same(
                    "negative texture size",
                    "as a 1 x 1 texture",
                    (g, Vec2::ZERO, Vec2::X, Vec2::Y, Vec2::new(-4.0, -8.0)),
                    (g, Vec2::ZERO, Vec2::X, Vec2::Y, Vec2::ONE),
                ),
                value(
                    "zero barycentric differentials",
                    "0",
                    (
                        Derivatives2::default(),
                        Vec2::ZERO,
                        Vec2::X,
                        Vec2::Y,
                        Vec2::splat(1024.0),
                    ),
                    vec![0.0; 4],
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "secondary_origin_derivatives",
            |(b, p0, p1, p2)| rd::secondary_origin_derivatives(b, p0, p1, p2),
            // Two edge differences, two products and a sum: 4 roundings of |du| |e1| + |dv| |e2|.
            |&(b, p0, p1, p2), _| {
                let edges = (p1 - p0).abs().max_element() + (p2 - p0).abs().max_element();
                ulps(4.0, (b.dx.abs() + b.dy.abs()).max_element() * edges)
            },
            vec![
                value(
                    "zero-area triangle (one point)",
                    "0: the hit cannot move",
                    (Derivatives2::new(Vec2::ONE, Vec2::ONE), x, x, x),
                    vec![0.0; 6],
                ),
                value(
                    "zero barycentric differentials",
                    "0",
                    (Derivatives2::default(), Vec3::ZERO, x, y),
                    vec![0.0; 6],
                ),
                value(
                    "clamped differentials (+-DIFF_MAX_VALUE), unit triangle",
                    "DIFF_MAX_VALUE e1 and -DIFF_MAX_VALUE e2: finite",
                    (
                        Derivatives2::new(Vec2::new(max, 0.0), Vec2::new(0.0, -max)),
                        Vec3::ZERO,
                        x,
                        y,
                    ),
                    vec![max, 0.0, 0.0, 0.0, -max, 0.0],
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "lod_isotropic",
            |(g,)| rd::lod_isotropic(g),
            |_, e| 0.5 * log2_error(2.0 * e) + ulps(1.0, e),
            vec![
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
                value(
                    "unit texel gradients",
                    "0 (one texel per pixel)",
                    (Derivatives2::new(Vec2::X, Vec2::Y),),
                    vec![0.0],
                ),
                value(
                    "gradients of 1e-16 (rho^2 below DIFF_MIN_MAGNITUDE)",
                    "0.5 log2(DIFF_MIN_MAGNITUDE)",
                    (Derivatives2::new(Vec2::new(1.0e-16, 0.0), Vec2::ZERO),),
                    vec![0.5 * DIFF_MIN_MAGNITUDE.log2()],
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "lod_box",
            |(g,)| rd::lod_box(g),
            |_, e| log2_error(e),
            vec![
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
                value(
                    "unit texel gradients",
                    "0",
                    (Derivatives2::new(Vec2::X, Vec2::Y),),
                    vec![0.0],
                ),
                value(
                    "dx = (1, 0), dy = (-1, 0)",
                    "1: the box adds magnitudes, opposite signs do not cancel",
                    (Derivatives2::new(Vec2::X, Vec2::NEG_X),),
                    vec![1.0],
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "sample_grad_gradients",
            |(g, scale)| rd::sample_grad_gradients(g, scale),
            |_, _| 0.0,
            vec![
                value(
                    "negative scale",
                    "0 (scale clamped to >= 0)",
                    (Derivatives2::new(Vec2::ONE, Vec2::ONE), -1.0),
                    vec![0.0; 4],
                ),
                value(
                    "scale 0",
                    "0 (samples mip 0)",
                    (Derivatives2::new(Vec2::ONE, Vec2::ONE), 0.0),
                    vec![0.0; 4],
                ),
                value(
                    "scale 1",
                    "the gradients unchanged",
                    (Derivatives2::new(Vec2::new(0.5, -0.25), Vec2::new(2.0, 1.0)), 1.0),
                    vec![0.5, -0.25, 2.0, 1.0],
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "normal_derivatives",
            |(n0, n1, n2, uv, b)| rd::normal_derivatives(n0, n1, n2, uv, b),
            |_, e| ulps(6.0, e),
            vec![
                value(
                    "interpolated normal of length 0 (opposite vertex normals)",
                    "dn / sqrt(DIFF_MIN_MAGNITUDE)",
                    (z, -z, z, Vec2::new(0.5, 0.0), g),
                    vec![0.0, 0.0, -2.0 / DIFF_MIN_MAGNITUDE.sqrt(), 0.0, 0.0, 0.0],
                ),
                value(
                    "equal vertex normals (flat)",
                    "0",
                    (z, z, z, Vec2::splat(0.25), Derivatives2::new(Vec2::X, Vec2::Y)),
                    vec![0.0; 6],
                ),
                value(
                    "zero barycentric differentials",
                    "0",
                    (z, x, y, Vec2::splat(0.25), Derivatives2::default()),
                    vec![0.0; 6],
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "reflect_ray_diff",
            |(diff, d, n, dn)| rd::reflect_ray_diff(diff, d, n, dn),
            |_, e| ulps(4.0, e),
            vec![
                value(
                    "ray in the surface plane, flat surface",
                    "dD - 2 dot(dD, N) N",
                    (direction_dx(z), x, z, flat),
                    parts(direction_dx(-z)),
                ),
                value(
                    "zero direction differentials, flat surface",
                    "zero direction differentials, origin differentials kept",
                    (RayDiff::new(x, y, Vec3::ZERO, Vec3::ZERO), -z, z, flat),
                    parts(RayDiff::new(x, y, Vec3::ZERO, Vec3::ZERO)),
                ),
                value(
                    "head-on (D = -N), normal turning by dN/dx = (1, 0, 0)",
                    "dR/dx = 2 dN/dx",
                    (RayDiff::ZERO, -z, z, Derivatives3::new(x, Vec3::ZERO)),
                    parts(RayDiff::new(Vec3::ZERO, Vec3::ZERO, 2.0 * x, Vec3::ZERO)),
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "refract_ray_diff",
            |(diff, d, n, dn, eta)| rd::refract_ray_diff(diff, d, n, dn, eta),
            |_, e| ulps(8.0, e),
            vec![
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
                value(
                    "head-on, eta = 1 (matched indices)",
                    "dD unchanged (mu = 0, dmu = 0), no reflection",
                    (direction_dx(x), -z, z, flat, 1.0),
                    [parts(direction_dx(x)), vec![0.0]].concat(),
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "gbuffer_ray_diff",
            |(c, r, l, b, a, epsilon)| rd::gbuffer_ray_diff(c, r, l, b, a, epsilon),
            // A difference of two products t e (3 roundings of 2 t) and of two reflections (each at
            // most 3 long: a dot product, two products and a difference, 5 roundings of 3).
            |&(c, r, l, b, a, _), _| {
                let largest = [c, r, l, b, a]
                    .iter()
                    .map(|s| s.distance.abs())
                    .fold(0.0, f32::max);
                ulps(3.0, 2.0 * largest) + ulps(6.0, 6.0)
            },
            vec![
                value(
                    "all five samples equal",
                    "zero differential",
                    (
                        sample(1.0),
                        sample(1.0),
                        sample(1.0),
                        sample(1.0),
                        sample(1.0),
                        0.1,
                    ),
                    parts(RayDiff::ZERO),
                ),
                value(
                    "depth edge on the right (t: left 1.5, centre 1, right 10), epsilon 0.1",
                    "the left neighbour: dO/dx = t(0) e(0) - t(-1) e(-1) = (0, 0, 0.5)",
                    (
                        sample(1.0),
                        sample(10.0),
                        sample(1.5),
                        sample(1.0),
                        sample(1.0),
                        0.1,
                    ),
                    parts(RayDiff::new(0.5 * z, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO)),
                ),
                value(
                    "step to the right exactly depth_epsilon (right 1.5, left 1.25, epsilon 0.5)",
                    "the right neighbour, dO/dx = (0, 0, -0.5): switching needs a larger step",
                    (
                        sample(1.0),
                        sample(1.5),
                        sample(1.25),
                        sample(1.0),
                        sample(1.0),
                        0.5,
                    ),
                    parts(RayDiff::new(-0.5 * z, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO)),
                ),
                value(
                    "right neighbour's normal perpendicular to its eye ray",
                    "dD/dx = e(+1) - reflect(e(0), n(0)) = (0, 0, -2)",
                    (
                        sample(1.0),
                        GBufferSample {
                            normal: x,
                            ..sample(1.0)
                        },
                        sample(1.0),
                        sample(1.0),
                        sample(1.0),
                        0.1,
                    ),
                    parts(RayDiff::new(Vec3::ZERO, Vec3::ZERO, -2.0 * z, Vec3::ZERO)),
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "tangent_plane_offsets",
            |(r, rx, ry, t, n)| rd::tangent_plane_offsets(r, rx, ry, t, n),
            |_, e| ulps(4.0, e),
            vec![
                value("t = 0", "0", (-z, x, -z, 0.0, z), vec![0.0; 6]),
                value(
                    "neighbour ray in the tangent plane",
                    "dot(rdx, n) clamped to +DIFF_MIN_COS",
                    (-z, x, -z, 1.0, z),
                    vec![in_plane_cos, 0.0, 1.0, 0.0, 0.0, 0.0],
                ),
                value(
                    "neighbour rays equal to the centre ray",
                    "0",
                    (-z, -z, -z, 5.0, z),
                    vec![0.0; 6],
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "planar_mapping_gradients",
            |(dp, scale)| rd::planar_mapping_gradients(dp, scale),
            // One product per component.
            |_, e| ulps(1.0, e),
            vec![
                value(
                    "zero scale",
                    "0",
                    (Derivatives3::new(Vec3::ONE, Vec3::ONE), Vec2::ZERO),
                    vec![0.0; 4],
                ),
                value(
                    "position changing along y only (normal to the mapping plane)",
                    "0",
                    (Derivatives3::new(y, -2.0 * y), Vec2::ONE),
                    vec![0.0; 4],
                ),
                value(
                    "negative scale (-1, 0.5)",
                    "mirrored in u: dx = (-1, 1), dy = (0, -2)",
                    (
                        Derivatives3::new(Vec3::new(1.0, 0.0, 2.0), Vec3::new(0.0, 0.0, -4.0)),
                        Vec2::new(-1.0, 0.5),
                    ),
                    vec![-1.0, 1.0, 0.0, -2.0],
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "triplanar_weights",
            |(n, k)| rd::triplanar_weights(n, k),
            |_, e| ulps(8.0, e),
            vec![
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
        ),
        register(
            Module::RayDiff,
            "triplanar_gradients",
            |(dp, scale)| rd::triplanar_gradients(dp, scale),
            // One product per component.
            |_, e| ulps(1.0, e),
            vec![
                value(
                    "zero scale",
                    "0 for every projection",
                    (Derivatives3::new(Vec3::ONE, Vec3::ONE), 0.0),
                    vec![0.0; 12],
                ),
                value(
                    "zero position differentials",
                    "0 for every projection",
                    (Derivatives3::default(), 2.0),
                    vec![0.0; 12],
                ),
                value(
                    "dp/dx = (1, 0, 0), dp/dy = (0, 1, 0), scale 2",
                    "each projection sees its own two axes: yz gets (0, 0) and (2, 0)",
                    (Derivatives3::new(x, y), 2.0),
                    parts(TriplanarGradients {
                        yz: Derivatives2::new(Vec2::ZERO, Vec2::new(2.0, 0.0)),
                        zx: Derivatives2::new(Vec2::new(0.0, 2.0), Vec2::ZERO),
                        xy: Derivatives2::new(Vec2::new(2.0, 0.0), Vec2::new(0.0, 2.0)),
                    }),
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "intersect_triangle_plane",
            |(o, d, p0, p1, p2)| rd::intersect_triangle_plane(o, d, p0, p1, p2),
            |_, e| ulps(3.0, e),
            plane_intersection_rows(
                "k clamped, u and v clamped to +-DIFF_MAX_VALUE",
                rd::DIFF_MAX_VALUE,
            ),
        ),
        register(
            Module::RayDiff,
            "barycentric_offsets",
            |(m, o, p0, p1, p2, dx, dy, hit)| rd::barycentric_offsets(m, o, p0, p1, p2, dx, dy, hit),
            |_, e| ulps(3.0, e),
            offset_rows(
                "(DIFF_MAX_VALUE, -DIFF_MAX_VALUE, 0) - hit in f32 (clamped u, v), (1, 0, 0) - hit",
                [vec![max, -max, -0.5], OFFSET.to_vec()].concat(),
            ),
        ),
        register(
            Module::RayDiff,
            "barycentric_deltas",
            |(m, o, p0, p1, p2, dx, dy, hit)| rd::barycentric_deltas(m, o, p0, p1, p2, dx, dy, hit),
            |_, e| ulps(3.0, e),
            delta_rows("(DIFF_MAX_VALUE, DIFF_MAX_VALUE, 1) in f32", vec![max, max, 1.0]),
        ),
        register(
            Module::RayDiff,
            "uv_gradients_from_offsets",
            |(offsets, uv0, uv1, uv2)| rd::uv_gradients_from_offsets(offsets, uv0, uv1, uv2),
            // The agreement check's enclosure, widest over the four components.
            |a, _| widest(diff_suite::uv_gradients_from_offsets(), a),
            vec![
                value(
                    "zero offsets",
                    "0",
                    (Derivatives3::default(), Vec2::ZERO, Vec2::X, Vec2::Y),
                    vec![0.0; 4],
                ),
                value(
                    "offsets summing to 0, all UVs equal",
                    "0: the UV does not change",
                    (
                        Derivatives3::new(Vec3::new(0.5, -0.25, -0.25), Vec3::new(-1.0, 0.5, 0.5)),
                        Vec2::splat(0.5),
                        Vec2::splat(0.5),
                        Vec2::splat(0.5),
                    ),
                    vec![0.0; 4],
                ),
                value(
                    "clamped offsets (+-DIFF_MAX_VALUE), UVs in [0, 1]",
                    "finite: (-DIFF_MAX_VALUE, 0) towards the right neighbour",
                    (
                        Derivatives3::new(Vec3::new(max, -max, 0.0), Vec3::ZERO),
                        Vec2::ZERO,
                        Vec2::X,
                        Vec2::Y,
                    ),
                    vec![-max, 0.0, 0.0, 0.0],
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "cone_barycentric_deltas",
            |(footprint, p0, p1, p2)| rd::cone_barycentric_deltas(footprint, p0, p1, p2),
            |_, e| ulps(3.0, e),
            vec![
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
                same(
                    "negative footprint, zero-area triangle",
                    "as |footprint|",
                    (-1.0, Vec3::ZERO, x, 2.0 * x),
                    (1.0, Vec3::ZERO, x, 2.0 * x),
                ),
            ],
        ),
        register(
            Module::RayDiff,
            "anisotropic_cone_axes",
            |(w, n, d)| rd::anisotropic_cone_axes(w, n, d),
            |a, _| widest(diff_suite::anisotropic_cone_axes(), a),
            vec![
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
        ),
        register(
            Module::RayDiff,
            "anisotropic_cone_gradients",
            |(w, d, p0, p1, p2, uv0, uv1, uv2)| {
                rd::anisotropic_cone_gradients(w, d, p0, p1, p2, uv0, uv1, uv2)
            },
            |a, _| widest(diff_suite::anisotropic_cone_gradients(), a),
            vec![
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
        ),
        register(
            Module::RayDiff,
            "ray_diff_from_cone",
            |(c, d)| rd::ray_diff_from_cone(c, d),
            |a, _| widest(diff_suite::ray_diff_from_cone(), a),
            vec![
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
        ),
        register(
            Module::RayDiff,
            "cone_from_ray_diff",
            |(diff, d)| rd::cone_from_ray_diff(diff, d),
            |a, _| widest(diff_suite::cone_from_ray_diff(), a),
            vec![
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
        ),
    ]
}

/// The rows of the functions of a pixel, the viewport size and the inverse view and projection
/// matrices (`eye_ray_direction_from_matrices`, `eye_ray_diff_from_matrices`, `pixel_directions`):
/// a zero inverse projection gives `zero`, described by `zero_output`.
fn matrix_rows(
    proj_inv: Mat4,
    zero_output: &'static str,
    zero: Vec<f32>,
) -> Vec<Row<(Vec2, Vec2, Mat4, Mat4)>> {
    let (centre, size) = (Vec2::ZERO, Vec2::splat(64.0));
    vec![
        same(
            "zero viewport (0 x 0)",
            "as a 1 x 1 image",
            (centre, Vec2::ZERO, Mat4::IDENTITY, proj_inv),
            (centre, Vec2::ONE, Mat4::IDENTITY, proj_inv),
        ),
        value(
            "zero inverse projection",
            zero_output,
            (centre, size, Mat4::IDENTITY, Mat4::ZERO),
            zero,
        ),
        same(
            "inverse view with a translation (5, -6, 7)",
            "as without: directions ignore it (w = 0)",
            (
                centre,
                size,
                Mat4::from_translation(Vec3::new(5.0, -6.0, 7.0)),
                proj_inv,
            ),
            (centre, size, Mat4::IDENTITY, proj_inv),
        ),
    ]
}
