//! The structs and functions a source declares at its top level, in order, read from its lines:
//! what the tests compare that hold one concept written in several languages (GLSL, HLSL, Slang,
//! WGSL, Rust) to the same declarations in the same order, so that the files read side by side.
//!
//! ```
//! use shader_proptest::declarations::{declarations, Declaration};
//!
//! let glsl = "struct Hit {\n    float t;\n};\n\n// The hit's distance.\nfloat hit_distance(Hit hit) {\n    return hit.t;\n}\n";
//! let rust = "pub struct Hit {\n    pub t: f32,\n}\n\npub fn hit_distance(hit: Hit) -> f32 {\n    hit.t\n}\n";
//! let expected = [Declaration::Struct("Hit"), Declaration::Function("hit_distance")];
//! assert_eq!(declarations(glsl), expected);
//! assert_eq!(declarations(rust), expected);
//! ```

/// One top-level declaration, by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Declaration<'a> {
    /// A struct: the word after `struct`.
    Struct(&'a str),
    /// A function: the word before the first `(` of its declaration's line.
    Function(&'a str),
}

impl<'a> Declaration<'a> {
    /// The declared name.
    pub fn name(self) -> &'a str {
        match self {
            Declaration::Struct(name) | Declaration::Function(name) => name,
        }
    }
}

/// The structs and functions declared at the top level of `source`, in order. A top-level line
/// starts at its first column and is not a comment (`/`), an attribute or a preprocessor line
/// (`#`); one with the word `struct` declares a struct, any other with a `(` a function.
pub fn declarations(source: &str) -> Vec<Declaration<'_>> {
    source
        .lines()
        .filter(|line| !line.starts_with(|c: char| c.is_whitespace() || c == '/' || c == '#'))
        .filter_map(declaration)
        .collect()
}

/// What the top-level `line` declares, if anything.
fn declaration(line: &str) -> Option<Declaration<'_>> {
    let mut words = line.split_whitespace();
    if words.any(|word| word == "struct") {
        return words
            .next()
            .map(|name| Declaration::Struct(name.trim_end_matches('{')));
    }
    let (head, _) = line.split_once('(')?;
    head.split_whitespace().last().map(Declaration::Function)
}
