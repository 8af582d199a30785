// ray-footprint ray-tracing renderer: the shading code, written once and compiled twice. glslang
// compiles it as GLSL inside rt_common.glsl, after the GLSL modules ray_cone.glsl, ray_diff.glsl and
// wireframe.glsl and the GLSL resource declarations; slangc compiles it inside closest_hit.slang
// (`import glsl;`, Slang's GLSL compatibility), where every rf_ call resolves to the Slang modules
// ray_cone, ray_diff and wireframe and every resource is declared in Slang. So the Slang closest hit
// runs the Slang modules in a real ray-tracing pipeline with the same shading as the GLSL one.
//
// It declares no resources and no constants: it reads the push constants `pc`, the buffers
// `rt_vertices`, `rt_indices`, `rt_meshes`, the textures `rt_textures` and the uniforms `rt_frame`
// that the including file declares, and the RT_ constants of rt_abi.glsl / rt_abi.slang (generated
// from the Rust declarations). It uses only the GLSL that Slang's `glsl` module also provides, and
// means the same in both: vectors are compared with equal() and all() (`==` of two vectors is one
// bool in GLSL, a bool vector in Slang), and matrices are only passed on, never multiplied (`*`
// of two matrices is their product in GLSL, the product of each element in Slang).

#ifndef RT_SHADING_GLSL
#define RT_SHADING_GLSL

#include "rt_path_rules.glsl"

// The section of a ray's beam across the plane of incidence of the last refraction (the sagittal
// section), which RT_MODE_CONE_SECTIONS carries beside the cone (the tangential section, in that
// plane): its cone and its axis, the unit cross(direction, normal) of that refraction. A round beam
// (a primary ray's, or any before glass) has both sections equal and no axis (zero).
struct RtSagittal {
    RfRayCone cone;
    vec3 axis;
};

// The recording shaders' ray payload: the library's cone payload, the ray's differential (Igehy),
// which the ray-differential modes carry through the mirror, and the sagittal section. A primary
// ray carries the eye-ray differential (rt_eye_diff) and its cone as a round sagittal section
// (rt_round_sagittal).
struct RtPayload {
    RfHitPayload hit;
    RfRayDiff diff;
    RtSagittal sagittal;
};

// The sagittal section of a round beam of cone `cone`: the cone itself, no axis.
RtSagittal rt_round_sagittal(RfRayCone cone) {
    return RtSagittal(cone, vec3(0.0));
}

// A ray differential of zero, for a ray that carries none.
RfRayDiff rt_no_diff() {
    return RfRayDiff(vec3(0.0), 0.0, vec3(0.0), 0.0, vec3(0.0), 0.0, vec3(0.0), 0.0);
}

// A triangle's vertices.
struct RtTriangle {
    vec3 p[3];
    vec3 n[3];
    vec2 uv[3];
};

// Triangle `primitive` of mesh `mesh`, from the vertex, index and mesh-table buffers.
RtTriangle rt_triangle(uint mesh, uint primitive) {
    uint first_index = rt_meshes[RT_MESH_TABLE_WORDS * mesh] + 3u * primitive;
    uint first_vertex = rt_meshes[RT_MESH_TABLE_WORDS * mesh + 1u];
    RtTriangle tri;
    for (uint k = 0u; k < 3u; k++) {
        uint f = (first_vertex + rt_indices[first_index + k]) * RT_VERTEX_FLOATS;
        tri.p[k] = vec3(rt_vertices[f], rt_vertices[f + 1u], rt_vertices[f + 2u]);
        tri.n[k] = vec3(rt_vertices[f + 4u], rt_vertices[f + 5u], rt_vertices[f + 6u]);
        tri.uv[k] = vec2(rt_vertices[f + 3u], rt_vertices[f + 7u]);
    }
    return tri;
}

// Barycentric weights (1 - u - v, u, v).
vec3 rt_weights(vec2 barycentrics) {
    return vec3(1.0 - barycentrics.x - barycentrics.y, barycentrics.x, barycentrics.y);
}

// A hash of four words to four (Jarzynski, Olano, "Hash Functions for GPU Rendering", JCGT 9(3),
// 2020: pcg4d): a multiply-add per word, then two rounds of mixing each word into the next around an
// xor-shift.
uvec4 rt_hash(uvec4 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    v ^= v >> 16u;
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    return v;
}

// The offset of `pixel`'s sample from the pixel's centre, in [-0.5, 0.5)^2: pc.pixel_offset, or with
// RT_FLAG_PIXEL_JITTER the pixel's own, from the two words of its hash that rt_random leaves unused
// (so a path's numbers and its sample's position are drawn apart). The flag is the frame's, so the
// branch is uniform, and a frame without it hashes nothing.
vec2 rt_sample_offset(uvec2 pixel) {
    if ((pc.flags & RT_FLAG_PIXEL_JITTER) == 0u) {
        return pc.pixel_offset;
    }
    uvec4 words = rt_hash(uvec4(pixel, floatBitsToUint(pc.pixel_offset.x), floatBitsToUint(pc.pixel_offset.y)));
    return vec2(words.zw >> 8u) * (1.0 / 16777216.0) - 0.5;
}

// Unit direction of the primary ray through `pixel`, offset from its centre by rt_sample_offset
// (see RtPushConstants' Rust doc).
vec3 rt_primary_direction(uvec2 pixel) {
    vec2 c = 2.0 * (vec2(pixel) + 0.5 + rt_sample_offset(pixel)) / vec2(pc.width, pc.height) - 1.0;
    return normalize(pc.forward + c.x * pc.aspect * pc.tan_half_fov_y * pc.right
        - c.y * pc.tan_half_fov_y * pc.up);
}

// Diffuse lighting of a surface with unit normal `normal`: an ambient part and the light's.
float rt_light(vec3 normal) {
    return 0.35 + 0.65 * max(dot(normal, normalize(RT_LIGHT)), 0.0);
}

