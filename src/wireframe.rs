//! Anti-aliased wireframe from per-pixel barycentric deltas, with the bool-to-int settings mirror.
//!
//! The Rust mirror of `shaders/wgsl/wireframe.wgsl` and `shaders/glsl/wireframe.glsl`. Every function
//! here has a shader twin with the same name prefixed `rf_` (constants `RF_`), in the same order,
//! computing the same expression in the same order of operations.
//!
//! Source: NVIDIA's ray-tracing tutorial "20 Wireframe" (nvpro-samples `vk_raytracing_tutorial_KHR`,
//! after `nvpro_core2/nvshaders/wireframe.h.slang`), cited as "the wireframe tutorial": a hit's
//! barycentrics `b = (w, u, v)` and their per-pixel spread `deltas` (the ray tracer's `fwidth(b)`: the
//! re-intersected or cone-derived barycentric deltas of [`crate::ray_diff`]) give an edge coverage in `[0, 1]` to blend a wire colour with:
//! `color = mix(shaded, wire, process_wireframe(settings, b, deltas))`.
//!
//! The tutorial's styling is a smoothstep per barycentric component against `deltas`, a thickness
//! that varies along each edge, and an optional dash pattern. Its settings carry `bool`s, which cannot
//! cross the CPU/GPU boundary as they are (1 byte in Rust and C++, 4 bytes in GLSL and Slang blocks,
//! not allowed at all in WGSL host-shareable memory), hence the integer mirror
//! [`WireframeSettingsIo`] and [`unpack_wireframe_settings`] / [`WireframeSettings::pack`].
//!
//! Where the tutorial is undefined (a smoothstep whose two edges coincide, a dash count of zero,
//! negative or absurd sizes), the functions clamp with the constants below or take the documented
//! limit, so finite inputs always give a finite coverage in `[0, 1]`.

use bytemuck::{Pod, Zeroable};
use glam::{Vec2, Vec3};
use std::fmt;

/// Largest line half-width, ramp width and `thickness_var` component the functions use; larger values
/// are clamped (a line a million pixels wide already covers any screen). Keeps every product finite.
pub const MAX_LINE_THICKNESS: f32 = 1.0e6;
/// Smallest anti-aliasing ramp width (in barycentric units) evaluated as a smoothstep; narrower ramps
/// (smoothing 0, or a zero delta) are a hard step. A normal float, so no device flushes it to zero.
pub const MIN_LINE_RAMP: f32 = 1.0e-30;

/// How a wireframe is drawn; the shader-side struct `RfWireframeSettings`, with real `bool`s. Never
/// in a uniform, storage or push-constant block (a `bool` has no host layout: 4 bytes in a GLSL block,
/// 1 in Rust, forbidden in WGSL): upload an `RfWireframeSettingsIo` and unpack it.
///
/// Meaning of the fields after the wireframe tutorial's settings. In WGSL this
/// struct can only be a function value or a constant: WGSL forbids `bool` in host-shareable memory
/// (uniform, storage and push-constant blocks), so hosts upload a [`WireframeSettingsIo`] and the
/// shader calls `rf_unpack_wireframe_settings`. GLSL could declare it in a block, but the `bool` is
/// 4 bytes there and 1 byte in Rust: upload the Io mirror there too.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WireframeSettings {
    /// Thickness factors along an edge: `x` at the edge middle, `y` at the vertices.
    pub thickness_var: Vec2,
    /// Line width factor: the line's half-width is `0.5 * thickness * edge_thickness` pixels (in
    /// barycentric units when `screen_space` is off). 0 disables the wireframe.
    pub thickness: f32,
    /// Anti-aliasing ramp width as a multiple of `thickness`; 0 is a hard (aliased) edge.
    pub smoothing: f32,
    /// Whether the line is dashed.
    pub stipple: bool,
    /// Fraction of each dash period that is drawn, in `[0, 1]` (clamped).
    pub stipple_length: f32,
    /// Dash periods per edge (each half, from the edge middle to a vertex, holds half of them);
    /// `<= 0` draws no dashes (a solid line).
    pub stipple_repeats: i32,
    /// `true`: `deltas` are per-pixel barycentric deltas and `thickness` is in pixels. `false`:
    /// deltas are taken as 1 and `thickness` is in barycentric units (the tutorial declares this flag
    /// but never reads it; this crate gives it this meaning).
    pub screen_space: bool,
}

