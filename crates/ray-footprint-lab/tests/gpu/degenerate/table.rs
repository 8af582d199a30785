//! The data of the degenerate-input table: per function, the degenerate inputs and the documented
//! outputs, one file per shader module. Rendered into `src/degenerate.md` and asserted on the CPU
//! and the GPU by `mod.rs`. This file holds what the modules' rows share.

use super::{Degenerate, Expect, Row};
use glam::{Mat4, Vec3};
use ray_footprint::ray_cone::RayCone;
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
pub fn tables(module: Module) -> Vec<Box<dyn Degenerate>> {
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

pub(super) type OffsetArgs = (Mat4, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3);

/// Re-intersection arguments with a triangle collapsed to one point and hit `(0.25, 0.25, 0.5)`.
pub(super) fn offset_args() -> OffsetArgs {
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
pub(super) fn plane_offset_args(direction_x: Vec3, direction_y: Vec3) -> OffsetArgs {
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
