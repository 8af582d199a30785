//! Symmetries: the transformations a function's math respects, declared in its record
//! ([`crate::Record::symmetry`]), and what each does to the result.
//!
//! A symmetry transforms a case and says how to take the result of the transformed case back to
//! the case's own terms (`restore`): a uniform scale of every length (a curvature then goes as
//! `1 / s`, a footprint as `s`, a LOD shifts by `log2 s`), a rotation of every vector, a translation
//! of every position, or a fixed exchange (the vertex order turned, a normal's sign flipped, the two
//! image axes swapped). The function is right at every scale and in every frame only if
//! `restore(f(transform(x)))` is `f(x)` within the errors of the two evaluations.
//!
//! Each change is exact in floating point, so that the only errors are the function's own:
//!
//! - a scale is a power of two, `2^-40` to `2^40` (about 1e-12 to 1e12, the documented range),
//!   drawn log-uniformly;
//! - a rotation is one of the 24 rotations of the cube, which permute the axes and flip signs;
//! - a translation is by multiples of `2^-6` up to 64 per axis, of a case whose translated values
//!   were first put on the grid of `2^-14` (moved by 1024 and back), so that every sum is exact;
//! - a case whose change is not exact is left out: every value a scale, a rotation or an exchange
//!   changes must stay finite, normal and within the documented range (0 or 1e-12 to 1e12 in
//!   magnitude), and every value a translation changes must differ from the case's by exactly the
//!   offset's component of its own axis.
//!
//! A symmetry may hold only on part of the domain, where an absolute clamp does not act (a zero
//! width clamped to `MIN_MAGNITUDE` is not scaled with the case): [`Symmetry::within`] states
//! where, and a case outside it, or transformed outside it, is left out.
//!
//! The tolerance of a comparison follows from the record's: the result of the case is within the
//! record's bound at the case of the exact value of its formula, the transformed case's within its
//! bound at the transformed case, which the restore carries to the case's terms (with one ULP of
//! the restore's own rounding). The runners are [`crate::Function::symmetry_cpu`] (the mirror,
//! [`CASES`] cases per symmetry) and [`crate::Function::symmetry_check`] (a
//! [`shader_proptest::MetamorphicCheck`] on the device, the shader function against itself).

use crate::record::{seeded_runner, Function, Record};
use crate::special::Perturb;
use glam::{Mat3, Vec3};
use proptest::strategy::{Strategy, ValueTree};
use shader_proptest::tolerance::count_vacuous;
use shader_proptest::{case_seed, Args, MetamorphicCheck, Tolerance, Value};
use std::fmt;
use std::sync::Arc;

/// Cases each symmetry runs on the mirror.
pub const CASES: usize = 100_000;

/// The variable that picks the functions whose symmetries a run checks: those whose
/// `module::function` name holds its text (every function where it is not set).
pub const ONLY_ENV: &str = "RAY_FOOTPRINT_SYMMETRIES";

/// Whether [`ONLY_ENV`] picks `function`.
pub fn picked(function: &dyn crate::Function) -> bool {
    let only = std::env::var(ONLY_ENV).unwrap_or_default();
    format!("{}::{}", function.module().stem(), function.name()).contains(&only)
}

/// Largest exponent of a drawn scale: `2^40` is about 1.1e12, the documented range.
pub const SCALE_EXPONENT: i32 = 40;

/// The documented range of nonzero magnitudes (1e-12 to 1e12, widened to the powers of two a scale
/// reaches from 1), which a changed value must stay within.
pub const RANGE: (f32, f32) = (
    1.0 / (1u64 << SCALE_EXPONENT) as f32,
    (1u64 << SCALE_EXPONENT) as f32,
);

/// The grid a translated case is put on first (`1024` is added and taken away: values below 1024
/// in magnitude land on multiples of `2^-14` at worst), and the step and range of a translation.
const SNAP: f32 = 1024.0;
const OFFSET_STEP: f32 = 1.0 / 64.0;
const OFFSET_STEPS: u64 = 4096;

/// Which change a symmetry draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Every length scaled by a power of two.
    Scale,
    /// Every vector turned by a rotation of the cube.
    Rotation,
    /// Every position moved by one offset.
    Translation,
    /// A fixed change with no parameter: an order, a sign, a swap.
    Exchange,
}