/// The host-shareable mirror of [`WireframeSettings`] (`RfWireframeSettingsIo`): every `bool` is an
/// `i32`, 0 = false and any other value true (the wireframe tutorial's "bool as int" push-constant
/// field, `WireframeSettingsIO`).
///
/// Layout: 32 bytes, no padding, identical in Rust (`#[repr(C)]`), WGSL, GLSL std430 and GLSL scalar
/// block layout. `thickness_var` comes first because a `vec2` is 8-byte aligned in WGSL and std430
/// (the struct is 8-byte aligned in Rust too, so it sits at the same offset inside other structs);
/// every later field is a 4-byte scalar at a multiple of 4, and 32 is a multiple of 8:
///
/// | field | offset |
/// |---|---|
/// | `thickness_var` | 0 |
/// | `thickness` | 8 |
/// | `smoothing` | 12 |
/// | `stipple` | 16 |
/// | `stipple_length` | 20 |
/// | `stipple_repeats` | 24 |
/// | `screen_space` | 28 |
#[repr(C, align(8))]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct WireframeSettingsIo {
    /// As [`WireframeSettings::thickness_var`].
    pub thickness_var: Vec2,
    /// As [`WireframeSettings::thickness`].
    pub thickness: f32,
    /// As [`WireframeSettings::smoothing`].
    pub smoothing: f32,
    /// [`WireframeSettings::stipple`]: 0 = false, anything else true.
    pub stipple: i32,
    /// As [`WireframeSettings::stipple_length`].
    pub stipple_length: f32,
    /// As [`WireframeSettings::stipple_repeats`] (an `int` in the tutorial's settings).
    pub stipple_repeats: i32,
    /// [`WireframeSettings::screen_space`]: 0 = false, anything else true.
    pub screen_space: i32,
}

const _: () = assert!(std::mem::size_of::<WireframeSettingsIo>() == 32);
const _: () = assert!(std::mem::offset_of!(WireframeSettingsIo, thickness) == 8);
const _: () = assert!(std::mem::offset_of!(WireframeSettingsIo, stipple) == 16);
const _: () = assert!(std::mem::offset_of!(WireframeSettingsIo, screen_space) == 28);

