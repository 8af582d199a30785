//! Bad input at the edges of the API (`src/bad_input.md`): every public entry of the crate that takes
//! data from outside the program (bytes, settings, textures to make mip chains of, include names,
//! WGSL, GLSL, Slang and HLSL sources and layouts, a naga_oil composer) gets each bad input of the table below. Each must give an error, never a
//! panic, whose message names the struct or field and the value received. The table is rendered
//! into `src/bad_input.md`; regenerate it with
//! `RAY_FOOTPRINT_BLESS=1 cargo test --release --all-features --test bad_input`.
#![cfg(all(feature = "validate", feature = "naga_oil"))]

mod common;

use bytemuck::{Pod, Zeroable};
use common::assert_generated_block;
use glam::Vec2;
use naga_oil::compose::Composer;
use ray_footprint::abi::{
    from_bytes, slice_from_bytes, vec_from_bytes, HitPayload, PackedRayCone, RayCone, RayConePushConstants,
    RayDiff, WireframePushConstants, WireframeSettingsIo,
};
use ray_footprint::layout::{self, FieldLayout, GlslPacking, LayoutError, StructLayout};
use ray_footprint::mip::{mip_chain_rgba16f, mip_chain_rgba8_srgb};
use ray_footprint::rust_layout;
use ray_footprint::shaders::{resolve_glsl_include, Module};
use ray_footprint::wireframe::{WireframeSettings, MAX_LINE_THICKNESS};
use shader_proptest::{Language, Shader};
use std::fmt::{Display, Write};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

/// What an entry did with a bad input.
#[derive(Debug)]
enum Outcome {
    Error(String),
    Accepted,
    Panicked,
}

/// One bad input: the entry, the input, what the entry answered and the texts its message must
/// contain (the struct or field and the value).
struct Row {
    entry: String,
    input: String,
    outcome: Outcome,
    names: Vec<String>,
}

/// Calls `entry` on a bad input, catching a panic.
fn attempt<T, E: Display>(
    entry: impl Into<String>,
    input: impl Into<String>,
    names: &[&str],
    call: impl FnOnce() -> Result<T, E>,
) -> Row {
    let outcome = match catch_unwind(AssertUnwindSafe(call)) {
        Ok(Err(error)) => Outcome::Error(error.to_string()),
        Ok(Ok(_)) => Outcome::Accepted,
        Err(_) => Outcome::Panicked,
    };
    Row {
        entry: entry.into(),
        input: input.into(),
        outcome,
        names: names.iter().map(ToString::to_string).collect(),
    }
}

/// Bytes aligned for every shared struct (16), so that a start offset sets the misalignment.
#[repr(C, align(16))]
struct Aligned([u8; 256]);

const BUFFER: Aligned = Aligned([0; 256]);

/// A too short, a not whole and a misaligned byte string for `T`.
fn bytes_rows<T: Pod>(name: &str) -> Vec<Row> {
    let (size, align) = (std::mem::size_of::<T>(), std::mem::align_of::<T>());
    let (short, long) = ((size - 1).to_string(), (size + 1).to_string());
    let (size_text, align_text) = (size.to_string(), align.to_string());
    vec![
        attempt(
            format!("abi::from_bytes::<{name}>"),
            format!("{short} bytes"),
            &[name, &size_text, &short],
            || from_bytes::<T>(&BUFFER.0[..size - 1]),
        ),
        attempt(
            format!("abi::vec_from_bytes::<{name}>"),
            format!("{long} bytes"),
            &[name, &size_text, &long],
            || vec_from_bytes::<T>(&BUFFER.0[..size + 1]),
        ),
        attempt(
            format!("abi::slice_from_bytes::<{name}>"),
            format!("{size} bytes starting 1 byte past a multiple of {align}"),
            &[name, &align_text, "1 byte"],
            || slice_from_bytes::<T>(&BUFFER.0[1..1 + size]),
        ),
    ]
}

