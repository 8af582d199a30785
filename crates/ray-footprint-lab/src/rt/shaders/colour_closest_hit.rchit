// Closest hit of the colour-only shaders: shades the hit as closest_hit.rchit does in the render
// mode RT_COLOUR_MODE (an RT_MODE_* value the renderer defines), computing only what that mode
// needs and recording nothing. Textured meshes sample the texture at the mode's level of detail
// (under the wireframe in RT_MODE_WIREFRAME); the mirror traces a reflected ray, whose cone leaves
// the hit by RTG Eq. 35, widened by the curvature spread angle in RT_MODE_CONE_CURVATURE only.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "rt_common.glsl"
#include "colour_payload.glsl"

layout(location = 0) rayPayloadInEXT RtColourPayload payload;
layout(location = 1) rayPayloadEXT RtColourPayload reflected;
hitAttributeEXT vec2 rt_hit_barycentrics;

#ifdef RT_PAYLOAD_CONE
// The ray-cone texture LOD of the hit (RTG Eq. 34).
float rt_cone_lod(RtTriangle tri, vec3 normal, vec3 direction) {
    float base_lod = rf_triangle_base_lod(tri.p[0], tri.p[1], tri.p[2], tri.uv[0], tri.uv[1], tri.uv[2]);
    return rf_texture_lod(base_lod, rf_width_at(payload.cone, gl_HitTEXT), vec2(pc.texture_size), normal,
        direction);
}

// The ray-cone footprint of the hit in world units.
float rt_footprint(vec3 normal, vec3 direction) {
    return rf_world_footprint(payload.cone, gl_HitTEXT, normal, direction);
}

// The neighbour pixels' rays re-intersected with the triangle's plane.
RfDerivatives3 rt_offsets(RtTriangle tri, vec3 weights) {
    RfNeighbourDirections next = rf_pixel_directions(vec2(gl_LaunchIDEXT.xy), vec2(pc.width, pc.height),
        rt_frame.view_inv, rt_frame.proj_inv);
    return rf_barycentric_offsets(mat4(gl_WorldToObjectEXT), gl_WorldRayOriginEXT, tri.p[0], tri.p[1], tri.p[2],
        next.right, next.below, weights);
}
#endif

// The texture colour at `uv` as the mode samples it (rt_texture_colour's choice). The gradient
// modes' own gradients exist on primary hits only; secondary hits sample at the ray-cone LOD.
vec3 rt_mode_texture(RtTriangle tri, vec2 uv, vec3 weights, vec3 normal, vec3 direction, bool primary) {
#ifndef RT_PAYLOAD_CONE
    return textureLod(rt_textures[0], uv, 0.0).rgb;
#else
#ifdef RT_PAYLOAD_DIFF
    if (primary) {
        RfRayDiff eye = RfRayDiff(vec3(0.0), 0.0, vec3(0.0), 0.0, payload.d_direction_dx, 0.0,
            payload.d_direction_dy, 0.0);
        RfDerivatives2 bary = rf_barycentric_derivatives(eye, direction, gl_HitTEXT, tri.p[0], tri.p[1], tri.p[2]);
        RfDerivatives2 uv_gradients = rf_texture_derivatives(bary, tri.uv[0], tri.uv[1], tri.uv[2]);
        return rt_sample_grad(uv, uv_gradients.dx, uv_gradients.dy);
    }
#endif
    if (RT_COLOUR_MODE == RT_MODE_BARY_GRADIENTS && primary) {
        RfDerivatives3 offsets = rt_offsets(tri, weights);
        RfDerivatives2 uv_gradients = rf_uv_gradients_from_offsets(offsets, tri.uv[0], tri.uv[1], tri.uv[2]);
        return rt_sample_grad(uv, uv_gradients.dx, uv_gradients.dy);
    }
    if (RT_COLOUR_MODE == RT_MODE_TEX_GRAD_SCALE) {
        float density = rf_texel_density(tri.p[0], tri.p[1], tri.p[2], tri.uv[0], tri.uv[1], tri.uv[2]);
        float gradient = rf_texture_gradient(rt_footprint(normal, direction) * density, pc.cone.tex_grad_scale);
        return textureGrad(rt_textures[0], uv, vec2(gradient, 0.0), vec2(0.0, gradient)).rgb;
    }
    uint texture_index = RT_COLOUR_MODE == RT_MODE_MIP_LEVELS ? 1u : 0u;
    return textureLod(rt_textures[texture_index], uv, rt_cone_lod(tri, normal, direction)).rgb;
#endif
}

