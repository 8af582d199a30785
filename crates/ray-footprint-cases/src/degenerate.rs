//! The degenerate inputs of each function: the rows its record documents
//! ([`crate::Record::degenerate`]) and their outputs, run through the Rust mirror and through the
//! shader function in every language; [`crate::pages::degenerate_table`] renders them
//! into the root crate's `src/degenerate.md`.
//!
//! Four kinds of rows:
//! - a documented value ([`value`]): the mirror returns exactly that value, each shader within the
//!   function's tolerance (the record's);
//! - a documented value to a relative accuracy ([`near`]), where the rounding of the inputs leaves
//!   no exact output: the mirror within that accuracy of the value, each shader within the
//!   function's tolerance of the mirror;
//! - "as `<other input>`" ([`same`]): a clamp; each implementation returns bit for bit what it
//!   returns on the clamped input, and the shaders agree with the mirror within the tolerance;
//! - NaN or infinity in ([`mirror`]): the mirror's output is documented and asserted; Vulkan
//!   leaves NaN and infinity handling to the implementation (and WGSL lets a compiler assume
//!   neither occurs), so the shaders' outputs are printed, not asserted.

use glam::{Mat4, Vec3};
use ray_footprint::ray_cone::RayCone;
use ray_footprint::shaders::Module;
use shader_proptest::{evaluate, Args, Error, Gpu, Language, Tolerance, Value};
use std::fmt::Write as _;

/// Not a number, for rows with NaN in or out.
pub const NAN: f32 = f32::NAN;
/// Infinity, for rows with infinity in or out.
pub const INF: f32 = f32::INFINITY;

/// What a row documents.
pub enum Expect<A> {
    /// These output components (NaN matches NaN).
    Values(Vec<f32>),
    /// These output components to within `relative` times the largest of their magnitudes.
    Near(Vec<f32>, f32),
    /// The same output as for these (clamped) arguments.
    SameAs(A),
    /// Non-finite input: these components from the mirror; the shaders are unspecified.
    Mirror(Vec<f32>),
}

/// One degenerate input of a function and its documented output.
pub struct Row<A> {
    /// The degenerate input, in words.
    pub input: &'static str,
    /// The documented output, in words.
    pub output: &'static str,
    /// The arguments.
    pub args: A,
    /// What is asserted.
    pub expect: Expect<A>,
}

/// A row whose output components are `values`.
pub fn value<A>(input: &'static str, output: &'static str, args: A, values: Vec<f32>) -> Row<A> {
    Row {
        input,
        output,
        args,
        expect: Expect::Values(values),
    }
}

/// A row whose output components are `values` to within `relative` times the largest of their
/// magnitudes.
pub fn near<A>(
    input: &'static str,
    output: &'static str,
    args: A,
    values: Vec<f32>,
    relative: f32,
) -> Row<A> {
    Row {
        input,
        output,
        args,
        expect: Expect::Near(values, relative),
    }
}

/// A row whose output is the output for the clamped arguments `other`.
pub fn same<A>(input: &'static str, output: &'static str, args: A, other: A) -> Row<A> {
    Row {
        input,
        output,
        args,
        expect: Expect::SameAs(other),
    }
}

/// A row with non-finite input: the mirror gives `values`, the shaders are unspecified.
pub fn mirror<A>(input: &'static str, output: &'static str, args: A, values: Vec<f32>) -> Row<A> {
    Row {
        input,
        output,
        args,
        expect: Expect::Mirror(values),
    }
}

/// A ray cone.
pub fn cone(width: f32, spread_angle: f32) -> RayCone {
    RayCone { width, spread_angle }
}

/// A unit direction at `cos` to +Z (in the xz plane, pointing down when `cos > 0` is towards -Z).
pub fn direction_at(cos: f32) -> Vec3 {
    Vec3::new((1.0 - cos * cos).sqrt(), 0.0, -cos)
}

/// A ray head-on to the rows' normal `+Z`.
pub const HEAD_ON: Vec3 = Vec3::NEG_Z;

/// A ray in the surface plane of the rows' normal `+Z` (`dot(n, d) = 0`).
pub const IN_PLANE: Vec3 = Vec3::X;

/// A ray grazing the surface plane of the rows' normal `+Z`: `dot(n, d) = -1e-6`.
pub fn grazing() -> Vec3 {
    direction_at(1.0e-6)
}

/// The inverse projection of a Vulkan perspective camera (fov_y 1, aspect 1.5, near 0.1, far 100).
pub fn vulkan_inverse_projection() -> Mat4 {
    glam::camera::rh::proj::vulkan::perspective(1.0, 1.5, 0.1, 100.0).inverse()
}

/// The components of a value as the harness compares them.
pub fn parts<R: Value>(value: R) -> Vec<f32> {
    let mut out = Vec::new();
    value.components(&mut out);
    out
}

/// Equal, or both NaN.
fn same_float(a: f32, b: f32) -> bool {
    a == b || (a.is_nan() && b.is_nan())
}

