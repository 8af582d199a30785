// ray-footprint ray-tracing renderer: declarations shared by the ray-generation, miss and
// closest-hit shaders (src/gpu/rt/). Not a library module: it includes one, ray_cone.glsl, exactly
// as a user's renderer would. The WGSL ray-query twin is ray_query.wgsl.

#ifndef RT_COMMON_GLSL
#define RT_COMMON_GLSL

#extension GL_EXT_ray_tracing : require
#include "rt_abi.glsl"

// Render modes: the discriminants of Mode in src/gpu/rt/mode.rs.
const uint RT_MODE_MIP0 = 0u;
const uint RT_MODE_CONE = 1u;
const uint RT_MODE_CONE_CURVATURE = 2u;
const uint RT_MODE_TEX_GRAD_SCALE = 3u;
const uint RT_MODE_MIP_LEVELS = 4u;

// Materials: the discriminants of Material in src/gpu/rt/scene.rs.
const uint RT_MATERIAL_TEXTURED = 0u;
const uint RT_MATERIAL_MIRROR = 1u;

// Floats per vertex: position xyz, u, normal xyz, v (VERTEX_FLOATS in scene.rs).
const uint RT_VERTEX_FLOATS = 8u;
// Offset that lifts a reflected ray's origin off the surface, in world units.
const float RT_SURFACE_OFFSET = 1.0e-3;
// Farthest hit distance.
const float RT_MAX_DISTANCE = 1.0e4;

layout(push_constant, std430) uniform RtPush { RtPushConstants pc; };
layout(set = 0, binding = 0) uniform accelerationStructureEXT rt_scene;
layout(std430, set = 0, binding = 1) readonly buffer RtVertices { float rt_vertices[]; };
layout(std430, set = 0, binding = 2) readonly buffer RtIndices { uint rt_indices[]; };
layout(std430, set = 0, binding = 3) readonly buffer RtMeshes { uint rt_meshes[]; };
layout(std430, set = 0, binding = 4) writeonly buffer RtRecords { RtPixelRecord rt_records[]; };
layout(std430, set = 0, binding = 5) writeonly buffer RtColours { uint rt_colours[]; };
// 0: the checker texture, 1: one colour per mip level.
layout(set = 0, binding = 6) uniform sampler2D rt_textures[2];

// A triangle's vertices.
struct RtTriangle {
    vec3 p[3];
    vec3 n[3];
    vec2 uv[3];
};

// Triangle `primitive` of mesh `mesh`, from the vertex, index and mesh-table buffers.
RtTriangle rt_triangle(uint mesh, uint primitive) {
    uint first_index = rt_meshes[3u * mesh] + 3u * primitive;
    uint first_vertex = rt_meshes[3u * mesh + 1u];
    RtTriangle tri;
    for (uint k = 0u; k < 3u; k++) {
        uint f = (first_vertex + rt_indices[first_index + k]) * RT_VERTEX_FLOATS;
        tri.p[k] = vec3(rt_vertices[f], rt_vertices[f + 1u], rt_vertices[f + 2u]);
        tri.n[k] = vec3(rt_vertices[f + 4u], rt_vertices[f + 5u], rt_vertices[f + 6u]);
        tri.uv[k] = vec2(rt_vertices[f + 3u], rt_vertices[f + 7u]);
    }
    return tri;
}

// Barycentric weights (1 - u - v, u, v).
vec3 rt_weights(vec2 barycentrics) {
    return vec3(1.0 - barycentrics.x - barycentrics.y, barycentrics.x, barycentrics.y);
}

// Unit direction of the primary ray through the centre of `pixel` (see RtPushConstants' Rust doc).
vec3 rt_primary_direction(uvec2 pixel) {
    vec2 c = 2.0 * (vec2(pixel) + 0.5) / vec2(pc.width, pc.height) - 1.0;
    return normalize(pc.forward + c.x * pc.aspect * pc.tan_half_fov_y * pc.right
        - c.y * pc.tan_half_fov_y * pc.up);
}

// The record of a ray that hit nothing.
RtPixelRecord rt_miss_record(vec3 direction, RfRayCone cone) {
    return RtPixelRecord(vec3(0.0), 0.0, direction, 0u, vec2(0.0), 0u, 0u, cone, 0.0, 0.0, 0.0, 0.0,
        0.0, 0.0, 0.0, 0.0, RfRayCone(0.0, 0.0));
}

// Every ray-cone value of a hit at distance t along the unit `direction` on `tri`, reached by
// `cone`: footprint and texel density (uv footprint = their product), base LOD and LOD (RTG Eq. 34),
// the textureGrad gradient, the triangle's curvature and the spread it gives a reflection (JCGT
// 2021), and the reflected cone (RTG Eq. 35).
RtPixelRecord rt_measure(RtTriangle tri, vec2 barycentrics, float t, vec3 direction, RfRayCone cone) {
    vec3 w = rt_weights(barycentrics);
    vec3 normal = normalize(w.x * tri.n[0] + w.y * tri.n[1] + w.z * tri.n[2]);
    float width = rf_width_at(cone, t);
    float footprint = rf_world_footprint(cone, t, normal, direction);
    float density = rf_texel_density(tri.p[0], tri.p[1], tri.p[2], tri.uv[0], tri.uv[1], tri.uv[2]);
    float base_lod = rf_triangle_base_lod(tri.p[0], tri.p[1], tri.p[2], tri.uv[0], tri.uv[1], tri.uv[2]);
    float lod = rf_texture_lod(base_lod, width, vec2(pc.texture_size), normal, direction);
    float gradient = rf_texture_gradient(footprint * density, pc.cone.tex_grad_scale);
    float curvature = rf_triangle_curvature(tri.p[0], tri.p[1], tri.p[2], tri.n[0], tri.n[1], tri.n[2]);
    float spread = rf_curvature_spread_angle(curvature, width, normal, direction);
    return RtPixelRecord(normal, t, direction, 0u, barycentrics, 0u, 1u, cone, width, footprint,
        density, base_lod, lod, gradient, curvature, spread, rf_propagate(cone, t, spread));
}

// The texture colour at `uv` as the render mode samples it.
vec3 rt_texture_colour(RtPixelRecord record, vec2 uv) {
    switch (pc.mode) {
    case RT_MODE_MIP0:
        return textureLod(rt_textures[0], uv, 0.0).rgb;
    case RT_MODE_TEX_GRAD_SCALE:
        return textureGrad(rt_textures[0], uv, vec2(record.gradient, 0.0), vec2(0.0, record.gradient)).rgb;
    case RT_MODE_MIP_LEVELS:
        return textureLod(rt_textures[1], uv, record.lod).rgb;
    default: // RT_MODE_CONE, RT_MODE_CONE_CURVATURE
        return textureLod(rt_textures[0], uv, record.lod).rgb;
    }
}

// Sky colour for a ray leaving the scene in `direction`.
vec3 rt_sky(vec3 direction) {
    return mix(vec3(0.75, 0.82, 0.9), vec3(0.35, 0.5, 0.8), clamp(direction.y, 0.0, 1.0));
}

#endif // RT_COMMON_GLSL
