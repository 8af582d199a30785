// ray-footprint ray-tracing renderer: the structs its shaders share with Rust (mirrors in
// src/abi.rs, layouts compared by tests/rt.rs). Declarations only, so a layout probe can include it.

#ifndef RT_ABI_GLSL
#define RT_ABI_GLSL

#include "ray_cone.glsl"
#include "wireframe.glsl"

// Push constants (Rust mirror: ray_footprint_lab::rt::abi::RtPushConstants, 96 bytes).
struct RtPushConstants {
    vec3 eye;
    float tan_half_fov_y;
    vec3 right;
    float aspect;
    vec3 up;
    float texture_size;
    vec3 forward;
    uint mode;
    RfRayConePushConstants cone;
    uint width;
    uint height;
    vec2 pixel_offset;
    uint flags;
    uint pad;
};

// The ray-differential, re-intersection and wireframe values of a primary hit (Rust mirror:
// ray_footprint_lab::rt::abi::RtDiffRecord, 176 bytes; the field docs are there).
struct RtDiffRecord {
    vec3 eye_d_direction_dx;
    float lod;
    vec3 eye_d_direction_dy;
    float offset_lod;
    vec2 barycentric_dx;
    vec2 barycentric_dy;
    vec2 uv_dx;
    vec2 uv_dy;
    vec3 neighbour_right;
    float coverage;
    vec3 neighbour_below;
    uint pad0;
    vec3 offset_dx;
    uint pad1;
    vec3 offset_dy;
    uint pad2;
    vec2 offset_uv_dx;
    vec2 offset_uv_dy;
    vec3 deltas;
    uint pad3;
    vec3 cone_deltas;
    uint pad4;
};

// What a primary hit measured (Rust mirror: ray_footprint_lab::rt::abi::RtPixelRecord, 320 bytes).
struct RtPixelRecord {
    vec3 normal;
    float t;
    vec3 direction;
    uint instance;
    vec2 barycentrics;
    uint primitive;
    uint hit;
    RfRayCone cone;
    float width;
    float footprint;
    float texel_density;
    float base_lod;
    float lod;
    float gradient;
    float curvature;
    float curvature_spread;
    RfRayCone reflected;
    RtDiffRecord diff;
    float roughness_spread;
    float eta;
    float normal_spread;
    uint total_internal_reflection;
    RfRayCone refracted;
    vec2 cone_uv_dx;
    vec2 cone_uv_dy;
    uvec2 pad;
};

// Per-frame uniforms (Rust mirror: ray_footprint_lab::rt::abi::RtUniforms, 176 bytes, std140 = std430):
// inverse view and projection matrices, wireframe colour and settings.
struct RtUniforms {
    mat4 view_inv;
    mat4 proj_inv;
    RfWireframePushConstants wireframe;
};

#endif // RT_ABI_GLSL