impl Kind {
    /// The kind in words.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Scale => "scale",
            Kind::Rotation => "rotation",
            Kind::Translation => "translation",
            Kind::Exchange => "exchange",
        }
    }
}

/// The change applied to one case.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Change {
    /// A power of two.
    pub scale: f32,
    /// A rotation of the cube: a permutation of the axes with sign flips, determinant 1.
    pub rotation: Mat3,
    /// An offset on the grid of `2^-6`.
    pub offset: Vec3,
}

impl Change {
    /// No change.
    pub const IDENTITY: Change = Change {
        scale: 1.0,
        rotation: Mat3::IDENTITY,
        offset: Vec3::ZERO,
    };

    /// The change of `kind` that `seed` draws.
    pub fn draw(kind: Kind, seed: u64) -> Change {
        let draw = |modulus: u64, shift: u32| (seed >> shift) % modulus;
        match kind {
            Kind::Scale => Change {
                scale: 2f32.powi(draw(2 * SCALE_EXPONENT as u64 + 1, 0) as i32 - SCALE_EXPONENT),
                ..Change::IDENTITY
            },
            Kind::Rotation => Change {
                rotation: cube_rotation(draw(24, 0) as usize),
                ..Change::IDENTITY
            },
            Kind::Translation => {
                let step =
                    |shift| (draw(2 * OFFSET_STEPS + 1, shift) as f32 - OFFSET_STEPS as f32) * OFFSET_STEP;
                Change {
                    offset: Vec3::new(step(0), step(16), step(32)),
                    ..Change::IDENTITY
                }
            }
            Kind::Exchange => Change::IDENTITY,
        }
    }

    /// The change that undoes this one.
    pub fn inverse(self) -> Change {
        Change {
            scale: 1.0 / self.scale,
            rotation: self.rotation.transpose(),
            offset: -self.offset,
        }
    }
}

/// Rotation `index` (0 to 23) of the cube: the axes permuted and signs flipped, determinant 1.
pub fn cube_rotation(index: usize) -> Mat3 {
    let permutations = [[0, 1, 2], [1, 2, 0], [2, 0, 1], [0, 2, 1], [2, 1, 0], [1, 0, 2]];
    let axes = [Vec3::X, Vec3::Y, Vec3::Z];
    let rotations = permutations.iter().flat_map(|permutation| {
        (0..8).filter_map(move |signs: usize| {
            let column = |i: usize| axes[permutation[i]] * if signs >> i & 1 == 1 { -1.0 } else { 1.0 };
            let rotation = Mat3::from_cols(column(0), column(1), column(2));
            (rotation.determinant() > 0.0).then_some(rotation)
        })
    });
    rotations.clone().nth(index % 24).expect("24 rotations")
}

/// Transforms a case by a change.
type Transform<A> = dyn Fn(&A, &Change) -> A + Send + Sync;

/// Takes a transformed case's result back to the case's terms, given the change.
type Restore<R> = dyn Fn(R, &Change) -> R + Send + Sync;

/// A transformation of a function's arguments that its math respects, and how the result of a
/// transformed case is taken back to the case's terms.
pub struct Symmetry<A, R> {
    kind: Kind,
    description: &'static str,
    transform: Arc<Transform<A>>,
    restore: Arc<Restore<R>>,
    within: fn(&A) -> bool,
    exact_restore: bool,
}

impl<A, R> Clone for Symmetry<A, R> {
    fn clone(&self) -> Self {
        Symmetry {
            kind: self.kind,
            description: self.description,
            transform: Arc::clone(&self.transform),
            restore: Arc::clone(&self.restore),
            within: self.within,
            exact_restore: self.exact_restore,
        }
    }
}

impl<A: Args, R: Value> Symmetry<A, R> {
    /// Every length scaled by `s` (`transform(case, s)`); `restore(result, s)` undoes what the
    /// scale did to the result (divides a length by `s`, multiplies a curvature by `s`).
    pub fn scale(description: &'static str, transform: fn(&A, f32) -> A, restore: fn(R, f32) -> R) -> Self {
        Symmetry {
            kind: Kind::Scale,
            description,
            transform: Arc::new(move |args, change| transform(args, change.scale)),
            restore: Arc::new(move |result, change| restore(result, change.scale)),
            within: |_| true,
            exact_restore: true,
        }
    }

