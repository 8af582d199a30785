// Miss: the sky.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "rt_common.glsl"

layout(location = 0) rayPayloadInEXT RtPayload payload;

void main() {
    payload.hit.colour = payload.hit.weight * rt_sky(gl_WorldRayDirectionEXT);
}
