//! What each shader function costs: for every public function of every module (the agreement
//! suite's checks, in module order) and every language, the function compiled alone in the
//! suite's kernel for it (WGSL by naga, GLSL by glslang, Slang by slangc, HLSL by glslang and by
//! slangc), optimised by `spirv-opt -O`, and
//! counted with `shader_proptest::spirv`: instructions inside functions (the kernel's own loads
//! and stores included: every function pays them, per argument and result word), conditional
//! branches and switches, extended-instruction calls and, among them, transcendental calls
//! (`shader_proptest::spirv::TRANSCENDENTAL`). Needs no Vulkan device. Every kernel has one
//! conditional branch and one switch of its own: its bounds check, an early return that
//! spirv-opt's merge-return pass wraps in a one-case switch.
//!
//! Prints a Markdown table (the README's), with a `*` where another language's instruction count
//! differs from GLSL's by more than a quarter. Below it, when `rf_process_wireframe` is measured, the same counts
//! for a yardstick in the same kernel: `unguarded_process_wireframe` (`benches/unguarded/`), the
//! wireframe tutorial's coverage formula without the crate's guards, so that the table says what
//! the defined behaviour on degenerate input costs.
//!
//! `cargo bench -p ray-footprint-lab --bench function_costs [-- --function NAME] [--module NAME]`
//!
//! `--function` takes the shader name (`rf_process_wireframe`) or the mirror's
//! (`process_wireframe`); `--module` a module's file stem (`wireframe`).

use glam::Vec3;
use ray_footprint::shaders::{Module, GLSL_INCLUDE_DIR, HLSL_INCLUDE_DIR, SLANG_INCLUDE_DIR};
use ray_footprint::wireframe::WireframeSettings;
use ray_footprint_cases::records;
use ray_footprint_lab::cli::options_or_exit;
use shader_proptest::spirv::{self, Statistics, TRANSCENDENTAL};
use shader_proptest::{kernel_source, Args, Check, Language, Shader, Value};
use std::process::{Command, ExitCode};

/// The languages, in the order of [`Language::ALL`].
const LANGUAGES: usize = Language::ALL.len();

/// The unguarded yardstick of `rf_process_wireframe` in HLSL, for both HLSL compilers.
const UNGUARDED_WIREFRAME_HLSL: &str = include_str!("unguarded/process_wireframe.hlsl");

/// The unguarded yardstick of `rf_process_wireframe`, per language, appended to the module.
const UNGUARDED_WIREFRAME: [(Language, &str); LANGUAGES] = [
    (Language::Wgsl, include_str!("unguarded/process_wireframe.wgsl")),
    (Language::Glsl, include_str!("unguarded/process_wireframe.glsl")),
    (Language::Slang, include_str!("unguarded/process_wireframe.slang")),
    (Language::HlslGlslang, UNGUARDED_WIREFRAME_HLSL),
    (Language::HlslSlangc, UNGUARDED_WIREFRAME_HLSL),
];

/// Largest relative difference between another language's and GLSL's instruction counts left
/// unmarked.
const MARK_ABOVE: f64 = 0.25;

/// Which functions to measure.
#[derive(Default)]
struct Filter {
    function: Option<String>,
    module: Option<String>,
}

impl Filter {
    fn accepts(&self, module: Module, function: &str) -> bool {
        let function_matches = self
            .function
            .as_deref()
            .is_none_or(|wanted| function == wanted || function.strip_prefix("rf_") == Some(wanted));
        let module_matches = self
            .module
            .as_deref()
            .is_none_or(|wanted| module.stem() == wanted);
        function_matches && module_matches
    }
}

fn parse_args(mut args: impl Iterator<Item = String>) -> Result<Filter, String> {
    let mut filter = Filter::default();
    while let Some(flag) = args.next() {
        let target = match flag.as_str() {
            // cargo bench passes --bench to every benchmark.
            "--bench" => continue,
            "--function" => &mut filter.function,
            "--module" => &mut filter.module,
            other => return Err(format!("unknown argument '{other}'")),
        };
        let value = args.next().ok_or_else(|| format!("{flag} needs a value"))?;
        *target = Some(value);
    }
    Ok(filter)
}

