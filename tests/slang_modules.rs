//! Every public function of every Slang module compiles, through shader-proptest's Slang compiler
//! (slangc, installed by `scripts/setup.sh`), to SPIR-V that `spirv-val` accepts, whether the
//! module is brought in by `import` or pasted twice by `#include` (the include guard must hold).
//! The agreement suite runs the checked functions through `import` on the device; this covers the
//! helpers it reaches only indirectly, and the `#include` path. A missing compiler fails the test.

use ray_footprint::shaders::{Module, SLANG_INCLUDE_DIR};
use shader_proptest::compile::{compile_slang, Stage, Target};
use shader_proptest::spirv;
use std::path::Path;

/// A public function of a module: return type, name, parameter types.
struct Function {
    result: String,
    name: String,
    parameters: Vec<String>,
}

/// The `public` functions of a Slang module in order, read from their signatures (which may span
/// several lines and end with `{`).
fn functions(source: &str) -> Vec<Function> {
    let mut functions = Vec::new();
    let mut lines = source.lines();
    while let Some(line) = lines.next() {
        if !line.starts_with("public ") || !line.contains(" rf_") {
            continue;
        }
        let mut signature = line.to_string();
        while !signature.trim_end().ends_with('{') {
            signature.push_str(lines.next().expect("a signature ends with `{`"));
        }
        let (head, parameters) = signature.split_once('(').expect("a signature has `(`");
        let words: Vec<&str> = head.split_whitespace().collect();
        let parameters = parameters.rsplit_once(')').expect("a signature has `)`").0;
        functions.push(Function {
            result: words[words.len() - 2].to_string(),
            name: words[words.len() - 1].to_string(),
            parameters: parameters
                .split(',')
                .map(|parameter| {
                    let ty = parameter.split_whitespace().next();
                    ty.expect("a typed parameter").to_string()
                })
                .collect(),
        });
    }
    functions
}

/// A compute kernel that brings in `module` with `preamble` and calls each of its public functions
/// once, every argument read from an input buffer and every result written to an output buffer
/// (so nothing is folded away). Each call gets its own 1 KiB of both buffers.
fn kernel_calling_every_function(module: Module, preamble: &str) -> String {
    let mut calls = String::new();
    for (index, function) in functions(module.slang()).iter().enumerate() {
        let base = index * 1024;
        let arguments: Vec<String> = (function.parameters.iter().enumerate())
            .map(|(position, ty)| format!("inputs.Load<{ty}>({})", base + 64 * position))
            .collect();
        calls.push_str(&format!(
            "    outputs.Store<{}>({base}, {}({}));\n",
            function.result,
            function.name,
            arguments.join(", ")
        ));
    }
    format!(
        "{preamble}
ByteAddressBuffer inputs;
RWByteAddressBuffer outputs;

[shader(\"compute\")]
[numthreads(1, 1, 1)]
void main() {{
{calls}}}
"
    )
}

/// The ways a user brings a module in: as a module, or pasted twice.
fn preambles(module: Module) -> [(&'static str, String); 2] {
    let stem = module.stem();
    [
        ("import", format!("import {stem};")),
        (
            "#include",
            format!("#include \"{stem}.slang\"\n#include \"{stem}.slang\""),
        ),
    ]
}

#[test]
fn every_function_compiles_to_valid_spirv_through_import_and_include() {
    for &module in Module::ALL {
        let count = functions(module.slang()).len();
        assert!(count > 0, "{}: no public functions found", module.stem());
        for (how, preamble) in preambles(module) {
            let kernel = kernel_calling_every_function(module, &preamble);
            let spirv = compile_slang(
                &kernel,
                Stage::Compute,
                Target::Vulkan1_1,
                &[Path::new(SLANG_INCLUDE_DIR)],
            )
            .unwrap_or_else(|error| panic!("{} ({how}): {error}\n--- kernel ---\n{kernel}", module.stem()));
            spirv::validate(&spirv, Target::Vulkan1_1)
                .unwrap_or_else(|e| panic!("{} ({how}): {e}", module.stem()));
            println!(
                "{}: {count} functions through {how}: {} SPIR-V words, spirv-val accepts them",
                module.stem(),
                spirv.len()
            );
        }
    }
}
