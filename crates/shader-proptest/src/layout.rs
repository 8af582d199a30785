//! Struct layout verification: does a Rust struct have exactly the byte layout of a shader struct?
//!
//! The Rust side is described by [`rust_layout!`](crate::rust_layout) (offsets and sizes from
//! `offset_of!` and `size_of`). The shader side comes from naga's layout of a WGSL source
//! ([`wgsl_layout`]) or from the `Offset` and `ArrayStride` decorations of a struct in a storage
//! buffer under std430 or scalar rules, in the SPIR-V glslang writes for GLSL ([`glsl_layout`]) or
//! slangc writes for Slang ([`slang_layout`]). [`compare`] returns a field-by-field [`LayoutTable`],
//! or an error that names the struct and the field.
//!
//! ```no_run
//! use shader_proptest::{layout, rust_layout};
//!
//! #[repr(C)]
//! #[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
//! struct Push {
//!     tint: [f32; 4],
//!     exposure: f32,
//!     frame: u32,
//!     pad: [u32; 2],
//! }
//!
//! let wgsl = "struct Push { tint: vec4<f32>, exposure: f32, frame: u32, pad: vec2<u32> }";
//! let table = layout::compare(&rust_layout!(Push { tint, exposure, frame, pad }), &layout::wgsl_layout(wgsl, "Push")?)?;
//! println!("{table}");
//! # Ok::<(), layout::LayoutError>(())
//! ```

pub use crate::back::{glsl_layout, slang_layout, wgsl_layout};
use crate::compile::CompileError;
use std::fmt;

/// One field: name, byte offset and byte size.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FieldLayout {
    /// The field's name.
    pub name: String,
    /// Byte offset from the start of the struct.
    pub offset: u32,
    /// Byte size of the field's type.
    pub size: u32,
}

/// A struct's layout: its name (as the shader spells it), size, alignment and fields.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StructLayout {
    /// The struct's name in the shader.
    pub name: String,
    /// Size in bytes, tail padding included (the array stride).
    pub size: u32,
    /// Alignment in bytes (0 where the source does not say, as in SPIR-V).
    pub align: u32,
    /// Fields in declaration order.
    pub fields: Vec<FieldLayout>,
}

/// A table of the fields' offsets and sizes, then the struct's size and alignment:
///
/// ```text
/// RfRayCone        offset  size
///   width               0     4
///   spread_angle        4     4
///   (size)                    8  align 4
/// ```
impl fmt::Display for StructLayout {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let width = self
            .fields
            .iter()
            .map(|field| field.name.len())
            .chain([self.name.len().saturating_sub(2), 6])
            .max()
            .unwrap_or(0);
        writeln!(
            f,
            "{:<w$}  {:>6} {:>5}",
            self.name,
            "offset",
            "size",
            w = width + 2
        )?;
        for field in &self.fields {
            writeln!(
                f,
                "  {:<width$}  {:>6} {:>5}",
                field.name, field.offset, field.size
            )?;
        }
        write!(f, "  {:<width$}  {:>6} {:>5}", "(size)", "", self.size)?;
        if self.align > 0 {
            write!(f, "  align {}", self.align)?;
        }
        Ok(())
    }
}

/// GLSL block packing rules; Slang's buffers take the same three (`Std140DataLayout`,
/// `Std430DataLayout`, `ScalarDataLayout`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GlslPacking {
    /// `std140`, the default of uniform blocks.
    Std140,
    /// `std430`, the default of push constants and storage buffers.
    Std430,
    /// `scalar` (GL_EXT_scalar_block_layout), as Slang-generated Vulkan code uses.
    Scalar,
}

impl GlslPacking {
    /// The layout qualifier: `std140`, `std430` or `scalar`.
    pub fn qualifier(self) -> &'static str {
        match self {
            GlslPacking::Std140 => "std140",
            GlslPacking::Std430 => "std430",
            GlslPacking::Scalar => "scalar",
        }
    }

    /// Slang's data layout type: `Std140DataLayout`, `Std430DataLayout` or `ScalarDataLayout`.
    pub fn slang_layout(self) -> &'static str {
        match self {
            GlslPacking::Std140 => "Std140DataLayout",
            GlslPacking::Std430 => "Std430DataLayout",
            GlslPacking::Scalar => "ScalarDataLayout",
        }
    }
}

