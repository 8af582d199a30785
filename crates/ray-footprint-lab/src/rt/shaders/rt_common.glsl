// ray-footprint ray-tracing renderer: declarations shared by the ray-generation, miss and
// closest-hit shaders (src/gpu/rt/). Not a library module: it includes the library modules
// ray_cone.glsl, ray_diff.glsl and wireframe.glsl exactly as a user's renderer would. The WGSL
// ray-query twin is ray_query.wgsl.

#ifndef RT_COMMON_GLSL
#define RT_COMMON_GLSL

#extension GL_EXT_ray_tracing : require
#include "rt_abi.glsl"
#include "ray_diff.glsl"

// Render modes: the discriminants of Mode in src/gpu/rt/mode.rs.
const uint RT_MODE_MIP0 = 0u;
const uint RT_MODE_CONE = 1u;
const uint RT_MODE_CONE_CURVATURE = 2u;
const uint RT_MODE_TEX_GRAD_SCALE = 3u;
const uint RT_MODE_MIP_LEVELS = 4u;
const uint RT_MODE_RAY_DIFF = 5u;
const uint RT_MODE_BARY_GRADIENTS = 6u;
const uint RT_MODE_WIREFRAME = 7u;
const uint RT_MODE_RAY_DIFF_ISOTROPIC = 8u;

// Materials: the discriminants of Material in src/gpu/rt/scene.rs.
const uint RT_MATERIAL_TEXTURED = 0u;
const uint RT_MATERIAL_MIRROR = 1u;

// Floats per vertex: position xyz, u, normal xyz, v (VERTEX_FLOATS in scene.rs).
const uint RT_VERTEX_FLOATS = 8u;
// Offset that lifts a reflected ray's origin off the surface, in world units.
const float RT_SURFACE_OFFSET = 1.0e-3;
// Farthest hit distance.
const float RT_MAX_DISTANCE = 1.0e4;
// Share of the light a mirror reflects.
const float RT_MIRROR_REFLECTANCE = 0.9;
// Direction towards the light.
const vec3 RT_LIGHT = vec3(0.4, 0.85, 0.35);

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

// The renderer's ray payload: the library's cone payload and the ray's differential (Igehy),
// which the ray-differential modes carry through the mirror. A primary ray's differential is zero:
// the closest-hit shader forms it at the hit from the inverse matrices.
struct RtPayload {
    RfHitPayload hit;
    RfRayDiff diff;
};

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

// Unit direction of the primary ray through `pixel`, offset from its centre by pc.pixel_offset
// (see RtPushConstants' Rust doc).
vec3 rt_primary_direction(uvec2 pixel) {
    vec2 c = 2.0 * (vec2(pixel) + 0.5 + pc.pixel_offset) / vec2(pc.width, pc.height) - 1.0;
    return normalize(pc.forward + c.x * pc.aspect * pc.tan_half_fov_y * pc.right
        - c.y * pc.tan_half_fov_y * pc.up);
}

// Diffuse lighting of a surface with unit normal `normal`: an ambient part and the light's.
float rt_light(vec3 normal) {
    return 0.35 + 0.65 * max(dot(normal, normalize(RT_LIGHT)), 0.0);
}

// A pixel's colour as stored: gamma 2.2, RGBA8.
uint rt_display(vec3 colour) {
    return packUnorm4x8(vec4(pow(clamp(colour, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0));
}

// A record with only the closed-form cone deltas and the coverage they give: what a secondary hit
// (seen in the mirror), which has no pixel neighbours to re-intersect, can measure.
RtDiffRecord rt_diff_record(vec3 cone_deltas, float coverage) {
    return RtDiffRecord(vec3(0.0), 0.0, vec3(0.0), 0.0, vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0),
        vec3(0.0), coverage, vec3(0.0), 0u, vec3(0.0), 0u, vec3(0.0), 0u, vec2(0.0), vec2(0.0), vec3(0.0),
        0u, cone_deltas, 0u);
}

// The record of a ray that hit nothing.
RtPixelRecord rt_miss_record(vec3 direction, RfRayCone cone) {
    return RtPixelRecord(vec3(0.0), 0.0, direction, 0u, vec2(0.0), 0u, 0u, cone, 0.0, 0.0, 0.0, 0.0,
        0.0, 0.0, 0.0, 0.0, RfRayCone(0.0, 0.0), rt_diff_record(vec3(0.0), 0.0));
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
        density, base_lod, lod, gradient, curvature, spread, rf_propagate(cone, t, spread),
        rt_diff_record(vec3(0.0), 0.0));
}