    /// Every length scaled by `s`, for a result on a log scale (a LOD): `restore(result, s)` adds
    /// or takes away `log2 s`, which rounds where [`Symmetry::scale`]'s multiplications by powers
    /// of two do not (so the references do not run through it).
    pub fn scale_in_log(
        description: &'static str,
        transform: fn(&A, f32) -> A,
        restore: fn(R, f32) -> R,
    ) -> Self {
        Symmetry {
            exact_restore: false,
            ..Symmetry::scale(description, transform, restore)
        }
    }

    /// Every vector turned by `rotation` (`transform(case, rotation)`); `restore(result,
    /// rotation)` turns a vector result back (by the transpose).
    pub fn rotation(
        description: &'static str,
        transform: fn(&A, Mat3) -> A,
        restore: fn(R, Mat3) -> R,
    ) -> Self {
        Symmetry {
            kind: Kind::Rotation,
            description,
            transform: Arc::new(move |args, change| transform(args, change.rotation)),
            restore: Arc::new(move |result, change| restore(result, change.rotation)),
            within: |_| true,
            exact_restore: true,
        }
    }

    /// Every position moved by `offset` (`transform(case, offset)`); `restore(result, offset)`
    /// moves a position result back.
    pub fn translation(
        description: &'static str,
        transform: fn(&A, Vec3) -> A,
        restore: fn(R, Vec3) -> R,
    ) -> Self {
        Symmetry {
            kind: Kind::Translation,
            description,
            transform: Arc::new(move |args, change| transform(args, change.offset)),
            restore: Arc::new(move |result, change| restore(result, change.offset)),
            within: |_| true,
            exact_restore: true,
        }
    }

    /// A fixed change (`transform(case)`: the vertex order turned, a sign flipped, two axes
    /// swapped, an image height doubled) and what undoes it in the result (`restore(result)`).
    pub fn exchange(description: &'static str, transform: fn(&A) -> A, restore: fn(R) -> R) -> Self {
        Symmetry {
            kind: Kind::Exchange,
            description,
            transform: Arc::new(move |args, _| transform(args)),
            restore: Arc::new(move |result, _| restore(result)),
            within: |_| true,
            exact_restore: true,
        }
    }

    /// The symmetry restricted to the cases where `holds` is true, before and after the change:
    /// where the function's absolute clamps do not act (say where in the description).
    pub fn within(self, holds: fn(&A) -> bool) -> Self {
        Symmetry {
            within: holds,
            ..self
        }
    }

    /// Whether the restore is exact (a scale by powers of two, a rotation, an exchange), so that
    /// the restored result carries no rounding of its own.
    pub fn restores_exactly(&self) -> bool {
        self.exact_restore
    }

    /// Its kind.
    pub fn kind(&self) -> Kind {
        self.kind
    }

