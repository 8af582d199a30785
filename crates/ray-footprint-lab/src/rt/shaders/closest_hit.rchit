// Closest hit: measures the ray-cone values at the hit with the library module (rt_measure), and
// on a primary hit the ray-differential, re-intersection and wireframe values (rt_measure_diff);
// records them for primary rays, then shades: textured meshes sample the texture as the mode
// says, under the wireframe in RT_MODE_WIREFRAME (seen in the mirror, with the closed-form cone
// deltas); the mirror traces a reflected ray whose cone leaves the hit by RTG Eq. 35, widened by
// the curvature spread angle only in RT_MODE_CONE_CURVATURE (otherwise as off a planar mirror),
// and which, in the ray-differential modes, carries the reflected ray differential (Igehy).
#version 460
#extension GL_GOOGLE_include_directive : require
#include "rt_common.glsl"

layout(location = 0) rayPayloadInEXT RtPayload payload;
layout(location = 1) rayPayloadEXT RtPayload reflected;
hitAttributeEXT vec2 rt_hit_barycentrics;

void main() {
    uint mesh = gl_InstanceCustomIndexEXT;
    RtTriangle tri = rt_triangle(mesh, gl_PrimitiveID);
    vec3 direction = gl_WorldRayDirectionEXT;
    RtPixelRecord record = rt_measure(tri, rt_hit_barycentrics, gl_HitTEXT, direction, payload.hit.cone);
    record.instance = mesh;
    record.primitive = gl_PrimitiveID;
    bool primary = payload.hit.depth == 0u;
    vec3 w = rt_weights(rt_hit_barycentrics);
    if (primary) {
        record.diff = rt_measure_diff(tri, rt_hit_barycentrics, gl_HitTEXT, gl_WorldRayOriginEXT, direction,
            mat4(gl_WorldToObjectEXT), gl_LaunchIDEXT.xy, record.footprint);
        rt_records[gl_LaunchIDEXT.y * gl_LaunchSizeEXT.x + gl_LaunchIDEXT.x] = record;
    } else {
        vec3 deltas = rf_cone_barycentric_deltas(record.footprint, tri.p[0], tri.p[1], tri.p[2]);
        record.diff = rt_diff_record(deltas, rt_coverage(w, deltas));
        if (rt_carries_diff()) {
            RfDerivatives2 uv = rt_uv_derivatives(tri, payload.diff, direction, gl_HitTEXT);
            record.diff.uv_dx = uv.dx;
            record.diff.uv_dy = uv.dy;
            record.diff.lod = rt_texel_lod(uv);
        }
    }
    if (rt_meshes[3u * mesh + 2u] == RT_MATERIAL_MIRROR && primary) {
        float spread = pc.mode == RT_MODE_CONE_CURVATURE ? record.curvature_spread : 0.0;
        RfRayCone cone = rf_propagate(payload.hit.cone, gl_HitTEXT, spread);
        reflected = RtPayload(RfHitPayload(vec3(0.0), payload.hit.weight * RT_MIRROR_REFLECTANCE, cone, payload.hit.depth + 1u, 0u),
            payload.diff);
        if (rt_carries_diff()) {
            reflected.diff = rt_reflected_diff(tri, rt_hit_barycentrics, record);
        }
        vec3 origin = gl_WorldRayOriginEXT + gl_HitTEXT * direction + RT_SURFACE_OFFSET * record.normal;
        traceRayEXT(rt_scene, gl_RayFlagsOpaqueEXT, 0xff, 0, 0, 0, origin, 0.0,
            reflect(direction, record.normal), RT_MAX_DISTANCE, 1);
        payload.hit.colour = reflected.hit.colour;
        return;
    }
    vec2 uv = w.x * tri.uv[0] + w.y * tri.uv[1] + w.z * tri.uv[2];
    vec3 colour = rt_light(record.normal) * rt_texture_colour(record, uv, primary);
    if (pc.mode == RT_MODE_WIREFRAME) {
        colour = mix(colour, rt_frame.wireframe.colour.rgb, record.diff.coverage);
    }
    payload.hit.colour = payload.hit.weight * colour;
}