// The isotropic LOD (RTG Eq. 1-2) of UV gradients scaled to texels (the size is a power of two).
float rt_texel_lod(RfDerivatives2 uv) {
    return rf_lod_isotropic(RfDerivatives2(uv.dx * pc.texture_size, uv.dy * pc.texture_size));
}

// The wireframe coverage of the frame's settings at barycentrics (w, u, v) with these deltas.
float rt_coverage(vec3 weights, vec3 deltas) {
    return rf_process_wireframe(rf_unpack_wireframe_settings(rt_frame.wireframe.settings), weights, deltas);
}

// The ray-differential and wireframe values of a primary hit of the ray through `pixel`, from
// `origin` along the unit `direction` to distance t, on `tri` (object space, mapped from world
// space by world_to_object), whose ray-cone footprint is `footprint`: the eye-ray differential from
// the inverse matrices, transferred to the hit as barycentric and UV derivatives (RTG Eq. 12-21);
// the neighbour pixels' rays re-intersected with the triangle's plane (signed barycentric offsets,
// their UV gradients and deltas); the wireframe coverage from the re-intersection deltas; and the
// closed-form cone deltas.
RtDiffRecord rt_measure_diff(RtTriangle tri, vec2 barycentrics, float t, vec3 origin, vec3 direction,
        mat4 world_to_object, uvec2 pixel, float footprint) {
    vec2 xy = vec2(pixel) + pc.pixel_offset;
    vec2 size = vec2(pc.width, pc.height);
    RfRayDiff eye = rf_eye_ray_diff_from_matrices(xy, size, rt_frame.view_inv, rt_frame.proj_inv);
    RfDerivatives2 bary = rf_barycentric_derivatives(eye, direction, t, tri.p[0], tri.p[1], tri.p[2]);
    RfDerivatives2 uv = rf_texture_derivatives(bary, tri.uv[0], tri.uv[1], tri.uv[2]);
    RfNeighbourDirections next = rf_pixel_directions(xy, size, rt_frame.view_inv, rt_frame.proj_inv);
    vec3 w = rt_weights(barycentrics);
    RfDerivatives3 offsets = rf_barycentric_offsets(world_to_object, origin, tri.p[0], tri.p[1], tri.p[2],
        next.right, next.below, w);
    RfDerivatives2 offset_uv = rf_uv_gradients_from_offsets(offsets, tri.uv[0], tri.uv[1], tri.uv[2]);
    vec3 deltas = rf_barycentric_deltas(world_to_object, origin, tri.p[0], tri.p[1], tri.p[2],
        next.right, next.below, w);
    return RtDiffRecord(eye.d_direction_dx, rt_texel_lod(uv), eye.d_direction_dy, rt_texel_lod(offset_uv),
        bary.dx, bary.dy, uv.dx, uv.dy, next.right, rt_coverage(w, deltas), next.below, 0u, offsets.dx, 0u,
        offsets.dy, 0u, offset_uv.dx, offset_uv.dy, deltas, 0u,
        rf_cone_barycentric_deltas(footprint, tri.p[0], tri.p[1], tri.p[2]), 0u);
}

// Whether the render mode carries ray differentials through the mirror.
bool rt_carries_diff() {
    return pc.mode == RT_MODE_RAY_DIFF || pc.mode == RT_MODE_RAY_DIFF_ISOTROPIC;
}