fn abi_rows() -> Vec<Row> {
    let mut rows = vec![attempt(
        "abi::from_bytes::<RayCone>",
        "0 bytes",
        &["RayCone", "8", "0"],
        || from_bytes::<RayCone>(&[]),
    )];
    rows.extend(bytes_rows::<RayCone>("RayCone"));
    rows.extend(bytes_rows::<PackedRayCone>("PackedRayCone"));
    rows.extend(bytes_rows::<HitPayload>("HitPayload"));
    rows.extend(bytes_rows::<RayConePushConstants>("RayConePushConstants"));
    rows.extend(bytes_rows::<RayDiff>("RayDiff"));
    rows.extend(bytes_rows::<WireframeSettingsIo>("WireframeSettingsIo"));
    rows.extend(bytes_rows::<WireframePushConstants>("WireframePushConstants"));
    rows
}

/// Settings with one field changed by `change`.
fn settings_with(change: impl FnOnce(&mut WireframeSettings)) -> WireframeSettings {
    let mut settings = WireframeSettings::default();
    change(&mut settings);
    settings
}

/// `WireframeSettings::try_new` with the default settings but one field.
fn try_new_row(field: &str, value: &str, change: impl FnOnce(&mut WireframeSettings)) -> Row {
    let s = settings_with(change);
    attempt(
        "WireframeSettings::try_new",
        format!("{field} = {value}"),
        &[field, value],
        || {
            WireframeSettings::try_new(
                s.thickness,
                s.thickness_var,
                s.smoothing,
                s.stipple,
                s.stipple_length,
                s.stipple_repeats,
                s.screen_space,
            )
        },
    )
}

fn settings_rows() -> Vec<Row> {
    let above_max = (MAX_LINE_THICKNESS * 2.0).to_string();
    let mut rows = vec![
        try_new_row("thickness", "NaN", |s| s.thickness = f32::NAN),
        try_new_row("thickness", "inf", |s| s.thickness = f32::INFINITY),
        try_new_row("thickness", "-1", |s| s.thickness = -1.0),
        try_new_row("thickness", &above_max, |s| {
            s.thickness = MAX_LINE_THICKNESS * 2.0
        }),
        try_new_row("thickness_var.x", "-inf", |s| {
            s.thickness_var = Vec2::new(f32::NEG_INFINITY, 1.0)
        }),
        try_new_row("thickness_var.y", "-0.5", |s| {
            s.thickness_var = Vec2::new(1.0, -0.5)
        }),
        try_new_row("smoothing", "-0.001", |s| s.smoothing = -0.001),
        try_new_row("smoothing", &f32::MAX.to_string(), |s| s.smoothing = f32::MAX),
        try_new_row("stipple_length", "1.5", |s| s.stipple_length = 1.5),
        try_new_row("stipple_length", "-0.1", |s| s.stipple_length = -0.1),
        try_new_row("stipple_length", "NaN", |s| s.stipple_length = f32::NAN),
        try_new_row("stipple_repeats", "-1", |s| s.stipple_repeats = -1),
        try_new_row("stipple_repeats", &i32::MIN.to_string(), |s| {
            s.stipple_repeats = i32::MIN
        }),
    ];
    let mut io = WireframeSettings::default().pack();
    io.smoothing = f32::NAN;
    let bytes = bytemuck::bytes_of(&io).to_vec();
    rows.push(attempt(
        "abi::from_bytes::<WireframeSettingsIo>, then unpack and WireframeSettings::validate",
        "32 bytes holding smoothing = NaN",
        &["smoothing", "NaN"],
        || {
            let io = from_bytes::<WireframeSettingsIo>(&bytes).map_err(|e| e.to_string())?;
            io.unpack().validate().map_err(|e| e.to_string())
        },
    ));
    rows
}

fn include_rows() -> Vec<Row> {
    let names = [
        "",
        "ray_cone",
        "ray_cone.wgsl",
        "RAY_CONE.glsl",
        " ray_cone.glsl",
        "ray_cone.glsl\0",
        "ray_cone.glsl.glsl",
        "ray_footprint/ray_cone.glsl",
        "../glsl/ray_cone.glsl",
        "/etc/passwd",
        "ray_cone.glsl/../../Cargo.toml",
    ];
    names
        .iter()
        .map(|name| {
            let quoted = format!("{name:?}");
            attempt(
                "shaders::resolve_glsl_include",
                quoted.clone(),
                &[&quoted],
                || resolve_glsl_include(name),
            )
        })
        .collect()
}

