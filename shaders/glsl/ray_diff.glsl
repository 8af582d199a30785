// ray-footprint: Ray differentials (Igehy 1999; RTG ch. 20 Eq. 1-24): how a ray's origin and direction change from pixel to pixel, carried to hits, barycentrics and texture coordinates.
//
// Library module for GLSL 460 (no main): #include "ray_diff.glsl". Twin of shaders/wgsl/ray_diff.wgsl
// and the Rust mirror src/ray_diff.rs: same functions, same order, same order of operations.

#ifndef RAY_FOOTPRINT_RAY_DIFF_GLSL
#define RAY_FOOTPRINT_RAY_DIFF_GLSL

#endif // RAY_FOOTPRINT_RAY_DIFF_GLSL
