//! One record per public function: everything the runners need to check it, declared once.
//!
//! A [`Record`] holds a function's Rust mirror (its one call site), the strategy of its agreement
//! cases, its tolerance (a bound per component, an interval enclosure, or exact), its documented
//! degenerate inputs, and how the fuzzer draws its arguments and what it promises about the
//! result. The runners take what they need from it: the agreement and special-value checks
//! ([`Record::check`], [`Record::special_check`]), the special values where the function is
//! ill-conditioned ([`Record::conditioned`], [`Function::ill_conditioned_gpu`]), the degenerate
//! table ([`crate::degenerate`]),
//! the `cpu_mirror` fuzz target ([`crate::fuzzing::mirror`]), and the independent references that
//! prove the mirror itself ([`crate::reference`]). Type-erased as [`Function`], the records of all
//! modules form one list in module order ([`crate::records`]).
//!
//! ```
//! use proptest::prelude::*;
//! use ray_footprint::ray_cone::{self as rc, RayCone};
//! use ray_footprint::shaders::Module;
//! use ray_footprint_cases::Record;
//!
//! let record = Record::new(
//!     Module::RayCone,
//!     "width_at",
//!     |(cone, t): (RayCone, f32)| rc::width_at(cone, t),
//!     || (0.0f32..1.0, 0.0f32..1.0, 0.0f32..10.0)
//!         .prop_map(|(width, spread_angle, t)| (RayCone { width, spread_angle }, t))
//!         .boxed(),
//! )
//! .bound(|_, _, expected| 4.0 * f32::EPSILON * expected.abs())
//! .fuzz(|draw| (draw.cone(), draw.distance()));
//! assert_eq!(record.check().function(), "rf_width_at");
//! ```

