// ray-footprint ray-tracing renderer: the structs its shaders share with Rust (mirrors in
// src/abi.rs, layouts compared by tests/rt.rs). Declarations only, so a layout probe can include it.

#ifndef RT_ABI_GLSL
#define RT_ABI_GLSL

#include "ray_cone.glsl"

// Push constants (Rust mirror: ray_footprint::abi::RtPushConstants, 80 bytes).
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
};

// What a primary hit measured (Rust mirror: ray_footprint::abi::RtPixelRecord, 96 bytes).
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
};

#endif // RT_ABI_GLSL