// A pixel's colour as stored: gamma 2.2, RGBA8.
uint rt_display(vec3 colour) {
    return packUnorm4x8(vec4(pow(clamp(colour, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0));
}

// A mesh's material: RT_MATERIAL_* and its parameter (a mirror's roughness, glass's index of
// refraction).
struct RtMaterial {
    uint kind;
    float parameter;
};

// The hit a closest-hit shader was called for, as the shared functions take it.
struct RtHit {
    // The hit mesh (instance custom index) and its material.
    uint mesh;
    RtMaterial material;
    // The hit triangle: its index in the mesh and its vertices.
    uint primitive;
    RtTriangle tri;
    // Hit barycentrics (u, v) of vertices 1 and 2, and the weights (1 - u - v, u, v).
    vec2 barycentrics;
    vec3 weights;
    // Unit shading normal interpolated from the stored vertex normals (not turned to the ray).
    vec3 normal;
    // The ray: origin, unit direction, hit distance.
    vec3 origin;
    vec3 direction;
    float t;
    // The hit instance's world-to-object matrix.
    mat4 world_to_object;
    // The pixel the ray belongs to, and its bounce depth (0: the primary ray).
    uvec2 pixel;
    uint depth;
};

// The hit of the ray from `origin` along the unit `direction` at distance t on triangle `primitive`
// of `mesh`, at `barycentrics`, for `pixel`'s ray at bounce `depth`.
RtHit rt_hit(uint mesh, uint primitive, vec2 barycentrics, vec3 origin, vec3 direction, float t,
        mat4 world_to_object, uvec2 pixel, uint depth) {
    RtTriangle tri = rt_triangle(mesh, primitive);
    vec3 w = rt_weights(barycentrics);
    vec3 normal = normalize(w.x * tri.n[0] + w.y * tri.n[1] + w.z * tri.n[2]);
    uint entry = RT_MESH_TABLE_WORDS * mesh;
    RtMaterial material = RtMaterial(rt_meshes[entry + 2u], uintBitsToFloat(rt_meshes[entry + 3u]));
    return RtHit(mesh, material, primitive, tri, barycentrics, w, normal, origin, direction, t, world_to_object,
        pixel, depth);
}

// The texture coordinates of the hit.
vec2 rt_uv(RtHit hit) {
    return hit.weights.x * hit.tri.uv[0] + hit.weights.y * hit.tri.uv[1] + hit.weights.z * hit.tri.uv[2];
}

// The primary ray's cone: the pixel spread angle (RTG Eq. 30) narrowed off axis by the ray's
// cosine to the view axis.
RfRayCone rt_primary_cone(vec3 direction) {
    return rf_pinhole_ray_cone_for_ray(pc.cone.pixel_spread_angle, direction, pc.forward);
}

// The eye-ray differential of the primary ray through `pixel` (offset by rt_sample_offset), from the
// inverse matrices; its origin differentials are 0.
RfRayDiff rt_eye_diff(uvec2 pixel) {
    return rf_eye_ray_diff_from_matrices(vec2(pixel) + rt_sample_offset(pixel), vec2(pc.width, pc.height),
        rt_frame.view_inv, rt_frame.proj_inv);
}

// The directions of the rays through the right and the lower neighbours of `pixel` (offset alike).
RfNeighbourDirections rt_neighbours(uvec2 pixel) {
    return rf_pixel_directions(vec2(pixel) + rt_sample_offset(pixel), vec2(pc.width, pc.height), rt_frame.view_inv,
        rt_frame.proj_inv);
}

// The ray-cone texture LOD of the hit reached by `cone` (RTG Eq. 34).
float rt_cone_lod(RtHit hit, RfRayCone cone) {
    RtTriangle tri = hit.tri;
    float base_lod = rf_triangle_base_lod(tri.p[0], tri.p[1], tri.p[2], tri.uv[0], tri.uv[1], tri.uv[2]);
    return rf_texture_lod(base_lod, rf_width_at(cone, hit.t), vec2(pc.texture_size), hit.normal, hit.direction);
}

// The ray-cone footprint of the hit reached by `cone`, in world units.
float rt_footprint(RtHit hit, RfRayCone cone) {
    return rf_world_footprint(cone, hit.t, hit.normal, hit.direction);
}

// The isotropic textureGrad gradient of the hit reached by `cone`: its footprint in UV units times
// tex_grad_scale.
float rt_cone_gradient(RtHit hit, RfRayCone cone) {
    RtTriangle tri = hit.tri;
    float density = rf_texel_density(tri.p[0], tri.p[1], tri.p[2], tri.uv[0], tri.uv[1], tri.uv[2]);
    return rf_texture_gradient(rt_footprint(hit, cone) * density, pc.cone.tex_grad_scale);
}

// The curvature the hit triangle gives an isotropic cone: the principal curvatures of the shape
// operator fitted to its vertex normals (Rusinkiewicz 2004, Sec. 3), the lesser in magnitude when
// they agree in sign, 0 on a saddle (rf_isotropic_curvature).
float rt_curvature(RtHit hit) {
    RtTriangle tri = hit.tri;
    vec3 shape_operator = rf_triangle_shape_operator(tri.p[0], tri.p[1], tri.p[2], tri.n[0], tri.n[1], tri.n[2]);
    return rf_isotropic_curvature(rf_principal_curvatures(shape_operator));
}

// The OptiX Toolkit's estimate of the hit triangle's curvature (ray_cone.h, minTriangleCurvature):
// of the three edge curvatures (the change of the normal along the edge over its length), the one
// of least magnitude when all three have one sign, else 0: a saddle's triangle, whose edges bend
// both ways, reflects as a plane.
float rt_least_edge_curvature(RtHit hit) {
    RtTriangle tri = hit.tri;
    float k01 = rf_edge_curvature(tri.p[0], tri.p[1], tri.n[0], tri.n[1]);
    float k12 = rf_edge_curvature(tri.p[1], tri.p[2], tri.n[1], tri.n[2]);
    float k20 = rf_edge_curvature(tri.p[2], tri.p[0], tri.n[2], tri.n[0]);
    if (k01 > 0.0 && k12 > 0.0 && k20 > 0.0) {
        return min(k01, min(k12, k20));
    }
    if (k01 < 0.0 && k12 < 0.0 && k20 < 0.0) {
        return max(k01, max(k12, k20));
    }
    return 0.0;
}

// The curvature a reflection or refraction in `mode` takes: the least edge curvature in
// RT_MODE_CONE_MIN_CURVATURE, the fitted shape operator's isotropic curvature in the others.
float rt_mode_curvature(uint mode, RtHit hit) {
    return mode == RT_MODE_CONE_MIN_CURVATURE ? rt_least_edge_curvature(hit) : rt_curvature(hit);
}

// The spread angle a reflection off the hit reached by `cone` gets from `curvature` (JCGT 2021).
float rt_curvature_spread(RtHit hit, RfRayCone cone, float curvature) {
    return rf_curvature_spread_angle(curvature, rf_width_at(cone, hit.t), hit.normal, hit.direction);
}

// The spread angle a mirror's roughness adds to a reflection, each way (JCGT 2021's mapping): 0 on
// a smooth mirror and on other materials.
float rt_roughness_spread(RtHit hit) {
    return hit.material.kind == RT_MATERIAL_MIRROR ? rf_roughness_spread_angle(hit.material.parameter) : 0.0;
}

// Whether `mode` widens reflected (and refracted) cones by the surface's curvature.
bool rt_follows_curvature(uint mode) {
    return mode == RT_MODE_CONE_CURVATURE || mode == RT_MODE_CONE_REFRACTION || mode == RT_MODE_CONE_ROUGHNESS
        || mode == RT_MODE_CONE_MIN_CURVATURE || mode == RT_MODE_CONE_ANISOTROPIC || mode == RT_MODE_CONE_SECTIONS;
}

// The spread angle a reflection off the hit adds to `cone` in `mode`: the curvature's (JCGT 2021)
// in the modes that follow the curvature, and in RT_MODE_CONE_ROUGHNESS twice the roughness spread
// on top (one for each way the lobe spreads the reflected direction); 0 in the others (a planar
// mirror).
float rt_reflection_spread(uint mode, RtHit hit, RfRayCone cone) {
    if (!rt_follows_curvature(mode)) {
        return 0.0;
    }
    float spread = rt_curvature_spread(hit, cone, rt_mode_curvature(mode, hit));
    return mode == RT_MODE_CONE_ROUGHNESS ? spread + 2.0 * rt_roughness_spread(hit) : spread;
}

// The index ratio n_incident / n_transmitted at a glass hit: 1 / index entering (the ray meets the
// side the stored normal points to), the index leaving.
float rt_relative_index(RtHit hit) {
    float index = hit.material.parameter;
    return dot(hit.normal, hit.direction) < 0.0 ? 1.0 / index : index;
}

// The normal's turn across the footprint of `cone` at the hit, as rf_refract_ray_cone takes it:
// the curvature from the stored normals times the slanted footprint |width| / |n.d|, positive
// where the surface is convex on the side the stored normal points to (the curvature's sign, as
// rf_curvature_spread_angle takes it with the same normal).
float rt_normal_spread(RtHit hit, RfRayCone cone) {
    return rt_curvature(hit) * rt_footprint(hit, cone);
}

// The refraction of `cone` at the glass hit with index ratio eta (RTG II ch. 10, whole angles):
// the cone propagated to the hit, refracted at the stored normal with rt_normal_spread; on total
// internal reflection the reflected cone and the flag.
RfRefractedRayCone rt_refract_cone(RtHit hit, RfRayCone cone, float eta) {
    return rf_refract_ray_cone(rf_propagate(cone, hit.t, 0.0), hit.normal, hit.direction, rt_normal_spread(hit, cone),
        eta);
}

// The normal's turn across the sagittal section `section` at the hit, as rf_refract_sagittal_cone
// takes it: the curvature times the section's width |width| (it lies in the tangent plane: no
// slant), positive where the surface is convex on the side the stored normal points to.
float rt_sagittal_normal_spread(RtHit hit, RfRayCone section) {
    return rt_curvature(hit) * abs(rf_width_at(section, hit.t));
}

// The sagittal section leaving a glass hit with index ratio eta, from the section `section` across
// the plane of incidence (Coddington's sagittal equation; on total internal reflection the
// reflected section).
RfRayCone rt_refract_sagittal(RtHit hit, RfRayCone section, float eta) {
    return rf_refract_sagittal_cone(rf_propagate(section, hit.t, 0.0), hit.normal, hit.direction,
        rt_sagittal_normal_spread(hit, section), eta);
}

// The two sections of a ray's beam: the cone (the tangential section) and the sagittal section.
struct RtSections {
    RfRayCone cone;
    RtSagittal sagittal;
};

// The sections leaving a glass hit with index ratio eta in RT_MODE_CONE_SECTIONS. The new sagittal
// axis is the unit cross(direction, normal) (kept at normal incidence, where there is no plane of
// incidence); where it lies nearer the carried cone's axis than the carried sagittal one (more than
// 45 degrees from it, as for a round beam's zero axis), the carried sections swap roles first. The
// section in the plane of incidence is refracted by rt_refract_cone, the one across it by
// rt_refract_sagittal.
RtSections rt_refract_sections(RtHit hit, RfRayCone cone, RtSagittal sagittal, float eta) {
    vec3 across = cross(hit.direction, hit.normal);
    float across_length = length(across);
    vec3 axis = across_length > RF_MIN_MAGNITUDE ? across / across_length : sagittal.axis;
    bool swap = abs(dot(axis, sagittal.axis)) < 0.70710678;
    RfRayCone tangential = swap ? sagittal.cone : cone;
    RfRayCone section = swap ? cone : sagittal.cone;
    return RtSections(rt_refract_cone(hit, tangential, eta).cone, RtSagittal(rt_refract_sagittal(hit, section, eta),
        axis));
}

// The sections of the ray a glass hit passes on in `mode`: both refracted in RT_MODE_CONE_SECTIONS
// (rt_refract_sections); in RT_MODE_CONE_REFRACTION the cone refracted (rt_refract_cone) and the
// sagittal section, which that mode does not read, carried on; in the others both carried on as if
// the glass were not there.
RtSections rt_glass_sections(uint mode, RtHit hit, RfRayCone cone, RtSagittal sagittal, float eta) {
    if (mode == RT_MODE_CONE_SECTIONS) {
        return rt_refract_sections(hit, cone, sagittal, eta);
    }
    bool refracts = mode == RT_MODE_CONE_REFRACTION || mode == RT_MODE_PATH_CONE;
    RfRayCone leaving = refracts ? rt_refract_cone(hit, cone, eta).cone : rf_propagate(cone, hit.t, 0.0);
    return RtSections(leaving, RtSagittal(rf_propagate(sagittal.cone, hit.t, 0.0), sagittal.axis));
}

// The sections of the ray a mirror reflects in `mode`: each widened by rt_reflection_spread of its own
// width (RTG Eq. 35), the sagittal axis mirrored with the ray.
RtSections rt_mirror_sections(uint mode, RtHit hit, RfRayCone cone, RtSagittal sagittal) {
    RfRayCone reflected = rf_propagate(cone, hit.t, rt_reflection_spread(mode, hit, cone));
    RfRayCone section = rf_propagate(sagittal.cone, hit.t, rt_reflection_spread(mode, hit, sagittal.cone));
    return RtSections(reflected, RtSagittal(section, reflect(sagittal.axis, hit.normal)));
}

// The cone a surface reached by the ray carrying `cone` and `sagittal` is filtered with: in
// RT_MODE_CONE_SECTIONS the round cone whose footprint is as long as the longer axis of the two
// sections' ellipse on the surface (rf_two_section_width; the same as `cone` for a round beam), at
// the hit (spread 0, so rf_width_at gives its width at any t); in the other modes `cone`.
RfRayCone rt_arriving_cone(uint mode, RtHit hit, RfRayCone cone, RtSagittal sagittal) {
    if (mode != RT_MODE_CONE_SECTIONS) {
        return cone;
    }
    float width = rf_two_section_width(rf_width_at(cone, hit.t), rf_width_at(sagittal.cone, hit.t), sagittal.axis,
        hit.normal, hit.direction);
    return RfRayCone(width, 0.0);
}

// The anisotropic textureGrad gradients of the footprint of `cone` at the hit (JCGT 2021, the
// elliptical footprint's axes in UV units).
RfDerivatives2 rt_cone_uv_gradients(RtHit hit, RfRayCone cone) {
    RtTriangle tri = hit.tri;
    return rf_anisotropic_cone_gradients(rf_width_at(cone, hit.t), hit.direction, tri.p[0], tri.p[1], tri.p[2],
        tri.uv[0], tri.uv[1], tri.uv[2]);
}

// The barycentric derivatives (RTG Eq. 12-19) of the hit reached by a ray carrying `diff`.
RfDerivatives2 rt_barycentric_derivatives(RtHit hit, RfRayDiff diff) {
    return rf_barycentric_derivatives(diff, hit.direction, hit.t, hit.tri.p[0], hit.tri.p[1], hit.tri.p[2]);
}

// UV derivatives (RTG Eq. 21) from the hit's barycentric derivatives.
RfDerivatives2 rt_uv_derivatives(RtHit hit, RfDerivatives2 barycentric) {
    return rf_texture_derivatives(barycentric, hit.tri.uv[0], hit.tri.uv[1], hit.tri.uv[2]);
}

// The isotropic LOD (RTG Eq. 1-2) of UV gradients scaled to texels (the size is a power of two).
float rt_texel_lod(RfDerivatives2 uv) {
    return rf_lod_isotropic(RfDerivatives2(uv.dx * pc.texture_size, uv.dy * pc.texture_size));
}

// The neighbour pixels' rays (`next`) re-intersected with the hit triangle's plane: signed
// barycentric offsets (w, u, v).
RfDerivatives3 rt_offsets(RtHit hit, RfNeighbourDirections next) {
    RtTriangle tri = hit.tri;
    return rf_barycentric_offsets(hit.world_to_object, hit.origin, tri.p[0], tri.p[1], tri.p[2], next.right,
        next.below, hit.weights);
}

// The UV gradients of the re-intersection offsets.
RfDerivatives2 rt_offset_uv(RtHit hit, RfDerivatives3 offsets) {
    return rf_uv_gradients_from_offsets(offsets, hit.tri.uv[0], hit.tri.uv[1], hit.tri.uv[2]);
}

// The per-pixel barycentric deltas of the neighbour pixels' rays (`next`) re-intersected.
vec3 rt_deltas(RtHit hit, RfNeighbourDirections next) {
    RtTriangle tri = hit.tri;
    return rf_barycentric_deltas(hit.world_to_object, hit.origin, tri.p[0], tri.p[1], tri.p[2], next.right,
        next.below, hit.weights);
}

// The closed-form barycentric deltas of the footprint of `cone` at the hit.
vec3 rt_cone_deltas(RtHit hit, RfRayCone cone) {
    return rf_cone_barycentric_deltas(rt_footprint(hit, cone), hit.tri.p[0], hit.tri.p[1], hit.tri.p[2]);
}

// The wireframe coverage of the frame's settings at barycentrics (w, u, v) with these deltas.
float rt_coverage(vec3 weights, vec3 deltas) {
    return rf_process_wireframe(rf_unpack_wireframe_settings(rt_frame.wireframe.settings), weights, deltas);
}

// The wireframe coverage of the hit: by re-intersection on a primary hit, from the closed-form cone
// deltas on a secondary hit (seen in the mirror), which has no pixel neighbours to re-intersect.
float rt_wireframe_coverage(RtHit hit, RfRayCone cone) {
    vec3 deltas = hit.depth == 0u ? rt_deltas(hit, rt_neighbours(hit.pixel)) : rt_cone_deltas(hit, cone);
    return rt_coverage(hit.weights, deltas);
}

// Whether the render mode carries ray differentials through mirrors and glass.
bool rt_carries_diff(uint mode) {
    return mode == RT_MODE_RAY_DIFF || mode == RT_MODE_RAY_DIFF_ISOTROPIC;
}

// The differential of the ray a mirror or glass passes on at the hit (Igehy): the incoming
// differential `diff` carried to the hit (origin derivatives from the barycentric derivatives, RTG
// Eq. 22), its direction derivatives reflected about the interpolated normal, or on glass refracted
// with the index ratio eta (reflected on total internal reflection); the normal's own derivatives
// come from the vertex normals.
RfRayDiff rt_bounced_diff(RtHit hit, RfRayDiff diff, float eta) {
    RtTriangle tri = hit.tri;
    RfDerivatives2 bary = rt_barycentric_derivatives(hit, diff);
    RfDerivatives3 position = rf_secondary_origin_derivatives(bary, tri.p[0], tri.p[1], tri.p[2]);
    RfDerivatives3 normal = rf_normal_derivatives(tri.n[0], tri.n[1], tri.n[2], hit.barycentrics, bary);
    RfRayDiff at_hit = RfRayDiff(position.dx, 0.0, position.dy, 0.0, diff.d_direction_dx, 0.0, diff.d_direction_dy,
        0.0);
    if (hit.material.kind == RT_MATERIAL_GLASS) {
        return rf_refract_ray_diff(at_hit, hit.direction, hit.normal, normal, eta).diff;
    }
    return rf_reflect_ray_diff(at_hit, hit.direction, hit.normal, normal);
}

// textureGrad with UV gradients scaled by tex_grad_scale.
vec3 rt_sample_grad(vec2 uv, RfDerivatives2 uv_gradients) {
    RfDerivatives2 grad = rf_sample_grad_gradients(uv_gradients, pc.cone.tex_grad_scale);
    return textureGrad(rt_textures[0], uv, grad.dx, grad.dy).rgb;
}

// The texture colour of the hit as `mode` samples it, reached by a ray carrying `cone` and `diff`
// (each read only by the modes that use it). The ray-differential modes sample with the UV
// derivatives of the carried differential, on primary and secondary hits alike; the
// re-intersection needs a primary hit: on secondary hits it samples, like the cone modes and the
// wireframe's base, at the ray-cone LOD. RT_MODE_PATH_BIAS adds pc.lod_bias to that LOD past the
// first hit.
vec3 rt_texture_colour(uint mode, RtHit hit, RfRayCone cone, RfRayDiff diff) {
    vec2 uv = rt_uv(hit);
    bool reintersection = mode == RT_MODE_BARY_GRADIENTS;
    switch (reintersection && hit.depth != 0u ? RT_MODE_CONE : mode) {
    case RT_MODE_MIP0:
    case RT_MODE_PATH_MIP0:
        return textureLod(rt_textures[0], uv, 0.0).rgb;
    case RT_MODE_TEX_GRAD_SCALE: {
        float gradient = rt_cone_gradient(hit, cone);
        return textureGrad(rt_textures[0], uv, vec2(gradient, 0.0), vec2(0.0, gradient)).rgb;
    }
    case RT_MODE_MIP_LEVELS:
        return textureLod(rt_textures[1], uv, rt_cone_lod(hit, cone)).rgb;
    case RT_MODE_RAY_DIFF:
        return rt_sample_grad(uv, rt_uv_derivatives(hit, rt_barycentric_derivatives(hit, diff)));
    case RT_MODE_RAY_DIFF_ISOTROPIC:
        return textureLod(rt_textures[0], uv, rt_texel_lod(rt_uv_derivatives(hit, rt_barycentric_derivatives(hit,
            diff)))).rgb;
    case RT_MODE_BARY_GRADIENTS:
        return rt_sample_grad(uv, rt_offset_uv(hit, rt_offsets(hit, rt_neighbours(hit.pixel))));
    case RT_MODE_CONE_ANISOTROPIC:
        return rt_sample_grad(uv, rt_cone_uv_gradients(hit, cone));
    case RT_MODE_PATH_BIAS:
        return textureLod(rt_textures[0], uv, rt_cone_lod(hit, cone) + (hit.depth != 0u ? pc.lod_bias : 0.0)).rgb;
    default: // RT_MODE_CONE, RT_MODE_CONE_CURVATURE, RT_MODE_WIREFRAME, RT_MODE_CONE_REFRACTION,
             // RT_MODE_CONE_ROUGHNESS, RT_MODE_CONE_SECTIONS (at rt_arriving_cone's cone), and the
             // path modes but RT_MODE_PATH_MIP0 and RT_MODE_PATH_BIAS
        return textureLod(rt_textures[0], uv, rt_cone_lod(hit, cone)).rgb;
    }
}

// The colour of a surface the ray ends on, lit, under the wireframe in RT_MODE_WIREFRAME; black on
// glass, which a ray reaches here only past the bounce limit (its light is lost).
vec3 rt_surface_colour(uint mode, RtHit hit, RfRayCone cone, RfRayDiff diff) {
    if (hit.material.kind == RT_MATERIAL_GLASS) {
        return vec3(0.0);
    }
    vec3 colour = rt_light(hit.normal) * rt_texture_colour(mode, hit, cone, diff);
    if (mode == RT_MODE_WIREFRAME) {
        colour = mix(colour, rt_frame.wireframe.colour.rgb, rt_wireframe_coverage(hit, cone));
    }
    return colour;
}

// The hit's shading normal turned against its ray.
vec3 rt_facing_normal(RtHit hit) {
    return dot(hit.normal, hit.direction) < 0.0 ? hit.normal : -hit.normal;
}

// Whether `mode` traces paths: every surface scatters the ray on (rt_path_bounce).
bool rt_traces_paths(uint mode) {
    return mode == RT_MODE_PATH_MIP0 || mode == RT_MODE_PATH_CONE || mode == RT_MODE_PATH_CURVATURE
        || mode == RT_MODE_PATH_ROUGHNESS || mode == RT_MODE_PATH_RTXPT || mode == RT_MODE_PATH_OPTIX
        || mode == RT_MODE_PATH_BIAS;
}

// Whether the ray goes on from the hit in `mode`: a mirror reflects primary rays (what it reflects is
// shaded as a textured surface), glass refracts every ray up to RT_MAX_DEPTH bounces; in the path
// modes every surface passes rays on up to RT_MAX_DEPTH bounces.
bool rt_passes_on(uint mode, RtHit hit) {
    if (hit.material.kind == RT_MATERIAL_GLASS || rt_traces_paths(mode)) {
        return hit.depth < RT_MAX_DEPTH;
    }
    return hit.material.kind == RT_MATERIAL_MIRROR && hit.depth == 0u;
}

// The ray a hit passes on: where it starts and where it goes, the share of the light it brings
// back, its cone, its differential and its sagittal section, and the colour the hit multiplies
// onto that light (a path mode's textured surface: its texture, at the arriving cone's level;
// white elsewhere).
struct RtBounce {
    vec3 origin;
    vec3 direction;
    float weight;
    RfRayCone cone;
    RfRayDiff diff;
    RtSagittal sagittal;
    vec3 tint;
};

// Two numbers in [0, 1) for the ray of `pixel` leaving bounce `depth` at the frame's pixel offset:
// different for every pixel, sub-pixel sample and bounce, the same on every run (a path draws new
// ones at every bounce; the glossy lobe of the other modes takes bounce 0's).
vec2 rt_random(uvec2 pixel, uint depth) {
    uvec4 words = rt_hash(uvec4(pixel, floatBitsToUint(pc.pixel_offset.x) ^ (depth * 0x9e3779b9u),
        floatBitsToUint(pc.pixel_offset.y)));
    return vec2(words.xy >> 8u) * (1.0 / 16777216.0);
}

// A direction drawn from the cosine lobe around the unit `normal` (Malley's method: a point
// uniform on the unit disc, lifted to the hemisphere; pdf cos(theta) / pi), in the tangent frame of
// rf_orthonormal_tangent.
vec3 rt_cosine_direction(vec3 normal, vec2 random) {
    float radius = sqrt(random.x);
    float phi = 6.28318530718 * random.y;
    vec3 tangent = rf_orthonormal_tangent(normal);
    vec3 bitangent = cross(normal, tangent);
    vec3 lifted = radius * (cos(phi) * tangent + sin(phi) * bitangent) + sqrt(max(1.0 - random.x, 0.0)) * normal;
    return normalize(lifted);
}

// A microfacet normal around the unit `normal` drawn from the GGX distribution of width `alpha`
// (Walter, Marschner, Li, Torrance 2007, Eq. 35-36: tan(theta) = alpha sqrt(u / (1 - u)),
// phi = 2 pi v), in the tangent frame of rf_orthonormal_tangent.
vec3 rt_ggx_normal(vec3 normal, float alpha, vec2 random) {
    float tan_theta = alpha * sqrt(random.x / (1.0 - random.x));
    float cos_theta = 1.0 / sqrt(1.0 + tan_theta * tan_theta);
    float sin_theta = tan_theta * cos_theta;
    float phi = 6.28318530718 * random.y;
    vec3 tangent = rf_orthonormal_tangent(normal);
    vec3 bitangent = cross(normal, tangent);
    return normalize(sin_theta * (cos(phi) * tangent + sin(phi) * bitangent) + cos_theta * normal);
}

// The direction a mirror reflects the hit's ray in `mode`: about the shading normal; under
// RT_FLAG_GLOSSY_LOBE, and in the path modes, about a normal drawn from the GGX distribution of the
// mirror's roughness (alpha = roughness^2; in the path modes with numbers new at every bounce),
// falling back to the shading normal where that reflection would leave below the surface.
vec3 rt_mirror_direction(uint mode, RtHit hit) {
    vec3 mirrored = reflect(hit.direction, hit.normal);
    bool paths = rt_traces_paths(mode);
    if ((pc.flags & RT_FLAG_GLOSSY_LOBE) == 0u && !paths) {
        return mirrored;
    }
    vec3 facing = rt_facing_normal(hit);
    float roughness = hit.material.parameter;
    vec2 random = rt_random(hit.pixel, paths ? hit.depth : 0u);
    vec3 glossy = reflect(hit.direction, rt_ggx_normal(facing, roughness * roughness, random));
    return dot(glossy, facing) > 0.0 ? glossy : mirrored;
}

// The direction of the ray leaving a glass hit with index ratio eta: refracted by Snell's law
// (GLSL refract, with the normal turned against the ray), reflected on total internal reflection.
vec3 rt_glass_direction(RtHit hit, float eta) {
    vec3 facing = rt_facing_normal(hit);
    vec3 refracted = refract(hit.direction, facing, eta);
    return all(equal(refracted, vec3(0.0))) ? reflect(hit.direction, facing) : refracted;
}

// Where a ray leaving the hit along `direction` starts: the hit point, lifted off the surface to the
// side the ray leaves to.
vec3 rt_leaving_origin(RtHit hit, vec3 direction) {
    float side = dot(direction, hit.normal) >= 0.0 ? RT_SURFACE_OFFSET : -RT_SURFACE_OFFSET;
    return hit.origin + hit.t * hit.direction + side * hit.normal;
}

// The hit triangle's curvature as the ray sees it, as the OptiX Toolkit reads it: rt_curvature,
// positive for a surface convex towards the ray (the stored curvature times the sign of
// -dot(normal, direction)).
float rt_seen_curvature(RtHit hit) {
    return dot(hit.normal, hit.direction) < 0.0 ? rt_curvature(hit) : -rt_curvature(hit);
}

// The cone leaving a path vertex in `mode` from the arriving `cone`, for the ray scattered to
// `direction` with the BSDF value `bsdf` and density `pdf` (`mirror`: off a mirror's GGX lobe,
// else a Lambertian one): rf_scatter_ray_cone's for the lobe drawn in RT_MODE_PATH_CONE; the
// curvature's spread (JCGT 2021) in RT_MODE_PATH_CURVATURE, plus twice rf_roughness_spread_angle of
// the lobe's roughness (1 for Lambert) in RT_MODE_PATH_ROUGHNESS; the curvature's spread in
// RT_MODE_PATH_BIAS too, whose bias is in the texture's level; RTXPT's and the OptiX Toolkit's
// rules in theirs; at level 0 (RT_MODE_PATH_MIP0) the arriving cone, which nothing reads.
RfRayCone rt_path_cone(uint mode, RtHit hit, RfRayCone cone, vec3 direction, bool mirror, float bsdf, float pdf) {
    float roughness = mirror ? hit.material.parameter : 1.0;
    switch (mode) {
    case RT_MODE_PATH_CONE:
        return rf_scatter_ray_cone(cone, hit.t, rt_curvature(hit), hit.normal, hit.direction, direction,
            mirror ? RF_LOBE_REFLECTION : RF_LOBE_DIFFUSE);
    case RT_MODE_PATH_CURVATURE:
    case RT_MODE_PATH_BIAS:
        return rf_propagate(cone, hit.t, rt_curvature_spread(hit, cone, rt_curvature(hit)));
    case RT_MODE_PATH_ROUGHNESS:
        return rf_propagate(cone, hit.t, rt_curvature_spread(hit, cone, rt_curvature(hit))
            + 2.0 * rf_roughness_spread_angle(roughness));
    case RT_MODE_PATH_RTXPT: {
        RfRayCone carried = rf_propagate(cone, hit.t, 0.0);
        bool delta = mirror && roughness * roughness < 0.0064;
        float spread = delta ? carried.spread_angle : min(carried.spread_angle + rt_rtxpt_expansion(pdf), 6.28318530718);
        return RfRayCone(carried.width, spread);
    }
    case RT_MODE_PATH_OPTIX:
        return rt_optix_toolkit_cone(cone, hit.t, rt_seen_curvature(hit), bsdf);
    default: // RT_MODE_PATH_MIP0
        return cone;
    }
}

// The ray a path mode scatters from a textured surface or a mirror reached by the ray carrying
// `cone`: a textured surface is Lambertian, a direction drawn from its cosine lobe (pdf cos / pi)
// bringing back its texture colour (f cos / pdf = albedo, f = albedo / pi), sampled at the
// arriving cone's level (at level 0 in RT_MODE_PATH_MIP0); a mirror reflects about a GGX normal of
// its roughness (rt_mirror_direction, pdf rt_ggx_pdf) and RT_MIRROR_REFLECTANCE of the light (f =
// RT_MIRROR_REFLECTANCE pdf / cos). The leaving cone is rt_path_cone's.
RtBounce rt_path_bounce(uint mode, RtHit hit, RfRayCone cone, RtSagittal sagittal) {
    bool mirror = hit.material.kind == RT_MATERIAL_MIRROR;
    vec3 facing = rt_facing_normal(hit);
    vec3 direction = mirror ? rt_mirror_direction(mode, hit)
                            : rt_cosine_direction(facing, rt_random(hit.pixel, hit.depth));
    vec3 tint = mirror ? vec3(1.0) : rt_texture_colour(mode, hit, cone, rt_no_diff());
    float cos_out = max(dot(direction, facing), 1e-6);
    float roughness = hit.material.parameter;
    float pdf = mirror ? rt_ggx_pdf(hit.direction, facing, direction, roughness * roughness) : cos_out * 0.318309886;
    float bsdf = mirror ? RT_MIRROR_REFLECTANCE * pdf / cos_out : (tint.r + tint.g + tint.b) * (0.318309886 / 3.0);
    RfRayCone leaving = rt_path_cone(mode, hit, cone, direction, mirror, bsdf, pdf);
    return RtBounce(rt_leaving_origin(hit, direction), direction, mirror ? RT_MIRROR_REFLECTANCE : 1.0, leaving,
        rt_no_diff(), sagittal, tint);
}

// The ray a mirror or glass passes on from the ray carrying `cone`, `diff` and `sagittal` in `mode`.
// A mirror reflects it (rt_mirror_direction) and 90% of the light; its sections leave by RTG Eq. 35,
// widened by rt_reflection_spread (rt_mirror_sections). Glass refracts it (rt_glass_direction) and
// passes all of the light on; its sections are rt_glass_sections. In the ray-differential modes it
// carries the reflected or refracted differential (Igehy).
RtBounce rt_bounce(uint mode, RtHit hit, RfRayCone cone, RfRayDiff diff, RtSagittal sagittal) {
    if (rt_traces_paths(mode) && hit.material.kind != RT_MATERIAL_GLASS) {
        return rt_path_bounce(mode, hit, cone, sagittal);
    }
    bool glass = hit.material.kind == RT_MATERIAL_GLASS;
    float eta = glass ? rt_relative_index(hit) : 0.0;
    vec3 direction = glass ? rt_glass_direction(hit, eta) : rt_mirror_direction(mode, hit);
    RtSections leaving = glass ? rt_glass_sections(mode, hit, cone, sagittal, eta)
                               : rt_mirror_sections(mode, hit, cone, sagittal);
    return RtBounce(rt_leaving_origin(hit, direction), direction, glass ? 1.0 : RT_MIRROR_REFLECTANCE, leaving.cone,
        rt_carries_diff(mode) ? rt_bounced_diff(hit, diff, eta) : diff, leaving.sagittal, vec3(1.0));
}

// The ray-differential, re-intersection and wireframe values of a primary hit reached by the eye
// ray carrying `eye` (rt_eye_diff), whose ray-cone footprint is `footprint`: the eye-ray differential
// transferred to the hit as barycentric and UV derivatives (RTG Eq. 12-21) and their LOD; the
// neighbour pixels' rays re-intersected with the triangle's plane (signed barycentric offsets, their
// UV gradients and LOD, and deltas); the wireframe coverage from the re-intersection deltas; and the
// closed-form cone deltas.
RtDiffRecord rt_measure_diff(RtHit hit, RfRayDiff eye, float footprint) {
    RfDerivatives2 bary = rt_barycentric_derivatives(hit, eye);
    RfDerivatives2 uv = rt_uv_derivatives(hit, bary);
    RfNeighbourDirections next = rt_neighbours(hit.pixel);
    RfDerivatives3 offsets = rt_offsets(hit, next);
    RfDerivatives2 offset_uv = rt_offset_uv(hit, offsets);
    vec3 deltas = rt_deltas(hit, next);
    vec3 cone_deltas = rf_cone_barycentric_deltas(footprint, hit.tri.p[0], hit.tri.p[1], hit.tri.p[2]);
    return RtDiffRecord(eye.d_direction_dx, rt_texel_lod(uv), eye.d_direction_dy, rt_texel_lod(offset_uv),
        bary.dx, bary.dy, uv.dx, uv.dy, next.right, rt_coverage(hit.weights, deltas), next.below, 0u, offsets.dx, 0u,
        offsets.dy, 0u, offset_uv.dx, offset_uv.dy, deltas, 0u, cone_deltas, 0u);
}

// What a primary hit reached by the eye ray carrying `cone` and `eye` measured: every ray-cone value
// (footprint and texel density, base LOD and LOD, RTG Eq. 34; the textureGrad gradient; the
// triangle's curvature and the spread it gives a reflection, JCGT 2021; the reflected cone with the
// roughness spread, RTG Eq. 35), the ray-differential, re-intersection and wireframe values
// (rt_measure_diff), the refraction of the cone on glass (RTG II ch. 10) and of its sagittal
// section (rt_refract_sagittal), and the anisotropic cone gradients (JCGT 2021).
RtPixelRecord rt_measure(RtHit hit, RfRayCone cone, RfRayDiff eye) {
    RtTriangle tri = hit.tri;
    float width = rf_width_at(cone, hit.t);
    float footprint = rt_footprint(hit, cone);
    float density = rf_texel_density(tri.p[0], tri.p[1], tri.p[2], tri.uv[0], tri.uv[1], tri.uv[2]);
    float base_lod = rf_triangle_base_lod(tri.p[0], tri.p[1], tri.p[2], tri.uv[0], tri.uv[1], tri.uv[2]);
    float spread = rt_curvature_spread(hit, cone, rt_curvature(hit));
    float roughness_spread = rt_roughness_spread(hit);
    bool glass = hit.material.kind == RT_MATERIAL_GLASS;
    float eta = glass ? rt_relative_index(hit) : 0.0;
    RfRefractedRayCone refracted = glass ? rt_refract_cone(hit, cone, eta) : RfRefractedRayCone(RfRayCone(0.0, 0.0),
        false);
    RfRayCone sagittal = glass ? rt_refract_sagittal(hit, cone, eta) : RfRayCone(0.0, 0.0);
    RfDerivatives2 cone_uv = rt_cone_uv_gradients(hit, cone);
    return RtPixelRecord(hit.normal, hit.t, hit.direction, hit.mesh, hit.barycentrics, hit.primitive, 1u, cone,
        width, footprint, density, base_lod, rt_cone_lod(hit, cone), rt_cone_gradient(hit, cone), rt_curvature(hit),
        spread, rf_propagate(cone, hit.t, spread + 2.0 * roughness_spread), rt_measure_diff(hit, eye, footprint),
        roughness_spread, eta, glass ? rt_normal_spread(hit, cone) : 0.0, refracted.total_internal_reflection ? 1u : 0u,
        refracted.cone, cone_uv.dx, cone_uv.dy, sagittal);
}

// The record of a ray that hit nothing.
RtPixelRecord rt_miss_record(vec3 direction, RfRayCone cone) {
    RtDiffRecord none = RtDiffRecord(vec3(0.0), 0.0, vec3(0.0), 0.0, vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0),
        vec3(0.0), 0.0, vec3(0.0), 0u, vec3(0.0), 0u, vec3(0.0), 0u, vec2(0.0), vec2(0.0), vec3(0.0), 0u, vec3(0.0), 0u);
    return RtPixelRecord(vec3(0.0), 0.0, direction, 0u, vec2(0.0), 0u, 0u, cone, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
        0.0, RfRayCone(0.0, 0.0), none, 0.0, 0.0, 0.0, 0u, RfRayCone(0.0, 0.0), vec2(0.0), vec2(0.0),
        RfRayCone(0.0, 0.0));
}

// Sky colour for a ray leaving the scene in `direction`.
vec3 rt_sky(vec3 direction) {
    return mix(vec3(0.75, 0.82, 0.9), vec3(0.35, 0.5, 0.8), clamp(direction.y, 0.0, 1.0));
}

#endif // RT_SHADING_GLSL