// The wireframe coverage of the hit: barycentric deltas by re-intersection on primary hits, the
// closed-form cone deltas on secondary hits.
float rt_mode_coverage(RtTriangle tri, vec3 weights, vec3 normal, vec3 direction, bool primary) {
#ifdef RT_PAYLOAD_CONE
    if (RT_COLOUR_MODE == RT_MODE_WIREFRAME) {
        vec3 deltas;
        if (primary) {
            RfNeighbourDirections next = rf_pixel_directions(vec2(gl_LaunchIDEXT.xy), vec2(pc.width, pc.height),
                rt_frame.view_inv, rt_frame.proj_inv);
            deltas = rf_barycentric_deltas(mat4(gl_WorldToObjectEXT), gl_WorldRayOriginEXT, tri.p[0], tri.p[1],
                tri.p[2], next.right, next.below, weights);
        } else {
            deltas = rf_cone_barycentric_deltas(rt_footprint(normal, direction), tri.p[0], tri.p[1], tri.p[2]);
        }
        return rt_coverage(weights, deltas);
    }
#endif
    return 0.0;
}

// The spread angle a reflection off this hit adds to its cone: the curvature's in
// RT_MODE_CONE_CURVATURE (JCGT 2021), 0 (a planar mirror) otherwise.
float rt_reflection_spread(RtTriangle tri, vec3 normal, vec3 direction) {
#ifdef RT_PAYLOAD_CONE
    if (RT_COLOUR_MODE == RT_MODE_CONE_CURVATURE) {
        float curvature = rf_triangle_curvature(tri.p[0], tri.p[1], tri.p[2], tri.n[0], tri.n[1], tri.n[2]);
        return rf_curvature_spread_angle(curvature, rf_width_at(payload.cone, gl_HitTEXT), normal, direction);
    }
#endif
    return 0.0;
}

void main() {
    uint mesh = gl_InstanceCustomIndexEXT;
    RtTriangle tri = rt_triangle(mesh, gl_PrimitiveID);
    vec3 direction = gl_WorldRayDirectionEXT;
    vec3 w = rt_weights(rt_hit_barycentrics);
    vec3 normal = normalize(w.x * tri.n[0] + w.y * tri.n[1] + w.z * tri.n[2]);
    bool primary = payload.depth == 0u;
    if (rt_meshes[3u * mesh + 2u] == RT_MATERIAL_MIRROR && primary) {
        reflected.colour = vec3(0.0);
        reflected.depth = payload.depth + 1u;
#ifdef RT_PAYLOAD_CONE
        reflected.cone = rf_propagate(payload.cone, gl_HitTEXT, rt_reflection_spread(tri, normal, direction));
#endif
        vec3 origin = gl_WorldRayOriginEXT + gl_HitTEXT * direction + RT_SURFACE_OFFSET * normal;
        traceRayEXT(rt_scene, gl_RayFlagsOpaqueEXT, 0xff, 0, 0, 0, origin, 0.0, reflect(direction, normal),
            RT_MAX_DISTANCE, 1);
        payload.colour = RT_MIRROR_REFLECTANCE * reflected.colour;
        return;
    }
    vec2 uv = w.x * tri.uv[0] + w.y * tri.uv[1] + w.z * tri.uv[2];
    vec3 colour = rt_light(normal) * rt_mode_texture(tri, uv, w, normal, direction, primary);
    if (RT_COLOUR_MODE == RT_MODE_WIREFRAME) {
        colour = mix(colour, rt_frame.wireframe.colour.rgb, rt_mode_coverage(tri, w, normal, direction, primary));
    }
    payload.colour = colour;
}