/// The counts of `check`'s kernel for `module` in `language`, after `spirv-opt -O`.
fn measure(module: Module, check: &dyn Check, language: Language) -> Result<Statistics, String> {
    let shader = module.shader(language);
    count(&shader, &check.kernel(&shader)).map_err(|e| format!("{} ({language}): {e}", check.function()))
}

/// The counts of `kernel`, compiled against `shader` and optimised by `spirv-opt -O`.
fn count(shader: &Shader, kernel: &str) -> Result<Statistics, String> {
    let words = shader.compile_kernel(kernel).map_err(|e| e.to_string())?;
    let optimized = spirv::optimize(&words).map_err(|e| e.to_string())?;
    Statistics::of(&optimized).map_err(|e| e.to_string())
}

/// The counts of the unguarded yardstick's kernel in `language`, after `spirv-opt -O`: the wireframe
/// module with the yardstick appended, called with `rf_process_wireframe`'s arguments.
fn measure_unguarded(language: Language) -> Result<Statistics, String> {
    let (_, yardstick) = UNGUARDED_WIREFRAME
        .iter()
        .find(|(l, _)| *l == language)
        .expect("a yardstick per language");
    let module = Module::Wireframe.shader(language);
    let shader = match language {
        Language::Wgsl => Shader::wgsl(format!("{}\n{yardstick}", module.source())),
        Language::Glsl => {
            Shader::glsl(format!("{}\n{yardstick}", module.source())).include_dir(GLSL_INCLUDE_DIR)
        }
        Language::Slang => {
            Shader::slang(format!("{}\n{yardstick}", module.source())).include_dir(SLANG_INCLUDE_DIR)
        }
        Language::HlslGlslang | Language::HlslSlangc => {
            Shader::new(language, format!("{}\n{yardstick}", module.source())).include_dir(HLSL_INCLUDE_DIR)
        }
    };
    let kernel = kernel_source(
        &shader,
        "unguarded_process_wireframe",
        <(WireframeSettings, Vec3, Vec3)>::TYPES,
        f32::TYPE,
    );
    count(&shader, &kernel).map_err(|e| format!("unguarded_process_wireframe ({language}): {e}"))
}

/// The first line `program flag` prints (on either stream), or why it did not run.
fn version(program: &str, flag: &str) -> String {
    match Command::new(program).arg(flag).output() {
        Ok(output) => [output.stdout, output.stderr]
            .iter()
            .flat_map(|bytes| {
                String::from_utf8_lossy(bytes)
                    .lines()
                    .map(str::to_string)
                    .collect::<Vec<_>>()
            })
            .find(|line| !line.trim().is_empty())
            .unwrap_or_default(),
        Err(error) => format!("{program}: {error}"),
    }
}

/// `(other - GLSL) / GLSL` in per cent, marked `*` where the larger count exceeds the smaller by
/// more than [`MARK_ABOVE`].
fn difference(other: usize, glsl: usize) -> String {
    let ratio = other as f64 / glsl.max(1) as f64;
    let larger_over_smaller = other.max(glsl) as f64 / other.min(glsl).max(1) as f64;
    let marked = larger_over_smaller > 1.0 + MARK_ABOVE;
    format!("{:+.0}%{}", 100.0 * (ratio - 1.0), if marked { " *" } else { "" })
}

/// The languages other than GLSL, whose instruction counts are compared with GLSL's.
fn compared_with_glsl() -> impl Iterator<Item = (usize, Language)> {
    Language::ALL
        .into_iter()
        .enumerate()
        .filter(|(_, language)| *language != Language::Glsl)
}

