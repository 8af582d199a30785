//! The Slang modules, written from the HLSL modules (after their generated blocks are filled), so
//! that each function is written once for both languages. Slang reads HLSL; what a Slang user
//! needs besides is made by a few rules over the HLSL text:
//!
//! - the header: a first line naming the HLSL file and the command, then the HLSL header with its
//!   paragraph on how to bring the module in (the one that starts [`HLSL_PARAGRAPH`]) replaced by
//!   Slang's (`import` or `#include`);
//! - the include guard `RAY_FOOTPRINT_<STEM>_HLSL` becomes `RAY_FOOTPRINT_<STEM>_SLANG`;
//! - the markers of the generated blocks are left out (the whole file is generated);
//! - of an `#ifdef __SLANG__` ... `#else` ... `#endif`, the lines for Slang are kept, without the
//!   directives;
//! - each top-level declaration named with the crate's prefixes (`rf_`, `Rf`, `RF_`), and each
//!   field of such a struct, is `public`, so that `import` sees it; other top-level helpers stay
//!   internal to the module;
//! - the comment right above a `public` declaration becomes a doc comment (`///`).

use crate::{blocks, COMMAND};

/// How the paragraph of an HLSL module's header that says how to bring it in starts.
const HLSL_PARAGRAPH: &str = "// HLSL 2021 library module";

/// The prefixes of the names of the modules' functions, structs and constants.
const PUBLIC_PREFIXES: [&str; 3] = ["rf_", "Rf", "RF_"];

/// The Slang module `stem` from the text of its HLSL module.
pub fn from_hlsl(stem: &str, hlsl: &str) -> Result<String, String> {
    let at = |error: String| format!("shaders/hlsl/{stem}.hlsl: {error}");
    let hlsl_guard = guard(stem, "HLSL");
    let lines: Vec<&str> = hlsl.lines().collect();
    let body_start = lines
        .iter()
        .position(|line| *line == format!("#ifndef {hlsl_guard}"))
        .ok_or_else(|| at(format!("no include guard `#ifndef {hlsl_guard}`")))?;
    let mut slang = header(stem, &lines[..body_start]).map_err(at)?;
    let body = slang_branches(&without_block_markers(&lines[body_start..])).map_err(at)?;
    slang.extend(public_declarations(&body).map_err(at)?);
    let text = slang.join("\n") + "\n";
    Ok(text.replace(&hlsl_guard, &guard(stem, "SLANG")))
}

/// The include guard of module `stem` in `language` (upper case).
fn guard(stem: &str, language: &str) -> String {
    format!("RAY_FOOTPRINT_{}_{language}", stem.to_uppercase())
}

/// The Slang header: the line that says where the file comes from, then the HLSL header's
/// paragraphs with the HLSL paragraph replaced by Slang's.
fn header(stem: &str, hlsl_header: &[&str]) -> Result<Vec<String>, String> {
    let replaced = hlsl_header
        .iter()
        .position(|line| line.starts_with(HLSL_PARAGRAPH))
        .ok_or_else(|| format!("no header paragraph starting `{HLSL_PARAGRAPH}`"))?;
    let paragraph_end = hlsl_header[replaced..]
        .iter()
        .position(|line| line.trim_end() == "//" || line.is_empty())
        .map_or(hlsl_header.len(), |length| replaced + length);
    let mut lines = vec![
        format!(
            "// Generated from shaders/hlsl/{stem}.hlsl by `{COMMAND}`: edit the HLSL file, not this one."
        ),
        "//".to_string(),
    ];
    lines.extend(hlsl_header[..replaced].iter().map(|line| line.to_string()));
    lines.extend(slang_paragraph(stem));
    lines.extend(hlsl_header[paragraph_end..].iter().map(|line| line.to_string()));
    Ok(lines)
}

/// How a Slang user brings module `stem` in.
fn slang_paragraph(stem: &str) -> [String; 4] {
    [
        "// Slang library module without entry points or resource bindings. Bring it in one way per program:"
            .to_string(),
        format!("//   import {stem};              // as a module, with this directory on the search path (-I)"),
        format!("//   #include \"{stem}.slang\"     // textually; the include guard makes a second include a no-op"),
        "// Every rf_ function, Rf struct (and its fields) and RF_ constant is `public`.".to_string(),
    ]
}

