// ray-footprint ray-tracing renderer: the payload of the colour-only shaders (colour_*.r*), which
// carries only what the render mode needs: the colour and the bounce depth always, the ray cone
// where RT_PAYLOAD_CONE is defined, the eye ray's direction differentials where RT_PAYLOAD_DIFF is.
// The renderer defines them per mode (Mode::payload in src/rt/mode.rs). Declarations only, so a
// layout probe can include it.

#ifndef RT_COLOUR_PAYLOAD_GLSL
#define RT_COLOUR_PAYLOAD_GLSL

#include "ray_cone.glsl"

struct RtColourPayload {
    vec3 colour;
    uint depth;
#ifdef RT_PAYLOAD_CONE
    RfRayCone cone;
#endif
#ifdef RT_PAYLOAD_DIFF
    // d_direction_dx and d_direction_dy of rf_eye_ray_diff_from_matrices; a pinhole camera's
    // origin differentials are 0.
    vec3 d_direction_dx;
    vec3 d_direction_dy;
#endif
};

#endif // RT_COLOUR_PAYLOAD_GLSL
