//! Each concept is one WGSL file, one GLSL file, one Slang file, one HLSL file and one Rust module
//! with the same functions and constants in the same order: the shader names are the Rust names
//! prefixed `rf_` / `RF_`. The four shader files also declare the same structs in the same order. Section banners
//! (`// ---- Title ----` lines) count as names, so each file has the same sections around the same
//! functions.

use ray_footprint::shaders::Module;
use shader_proptest::declarations::{declarations, Declaration};

/// The functions, constants and section banners of a shader module or a Rust module, in order, as
/// the Rust names: the functions and constants without their `rf_` / `RF_` prefixes, the banners
/// as `// ---- Title ----`. A shader module's functions are those prefixed `rf_` (a module may
/// keep helpers of its own); a Rust module's are all its top-level functions, public or not.
fn names(source: &str, is_shader: bool) -> Vec<String> {
    declarations(source)
        .into_iter()
        .filter_map(|declaration| match declaration {
            Declaration::Section(title) => Some(format!("// ---- {title} ----")),
            Declaration::Function(name) if is_shader => name.strip_prefix("rf_").map(str::to_string),
            Declaration::Function(name) => Some(name.to_string()),
            Declaration::Constant(name) => Some(name.trim_start_matches("RF_").to_string()),
            Declaration::Struct(_) => None,
        })
        .collect()
}

/// Structs declared at the top level of a shader module, in order.
fn struct_names(source: &str) -> Vec<&str> {
    declarations(source)
        .into_iter()
        .filter_map(|declaration| match declaration {
            Declaration::Struct(name) => Some(name),
            _ => None,
        })
        .collect()
}

fn rust_source(module: Module) -> String {
    let path = format!("{}/src/{}.rs", env!("CARGO_MANIFEST_DIR"), module.stem());
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

#[test]
fn every_module_declares_the_same_names_in_the_same_order() {
    for &module in Module::ALL {
        let rust = names(&rust_source(module), false);
        let wgsl = names(module.wgsl(), true);
        let glsl = names(module.glsl(), true);
        let slang = names(module.slang(), true);
        let hlsl = names(module.hlsl(), true);
        assert_eq!(wgsl, rust, "{}: WGSL and Rust differ", module.stem());
        assert_eq!(glsl, rust, "{}: GLSL and Rust differ", module.stem());
        assert_eq!(slang, rust, "{}: Slang and Rust differ", module.stem());
        assert_eq!(hlsl, rust, "{}: HLSL and Rust differ", module.stem());
        println!(
            "{}: {} names agree: {}",
            module.stem(),
            rust.len(),
            rust.join(" ")
        );
    }
}

#[test]
fn every_shader_module_declares_the_same_structs_in_the_same_order() {
    for &module in Module::ALL {
        let wgsl = struct_names(module.wgsl());
        assert_eq!(
            struct_names(module.glsl()),
            wgsl,
            "{}: GLSL and WGSL differ",
            module.stem()
        );
        assert_eq!(
            struct_names(module.slang()),
            wgsl,
            "{}: Slang and WGSL differ",
            module.stem()
        );
        assert_eq!(
            struct_names(module.hlsl()),
            wgsl,
            "{}: HLSL and WGSL differ",
            module.stem()
        );
        println!(
            "{}: {} structs agree: {}",
            module.stem(),
            wgsl.len(),
            wgsl.join(" ")
        );
    }
}

#[test]
fn slang_modules_have_an_include_guard_and_no_entry_point_or_module_declaration() {
    for &module in Module::ALL {
        let forbidden = ["[shader(", "[numthreads(", "\nmodule ", "\nimplementing "];
        assert_includable(module, "SLANG", module.slang(), &forbidden);
    }
}

/// Slang's own syntax, and matrix swizzles, which glslang's HLSL front end compiles into nothing
/// (it prints "Missing functionality: matrix swizzle" and succeeds).
const NOT_HLSL: &[&str] = &[
    "public ",
    "import ",
    "__init",
    "__generic",
    "[shader(",
    "[numthreads(",
    "._m",
];

/// Functions an HLSL module must not call: HLSL 2021's `select`, `and` and `or`, which glslang's
/// HLSL front end lacks, and GLSL's or Slang's names for `f32tof16` / `f16tof32`.
const NOT_PORTABLE_HLSL_CALLS: &[&str] = &[
    "select",
    "and",
    "or",
    "packHalf2x16",
    "unpackHalf2x16",
    "unpackHalf2x16ToFloat",
];

#[test]
fn hlsl_modules_are_includable_plain_hlsl() {
    for &module in Module::ALL {
        let code: Vec<&str> = module
            .hlsl()
            .lines()
            .filter(|line| !line.trim_start().starts_with("//"))
            .collect();
        assert_includable(module, "HLSL", &code.join("\n"), NOT_HLSL);
        for line in portable_lines(&code) {
            for name in NOT_PORTABLE_HLSL_CALLS {
                assert!(
                    calls(line, name).next().is_none(),
                    "{}: `{line}` calls {name}, which not every HLSL compiler has",
                    module.stem()
                );
            }
            for vector in ["float2", "float3", "float4", "double2", "double3", "double4"] {
                assert!(
                    !calls(line, vector).any(is_scalar_argument),
                    "{}: `{line}` builds a vector from one scalar, which DXC rejects; write a cast",
                    module.stem()
                );
            }
        }
    }
}

/// The lines every HLSL compiler reads: without the branches under `#ifdef __SLANG__`, which
/// only slangc compiles (up to their `#else` or `#endif`).
fn portable_lines<'a>(code: &[&'a str]) -> Vec<&'a str> {
    let mut slang_only = false;
    let mut lines = Vec::new();
    for &line in code {
        match line.trim() {
            "#ifdef __SLANG__" => slang_only = true,
            "#else" | "#endif" => slang_only = false,
            _ if !slang_only => lines.push(line),
            _ => {}
        }
    }
    lines
}