/// Preset "default" (wireframe tutorial): an anti-aliased solid line about 2 pixels of ink wide
/// across an edge, a 1-pixel core (half a pixel on each triangle's side) fading over 1 more pixel
/// on each side. For a hard 1-pixel line, set `smoothing` to 0.
///
/// Each triangle covers `b < 0.5 d` fully and ramps down until `b = 1.5 d` (`d` the barycentric
/// change per pixel), so the two triangles of an edge ink `1 + 2 * 0.5 = 2` pixels.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::wireframe::{process_wireframe, WIREFRAME_DEFAULT};
///
/// // The ink of one triangle's side of an edge, summed over 1/100-pixel steps away from it with
/// // barycentric changes of 0.01 per pixel: 1 pixel, so 2 for the edge's two triangles.
/// let deltas = Vec3::splat(0.01);
/// let ink: f32 = (0..1000)
///     .map(|i| (i as f32 + 0.5) / 100.0)
///     .map(|pixels| process_wireframe(WIREFRAME_DEFAULT, Vec3::new(0.5, 0.01 * pixels, 0.5), deltas) / 100.0)
///     .sum();
/// assert!((2.0 * ink - 2.0).abs() < 0.01);
/// // Smoothing 0 makes it a hard line of 1 pixel.
/// let hard = ray_footprint::wireframe::WireframeSettings { smoothing: 0.0, ..WIREFRAME_DEFAULT };
/// assert_eq!(process_wireframe(hard, Vec3::new(0.5, 0.0049, 0.5), deltas), 1.0);
/// assert_eq!(process_wireframe(hard, Vec3::new(0.5, 0.0051, 0.5), deltas), 0.0);
/// ```
pub const WIREFRAME_DEFAULT: WireframeSettings = WireframeSettings {
    thickness_var: Vec2::new(1.0, 1.0),
    thickness: 1.0,
    smoothing: 1.0,
    stipple: false,
    stipple_length: 0.5,
    stipple_repeats: 5,
    screen_space: true,
};
/// Preset "wire dot": as the default with a ramp half as wide.
pub const WIREFRAME_WIRE_DOT: WireframeSettings = WireframeSettings {
    thickness_var: Vec2::new(1.0, 1.0),
    thickness: 1.0,
    smoothing: 0.5,
    stipple: false,
    stipple_length: 0.5,
    stipple_repeats: 5,
    screen_space: true,
};
/// Preset "star": thin barycentric-space lines that vanish at edge middles and grow to the vertices.
pub const WIREFRAME_STAR: WireframeSettings = WireframeSettings {
    thickness_var: Vec2::new(0.0, 1.0),
    thickness: 0.1,
    smoothing: 0.1,
    stipple: false,
    stipple_length: 0.5,
    stipple_repeats: 5,
    screen_space: false,
};
/// Preset "flake": dashed barycentric-space lines, widest at edge middles, vanishing at the vertices.
pub const WIREFRAME_FLAKE: WireframeSettings = WireframeSettings {
    thickness_var: Vec2::new(0.7, 0.0),
    thickness: 0.1,
    smoothing: 0.1,
    stipple: true,
    stipple_length: 0.8,
    stipple_repeats: 10,
    screen_space: false,
};
/// Preset "thin": a 0.3-pixel line with a wide (2x) anti-aliasing ramp.
pub const WIREFRAME_THIN: WireframeSettings = WireframeSettings {
    thickness_var: Vec2::new(1.0, 1.0),
    thickness: 0.3,
    smoothing: 2.0,
    stipple: false,
    stipple_length: 0.4,
    stipple_repeats: 8,
    screen_space: true,
};
/// Preset "wire line": stipple on with dashes covering the whole period, so a solid half-pixel line.
pub const WIREFRAME_WIRE_LINE: WireframeSettings = WireframeSettings {
    thickness_var: Vec2::new(1.0, 1.0),
    thickness: 0.5,
    smoothing: 1.0,
    stipple: true,
    stipple_length: 1.0,
    stipple_repeats: 1,
    screen_space: true,
};
/// Preset "stipple": a half-pixel line in 20 dashes per edge, half of each period drawn.
pub const WIREFRAME_STIPPLE: WireframeSettings = WireframeSettings {
    thickness_var: Vec2::new(1.0, 1.0),
    thickness: 0.5,
    smoothing: 1.0,
    stipple: true,
    stipple_length: 0.5,
    stipple_repeats: 20,
    screen_space: true,
};

// ---- Settings from the host ----

/// Turns the host-shareable mirror back into settings: every integer flag becomes `flag != 0`
/// (the wireframe tutorial's `unpackWireframeSettings`).
///
/// # Examples
///
/// ```
/// use ray_footprint::wireframe::{unpack_wireframe_settings, WIREFRAME_STIPPLE};
///
/// // Packing and unpacking gives the settings back; any non-zero integer is true, as in GLSL's bool(int).
/// let mut io = WIREFRAME_STIPPLE.pack();
/// assert_eq!(unpack_wireframe_settings(io), WIREFRAME_STIPPLE);
/// io.screen_space = -7;
/// assert!(unpack_wireframe_settings(io).screen_space);
/// ```
pub fn unpack_wireframe_settings(io: WireframeSettingsIo) -> WireframeSettings {
    WireframeSettings {
        thickness_var: io.thickness_var,
        thickness: io.thickness,
        smoothing: io.smoothing,
        stipple: io.stipple != 0,
        stipple_length: io.stipple_length,
        stipple_repeats: io.stipple_repeats,
        screen_space: io.screen_space != 0,
    }
}

// ---- Coverage (wireframe tutorial) ----