    /// What it changes and what that does to the result, in words.
    pub fn description(&self) -> &'static str {
        self.description
    }

    /// The change that `seed` draws for a case.
    pub fn change(&self, seed: u64) -> Change {
        Change::draw(self.kind, seed)
    }

    /// The case transformed by `change`.
    pub fn transform(&self, args: &A, change: &Change) -> A {
        (self.transform)(args, change)
    }

    /// The transformed case's `result` taken back to the case's terms.
    pub fn restore(&self, result: R, change: &Change) -> R {
        (self.restore)(result, change)
    }

    /// The case as the symmetry takes it: a translation's case put on the grid (moved by 1024 and
    /// back); any other case as it is.
    pub fn prepare(&self, args: &A) -> A {
        match self.kind {
            Kind::Translation => {
                let snap = Change {
                    offset: Vec3::splat(SNAP),
                    ..Change::IDENTITY
                };
                self.transform(&self.transform(args, &snap), &snap.inverse())
            }
            _ => args.clone(),
        }
    }

    /// Whether `change` is exact on `args` (see the module's documentation): every float it
    /// changes stays finite, normal and within [`RANGE`], a translation's position moved by exactly
    /// the offset's component of its own axis; and neither case holds a subnormal float (which a
    /// device may flush to zero).
    pub fn exact(&self, args: &A, change: &Change) -> bool {
        let transformed = self.transform(args, change);
        let (before, after) = (floats(args), floats(&transformed));
        let offsets = change.offset.to_array().map(f64::from);
        let in_range = |x: f32| x == 0.0 || (RANGE.0..=RANGE.1).contains(&x.abs());
        let changed_exactly = before
            .iter()
            .zip(&after)
            .zip(self.position_axes(args, &before))
            .all(|((&before, &after), axis)| {
                let moved = f64::from(after) - f64::from(before);
                let valid = after.is_finite() && in_range(after);
                match axis {
                    Some(axis) => valid && moved == offsets[axis],
                    None => before.to_bits() == after.to_bits() || valid,
                }
            });
        let normal = |values: &[f32]| !values.iter().any(|x| x.is_subnormal());
        changed_exactly && normal(&before) && normal(&after)
    }

    /// For each float of `args` (`before`, its floats), the axis whose offset a translation adds
    /// to it (`None` for a float it leaves, and for every float of another kind of symmetry): a far
    /// probe offset, `(1, 2, 4) * 1e30`, moves a position of axis `i` by about `2^i * 1e30` (a
    /// position too large for the grid would not move).
    fn position_axes(&self, args: &A, before: &[f32]) -> Vec<Option<usize>> {
        if self.kind != Kind::Translation {
            return vec![None; before.len()];
        }
        let probe = Change {
            offset: Vec3::new(1.0e30, 2.0e30, 4.0e30),
            ..Change::IDENTITY
        };
        before
            .iter()
            .zip(floats(&self.transform(args, &probe)))
            .map(
                |(&before, moved)| match ((f64::from(moved) - f64::from(before)) / 1.0e30).round() as i64 {
                    1 => Some(0),
                    2 => Some(1),
                    4 => Some(2),
                    _ => None,
                },
            )
            .collect()
    }

    /// Whether the symmetry applies to `args` under `change`: the change is exact and the case and
    /// the transformed case both lie where the symmetry holds ([`Symmetry::within`]).
    pub fn applies(&self, args: &A, change: &Change) -> bool {
        self.exact(args, change) && (self.within)(args) && (self.within)(&self.transform(args, change))
    }

    /// The bound of each component of the restored result of the transformed case, from the bound
    /// `bounds` of each component of its result `result` (for the transformed case): how far the
    /// restore carries a change of that size, measured at the result, plus one ULP of the restored
    /// value for the restore's own rounding.
    pub fn restored_bounds(&self, result: &R, bounds: &[f32], change: &Change) -> Vec<f32> {
        let restored = components(&self.restore(result.clone(), change));
        let mut moved_words = Vec::new();
        result.write(&mut moved_words);
        let mut float = Vec::new();
        R::TYPE.float_words(&mut float);
        let mut bound = bounds.iter();
        for (word, is_float) in moved_words.iter_mut().zip(float) {
            let step = bound.next().copied().unwrap_or(0.0);
            if is_float {
                *word = (f32::from_bits(*word) + step).to_bits();
            }
        }
        let moved = components(&self.restore(R::read(&mut &moved_words[..]), change));
        restored
            .iter()
            .zip(&moved)
            .map(|(&value, &shifted)| {
                (shifted - value).abs() + f32::EPSILON * value.abs() + f32::MIN_POSITIVE
            })
            .collect()
    }
}

/// What one symmetry of one function did on the mirror.
#[derive(Clone, Debug)]
pub struct SymmetryReport {
    /// `module::function`.
    pub function: String,
    /// The symmetry's kind.
    pub kind: Kind,
    /// The symmetry in words.
    pub description: &'static str,
    /// Cases compared.
    pub cases: usize,
    /// Cases drawn and left out: the change was not exact, or the case or its transform lies
    /// outside the function's well-conditioned domain.
    pub left_out: usize,
    /// Largest difference as a share of its bound.
    pub max_ratio: f32,
    /// Share of the cases whose bound was vacuous (as wide as the spread of the results).
    pub vacuous: f64,
    /// The first case that broke the symmetry, in words.
    pub failure: Option<String>,
}

impl SymmetryReport {
    /// Whether every case kept the symmetry within its bound and at most
    /// [`shader_proptest::MAX_VACUOUS`] of the bounds were vacuous.
    pub fn passed(&self) -> bool {
        self.failure.is_none() && self.cases > 0 && self.vacuous <= shader_proptest::MAX_VACUOUS
    }
}

