//! What the re-intersection functions share, in f32 and, through `ray_diff_f64`, in f64: their
//! arguments and cases, the degenerate rows, the barycentrics of a ray's hit on a triangle's plane
//! in interval arithmetic, whether both neighbour rays' intersections are well-conditioned, and
//! for the references the exact offsets.

use crate::conditioning::well_conditioned;
use crate::degenerate::{value, Row};
use crate::exact::triangle_hit;
use crate::ray_diff::intervals::{determinant, direction_well_conditioned};
use crate::ray_diff::strategy::rotation;
use crate::strategy::{small_vec3, triangle, unit_vec3};
use glam::{DMat3, DVec3, Mat4, Vec3};
use proptest::prelude::*;
use shader_proptest::draw::uniform;
use shader_proptest::interval::{interval3, mat_vec, Interval, Interval3, IntervalVec, F32};

/// The arguments of the re-intersection functions (here and in the f64 module).
pub type OffsetArgs = (Mat4, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3);

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

/// [`offset_args`] where both intersections are well-conditioned.
pub(crate) fn well_conditioned_offset_args(max_exponent: f32) -> BoxedStrategy<OffsetArgs> {
    offset_args(max_exponent)
        .prop_filter(REINTERSECTION_ILL_CONDITIONED, offsets_well_conditioned)
        .boxed()
}

/// Largest exponent of the world origin and translation for the f32 re-intersection checks. Beyond
/// about 1e6 the f32 sum `O + direction` loses the unit direction entirely and both sides compute
/// rounding noise (the f64 variant exists for that range, and its checks go to 1e8).
pub(crate) const F32_ORIGIN_EXPONENT: f32 = 5.0;

/// `(1, 0, 0) - hit` for the hit of [`collapsed_offset_args`]: what a zero-area triangle gives.
pub(crate) const OFFSET: [f32; 3] = [0.75, -0.25, -0.5];