/// The text after `name(` at each call of the function `name` in `line` (not of a name ending in
/// it).
fn calls<'a>(line: &'a str, name: &str) -> impl Iterator<Item = &'a str> {
    let call = format!("{name}(");
    let skip = call.len();
    let starts: Vec<usize> = line.match_indices(&call).map(|(at, _)| at).collect();
    starts
        .into_iter()
        .filter(move |&at| {
            !line[..at]
                .chars()
                .next_back()
                .is_some_and(|c| c.is_alphanumeric() || c == '_')
        })
        .map(move |at| &line[at + skip..])
}

/// Whether a call's arguments (the text after its `(`, up to the `)` that closes it) are one
/// argument that starts as a scalar does: a number or an `RF_` constant.
fn is_scalar_argument(arguments: &str) -> bool {
    let mut depth = 0usize;
    let mut end = arguments.len();
    let mut several = false;
    for (at, c) in arguments.char_indices() {
        match c {
            '(' => depth += 1,
            ')' if depth == 0 => {
                end = at;
                break;
            }
            ')' => depth -= 1,
            ',' if depth == 0 => several = true,
            _ => {}
        }
    }
    let argument = arguments[..end].trim();
    !several
        && (argument.starts_with("RF_") || argument.starts_with(|c: char| c.is_ascii_digit() || c == '-'))
}

