// ray-footprint: ray cones, an isotropic pixel footprint carried along a ray.
//
// Library module for GLSL 460 (no main): #include "ray_cone.glsl". Twin of
// shaders/wgsl/ray_cone.wgsl and the Rust mirror src/ray_cone.rs: same functions, same order, same
// order of operations. Formulas and sources are documented in src/ray_cone.rs; "RTG Eq. N" is
// Ray Tracing Gems ch. 20 (Akenine-Moller et al. 2019), "JCGT 2021" is "Improved Shader and Texture
// Level of Detail Using Ray Cones".
//
// width is the full footprint diameter, spread_angle the full cone angle, both signed; normals and
// directions are unit length, normals as the mesh stores them (either orientation). Divergent cases
// are clamped with the RF_ constants: finite inputs give finite outputs.

#ifndef RAY_FOOTPRINT_RAY_CONE_GLSL
#define RAY_FOOTPRINT_RAY_CONE_GLSL

// Smallest |cos| between a normal and a direction used as a divisor (grazing-angle clamp).
const float RF_MIN_COS = 1.0e-4;
// Smallest magnitude passed to log2 or used as a divisor.
const float RF_MIN_MAGNITUDE = 1.0e-20;
// Largest vertical field of view in radians.
const float RF_MAX_FOV_Y = 3.1;
// Largest finite f16; packed cone values are clamped to [-RF_F16_MAX, RF_F16_MAX].
const float RF_F16_MAX = 65504.0;

// A ray cone (8 bytes): footprint width at the ray origin and full spread angle (RTG Sec. 20.3.4).
struct RfRayCone {
    float width;
    float spread_angle;
};

// A ray payload carrying a cone (32 bytes, 16-byte aligned; the same layout in WGSL, std430 and
// scalar): accumulated colour, path weight, the cone, and the bounce depth. pad is always 0.
struct RfHitPayload {
    vec3 colour;
    float weight;
    RfRayCone cone;
    uint depth;
    uint pad;
};

// Push constants of a ray-cone renderer (8 bytes): textureGrad scale (0 = mip 0, 1 = matching,
// > 1 blurred) and the pixel spread angle of the camera.
struct RfRayConePushConstants {
    float tex_grad_scale;
    float pixel_spread_angle;
};

// Packs a cone as two f16 (width low, spread high), clamped to the f16 range.
uint rf_pack_ray_cone(RfRayCone cone) {
    vec2 values = vec2(cone.width, cone.spread_angle);
    return packHalf2x16(clamp(values, vec2(-RF_F16_MAX), vec2(RF_F16_MAX)));
}

// Unpacks a cone packed by rf_pack_ray_cone.
RfRayCone rf_unpack_ray_cone(uint packed) {
    vec2 values = unpackHalf2x16(packed);
    return RfRayCone(values.x, values.y);
}

// 2 tan(fov_y / 2) / H with fov_y clamped to [0, RF_MAX_FOV_Y] and H to >= 1.
float rf_pixel_tan_ratio(float fov_y, float image_height) {
    return 2.0 * tan(0.5 * clamp(fov_y, 0.0, RF_MAX_FOV_Y)) / max(image_height, 1.0);
}

// Exact pixel spread angle of a pinhole camera (RTG Eq. 30): atan(2 tan(fov_y / 2) / H).
float rf_pixel_spread_angle(float fov_y, float image_height) {
    return atan(rf_pixel_tan_ratio(fov_y, image_height));
}

// Small-angle pixel spread angle: 2 tan(fov_y / 2) / H.
float rf_pixel_spread_angle_small(float fov_y, float image_height) {
    return rf_pixel_tan_ratio(fov_y, image_height);
}

// Exact pixel spread angle from an inverse projection matrix: tan(fov_y / 2) = |proj_inv[1][1]|.
float rf_pixel_spread_angle_from_proj_inv(mat4 proj_inv, float image_height) {
    return atan(2.0 * abs(proj_inv[1][1]) / max(image_height, 1.0));
}

// Primary cone of a pinhole camera: width 0, spread = pixel spread angle.
RfRayCone rf_pinhole_ray_cone(float pixel_spread_angle) {
    return RfRayCone(0.0, pixel_spread_angle);
}