impl fmt::Display for SymmetryReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{:<40} {:<11} {:>7} cases ({:>6} left out)  {:>7.4} of bound  vacuous {:>5.2}%  {}",
            self.function,
            self.kind.name(),
            self.cases,
            self.left_out,
            self.max_ratio,
            100.0 * self.vacuous,
            if self.passed() { "pass" } else { "FAIL" }
        )?;
        write!(f, "  ({})", self.description)?;
        if let Some(failure) = &self.failure {
            write!(f, "\n  {failure}")?;
        }
        Ok(())
    }
}

/// Cases compared per batch of the vacuous share (as the harness's batches).
const VACUOUS_BATCH: usize = 8192;

/// A case of symmetry `symmetry` as drawn: the case as the symmetry takes it, the change, and the
/// transformed case; `None` where the change is not exact there or either case lies outside the
/// record's well-conditioned domain.
fn symmetric_case<A: Args + Perturb, R: Value>(
    record: &Record<A, R>,
    symmetry: &Symmetry<A, R>,
    drawn: &A,
) -> Option<(A, Change, A)> {
    let args = symmetry.prepare(drawn);
    let change = symmetry.change(case_seed(&args));
    if !symmetry.applies(&args, &change) {
        return None;
    }
    let transformed = symmetry.transform(&args, &change);
    (record.well_conditioned_at(&args) && record.well_conditioned_at(&transformed)).then_some((
        args,
        change,
        transformed,
    ))
}

/// The bound of each component of `|restore(f(transform(x))) - f(x)|`: the record's bound at the
/// case (`result`: its components) plus its bound at the transformed case carried through the
/// restore ([`transformed_bounds`]).
fn symmetric_bounds<A: Args + Perturb, R: Value>(
    tolerance: &Tolerance<A>,
    mirror: &dyn Fn(A) -> R,
    symmetry: &Symmetry<A, R>,
    args: &A,
    result: &[f32],
) -> Vec<f32> {
    let change = symmetry.change(case_seed(args));
    let transformed = symmetry.transform(args, &change);
    let transformed_result = mirror(transformed.clone());
    transformed_bounds(
        tolerance,
        symmetry,
        (args, result),
        (&transformed, &transformed_result),
        &change,
    )
}

/// [`symmetric_bounds`] where the transformed case `transformed` (under `change`) and its result
/// `transformed_result` are known.
fn transformed_bounds<A: Args + Perturb, R: Value>(
    tolerance: &Tolerance<A>,
    symmetry: &Symmetry<A, R>,
    (args, result): (&A, &[f32]),
    (transformed, transformed_result): (&A, &R),
    change: &Change,
) -> Vec<f32> {
    let (mut at_case, mut at_transformed) = (Vec::new(), Vec::new());
    tolerance.bounds(args, result, &mut at_case);
    tolerance.bounds(transformed, &components(transformed_result), &mut at_transformed);
    let carried = symmetry.restored_bounds(transformed_result, &at_transformed, change);
    at_case.iter().zip(carried).map(|(a, b)| a + b).collect()
}