/// Position along the nearest edge (wireframe tutorial, `edgePosition`):
/// `e = max(b.x, b.y, b.z)`, 1 at a vertex and 0.5 at an edge middle (1/3 at the centroid).
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::wireframe::edge_position;
///
/// // 1/3 at the centroid, 1/2 in the middle of an edge, 1 at a vertex.
/// assert_eq!(edge_position(Vec3::splat(1.0 / 3.0)), 1.0 / 3.0);
/// assert_eq!(edge_position(Vec3::new(0.5, 0.0, 0.5)), 0.5);
/// assert_eq!(edge_position(Vec3::new(0.0, 1.0, 0.0)), 1.0);
/// ```
pub fn edge_position(barycentrics: Vec3) -> f32 {
    barycentrics.x.max(barycentrics.y).max(barycentrics.z)
}

/// Thickness factor at edge position `e` (wireframe tutorial, `edgeThickness`):
/// `mix(var.x, var.y, 1 - sin(e * pi))`, so `var.x` at an edge middle and `var.y` at a vertex.
///
/// `mix(x, y, a)` is spelled as GLSL defines it, `x * (1 - a) + y * a`. Clamps: `e` to `[0, 1]` (its
/// range for barycentrics, which also keeps `sin` inside `[-pi, pi]` where its precision is
/// specified); `a = 1 - sin(e * pi)` to `[0, 1]`, because `sin` of the f32 nearest pi is slightly
/// negative (and a device's `sin` may be off by 2^-11), which would extrapolate beyond `var` (at a
/// vertex, `var = (1e6, 0.1)` would give a negative thickness); each `thickness_var` component to
/// `[0, MAX_LINE_THICKNESS]`. The result lies between the two clamped factors.
///
/// # Examples
///
/// ```
/// use glam::Vec2;
/// use ray_footprint::wireframe::edge_thickness;
///
/// // Twice as thick in the middle of an edge (e = 1/2) as at its vertices (e = 1); at e = 5/6,
/// // sin(5 pi / 6) = 1/2 puts it half way, 1.5.
/// let var = Vec2::new(2.0, 1.0);
/// assert!((edge_thickness(var, 0.5) - 2.0).abs() < 1e-6);
/// assert!((edge_thickness(var, 5.0 / 6.0) - 1.5).abs() < 1e-6);
/// assert_eq!(edge_thickness(var, 1.0), 1.0);
/// ```
pub fn edge_thickness(thickness_var: Vec2, edge_position: f32) -> f32 {
    let factors = thickness_var.clamp(Vec2::ZERO, Vec2::splat(MAX_LINE_THICKNESS));
    let towards_vertex = (1.0 - (edge_position.clamp(0.0, 1.0) * std::f32::consts::PI).sin()).clamp(0.0, 1.0);
    factors.x * (1.0 - towards_vertex) + factors.y * towards_vertex
}

/// Dash pattern along an edge, 1 where the line is drawn and 0 in the gaps (wireframe tutorial,
/// `stipple`): `offset = 0.5 * length / repeats`, `pattern = fract((e + offset) * repeats)`,
/// 1 if `pattern < length`.
///
/// `fract(x)` is `x - floor(x)`, as in GLSL and WGSL (not Rust's `f32::fract`). Defined beyond the
/// tutorial: `stipple_repeats <= 0` draws no dashes (returns 1); `stipple_length` is clamped to
/// `[0, 1]` (1 = a solid line, 0 = nothing drawn) and `e` to `[0, 1]`.
///
/// # Examples
///
/// ```
/// use ray_footprint::wireframe::stipple;
///
/// // Five dash periods per edge, half of each drawn: the dashes are centred on the multiples of 1/5,
/// // each 1/10 long. Drawn at e = 0.6, a gap at e = 0.7 (half way to the next dash).
/// assert_eq!(stipple(5, 0.5, 0.6), 1.0);
/// assert_eq!(stipple(5, 0.5, 0.7), 0.0);
/// assert_eq!(stipple(5, 0.5, 1.0), 1.0); // a vertex is covered
/// assert_eq!(stipple(0, 0.5, 0.7), 1.0); // no repeats: a solid line
/// ```
pub fn stipple(stipple_repeats: i32, stipple_length: f32, edge_position: f32) -> f32 {
    let repeats = stipple_repeats.max(1) as f32;
    let drawn = stipple_length.clamp(0.0, 1.0);
    let offset = 0.5 * drawn / repeats;
    let period = (edge_position.clamp(0.0, 1.0) + offset) * repeats;
    let pattern = period - period.floor();
    let dash = if pattern < drawn { 1.0 } else { 0.0 };
    if stipple_repeats > 0 {
        dash
    } else {
        1.0
    }
}

