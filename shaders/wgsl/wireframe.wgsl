// ray-footprint: Anti-aliased wireframe from per-pixel barycentric deltas, with the bool-to-int settings mirror.
//
// Library module (no entry points). Twin of shaders/glsl/wireframe.glsl and the Rust mirror
// src/wireframe.rs: same functions, same order, same order of operations. Formulas and sources are
// documented in src/wireframe.rs; "the wireframe tutorial" is NVIDIA's ray-tracing tutorial
// "20 Wireframe" (after nvpro_core2/nvshaders/wireframe.h.slang).
//
// Usage: t = rf_process_wireframe(rf_unpack_wireframe_settings(io), barycentrics, deltas);
// color = mix(shaded, wire_color, t). barycentrics are (w, u, v); deltas their per-pixel spread.
// Undefined cases (coinciding smoothstep edges, no dashes, absurd sizes) are clamped with the RF_
// constants: finite inputs give a finite coverage in [0, 1].

// Largest line half-width, ramp width and thickness_var component used; larger values are clamped.
const RF_MAX_LINE_THICKNESS: f32 = 1.0e6;
// Smallest ramp width evaluated as a smoothstep; narrower ramps are a hard step.
const RF_MIN_LINE_RAMP: f32 = 1.0e-30;

// Wireframe settings with real bools. WGSL forbids bool in host-shareable memory (uniform, storage,
// immediate/push-constant), so this struct only exists as a function value or constant: upload an
// RfWireframeSettingsIo and call rf_unpack_wireframe_settings.
struct RfWireframeSettings {
    thickness_var: vec2<f32>,
    thickness: f32,
    smoothing: f32,
    stipple: bool,
    stipple_length: f32,
    stipple_repeats: i32,
    screen_space: bool,
}

// Host-shareable mirror (32 bytes, no padding; same layout as WGSL, GLSL std430 and scalar, and
// Rust's #[repr(C)] WireframeSettingsIo): every bool is an i32, 0 = false, anything else true.
struct RfWireframeSettingsIo {
    thickness_var: vec2<f32>,
    thickness: f32,
    smoothing: f32,
    stipple: i32,
    stipple_length: f32,
    stipple_repeats: i32,
    screen_space: i32,
}

// Push constants of a wireframe overlay (48 bytes, 16-byte aligned): line colour (rgba) and the
// host-shareable settings.
struct RfWireframePushConstants {
    colour: vec4<f32>,
    settings: RfWireframeSettingsIo,
}

// Presets of the wireframe tutorial, fields in declaration order.
const RF_WIREFRAME_DEFAULT: RfWireframeSettings = RfWireframeSettings(vec2<f32>(1.0, 1.0), 1.0, 1.0, false, 0.5, 5, true);
const RF_WIREFRAME_WIRE_DOT: RfWireframeSettings = RfWireframeSettings(vec2<f32>(1.0, 1.0), 1.0, 0.5, false, 0.5, 5, true);
const RF_WIREFRAME_STAR: RfWireframeSettings = RfWireframeSettings(vec2<f32>(0.0, 1.0), 0.1, 0.1, false, 0.5, 5, false);
const RF_WIREFRAME_FLAKE: RfWireframeSettings = RfWireframeSettings(vec2<f32>(0.7, 0.0), 0.1, 0.1, true, 0.8, 10, false);
const RF_WIREFRAME_THIN: RfWireframeSettings = RfWireframeSettings(vec2<f32>(1.0, 1.0), 0.3, 2.0, false, 0.4, 8, true);
const RF_WIREFRAME_WIRE_LINE: RfWireframeSettings = RfWireframeSettings(vec2<f32>(1.0, 1.0), 0.5, 1.0, true, 1.0, 1, true);
const RF_WIREFRAME_STIPPLE: RfWireframeSettings = RfWireframeSettings(vec2<f32>(1.0, 1.0), 0.5, 1.0, true, 0.5, 20, true);

// Settings from the host-shareable mirror: every integer flag becomes flag != 0.
fn rf_unpack_wireframe_settings(io: RfWireframeSettingsIo) -> RfWireframeSettings {
    return RfWireframeSettings(io.thickness_var, io.thickness, io.smoothing, io.stipple != 0,
        io.stipple_length, io.stipple_repeats, io.screen_space != 0);
}

