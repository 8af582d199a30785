// Miss: the sky.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "rt_common.glsl"

layout(location = 0) rayPayloadInEXT RfHitPayload payload;

void main() {
    payload.colour = payload.weight * rt_sky(gl_WorldRayDirectionEXT);
}
