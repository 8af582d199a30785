//! Every public function and method of the mirror modules and of `abi` shows its use: its doc
//! comment has an `# Examples` section whose code asserts something. The sources are read as
//! `Module::functions` reads them, in module order, and the first function without one is named.

use ray_footprint::shaders::Module;

/// A public function or method and the doc comment above it.
struct Documented {
    /// `function` or `Type::method`.
    name: String,
    /// The doc comment's lines without `///`.
    doc: Vec<String>,
}

/// The public functions and methods of a Rust source, in order, with their doc comments. Attributes
/// and plain comments between a doc comment and its function are skipped; a method is named after
/// the type of the `impl` block it is in.
fn documented_functions(source: &str) -> Vec<Documented> {
    let mut functions = Vec::new();
    let mut doc = Vec::new();
    let mut impl_type = String::new();
    for line in source.lines() {
        let trimmed = line.trim_start();
        if let Some(text) = trimmed.strip_prefix("///") {
            doc.push(text.strip_prefix(' ').unwrap_or(text).to_string());
            continue;
        }
        if trimmed.starts_with("#[") || trimmed.starts_with("//") {
            continue;
        }
        if let Some(rest) = line.strip_prefix("impl ") {
            impl_type = rest.split([' ', '<', '{']).next().unwrap_or_default().to_string();
        }
        let signature = trimmed
            .strip_prefix("pub fn ")
            .or(trimmed.strip_prefix("pub const fn "));
        if let Some(rest) = signature {
            let function = rest.split(['(', '<']).next().unwrap_or_default();
            let name = if line.starts_with(' ') {
                format!("{impl_type}::{function}")
            } else {
                function.to_string()
            };
            functions.push(Documented {
                name,
                doc: doc.clone(),
            });
        }
        doc.clear();
    }
    functions
}

/// Whether the doc comment has an `# Examples` section with a code block that asserts.
fn has_asserting_example(doc: &[String]) -> bool {
    let Some(start) = doc.iter().position(|line| line == "# Examples") else {
        return false;
    };
    let mut in_code = false;
    for line in &doc[start + 1..] {
        if line.starts_with("# ") && !in_code {
            return false;
        }
        if line.starts_with("```") {
            in_code = !in_code;
        } else if in_code && line.contains("assert") {
            return true;
        }
    }
    false
}

/// The mirror modules in module order, then `abi`: `(name, source)`.
fn sources() -> Vec<(String, String)> {
    let stems = Module::ALL.iter().map(|module| module.stem()).chain(["abi"]);
    stems
        .map(|stem| {
            let path = format!("{}/src/{stem}.rs", env!("CARGO_MANIFEST_DIR"));
            let source = std::fs::read_to_string(&path).unwrap_or_else(|error| panic!("{path}: {error}"));
            (stem.to_string(), source)
        })
        .collect()
}

#[test]
fn every_public_function_has_an_example_that_asserts() {
    let mut missing = Vec::new();
    let mut count = 0;
    for (module, source) in sources() {
        for function in documented_functions(&source) {
            count += 1;
            if !has_asserting_example(&function.doc) {
                missing.push(format!("{module}::{}", function.name));
            }
        }
    }
    assert!(
        count > 80,
        "only {count} public functions found: is the source reader stale?"
    );
    assert!(
        missing.is_empty(),
        "{} has no `# Examples` section with an assertion in its doc comment ({} of {count} public \
         functions lack one: {})",
        missing[0],
        missing.len(),
        missing.join(", ")
    );
}

#[test]
fn the_reader_finds_functions_methods_and_examples() {
    let source = "\
/// Doc.
///
/// # Examples
///
/// ```
/// assert_eq!(1 + 1, 2);
/// ```
#[inline]
pub fn shown() {}

/// No example.
pub fn hidden() {}

impl Thing {
    /// # Examples
    ///
    /// Prose only.
    pub const fn new() -> Self {}
}
";
    let functions = documented_functions(source);
    let summary: Vec<(&str, bool)> = functions
        .iter()
        .map(|function| (function.name.as_str(), has_asserting_example(&function.doc)))
        .collect();
    assert_eq!(
        summary,
        [("shown", true), ("hidden", false), ("Thing::new", false)]
    );
}
