// ray-footprint ray-tracing renderer: what every GLSL shader of both pipelines (src/rt/) includes:
// the recording shaders (raygen.rgen, miss.rmiss, closest_hit.rchit) and the colour-only shaders
// (colour_*.r*), compiled once per mode. It includes the library modules ray_cone.glsl,
// ray_diff.glsl and wireframe.glsl exactly as a user's renderer would, the generated constants and
// structs (rt_abi.glsl), declares the GLSL resources, and includes the shading code
// (rt_shading.glsl), which the Slang closest hit compiles too. The shading is written for a mode
// passed in (rt_surface_colour, rt_bounce): the recording shaders pass the push constants' mode,
// the colour-only shaders the mode they were compiled for, so both render the same pixels. The
// WGSL ray-query twin of the measurements is ray_query.wgsl.

#ifndef RT_COMMON_GLSL
#define RT_COMMON_GLSL

#extension GL_EXT_ray_tracing : require
#include "rt_abi.glsl"
#include "ray_diff.glsl"

layout(push_constant, std430) uniform RtPush { RtPushConstants pc; };
layout(set = 0, binding = 0) uniform accelerationStructureEXT rt_scene;
layout(std430, set = 0, binding = 1) readonly buffer RtVertices { float rt_vertices[]; };
layout(std430, set = 0, binding = 2) readonly buffer RtIndices { uint rt_indices[]; };
layout(std430, set = 0, binding = 3) readonly buffer RtMeshes { uint rt_meshes[]; };
layout(std430, set = 0, binding = 4) writeonly buffer RtRecords { RtPixelRecord rt_records[]; };
layout(std430, set = 0, binding = 5) writeonly buffer RtColours { uint rt_colours[]; };
// 0: the checker texture, 1: one colour per mip level.
layout(set = 0, binding = 6) uniform sampler2D rt_textures[2];
layout(std140, set = 0, binding = 7) uniform RtFrame { RtUniforms rt_frame; };

#include "rt_shading.glsl"

#endif // RT_COMMON_GLSL
