// Closest hit of the recording shaders in HLSL, in place of closest_hit.rchit: the library's HLSL
// modules brought in by #include as an HLSL renderer would, the generated structs and constants of
// rt_abi.hlsl, the shading of rt_shading.hlsl (the HLSL twin of rt_shading.glsl), and the same
// bindings, push constants and payload as the GLSL stages. On a primary hit it records every value
// measured there (rt_measure); then it shades in the push constants' mode: a mirror or glass traces
// the ray rt_bounce gives, every other surface is textured as the mode says. The renderer runs it
// with the GLSL ray generation and miss shaders (ClosestHit::Hlsl), compiled by slangc reading
// HLSL: glslang's HLSL front end has no ray-tracing stages.
//
// Layouts are slangc's defaults for Vulkan, those the GLSL stages name: std430 for the push
// constants and the structured buffers, std140 for the frame's constant buffer. A float4x4 m is
// indexed m[r][c] (row r, column c) and stored column by column, as the host writes it (glam).

#include "rt_abi.hlsl"
#include "ray_diff.hlsl"

[[vk::push_constant]] ConstantBuffer<RtPushConstants> pc;
[[vk::binding(0, 0)]] RaytracingAccelerationStructure rt_scene;
[[vk::binding(1, 0)]] StructuredBuffer<float> rt_vertices;
[[vk::binding(2, 0)]] StructuredBuffer<uint> rt_indices;
[[vk::binding(3, 0)]] StructuredBuffer<uint> rt_meshes;
[[vk::binding(4, 0)]] RWStructuredBuffer<RtPixelRecord> rt_records;
// 0: the checker texture, 1: one colour per mip level; combined image samplers, as the GLSL stages
// declare them. HLSL has no such type: slangc's is Sampler2D (it rejects DXC's
// [[vk::combinedImageSampler]] as an unknown attribute), the one Slang type in this file.
[[vk::binding(6, 0)]] Sampler2D rt_textures[2];
[[vk::binding(7, 0)]] ConstantBuffer<RtUniforms> rt_frame;

// GLSL's textureLod(rt_textures[0], uv, lod).
float4 rt_checker_lod(float2 uv, float lod) {
    return rt_textures[0].SampleLevel(uv, lod);
}

// GLSL's textureGrad(rt_textures[0], uv, dx, dy).
float4 rt_checker_grad(float2 uv, float2 dx, float2 dy) {
    return rt_textures[0].SampleGrad(uv, dx, dy);
}

// GLSL's textureLod(rt_textures[1], uv, lod).
float4 rt_level_colour_lod(float2 uv, float lod) {
    return rt_textures[1].SampleLevel(uv, lod);
}

#include "rt_shading.hlsl"

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
    if (rt_passes_on(hit)) {
        RtBounce bounce = rt_bounce(pc.mode, hit, payload.hit.cone, payload.diff);
        RfHitPayload on = { float3(0.0, 0.0, 0.0), payload.hit.weight * bounce.weight, bounce.cone, hit.depth + 1u,
            0u };
        RtPayload next = { on, bounce.diff };
        RayDesc ray;
        ray.Origin = bounce.origin;
        ray.TMin = 0.0;
        ray.Direction = bounce.direction;
        ray.TMax = RT_MAX_DISTANCE;
        TraceRay(rt_scene, RAY_FLAG_FORCE_OPAQUE, 0xff, 0, 0, 0, ray, next);
        payload.hit.colour = next.hit.colour;
        return;
    }
    payload.hit.colour = payload.hit.weight * rt_surface_colour(pc.mode, hit, payload.hit.cone, payload.diff);
}
