//! The degenerate-input rows of `wireframe`.

use super::table::{mirror, parts, same, value, NAN};
use super::{register, Degenerate};
use glam::{Vec2, Vec3};
use ray_footprint::registry::Registered;
use ray_footprint::shaders::Module;
use ray_footprint::wireframe::{self as wf, WireframeSettings, WireframeSettingsIo, WIREFRAME_DEFAULT};
use shader_proptest::tolerance::ulps;

fn settings(f: impl FnOnce(&mut WireframeSettings)) -> WireframeSettings {
    let mut settings = WIREFRAME_DEFAULT;
    f(&mut settings);
    settings
}

pub fn tables() -> Vec<Registered<Box<dyn Degenerate>>> {
    let on_edge = Vec3::new(0.0, 0.5, 0.5);
    let near_edge = Vec3::new(0.004, 0.496, 0.5);
    let deltas = Vec3::splat(0.01);
    let io = WireframeSettingsIo {
        stipple: 7,
        ..WIREFRAME_DEFAULT.pack()
    };
    vec![
        register(
            Module::Wireframe,
            "unpack_wireframe_settings",
            |(io,)| wf::unpack_wireframe_settings(io),
            |_, _| 0.0,
            vec![
                value(
                    "flag 7 (any non-zero)",
                    "true (packed again as 1)",
                    (io,),
                    parts(WireframeSettings {
                        stipple: true,
                        ..WIREFRAME_DEFAULT
                    }),
                ),
                mirror(
                    "NaN in (thickness)",
                    "CPU: kept",
                    (WireframeSettingsIo {
                        thickness: NAN,
                        ..WIREFRAME_DEFAULT.pack()
                    },),
                    parts(WireframeSettings {
                        thickness: NAN,
                        ..WIREFRAME_DEFAULT
                    }),
                ),
                value(
                    "flags 0",
                    "false",
                    (WireframeSettingsIo {
                        stipple: 0,
                        screen_space: 0,
                        ..WIREFRAME_DEFAULT.pack()
                    },),
                    parts(WireframeSettings {
                        stipple: false,
                        screen_space: false,
                        ..WIREFRAME_DEFAULT
                    }),
                ),
                value(
                    "flags -1 (negative)",
                    "true (any non-zero)",
                    (WireframeSettingsIo {
                        stipple: -1,
                        screen_space: -1,
                        ..WIREFRAME_DEFAULT.pack()
                    },),
                    parts(WireframeSettings {
                        stipple: true,
                        screen_space: true,
                        ..WIREFRAME_DEFAULT
                    }),
                ),
            ],
        ),
        register(
            Module::Wireframe,
            "edge_position",
            |(b,)| wf::edge_position(b),
            |_, _| 0.0,
            vec![
                mirror(
                    "NaN in (b.x)",
                    "CPU: max(b.y, b.z) (Rust's `max` ignores NaN)",
                    (Vec3::new(NAN, 0.2, 0.3),),
                    vec![0.3],
                ),
                value("at a vertex (0, 1, 0)", "1", (Vec3::Y,), vec![1.0]),
                value(
                    "at the centroid (1/3 each)",
                    "1/3",
                    (Vec3::splat(1.0 / 3.0),),
                    vec![1.0 / 3.0],
                ),
                value(
                    "outside the triangle (-0.5, 0.75, 0.75)",
                    "0.75, the largest component",
                    (Vec3::new(-0.5, 0.75, 0.75),),
                    vec![0.75],
                ),
            ],
        ),
        register(
            Module::Wireframe,
            "edge_thickness",
            |(var, e)| wf::edge_thickness(var, e),
            |_, e| ulps(4.0, e),
            vec![
                same(
                    "edge position 2",
                    "as edge position 1 (clamped to `[0, 1]`)",
                    (Vec2::new(0.5, 2.0), 2.0),
                    (Vec2::new(0.5, 2.0), 1.0),
                ),
                same(
                    "edge position -1",
                    "as edge position 0",
                    (Vec2::new(0.5, 2.0), -1.0),
                    (Vec2::new(0.5, 2.0), 0.0),
                ),
                same(
                    "negative thickness_var",
                    "as 0",
                    (Vec2::new(-1.0, 2.0), 0.5),
                    (Vec2::new(0.0, 2.0), 0.5),
                ),
            ],
        ),
        register(
            Module::Wireframe,
            "stipple",
            |(repeats, length, e)| wf::stipple(repeats, length, e),
            |_, _| 0.0,
            vec![
                value("repeats 0", "1 (no dashes)", (0, 0.5, 0.3), vec![1.0]),
                value("negative repeats", "1 (no dashes)", (-3, 0.5, 0.3), vec![1.0]),
                value("stipple length 0", "0 (nothing drawn)", (5, 0.0, 0.3), vec![0.0]),
                mirror(
                    "NaN in (stipple length)",
                    "CPU: 0 (pattern < NaN is false)",
                    (5, NAN, 0.3),
                    vec![0.0],
                ),
            ],
        ),
        register(
            Module::Wireframe,
            "edge_ramp",
            |(v, start, width)| wf::edge_ramp(v, start, width),
            |_, e| ulps(4.0, e),
            vec![
                value(
                    "zero ramp width, x = start",
                    "1 (hard step)",
                    (Vec3::splat(0.5), Vec3::splat(0.5), Vec3::ZERO),
                    vec![1.0; 3],
                ),
                value(
                    "zero ramp width, x < start",
                    "0 (hard step)",
                    (Vec3::splat(0.4), Vec3::splat(0.5), Vec3::ZERO),
                    vec![0.0; 3],
                ),
                mirror(
                    "NaN in (x)",
                    "CPU: 1 (NaN < start is false, Rust's `min` ignores NaN)",
                    (Vec3::splat(NAN), Vec3::splat(0.5), Vec3::ONE),
                    vec![1.0; 3],
                ),
            ],
        ),
        register(
            Module::Wireframe,
            "line_width",
            |(d, th, sm, b)| wf::line_width(d, th, sm, b),
            |_, e| ulps(4.0, e),
            vec![
                value(
                    "smoothing 0, inside the line",
                    "1 (hard step)",
                    (deltas, 1.0, 0.0, near_edge),
                    vec![1.0],
                ),
                value(
                    "smoothing 0, outside the line",
                    "0 (hard step)",
                    (deltas, 0.1, 0.0, near_edge),
                    vec![0.0],
                ),
                value(
                    "zero deltas",
                    "0 (a line of zero width)",
                    (Vec3::ZERO, 1.0, 1.0, near_edge),
                    vec![0.0],
                ),
            ],
        ),
        register(
            Module::Wireframe,
            "process_wireframe",
            |(s, b, d)| wf::process_wireframe(s, b, d),
            |_, e| ulps(8.0, e),
            vec![
                value(
                    "smoothing 0, on an edge",
                    "1 (hard step)",
                    (settings(|s| s.smoothing = 0.0), on_edge, deltas),
                    vec![1.0],
                ),
                same(
                    "stipple on, repeats 0",
                    "as stipple off",
                    (
                        settings(|s| {
                            s.stipple = true;
                            s.stipple_repeats = 0
                        }),
                        near_edge,
                        deltas,
                    ),
                    (WIREFRAME_DEFAULT, near_edge, deltas),
                ),
                value(
                    "thickness 0, on an edge",
                    "0 (no line)",
                    (settings(|s| s.thickness = 0.0), on_edge, deltas),
                    vec![0.0],
                ),
                mirror(
                    "NaN in (thickness)",
                    "CPU: 0 (the ramp's NaN bounds compare false)",
                    (settings(|s| s.thickness = NAN), near_edge, deltas),
                    vec![0.0],
                ),
            ],
        ),
    ]
}
