//! The degenerate-input table (the root crate's `src/degenerate.md`): for each function, the
//! degenerate inputs and the documented output, driven from one data source ([`table::tables`]) on
//! the CPU (the Rust mirror) and on the GPU (WGSL, GLSL and Slang kernels).
//!
//! Three kinds of rows:
//! - a documented value: the mirror returns exactly that value, each shader within the function's
//!   tolerance (derived from Vulkan's precision rules, `shader_proptest::tolerance`);
//! - "as <other input>": a clamp; each implementation returns bit for bit what it returns on the
//!   clamped input, and the shaders agree with the mirror within the tolerance;
//! - NaN or infinity in: the mirror's output is documented and asserted; Vulkan leaves NaN and
//!   infinity handling to the implementation (and WGSL lets a compiler assume neither occurs), so
//!   the shaders' outputs are printed, not asserted.

mod ray_cone;
mod ray_diff;
mod ray_diff_f64;
mod table;
mod wireframe;

use super::common::assert_generated_block;
use super::gpu;
use ray_footprint::registry::{check_registry, registry, Coverage, Registered};
use ray_footprint::shaders::Module;
use shader_proptest::{evaluate, Args, Error, Gpu, Language, Value};
use std::fmt::Write as _;
use std::path::Path;

/// What a row documents.
pub enum Expect<A> {
    /// These output components (NaN matches NaN).
    Values(Vec<f32>),
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

/// The rows of one function.
struct Table<A, R> {
    module: Module,
    function: &'static str,
    mirror: fn(A) -> R,
    /// Allowed `|shader - expected|` for an output component whose expected value is `expected`.
    tolerance: fn(&A, f32) -> f32,
    rows: Vec<Row<A>>,
}

/// The rows of `function` of `module`, registered for it: `mirror` is the function's Rust mirror,
/// `tolerance(args, expected)` the allowed `|shader - expected|` for an output component whose
/// expected value is `expected`.
pub fn register<A: Args, R: Value>(
    module: Module,
    function: &'static str,
    mirror: fn(A) -> R,
    tolerance: fn(&A, f32) -> f32,
    rows: Vec<Row<A>>,
) -> Registered<Box<dyn Degenerate>> {
    let table = Table {
        module,
        function,
        mirror,
        tolerance,
        rows,
    };
    Registered::new(module, function, Box::new(table))
}

/// A type-erased [`Table`].
pub trait Degenerate {
    fn markdown(&self, out: &mut String);
    fn cpu(&self) -> Vec<String>;
    fn gpu(&self, gpu: &Gpu, language: Language) -> Result<Vec<String>, Error>;
    fn rows(&self) -> usize;
}

fn components<R: Value>(value: &R) -> Vec<f32> {
    let mut out = Vec::new();
    value.components(&mut out);
    out
}

/// Equal, or both NaN.
fn same(a: f32, b: f32) -> bool {
    a == b || (a.is_nan() && b.is_nan())
}

fn all_same(a: &[f32], b: &[f32]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(&x, &y)| same(x, y))
}

fn bits(values: &[f32]) -> Vec<u32> {
    values.iter().map(|x| x.to_bits()).collect()
}

impl<A: Args, R: Value> Table<A, R> {
    fn name(&self) -> String {
        format!("{}::{}", self.module.stem(), self.function)
    }

    fn within(&self, args: &A, got: &[f32], expected: &[f32]) -> bool {
        got.len() == expected.len()
            && got
                .iter()
                .zip(expected)
                .all(|(&g, &e)| same(g, e) || (g.is_finite() && (g - e).abs() <= (self.tolerance)(args, e)))
    }

    /// Runs every row's arguments and every `SameAs` reference in one dispatch.
    fn dispatch(&self, gpu: &Gpu, language: Language) -> Result<Vec<Vec<f32>>, Error> {
        let mut cases: Vec<A> = self.rows.iter().map(|row| row.args.clone()).collect();
        cases.extend(self.rows.iter().filter_map(|row| match &row.expect {
            Expect::SameAs(other) => Some(other.clone()),
            _ => None,
        }));
        let function = format!("rf_{}", self.function);
        let results: Vec<R> = evaluate(gpu, &self.module.shader(language), &function, &cases)?;
        Ok(results.iter().map(components).collect())
    }
}

