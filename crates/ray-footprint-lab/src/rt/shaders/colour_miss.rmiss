// Miss of the colour-only shaders: the sky.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "rt_common.glsl"
#include "colour_payload.glsl"

layout(location = 0) rayPayloadInEXT RtColourPayload payload;

void main() {
    payload.colour = rt_sky(gl_WorldRayDirectionEXT);
}