// Position along the nearest edge: max(b.x, b.y, b.z); 1 at a vertex, 0.5 at an edge middle.
fn rf_edge_position(barycentrics: vec3<f32>) -> f32 {
    return max(max(barycentrics.x, barycentrics.y), barycentrics.z);
}

// Thickness factor along an edge: mix(var.x, var.y, 1 - sin(e pi)), var.x at the middle, var.y at
// the vertices; e and 1 - sin(e pi) clamped to [0, 1] (sin of the f32 nearest pi is negative: no
// extrapolation beyond var), var to [0, RF_MAX_LINE_THICKNESS].
fn rf_edge_thickness(thickness_var: vec2<f32>, edge_position: f32) -> f32 {
    let factors = clamp(thickness_var, vec2<f32>(0.0), vec2<f32>(RF_MAX_LINE_THICKNESS));
    let towards_vertex = clamp(1.0 - sin(clamp(edge_position, 0.0, 1.0) * 3.14159265358979), 0.0, 1.0);
    return mix(factors.x, factors.y, towards_vertex);
}

// Dash pattern: 1 if fract((e + 0.5 length / repeats) repeats) < length, else 0; repeats <= 0 is a
// solid line (1); length and e clamped to [0, 1].
fn rf_stipple(stipple_repeats: i32, stipple_length: f32, edge_position: f32) -> f32 {
    let repeats = f32(max(stipple_repeats, 1));
    let drawn = clamp(stipple_length, 0.0, 1.0);
    let offset = 0.5 * drawn / repeats;
    let period = (clamp(edge_position, 0.0, 1.0) + offset) * repeats;
    let pattern = fract(period);
    return select(1.0, select(0.0, 1.0, pattern < drawn), stipple_repeats > 0);
}

// smoothstep(start, start + width, x) written out, per component: t t (3 - 2 t) with
// t = min((x - start) / max(width, RF_MIN_LINE_RAMP), 1) from start on, 0 below start; 1 from start
// on where width <= RF_MIN_LINE_RAMP (a hard step). Every case is evaluated and one selected per
// component: no branch.
fn rf_edge_ramp(x: vec3<f32>, start: vec3<f32>, width: vec3<f32>) -> vec3<f32> {
    let t = min((x - start) / max(width, vec3<f32>(RF_MIN_LINE_RAMP)), vec3<f32>(1.0));
    let ramp = t * t * (3.0 - 2.0 * t);
    let above_start = select(vec3<f32>(1.0), ramp, width > vec3<f32>(RF_MIN_LINE_RAMP));
    return select(above_start, vec3<f32>(0.0), x < start);
}

// Line coverage: 1 - min_i edge_ramp(b, |d| th, |d| sm)_i, th and sm clamped to
// [0, RF_MAX_LINE_THICKNESS]; 1 on an edge, 0 beyond |d_i| (th + sm) from every edge.
fn rf_line_width(deltas: vec3<f32>, thickness: f32, smoothing: f32, barycentrics: vec3<f32>) -> f32 {
    let magnitude = abs(deltas);
    let start = magnitude * clamp(thickness, 0.0, RF_MAX_LINE_THICKNESS);
    let width = magnitude * clamp(smoothing, 0.0, RF_MAX_LINE_THICKNESS);
    let ramp = rf_edge_ramp(barycentrics, start, width);
    return 1.0 - min(min(ramp.x, ramp.y), ramp.z);
}

// Wireframe coverage in [0, 1]: line_width(d, 0.5 thickness edge_thickness(var, e),
// thickness smoothing, b), times the stipple pattern when on; d = deltas in screen space, else 1.
// A negative thickness is clamped to 0.
fn rf_process_wireframe(settings: RfWireframeSettings, barycentrics: vec3<f32>, deltas: vec3<f32>) -> f32 {
    let e = rf_edge_position(barycentrics);
    let thickness = max(settings.thickness, 0.0);
    let half_width = 0.5 * thickness * rf_edge_thickness(settings.thickness_var, e);
    let ramp_width = thickness * settings.smoothing;
    let pixel_deltas = select(vec3<f32>(1.0), deltas, settings.screen_space);
    let coverage = rf_line_width(pixel_deltas, half_width, ramp_width, barycentrics);
    let dashes = rf_stipple(settings.stipple_repeats, settings.stipple_length, e);
    return coverage * select(1.0, dashes, settings.stipple);
}
