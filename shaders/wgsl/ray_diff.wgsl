// ray-footprint: Ray differentials (Igehy 1999; RTG ch. 20 Eq. 1-24): how a ray's origin and direction change from pixel to pixel, carried to hits, barycentrics and texture coordinates.
//
// Library module (no entry points). Twin of shaders/glsl/ray_diff.glsl and the Rust mirror
// src/ray_diff.rs: same functions, same order, same order of operations.