use crate::degenerate::{Row, RowsOf};
use crate::fuzzing::draw::{Draw, Mode};
use crate::reference::{reference_seed, Kind, Reference, ReferenceReport, Summary};
use crate::special::Perturb;
use crate::symmetry::{self, Kind as SymmetryKind, Symmetry, SymmetryReport};
use proptest::strategy::{BoxedStrategy, Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use ray_footprint::shaders::Module;
use shader_proptest::interval::Interval;
use shader_proptest::{evaluate, Args, Check, Error, FunctionCheck, Gpu, Language, Tolerance, Value};
use std::cell::Cell;

/// What the fuzzer checks of a result beyond finiteness, for arguments in the documented domain.
enum Promise<A, R> {
    /// Nothing more.
    Finite,
    /// Every component of the result lies in `[low, high]`; `what` names it.
    Range(f32, f32, &'static str),
    /// A property of the arguments and the result, recorded in [`Promises`].
    Custom(fn(&A, &R, &mut Promises)),
}

/// The promises a result broke, in words.
#[derive(Default)]
pub struct Promises {
    broken: Vec<String>,
}

impl Promises {
    /// Records a broken promise unless `low <= value <= high`; `what` names the value.
    pub fn within(&mut self, value: f32, low: f32, high: f32, what: &str) {
        if !(low..=high).contains(&value) {
            self.broken
                .push(format!("{what} = {value:e} outside [{low:e}, {high:e}]"));
        }
    }
}

/// Where a function is well-conditioned: `holds(arguments)`, a property of the inputs in the
/// function's own terms; `reason` says what the other inputs are and why their value cannot be
/// checked against the mirror's (either side of a threshold is right, or the result is known only
/// to the documented clamp).
struct Conditioning<A> {
    reason: &'static str,
    holds: fn(&A) -> bool,
}

impl<A> Clone for Conditioning<A> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<A> Copy for Conditioning<A> {}

/// The special-value cases of a function outside its well-conditioned domain
/// ([`Function::ill_conditioned_gpu`]): how many were drawn and run, and the promises their
/// device results broke.
#[derive(Clone, Debug)]
pub struct IllConditioned {
    /// Why these cases are not judged on their value ([`Record::conditioned`]).
    pub reason: &'static str,
    /// Special-value cases drawn.
    pub drawn: usize,
    /// Those outside the well-conditioned domain, run on the device.
    pub run: usize,
    /// The broken promises, one line per case.
    pub failures: Vec<String>,
}

impl IllConditioned {
    /// The share of the drawn cases that were ill-conditioned.
    pub fn share(&self) -> f64 {
        self.run as f64 / self.drawn.max(1) as f64
    }
}

/// A proptest runner whose random numbers follow from `seed` alone.
pub(crate) fn seeded_runner(seed: u64) -> TestRunner {
    let mut bytes = [0u8; 16];
    bytes[..8].copy_from_slice(&seed.to_le_bytes());
    bytes[8..].copy_from_slice(&(!seed).to_le_bytes());
    TestRunner::new_with_rng(
        Config::default(),
        TestRng::from_seed(RngAlgorithm::XorShift, &bytes),
    )
}

/// One public function of a shader module and how every runner checks it.
pub struct Record<A, R> {
    module: Module,
    function: &'static str,
    mirror: fn(A) -> R,
    cases: fn() -> BoxedStrategy<A>,
    tolerance: Tolerance<A>,
    conditioning: Option<Conditioning<A>>,
    degenerate: Vec<Row<A>>,
    fuzz: Option<fn(&mut Draw) -> A>,
    promise: Promise<A, R>,
    references: Vec<Reference<A, R>>,
    symmetries: Vec<Symmetry<A, R>>,
    without_symmetry: Option<&'static str>,
    found: Option<&'static str>,
}

impl<A: Args + Perturb, R: Value> Record<A, R> {
    /// The record of `function` of `module` (its Rust name: the shader function is
    /// `rf_<function>`), with its Rust `mirror` and the strategy of its agreement `cases`; exact
    /// until a tolerance is given, with no degenerate rows and no fuzz draw yet.
    pub fn new(
        module: Module,
        function: &'static str,
        mirror: fn(A) -> R,
        cases: fn() -> BoxedStrategy<A>,
    ) -> Self {
        Record {
            module,
            function,
            mirror,
            cases,
            tolerance: Tolerance::Exact,
            conditioning: None,
            degenerate: Vec::new(),
            fuzz: None,
            promise: Promise::Finite,
            references: Vec::new(),
            symmetries: Vec::new(),
            without_symmetry: None,
            found: None,
        }
    }

    /// The tolerance `bound(arguments, component, expected)`, derived from the operations the
    /// function performs.
    pub fn bound(self, bound: fn(&A, usize, f32) -> f32) -> Self {
        Record {
            tolerance: Tolerance::per_component(bound),
            ..self
        }
    }

    /// The tolerance of each output component as the width of `enclosure`'s interval: the function
    /// re-evaluated in interval arithmetic with the rounding Vulkan allows the device and the
    /// mirror.
    pub fn enclosure(self, enclosure: fn(&A) -> Vec<Interval>) -> Self {
        let widths = move |args: &A, _: &[f32]| {
            enclosure(args)
                .iter()
                .map(|interval| interval.tolerance())
                .collect()
        };
        Record {
            tolerance: Tolerance::per_case(widths),
            ..self
        }
    }

    /// The inputs where the function is well-conditioned: `holds(arguments)`, a property of the
    /// inputs in the function's own terms, with the `reason` the others are not (either side of a
    /// threshold is right, or the result is known only to the documented clamp). The agreement
    /// and special-value checks keep to them; the others must keep the record's promises on the
    /// device ([`Function::ill_conditioned_gpu`]).
    pub fn conditioned(self, reason: &'static str, holds: fn(&A) -> bool) -> Self {
        Record {
            conditioning: Some(Conditioning { reason, holds }),
            ..self
        }
    }

    /// The documented degenerate inputs and outputs ([`crate::degenerate`]).
    pub fn degenerate(self, rows: Vec<Row<A>>) -> Self {
        Record {
            degenerate: rows,
            ..self
        }
    }

    /// How the `cpu_mirror` fuzz target draws the arguments from its input.
    pub fn fuzz(self, draw: fn(&mut Draw) -> A) -> Self {
        Record {
            fuzz: Some(draw),
            ..self
        }
    }

    /// For arguments in the documented domain, every component of the result lies in
    /// `[low, high]` (`what` names it in a failure).
    pub fn range(self, low: f32, high: f32, what: &'static str) -> Self {
        Record {
            promise: Promise::Range(low, high, what),
            ..self
        }
    }

    /// For arguments in the documented domain, `promise(arguments, result, promises)` records
    /// what the result breaks.
    pub fn promise(self, promise: fn(&A, &R, &mut Promises)) -> Self {
        Record {
            promise: Promise::Custom(promise),
            ..self
        }
    }

    /// An independent reference of the function ([`crate::reference`]); a function may have several.
    pub fn reference(mut self, reference: Reference<A, R>) -> Self {
        self.references.push(reference);
        self
    }

    /// A transformation the function's math respects ([`crate::symmetry`]); a function may
    /// have several.
    pub fn symmetry(mut self, symmetry: Symmetry<A, R>) -> Self {
        self.symmetries.push(symmetry);
        self
    }

    /// Why the function has no symmetry to declare.
    pub fn without_symmetry(self, reason: &'static str) -> Self {
        Record {
            without_symmetry: Some(reason),
            ..self
        }
    }

    /// The bug that a check or reference of this function found, in words (for the table of
    /// `src/proven.md`).
    pub fn found(self, bug: &'static str) -> Self {
        Record {
            found: Some(bug),
            ..self
        }
    }

    /// Runs reference `index` on cases drawn from a seed derived from `seed` and the function's
    /// name ([`reference_seed`]); then once more through each scale symmetry whose restore is
    /// exact ([`Symmetry::restores_exactly`]): the function evaluated at each case scaled by the
    /// power of two its words draw over the documented range, and restored
    /// (`Record::scaled_mirror`), so that the reference holds far from 1 too.
    pub fn run_reference(&self, index: usize, seed: u64) -> ReferenceReport {
        let reference = &self.references[index];
        let seed = reference_seed(seed, self.module, self.function, index);
        let scales = self
            .symmetries
            .iter()
            .filter(|symmetry| symmetry.kind() == SymmetryKind::Scale && symmetry.restores_exactly());
        let outcome = scales.fold(reference.run(&self.mirror, seed), |outcome, symmetry| {
            let evaluations_scaled = Cell::new(0);
            let scaled = reference
                .run(
                    &|args| self.scaled_mirror(symmetry, args, &evaluations_scaled),
                    seed,
                )
                .map_err(|failure| format!("the case scaled ({}): {failure}", symmetry.description()));
            match (outcome, scaled) {
                (Ok(unit), Ok(scaled)) => Ok(Summary {
                    cases: unit.cases + scaled.cases,
                    left_out: unit.left_out + scaled.left_out,
                    scaled: unit.scaled + evaluations_scaled.get(),
                    worst: unit.worst.and(scaled.worst),
                }),
                (Err(failure), _) | (_, Err(failure)) => Err(failure),
            }
        });
        ReferenceReport {
            function: format!("{}::{}", self.module.stem(), self.function),
            kind: reference.kind(),
            description: reference.description(),
            seed,
            outcome,
        }
    }

    /// The mirror at `args` through a scale symmetry: the case scaled by the power of two its words
    /// draw ([`shader_proptest::case_seed`]) and the result restored, counted in `scaled`, where
    /// that change applies; else the mirror at `args`.
    fn scaled_mirror(&self, symmetry: &Symmetry<A, R>, args: A, scaled: &Cell<u32>) -> R {
        let change = symmetry.change(shader_proptest::case_seed(&args));
        if symmetry.applies(&args, &change) {
            scaled.set(scaled.get() + 1);
            symmetry.restore((self.mirror)(symmetry.transform(&args, &change)), &change)
        } else {
            (self.mirror)(args)
        }
    }

    /// The mirror's result for `args`.
    pub fn mirror(&self, args: A) -> R {
        (self.mirror)(args)
    }

    /// The tolerance.
    pub fn tolerance(&self) -> &Tolerance<A> {
        &self.tolerance
    }

    /// The strategy of the agreement cases (before the conditioning filter).
    pub fn cases(&self) -> fn() -> BoxedStrategy<A> {
        self.cases
    }

    /// The mirror.
    pub fn mirror_fn(&self) -> fn(A) -> R {
        self.mirror
    }

    /// Where the function is well-conditioned ([`Record::conditioned`]): `None` where it is
    /// everywhere.
    pub fn conditioning(&self) -> Option<fn(&A) -> bool> {
        self.conditioning.map(|conditioning| conditioning.holds)
    }

    /// Whether the function is well-conditioned at `args` ([`Record::conditioned`]).
    pub fn well_conditioned_at(&self, args: &A) -> bool {
        self.conditioning().is_none_or(|holds| holds(args))
    }

    /// The declared symmetries.
    pub fn symmetries(&self) -> &[Symmetry<A, R>] {
        &self.symmetries
    }

    /// The degenerate rows with the function, mirror and tolerance they run against.
    fn rows_to_run(&self) -> RowsOf<'_, A, R> {
        RowsOf {
            module: self.module,
            function: self.function,
            rows: &self.degenerate,
            mirror: self.mirror,
            tolerance: &self.tolerance,
        }
    }

    /// The agreement check: `rf_<function>` against the mirror on the record's cases where it is
    /// well-conditioned ([`Record::conditioned`]), within its tolerance.
    pub fn check(&self) -> FunctionCheck<A, R> {
        let check = FunctionCheck::new(format!("rf_{}", self.function), self.cases, self.mirror)
            .tolerance(self.tolerance.clone());
        self.well_conditioned(check)
    }

    /// `check` on its cases where the function is well-conditioned.
    fn well_conditioned(&self, check: FunctionCheck<A, R>) -> FunctionCheck<A, R> {
        match self.conditioning {
            Some(Conditioning { reason, holds }) => check.with_filter(reason, holds),
            None => check,
        }
    }

    /// The agreement check on its cases pushed towards special values ([`crate::special`]),
    /// well-conditioned or not.
    fn every_special_case(&self) -> FunctionCheck<A, R> {
        self.check().with_perturbation(|mut args: A, rng| {
            args.perturb(rng);
            args
        })
    }

    /// The special-value check: the agreement check on its cases pushed towards special values
    /// ([`crate::special`]), those where the function is well-conditioned
    /// ([`Record::conditioned`]).
    pub fn special_check(&self) -> FunctionCheck<A, R> {
        self.well_conditioned(self.every_special_case())
    }

    fn broken_promises(&self, args: &A, result: &R) -> Vec<String> {
        let mut components = Vec::new();
        result.components(&mut components);
        let mut promises = Promises::default();
        if components.iter().any(|x| !x.is_finite()) {
            promises.broken.push(format!("non-finite output {components:?}"));
        }
        match self.promise {
            Promise::Finite => {}
            Promise::Range(low, high, what) => components
                .iter()
                .for_each(|&x| promises.within(x, low, high, what)),
            Promise::Custom(promise) => promise(args, result, &mut promises),
        }
        promises.broken
    }
}

/// A record with its argument and result types erased, for the list of every function.
pub trait Function: Send + Sync {
    /// The module declaring the function.
    fn module(&self) -> Module;
    /// The function's Rust name (the shader function is `rf_<name>`).
    fn name(&self) -> &'static str;
    /// [`Record::check`].
    fn agreement_check(&self) -> Box<dyn Check>;
    /// [`Record::special_check`].
    fn special_check(&self) -> Box<dyn Check>;
    /// How many degenerate rows the record documents.
    fn degenerate_rows(&self) -> usize;
    /// Appends the degenerate rows to a markdown table.
    fn degenerate_markdown(&self, out: &mut String);
    /// Runs the degenerate rows through the mirror: the rows it does not follow.
    fn degenerate_cpu(&self) -> Vec<String>;
    /// Runs the degenerate rows through the shader function in `language`: the rows it does not
    /// follow.
    fn degenerate_gpu(&self, gpu: &Gpu, language: Language) -> Result<Vec<String>, Error>;
    /// Draws `count` special-value cases from `seed` and runs those where the function is
    /// ill-conditioned ([`Record::conditioned`]) through the shader function in `language`: their
    /// results must keep the record's promises. `None` for a record well-conditioned everywhere.
    fn ill_conditioned_gpu(
        &self,
        gpu: &Gpu,
        language: Language,
        count: usize,
        seed: u64,
    ) -> Result<Option<IllConditioned>, Error>;
    /// Whether the record says how the fuzzer draws its arguments.
    fn has_fuzz_draw(&self) -> bool;
    /// Evaluates the mirror on arguments drawn from `data` in `mode`: `Err` names the promises the
    /// result broke, where the function promises something for such arguments.
    fn fuzz(&self, data: &[u8], mode: Mode) -> Result<(), String>;
    /// The kind and description of each independent reference, in the record's order.
    fn references(&self) -> Vec<(Kind, &'static str)>;
    /// [`Record::run_reference`].
    fn run_reference(&self, index: usize, seed: u64) -> ReferenceReport;
    /// [`Record::found`]'s bug, if any.
    fn found(&self) -> Option<&'static str>;
    /// The kind and description of each declared symmetry, in the record's order.
    fn symmetry_list(&self) -> Vec<(SymmetryKind, &'static str)>;
    /// Why the function declares no symmetry, where it says so.
    fn without_symmetry(&self) -> Option<&'static str>;
    /// Runs symmetry `index` on the mirror over `cases` cases drawn from `seed`
    /// ([`crate::symmetry`]).
    fn symmetry_cpu(&self, index: usize, cases: usize, seed: u64) -> SymmetryReport;
    /// Symmetry `index` as a metamorphic check of the shader function against itself.
    fn symmetry_check(&self, index: usize) -> Box<dyn Check>;
}

impl<A: Args + Perturb, R: Value> Function for Record<A, R> {
    fn module(&self) -> Module {
        self.module
    }

    fn name(&self) -> &'static str {
        self.function
    }

    fn agreement_check(&self) -> Box<dyn Check> {
        Box::new(self.check())
    }

    fn special_check(&self) -> Box<dyn Check> {
        Box::new(Record::special_check(self))
    }

    fn degenerate_rows(&self) -> usize {
        self.degenerate.len()
    }

    fn degenerate_markdown(&self, out: &mut String) {
        self.rows_to_run().markdown(out);
    }

    fn degenerate_cpu(&self) -> Vec<String> {
        self.rows_to_run().cpu()
    }

    fn degenerate_gpu(&self, gpu: &Gpu, language: Language) -> Result<Vec<String>, Error> {
        self.rows_to_run().gpu(gpu, language)
    }

    fn ill_conditioned_gpu(
        &self,
        gpu: &Gpu,
        language: Language,
        count: usize,
        seed: u64,
    ) -> Result<Option<IllConditioned>, Error> {
        let Some(Conditioning { reason, holds }) = self.conditioning else {
            return Ok(None);
        };
        let strategy = self.every_special_case().strategy();
        let mut runner = seeded_runner(seed);
        let drawn: Vec<A> = (0..count)
            .filter_map(|_| strategy.new_tree(&mut runner).ok().map(|tree| tree.current()))
            .collect();
        let cases: Vec<A> = drawn.iter().filter(|args| !holds(args)).cloned().collect();
        let shader = self.module.shader(language);
        let results: Vec<R> = if cases.is_empty() {
            Vec::new()
        } else {
            evaluate(gpu, &shader, &format!("rf_{}", self.function), &cases)?
        };
        let failures = cases
            .iter()
            .zip(&results)
            .filter(|(args, _)| args.is_finite())
            .filter_map(|(args, result)| {
                let broken = self.broken_promises(args, result);
                (!broken.is_empty()).then(|| format!("{args:?} gave {result:?}: {}", broken.join("; ")))
            })
            .collect();
        Ok(Some(IllConditioned {
            reason,
            drawn: drawn.len(),
            run: cases.len(),
            failures,
        }))
    }

    fn has_fuzz_draw(&self) -> bool {
        self.fuzz.is_some()
    }

    fn references(&self) -> Vec<(Kind, &'static str)> {
        self.references
            .iter()
            .map(|reference| (reference.kind(), reference.description()))
            .collect()
    }

    fn run_reference(&self, index: usize, seed: u64) -> ReferenceReport {
        Record::run_reference(self, index, seed)
    }

    fn found(&self) -> Option<&'static str> {
        self.found
    }

    fn symmetry_list(&self) -> Vec<(SymmetryKind, &'static str)> {
        self.symmetries
            .iter()
            .map(|symmetry| (symmetry.kind(), symmetry.description()))
            .collect()
    }

    fn without_symmetry(&self) -> Option<&'static str> {
        self.without_symmetry
    }

    fn symmetry_cpu(&self, index: usize, cases: usize, seed: u64) -> SymmetryReport {
        symmetry::run_on_mirror(self, index, cases, seed)
    }

    fn symmetry_check(&self, index: usize) -> Box<dyn Check> {
        Box::new(symmetry::metamorphic_check(self, index))
    }

    fn fuzz(&self, data: &[u8], mode: Mode) -> Result<(), String> {
        let Some(draw_arguments) = self.fuzz else {
            return Ok(());
        };
        let mut draw = Draw::new(data, mode);
        let args = draw_arguments(&mut draw);
        let result = (self.mirror)(args.clone());
        // Raw bits promise nothing but the absence of a panic, except to the wireframe module,
        // whose documentation promises a finite coverage in [0, 1] for every finite input.
        let promised = match mode {
            Mode::Domain => true,
            Mode::Raw => draw.finite() && self.module == Module::Wireframe,
        };
        let broken = if promised {
            self.broken_promises(&args, &result)
        } else {
            Vec::new()
        };
        if broken.is_empty() {
            Ok(())
        } else {
            Err(format!(
                "{}::{} ({mode:?} inputs): {}",
                self.module.stem(),
                self.function,
                broken.join("; ")
            ))
        }
    }
}
