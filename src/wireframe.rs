//! Anti-aliased wireframe from per-pixel barycentric deltas, with the bool-to-int settings mirror.
//!
//! The Rust mirror of `shaders/wgsl/wireframe.wgsl` and `shaders/glsl/wireframe.glsl`.