fn all_same(a: &[f32], b: &[f32]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(&x, &y)| same_float(x, y))
}

/// Within `relative` times the largest magnitude of `expected`, component by component.
fn all_near(got: &[f32], expected: &[f32], relative: f32) -> bool {
    let scale = expected.iter().fold(0.0f32, |largest, x| largest.max(x.abs()));
    got.len() == expected.len()
        && got
            .iter()
            .zip(expected)
            .all(|(&g, &e)| (g - e).abs() <= relative * scale)
}

fn bits(values: &[f32]) -> Vec<u32> {
    values.iter().map(|x| x.to_bits()).collect()
}

/// A function's degenerate rows and what running them needs: the function, its mirror and its
/// tolerance (a record's, [`crate::Record::degenerate`]).
pub(crate) struct RowsOf<'a, A, R> {
    /// The module declaring the function.
    pub module: Module,
    /// The function's Rust name (the shader function is `rf_<function>`).
    pub function: &'static str,
    /// The documented rows.
    pub rows: &'a [Row<A>],
    /// The Rust mirror.
    pub mirror: fn(A) -> R,
    /// The tolerance of the shaders against the mirror.
    pub tolerance: &'a Tolerance<A>,
}

impl<A: Args, R: Value> RowsOf<'_, A, R> {
    /// Appends the rows to a markdown table.
    pub fn markdown(&self, out: &mut String) {
        for row in self.rows {
            let cell = |text: &str| text.replace('|', "\\|");
            writeln!(
                out,
                "| `{}` | {} | {} |",
                self.function,
                cell(row.input),
                cell(row.output)
            )
            .expect("a String");
        }
    }

    fn name(&self) -> String {
        format!("{}::{}", self.module.stem(), self.function)
    }

    /// Whether the shader's `got` is within the tolerance of `expected` for `args`.
    fn within(&self, args: &A, got: &[f32], expected: &[f32]) -> bool {
        let mut bounds = Vec::new();
        self.tolerance.bounds(args, expected, &mut bounds);
        got.len() == expected.len()
            && got
                .iter()
                .zip(expected)
                .zip(&bounds)
                .all(|((&g, &e), &bound)| same_float(g, e) || (g.is_finite() && (g - e).abs() <= bound))
    }

    /// Runs every row through the mirror: the rows it does not follow.
    pub fn cpu(&self) -> Vec<String> {
        let mut failures = Vec::new();
        for row in self.rows {
            let got = parts((self.mirror)(row.args.clone()));
            let (ok, expected) = match &row.expect {
                Expect::Values(values) | Expect::Mirror(values) => (all_same(&got, values), values.clone()),
                Expect::Near(values, relative) => (all_near(&got, values, *relative), values.clone()),
                Expect::SameAs(other) => {
                    let expected = parts((self.mirror)(other.clone()));
                    (bits(&got) == bits(&expected), expected)
                }
            };
            println!("{:<45} {:<48} CPU {got:?}", self.name(), row.input);
            if !ok {
                failures.push(format!(
                    "{} [{}]: CPU gave {got:?}, documented {expected:?}",
                    self.name(),
                    row.input
                ));
            }
        }
        failures
    }

    /// Runs every row and every clamped input of its `SameAs` rows through the shader function in
    /// `language`, in one dispatch: the rows it does not follow.
    pub fn gpu(&self, gpu: &Gpu, language: Language) -> Result<Vec<String>, Error> {
        let rows = self.rows;
        let mut cases: Vec<A> = rows.iter().map(|row| row.args.clone()).collect();
        cases.extend(rows.iter().filter_map(|row| match &row.expect {
            Expect::SameAs(other) => Some(other.clone()),
            _ => None,
        }));
        let function = format!("rf_{}", self.function);
        let shader = self.module.shader(language);
        let results: Vec<R> = evaluate(gpu, &shader, &function, &cases)?;
        let outputs: Vec<Vec<f32>> = results.into_iter().map(parts).collect();
        let mut references = outputs[rows.len()..].iter();
        let mut failures = Vec::new();
        for (row, got) in rows.iter().zip(&outputs) {
            let mirror = parts((self.mirror)(row.args.clone()));
            let (ok, note) = match &row.expect {
                Expect::Values(values) => (self.within(&row.args, got, values), ""),
                Expect::Near(..) => (self.within(&row.args, got, &mirror), ""),
                Expect::SameAs(_) => {
                    let reference = references.next().expect("one output per reference");
                    (
                        bits(got) == bits(reference) && self.within(&row.args, got, &mirror),
                        "",
                    )
                }
                Expect::Mirror(_) => (true, " (unspecified, not asserted)"),
            };
            println!(
                "{:<45} {:<48} {} {got:?}{note}",
                self.name(),
                row.input,
                language.name()
            );
            if !ok {
                failures.push(format!(
                    "{} [{}] {}: got {got:?}, mirror {mirror:?}",
                    self.name(),
                    row.input,
                    language.name()
                ));
            }
        }
        Ok(failures)
    }
}
