// Closest hit of the colour-only shaders: shades the hit as closest_hit.rchit does, with the same
// functions (rt_common.glsl), in the render mode RT_COLOUR_MODE (an RT_MODE_* value the renderer
// defines), so that the compiler keeps only what that mode computes; records nothing. The payload
// carries only what the mode reads (colour_payload.glsl): the functions get a zero cone, sagittal
// section or differential in its place, which the mode never reads.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "rt_common.glsl"
#include "rt_closest_hit.glsl"
#include "colour_payload.glsl"

layout(location = 0) rayPayloadInEXT RtColourPayload payload;
layout(location = 1) rayPayloadEXT RtColourPayload next;

// The cone the ray carries, or a zero cone where the mode needs none.
RfRayCone rt_payload_cone() {
#ifdef RT_PAYLOAD_CONE
    return payload.cone;
#else
    return RfRayCone(0.0, 0.0);
#endif
}

// The sagittal section the ray carries, or a zero one where the mode needs none.
RtSagittal rt_payload_sagittal() {
#ifdef RT_PAYLOAD_SAGITTAL
    return RtSagittal(payload.sagittal_cone, rt_unpack_axis(payload.sagittal_axis));
#else
    return RtSagittal(RfRayCone(0.0, 0.0), vec3(0.0));
#endif
}

// The differential the ray carries, or a zero one where the mode needs none.
RfRayDiff rt_payload_diff() {
#ifdef RT_PAYLOAD_DIFF
    return rt_ray_diff(payload.diff);
#else
    return rt_no_diff();
#endif
}

void main() {
    RtHit hit = rt_current_hit(payload.depth);
    if (rt_passes_on(RT_COLOUR_MODE, hit)) {
        RtBounce bounce = rt_bounce(RT_COLOUR_MODE, hit, rt_payload_cone(), rt_payload_diff(), rt_payload_sagittal());
        next.colour = vec3(0.0);
        next.depth = hit.depth + 1u;
#ifdef RT_PAYLOAD_CONE
        next.cone = bounce.cone;
#endif
#ifdef RT_PAYLOAD_SAGITTAL
        next.sagittal_cone = bounce.sagittal.cone;
        next.sagittal_axis = rt_pack_axis(bounce.sagittal.axis);
#endif
#ifdef RT_PAYLOAD_DIFF
        next.diff = rt_colour_diff(bounce.diff);
#endif
        traceRayEXT(rt_scene, gl_RayFlagsOpaqueEXT, 0xff, 0, 0, 0, bounce.origin, 0.0, bounce.direction,
            RT_MAX_DISTANCE, 1);
        payload.colour = bounce.weight * bounce.tint * next.colour;
        return;
    }
    RfRayCone arriving = rt_arriving_cone(RT_COLOUR_MODE, hit, rt_payload_cone(), rt_payload_sagittal());
    payload.colour = rt_surface_colour(RT_COLOUR_MODE, hit, arriving, rt_payload_diff());
}
