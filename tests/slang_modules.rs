//! Every Slang module compiles with the Slang compiler (`slangc`, installed by `scripts/setup.sh`):
//! as a whole module, and every function in SPIR-V that `spirv-val` accepts, reached both through
//! `import` and through `#include`; and the Slang closest-hit shader of the ray-tracing renderer. A
//! missing compiler fails these tests; they never skip.

#[path = "common/slangc.rs"]
mod slangc;

use ray_footprint::shaders::{Module, SLANG_INCLUDE_DIR};

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
                    parameter
                        .split_whitespace()
                        .next()
                        .expect("a typed parameter")
                        .to_string()
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
        let arguments: Vec<String> = (0..function.parameters.len())
            .map(|position| {
                let ty = &function.parameters[position];
                format!("inputs.Load<{ty}>({})", base + 64 * position)
            })
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

/// The ways a user brings a module in: as a module, or pasted twice (the include guard must hold).
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
fn every_module_compiles_as_a_whole_module() {
    for &module in Module::ALL {
        let source = format!("{SLANG_INCLUDE_DIR}/{}.slang", module.stem());
        let output = slangc::temp_path("slang-module");
        let result = slangc::run(
            slangc::SLANGC,
            &[
                "-warnings-as-errors",
                "all",
                &source,
                "-o",
                slangc::path_str(&output),
            ],
        );
        let _ = std::fs::remove_file(&output);
        result.unwrap_or_else(|log| panic!("{}: {log}", module.stem()));
        println!("{}: compiles as a Slang module", module.stem());
    }
}

#[test]
fn every_function_compiles_to_valid_spirv_through_import_and_include() {
    for &module in Module::ALL {
        let count = functions(module.slang()).len();
        assert!(count > 0, "{}: no public functions found", module.stem());
        for (how, preamble) in preambles(module) {
            let kernel = kernel_calling_every_function(module, &preamble);
            let spirv = slangc::compile(&kernel, "compute", "spirv_1_3")
                .unwrap_or_else(|log| panic!("{} ({how}): {log}", module.stem()));
            slangc::validate(&spirv, "vulkan1.1")
                .unwrap_or_else(|log| panic!("{} ({how}): {log}", module.stem()));
            println!(
                "{}: {count} functions through {how}: {} SPIR-V words, spirv-val accepts them",
                module.stem(),
                spirv.len()
            );
        }
    }
}

#[test]
fn a_missing_compiler_names_the_setup_script() {
    let error = slangc::run("ray-footprint-no-such-slangc", &["-v"]).expect_err("no such program");
    assert!(error.contains("scripts/setup.sh"), "{error}");
}

/// The Slang closest-hit shader of the ray-tracing renderer, which imports the modules, compiles to
/// SPIR-V 1.5 that spirv-val accepts for Vulkan 1.2.
#[test]
fn the_slang_closest_hit_shader_compiles_for_vulkan_1_2() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/crates/ray-footprint-lab/src/rt/shaders/closest_hit.slang"
    );
    let source = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let spirv = slangc::compile(&source, "closesthit", "spirv_1_5").unwrap_or_else(|log| panic!("{log}"));
    slangc::validate(&spirv, "vulkan1.2").unwrap_or_else(|log| panic!("{log}"));
    println!(
        "closest_hit.slang: {} SPIR-V words, spirv-val accepts them",
        spirv.len()
    );
}