fn naga_oil_rows() -> Vec<Row> {
    use ray_footprint::naga_oil::{add_composable_modules, capabilities};
    let without = |modules: &'static [Module], composer: Composer| {
        move || {
            let mut composer = composer;
            add_composable_modules(&mut composer, modules)
        }
    };
    vec![
        attempt(
            "naga_oil::add_composable_modules",
            "[RayCone] into Composer::default() (no capabilities)",
            &["ray_footprint::ray_cone", "SHADER_FLOAT16_IN_FLOAT32"],
            without(&[Module::RayCone], Composer::default()),
        ),
        attempt(
            "naga_oil::add_composable_modules",
            "[RayCone, RayDiffF64] into a composer with capabilities(&[RayCone])",
            &["ray_footprint::ray_diff_f64", "FLOAT64"],
            without(
                &[Module::RayCone, Module::RayDiffF64],
                Composer::default().with_capabilities(capabilities(&[Module::RayCone])),
            ),
        ),
    ]
}

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct Probe {
    a: f32,
    b: [f32; 3],
}

#[repr(C)]
struct Padded {
    flag: u8,
    value: f32,
}

/// A layout reader: its name in the table and the call (std430 for GLSL and Slang).
type Reader = (&'static str, fn(&str, &str) -> Result<StructLayout, LayoutError>);

const WGSL_READER: Reader = ("layout::wgsl_layout", layout::wgsl_layout);
const GLSL_READER: Reader = ("layout::glsl_layout (std430)", |source, name| {
    layout::glsl_layout(source, name, GlslPacking::Std430, &[])
});
const SLANG_READER: Reader = ("layout::slang_layout (std430)", |source, name| {
    layout::slang_layout(source, name, GlslPacking::Std430, &[])
});
const HLSL_GLSLANG_READER: Reader = ("Shader::struct_layout (HLSL, glslang)", |source, name| {
    Shader::new(Language::HlslGlslang, source).struct_layout(name)
});
const HLSL_SLANGC_READER: Reader = ("Shader::struct_layout (HLSL, slangc)", |source, name| {
    Shader::new(Language::HlslSlangc, source).struct_layout(name)
});

/// A layout reader on a bad source or struct name.
fn reader_row(reader: Reader, input: &str, name: &str, names: &[&str], source: &'static str) -> Row {
    let (entry, read) = reader;
    let name_owned = name.to_string();
    attempt(entry, format!("{input}, struct {name:?}"), names, move || {
        read(source, &name_owned)
    })
}

fn compare_row(input: &str, names: &[&str], rust: StructLayout, shader: Result<StructLayout, String>) -> Row {
    attempt("layout::compare", input, names, move || {
        layout::compare(&rust, &shader.expect("the shader layout is read")).map_err(|e| e.to_string())
    })
}

fn layout_rows() -> Vec<Row> {
    let probe = rust_layout!(Probe { a, b });
    let wgsl = |source: &str| layout::wgsl_layout(source, "Probe").map_err(|e| e.to_string());
    let std140 = layout::glsl_layout(
        "struct Probe { float a; float b[3]; };",
        "Probe",
        GlslPacking::Std140,
        &[],
    )
    .map_err(|e| e.to_string());
    let huge = StructLayout {
        fields: vec![
            FieldLayout {
                name: "a".into(),
                offset: 0,
                size: u32::MAX,
            },
            FieldLayout {
                name: "b".into(),
                offset: 4,
                size: u32::MAX,
            },
        ],
        ..probe.clone()
    };
    let padded = rust_layout!(Padded { flag, value });
    vec![
        reader_row(
            WGSL_READER,
            "`struct Probe { a: f32`",
            "Probe",
            &["expected", "wgsl:1:"],
            "struct Probe { a: f32",
        ),
        reader_row(
            WGSL_READER,
            "`struct Other { a: f32 }`",
            "Probe",
            &["Probe"],
            "struct Other { a: f32 }",
        ),
        reader_row(WGSL_READER, "empty source", "Probe", &["Probe"], ""),
        reader_row(
            WGSL_READER,
            "`struct Probe { a: f32 }`",
            "f32",
            &["f32"],
            "struct Probe { a: f32 }",
        ),
        reader_row(
            WGSL_READER,
            "`struct Probe { a: f32 }`",
            "",
            &["``"],
            "struct Probe { a: f32 }",
        ),
        reader_row(
            GLSL_READER,
            "`struct Probe { float a }`",
            "Probe",
            &["source:1:", "syntax error"],
            "struct Probe { float a }",
        ),
        reader_row(
            GLSL_READER,
            "`struct Probe { float a; };`",
            "Missing",
            &["Missing"],
            "struct Probe { float a; };",
        ),
        reader_row(
            GLSL_READER,
            "`struct Probe { float a; };` and a newline",
            "Missing",
            &["Missing"],
            "struct Probe { float a; };\n",
        ),
        reader_row(
            GLSL_READER,
            "`struct Probe { float a; };`",
            "Probe p; float",
            &["Probe p; float"],
            "struct Probe { float a; };",
        ),
        reader_row(
            GLSL_READER,
            "`#include \"nope.glsl\"`, no include directory",
            "Probe",
            &["source:1:", "nope.glsl"],
            "#include \"nope.glsl\"",
        ),
        reader_row(
            SLANG_READER,
            "`struct Probe { float a }`",
            "Probe",
            &["source:1:", "expected"],
            "struct Probe { float a }",
        ),
        reader_row(
            SLANG_READER,
            "`struct Probe { float a; };` and a newline",
            "Missing",
            &["Missing"],
            "struct Probe { float a; };\n",
        ),
        reader_row(
            SLANG_READER,
            "`struct Probe { float a; };`",
            "Probe p; float",
            &["Probe p; float"],
            "struct Probe { float a; };",
        ),
        reader_row(
            SLANG_READER,
            "`import nope;`, no search directory",
            "Probe",
            &["source:1:", "nope"],
            "import nope;",
        ),
    ]
    .into_iter()
    .chain(
        [HLSL_GLSLANG_READER, HLSL_SLANGC_READER]
            .into_iter()
            .flat_map(hlsl_reader_rows),
    )
    .chain([
        compare_row(
            "Rust `Probe { a, b }`, WGSL with an extra field `c`",
            &["Probe", "c", "Rust"],
            probe.clone(),
            wgsl("struct Probe { a: f32, b: array<f32, 3>, c: f32 }"),
        ),
        compare_row(
            "Rust `Probe { a, b }`, WGSL without `b`",
            &["Probe", "b", "shader"],
            probe.clone(),
            wgsl("struct Probe { a: f32 }"),
        ),
        compare_row(
            "Rust `Probe { a, b }`, WGSL `b: vec3<f32>` (16-byte aligned)",
            &["Probe", "b", "(size)"],
            probe.clone(),
            wgsl("struct Probe { a: f32, b: vec3<f32> }"),
        ),
        compare_row(
            "Rust `Probe { a, b }`, GLSL `float b[3]` under std140 (array stride 16)",
            &["Probe", "b", "(size)"],
            probe.clone(),
            std140,
        ),
        compare_row(
            "Rust `Padded { flag: u8, value: f32 }` (a one-byte field, as a `bool` is), same layout as shader",
            &["Padded", "flag", "1 byte"],
            padded.clone(),
            Ok(padded),
        ),
        compare_row(
            "hand-made Rust layout whose field sizes add up past `u32::MAX`",
            &["Probe", "a", "b"],
            huge,
            wgsl("struct Probe { a: f32, b: array<f32, 3> }"),
        ),
    ])
    .collect()
}

/// An HLSL layout reader on a syntax error, a missing struct, a name that is not one, and an
/// include that is not there.
fn hlsl_reader_rows(reader: Reader) -> [Row; 4] {
    [
        reader_row(
            reader,
            "`struct Probe { float a }`",
            "Probe",
            &["source:1"],
            "struct Probe { float a }",
        ),
        reader_row(
            reader,
            "`struct Probe { float a; };` and a newline",
            "Missing",
            &["Missing"],
            "struct Probe { float a; };\n",
        ),
        reader_row(
            reader,
            "`struct Probe { float a; };`",
            "Probe p; float",
            &["Probe p; float"],
            "struct Probe { float a; };",
        ),
        reader_row(
            reader,
            "`#include \"nope.hlsl\"`, no include directory",
            "Probe",
            &["source:1", "nope.hlsl"],
            "#include \"nope.hlsl\"",
        ),
    ]
}

fn mip_rows() -> Vec<Row> {
    let texels = vec![[0u8; 4]; 12];
    vec![
        attempt("mip::mip_chain_rgba8_srgb", "width 0", &["width", "0"], || {
            mip_chain_rgba8_srgb(0, 4, &texels)
        }),
        attempt("mip::mip_chain_rgba8_srgb", "height 0", &["height", "0"], || {
            mip_chain_rgba8_srgb(4, 0, &texels)
        }),
        attempt(
            "mip::mip_chain_rgba8_srgb",
            "12 texels for 4 x 4",
            &["texels", "12", "16"],
            || mip_chain_rgba8_srgb(4, 4, &texels),
        ),
        attempt(
            "mip::mip_chain_rgba16f",
            "3 texels for 2 x 2",
            &["texels", "3", "4"],
            || mip_chain_rgba16f(2, 2, &[[0u16; 4]; 3]),
        ),
    ]
}

fn all_rows() -> Vec<(&'static str, Vec<Row>)> {
    vec![
        ("Bytes to ABI structs", abi_rows()),
        ("Wireframe settings", settings_rows()),
        ("Mip chains", mip_rows()),
        ("GLSL include names", include_rows()),
        ("naga_oil composer", naga_oil_rows()),
        ("Layout verification", layout_rows()),
    ]
}

/// Why a row fails: a panic, an accepted input, or a message missing a name.
fn problem(row: &Row) -> Option<String> {
    match &row.outcome {
        Outcome::Error(message) => {
            let missing: Vec<&String> = row.names.iter().filter(|name| !message.contains(*name)).collect();
            (!missing.is_empty()).then(|| format!("the message {message:?} lacks {missing:?}"))
        }
        other => Some(format!("{other:?}")),
    }
}

#[test]
fn every_bad_input_is_an_error_naming_the_field_and_the_value() {
    let sections = all_rows();
    let mut failures = Vec::new();
    for row in sections.iter().flat_map(|(_, rows)| rows) {
        if let Some(problem) = problem(row) {
            failures.push(format!("{} with {}: {problem}", row.entry, row.input));
        }
    }
    let count: usize = sections.iter().map(|(_, rows)| rows.len()).sum();
    println!("{count} bad inputs tried, {} failures", failures.len());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// `text` as a markdown code span inside a table cell: delimited by one backtick more than the
/// longest run of backticks in it.
fn code(text: &str) -> String {
    let longest_run = text.split(|c| c != '`').map(str::len).max().unwrap_or(0);
    let fence = "`".repeat(longest_run + 1);
    format!("{fence} {} {fence}", text.replace('|', "\\|"))
}

/// The first line of an outcome, for the table.
fn first_line(outcome: &Outcome) -> String {
    match outcome {
        Outcome::Error(message) => message.lines().next().unwrap_or_default().to_string(),
        other => format!("{other:?}"),
    }
}

fn render() -> String {
    let mut out = String::new();
    for (title, rows) in all_rows() {
        writeln!(out, "\n### {title}\n").expect("a String");
        out.push_str("| entry | bad input | error (first line) |\n| --- | --- | --- |\n");
        for row in rows {
            let input = if row.input.contains('`') {
                row.input.clone()
            } else {
                code(&row.input)
            };
            writeln!(
                out,
                "| {} | {} | {} |",
                code(&row.entry),
                input,
                code(&first_line(&row.outcome))
            )
            .expect("a String");
        }
    }
    out
}

const START: &str = "<!-- bad input table: generated by tests/bad_input.rs, do not edit by hand -->";
const END: &str = "<!-- end of bad input table -->";

#[test]
fn the_docs_show_the_table() {
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/src/bad_input.md"));
    let block = format!("\n{}\n", render());
    assert_generated_block(path, START, END, &block, "src/bad_input.md");
}