impl<A: Args, R: Value> Degenerate for Table<A, R> {
    fn markdown(&self, out: &mut String) {
        for row in &self.rows {
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

    fn cpu(&self) -> Vec<String> {
        let mut failures = Vec::new();
        for row in &self.rows {
            let got = components(&(self.mirror)(row.args.clone()));
            let expected = match &row.expect {
                Expect::Values(values) | Expect::Mirror(values) => values.clone(),
                Expect::SameAs(other) => components(&(self.mirror)(other.clone())),
            };
            let ok = match &row.expect {
                Expect::SameAs(_) => bits(&got) == bits(&expected),
                _ => all_same(&got, &expected),
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

    fn gpu(&self, gpu: &Gpu, language: Language) -> Result<Vec<String>, Error> {
        let outputs = self.dispatch(gpu, language)?;
        let mut references = outputs[self.rows.len()..].iter();
        let mut failures = Vec::new();
        for (row, got) in self.rows.iter().zip(&outputs) {
            let mirror = components(&(self.mirror)(row.args.clone()));
            let (ok, note) = match &row.expect {
                Expect::Values(values) => (self.within(&row.args, got, values), ""),
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

    fn rows(&self) -> usize {
        self.rows.len()
    }
}

/// The table as markdown, one section per module.
fn render() -> String {
    let mut out = String::new();
    for &module in Module::ALL {
        writeln!(out, "\n### `{}`\n", module.stem()).expect("a String");
        out.push_str("| function | degenerate input | documented output |\n| --- | --- | --- |\n");
        for table in table::tables(module) {
            table.item.markdown(&mut out);
        }
    }
    out
}

const START: &str =
    "<!-- degenerate table: generated by the lab's tests/gpu/degenerate, do not edit by hand -->";
/// The root crate's documentation page that shows the table.
const DOC: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../src/degenerate.md");
const END: &str = "<!-- end of degenerate table -->";

#[test]
fn the_docs_show_the_table() {
    let block = format!("\n{}\n", render());
    assert_generated_block(Path::new(DOC), START, END, &block, "src/degenerate.md");
}

fn all_tables() -> Vec<Box<dyn Degenerate>> {
    registry(table::tables)
        .into_iter()
        .map(|table| table.item)
        .collect()
}

/// Every public function has degenerate rows (the crate documents the degenerate output of every
/// function), registered in module order, so the table lists the functions in that order.
#[test]
fn every_function_has_rows_in_module_order() {
    let tables = registry(table::tables);
    check_registry(&tables, Coverage::Complete).unwrap_or_else(|error| panic!("{error}"));
    println!("{} functions with degenerate rows", tables.len());
}

#[test]
fn cpu_follows_the_table() {
    let tables = all_tables();
    let rows: usize = tables.iter().map(|t| t.rows()).sum();
    let failures: Vec<String> = tables.iter().flat_map(|t| t.cpu()).collect();
    println!("{} functions, {rows} rows", tables.len());
    assert!(rows > 0);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

fn gpu_follows_the_table(language: Language) {
    let gpu = gpu();
    println!("device: {}", gpu.name());
    let mut failures = Vec::new();
    for table in all_tables() {
        failures.extend(
            table
                .gpu(&gpu, language)
                .unwrap_or_else(|error| panic!("{error}")),
        );
    }
    gpu.check_messages().unwrap_or_else(|error| panic!("{error}"));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn wgsl_follows_the_table() {
    gpu_follows_the_table(Language::Wgsl);
}

#[test]
fn glsl_follows_the_table() {
    gpu_follows_the_table(Language::Glsl);
}

#[test]
fn slang_follows_the_table() {
    gpu_follows_the_table(Language::Slang);
}