/// One table row: per count, the languages in the order of [`Language::ALL`].
fn row(module: Module, function: &str, counts: &[Statistics; LANGUAGES]) -> String {
    let glsl = &counts[Language::ALL
        .iter()
        .position(|language| *language == Language::Glsl)
        .expect("GLSL is a language")];
    let cells = |count: fn(&Statistics) -> String| counts.iter().map(count).collect::<Vec<_>>().join(" | ");
    let differences: Vec<String> = compared_with_glsl()
        .map(|(index, _)| difference(counts[index].instructions, glsl.instructions))
        .collect();
    format!(
        "| {} | `{function}` | {} | {} | {} | {} | {} |",
        module.stem(),
        cells(|s| s.instructions.to_string()),
        differences.join(" | "),
        cells(|s| format!("{}+{}", s.conditional_branches, s.switches)),
        cells(|s| s.extended_calls.to_string()),
        cells(|s| s.transcendental_calls.to_string()),
    )
}

fn print_header() {
    let per_language = |count: &str| {
        Language::ALL
            .map(|language| format!("{} {count}", language.name()))
            .join(" | ")
    };
    let differences: Vec<String> = compared_with_glsl()
        .map(|(_, language)| format!("{} vs GLSL", language.name()))
        .collect();
    println!(
        "| module | function | {} | {} | {} | {} | {} |",
        per_language("instructions"),
        differences.join(" | "),
        per_language("branches"),
        per_language("extended"),
        per_language("transcendental")
    );
    println!("| --- | --- |{}", " ---: |".repeat(5 * LANGUAGES - 1));
}

/// Prints the row of `function`, or its errors; whether it was measured in every language.
fn print_row(module: Module, function: &str, counts: [Result<Statistics, String>; LANGUAGES]) -> bool {
    let errors: Vec<&String> = counts.iter().filter_map(|count| count.as_ref().err()).collect();
    if !errors.is_empty() {
        errors.iter().for_each(|error| eprintln!("error: {error}"));
        return false;
    }
    println!(
        "{}",
        row(module, function, &counts.map(|count| count.expect("no errors")))
    );
    true
}

fn main() -> ExitCode {
    let filter = options_or_exit(
        parse_args(std::env::args().skip(1)),
        "usage: function_costs [--function NAME] [--module NAME]",
    );
    let checks: Vec<_> = records()
        .iter()
        .map(|record| (record.module(), record.agreement_check()))
        .filter(|(module, check)| filter.accepts(*module, check.function()))
        .collect();
    if checks.is_empty() {
        eprintln!("error: no function matches");
        return ExitCode::from(2);
    }
    println!(
        "SPIR-V per function for Vulkan 1.1 after spirv-opt -O; WGSL by naga, GLSL by {}, Slang by slangc {}; {}",
        version("glslangValidator", "--version"),
        version("slangc", "-v"),
        version("spirv-opt", "--version")
    );
    let names: Vec<_> = TRANSCENDENTAL.iter().map(|(_, name)| *name).collect();
    println!("transcendental: GLSL.std.450 {}", names.join(", "));
    println!(
        "branches: conditional branches + switches, the kernel's own 1+1 (its bounds check) included; \
         * marks an instruction difference from GLSL above 25%\n"
    );
    print_header();
    let mut failed = 0;
    for (module, check) in &checks {
        let counts = Language::ALL.map(|language| measure(*module, check.as_ref(), language));
        failed += usize::from(!print_row(*module, check.function(), counts));
    }
    if filter.accepts(Module::Wireframe, "rf_process_wireframe") {
        println!(
            "\nYardstick in the same kernel: the tutorial's formula without guards (benches/unguarded/)\n"
        );
        print_header();
        let counts = Language::ALL.map(measure_unguarded);
        failed += usize::from(!print_row(
            Module::Wireframe,
            "unguarded_process_wireframe",
            counts,
        ));
    }
    if failed == 0 {
        ExitCode::SUCCESS
    } else {
        eprintln!("{failed} function(s) could not be measured");
        ExitCode::FAILURE
    }
}
