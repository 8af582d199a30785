//! The agreement suite: every shader function of every module, checked against its Rust mirror
//! with shader-proptest, one check per function in the module's order.
//!
//! Each check's tolerance is derived from the operations its function performs (Vulkan's
//! precision rules, `shader_proptest::tolerance`), either by hand (a bound per output component,
//! with a comment saying how) or mechanically, as the width of an interval enclosure of the
//! function (`shader_proptest::interval`).

pub mod edge;
pub mod ray_cone;
pub mod ray_diff;
pub mod ray_diff_f64;
pub mod strategy;
pub mod wireframe;

use edge::Edge;
use proptest::strategy::BoxedStrategy;
use ray_footprint::registry::{registry, Registered};
use ray_footprint::shaders::Module;
use shader_proptest::interval::Interval;
use shader_proptest::{
    run_checks, Args, Check, Error, FunctionCheck, Gpu, Language, Report, RunConfig, Tolerance, Value,
};

/// One function's checks: the agreement check on its well-conditioned domain, and the same
/// function, mirror and tolerance on edge cases ([`edge`]).
pub struct Entry {
    /// The agreement check.
    pub check: Box<dyn Check>,
    /// The edge-case check.
    pub edge: Box<dyn Check>,
}

impl Entry {
    /// The entry of `check` with its edge variant.
    pub fn new<A: Args + Edge, R: Value>(check: FunctionCheck<A, R>) -> Entry {
        let edge = Box::new(check.with_perturbation(|mut args: A, rng| {
            args.perturb(rng);
            args
        }));
        Entry {
            check: Box::new(check),
            edge,
        }
    }
}

/// The entries of a module's functions: `registered_checks!(Module::RayCone, [width_at, propagate])`
/// registers the check that `width_at()` builds as function `width_at` of `Module::RayCone`, and so
/// on, in the order given (the module's function order), so that a check and the function it is
/// registered for cannot carry different names.
macro_rules! registered_checks {
    ($module:path, [$($function:ident),+ $(,)?]) => {
        vec![$(
            ray_footprint::registry::Registered::new(
                $module,
                stringify!($function),
                $crate::checks::Entry::new($function()),
            ),
        )+]
    };
}
use registered_checks;

/// A check of `rf_<function>` whose tolerance is `bound(arguments, component, expected)`.
pub fn per_component<A: Args, R: Value>(
    function: &str,
    strategy: fn() -> BoxedStrategy<A>,
    mirror: fn(A) -> R,
    bound: fn(&A, usize, f32) -> f32,
) -> FunctionCheck<A, R> {
    FunctionCheck::new(format!("rf_{function}"), strategy, mirror).tolerance(Tolerance::per_component(bound))
}

/// A check of `rf_<function>` whose every output component must equal the mirror's (a function
/// that only copies, converts exactly or compares: the caller says why).
pub(crate) fn exact<A: Args, R: Value>(
    function: &str,
    strategy: fn() -> BoxedStrategy<A>,
    mirror: fn(A) -> R,
) -> FunctionCheck<A, R> {
    per_component(function, strategy, mirror, |_, _, _| 0.0)
}

/// A check of `rf_<function>` whose tolerance is the width of `enclosure`'s interval for each
/// output component: the function re-evaluated in interval arithmetic with the rounding Vulkan
/// allows the device and the mirror.
pub fn enclosed<A: Args, R: Value>(
    function: &str,
    strategy: fn() -> BoxedStrategy<A>,
    mirror: fn(A) -> R,
    enclosure: fn(&A) -> Vec<Interval>,
) -> FunctionCheck<A, R> {
    let widths = move |args: &A, _: &[f32]| {
        enclosure(args)
            .iter()
            .map(|interval| interval.tolerance())
            .collect()
    };
    FunctionCheck::new(format!("rf_{function}"), strategy, mirror).tolerance(Tolerance::per_case(widths))
}

/// Every function's entry in one module, in the module's function order.
pub fn entries(module: Module) -> Vec<Registered<Entry>> {
    match module {
        Module::RayCone => ray_cone::entries(),
        Module::RayDiff => ray_diff::entries(),
        Module::RayDiffF64 => ray_diff_f64::entries(),
        Module::Wireframe => wireframe::entries(),
    }
}

/// Every function's entry, in module order.
pub fn all_entries() -> Vec<Registered<Entry>> {
    registry(entries)
}

/// The agreement checks of one module, in the module's function order.
pub fn checks(module: Module) -> Vec<Box<dyn Check>> {
    entries(module)
        .into_iter()
        .map(|entry| entry.item.check)
        .collect()
}

/// Every agreement check, registered for its function, in module order.
pub fn all_checks() -> Vec<Registered<Box<dyn Check>>> {
    all_entries()
        .into_iter()
        .map(|entry| entry.map(|entry| entry.check))
        .collect()
}

/// Runs every agreement check in every language ([`Language::ALL`]), in module order, and hands
/// each result to `each` with the check's module and language. Half the processors (at least one)
/// prepare the next checks while one runs ([`shader_proptest::run_checks`]).
pub fn run_all_checks(
    gpu: &Gpu,
    config: &RunConfig,
    mut each: impl FnMut(Module, &dyn Check, Language, Result<Report, Error>),
) -> Result<(), Error> {
    let checks = all_checks();
    let runs: Vec<(Module, &dyn Check, Language)> = checks
        .iter()
        .flat_map(|check| Language::ALL.map(|language| (check.module, check.item.as_ref(), language)))
        .collect();
    let shaders: Vec<(&dyn Check, shader_proptest::Shader)> = runs
        .iter()
        .map(|&(module, check, language)| (check, module.shader(language)))
        .collect();
    let preparers = (std::thread::available_parallelism().map_or(1, usize::from) / 2).max(1);
    run_checks(gpu, &shaders, config, preparers, |index, result| {
        let (module, check, language) = runs[index];
        each(module, check, language, result);
    })
}