// The differential of the ray the mirror reflects at a primary hit (Igehy): the eye-ray
// differential carried to the hit (origin derivatives from the barycentric derivatives, RTG Eq. 22),
// its direction derivatives reflected about the interpolated normal, whose own derivatives come from
// the vertex normals.
RfRayDiff rt_reflected_diff(RtTriangle tri, vec2 barycentrics, RtPixelRecord record) {
    RfDerivatives2 bary = RfDerivatives2(record.diff.barycentric_dx, record.diff.barycentric_dy);
    RfDerivatives3 position = rf_secondary_origin_derivatives(bary, tri.p[0], tri.p[1], tri.p[2]);
    RfDerivatives3 normal = rf_normal_derivatives(tri.n[0], tri.n[1], tri.n[2], barycentrics, bary);
    RfRayDiff at_hit = RfRayDiff(position.dx, 0.0, position.dy, 0.0, record.diff.eye_d_direction_dx, 0.0,
        record.diff.eye_d_direction_dy, 0.0);
    return rf_reflect_ray_diff(at_hit, record.direction, record.normal, normal);
}

// The UV derivatives of a hit at distance t along the unit `direction` on `tri`, reached by a ray
// carrying `diff`: its barycentric derivatives (RTG Eq. 12-19) through the UVs (Eq. 21).
RfDerivatives2 rt_uv_derivatives(RtTriangle tri, RfRayDiff diff, vec3 direction, float t) {
    RfDerivatives2 bary = rf_barycentric_derivatives(diff, direction, t, tri.p[0], tri.p[1], tri.p[2]);
    return rf_texture_derivatives(bary, tri.uv[0], tri.uv[1], tri.uv[2]);
}

// textureGrad with UV gradients scaled by tex_grad_scale.
vec3 rt_sample_grad(vec2 uv, vec2 uv_dx, vec2 uv_dy) {
    RfDerivatives2 grad = rf_sample_grad_gradients(RfDerivatives2(uv_dx, uv_dy), pc.cone.tex_grad_scale);
    return textureGrad(rt_textures[0], uv, grad.dx, grad.dy).rgb;
}

// The texture colour at `uv` as the render mode samples it. The ray-differential modes read the
// UV derivatives of the record, measured on primary and secondary hits alike; the re-intersection
// needs a primary hit: on secondary hits it samples, like the cone modes and the wireframe's base,
// at the ray-cone LOD.
vec3 rt_texture_colour(RtPixelRecord record, vec2 uv, bool primary) {
    bool reintersection = pc.mode == RT_MODE_BARY_GRADIENTS;
    switch (reintersection && !primary ? RT_MODE_CONE : pc.mode) {
    case RT_MODE_MIP0:
        return textureLod(rt_textures[0], uv, 0.0).rgb;
    case RT_MODE_TEX_GRAD_SCALE:
        return textureGrad(rt_textures[0], uv, vec2(record.gradient, 0.0), vec2(0.0, record.gradient)).rgb;
    case RT_MODE_MIP_LEVELS:
        return textureLod(rt_textures[1], uv, record.lod).rgb;
    case RT_MODE_RAY_DIFF:
        return rt_sample_grad(uv, record.diff.uv_dx, record.diff.uv_dy);
    case RT_MODE_RAY_DIFF_ISOTROPIC:
        return textureLod(rt_textures[0], uv, record.diff.lod).rgb;
    case RT_MODE_BARY_GRADIENTS:
        return rt_sample_grad(uv, record.diff.offset_uv_dx, record.diff.offset_uv_dy);
    default: // RT_MODE_CONE, RT_MODE_CONE_CURVATURE, RT_MODE_WIREFRAME
        return textureLod(rt_textures[0], uv, record.lod).rgb;
    }
}

// Sky colour for a ray leaving the scene in `direction`.
vec3 rt_sky(vec3 direction) {
    return mix(vec3(0.75, 0.82, 0.9), vec3(0.35, 0.5, 0.8), clamp(direction.y, 0.0, 1.0));
}

#endif // RT_COMMON_GLSL