/// Runs symmetry `index` of `record` on the mirror over `cases` cases of the record's strategy
/// drawn from `seed` (at most four times as many drawn): `restore(mirror(transform(x)))` against
/// `mirror(x)` within the derived bound.
pub(crate) fn run_on_mirror<A: Args + Perturb, R: Value>(
    record: &Record<A, R>,
    index: usize,
    cases: usize,
    seed: u64,
) -> SymmetryReport {
    let symmetry = &record.symmetries()[index];
    let strategy = (record.cases())();
    let mut runner = seeded_runner(seed);
    let mut report = SymmetryReport {
        function: format!("{}::{}", Function::module(record).stem(), Function::name(record)),
        kind: symmetry.kind(),
        description: symmetry.description(),
        cases: 0,
        left_out: 0,
        max_ratio: 0.0,
        vacuous: 0.0,
        failure: None,
    };
    let (mut expected, mut bounds, mut vacuous) = (Vec::new(), Vec::new(), 0);
    while report.cases < cases && report.left_out < 4 * cases {
        let Ok(tree) = strategy.new_tree(&mut runner) else {
            report.left_out += 1;
            continue;
        };
        let Some((args, change, transformed)) = symmetric_case(record, symmetry, &tree.current()) else {
            report.left_out += 1;
            continue;
        };
        let result = components(&record.mirror(args.clone()));
        let transformed_result = record.mirror(transformed.clone());
        let restored = components(&symmetry.restore(transformed_result.clone(), &change));
        let bound = transformed_bounds(
            record.tolerance(),
            symmetry,
            (&args, &result),
            (&transformed, &transformed_result),
            &change,
        );
        for (component, ((&got, &want), &limit)) in restored.iter().zip(&result).zip(&bound).enumerate() {
            let difference = (got - want).abs();
            let finite = got.is_finite() == want.is_finite() || !args.is_finite();
            if report.failure.is_none() && (!finite || difference > limit || difference.is_nan()) {
                report.failure = Some(format!(
                    "component {component}: {got:e} restored from the transformed case against {want:e}, \
                     differing by {difference:e} (bound {limit:e}); case {args:?}, transformed {transformed:?}"
                ));
            }
            if limit > 0.0 && difference.is_finite() {
                report.max_ratio = report.max_ratio.max(difference / limit);
            }
        }
        expected.extend(result);
        bounds.extend(bound);
        report.cases += 1;
        if report.cases.is_multiple_of(VACUOUS_BATCH) || report.cases == cases {
            let batch = report.cases - (report.cases - 1) / VACUOUS_BATCH * VACUOUS_BATCH;
            vacuous += count_vacuous(&expected, &bounds, batch).cases;
            expected.clear();
            bounds.clear();
        }
    }
    report.vacuous = vacuous as f64 / report.cases.max(1) as f64;
    report
}

/// Symmetry `index` of `record` as a metamorphic check of `rf_<function>` against itself: each
/// case of the record's strategy put as the symmetry takes it, where the change is exact and both
/// cases are well-conditioned, its change drawn from the case's words ([`case_seed`]), within the
/// derived bound.
pub(crate) fn metamorphic_check<A: Args + Perturb, R: Value>(
    record: &Record<A, R>,
    index: usize,
) -> MetamorphicCheck<A, R> {
    let symmetry = record.symmetries()[index].clone();
    let cases = record.cases();
    let conditioning = record.conditioning();
    let holds = move |args: &A| conditioning.is_none_or(|holds| holds(args));
    let mirror = record.mirror_fn();
    let tolerance = record.tolerance().clone();
    let (for_cases, for_transform, for_restore, for_bounds) =
        (symmetry.clone(), symmetry.clone(), symmetry.clone(), symmetry);
    let strategy = move || {
        let symmetry = for_cases.clone();
        let prepare = for_cases.clone();
        cases()
            .prop_map(move |drawn| prepare.prepare(&drawn))
            .prop_filter(
                "the change is not exact, or a case is ill-conditioned",
                move |args| {
                    let change = symmetry.change(case_seed(args));
                    symmetry.applies(args, &change)
                        && holds(args)
                        && holds(&symmetry.transform(args, &change))
                },
            )
    };
    MetamorphicCheck::new(
        format!("rf_{}", Function::name(record)),
        strategy,
        move |args: &A| for_transform.transform(args, &for_transform.change(case_seed(args))),
        move |args: &A, result: R| for_restore.restore(result, &for_restore.change(case_seed(args))),
    )
    .tolerance(Tolerance::per_case(move |args: &A, result: &[f32]| {
        symmetric_bounds(&tolerance, &mirror, &for_bounds, args, result)
    }))
}

/// How many words an argument list of `A` takes.
fn word_count<A: Args>() -> usize {
    A::TYPES.iter().map(|ty| ty.words()).sum()
}

/// The words of a value.
fn words<A: Args>(args: &A) -> Vec<u32> {
    let mut out = Vec::with_capacity(word_count::<A>());
    args.write(&mut out);
    out
}

/// The floats of `args`, in the order of its words.
fn floats<A: Args>(args: &A) -> Vec<f32> {
    let mut float = Vec::with_capacity(word_count::<A>());
    A::TYPES.iter().for_each(|ty| ty.float_words(&mut float));
    words(args)
        .iter()
        .zip(float)
        .filter(|&(_, is_float)| is_float)
        .map(|(&word, _)| f32::from_bits(word))
        .collect()
}

