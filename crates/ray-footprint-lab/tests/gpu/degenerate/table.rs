//! The data of the degenerate-input table: per function, the degenerate inputs and the documented
//! outputs, one file per shader module. Rendered into `src/degenerate.md` and asserted on the CPU
//! and the GPU by `mod.rs`. This file holds what the modules' rows share.

use super::{Degenerate, Expect, Row};
use glam::{Mat4, Vec3};
use ray_footprint::ray_cone::RayCone;
use ray_footprint::registry::Registered;
use ray_footprint::shaders::Module;
use shader_proptest::{Args, FunctionCheck, Value};

pub(super) const NAN: f32 = f32::NAN;
pub(super) const INF: f32 = f32::INFINITY;

pub(super) fn value<A>(input: &'static str, output: &'static str, args: A, values: Vec<f32>) -> Row<A> {
    Row {
        input,
        output,
        args,
        expect: Expect::Values(values),
    }
}

pub(super) fn same<A>(input: &'static str, output: &'static str, args: A, other: A) -> Row<A> {
    Row {
        input,
        output,
        args,
        expect: Expect::SameAs(other),
    }
}

pub(super) fn mirror<A>(input: &'static str, output: &'static str, args: A, values: Vec<f32>) -> Row<A> {
    Row {
        input,
        output,
        args,
        expect: Expect::Mirror(values),
    }
}

/// The components of a value as the harness compares them.
pub(super) fn parts<R: Value>(value: R) -> Vec<f32> {
    let mut out = Vec::new();
    value.components(&mut out);
    out
}

pub(super) fn cone(width: f32, spread_angle: f32) -> RayCone {
    RayCone { width, spread_angle }
}

/// A unit direction at `cos` to +Z (in the xz plane, pointing down when `cos > 0` is towards -Z).
pub(super) fn direction_at(cos: f32) -> Vec3 {
    Vec3::new((1.0 - cos * cos).sqrt(), 0.0, -cos)
}

/// The tables of `module`, in the module's function order.
pub fn tables(module: Module) -> Vec<Registered<Box<dyn Degenerate>>> {
    match module {
        Module::RayCone => super::ray_cone::tables(),
        Module::RayDiff => super::ray_diff::tables(),
        Module::RayDiffF64 => super::ray_diff_f64::tables(),
        Module::Wireframe => super::wireframe::tables(),
    }
}

/// The widest of an agreement check's per-component tolerances for `args`.
pub(super) fn widest<A: Args, R: Value>(check: FunctionCheck<A, R>, args: &A) -> f32 {
    check
        .bounds(args, &check.mirror(args.clone()))
        .into_iter()
        .fold(0.0, f32::max)
}

/// `(1, 0, 0) - hit` for the hit of [`offset_args`]: what a zero-area triangle gives.
pub(super) const OFFSET: [f32; 3] = [0.75, -0.25, -0.5];

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
pub(super) fn reintersection_rows(
    collapsed_output: &'static str,
    collapsed: Vec<f32>,
    parallel_output: &'static str,
    parallel: Vec<f32>,
) -> Vec<Row<OffsetArgs>> {
    vec![
        value(
            "zero-area triangle (one point)",
            collapsed_output,
            offset_args(),
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
pub(super) fn offset_rows(parallel_output: &'static str, parallel: Vec<f32>) -> Vec<Row<OffsetArgs>> {
    reintersection_rows(
        "(1, 0, 0) - hit, both ways",
        [OFFSET; 2].concat(),
        parallel_output,
        parallel,
    )
}

/// [`reintersection_rows`] of `barycentric_deltas`: `2 |(1, 0, 0) - hit|` when collapsed.
pub(super) fn delta_rows(parallel_output: &'static str, parallel: Vec<f32>) -> Vec<Row<OffsetArgs>> {
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
pub(super) fn plane_intersection_rows(parallel_output: &'static str, max: f32) -> Vec<Row<PlaneArgs>> {
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
