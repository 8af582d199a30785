//! One record per public function: everything the runners need to check it, declared once.
//!
//! A [`Record`] holds a function's Rust mirror (its one call site), the strategy of its agreement
//! cases, its tolerance (a bound per component, an interval enclosure, or exact), its documented
//! degenerate inputs, and how the fuzzer draws its arguments and what it promises about the
//! result. The runners take what they need from it: the agreement and special-value checks
//! ([`Record::check`], [`Record::special_check`]), the degenerate table ([`crate::degenerate`]),
//! the `cpu_mirror` fuzz target ([`crate::fuzzing::mirror`]). Type-erased as [`Function`], the
//! records of all modules form one list in module order ([`crate::records`]).
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

use crate::degenerate::Row;
use crate::fuzzing::draw::{Draw, Mode};
use crate::special::Perturb;
use proptest::strategy::BoxedStrategy;
use ray_footprint::shaders::Module;
use shader_proptest::interval::Interval;
use shader_proptest::{Args, Check, Error, FunctionCheck, Gpu, Language, Tolerance, Value};

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

/// One public function of a shader module and how every runner checks it.
pub struct Record<A, R> {
    module: Module,
    function: &'static str,
    mirror: fn(A) -> R,
    cases: fn() -> BoxedStrategy<A>,
    tolerance: Tolerance<A>,
    degenerate: Vec<Row<A>>,
    fuzz: Option<fn(&mut Draw) -> A>,
    promise: Promise<A, R>,
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
            degenerate: Vec::new(),
            fuzz: None,
            promise: Promise::Finite,
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

    /// The mirror's result for `args`.
    pub fn mirror(&self, args: A) -> R {
        (self.mirror)(args)
    }

    /// The tolerance.
    pub fn tolerance(&self) -> &Tolerance<A> {
        &self.tolerance
    }

    /// The degenerate rows.
    pub fn rows(&self) -> &[Row<A>] {
        &self.degenerate
    }

    /// The agreement check: `rf_<function>` against the mirror on the record's cases, within its
    /// tolerance.
    pub fn check(&self) -> FunctionCheck<A, R> {
        FunctionCheck::new(format!("rf_{}", self.function), self.cases, self.mirror)
            .tolerance(self.tolerance.clone())
    }

    /// The special-value check: the agreement check on its cases pushed towards special values
    /// ([`crate::special`]).
    pub fn special_check(&self) -> FunctionCheck<A, R> {
        self.check().with_perturbation(|mut args: A, rng| {
            args.perturb(rng);
            args
        })
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
    /// Whether the record says how the fuzzer draws its arguments.
    fn has_fuzz_draw(&self) -> bool;
    /// Evaluates the mirror on arguments drawn from `data` in `mode`: `Err` names the promises the
    /// result broke, where the function promises something for such arguments.
    fn fuzz(&self, data: &[u8], mode: Mode) -> Result<(), String>;
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
        crate::degenerate::markdown(self.function, &self.degenerate, out);
    }

    fn degenerate_cpu(&self) -> Vec<String> {
        crate::degenerate::cpu(self)
    }

    fn degenerate_gpu(&self, gpu: &Gpu, language: Language) -> Result<Vec<String>, Error> {
        crate::degenerate::gpu(self, gpu, language)
    }

    fn has_fuzz_draw(&self) -> bool {
        self.fuzz.is_some()
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
