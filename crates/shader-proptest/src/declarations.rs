//! The structs, functions, constants and section banners a source declares at its top level, in
//! order, read from its lines: what the tests compare that hold one concept written in several
//! languages (GLSL, HLSL, Slang, WGSL, Rust) to the same declarations in the same order, so that
//! the files read side by side.
//!
//! ```
//! use shader_proptest::declarations::{declarations, Declaration};
//!
//! let glsl = "// ---- Hits ----\n\nconst float MAX_T = 1e30;\n\nstruct Hit {\n    float t;\n};\n\n// The hit's distance.\nfloat hit_distance(Hit hit) {\n    return hit.t;\n}\n";
//! let rust = "// ---- Hits ----\n\npub const MAX_T: f32 = 1e30;\n\npub struct Hit {\n    pub t: f32,\n}\n\npub fn hit_distance(hit: Hit) -> f32 {\n    hit.t\n}\n";
//! let expected = [
//!     Declaration::Section("Hits"),
//!     Declaration::Constant("MAX_T"),
//!     Declaration::Struct("Hit"),
//!     Declaration::Function("hit_distance"),
//! ];
//! assert_eq!(declarations(glsl), expected);
//! assert_eq!(declarations(rust), expected);
//! ```

/// One top-level declaration, by name, or a section banner, by title.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Declaration<'a> {
    /// A section banner, a comment line `// ---- Title ----`: its title.
    Section(&'a str),
    /// A struct: the word after `struct`.
    Struct(&'a str),
    /// A function: the word after `fn`, or else the word before the first `(`.
    Function(&'a str),
    /// A named constant: the last word before its `=`, or before the `:` of its type.
    Constant(&'a str),
}

impl<'a> Declaration<'a> {
    /// The declared name, or the section's title.
    pub fn name(self) -> &'a str {
        match self {
            Declaration::Section(name)
            | Declaration::Struct(name)
            | Declaration::Function(name)
            | Declaration::Constant(name) => name,
        }
    }
}

/// The declarations at the top level of `source`, in order. A top-level line starts at its first
/// column and is not a comment (`/`) other than a section banner, an attribute (`#`, `@`, `[`), a
/// preprocessor line (`#`) or the end of something (`)`, `}`). Of those, one with the word `fn`
/// declares a function; one with the word `struct` a struct; one with the word `const` before its
/// first `=` or `(` a constant (but `const _`, which names nothing); and any other with a type and
/// a name before its first `(` (and no `=` there) a function.
pub fn declarations(source: &str) -> Vec<Declaration<'_>> {
    source.lines().filter_map(declaration).collect()
}

/// What the `line` declares, if anything.
fn declaration(line: &str) -> Option<Declaration<'_>> {
    if let Some(title) = section(line) {
        return Some(Declaration::Section(title));
    }
    if line.starts_with(|c: char| c.is_whitespace() || "/#@[)}".contains(c)) {
        return None;
    }
    let words: Vec<&str> = line
        .split(|c: char| !(c.is_alphanumeric() || c == '_'))
        .filter(|word| !word.is_empty())
        .collect();
    let word_after = |keyword: &str| {
        let at = words.iter().position(|word| *word == keyword)?;
        words.get(at + 1).copied()
    };
    if let Some(name) = word_after("fn") {
        return Some(Declaration::Function(name));
    }
    if let Some(name) = word_after("struct") {
        return Some(Declaration::Struct(name));
    }
    let head = line.split(['(', '=']).next().unwrap_or_default();
    if head.split_whitespace().any(|word| word == "const") {
        let before_type = head.split(':').next().unwrap_or_default();
        let name = before_type.split_whitespace().last()?;
        return (name != "_").then_some(Declaration::Constant(name));
    }
    let (before_call, _) = line.split_once('(')?;
    match before_call.split_whitespace().collect::<Vec<_>>().as_slice() {
        [.., _, name] if !before_call.contains('=') => Some(Declaration::Function(name)),
        _ => None,
    }
}

/// The title of a section banner line, `// ---- Title ----`.
fn section(line: &str) -> Option<&str> {
    line.strip_prefix("// ---- ")?.strip_suffix(" ----")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn functions_are_read_in_every_language() {
        for line in [
            "fn rf_width(cone: RfRayCone) -> f32 {",
            "pub fn width(cone: RayCone) -> f32 {",
            "pub(crate) fn width(cone: RayCone) -> f32 {",
            "pub const fn width(cone: RayCone) -> f32 {",
            "float width(RfRayCone cone) {",
            "public float width(RfRayCone cone) {",
            "RfRayCone width(float a,",
            "float width(const float a) {",
        ] {
            let expected = if line.contains("rf_") { "rf_width" } else { "width" };
            assert_eq!(declaration(line), Some(Declaration::Function(expected)), "{line}");
        }
    }

    #[test]
    fn constants_are_read_in_every_language() {
        for line in [
            "const RF_MIN_COS: f32 = 1e-4;",
            "pub const RF_MIN_COS: f32 = 1e-4;",
            "const float RF_MIN_COS = 1e-4;",
            "static const float RF_MIN_COS = 1e-4;",
            "public static const float RF_MIN_COS = 1e-4;",
            "static const RfSettings RF_MIN_COS = { float2(1.0, 1.0), true };",
            "const RF_MIN_COS: RfSettings = RfSettings(vec2<f32>(1.0, 1.0), true);",
        ] {
            assert_eq!(
                declaration(line),
                Some(Declaration::Constant("RF_MIN_COS")),
                "{line}"
            );
        }
        assert_eq!(declaration("const _: () = assert!(size_of::<Io>() == 32);"), None);
    }

    #[test]
    fn structs_and_sections_are_read() {
        assert_eq!(
            declaration("pub struct RayCone {"),
            Some(Declaration::Struct("RayCone"))
        );
        assert_eq!(
            declaration("public struct RfRayCone {"),
            Some(Declaration::Struct("RfRayCone"))
        );
        assert_eq!(
            declaration("struct Hit { float t; };"),
            Some(Declaration::Struct("Hit"))
        );
        assert_eq!(
            declaration("// ---- Packing ----"),
            Some(Declaration::Section("Packing"))
        );
    }

    #[test]
    fn other_lines_declare_nothing() {
        for line in [
            "    float t;",
            "// A comment (with parentheses).",
            "#define LIMIT (2)",
            "#[derive(Clone, Copy)]",
            "@compute @workgroup_size(64)",
            "[numthreads(64, 1, 1)]",
            ") -> (f32, f32) {",
            "}",
            "use glam::{Vec2, Vec3};",
            "impl Default for Settings {",
            "layout(set = 0, binding = 0) buffer Values { float values[]; };",
            "mod tests {",
            "vec3 origin = vec3(0.0);",
            "",
        ] {
            assert_eq!(declaration(line), None, "{line}");
        }
    }
}
