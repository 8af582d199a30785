//! The proof of [`unpack_wireframe_settings`](ray_footprint::wireframe::unpack_wireframe_settings):
//! its record, its case strategy and its reference.

use crate::degenerate::{mirror, parts, value, NAN};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::one_argument;
use crate::wireframe::strategy::settings;
use proptest::prelude::*;
use ray_footprint::shaders::Module;
use ray_footprint::wireframe::{self as wf, WireframeSettings, WireframeSettingsIo, WIREFRAME_DEFAULT};
use shader_proptest::one_of;
use shader_proptest::{Args, Value};

/// The record of `rf_unpack_wireframe_settings`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let io = WireframeSettingsIo {
        stipple: 7,
        ..WIREFRAME_DEFAULT.pack()
    };
    // Copies and integer comparisons: exact.
    Record::new(
        Module::Wireframe,
        "unpack_wireframe_settings",
        |(io,)| wf::unpack_wireframe_settings(io),
        || one_argument(settings_io()),
    )
    .reference(reference())
    .without_symmetry("a field-by-field copy of the settings' words: no length, frame or order")
    .fuzz(|d| (d.settings_io(),))
    .degenerate(vec![
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
    ])
}

/// An integer flag of the Io mirror: 0, 1, -1 and any other `i32`.
fn flag() -> BoxedStrategy<i32> {
    one_of![
        2 => Just(0i32),
        2 => Just(1i32),
        1 => Just(-1i32),
        2 => any::<i32>(),
    ]
    .boxed()
}

/// Io mirrors with arbitrary integers in the flags (negative ones included) and bit-exact floats.
fn settings_io() -> BoxedStrategy<WireframeSettingsIo> {
    (settings(), flag(), flag())
        .prop_map(|(settings, stipple, screen_space)| WireframeSettingsIo {
            stipple,
            screen_space,
            ..settings.pack()
        })
        .boxed()
}

/// The reference of `rf_unpack_wireframe_settings`.
fn reference() -> Reference<(WireframeSettingsIo,), WireframeSettings> {
    Reference::new(
        Kind::Identity,
        "packing the unpacked settings gives the Io mirror back with each flag 0 or 1 (0 where it was 0), every float bit for bit",
        settings_io,
        |&io, unpack_wireframe_settings| {
            let packed = unpack_wireframe_settings((io,)).pack();
            let flag = |x: i32| i32::from(x != 0);
            let expected = WireframeSettingsIo {
                stipple: flag(io.stipple),
                screen_space: flag(io.screen_space),
                ..io
            };
            // Copies and comparisons: exact, bit for bit (NaN payloads included).
            let same = bytemuck::bytes_of(&packed) == bytemuck::bytes_of(&expected);
            Some(Deviation::new(if same { 0.0 } else { 1.0 }, 0.0))
        },
    )
}
