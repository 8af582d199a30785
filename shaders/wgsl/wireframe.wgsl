// ray-footprint: Anti-aliased wireframe from per-pixel barycentric deltas, with the bool-to-int settings mirror.
//
// Library module (no entry points). Twin of shaders/glsl/wireframe.glsl and the Rust mirror
// src/wireframe.rs: same functions, same order, same order of operations.
