//! Ray differentials in double precision, for scenes whose coordinate range defeats f32. Needs f64 in shaders (naga FLOAT64 / wgpu SHADER_F64; GLSL double with shaderFloat64).
//!
//! The Rust mirror of `shaders/wgsl/ray_diff_f64.wgsl` and `shaders/glsl/ray_diff_f64.glsl`.