/// Every `?:` of the GLSL and Slang modules chooses between named values: an identifier, a
/// literal, an `RF_` constant (negated or not) or a vector of literals. Both languages evaluate
/// only the operand a scalar `?:` picks, so an operand written as an expression (`-x`, `a * b`,
/// `v.x`, a call, another `?:`) compiles to a branch around it, where a choice between values
/// already computed is an `OpSelect`. The HLSL modules' lines are the Slang modules' but for the
/// `#else` of an `#ifdef __SLANG__`, where `rf_edge_ramp` chooses per component (glslang, which
/// has no `select`, makes selects of them).
#[test]
fn every_choice_is_between_named_values() {
    for &module in Module::ALL {
        for (language, source) in [("GLSL", module.glsl()), ("Slang", module.slang())] {
            for line in source.lines() {
                let code = line.split("//").next().unwrap_or_default();
                for operand in choices(code)
                    .into_iter()
                    .flat_map(|(then, otherwise)| [then, otherwise])
                {
                    assert!(
                        is_named_value(operand),
                        "{} ({language}): `{}` chooses `{operand}`, an expression: name it first",
                        module.stem(),
                        line.trim()
                    );
                }
            }
        }
    }
}

/// The two operands of each `c ? a : b` in `code`.
fn choices(code: &str) -> Vec<(&str, &str)> {
    let mut found = Vec::new();
    for (at, _) in code.match_indices('?') {
        let rest = &code[at + 1..];
        let Some(colon) = operand_end(rest, ':') else {
            continue;
        };
        let otherwise = &rest[colon + 1..];
        let end = operand_end(otherwise, ';').unwrap_or(otherwise.len());
        found.push((rest[..colon].trim(), otherwise[..end].trim()));
    }
    found
}

/// Where the operand that starts `text` ends: at the first `stop` or `,` outside brackets, or at
/// a bracket that closes one opened before `text`.
fn operand_end(text: &str, stop: char) -> Option<usize> {
    let mut depth = 0usize;
    for (at, c) in text.char_indices() {
        match c {
            '(' | '{' => depth += 1,
            ')' | '}' if depth == 0 => return Some(at),
            ')' | '}' => depth -= 1,
            _ if depth == 0 && (c == stop || c == ',') => return Some(at),
            _ => {}
        }
    }
    None
}

/// Whether `operand` names a value: an identifier, a number, an `RF_` constant or a number with
/// a minus sign, or a vector of numbers (`float2(0.0, 1.0)`, `(float3)1.0`).
fn is_named_value(operand: &str) -> bool {
    let is_identifier = |text: &str| {
        text.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
            && text.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
    };
    let is_number = |text: &str| text.parse::<f64>().is_ok();
    let negated = operand.strip_prefix('-');
    let vector = operand
        .trim_start_matches('(')
        .split_once(['(', ')'])
        .filter(|(ty, _)| {
            ["float", "vec", "double", "dvec"]
                .iter()
                .any(|prefix| ty.starts_with(prefix))
        })
        .is_some_and(|(_, values)| values.chars().all(|c| c.is_ascii_digit() || ".,-e )".contains(c)));
    is_identifier(operand)
        || is_number(operand)
        || negated.is_some_and(|name| name.starts_with("RF_") && is_identifier(name))
        || vector
}

#[test]
fn glsl_modules_have_an_include_guard_and_no_version_or_main() {
    for &module in Module::ALL {
        assert_includable(module, "GLSL", module.glsl(), &["#version", "void main"]);
        assert!(
            !module.wgsl().contains('@'),
            "{}: a WGSL module must not declare entry points or bindings",
            module.stem()
        );
    }
}

/// `source`, `module` in `language` (upper case), has the include guard
/// `RAY_FOOTPRINT_<MODULE>_<LANGUAGE>` and none of the texts in `forbidden` (a module must work
/// under `#include`).
fn assert_includable(module: Module, language: &str, source: &str, forbidden: &[&str]) {
    let guard = format!(
        "#ifndef RAY_FOOTPRINT_{}_{language}",
        module.stem().to_uppercase()
    );
    assert!(source.contains(&guard), "{}: missing `{guard}`", module.stem());
    for text in forbidden {
        assert!(
            !source.contains(text),
            "{}: a {language} module must not contain {text:?} (it must work under #include)",
            module.stem()
        );
    }
}
