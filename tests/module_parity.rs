//! Each concept is one WGSL file, one GLSL file, one Slang file, one HLSL file and one Rust module
//! with the same functions and constants in the same order: the shader names are the Rust names
//! prefixed `rf_` / `RF_`. The four shader files also declare the same structs in the same order. Section banners
//! (`// ---- Title ----` lines) count as names, so each file has the same sections around the same
//! functions.

use ray_footprint::shaders::Module;

/// A section banner line, `// ---- Title ----`, as it is.
fn banner(line: &str) -> Option<String> {
    (line.starts_with("// ---- ") && line.ends_with(" ----")).then(|| line.to_string())
}

/// Names declared at the top level, in order: functions and constants, without prefixes, and
/// section banners.
fn shader_names(source: &str, language: &str) -> Vec<String> {
    let mut names = Vec::new();
    for line in source.lines().filter(|line| !line.starts_with(' ')) {
        if let Some(banner) = banner(line) {
            names.push(banner);
            continue;
        }
        if line.starts_with("//") {
            continue;
        }
        let words: Vec<&str> = line
            .split(|c: char| c.is_whitespace() || c == '(' || c == ':')
            .collect();
        let name = match (language, words.as_slice()) {
            ("wgsl", ["fn", name, ..]) => name,
            ("wgsl", ["const", name, ..]) => name,
            ("glsl", ["const", _, name, ..]) => name,
            ("hlsl", ["static", "const", _, name, ..]) => name,
            ("glsl" | "hlsl", [_, name, ..]) if name.starts_with("rf_") && line.trim_end().ends_with('{') => {
                name
            }
            ("glsl" | "hlsl", [_, name, ..]) if name.starts_with("rf_") && line.ends_with(',') => name,
            ("slang", ["public", "static", "const", _, name, ..]) => name,
            ("slang", ["public", _, name, ..]) if name.starts_with("rf_") => name,
            _ => continue,
        };
        names.push(
            name.trim_start_matches("rf_")
                .trim_start_matches("RF_")
                .to_string(),
        );
    }
    names
}

/// Structs declared at the top level of a shader module, in order.
fn struct_names(source: &str) -> Vec<&str> {
    source
        .lines()
        .filter_map(|line| {
            let words: Vec<&str> = line.split_whitespace().collect();
            match words.as_slice() {
                ["struct", name, ..] | ["public", "struct", name, ..] => Some(*name),
                _ => None,
            }
        })
        .collect()
}

/// Functions (public or not), public constants and section banners of a Rust module, in order.
fn rust_names(source: &str) -> Vec<String> {
    let mut names = Vec::new();
    for line in source.lines() {
        if let Some(banner) = banner(line) {
            names.push(banner);
            continue;
        }
        let words: Vec<&str> = line
            .split(|c: char| c.is_whitespace() || c == '(' || c == ':' || c == '<')
            .collect();
        match words.as_slice() {
            ["pub", "fn", name, ..] | ["fn", name, ..] | ["pub", "const", name, ..] => {
                names.push(name.to_string())
            }
            _ => {}
        }
    }
    names
}

fn rust_source(module: Module) -> String {
    let path = format!("{}/src/{}.rs", env!("CARGO_MANIFEST_DIR"), module.stem());
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

#[test]
fn every_module_declares_the_same_names_in_the_same_order() {
    for &module in Module::ALL {
        let rust = rust_names(&rust_source(module));
        let wgsl = shader_names(module.wgsl(), "wgsl");
        let glsl = shader_names(module.glsl(), "glsl");
        let slang = shader_names(module.slang(), "slang");
        let hlsl = shader_names(module.hlsl(), "hlsl");
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
