// ray-footprint ray-tracing renderer: what both pipelines' closest-hit shaders share, the hit
// attributes and the hit as the shading code (rt_shading.glsl) takes it. Include it after
// rt_common.glsl in closest-hit shaders only (it reads their built-in variables).

#ifndef RT_CLOSEST_HIT_GLSL
#define RT_CLOSEST_HIT_GLSL

hitAttributeEXT vec2 rt_hit_barycentrics;

// The hit this shader was called for, of a ray at bounce `depth`.
RtHit rt_current_hit(uint depth) {
    return rt_hit(gl_InstanceCustomIndexEXT, gl_PrimitiveID, rt_hit_barycentrics, gl_WorldRayOriginEXT,
        gl_WorldRayDirectionEXT, gl_HitTEXT, mat4(gl_WorldToObjectEXT), gl_LaunchIDEXT.xy, depth);
}

#endif // RT_CLOSEST_HIT_GLSL