/// The distance-to-edge ramp of each barycentric component: 0 below `start`, then the smoothstep
/// `t * t * (3 - 2 * t)` with `t = min((x - start) / width, 1)`, reaching 1 at `start + width`;
/// component by component.
///
/// This is `smoothstep(start, start + width, x)` of the wireframe tutorial's `getLineWidth`, written
/// out so that it is defined everywhere: a ramp narrower than `MIN_LINE_RAMP` (including zero, where
/// `smoothstep` is undefined) is the hard step `x < start ? 0 : 1`. The shaders evaluate the ramp
/// (dividing by `max(width, MIN_LINE_RAMP)`), the step and the part below `start` on all three
/// components at once and select per component: no branch, one vector instruction per step. The
/// selects never pass on the quotient of a discarded case (an overflowed `start` and `width` give
/// `-inf / inf`).
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::wireframe::edge_ramp;
///
/// // smoothstep(0.1, 0.3, x): 0 below 0.1; 3 t^2 - 2 t^3 above, with t = (x - 0.1) / 0.2: 1/2 at
/// // t = 1/2, 3/16 - 2/64 = 0.15625 at t = 1/4.
/// let ramp = edge_ramp(Vec3::new(0.05, 0.2, 0.15), Vec3::splat(0.1), Vec3::splat(0.2));
/// assert!((ramp - Vec3::new(0.0, 0.5, 0.15625)).length() < 1e-6);
/// // A ramp of width 0 is a hard step.
/// let step = edge_ramp(Vec3::new(0.09, 0.1, 0.11), Vec3::splat(0.1), Vec3::ZERO);
/// assert_eq!(step, Vec3::new(0.0, 1.0, 1.0));
/// ```
pub fn edge_ramp(x: Vec3, start: Vec3, width: Vec3) -> Vec3 {
    let t = ((x - start) / width.max(Vec3::splat(MIN_LINE_RAMP))).min(Vec3::ONE);
    let ramp = t * t * (3.0 - 2.0 * t);
    let above_start = Vec3::select(width.cmpgt(Vec3::splat(MIN_LINE_RAMP)), ramp, Vec3::ONE);
    Vec3::select(x.cmplt(start), Vec3::ZERO, above_start)
}

/// Line coverage from the barycentrics and their per-pixel deltas (wireframe tutorial,
/// `getLineWidth`): per component `s_i = smoothstep(d_i * th, d_i * (th + sm), b_i)`, coverage
/// `1 - min(s_i)`; 1 on an edge, 0 farther than `d_i * (th + sm)` from every edge.
///
/// Evaluated as [`edge_ramp`]`(b, d * th, d * sm)` with `d = |deltas|` (deltas are magnitudes;
/// the ramp width is the product `d_i * sm` itself, not a difference of edges, so it neither cancels
/// nor overflows into `inf - inf`). `thickness` (`th`) and `smoothing` (`sm`) are clamped to
/// `[0, MAX_LINE_THICKNESS]`. A zero delta or zero smoothing gives a hard step.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::wireframe::line_width;
///
/// // Barycentric deltas of 0.01 per pixel, a line 1 pixel from the edge then a 1-pixel ramp:
/// let deltas = Vec3::splat(0.01);
/// // covered on the edge (u = 0), half covered 1.5 pixels away (the middle of the ramp), not at all
/// // 3 pixels from every edge.
/// assert_eq!(line_width(deltas, 1.0, 1.0, Vec3::new(0.6, 0.0, 0.4)), 1.0);
/// assert!((line_width(deltas, 1.0, 1.0, Vec3::new(0.5, 0.015, 0.485)) - 0.5).abs() < 1e-5);
/// assert_eq!(line_width(deltas, 1.0, 1.0, Vec3::new(0.4, 0.3, 0.3)), 0.0);
/// ```
pub fn line_width(deltas: Vec3, thickness: f32, smoothing: f32, barycentrics: Vec3) -> f32 {
    let magnitude = deltas.abs();
    let start = magnitude * thickness.clamp(0.0, MAX_LINE_THICKNESS);
    let width = magnitude * smoothing.clamp(0.0, MAX_LINE_THICKNESS);
    let ramp = edge_ramp(barycentrics, start, width);
    1.0 - ramp.x.min(ramp.y).min(ramp.z)
}