// Primary cone of a pinhole camera for one ray (unit direction and view axis): width 0, spread =
// pixel spread angle * clamp(dot(direction, view_axis), 0, 1); off-axis pixels subtend less.
RfRayCone rf_pinhole_ray_cone_for_ray(float pixel_spread_angle, vec3 direction, vec3 view_axis) {
    return RfRayCone(0.0, pixel_spread_angle * clamp(dot(direction, view_axis), 0.0, 1.0));
}

// Primary cone of an orthographic camera view_height world units tall: width = one pixel, spread 0.
RfRayCone rf_orthographic_ray_cone(float view_height, float image_height) {
    return RfRayCone(view_height / max(image_height, 1.0), 0.0);
}

// Primary cone of a thin lens: width = aperture, spread = alpha - aperture / focus_distance.
RfRayCone rf_thin_lens_ray_cone(float pixel_spread_angle, float aperture, float focus_distance) {
    return RfRayCone(aperture, pixel_spread_angle - aperture / max(focus_distance, RF_MIN_MAGNITUDE));
}

// Cone width after travelling t: width + spread_angle * t (RTG Eq. 35).
float rf_width_at(RfRayCone cone, float t) {
    return cone.width + cone.spread_angle * t;
}

// The cone leaving a hit at distance t with surface spread angle beta (RTG Eq. 35); also the
// reflected cone (unslanted width, so a planar mirror acts as a mirror-image camera).
RfRayCone rf_propagate(RfRayCone cone, float t, float surface_spread_angle) {
    return RfRayCone(rf_width_at(cone, t), cone.spread_angle + surface_spread_angle);
}

// sqrt(dn_dx.dn_dx + dn_dy.dn_dy).
float rf_normal_derivative_length(vec3 dn_dx, vec3 dn_dy) {
    return sqrt(dot(dn_dx, dn_dx) + dot(dn_dy, dn_dy));
}

// Normal spread across a pixel (RTG Eq. 31-32): 2 atan(0.5 sqrt(dn_dx.dn_dx + dn_dy.dn_dy)).
float rf_normal_spread_angle(vec3 dn_dx, vec3 dn_dy) {
    return 2.0 * atan(0.5 * rf_normal_derivative_length(dn_dx, dn_dy));
}

// Small-angle normal spread: sqrt(dn_dx.dn_dx + dn_dy.dn_dy).
float rf_normal_spread_angle_small(vec3 dn_dx, vec3 dn_dy) {
    return rf_normal_derivative_length(dn_dx, dn_dy);
}

// Convex (1) or concave (-1) (RTG Eq. 33): sign(dp_dx.dn_dx + dp_dy.dn_dy), sign(0) = -1.
float rf_curvature_sign(vec3 dp_dx, vec3 dp_dy, vec3 dn_dx, vec3 dn_dy) {
    return dot(dp_dx, dn_dx) + dot(dp_dy, dn_dy) > 0.0 ? 1.0 : -1.0;
}

// Surface spread angle (RTG Eq. 32): 2 k1 s phi + k2.
float rf_surface_spread_angle(float normal_spread_angle, float curvature_sign, float k1, float k2) {
    return 2.0 * k1 * curvature_sign * normal_spread_angle + k2;
}

// Edge curvature from vertex normals (JCGT 2021): (n_j - n_i).(p_j - p_i) / max(|p_j - p_i|^2, min).
float rf_edge_curvature(vec3 p_i, vec3 p_j, vec3 n_i, vec3 n_j) {
    vec3 edge = p_j - p_i;
    return dot(n_j - n_i, edge) / max(dot(edge, edge), RF_MIN_MAGNITUDE);
}

// Triangle curvature: mean of the three edge curvatures (JCGT 2021).
float rf_triangle_curvature(vec3 p0, vec3 p1, vec3 p2, vec3 n0, vec3 n1, vec3 n2) {
    return (rf_edge_curvature(p0, p1, n0, n1) + rf_edge_curvature(p1, p2, n1, n2)
        + rf_edge_curvature(p2, p0, n2, n0)) / 3.0;
}

// -dot(normal, direction), kept at least RF_MIN_COS away from 0 with its sign; +0 and -0 give
// +RF_MIN_COS. mix with a bool selector is OpSelect: no branch.
float rf_facing_cos(vec3 normal, vec3 direction) {
    float facing = -dot(normal, direction);
    float signed_minimum = mix(-RF_MIN_COS, RF_MIN_COS, facing >= 0.0);
    return mix(facing, signed_minimum, abs(facing) < RF_MIN_COS);
}

