//! The layout reader: what it reads from naga, glslang and slangc, and the errors it gives.

use shader_proptest::layout::{self, GlslPacking, LayoutError};
use shader_proptest::rust_layout;

/// The GLSL reader sees the difference between std430 (vec3 aligned to 16) and scalar (to 4).
#[test]
fn glsl_packings_differ_where_the_rules_differ() {
    let source = "struct Probe { float a; vec3 b; };";
    let offset_of_b = |packing| {
        layout::glsl_layout(source, "Probe", packing, &[])
            .expect("compiles")
            .fields[1]
            .offset
    };
    assert_eq!(offset_of_b(GlslPacking::Std430), 16);
    assert_eq!(offset_of_b(GlslPacking::Scalar), 4);
    let wgsl = layout::wgsl_layout("struct Probe { a: f32, b: vec3<f32> }", "Probe").expect("parses");
    assert_eq!((wgsl.fields[1].offset, wgsl.size, wgsl.align), (16, 32, 16));
}

/// The Slang reader sees the same difference between Slang's std430 and scalar buffer layouts,
/// for a struct declared in the source and for one a nested struct holds.
#[test]
fn slang_layouts_differ_where_the_rules_differ() {
    let source = "struct Probe { float a; float3 b; };\nstruct Outer { float c; Probe probe; };";
    let layout = |name, packing| layout::slang_layout(source, name, packing, &[]).expect("compiles");
    let std430 = layout("Probe", GlslPacking::Std430);
    let scalar = layout("Probe", GlslPacking::Scalar);
    assert_eq!(
        (std430.name.as_str(), std430.fields[1].offset, std430.size),
        ("Probe", 16, 32)
    );
    assert_eq!((scalar.fields[1].offset, scalar.size), (4, 16));
    let outer = layout("Outer", GlslPacking::Std430);
    assert_eq!(
        (outer.fields[1].name.as_str(), outer.fields[1].offset, outer.size),
        ("probe", 16, 48)
    );
    assert_eq!(
        layout::slang_layout(source, "Missing", GlslPacking::Std430, &[]),
        Err(LayoutError::StructNotFound("Missing".into()))
    );
    assert!(matches!(
        layout::slang_layout("struct Probe { float a }", "Probe", GlslPacking::Std430, &[]),
        Err(LayoutError::Source(_))
    ));
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct Probe {
    a: f32,
    b: [f32; 3],
}

/// The verification API names what is wrong instead of panicking.
#[test]
fn layout_errors_name_the_struct_and_field() {
    let rust = rust_layout!(Probe { a, b });
    let wgsl = |source: &str| layout::wgsl_layout(source, "Probe");
    assert_eq!(
        wgsl("struct Other { a: f32 }"),
        Err(LayoutError::StructNotFound("Probe".into()))
    );
    assert!(matches!(
        wgsl("struct Probe { a: f32"),
        Err(LayoutError::Source(_))
    ));
    let missing_in_rust = wgsl("struct Probe { a: f32, b: array<f32, 3>, c: f32 }").expect("parses");
    assert_eq!(
        layout::compare(&rust, &missing_in_rust),
        Err(LayoutError::MissingField {
            structure: "Probe".into(),
            field: "c".into(),
            missing_in: "Rust"
        })
    );
    let missing_in_shader = wgsl("struct Probe { a: f32 }").expect("parses");
    assert!(matches!(
        layout::compare(&rust, &missing_in_shader),
        Err(LayoutError::MissingField {
            missing_in: "shader",
            ..
        })
    ));
    match layout::compare(
        &rust,
        &wgsl("struct Probe { a: f32, b: vec3<f32> }").expect("parses"),
    ) {
        Err(LayoutError::Mismatch(table)) => {
            println!("{table}");
            assert_eq!(table.mismatches(), ["b", "(size)"]);
        }
        other => panic!("expected a mismatch, got {other:?}"),
    }
    let good = wgsl("struct Probe { a: f32, b: array<f32, 3> }").expect("parses");
    assert!(layout::compare(&rust, &good).is_ok());
    assert!(matches!(
        layout::glsl_layout("struct Probe { float a; }", "Missing", GlslPacking::Std430, &[]),
        Err(LayoutError::StructNotFound(_))
    ));
    assert!(matches!(
        layout::glsl_layout("struct Probe { float a }", "Probe", GlslPacking::Std430, &[]),
        Err(LayoutError::Source(_))
    ));
}

#[repr(C)]
struct Padded {
    flag: u16,
    value: f32,
}

/// A Rust struct with implicit padding is refused even where the offsets happen to agree.
#[test]
fn implicit_padding_is_reported() {
    let rust = rust_layout!(Padded { flag, value });
    let shader = layout::StructLayout {
        name: "Padded".into(),
        ..rust.clone()
    };
    assert_eq!(
        layout::compare(&rust, &shader),
        Err(LayoutError::ImplicitPadding {
            structure: "Padded".into(),
            uncovered: 2
        })
    );
}

#[repr(C)]
struct Settings {
    width: f32,
    stipple: bool,
}

/// A Rust `bool` in a shared struct is named with its fix, before any byte counting; a WGSL
/// `bool` in a struct (or a struct it holds) is refused naming the field, as WGSL forbids it in
/// buffers.
#[test]
fn bools_are_named_with_their_fix() {
    let rust = rust_layout!(Settings { width, stipple });
    let shader = layout::glsl_layout(
        "struct Settings { float width; uint stipple; };",
        "Settings",
        GlslPacking::Std430,
        &[],
    )
    .expect("compiles");
    let error = layout::compare(&rust, &shader).expect_err("a bool");
    assert_eq!(
        error,
        LayoutError::OneByteField {
            structure: "Settings".into(),
            field: "stipple".into()
        }
    );
    let message = error.to_string();
    assert!(
        message.contains("Make `stipple` a `u32`") && message.contains("IO struct"),
        "{message}"
    );
    let nested = "struct Flags { visible: bool } struct Settings { width: f32, flags: array<Flags, 2> }";
    assert_eq!(
        layout::wgsl_layout(nested, "Settings"),
        Err(LayoutError::BoolInBuffer {
            structure: "Settings".into(),
            field: "flags.visible".into()
        })
    );
}

/// A layout prints as a table of offsets and sizes.
#[test]
fn a_layout_prints_as_a_table() {
    let layout = layout::wgsl_layout("struct Probe { a: f32, b: vec3<f32> }", "Probe").expect("parses");
    assert_eq!(
        layout.to_string(),
        "Probe     offset  size\n  a            0     4\n  b           16    12\n  (size)            32  align 16"
    );
}

/// The GLSL and Slang readers compile the source with a probe after it: a struct the source does not
/// declare (also after a final newline) and a name that is not an identifier are `StructNotFound`,
/// and an error in the source is reported at the source's own line.
#[test]
fn probe_errors_name_the_struct_or_the_source_line() {
    type Reader = fn(&str, &str) -> Result<layout::StructLayout, LayoutError>;
    let readers: [(&str, Reader); 2] = [
        ("GLSL", |source, name| {
            layout::glsl_layout(source, name, GlslPacking::Std430, &[])
        }),
        ("Slang", |source, name| {
            layout::slang_layout(source, name, GlslPacking::Std430, &[])
        }),
    ];
    for (language, read) in readers {
        for (source, name) in [
            ("struct Probe { float a; };\n", "Missing"),
            ("struct Probe { float a; };\n\n", "Missing"),
            ("struct Probe { float a; };", "Probe p; float"),
            ("struct Probe { float a; };", ""),
        ] {
            assert_eq!(
                read(source, name),
                Err(LayoutError::StructNotFound(name.into())),
                "{language}: {source:?}, {name:?}"
            );
        }
        match read("struct Probe { float a; };\nstruct Broken { float b }", "Probe") {
            Err(LayoutError::Source(log)) => {
                assert!(log.contains("source:2:"), "{language}: {log}");
                println!("{language}: {}", log.lines().next().unwrap_or_default());
            }
            other => panic!("{language}: expected a source error, got {other:?}"),
        }
    }
}
