//! Error bounds of the wireframe records: the largest `|device - mirror|` of each function, and
//! where the coverage is ambiguous (either side of a threshold is right).

use glam::{Vec2, Vec3};
use ray_footprint::wireframe::{self as wf, WireframeSettings, MAX_LINE_THICKNESS, MIN_LINE_RAMP};
use shader_proptest::tolerance::{ulps, SIN_COS_ERROR, ULP};

/// Largest slope of the smoothstep `t * t * (3 - 2 * t)`, `6 t (1 - t)`, over `[t - dt, t + dt]`:
/// at the point of that interval nearest to 1/2.
pub(super) fn ramp_slope(t: f32, dt: f32) -> f32 {
    let nearest = 0.5f32.clamp(t - dt, t + dt).clamp(0.0, 1.0);
    6.0 * nearest * (1.0 - nearest)
}

/// Largest `|device - mirror|` of `edge_ramp(x, start, width)` when the device's `start` may be off
/// by `start_error`. Hard step: either side within `start_error` of the step, else exact. Ramp: the
/// numerator `x - start` is off by `start_error` plus one rounding, the quotient by 3 ULP (2.5 for
/// the device's division, 0.5 for the mirror's); through the smoothstep's slope, plus 8 ULP for the
/// three products and one difference of the polynomial on each side.
pub(super) fn edge_ramp_error(x: f32, start: f32, width: f32, start_error: f32) -> f32 {
    if width <= MIN_LINE_RAMP {
        let near_step = start_error > 0.0 && (x - start).abs() <= start_error;
        return if near_step { 1.0 } else { 0.0 };
    }
    if x < start - start_error {
        return 0.0;
    }
    let t = ((x - start) / width).clamp(0.0, 1.0);
    let dt = (start_error + ulps(1.0, x - start)) / width + ulps(3.0, t);
    ramp_slope(t, dt) * dt + ulps(8.0, 1.0)
}

/// Largest `|device - mirror|` of `line_width(deltas, thickness, smoothing, b)` when the device's
/// `thickness` may be off by `thickness_error`. Each start `|d_i| * th` is off by `|d_i|` times that,
/// plus half an ULP (the device may fuse the product into `x - start`, or flush a denormal product);
/// the widths `|d_i| * sm` are identical products. The coverage `1 - min` adds one rounding.
pub(super) fn line_width_error(
    deltas: Vec3,
    thickness: f32,
    thickness_error: f32,
    smoothing: f32,
    b: Vec3,
) -> f32 {
    let magnitude = deltas.abs();
    let start = magnitude * thickness.clamp(0.0, MAX_LINE_THICKNESS);
    let width = magnitude * smoothing.clamp(0.0, MAX_LINE_THICKNESS);
    let start_error = magnitude * thickness_error + Vec3::splat(0.5 * ULP) * start + f32::MIN_POSITIVE;
    let errors: Vec<f32> = (0..3)
        .map(|i| edge_ramp_error(b[i], start[i], width[i], start_error[i]))
        .collect();
    errors.iter().fold(0.0f32, |a, &e| a.max(e)) + ULP
}

/// Largest `|device - mirror|` of `edge_thickness(var, e)`: the argument `e * pi` is the same
/// product on both sides; the device's `sin` is off by 2^-11 (Vulkan, inside `[-pi, pi]`), the
/// mirror's by an ULP, and `1 - sin` may round differently (an ULP; the clamp to `[0, 1]` does not
/// widen a difference): that moves the mix by `|var.y - var.x|` times as much. The mix itself (`x (1 - a) + y a`, or `x + (y - x) a` on the
/// device) rounds at most 4 times on each side: 4 ULP of `|x| + |y|`.
pub(super) fn edge_thickness_error(thickness_var: Vec2) -> f32 {
    let factors = thickness_var.clamp(Vec2::ZERO, Vec2::splat(MAX_LINE_THICKNESS));
    (factors.y - factors.x).abs() * (SIN_COS_ERROR + 2.0 * ULP) + ulps(4.0, factors.x + factors.y)
}

/// A coverage error bound from which on the coverage is ambiguous: the case lies within rounding
/// of a hard edge, a ramp steeper than its inputs' precision, or a dash boundary, where either side
/// is right. The line checks leave those cases to the edge-case suite, which checks them for a
/// finite coverage in `[0, 1]`; everywhere else the bound is far below it.
pub(super) const AMBIGUOUS_COVERAGE: f32 = 0.5;

/// Why a case is left out of the line checks ([`AMBIGUOUS_COVERAGE`]).
pub(super) const AT_AN_EDGE: &str = "within rounding of a hard edge or a dash boundary";

/// Whether the device may legitimately land on the other side of a dash boundary. The device's
/// `offset = 0.5 * length / repeats` is off by 3 ULP (2.5 for its division, 0.5 for the mirror's);
/// `e + offset` adds a rounding (1 ULP of the sum between the two sides) and the product with
/// `repeats` scales both and adds 1 ULP of the period; `fract` is exact. Within that band of the
/// dash length or of a period boundary (where `fract` wraps), either value is right.
pub(super) fn stipple_may_flip(stipple_repeats: i32, stipple_length: f32, edge_position: f32) -> bool {
    if stipple_repeats <= 0 {
        return false;
    }
    let repeats = stipple_repeats as f32;
    let drawn = stipple_length.clamp(0.0, 1.0);
    let offset = 0.5 * drawn / repeats;
    let sum = edge_position.clamp(0.0, 1.0) + offset;
    let period = sum * repeats;
    let pattern = period - period.floor();
    let band = repeats * (ulps(3.0, offset) + ulps(1.0, sum)) + ulps(1.0, period);
    (pattern - drawn).abs() <= band || pattern <= band || 1.0 - pattern <= band
}

/// Largest `|device - mirror|` of `process_wireframe`: the half width `0.5 * thickness * et` carries
/// `edge_thickness`'s error times `0.5 * thickness`, plus its own rounding (an ULP: a different
/// `et` may round the other way); `thickness * smoothing` is the same product on both sides. Then
/// as `line_width`; a dash boundary within its band allows either coverage (the factor is 0 or 1).
pub(super) fn process_wireframe_error(settings: WireframeSettings, b: Vec3, deltas: Vec3) -> f32 {
    let e = wf::edge_position(b);
    if settings.stipple && stipple_may_flip(settings.stipple_repeats, settings.stipple_length, e) {
        return 1.0;
    }
    let thickness = settings.thickness.max(0.0);
    let edge_thickness = wf::edge_thickness(settings.thickness_var, e);
    let half_width = 0.5 * thickness * edge_thickness;
    let half_width_error =
        0.5 * thickness * edge_thickness_error(settings.thickness_var) + ulps(1.0, half_width);
    let pixel_deltas = if settings.screen_space { deltas } else { Vec3::ONE };
    let ramp_width = thickness * settings.smoothing;
    line_width_error(pixel_deltas, half_width, half_width_error, ramp_width, b)
}