// Reflection spread from curvature (JCGT 2021, Falcor's form): 2 k width / dn with the signed
// width and dn = -n.d kept away from 0 with its sign. k from the stored normals and n interpolated
// from the same normals (not turned towards the ray): independent of their orientation.
float rf_curvature_spread_angle(float curvature, float width, vec3 normal, vec3 direction) {
    return 2.0 * curvature * width / rf_facing_cos(normal, direction);
}

// Slant-corrected world footprint: |width + spread t| / max(|n.d|, RF_MIN_COS).
float rf_world_footprint(RfRayCone cone, float t, vec3 normal, vec3 direction) {
    return abs(rf_width_at(cone, t)) / max(abs(dot(normal, direction)), RF_MIN_COS);
}

// Twice the world-space triangle area: |cross(p1 - p0, p2 - p0)| (RTG Eq. 4), measured as
// m * |c / m| with m the largest component (>= RF_MIN_MAGNITUDE) so squaring cannot overflow.
float rf_triangle_world_area2(vec3 p0, vec3 p1, vec3 p2) {
    vec3 c = cross(p1 - p0, p2 - p0);
    float scale = max(max(abs(c.x), abs(c.y)), max(abs(c.z), RF_MIN_MAGNITUDE));
    return scale * length(c / scale);
}

// Twice the UV-space triangle area: |cross(uv1 - uv0, uv2 - uv0)| (RTG Eq. 4).
float rf_triangle_uv_area2(vec2 uv0, vec2 uv1, vec2 uv2) {
    vec2 e1 = uv1 - uv0;
    vec2 e2 = uv2 - uv0;
    return abs(e1.x * e2.y - e1.y * e2.x);
}

// Texel density, UV units per world unit: sqrt(uv_area2) / sqrt(max(world_area2, min)).
float rf_texel_density(vec3 p0, vec3 p1, vec3 p2, vec2 uv0, vec2 uv1, vec2 uv2) {
    return sqrt(rf_triangle_uv_area2(uv0, uv1, uv2))
        / sqrt(max(rf_triangle_world_area2(p0, p1, p2), RF_MIN_MAGNITUDE));
}

// Base LOD in UV units (RTG Eq. 4): 0.5 (log2(uv_area2) - log2(world_area2)), areas clamped.
float rf_triangle_base_lod(vec3 p0, vec3 p1, vec3 p2, vec2 uv0, vec2 uv1, vec2 uv2) {
    float uv_area2 = max(rf_triangle_uv_area2(uv0, uv1, uv2), RF_MIN_MAGNITUDE);
    float world_area2 = max(rf_triangle_world_area2(p0, p1, p2), RF_MIN_MAGNITUDE);
    return 0.5 * (log2(uv_area2) - log2(world_area2));
}

// Texture LOD (RTG Eq. 34): base_lod + log2|width| + 0.5 (log2 W + log2 H) - log2|n.d|, clamped.
float rf_texture_lod(float base_lod, float width, vec2 texture_size, vec3 normal, vec3 direction) {
    vec2 size = max(texture_size, vec2(1.0));
    return base_lod + log2(max(abs(width), RF_MIN_MAGNITUDE)) + 0.5 * (log2(size.x) + log2(size.y))
        - log2(max(abs(dot(normal, direction)), RF_MIN_COS));
}

// Isotropic textureGrad gradient: |uv_footprint| * max(tex_grad_scale, 0);
// use dPdx = vec2(g, 0), dPdy = vec2(0, g).
float rf_texture_gradient(float uv_footprint, float tex_grad_scale) {
    return abs(uv_footprint) * max(tex_grad_scale, 0.0);
}

// Lat-long environment map LOD (RTG ch. 21): log2(max(|spread| H / pi, RF_MIN_MAGNITUDE)).
float rf_environment_lod(float spread_angle, float map_height) {
    return log2(max(abs(spread_angle) * max(map_height, 1.0) / 3.14159265358979, RF_MIN_MAGNITUDE));
}

// Largest angle between a boundary ray of a refracted cone and the normal: pi / 2 - 1e-4, so that
// every boundary ray meets the surface with |cos| >= RF_MIN_COS.
const float RF_MAX_INCIDENCE_ANGLE = 1.5706963;
// Largest |normal_spread_angle| that rf_refract_ray_cone applies.
const float RF_MAX_NORMAL_SPREAD = 3.1;
// Smallest 1 - alpha^2 in rf_roughness_spread_angle (roughness 1 gives about 141 radians).
const float RF_MIN_ROUGHNESS_DENOMINATOR = 1.0e-4;