/// Why a layout could not be read, or does not match.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LayoutError {
    /// The shader source does not parse or compile; the message is the compiler's.
    Source(String),
    /// No struct of that name in the source.
    StructNotFound(String),
    /// A field is declared on one side only.
    MissingField {
        /// The struct's name.
        structure: String,
        /// The field's name.
        field: String,
        /// `"Rust"` or `"shader"`: the side that lacks the field.
        missing_in: &'static str,
    },
    /// A Rust field takes one byte, as a `bool` does: no shader type does, and a shader `bool`
    /// has no layout a Rust `bool` can match.
    OneByteField {
        /// The struct's name.
        structure: String,
        /// The field's name.
        field: String,
    },
    /// A WGSL struct holds a `bool`, which WGSL forbids in host-shareable memory (storage and
    /// uniform buffers, push constants).
    BoolInBuffer {
        /// The struct's name.
        structure: String,
        /// The field, as a path from the struct (`inner.flag` for a nested struct's field).
        field: String,
    },
    /// The Rust fields listed do not cover the struct: it has implicit padding or unlisted fields.
    ImplicitPadding {
        /// The struct's name.
        structure: String,
        /// Bytes not covered by any listed field.
        uncovered: u32,
    },
    /// Offsets or sizes differ; the table marks each mismatch.
    Mismatch(LayoutTable),
}

impl fmt::Display for LayoutError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LayoutError::Source(message) => write!(f, "shader source: {message}"),
            LayoutError::StructNotFound(name) => write!(f, "no struct named `{name}` in the shader source"),
            LayoutError::MissingField {
                structure,
                field,
                missing_in,
            } => {
                write!(f, "{structure}.{field}: field missing on the {missing_in} side")
            }
            LayoutError::OneByteField { structure, field } => write!(
                f,
                "{structure}.{field} takes 1 byte in Rust, as a `bool` does: no shader type takes 1 byte, \
                 and a shader `bool` is 4 bytes where it may be in a buffer at all (WGSL forbids it). \
                 Make `{field}` a `u32` that holds 0 or 1, or keep the `bool` in a Rust struct of your \
                 own and share an IO struct with a `u32` in its place, converting between the two"
            ),
            LayoutError::BoolInBuffer { structure, field } => write!(
                f,
                "{structure}.{field} is a `bool`, which WGSL forbids in storage and uniform buffers and \
                 push constants: make it a `u32` that holds 0 or 1"
            ),
            LayoutError::ImplicitPadding { structure, uncovered } => write!(
                f,
                "{structure}: {uncovered} byte(s) of the Rust struct are not covered by the listed fields \
                 (implicit padding or unlisted fields); declare padding as a field, such as `pad: u32`"
            ),
            LayoutError::Mismatch(table) => write!(
                f,
                "{}: offset or size differs at {}:\n{table}",
                table.shader.name,
                table.mismatches().join(", ")
            ),
        }
    }
}

impl std::error::Error for LayoutError {}

/// A Rust layout next to a shader layout, field by field.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LayoutTable {
    /// The Rust side.
    pub rust: StructLayout,
    /// The shader side.
    pub shader: StructLayout,
}

impl LayoutTable {
    /// Names of the fields whose offset or size differ (and `"(size)"` if the struct sizes differ).
    pub fn mismatches(&self) -> Vec<String> {
        let mut names: Vec<String> = self
            .rust
            .fields
            .iter()
            .zip(&self.shader.fields)
            .filter(|(rust, shader)| rust.offset != shader.offset || rust.size != shader.size)
            .map(|(rust, _)| rust.name.clone())
            .collect();
        if self.rust.size != self.shader.size {
            names.push(String::from("(size)"));
        }
        names
    }
}

impl fmt::Display for LayoutTable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{:<20} {:>11} {:>13}",
            self.rust.name, "Rust off/sz", "shader off/sz"
        )?;
        for (rust, shader) in self.rust.fields.iter().zip(&self.shader.fields) {
            let mark = if rust.offset != shader.offset || rust.size != shader.size {
                "  MISMATCH"
            } else {
                ""
            };
            writeln!(
                f,
                "  {:<18} {:>5}/{:<5} {:>7}/{:<5}{mark}",
                rust.name, rust.offset, rust.size, shader.offset, shader.size
            )?;
        }
        let mark = if self.rust.size != self.shader.size {
            "  MISMATCH"
        } else {
            ""
        };
        write!(
            f,
            "  {:<18} {:>11} {:>13}{mark}",
            "(size)", self.rust.size, self.shader.size
        )
    }
}

/// Renders a Rust layout next to several shader layouts of the same struct, one column each
/// (`offset/size` per field, then the struct size), each at least as wide as its label. Fields
/// follow the Rust layout's order; a field a column lacks shows as `-`.
pub fn render_columns(rust: &StructLayout, columns: &[(&str, &StructLayout)]) -> String {
    let cell = |layout: &StructLayout, field: &str| {
        layout
            .fields
            .iter()
            .find(|f| f.name == field)
            .map_or_else(|| String::from("-"), |f| format!("{}/{}", f.offset, f.size))
    };
    let width = |label: &str| label.len().max(9);
    let mut out = format!("{:<26} {:>9}", rust.name, "Rust");
    columns
        .iter()
        .for_each(|(label, _)| out.push_str(&format!(" {label:>w$}", w = width(label))));
    for field in &rust.fields {
        out.push_str(&format!("\n  {:<24} {:>9}", field.name, cell(rust, &field.name)));
        columns.iter().for_each(|(label, layout)| {
            out.push_str(&format!(" {:>w$}", cell(layout, &field.name), w = width(label)))
        });
    }
    out.push_str(&format!("\n  {:<24} {:>9}", "(size)", rust.size));
    columns
        .iter()
        .for_each(|(label, layout)| out.push_str(&format!(" {:>w$}", layout.size, w = width(label))));
    out
}