/// Wireframe coverage in `[0, 1]` of a hit (wireframe tutorial, `processWireframe`):
/// `e = edge_position(b)`, `th = 0.5 * thickness * edge_thickness(var, e)`, `sm = thickness * smoothing`,
/// coverage `line_width(d, th, sm, b)`, times `stipple(repeats, length, e)` when `stipple` is on.
///
/// `d` is `deltas` when `screen_space` is on and `(1, 1, 1)` otherwise (thickness in barycentric
/// units). A negative `thickness` is clamped to 0 (no line) before either product.
///
/// Cost: the clamps that keep every product finite, the hard step at a zero ramp width, the ramp
/// taken over its width (defined where the width is below half an ulp of the ramp's start, where
/// `smoothstep(start, start + width, x)` is not) and the stipple pattern always evaluated and
/// selected. On an NVIDIA H200 the shader function takes 1.65 times nvpro's `processWireframe`,
/// and 1.06 times nvpro's with the same guards added around it and inside it, where the hard step
/// costs 0.00026 ns a call and the ramp over its width 0.00024 ns.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::wireframe::{process_wireframe, WIREFRAME_DEFAULT};
///
/// // The default line is 1 pixel wide (0.5 pixel either side of the edge) with a 1-pixel ramp: with
/// // deltas of 0.01 per pixel a hit 1 pixel from an edge is half way up the ramp, half covered.
/// let deltas = Vec3::splat(0.01);
/// assert_eq!(process_wireframe(WIREFRAME_DEFAULT, Vec3::new(0.0, 0.5, 0.5), deltas), 1.0);
/// let coverage = process_wireframe(WIREFRAME_DEFAULT, Vec3::new(0.01, 0.5, 0.49), deltas);
/// assert!((coverage - 0.5).abs() < 1e-5);
/// ```
pub fn process_wireframe(settings: WireframeSettings, barycentrics: Vec3, deltas: Vec3) -> f32 {
    let e = edge_position(barycentrics);
    let thickness = settings.thickness.max(0.0);
    let half_width = 0.5 * thickness * edge_thickness(settings.thickness_var, e);
    let ramp_width = thickness * settings.smoothing;
    let pixel_deltas = if settings.screen_space { deltas } else { Vec3::ONE };
    let coverage = line_width(pixel_deltas, half_width, ramp_width, barycentrics);
    let dashes = stipple(settings.stipple_repeats, settings.stipple_length, e);
    coverage * if settings.stipple { dashes } else { 1.0 }
}