// A refracted cone; on total internal reflection, the reflected cone and the flag set.
struct RfRefractedRayCone {
    RfRayCone cone;
    bool total_internal_reflection;
};

// (sin i, cos i) from (|d - cosine n|, |cosine|) scaled to unit length; a zero direction gives (0, 1).
vec2 rf_incidence_sin_cos(vec3 normal, vec3 direction, float cosine) {
    vec2 sin_cos = vec2(length(direction - cosine * normal), abs(cosine));
    float sin_cos_length = length(sin_cos);
    return mix(sin_cos / sin_cos_length, vec2(0.0, 1.0), bvec2(sin_cos_length < RF_MIN_MAGNITUDE));
}

// (sin(angle), cos(angle)).
vec2 rf_angle_sin_cos(float angle) {
    return vec2(sin(angle), cos(angle));
}

// Half the cone angle, limited so both boundary rays meet the surface within RF_MAX_INCIDENCE_ANGLE.
float rf_refraction_half_spread(float spread_angle, vec2 incidence) {
    float limit = max(RF_MAX_INCIDENCE_ANGLE - atan(incidence.x, incidence.y), 0.0);
    return clamp(0.5 * spread_angle, -limit, limit);
}

// Half the normal turn across the footprint, signed for the upper boundary (negated for width < 0).
float rf_normal_tilt(float width, float facing_spread) {
    float signed_half = width < 0.0 ? -0.5 : 0.5;
    return signed_half * clamp(facing_spread, -RF_MAX_NORMAL_SPREAD, RF_MAX_NORMAL_SPREAD);
}

// (sin, cos) of the angle i + side q from those of i and q.
vec2 rf_boundary_incidence(vec2 incidence, vec2 local, float side) {
    return vec2(
        incidence.x * local.y + side * incidence.y * local.x,
        incidence.y * local.y - side * incidence.x * local.x
    );
}

// (sin, cos) refracted by Snell's law from (sin phi, cos phi): clamp(eta sin phi, -1, 1) and
// sqrt(max(cos^2 phi + ((1 - eta) sin phi) ((1 + eta) sin phi), 0)); (+-1, 0) past the critical angle.
vec2 rf_refracted_sin_cos(vec2 incidence, float eta) {
    float cos2 = incidence.y * incidence.y + ((1.0 - eta) * incidence.x) * ((1.0 + eta) * incidence.x);
    return vec2(clamp(eta * incidence.x, -1.0, 1.0), sqrt(max(cos2, 0.0)));
}

// Where the boundary ray on `side` lands: side (width / 2) cos(h) / max(cos(i + side h), RF_MIN_COS).
float rf_boundary_hit(float width, float side, vec2 incidence, vec2 half_spread) {
    float cos_boundary = incidence.y * half_spread.y - side * incidence.x * half_spread.x;
    return side * 0.5 * width * half_spread.y / max(cos_boundary, RF_MIN_COS);
}

// Offset of a refracted boundary across the refracted central ray: hit cos(rho) / max(cos(rho - t), min),
// rho = tau - side tilt.
float rf_boundary_offset(float hit, float side, vec2 refracted, vec2 tilt, vec2 transmitted) {
    float cos_rho = refracted.y * tilt.y + side * refracted.x * tilt.x;
    float sin_rho = refracted.x * tilt.y - side * refracted.y * tilt.x;
    return hit * cos_rho / max(cos_rho * transmitted.y + sin_rho * transmitted.x, RF_MIN_COS);
}

// s_u - s_l of the refracted boundaries from their incidences (sin, cos of i +- q): 2 eta cos i sin q
// (exact) while neither eta sin(i +- q) exceeds 1, else the difference of the clamped sines.
float rf_refracted_sine_gap(float eta, vec2 incidence, vec2 local, vec2 upper, vec2 lower) {
    float upper_sine = eta * upper.x;
    float lower_sine = eta * lower.x;
    float exact = 2.0 * eta * incidence.y * local.x;
    float clamped = clamp(upper_sine, -1.0, 1.0) - clamp(lower_sine, -1.0, 1.0);
    return mix(clamped, exact, all(lessThanEqual(abs(vec2(upper_sine, lower_sine)), vec2(1.0))));
}

