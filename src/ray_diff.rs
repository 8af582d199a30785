//! Ray differentials (Igehy 1999; RTG ch. 20 Eq. 1-24): how a ray's origin and direction change from pixel to pixel, carried to hits, barycentrics and texture coordinates.
//!
//! The Rust mirror of `shaders/wgsl/ray_diff.wgsl` and `shaders/glsl/ray_diff.glsl`.
