//! Agreement checks of the ray_diff module, one per function, in the module's order.
//!
//! Every tolerance is the width of an enclosure: the check re-evaluates its function in interval
//! arithmetic on the same inputs, widening after each operation by the rounding error that Vulkan's
//! precision rules allow the device (and that the mirror makes), so both results lie inside. The
//! re-evaluations (`b_*`, one per shader function, in the module's order of operations) are in the
//! `enclosure` submodule, the case strategies in `strategy`.

mod enclosure;
mod strategy;

use super::edge::Edge;
use super::enclosed;
use super::strategy::{
    angle, distance, image_size, magnitude, normal_and_direction, one_argument, scalar, triangle, unit_vec3,
    uv_triangle, vec2_of, vec3, with_corners,
};
use super::{registered_checks, Entry};
use enclosure::{
    b_anisotropic_cone_axes, b_anisotropic_cone_gradients, b_barycentric_derivatives, b_barycentric_offsets,
    b_cone_barycentric_deltas, b_cone_from_ray_diff, b_derivatives2, b_derivatives3, b_determinant,
    b_eye_ray_diff, b_eye_ray_diff_from_matrices, b_eye_ray_direction, b_eye_ray_direction_from_matrices,
    b_gbuffer_ray_diff, b_intersect_triangle_plane, b_lod_box, b_lod_isotropic, b_normal_derivatives,
    b_normalized_derivative, b_pixel_directions, b_ray_diff_from_cone, b_reflect_ray_diff,
    b_refract_ray_diff, b_refraction_determinant, b_secondary_origin_derivatives, b_tangent_plane_offset,
    b_texture_derivatives, b_transfer, b_triplanar_weights, s, well_conditioned,
};
use glam::{Mat4, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives2, Derivatives3, NeighbourDirections, RayDiff};
use ray_footprint::registry::Registered;
use ray_footprint::shaders::Module;
use shader_proptest::interval::{
    interval2 as v2, interval3 as v3, Interval as I, Interval3 as V3, IntervalVec as V,
};
use shader_proptest::{Args, FunctionCheck, Value};
use strategy::{
    any_direction, camera, camera_with_a_view, derivatives2, derivatives3, differential_vec3, gbuffer_sample,
    matrices, ray_diff, triangle_and_direction, well_conditioned_offset_args, F32_ORIGIN_EXPONENT,
};

pub(crate) use enclosure::{
    b_eye_ray_direction_derivatives, b_reflected_direction, b_transferred_origin, direction_well_conditioned,
    WELL_CONDITIONED,
};
pub(crate) use strategy::offset_args;

/// The arguments of the pinhole camera functions: pixel, image size, fov_y, right, up, view.
pub(crate) type Camera = (Vec2, Vec2, f32, Vec3, Vec3, Vec3);

/// The arguments of the matrix camera functions: pixel, image size, view_inv, proj_inv.
pub type Matrices = (Vec2, Vec2, Mat4, Mat4);

/// The arguments of `barycentric_derivatives`: differential, direction, t, the triangle.
pub type BarycentricArgs = (RayDiff, Vec3, f32, Vec3, Vec3, Vec3);

/// The arguments of the re-intersection functions (here and in the f64 module).
pub type OffsetArgs = (Mat4, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3);

/// The arguments of `anisotropic_cone_gradients`: width, direction, the triangle, its UVs.
pub type ConeGradientArgs = (f32, Vec3, Vec3, Vec3, Vec3, Vec2, Vec2, Vec2);

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
        || one_argument(derivatives2()),
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
        || with_corners(derivatives2(), uv_triangle()),
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
            (derivatives2(), uv_triangle(), image_size())
                .prop_map(|(b, t, size)| (b, t[0], t[1], t[2], size))
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
        || with_corners(derivatives2(), triangle()),
        |(b, p0, p1, p2)| rd::secondary_origin_derivatives(b, p0, p1, p2),
        b_secondary_origin_derivatives,
    )
}

/// `rf_lod_isotropic`: the enclosure of the LOD.
pub fn lod_isotropic() -> FunctionCheck<(Derivatives2,), f32> {
    enclosed(
        "lod_isotropic",
        || one_argument(derivatives2()),
        |(g,)| rd::lod_isotropic(g),
        |&(g,)| vec![b_lod_isotropic(g)],
    )
}

/// `rf_lod_box`.
pub fn lod_box() -> FunctionCheck<impl Args + Edge, impl Value> {
    enclosed(
        "lod_box",
        || one_argument(derivatives2()),
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
                vec2_of(-1.0f32..2.0, -1.0f32..2.0),
                derivatives2(),
            )
                .prop_map(|((n0, n1, n2), uv, b)| (n0, n1, n2, uv, b))
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
        || (derivatives3(), vec2_of(-10.0f32..10.0, -10.0f32..10.0)).boxed(),
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
        || with_corners(derivatives3(), uv_triangle()),
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
        || with_corners(scalar(), triangle()),
        |(f, p0, p1, p2)| rd::cone_barycentric_deltas(f, p0, p1, p2),
        b_cone_barycentric_deltas,
    )
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
        || (vec2_of(scalar(), angle()), unit_vec3()).boxed(),
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