/// The components of a result, in the harness's order.
pub(crate) fn components<R: Value>(value: &R) -> Vec<f32> {
    let mut out = Vec::new();
    value.components(&mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 24 rotations of the cube are distinct, orthonormal with determinant 1, and each
    /// component is 0 or +-1, so that turning a vector is exact.
    #[test]
    fn the_cube_has_24_exact_rotations() {
        let rotations: Vec<Mat3> = (0..24).map(cube_rotation).collect();
        for (i, rotation) in rotations.iter().enumerate() {
            assert_eq!(rotation.determinant(), 1.0);
            assert_eq!(*rotation * rotation.transpose(), Mat3::IDENTITY);
            assert!(rotation
                .to_cols_array()
                .iter()
                .all(|x| [0.0, 1.0, -1.0].contains(x)));
            assert!(
                rotations[..i].iter().all(|other| other != rotation),
                "{i} repeats"
            );
        }
    }

    /// Scales are powers of two over the whole range, both ends drawn; offsets are on their grid.
    #[test]
    fn changes_cover_their_range_exactly() {
        let scales: Vec<f32> = (0..1000u64)
            .map(|seed| Change::draw(Kind::Scale, seed).scale)
            .collect();
        assert!(scales.iter().all(|s| s.log2().fract() == 0.0));
        assert!(scales.contains(&2f32.powi(-SCALE_EXPONENT)) && scales.contains(&2f32.powi(SCALE_EXPONENT)));
        for seed in 0..1000u64 {
            let offset = Change::draw(Kind::Translation, seed.wrapping_mul(0x9e37_79b9_7f4a_7c15)).offset;
            assert!(offset.abs().max_element() <= 64.0);
            assert_eq!(offset * 64.0, (offset * 64.0).round());
        }
    }

    /// A translation puts the case on the grid first, and its change is then exact; a translation
    /// of a value too large for the grid, or a scale out of the documented range, is not.
    #[test]
    fn exactness_is_checked_by_the_round_trip() {
        let translate = Symmetry::<(Vec3,), Vec3>::translation("p", |&(p,), t| (p + t,), |p, t| p - t);
        let case = translate.prepare(&(Vec3::new(0.1, -3.3, 700.7),));
        let change = Change::draw(Kind::Translation, 12345);
        assert!(translate.exact(&case, &change));
        let far = translate.prepare(&(Vec3::new(1.75e8, 0.0, 0.0),));
        let odd = Change {
            offset: Vec3::splat(1.0 / 64.0),
            ..Change::IDENTITY
        };
        assert!(!translate.exact(&far, &odd), "1.75e8 + 1/64 rounds");
        let scale = Symmetry::<(f32,), f32>::scale("x", |&(x,), s| (x * s,), |x, s| x / s);
        let tiny = Change {
            scale: 2f32.powi(-40),
            ..Change::IDENTITY
        };
        assert!(scale.exact(&(1.0,), &tiny));
        assert!(
            !scale.exact(&(1e-30,), &tiny),
            "1e-30 * 2^-40 is below the documented range"
        );
        assert!(!scale.exact(&(1e3,), &tiny.inverse()), "1e3 * 2^40 is above it");
    }

    /// The bound carried through a restore that divides by 4 is a quarter, plus a ULP of the
    /// restored value; through a sign flip, itself.
    #[test]
    fn restored_bounds_follow_the_restore() {
        let scale = Symmetry::<(f32,), f32>::scale("x", |&(x,), s| (x * s,), |x, s| x / s);
        let change = Change {
            scale: 4.0,
            ..Change::IDENTITY
        };
        let bound = scale.restored_bounds(&8.0, &[0.5], &change)[0];
        assert!((bound - (0.125 + f32::EPSILON * 2.0)).abs() < 1e-6, "{bound}");
        let flip = Symmetry::<(f32,), f32>::exchange("-x", |&(x,)| (-x,), |x| -x);
        let bound = flip.restored_bounds(&8.0, &[0.5], &Change::IDENTITY)[0];
        assert!((bound - 0.5).abs() < 1e-5, "{bound}");
    }
}
