// ray-footprint ray-tracing renderer: the payload of the colour-only shaders (colour_*.r*), which
// carries only what the render mode needs: the colour and the bounce depth always, the ray cone
// where RT_PAYLOAD_CONE is defined, the sagittal section's cone and axis (rt_shading.glsl's
// RtSagittal), the axis packed into one word, where RT_PAYLOAD_SAGITTAL is, the ray differential
// where RT_PAYLOAD_DIFF is. The renderer defines them per mode (Mode::payload in src/rt/mode.rs).
// Declarations and conversions only, so a layout probe can include it.

#ifndef RT_COLOUR_PAYLOAD_GLSL
#define RT_COLOUR_PAYLOAD_GLSL

#include "ray_cone.glsl"
#include "ray_diff.glsl"

// A ray differential without the pads of RfRayDiff: origin and direction changes per pixel step.
struct RtColourDiff {
    vec3 d_origin_dx;
    vec3 d_origin_dy;
    vec3 d_direction_dx;
    vec3 d_direction_dy;
};

struct RtColourPayload {
    vec3 colour;
    uint depth;
#ifdef RT_PAYLOAD_CONE
    RfRayCone cone;
#endif
#ifdef RT_PAYLOAD_SAGITTAL
    RfRayCone sagittal_cone;
    uint sagittal_axis; // rt_pack_axis
#endif
#ifdef RT_PAYLOAD_DIFF
    RtColourDiff diff;
#endif
};

// `diff` as the payload carries it.
RtColourDiff rt_colour_diff(RfRayDiff diff) {
    return RtColourDiff(diff.d_origin_dx, diff.d_origin_dy, diff.d_direction_dx, diff.d_direction_dy);
}

// The differential the payload carries, as the library takes it (pads 0).
RfRayDiff rt_ray_diff(RtColourDiff diff) {
    return RfRayDiff(diff.d_origin_dx, 0.0, diff.d_origin_dy, 0.0, diff.d_direction_dx, 0.0, diff.d_direction_dy,
        0.0);
}

// The packed word of no axis (a round beam's zero axis): both halves -32768, which packSnorm2x16
// never writes (it clamps to [-32767, 32767]).
const uint RT_NO_AXIS = 0x80008000u;

// +1 or -1 per component: the side of zero `value` lies on (zero counts as positive).
vec2 rt_signs(vec2 value) {
    return mix(vec2(-1.0), vec2(1.0), greaterThanEqual(value, vec2(0.0)));
}

// `axis` (unit, or zero for none) in one word: its octahedral projection (Cigolle et al., "A Survey
// of Efficient Representations for Independent Unit Vectors", JCGT 3(2) 2014, section 3.2: the
// vector over its L1 norm, the lower half folded over the diagonals) as two 16-bit snorms, steps
// of 1/32767 in each; selects, no branches. rt_pack_axis(vec3(0.0, 0.0, 1.0)) is 0u.
uint rt_pack_axis(vec3 axis) {
    float l1_norm = abs(axis.x) + abs(axis.y) + abs(axis.z);
    vec2 projected = axis.xy / max(l1_norm, RF_MIN_MAGNITUDE);
    vec2 folded = (1.0 - abs(projected.yx)) * rt_signs(projected);
    uint packed = packSnorm2x16(axis.z < 0.0 ? folded : projected);
    return l1_norm > 0.0 ? packed : RT_NO_AXIS;
}

// The unit axis rt_pack_axis packed, or zero for RT_NO_AXIS.
vec3 rt_unpack_axis(uint packed) {
    vec2 projected = unpackSnorm2x16(packed);
    vec3 axis = vec3(projected, 1.0 - abs(projected.x) - abs(projected.y));
    axis.xy -= rt_signs(projected) * max(-axis.z, 0.0);
    return packed == RT_NO_AXIS ? vec3(0.0) : normalize(axis);
}

#endif // RT_COLOUR_PAYLOAD_GLSL
