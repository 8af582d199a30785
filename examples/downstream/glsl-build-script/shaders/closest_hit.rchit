#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require
#include "ray_cone.glsl"
#include "wireframe.glsl"

layout(location = 0) rayPayloadInEXT RfHitPayload payload;
hitAttributeEXT vec2 hit_barycentrics;
layout(push_constant) uniform Push { RfWireframePushConstants wire; };

// Blends a wireframe over the hit colour and hands the reflected cone on (RTG Eq. 35).
void main() {
    vec3 barycentrics = vec3(1.0 - hit_barycentrics.x - hit_barycentrics.y, hit_barycentrics);
    RfWireframeSettings settings = rf_unpack_wireframe_settings(wire.settings);
    float coverage = rf_process_wireframe(settings, barycentrics, vec3(0.01));
    payload.colour = mix(payload.colour, wire.colour.rgb, coverage * wire.colour.a);
    payload.cone = rf_propagate(payload.cone, gl_HitTEXT, 0.0);
    payload.depth += 1u;
}
