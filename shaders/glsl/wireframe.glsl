// ray-footprint: Anti-aliased wireframe from per-pixel barycentric deltas, with the bool-to-int settings mirror.
//
// Library module for GLSL 460 (no main): #include "wireframe.glsl". Twin of shaders/wgsl/wireframe.wgsl
// and the Rust mirror src/wireframe.rs: same functions, same order, same order of operations.

#ifndef RAY_FOOTPRINT_WIREFRAME_GLSL
#define RAY_FOOTPRINT_WIREFRAME_GLSL

#endif // RAY_FOOTPRINT_WIREFRAME_GLSL