/// Re-intersection arguments with a triangle collapsed to one point and hit `(0.25, 0.25, 0.5)`.
fn collapsed_offset_args() -> OffsetArgs {
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

/// Re-intersection arguments with the triangle `(0, 0, -5)`, `(1, 0, -5)`, `(0, 1, -5)` seen from
/// the origin, hit `(0.25, 0.25, 0.5)` and the given neighbour directions.
fn plane_offset_args(direction_x: Vec3, direction_y: Vec3) -> OffsetArgs {
    let p0 = Vec3::new(0.0, 0.0, -5.0);
    (
        Mat4::IDENTITY,
        Vec3::ZERO,
        p0,
        p0 + Vec3::X,
        p0 + Vec3::Y,
        direction_x,
        direction_y,
        Vec3::new(0.25, 0.25, 0.5),
    )
}

/// The rows of `barycentric_offsets` and `barycentric_deltas`, f32 and f64: a triangle collapsed to
/// a point, and zero neighbour directions, give `collapsed`; a right neighbour ray parallel to the
/// plane gives the clamp, `parallel`. Each described by its `_output`.
fn reintersection_rows(
    collapsed_output: &'static str,
    collapsed: Vec<f32>,
    parallel_output: &'static str,
    parallel: Vec<f32>,
) -> Vec<Row<OffsetArgs>> {
    vec![
        value(
            "zero-area triangle (one point)",
            collapsed_output,
            collapsed_offset_args(),
            collapsed.clone(),
        ),
        value(
            "right neighbour ray parallel to the plane, lower one through p0",
            parallel_output,
            plane_offset_args(Vec3::X, Vec3::NEG_Z),
            parallel,
        ),
        value(
            "zero neighbour directions",
            collapsed_output,
            plane_offset_args(Vec3::ZERO, Vec3::ZERO),
            collapsed,
        ),
    ]
}

/// [`reintersection_rows`] of `barycentric_offsets`: `(1, 0, 0) - hit` both ways when collapsed.
pub(crate) fn offset_rows(parallel_output: &'static str, parallel: Vec<f32>) -> Vec<Row<OffsetArgs>> {
    reintersection_rows(
        "(1, 0, 0) - hit, both ways",
        [OFFSET; 2].concat(),
        parallel_output,
        parallel,
    )
}

/// [`reintersection_rows`] of `barycentric_deltas`: `2 |(1, 0, 0) - hit|` when collapsed.
pub(crate) fn delta_rows(parallel_output: &'static str, parallel: Vec<f32>) -> Vec<Row<OffsetArgs>> {
    reintersection_rows(
        "2 |(1, 0, 0) - hit|",
        OFFSET.map(|v| 2.0 * v.abs()).to_vec(),
        parallel_output,
        parallel,
    )
}

/// The arguments of `intersect_triangle_plane` (f32 and f64): ray origin, direction, three vertices.
type PlaneArgs = (Vec3, Vec3, Vec3, Vec3, Vec3);

/// The rows of `intersect_triangle_plane` in f32 and f64: a ray parallel to the plane gives the
/// barycentrics clamped to `+-max`, described by `parallel_output`.
pub(crate) fn plane_intersection_rows(parallel_output: &'static str, max: f32) -> Vec<Row<PlaneArgs>> {
    let (x, y, z) = (Vec3::X, Vec3::Y, Vec3::Z);
    vec![
        value(
            "ray parallel to the plane",
            parallel_output,
            (z, x, Vec3::ZERO, x, y),
            vec![max, -max, 0.0],
        ),
        value(
            "zero-area triangle (one point)",
            "(1, 0, 0)",
            (z, -z, x, x, x),
            vec![1.0, 0.0, 0.0],
        ),
        value(
            "zero direction",
            "(1, 0, 0): every cross product with d is 0",
            (z, Vec3::ZERO, Vec3::ZERO, x, y),
            vec![1.0, 0.0, 0.0],
        ),
        value(
            "plane behind the origin",
            "the hit behind it: (0.25, 0.25, 0.5)",
            (Vec3::new(0.25, 0.5, -1.0), -z, Vec3::ZERO, x, y),
            vec![0.25, 0.25, 0.5],
        ),
    ]
}

/// The barycentrics `(1 - u - v, u, v)` of the ray's hit on the plane of the triangle `p`, in the
/// arithmetic of the inputs (f32, or f64 for the `ray_diff_f64` module), in the order of
/// operations of `intersect_triangle_plane` (RTG Eq. 13): `u = dot(e2 x d, s0) / k` and
/// `v = dot(d x e1, s0) / k`, each divided by `quotient(numerator, k)`, the module's clamped
/// division.
pub(crate) fn plane_barycentrics(
    origin: Interval3,
    direction: Interval3,
    [p0, p1, p2]: [Interval3; 3],
    quotient: impl Fn(Interval, Interval) -> Interval,
) -> Interval3 {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let s0 = origin - p0;
    let k = determinant(direction, p0, p1, p2);
    let u = quotient(e2.cross(direction).dot(s0), k);
    let v = quotient(direction.cross(e1).dot(s0), k);
    // The exact 1 in the determinant's arithmetic.
    let one = Interval {
        lo: 1.0,
        hi: 1.0,
        p: k.p,
    };
    IntervalVec([one - u - v, u, v])
}

/// Why a re-intersection is left out of a check ([`offsets_well_conditioned`]).
pub(crate) const REINTERSECTION_ILL_CONDITIONED: &str =
    "a neighbour ray is parallel to the triangle's plane \
     within rounding, or its object-space direction is lost to the cancellation of a far origin \
     (not known to 2^-10): the clamped barycentrics may take either +-DIFF_MAX_VALUE";

/// The object-space origin and the two neighbour directions of the re-intersection.
pub(crate) fn object_rays(
    &(w2o, origin, _, _, _, dir_x, dir_y, _): &OffsetArgs,
) -> (Interval3, Interval3, Interval3) {
    let transform = |p: Interval3| mat_vec(w2o, p, Interval::c(1.0), F32);
    let object_origin = transform(interval3(origin));
    let object_x = transform(interval3(origin) + interval3(dir_x)) - object_origin;
    let object_y = transform(interval3(origin) + interval3(dir_y)) - object_origin;
    (object_origin, object_x, object_y)
}

/// Whether both neighbour rays' intersections are well-conditioned
/// ([`WELL_CONDITIONED`](crate::conditioning::WELL_CONDITIONED)): the object-space directions and
/// their determinants against the triangle.
pub(crate) fn offsets_well_conditioned(args: &OffsetArgs) -> bool {
    let &(_, _, p0, p1, p2, _, _, _) = args;
    let (_, object_x, object_y) = object_rays(args);
    let (p0, p1, p2) = (interval3(p0), interval3(p1), interval3(p2));
    [object_x, object_y]
        .iter()
        .all(|&d| direction_well_conditioned(d) && well_conditioned(determinant(d, p0, p1, p2)))
}

/// Whether barycentrics lie inside `[-limit, limit]`, the range the functions clamp to (with a
/// margin).
pub(crate) fn unclamped(b: DVec3, limit: f64) -> bool {
    b.abs().max_element() < 0.99 * limit
}

/// The exact offsets `(b_x - b, b_y - b)` of the re-intersection: the world origin and the
/// neighbour directions taken to object space in f64 (the direction by the matrix's linear part,
/// so `T(O + d) - T(O)` cancels nothing), intersected with the triangle's plane; `None` where a
/// neighbour's barycentrics leave `[-limit, limit]`.
pub(crate) fn exact_offsets(
    &(world_to_object, origin, p0, p1, p2, dir_x, dir_y, hit): &OffsetArgs,
    limit: f64,
) -> Option<[DVec3; 2]> {
    let matrix = world_to_object.as_dmat4();
    let object_origin = matrix.transform_point3(origin.as_dvec3());
    let linear = DMat3::from_mat4(matrix);
    let p = [p0, p1, p2].map(Vec3::as_dvec3);
    let offset = |direction: Vec3| {
        let (b, _) = triangle_hit(object_origin, linear * direction.as_dvec3(), p);
        unclamped(b, limit).then(|| b - hit.as_dvec3())
    };
    Some([offset(dir_x)?, offset(dir_y)?])
}

#[cfg(test)]
mod tests {
    use super::OFFSET;
    use glam::DVec3;

    /// The collapsed triangle's offsets, `(1, 0, 0) - hit`, are the same in f32 and f64.
    #[test]
    fn the_collapsed_offsets_are_exact_in_f32_and_f64() {
        let offset = (DVec3::X - DVec3::new(0.25, 0.25, 0.5)).as_vec3();
        assert_eq!(offset.to_array(), OFFSET);
    }
}
