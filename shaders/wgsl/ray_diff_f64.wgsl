// ray-footprint: Ray differentials in double precision, for scenes whose coordinate range defeats f32. Needs f64 in shaders (naga FLOAT64 / wgpu SHADER_F64; GLSL double with shaderFloat64).
//
// Library module (no entry points). Twin of shaders/glsl/ray_diff_f64.glsl and the Rust mirror
// src/ray_diff_f64.rs: same functions, same order, same order of operations.