impl WireframeSettings {
    /// Every preset with a display name for a UI, in the order of the wireframe
    /// tutorial's preset table.
    pub const PRESETS: [(&'static str, WireframeSettings); 7] = [
        ("Default", WIREFRAME_DEFAULT),
        ("Wire dot", WIREFRAME_WIRE_DOT),
        ("Star", WIREFRAME_STAR),
        ("Flake", WIREFRAME_FLAKE),
        ("Thin", WIREFRAME_THIN),
        ("Wire line", WIREFRAME_WIRE_LINE),
        ("Stipple", WIREFRAME_STIPPLE),
    ];

    /// Settings in the tutorial's column order, unchecked (the shader functions clamp as documented;
    /// use [`WireframeSettings::try_new`] for values that come from a user).
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec2;
    /// use ray_footprint::wireframe::{WireframeSettings, WIREFRAME_DEFAULT};
    ///
    /// // The tutorial's default row: thickness 1, var (1, 1), smoothing 1, no stipple (length 0.5,
    /// // 5 repeats), screen space.
    /// let settings = WireframeSettings::new(1.0, Vec2::ONE, 1.0, false, 0.5, 5, true);
    /// assert_eq!(settings, WIREFRAME_DEFAULT);
    /// ```
    pub const fn new(
        thickness: f32,
        thickness_var: Vec2,
        smoothing: f32,
        stipple: bool,
        stipple_length: f32,
        stipple_repeats: i32,
        screen_space: bool,
    ) -> WireframeSettings {
        WireframeSettings {
            thickness_var,
            thickness,
            smoothing,
            stipple,
            stipple_length,
            stipple_repeats,
            screen_space,
        }
    }

    /// As [`WireframeSettings::new`], rejecting what [`WireframeSettings::validate`] rejects.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec2;
    /// use ray_footprint::wireframe::WireframeSettings;
    ///
    /// // A UI slider that went below zero: the error names the field.
    /// let error = WireframeSettings::try_new(-0.5, Vec2::ONE, 1.0, false, 0.5, 5, true).unwrap_err();
    /// assert_eq!(error.field(), "thickness");
    /// assert!(WireframeSettings::try_new(0.5, Vec2::ONE, 1.0, true, 0.5, 20, true).is_ok());
    /// ```
    pub fn try_new(
        thickness: f32,
        thickness_var: Vec2,
        smoothing: f32,
        stipple: bool,
        stipple_length: f32,
        stipple_repeats: i32,
        screen_space: bool,
    ) -> Result<WireframeSettings, WireframeSettingsError> {
        let settings = WireframeSettings::new(
            thickness,
            thickness_var,
            smoothing,
            stipple,
            stipple_length,
            stipple_repeats,
            screen_space,
        );
        settings.validate().map(|()| settings)
    }

    /// Checks the values a UI should never send, naming the first offending field in declaration
    /// order: every float finite; `thickness`, both `thickness_var` components and `smoothing` in
    /// `[0, MAX_LINE_THICKNESS]`; `stipple_length` in `[0, 1]`; `stipple_repeats >= 0`.
    ///
    /// The shader functions accept anything finite and clamp; this is for catching mistakes early.
    ///
    /// # Examples
    ///
    /// ```
    /// use ray_footprint::wireframe::{WireframeSettings, WireframeSettingsError};
    ///
    /// // Every preset is valid; a NaN smoothing is not.
    /// assert!(WireframeSettings::PRESETS.iter().all(|(_, preset)| preset.validate().is_ok()));
    /// let broken = WireframeSettings { smoothing: f32::NAN, ..Default::default() };
    /// assert!(matches!(
    ///     broken.validate(),
    ///     Err(WireframeSettingsError::NotFinite { field: "smoothing", .. })
    /// ));
    /// ```
    pub fn validate(&self) -> Result<(), WireframeSettingsError> {
        let sizes = [
            ("thickness_var.x", self.thickness_var.x),
            ("thickness_var.y", self.thickness_var.y),
            ("thickness", self.thickness),
            ("smoothing", self.smoothing),
        ];
        for (field, value) in sizes {
            WireframeSettingsError::check_range(field, value, 0.0, MAX_LINE_THICKNESS)?;
        }
        WireframeSettingsError::check_range("stipple_length", self.stipple_length, 0.0, 1.0)?;
        if self.stipple_repeats < 0 {
            return Err(WireframeSettingsError::NegativeRepeats {
                value: self.stipple_repeats,
            });
        }
        Ok(())
    }

    /// The host-shareable mirror; every `bool` becomes exactly 0 or 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use ray_footprint::wireframe::WIREFRAME_FLAKE;
    ///
    /// // The flake preset's stipple flag (true) becomes the i32 1 at byte 16, and its screen_space
    /// // flag (false) the i32 0 at byte 28, as the 32-byte layout says.
    /// let io = WIREFRAME_FLAKE.pack();
    /// let bytes = bytemuck::bytes_of(&io);
    /// assert_eq!(bytes.len(), 32);
    /// assert_eq!(bytes[16..20], 1i32.to_ne_bytes());
    /// assert_eq!(bytes[28..32], 0i32.to_ne_bytes());
    /// ```
    pub fn pack(self) -> WireframeSettingsIo {
        WireframeSettingsIo {
            thickness_var: self.thickness_var,
            thickness: self.thickness,
            smoothing: self.smoothing,
            stipple: i32::from(self.stipple),
            stipple_length: self.stipple_length,
            stipple_repeats: self.stipple_repeats,
            screen_space: i32::from(self.screen_space),
        }
    }
}

impl Default for WireframeSettings {
    /// [`WIREFRAME_DEFAULT`].
    fn default() -> Self {
        WIREFRAME_DEFAULT
    }
}

impl WireframeSettingsIo {
    /// The settings, as [`unpack_wireframe_settings`].
    ///
    /// # Examples
    ///
    /// ```
    /// use ray_footprint::wireframe::WireframeSettings;
    ///
    /// // Every preset survives the trip to the GPU's integer form and back.
    /// for (name, preset) in WireframeSettings::PRESETS {
    ///     assert_eq!(preset.pack().unpack(), preset, "{name}");
    /// }
    /// ```
    pub fn unpack(self) -> WireframeSettings {
        unpack_wireframe_settings(self)
    }
}

impl Default for WireframeSettingsIo {
    /// [`WIREFRAME_DEFAULT`], packed.
    fn default() -> Self {
        WIREFRAME_DEFAULT.pack()
    }
}

impl From<WireframeSettings> for WireframeSettingsIo {
    fn from(settings: WireframeSettings) -> Self {
        settings.pack()
    }
}

impl From<WireframeSettingsIo> for WireframeSettings {
    fn from(io: WireframeSettingsIo) -> Self {
        unpack_wireframe_settings(io)
    }
}

/// A settings value a UI should never send; returned by [`WireframeSettings::validate`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WireframeSettingsError {
    /// A float field is NaN or infinite.
    NotFinite {
        /// The field, e.g. `"thickness"` or `"thickness_var.y"`.
        field: &'static str,
        /// The value received.
        value: f32,
    },
    /// A float field lies outside its range.
    OutOfRange {
        /// The field, e.g. `"stipple_length"`.
        field: &'static str,
        /// The value received.
        value: f32,
        /// Smallest accepted value.
        min: f32,
        /// Largest accepted value.
        max: f32,
    },
    /// `stipple_repeats` is negative (0 is accepted and means a solid line).
    NegativeRepeats {
        /// The value received.
        value: i32,
    },
}

