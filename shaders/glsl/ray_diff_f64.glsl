// ray-footprint: Ray differentials in double precision, for scenes whose coordinate range defeats f32. Needs f64 in shaders (naga FLOAT64 / wgpu SHADER_F64; GLSL double with shaderFloat64).
//
// Library module for GLSL 460 (no main): #include "ray_diff_f64.glsl". Twin of shaders/wgsl/ray_diff_f64.wgsl
// and the Rust mirror src/ray_diff_f64.rs: same functions, same order, same order of operations.

#ifndef RAY_FOOTPRINT_RAY_DIFF_F64_GLSL
#define RAY_FOOTPRINT_RAY_DIFF_F64_GLSL

#endif // RAY_FOOTPRINT_RAY_DIFF_F64_GLSL
