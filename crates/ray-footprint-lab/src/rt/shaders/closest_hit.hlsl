// Closest hit of the recording shaders in HLSL, in place of closest_hit.rchit: the library's HLSL
// modules brought in by #include as an HLSL renderer would, the generated structs and constants of
// rt_abi.hlsl, and the closest hit of rt_closest_hit.hlsl, so every rf_ call it makes is a call of
// the HLSL modules. slangc compiles it, reading HLSL: glslang's HLSL front end has no ray-tracing
// stages. The renderer runs it with the GLSL ray generation and miss shaders (ClosestHit::Hlsl);
// tests/gpu/rt.rs compares every pixel it records with the Rust mirror, and every colour it
// renders with the GLSL closest hit's.

#include "rt_abi.hlsl"
#include "ray_diff.hlsl"
#include "rt_closest_hit.hlsl"