/// `lines` without the begin and end markers of generated blocks.
fn without_block_markers<'a>(lines: &[&'a str]) -> Vec<&'a str> {
    lines
        .iter()
        .filter(|line| !blocks::is_marker(line))
        .copied()
        .collect()
}

/// `lines` with each `#ifdef __SLANG__` block reduced to its lines for Slang: those before its
/// `#else`, or before its `#endif` where it has none.
fn slang_branches<'a>(lines: &[&'a str]) -> Result<Vec<&'a str>, String> {
    let mut kept = Vec::new();
    let mut branch = None;
    for &line in lines {
        match (line.trim(), branch) {
            ("#ifdef __SLANG__", None) => branch = Some(true),
            ("#else", Some(true)) => branch = Some(false),
            ("#endif", Some(_)) => branch = None,
            (directive, Some(_)) if directive.starts_with("#if") => {
                return Err(format!("`{directive}` inside `#ifdef __SLANG__`"));
            }
            (_, None | Some(true)) => kept.push(line),
            (_, Some(false)) => {}
        }
    }
    match branch {
        Some(_) => Err("`#ifdef __SLANG__` without `#endif`".to_string()),
        None => Ok(kept),
    }
}

/// `lines` with `public` before each top-level declaration named with a public prefix and each
/// field of such a struct, and the comments right above them turned into doc comments.
fn public_declarations(lines: &[&str]) -> Result<Vec<String>, String> {
    let mut out: Vec<String> = Vec::new();
    let mut depth = 0usize;
    let mut in_public_struct = false;
    for &line in lines {
        let indent = &line[..line.len() - line.trim_start().len()];
        let starts_a_declaration = line.trim_start().starts_with(|c: char| c.is_ascii_alphabetic());
        if depth == 0 && starts_a_declaration {
            let name = declared_name(line).ok_or_else(|| format!("no declared name in `{line}`"))?;
            let public = PUBLIC_PREFIXES.iter().any(|prefix| name.starts_with(prefix));
            in_public_struct = public && line.starts_with("struct ");
            if public {
                as_doc_comments(&mut out, indent);
                out.push(format!("public {line}"));
            } else {
                out.push(line.to_string());
            }
        } else if depth == 1 && in_public_struct && starts_a_declaration {
            as_doc_comments(&mut out, indent);
            out.push(format!("{indent}public {}", line.trim_start()));
        } else {
            out.push(line.to_string());
        }
        depth = depth_after(depth, line).ok_or_else(|| format!("`{line}` closes a brace never opened"))?;
    }
    Ok(out)
}

/// The name a top-level declaration's first line declares: the last word before its first `(`
/// (a function), `=` (a constant) or `{` (a struct).
fn declared_name(line: &str) -> Option<&str> {
    let head = line.split(['(', '=', '{']).next()?;
    head.split_whitespace().last()
}

/// The brace depth after `line` (its code, not its comment) from `depth`; `None` where it closes
/// more than is open.
fn depth_after(depth: usize, line: &str) -> Option<usize> {
    let code = line.split("//").next().unwrap_or_default();
    let opened = code.matches('{').count();
    let closed = code.matches('}').count();
    (depth + opened).checked_sub(closed)
}