// Angle from the lower to the upper refracted boundary: atan2(sin, cos), sin = sine_gap (1 + cos) /
// (c_u + c_l) without cancellation; the divisor kept >= sqrt(|sine_gap (s_u + s_l)|) (its lower bound)
// and >= RF_MIN_MAGNITUDE.
float rf_refracted_angle_between(float sine_gap, vec2 upper, vec2 lower) {
    float cos_between = upper.y * lower.y + upper.x * lower.x;
    float cos_sum = max(max(upper.y + lower.y, sqrt(abs(sine_gap * (upper.x + lower.x)))), RF_MIN_MAGNITUDE);
    float sin_between = sine_gap * (1.0 + cos_between) / cos_sum;
    return atan(sin_between, cos_between);
}

// Refraction of a cone at the hit (RTG II ch. 10, whole angles; Falcor computeRayConeForRefraction):
// boundary rays at i +- h land at +-(w/2) cos h / cos(i +- h), refract at normals tilted -+beta/2;
// new spread = angle between them, new width = their distance across the refracted central ray.
// eta sin i > 1: the reflected cone (width, spread + 2 beta) and the flag. Both cones are evaluated
// and one selected: no branch.
RfRefractedRayCone rf_refract_ray_cone(RfRayCone cone, vec3 normal, vec3 direction, float normal_spread_angle,
    float eta) {
    float cosine = dot(normal, direction);
    float facing_spread = mix(normal_spread_angle, -normal_spread_angle, cosine > 0.0);
    vec2 incidence = rf_incidence_sin_cos(normal, direction, cosine);
    float index = max(eta, 0.0);
    bool total_internal_reflection = index * incidence.x > 1.0;
    vec2 transmitted = rf_refracted_sin_cos(incidence, index);
    float half_spread = rf_refraction_half_spread(cone.spread_angle, incidence);
    float tilt = rf_normal_tilt(cone.width, facing_spread);
    vec2 local = rf_angle_sin_cos(half_spread + tilt);
    vec2 upper_incidence = rf_boundary_incidence(incidence, local, 1.0);
    vec2 lower_incidence = rf_boundary_incidence(incidence, local, -1.0);
    vec2 upper = rf_refracted_sin_cos(upper_incidence, index);
    vec2 lower = rf_refracted_sin_cos(lower_incidence, index);
    float sine_gap = rf_refracted_sine_gap(index, incidence, local, upper_incidence, lower_incidence);
    vec2 half_sin_cos = rf_angle_sin_cos(half_spread);
    vec2 tilt_sin_cos = rf_angle_sin_cos(tilt);
    float upper_hit = rf_boundary_hit(cone.width, 1.0, incidence, half_sin_cos);
    float lower_hit = rf_boundary_hit(cone.width, -1.0, incidence, half_sin_cos);
    float refracted_width = rf_boundary_offset(upper_hit, 1.0, upper, tilt_sin_cos, transmitted)
        - rf_boundary_offset(lower_hit, -1.0, lower, tilt_sin_cos, transmitted);
    float refracted_spread = rf_refracted_angle_between(sine_gap, upper, lower) - 2.0 * tilt;
    float reflected_spread = cone.spread_angle + 2.0 * facing_spread;
    return RfRefractedRayCone(
        RfRayCone(
            mix(refracted_width, cone.width, total_internal_reflection),
            mix(refracted_spread, reflected_spread, total_internal_reflection)
        ),
        total_internal_reflection
    );
}

// Spread added by roughness (JCGT 2021; Falcor roughnessToSpread): alpha = r^2 (r perceptual, clamped
// to [0, 1]), sigma^2 = 0.5 alpha^2 / max(1 - alpha^2, RF_MIN_ROUGHNESS_DENOMINATOR), spread 2 sigma.
float rf_roughness_spread_angle(float roughness) {
    float r = clamp(roughness, 0.0, 1.0);
    float alpha = r * r;
    float alpha2 = alpha * alpha;
    float variance = 0.5 * alpha2 / max(1.0 - alpha2, RF_MIN_ROUGHNESS_DENOMINATOR);
    return 2.0 * sqrt(variance);
}

#endif // RAY_FOOTPRINT_RAY_CONE_GLSL
