//! The wireframe mirror does what its documentation says: coverage in [0, 1] for every finite input,
//! lines on edges and none inside, hard steps, dash fractions, the bool-to-int mirror, validation
//! and the presets' exact values. (Agreement of the shaders with this mirror is tests/agreement.rs.)

mod common;

use glam::{Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::shaders::Module;
use ray_footprint::wireframe::{
    self as wf, WireframeSettings, WireframeSettingsError, WireframeSettingsIo, MAX_LINE_THICKNESS,
};

/// Any finite f32, zero and subnormals included.
fn finite() -> impl Strategy<Value = f32> {
    prop::num::f32::NORMAL | prop::num::f32::SUBNORMAL | prop::num::f32::ZERO
}

fn finite_vec3() -> impl Strategy<Value = Vec3> {
    (finite(), finite(), finite()).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn finite_settings() -> impl Strategy<Value = WireframeSettings> {
    (
        (finite(), finite()),
        finite(),
        finite(),
        any::<bool>(),
        finite(),
        any::<i32>(),
        any::<bool>(),
    )
        .prop_map(
            |((x, y), thickness, smoothing, stipple, length, repeats, screen_space)| {
                WireframeSettings::new(
                    thickness,
                    Vec2::new(x, y),
                    smoothing,
                    stipple,
                    length,
                    repeats,
                    screen_space,
                )
            },
        )
}

fn assert_coverage(value: f32, what: &str) {
    assert!(
        (0.0..=1.0).contains(&value),
        "{what}: coverage {value} outside [0, 1]"
    );
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 20_000,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    #[test]
    fn coverage_lies_in_unit_interval_for_every_finite_input(
        settings in finite_settings(),
        barycentrics in finite_vec3(),
        deltas in finite_vec3(),
    ) {
        assert_coverage(wf::process_wireframe(settings, barycentrics, deltas), "process_wireframe");
        assert_coverage(
            wf::line_width(deltas, settings.thickness, settings.smoothing, barycentrics),
            "line_width",
        );
        let e = wf::edge_position(barycentrics);
        assert_coverage(wf::stipple(settings.stipple_repeats, settings.stipple_length, e), "stipple");
        assert!(wf::edge_thickness(settings.thickness_var, e).is_finite());
    }

    #[test]
    fn edge_ramp_is_finite_and_in_unit_interval(x in finite_vec3(), start in finite_vec3(), width in finite_vec3()) {
        for ramp in wf::edge_ramp(x, start, width).to_array() {
            assert_coverage(ramp, "edge_ramp");
        }
    }

    #[test]
    fn edge_thickness_lies_between_its_clamped_factors(x in finite(), y in finite(), e in finite()) {
        let clamp = |v: f32| v.clamp(0.0, MAX_LINE_THICKNESS);
        let (low, high) = (clamp(x).min(clamp(y)), clamp(x).max(clamp(y)));
        let thickness = wf::edge_thickness(Vec2::new(x, y), e);
        // Two roundings of the mix may step one ULP outside.
        let slack = 2.0 * f32::EPSILON * high;
        prop_assert!(thickness >= low - slack && thickness <= high + slack, "{thickness} not in [{low}, {high}]");
    }

    #[test]
    fn screen_space_off_ignores_deltas(
        settings in finite_settings(),
        barycentrics in finite_vec3(),
        first in finite_vec3(),
        second in finite_vec3(),
    ) {
        let settings = WireframeSettings { screen_space: false, ..settings };
        prop_assert_eq!(
            wf::process_wireframe(settings, barycentrics, first).to_bits(),
            wf::process_wireframe(settings, barycentrics, second).to_bits()
        );
    }

    #[test]
    fn unpack_maps_every_integer_to_nonzero(stipple in any::<i32>(), screen_space in any::<i32>()) {
        let io = WireframeSettingsIo { stipple, screen_space, ..WireframeSettingsIo::default() };
        let settings = wf::unpack_wireframe_settings(io);
        prop_assert_eq!(settings.stipple, stipple != 0);
        prop_assert_eq!(settings.screen_space, screen_space != 0);
        // Packing writes exactly 0 or 1, and unpacking that gives the same settings back.
        let packed = settings.pack();
        prop_assert_eq!(packed.stipple, i32::from(stipple != 0));
        prop_assert_eq!(packed.screen_space, i32::from(screen_space != 0));
        prop_assert_eq!(packed.unpack(), settings);
    }

    #[test]
    fn pack_then_unpack_round_trips(settings in finite_settings()) {
        let packed = settings.pack();
        prop_assert!(packed.stipple == 0 || packed.stipple == 1);
        prop_assert!(packed.screen_space == 0 || packed.screen_space == 1);
        prop_assert_eq!(wf::unpack_wireframe_settings(packed), settings);
        prop_assert_eq!(WireframeSettings::from(WireframeSettingsIo::from(settings)), settings);
    }
}

/// The six orders of `(a, b, c)`.
fn orders(a: f32, b: f32, c: f32) -> [Vec3; 6] {
    [
        Vec3::new(a, b, c),
        Vec3::new(a, c, b),
        Vec3::new(b, a, c),
        Vec3::new(b, c, a),
        Vec3::new(c, a, b),
        Vec3::new(c, b, a),
    ]
}

#[test]
fn edge_position_is_one_at_vertices_and_half_at_edge_middles() {
    for b in orders(1.0, 0.0, 0.0) {
        assert_eq!(wf::edge_position(b), 1.0, "{b}");
    }
    for b in orders(0.5, 0.5, 0.0) {
        assert_eq!(wf::edge_position(b), 0.5, "{b}");
    }
    assert_eq!(wf::edge_position(Vec3::splat(1.0 / 3.0)), 1.0 / 3.0);
}

#[test]
fn edge_thickness_is_var_x_at_edge_middles_and_var_y_at_vertices() {
    let var = Vec2::new(0.7, 0.2);
    let middle = wf::edge_thickness(var, 0.5);
    let vertex = wf::edge_thickness(var, 1.0);
    println!("edge_thickness((0.7, 0.2)): middle {middle}, vertex {vertex}");
    assert!((middle - 0.7).abs() <= 1.0e-6, "{middle}");
    assert!((vertex - 0.2).abs() <= 1.0e-6, "{vertex}");
    assert_eq!(wf::edge_thickness(Vec2::ZERO, 0.75), 0.0);
}

/// A 1-pixel line (the default preset) with a delta of 0.01 barycentric units per pixel.
const PIXEL: f32 = 0.01;

#[test]
fn coverage_is_one_on_an_edge_and_zero_deep_inside() {
    let deltas = Vec3::splat(PIXEL);
    for b in orders(0.0, 0.3, 0.7) {
        assert_eq!(
            wf::process_wireframe(wf::WIREFRAME_DEFAULT, b, deltas),
            1.0,
            "on edge {b}"
        );
    }
    let inside = [Vec3::splat(1.0 / 3.0), Vec3::new(0.2, 0.3, 0.5)];
    for b in inside {
        assert_eq!(
            wf::process_wireframe(wf::WIREFRAME_DEFAULT, b, deltas),
            0.0,
            "inside {b}"
        );
    }
    // Half-width 0.5 px, ramp 1 px: covered below 0.5 px from an edge, uncovered beyond 1.5 px,
    // and decreasing in between.
    let at = |pixels: f32| {
        let b = Vec3::new(pixels * PIXEL, 0.5, 0.5 - pixels * PIXEL);
        wf::process_wireframe(wf::WIREFRAME_DEFAULT, b, deltas)
    };
    let ramp: Vec<f32> = (0..=8).map(|i| at(0.25 * i as f32)).collect();
    println!("default preset, coverage at 0, 0.25, .., 2 px from an edge: {ramp:?}");
    assert_eq!(at(0.4), 1.0);
    assert_eq!(at(1.6), 0.0);
    assert!(ramp.windows(2).all(|w| w[1] <= w[0]), "{ramp:?}");
    assert!(at(1.0) > 0.0 && at(1.0) < 1.0);
}

#[test]
fn zero_smoothing_is_a_hard_step_at_the_half_width() {
    let settings = WireframeSettings {
        smoothing: 0.0,
        ..wf::WIREFRAME_DEFAULT
    };
    let deltas = Vec3::splat(PIXEL);
    // Half-width 0.5 px at the edge middle region (var = (1, 1)).
    let samples: Vec<(f32, f32)> = (0..200)
        .map(|i| {
            let pixels = i as f32 * 0.005;
            let b = Vec3::new(pixels * PIXEL, 0.5, 0.5 - pixels * PIXEL);
            (pixels, wf::process_wireframe(settings, b, deltas))
        })
        .collect();
    assert!(samples.iter().all(|&(_, c)| c == 0.0 || c == 1.0), "not a step");
    let last_covered = samples
        .iter()
        .filter(|&&(_, c)| c == 1.0)
        .map(|&(p, _)| p)
        .fold(0.0, f32::max);
    let first_uncovered = samples.iter().find(|&&(_, c)| c == 0.0).map(|&(p, _)| p).unwrap();
    println!("smoothing 0: covered up to {last_covered} px, uncovered from {first_uncovered} px");
    assert!(last_covered < 0.5 && (0.5..0.51).contains(&first_uncovered));
    // Coinciding smoothstep edges are defined: zero deltas and zero smoothing give 0 or 1.
    for b in [Vec3::ZERO, Vec3::new(0.0, 0.5, 0.5), Vec3::splat(1.0 / 3.0)] {
        let value = wf::line_width(Vec3::ZERO, 0.5, 0.0, b);
        assert!(value == 0.0 || value == 1.0, "{value}");
        assert_eq!(wf::edge_ramp(b, Vec3::ZERO, Vec3::ZERO), Vec3::ONE);
    }
}

#[test]
fn zero_or_negative_thickness_draws_nothing() {
    let deltas = Vec3::splat(PIXEL);
    for thickness in [0.0, -1.0, -1.0e30] {
        for smoothing in [0.0, 1.0, -2.0] {
            let settings = WireframeSettings {
                thickness,
                smoothing,
                ..wf::WIREFRAME_DEFAULT
            };
            for b in orders(0.0, 0.3, 0.7) {
                assert_eq!(
                    wf::process_wireframe(settings, b, deltas),
                    0.0,
                    "{settings:?} {b}"
                );
            }
        }
    }
}

/// Fraction of `samples` points along an edge (edge position from the middle to a vertex, uniform
/// along the edge) where the dash pattern draws.
fn dash_fraction(repeats: i32, length: f32, samples: usize) -> f32 {
    let drawn = (0..samples)
        .map(|i| (i as f32 + 0.5) / samples as f32)
        .map(|t| wf::edge_position(Vec3::new(0.0, t, 1.0 - t)))
        .filter(|&e| wf::stipple(repeats, length, e) == 1.0)
        .count();
    drawn as f32 / samples as f32
}

#[test]
fn stipple_draws_the_dash_fraction_of_an_edge() {
    for (repeats, length) in [(20, 0.5), (10, 0.8), (8, 0.4), (2, 0.25), (1, 1.0), (4, 0.0)] {
        let fraction = dash_fraction(repeats, length, 100_000);
        println!("stipple repeats {repeats:>2} length {length}: drawn fraction {fraction:.5}");
        assert!(
            (fraction - length).abs() <= 1.0e-3,
            "{repeats} {length}: {fraction}"
        );
    }
    // No dashes for repeats <= 0; the length is clamped to [0, 1].
    for repeats in [0, -1, i32::MIN] {
        assert_eq!(dash_fraction(repeats, 0.3, 1000), 1.0);
    }
    assert_eq!(dash_fraction(20, 1.5, 1000), 1.0);
    assert_eq!(dash_fraction(20, -0.5, 1000), 0.0);
}

#[test]
fn stipple_applies_only_when_on() {
    let deltas = Vec3::splat(PIXEL);
    let edge: Vec<Vec3> = (0..1000)
        .map(|i| Vec3::new(0.0, i as f32 / 999.0, 1.0 - i as f32 / 999.0))
        .collect();
    let covered = |settings: WireframeSettings| {
        edge.iter()
            .filter(|&&b| wf::process_wireframe(settings, b, deltas) == 1.0)
            .count()
    };
    let dashed = covered(wf::WIREFRAME_STIPPLE);
    let solid = covered(WireframeSettings {
        stipple: false,
        ..wf::WIREFRAME_STIPPLE
    });
    println!(
        "stipple preset: {dashed} of {} edge samples covered, {solid} without stipple",
        edge.len()
    );
    assert_eq!(solid, edge.len());
    assert!((dashed as f32 / edge.len() as f32 - 0.5).abs() < 0.02);
    // The wire-line preset dashes with length 1: a solid line.
    assert_eq!(covered(wf::WIREFRAME_WIRE_LINE), edge.len());
}

/// Asserts that `settings` fail validation naming `field`, and that the message names it too.
fn assert_rejects(settings: WireframeSettings, field: &str) {
    let error = settings.validate().expect_err(field);
    assert_eq!(error.field(), field, "{error}");
    assert!(error.to_string().contains(field), "{error}");
    let source: &dyn std::error::Error = &error;
    assert!(source.source().is_none());
}

#[test]
fn validation_names_the_offending_field() {
    let base = wf::WIREFRAME_DEFAULT;
    assert_rejects(
        WireframeSettings {
            thickness: -0.1,
            ..base
        },
        "thickness",
    );
    assert_rejects(
        WireframeSettings {
            thickness: f32::NAN,
            ..base
        },
        "thickness",
    );
    assert_rejects(
        WireframeSettings {
            thickness: 2.0e6,
            ..base
        },
        "thickness",
    );
    assert_rejects(
        WireframeSettings {
            smoothing: f32::INFINITY,
            ..base
        },
        "smoothing",
    );
    assert_rejects(
        WireframeSettings {
            smoothing: -1.0,
            ..base
        },
        "smoothing",
    );
    assert_rejects(
        WireframeSettings {
            thickness_var: Vec2::new(-1.0, 1.0),
            ..base
        },
        "thickness_var.x",
    );
    assert_rejects(
        WireframeSettings {
            thickness_var: Vec2::new(1.0, f32::NAN),
            ..base
        },
        "thickness_var.y",
    );
    assert_rejects(
        WireframeSettings {
            stipple_length: 1.5,
            ..base
        },
        "stipple_length",
    );
    assert_rejects(
        WireframeSettings {
            stipple_length: f32::NEG_INFINITY,
            ..base
        },
        "stipple_length",
    );
    assert_rejects(
        WireframeSettings {
            stipple_repeats: -3,
            ..base
        },
        "stipple_repeats",
    );
    assert_eq!(
        WireframeSettings::try_new(1.0, Vec2::ONE, 1.0, false, 0.5, -1, true).map_err(|e| e.field()),
        Err("stipple_repeats")
    );
    assert!(matches!(
        WireframeSettings::try_new(f32::NAN, Vec2::ONE, 1.0, false, 0.5, 5, true),
        Err(WireframeSettingsError::NotFinite {
            field: "thickness",
            ..
        })
    ));
    for (name, preset) in WireframeSettings::PRESETS {
        assert_eq!(preset.validate(), Ok(()), "{name}");
    }
    assert_eq!(
        WireframeSettings {
            stipple_repeats: 0,
            ..base
        }
        .validate(),
        Ok(())
    );
}

/// The wireframe tutorial's preset table, typed from the tutorial: thickness, thickness_var, smoothing, stipple,
/// stipple_length, stipple_repeats, screen_space.
type TutorialRow = (&'static str, f32, (f32, f32), f32, bool, f32, i32, bool);
const TUTORIAL_PRESETS: [TutorialRow; 7] = [
    ("DEFAULT", 1.0, (1.0, 1.0), 1.0, false, 0.5, 5, true),
    ("WIRE_DOT", 1.0, (1.0, 1.0), 0.5, false, 0.5, 5, true),
    ("STAR", 0.1, (0.0, 1.0), 0.1, false, 0.5, 5, false),
    ("FLAKE", 0.1, (0.7, 0.0), 0.1, true, 0.8, 10, false),
    ("THIN", 0.3, (1.0, 1.0), 2.0, false, 0.4, 8, true),
    ("WIRE_LINE", 0.5, (1.0, 1.0), 1.0, true, 1.0, 1, true),
    ("STIPPLE", 0.5, (1.0, 1.0), 1.0, true, 0.5, 20, true),
];

/// The settings of a row, through [`WireframeSettings::new`], whose arguments follow the tutorial's
/// column order: a constant that differs from it has a wrong value, or `new` takes its arguments
/// in another order.
fn spec_settings(row: &TutorialRow) -> WireframeSettings {
    let &(_, thickness, (x, y), smoothing, stipple, stipple_length, stipple_repeats, screen_space) = row;
    WireframeSettings::new(
        thickness,
        Vec2::new(x, y),
        smoothing,
        stipple,
        stipple_length,
        stipple_repeats,
        screen_space,
    )
}

#[test]
fn presets_have_the_spec_values() {
    let constants = [
        wf::WIREFRAME_DEFAULT,
        wf::WIREFRAME_WIRE_DOT,
        wf::WIREFRAME_STAR,
        wf::WIREFRAME_FLAKE,
        wf::WIREFRAME_THIN,
        wf::WIREFRAME_WIRE_LINE,
        wf::WIREFRAME_STIPPLE,
    ];
    for ((row, constant), (ui_name, listed)) in TUTORIAL_PRESETS
        .iter()
        .zip(constants)
        .zip(WireframeSettings::PRESETS)
    {
        assert_eq!(constant, spec_settings(row), "{}", row.0);
        assert_eq!(listed, constant, "{ui_name}");
        assert_eq!(ui_name.to_uppercase().replace(' ', "_"), row.0);
    }
    assert_eq!(WireframeSettings::default(), wf::WIREFRAME_DEFAULT);
    assert_eq!(WireframeSettingsIo::default().unpack(), wf::WIREFRAME_DEFAULT);
}

/// The constructor call a shader module spells for a preset, from the tutorial's row.
fn shader_constructor(row: &TutorialRow, vec2: &str) -> String {
    let &(name, thickness, (x, y), smoothing, stipple, length, repeats, screen_space) = row;
    format!(
        "RF_WIREFRAME_{name}: RfWireframeSettings = RfWireframeSettings({vec2}({x:?}, {y:?}), {thickness:?}, \
         {smoothing:?}, {stipple}, {length:?}, {repeats}, {screen_space});"
    )
}

#[test]
fn shader_presets_spell_the_spec_values() {
    let wgsl = Module::Wireframe.wgsl();
    // GLSL spells `const RfWireframeSettings NAME = ...`; normalise it to the WGSL order.
    let glsl = Module::Wireframe
        .glsl()
        .replace("const RfWireframeSettings RF_WIREFRAME_", "const RF_WIREFRAME_")
        .replace(
            " = RfWireframeSettings(",
            ": RfWireframeSettings = RfWireframeSettings(",
        );
    for row in &TUTORIAL_PRESETS {
        let wgsl_line = shader_constructor(row, "vec2<f32>");
        let glsl_line = shader_constructor(row, "vec2");
        assert!(wgsl.contains(&wgsl_line), "WGSL lacks `{wgsl_line}`");
        assert!(glsl.contains(&glsl_line), "GLSL lacks `{glsl_line}`");
    }
}

#[test]
fn settings_io_is_32_bytes_with_the_documented_offsets() {
    assert_layout!(WireframeSettingsIo, 32, {
        thickness_var: 0,
        thickness: 8,
        smoothing: 12,
        stipple: 16,
        stipple_length: 20,
        stipple_repeats: 24,
        screen_space: 28,
    });
    let bytes = bytemuck::bytes_of(&wf::WIREFRAME_FLAKE.pack()).to_vec();
    assert_eq!(&bytes[16..20], &1i32.to_le_bytes(), "stipple flag");
    assert_eq!(&bytes[24..28], &10i32.to_le_bytes(), "stipple_repeats");
    assert_eq!(&bytes[28..32], &0i32.to_le_bytes(), "screen_space flag");
}
