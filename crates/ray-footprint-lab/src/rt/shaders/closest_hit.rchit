// Closest hit of the recording shaders: on a primary hit, records every value measured there
// (rt_measure: the ray-cone values, and the ray-differential, re-intersection and wireframe
// values, the material's and the anisotropic cone's); then shades in the push constants' mode with
// the functions the colour-only shaders share (rt_common.glsl): a mirror or glass traces the ray
// rt_bounce gives (reflected or refracted, its cone and sagittal section, and in the
// ray-differential modes its differential), every other surface is textured as the mode says, at
// the cone rt_arriving_cone gives.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "rt_common.glsl"
#include "rt_closest_hit.glsl"

layout(location = 0) rayPayloadInEXT RtPayload payload;
layout(location = 1) rayPayloadEXT RtPayload next;

void main() {
    RtHit hit = rt_current_hit(payload.hit.depth);
    if (hit.depth == 0u) {
        rt_records[hit.pixel.y * gl_LaunchSizeEXT.x + hit.pixel.x] = rt_measure(hit, payload.hit.cone, payload.diff);
    }
    if (rt_passes_on(pc.mode, hit)) {
        RtBounce bounce = rt_bounce(pc.mode, hit, payload.hit.cone, payload.diff, payload.sagittal);
        RfHitPayload on = RfHitPayload(vec3(0.0), payload.hit.weight * bounce.weight, bounce.cone, hit.depth + 1u, 0u);
        next = RtPayload(on, bounce.diff, bounce.sagittal);
        traceRayEXT(rt_scene, gl_RayFlagsOpaqueEXT, 0xff, 0, 0, 0, bounce.origin, 0.0, bounce.direction,
            RT_MAX_DISTANCE, 1);
        payload.hit.colour = bounce.tint * next.hit.colour;
        return;
    }
    RfRayCone arriving = rt_arriving_cone(pc.mode, hit, payload.hit.cone, payload.sagittal);
    payload.hit.colour = payload.hit.weight * rt_surface_colour(pc.mode, hit, arriving, payload.diff);
}