/// The `//` comment lines at the end of `out` with indentation `indent`, as `///` lines.
fn as_doc_comments(out: &mut [String], indent: &str) {
    let comment = format!("{indent}//");
    for line in out.iter_mut().rev() {
        match line.strip_prefix(&comment) {
            Some(text) if !text.starts_with('/') => *line = format!("{indent}///{text}"),
            _ => break,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small HLSL module with every construct the rules touch.
    const HLSL: &str = "\
// ray-footprint: a test module.
//
// HLSL 2021 library module without entry points or resources: #include \"demo.hlsl\".
// Compiles with glslang's HLSL front end.
//
// Conventions.

#ifndef RAY_FOOTPRINT_DEMO_HLSL
#define RAY_FOOTPRINT_DEMO_HLSL

// generated by `cargo xtask codegen` from src/demo.rs: do not edit
// A constant.
static const float RF_LIMIT = 1.0;

// A struct.
struct RfPair {
    // The first.
    float first;
    float second;
};
// end of generated code

// ---- Section ----

// A helper of the module.
float demo_square(float x) {
    return x * x;
}

// A function.
RfPair rf_pair(float x,
    float y) {
#ifdef __SLANG__
    // For Slang.
    float z = select(x > 0.0, x, y);
#else
    float z = x > 0.0 ? x : y;
#endif
    RfPair pair = { demo_square(z), y };
    return pair;
}

#endif // RAY_FOOTPRINT_DEMO_HLSL
";

    const SLANG: &str = "\
// Generated from shaders/hlsl/demo.hlsl by `cargo xtask codegen`: edit the HLSL file, not this one.
//
// ray-footprint: a test module.
//
// Slang library module without entry points or resource bindings. Bring it in one way per program:
//   import demo;              // as a module, with this directory on the search path (-I)
//   #include \"demo.slang\"     // textually; the include guard makes a second include a no-op
// Every rf_ function, Rf struct (and its fields) and RF_ constant is `public`.
//
// Conventions.

#ifndef RAY_FOOTPRINT_DEMO_SLANG
#define RAY_FOOTPRINT_DEMO_SLANG

/// A constant.
public static const float RF_LIMIT = 1.0;

/// A struct.
public struct RfPair {
    /// The first.
    public float first;
    public float second;
};

// ---- Section ----

// A helper of the module.
float demo_square(float x) {
    return x * x;
}

/// A function.
public RfPair rf_pair(float x,
    float y) {
    // For Slang.
    float z = select(x > 0.0, x, y);
    RfPair pair = { demo_square(z), y };
    return pair;
}

#endif // RAY_FOOTPRINT_DEMO_SLANG
";

    #[test]
    fn a_module_follows_every_rule() {
        assert_eq!(from_hlsl("demo", HLSL), Ok(SLANG.to_string()));
    }

    #[test]
    fn a_module_without_its_guard_or_hlsl_paragraph_is_refused() {
        let unguarded = HLSL.replace("DEMO_HLSL", "OTHER_HLSL");
        assert!(from_hlsl("demo", &unguarded)
            .unwrap_err()
            .contains("no include guard"));
        let unexplained = HLSL.replace(HLSL_PARAGRAPH, "// A library module");
        assert!(from_hlsl("demo", &unexplained)
            .unwrap_err()
            .contains("no header paragraph"));
    }

    #[test]
    fn only_the_slang_branch_is_kept() {
        let lines = [
            "a",
            "#ifdef __SLANG__",
            "b",
            "#else",
            "c",
            "#endif",
            "#ifdef __SLANG__",
            "d",
            "#endif",
        ];
        assert_eq!(slang_branches(&lines), Ok(vec!["a", "b", "d"]));
        assert!(slang_branches(&["#ifdef __SLANG__", "#if X", "#endif"]).is_err());
        assert!(slang_branches(&["#ifdef __SLANG__", "b"]).is_err());
    }

    #[test]
    fn the_declared_name_comes_before_the_first_parenthesis_equals_or_brace() {
        assert_eq!(
            declared_name("float3 rf_edge_ramp(float3 x) {"),
            Some("rf_edge_ramp")
        );
        assert_eq!(
            declared_name("static const RfPair RF_PAIR = { 1.0, float2(2.0) };"),
            Some("RF_PAIR")
        );
        assert_eq!(declared_name("struct RfPair {"), Some("RfPair"));
        assert_eq!(declared_name("("), None);
    }

    #[test]
    fn only_prefixed_declarations_and_their_fields_become_public() {
        let lines = [
            "// The pair.",
            "struct RfPair {",
            "    float first;",
            "};",
            "struct Helper {",
            "    float first;",
            "};",
            "RfPair rf_pair() {",
            "    RfPair pair = {",
            "        1.0, 2.0 };",
            "    return pair;",
            "}",
        ];
        let expected = [
            "/// The pair.",
            "public struct RfPair {",
            "    public float first;",
            "};",
            "struct Helper {",
            "    float first;",
            "};",
            "public RfPair rf_pair() {",
            "    RfPair pair = {",
            "        1.0, 2.0 };",
            "    return pair;",
            "}",
        ];
        assert_eq!(
            public_declarations(&lines),
            Ok(expected.map(String::from).to_vec())
        );
        assert!(public_declarations(&["}"]).is_err());
    }

    #[test]
    fn doc_comments_stop_at_the_first_other_line() {
        let mut out = ["// A banner.", "", "// Its comment,", "// two lines."].map(String::from);
        as_doc_comments(&mut out, "");
        assert_eq!(out, ["// A banner.", "", "/// Its comment,", "/// two lines."]);
    }
}