impl WireframeSettingsError {
    /// `Ok` when `value` is finite and in `[min, max]`, else the error naming `field`.
    fn check_range(
        field: &'static str,
        value: f32,
        min: f32,
        max: f32,
    ) -> Result<(), WireframeSettingsError> {
        if !value.is_finite() {
            Err(WireframeSettingsError::NotFinite { field, value })
        } else if !(min..=max).contains(&value) {
            Err(WireframeSettingsError::OutOfRange {
                field,
                value,
                min,
                max,
            })
        } else {
            Ok(())
        }
    }

    /// The name of the offending field.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec2;
    /// use ray_footprint::wireframe::WireframeSettings;
    ///
    /// // A dash length above 1 is caught, naming the field for the UI to highlight.
    /// let error = WireframeSettings::try_new(1.0, Vec2::ONE, 1.0, true, 1.5, 5, true).unwrap_err();
    /// assert_eq!(error.field(), "stipple_length");
    /// assert_eq!(error.to_string(), "wireframe setting `stipple_length` must lie in [0, 1], got 1.5");
    /// ```
    pub fn field(&self) -> &'static str {
        match self {
            WireframeSettingsError::NotFinite { field, .. }
            | WireframeSettingsError::OutOfRange { field, .. } => field,
            WireframeSettingsError::NegativeRepeats { .. } => "stipple_repeats",
        }
    }
}

impl fmt::Display for WireframeSettingsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WireframeSettingsError::NotFinite { field, value } => {
                write!(f, "wireframe setting `{field}` must be finite, got {value}")
            }
            WireframeSettingsError::OutOfRange {
                field,
                value,
                min,
                max,
            } => write!(
                f,
                "wireframe setting `{field}` must lie in [{min}, {max}], got {value}"
            ),
            WireframeSettingsError::NegativeRepeats { value } => write!(
                f,
                "wireframe setting `stipple_repeats` must be >= 0 (0 = solid line), got {value}"
            ),
        }
    }
}

impl std::error::Error for WireframeSettingsError {}
