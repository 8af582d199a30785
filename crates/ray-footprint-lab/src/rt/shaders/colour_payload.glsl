// ray-footprint ray-tracing renderer: the payload of the colour-only shaders (colour_*.r*), which
// carries only what the render mode needs: the colour and the bounce depth always, the ray cone
// where RT_PAYLOAD_CONE is defined, the sagittal section's cone and axis (rt_shading.glsl's
// RtSagittal) where RT_PAYLOAD_SAGITTAL is, the ray differential where RT_PAYLOAD_DIFF is. The renderer
// defines them per mode (Mode::payload in src/rt/mode.rs). Declarations and conversions only, so a
// layout probe can include it.

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
    vec3 sagittal_axis;
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

#endif // RT_COLOUR_PAYLOAD_GLSL
