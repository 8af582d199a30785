// ray-footprint: Anti-aliased wireframe from per-pixel barycentric deltas, with the bool-to-int settings mirror.
//
// Library module for GLSL 460 (no main): #include "wireframe.glsl". Twin of shaders/wgsl/wireframe.wgsl
// and the Rust mirror src/wireframe.rs: same functions, same order, same order of operations.
// Formulas and sources are documented in src/wireframe.rs; "the wireframe tutorial" is NVIDIA's
// ray-tracing tutorial "20 Wireframe" (after nvpro_core2/nvshaders/wireframe.h.slang).
//
// Usage: t = rf_process_wireframe(rf_unpack_wireframe_settings(io), barycentrics, deltas);
// color = mix(shaded, wire_color, t). barycentrics are (w, u, v); deltas their per-pixel spread.
// Undefined cases (coinciding smoothstep edges, no dashes, absurd sizes) are clamped with the RF_
// constants: finite inputs give a finite coverage in [0, 1].

#ifndef RAY_FOOTPRINT_WIREFRAME_GLSL
#define RAY_FOOTPRINT_WIREFRAME_GLSL

// Largest line half-width, ramp width and thickness_var component used; larger values are clamped.
const float RF_MAX_LINE_THICKNESS = 1.0e6;
// Smallest ramp width evaluated as a smoothstep; narrower ramps are a hard step.
const float RF_MIN_LINE_RAMP = 1.0e-30;

// Wireframe settings with real bools. Do not put it in a block: a GLSL bool is 4 bytes there and
// 1 byte in Rust and C++. Upload an RfWireframeSettingsIo and call rf_unpack_wireframe_settings.
struct RfWireframeSettings {
    vec2 thickness_var;
    float thickness;
    float smoothing;
    bool stipple;
    float stipple_length;
    int stipple_repeats;
    bool screen_space;
};

// Host-shareable mirror (32 bytes, no padding; same layout under std430 and scalar block layout as
// in WGSL and Rust's #[repr(C)] WireframeSettingsIo): every bool is an int, 0 = false, else true.
struct RfWireframeSettingsIo {
    vec2 thickness_var;
    float thickness;
    float smoothing;
    int stipple;
    float stipple_length;
    int stipple_repeats;
    int screen_space;
};

// Push constants of a wireframe overlay (48 bytes, 16-byte aligned): line colour (rgba) and the
// host-shareable settings.
struct RfWireframePushConstants {
    vec4 colour;
    RfWireframeSettingsIo settings;
};

// Presets of the wireframe tutorial, fields in declaration order.
const RfWireframeSettings RF_WIREFRAME_DEFAULT = RfWireframeSettings(vec2(1.0, 1.0), 1.0, 1.0, false, 0.5, 5, true);
const RfWireframeSettings RF_WIREFRAME_WIRE_DOT = RfWireframeSettings(vec2(1.0, 1.0), 1.0, 0.5, false, 0.5, 5, true);
const RfWireframeSettings RF_WIREFRAME_STAR = RfWireframeSettings(vec2(0.0, 1.0), 0.1, 0.1, false, 0.5, 5, false);
const RfWireframeSettings RF_WIREFRAME_FLAKE = RfWireframeSettings(vec2(0.7, 0.0), 0.1, 0.1, true, 0.8, 10, false);
const RfWireframeSettings RF_WIREFRAME_THIN = RfWireframeSettings(vec2(1.0, 1.0), 0.3, 2.0, false, 0.4, 8, true);
const RfWireframeSettings RF_WIREFRAME_WIRE_LINE = RfWireframeSettings(vec2(1.0, 1.0), 0.5, 1.0, true, 1.0, 1, true);
const RfWireframeSettings RF_WIREFRAME_STIPPLE = RfWireframeSettings(vec2(1.0, 1.0), 0.5, 1.0, true, 0.5, 20, true);

// Settings from the host-shareable mirror: every integer flag becomes flag != 0.
RfWireframeSettings rf_unpack_wireframe_settings(RfWireframeSettingsIo io) {
    return RfWireframeSettings(io.thickness_var, io.thickness, io.smoothing, io.stipple != 0,
        io.stipple_length, io.stipple_repeats, io.screen_space != 0);
}

