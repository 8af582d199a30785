// ray-footprint ray-tracing renderer: the recording closest hit that closest_hit.slang and
// closest_hit.hlsl share, in the HLSL that slangc reads as Slang too. It declares the same
// bindings, push constants and payload as the GLSL stages, shades with rt_shading.glsl (the GLSL
// stages' shading, compiled through slangc's GLSL compatibility, `import glsl;`), and has the
// entry point: on a primary hit it records every value measured there (rt_measure); then it shades
// in the push constants' mode: a mirror or glass traces the ray rt_bounce gives (reflected or
// refracted, its cone and sagittal section, and in the ray-differential modes its differential),
// every other surface is textured as the mode says, at the cone rt_arriving_cone gives. Include it after the library modules and the renderer's generated
// declarations (rt_abi) in the including file's language: every rf_ call it makes is a call of
// those modules.
//
// The resources use slangc's default Vulkan layouts: std430 for the push constants and the
// records, std140 for the frame's uniform buffer, the layouts the GLSL stages name. rt_frame's
// float4x4 are indexed m[r][c] (row r, column c); the host writes them column by column (glam),
// which is the memory order of slangc's default column-major matrix layout.

#ifndef RT_CLOSEST_HIT_HLSL
#define RT_CLOSEST_HIT_HLSL

import glsl;

[[vk::push_constant]] ConstantBuffer<RtPushConstants> pc;
[[vk::binding(0, 0)]] RaytracingAccelerationStructure rt_scene;
[[vk::binding(1, 0)]] StructuredBuffer<float> rt_vertices;
[[vk::binding(2, 0)]] StructuredBuffer<uint> rt_indices;
[[vk::binding(3, 0)]] StructuredBuffer<uint> rt_meshes;
[[vk::binding(4, 0)]] RWStructuredBuffer<RtPixelRecord> rt_records;
// 0: the checker texture, 1: one colour per mip level; combined image samplers, as the GLSL stages
// declare them. HLSL has no such type: slangc's is Sampler2D (it rejects DXC's
// [[vk::combinedImageSampler]] as an unknown attribute).
[[vk::binding(6, 0)]] Sampler2D rt_textures[2];
[[vk::binding(7, 0)]] ConstantBuffer<RtUniforms> rt_frame;

#include "rt_shading.glsl"

// The hit instance's world-to-object matrix as a float4x4 whose fourth row is (0, 0, 0, 1), as
// GLSL's mat4(gl_WorldToObjectEXT).
float4x4 rt_world_to_object() {
    float3x4 rows = WorldToObject3x4();
    return float4x4(rows[0], rows[1], rows[2], float4(0.0, 0.0, 0.0, 1.0));
}

// The hit this shader was called for, of a ray at bounce `depth` (rt_closest_hit.glsl).
RtHit rt_current_hit(float2 barycentrics, uint depth) {
    return rt_hit(InstanceID(), PrimitiveIndex(), barycentrics, WorldRayOrigin(), WorldRayDirection(),
        RayTCurrent(), rt_world_to_object(), DispatchRaysIndex().xy, depth);
}

[shader("closesthit")]
void main(inout RtPayload payload, in BuiltInTriangleIntersectionAttributes attributes) {
    RtHit hit = rt_current_hit(attributes.barycentrics, payload.hit.depth);
    if (hit.depth == 0u) {
        rt_records[hit.pixel.y * DispatchRaysDimensions().x + hit.pixel.x] = rt_measure(hit, payload.hit.cone,
            payload.diff);
    }
    if (rt_passes_on(pc.mode, hit)) {
        RtBounce bounce = rt_bounce(pc.mode, hit, payload.hit.cone, payload.diff, payload.sagittal);
        RfHitPayload on = { float3(0.0, 0.0, 0.0), payload.hit.weight * bounce.weight, bounce.cone, hit.depth + 1u,
            0u };
        RtPayload next = { on, bounce.diff, bounce.sagittal };
        RayDesc ray;
        ray.Origin = bounce.origin;
        ray.TMin = 0.0;
        ray.Direction = bounce.direction;
        ray.TMax = RT_MAX_DISTANCE;
        TraceRay(rt_scene, RAY_FLAG_FORCE_OPAQUE, 0xff, 0, 0, 0, ray, next);
        payload.hit.colour = bounce.tint * next.hit.colour;
        return;
    }
    RfRayCone arriving = rt_arriving_cone(pc.mode, hit, payload.hit.cone, payload.sagittal);
    payload.hit.colour = payload.hit.weight * rt_surface_colour(pc.mode, hit, arriving, payload.diff);
}

#endif // RT_CLOSEST_HIT_HLSL