/// Compares a Rust layout with a shader layout: every field present on both sides, at the same
/// offset with the same size, the same total size, and no bytes of the Rust struct left uncovered.
pub fn compare(rust: &StructLayout, shader: &StructLayout) -> Result<LayoutTable, LayoutError> {
    let missing = |field: &str, missing_in| LayoutError::MissingField {
        structure: shader.name.clone(),
        field: field.to_string(),
        missing_in,
    };
    if let Some(field) = shader
        .fields
        .iter()
        .find(|s| !rust.fields.iter().any(|r| r.name == s.name))
    {
        return Err(missing(&field.name, "Rust"));
    }
    if let Some(field) = rust
        .fields
        .iter()
        .find(|r| !shader.fields.iter().any(|s| s.name == r.name))
    {
        return Err(missing(&field.name, "shader"));
    }
    if let Some(field) = rust.fields.iter().find(|field| field.size == 1) {
        return Err(LayoutError::OneByteField {
            structure: shader.name.clone(),
            field: field.name.clone(),
        });
    }
    // Summed in 64 bits: the fields of a hand-made layout may add up past u32::MAX.
    let covered: u64 = rust.fields.iter().map(|field| u64::from(field.size)).sum();
    if covered < u64::from(rust.size) {
        return Err(LayoutError::ImplicitPadding {
            structure: shader.name.clone(),
            uncovered: rust.size - covered as u32,
        });
    }
    let rust_in_shader_order = StructLayout {
        fields: shader
            .fields
            .iter()
            .filter_map(|s| rust.fields.iter().find(|r| r.name == s.name).cloned())
            .collect(),
        ..rust.clone()
    };
    let table = LayoutTable {
        rust: rust_in_shader_order,
        shader: shader.clone(),
    };
    if table.mismatches().is_empty() {
        Ok(table)
    } else {
        Err(LayoutError::Mismatch(table))
    }
}

/// Whether `name` is a GLSL identifier (ASCII letters, digits and `_`, not starting with a digit).
pub(crate) fn is_identifier(name: &str) -> bool {
    let mut chars = name.chars();
    chars
        .next()
        .is_some_and(|first| first.is_ascii_alphabetic() || first == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// The number of a probe's line right after `source`, which starts the probe at line 1 (counted
/// from the newlines, so that a source ending in one counts right).
pub(crate) fn line_after(source: &str) -> usize {
    source.matches('\n').count() + 2
}

/// A failed probe compile as a layout error: the compiler's message when it did not run, else
/// `from_log` of its log, in which the probe's path reads `source`.
pub(crate) fn probe_error(error: CompileError, from_log: impl FnOnce(&str) -> LayoutError) -> LayoutError {
    match error {
        CompileError::NotRun(message) => LayoutError::Source(message),
        CompileError::Failed { log, source_path } => from_log(&log.replace(&source_path, "source")),
    }
}

/// The size of a field's type, for [`rust_layout!`](crate::rust_layout).
#[doc(hidden)]
pub fn field_size<T, F>(_field: fn(&T) -> &F) -> u32 {
    std::mem::size_of::<F>() as u32
}

/// The [`StructLayout`] of a Rust struct from its listed fields:
/// `rust_layout!(Type { field, ... })`, or `rust_layout!(Type as "ShaderName" { field, ... })`
/// when the shader spells the struct's name differently. List every field, in any order.
#[macro_export]
macro_rules! rust_layout {
    (@build $ty:ty, $name:expr, $($field:ident),+) => {
        $crate::layout::StructLayout {
            name: ::std::string::String::from($name),
            size: ::std::mem::size_of::<$ty>() as u32,
            align: ::std::mem::align_of::<$ty>() as u32,
            fields: ::std::vec![$(
                $crate::layout::FieldLayout {
                    name: ::std::string::String::from(stringify!($field)),
                    offset: ::std::mem::offset_of!($ty, $field) as u32,
                    size: $crate::layout::field_size(|value: &$ty| &value.$field),
                },
            )+],
        }
    };
    ($ty:ty as $shader:literal { $($field:ident),+ $(,)? }) => {
        $crate::rust_layout!(@build $ty, $shader, $($field),+)
    };
    ($ty:ident { $($field:ident),+ $(,)? }) => {
        $crate::rust_layout!(@build $ty, stringify!($ty), $($field),+)
    };
}