// Position along the nearest edge: max(b.x, b.y, b.z); 1 at a vertex, 0.5 at an edge middle.
float rf_edge_position(vec3 barycentrics) {
    return max(max(barycentrics.x, barycentrics.y), barycentrics.z);
}

// Thickness factor along an edge: mix(var.x, var.y, 1 - sin(e pi)), var.x at the middle, var.y at
// the vertices; e and 1 - sin(e pi) clamped to [0, 1] (sin of the f32 nearest pi is negative: no
// extrapolation beyond var), var to [0, RF_MAX_LINE_THICKNESS].
float rf_edge_thickness(vec2 thickness_var, float edge_position) {
    vec2 factors = clamp(thickness_var, vec2(0.0), vec2(RF_MAX_LINE_THICKNESS));
    float towards_vertex = clamp(1.0 - sin(clamp(edge_position, 0.0, 1.0) * 3.14159265358979), 0.0, 1.0);
    return mix(factors.x, factors.y, towards_vertex);
}

// Dash pattern: 1 if fract((e + 0.5 length / repeats) repeats) < length, else 0; repeats <= 0 is a
// solid line (1); length and e clamped to [0, 1].
float rf_stipple(int stipple_repeats, float stipple_length, float edge_position) {
    float repeats = float(max(stipple_repeats, 1));
    float drawn = clamp(stipple_length, 0.0, 1.0);
    float offset = 0.5 * drawn / repeats;
    float period = (clamp(edge_position, 0.0, 1.0) + offset) * repeats;
    float pattern = fract(period);
    return mix(1.0, mix(0.0, 1.0, pattern < drawn), stipple_repeats > 0);
}

// smoothstep(start, start + width, x) written out, per component: t t (3 - 2 t) with
// t = min((x - start) / max(width, RF_MIN_LINE_RAMP), 1) from start on, 0 below start; 1 from start
// on where width <= RF_MIN_LINE_RAMP (a hard step). Every case is evaluated and one selected per
// component (mix with a bool vector is OpSelect): no branch.
vec3 rf_edge_ramp(vec3 x, vec3 start, vec3 width) {
    vec3 t = min((x - start) / max(width, vec3(RF_MIN_LINE_RAMP)), 1.0);
    vec3 ramp = t * t * (3.0 - 2.0 * t);
    vec3 above_start = mix(vec3(1.0), ramp, greaterThan(width, vec3(RF_MIN_LINE_RAMP)));
    return mix(above_start, vec3(0.0), lessThan(x, start));
}

// Line coverage: 1 - min_i edge_ramp(b, |d| th, |d| sm)_i, th and sm clamped to
// [0, RF_MAX_LINE_THICKNESS]; 1 on an edge, 0 beyond |d_i| (th + sm) from every edge.
float rf_line_width(vec3 deltas, float thickness, float smoothing, vec3 barycentrics) {
    vec3 magnitude = abs(deltas);
    vec3 start = magnitude * clamp(thickness, 0.0, RF_MAX_LINE_THICKNESS);
    vec3 width = magnitude * clamp(smoothing, 0.0, RF_MAX_LINE_THICKNESS);
    vec3 ramp = rf_edge_ramp(barycentrics, start, width);
    return 1.0 - min(min(ramp.x, ramp.y), ramp.z);
}

// Wireframe coverage in [0, 1]: line_width(d, 0.5 thickness edge_thickness(var, e),
// thickness smoothing, b), times the stipple pattern when on; d = deltas in screen space, else 1.
// A negative thickness is clamped to 0.
float rf_process_wireframe(RfWireframeSettings settings, vec3 barycentrics, vec3 deltas) {
    float e = rf_edge_position(barycentrics);
    float thickness = max(settings.thickness, 0.0);
    float half_width = 0.5 * thickness * rf_edge_thickness(settings.thickness_var, e);
    float ramp_width = thickness * settings.smoothing;
    vec3 pixel_deltas = mix(vec3(1.0), deltas, bvec3(settings.screen_space));
    float coverage = rf_line_width(pixel_deltas, half_width, ramp_width, barycentrics);
    float dashes = rf_stipple(settings.stipple_repeats, settings.stipple_length, e);
    return coverage * mix(1.0, dashes, settings.stipple);
}

#endif // RAY_FOOTPRINT_WIREFRAME_GLSL
