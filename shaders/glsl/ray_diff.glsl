// ray-footprint: Ray differentials (Igehy 1999; RTG ch. 20 Eq. 1-24): how a ray's origin and direction change from pixel to pixel, carried to hits, barycentrics and texture coordinates.
//
// Library module for GLSL 460 (no main): #include "ray_diff.glsl". Twin of shaders/wgsl/ray_diff.wgsl
// and the Rust mirror src/ray_diff.rs: same functions, same order, same order of operations. Formulas
// and sources are documented in src/ray_diff.rs; "RTG Eq. N" is Ray Tracing Gems ch. 20
// (Akenine-Moller et al. 2019), "Igehy" is "Tracing Ray Differentials" (1999), "Quilez" is "ray
// differentials and texturing" (2015), "wireframe tutorial" is nvpro's ray-tracing tutorial 20
// (computeDifferentials, computeDerivative).
//
// Pixel (0, 0) is the top-left pixel; dx is the change for one pixel step right, dy for one step down.
// Normals and directions are unit length unless stated. Divergent cases are clamped with the RF_DIFF_
// constants: finite inputs give finite outputs.

#ifndef RAY_FOOTPRINT_RAY_DIFF_GLSL
#define RAY_FOOTPRINT_RAY_DIFF_GLSL

// Largest vertical field of view in radians.
const float RF_DIFF_MAX_FOV_Y = 3.1;
// Smallest |cos| between two unit vectors used as a divisor (grazing-angle clamp), keeping its sign.
const float RF_DIFF_MIN_COS = 1.0e-4;
// Smallest magnitude used as a divisor (squared lengths, triangle determinants) or passed to log2.
const float RF_DIFF_MIN_MAGNITUDE = 1.0e-30;
// Largest magnitude of a barycentric coordinate, differential or delta (ray parallel to a plane): 2^40,
// so that such a value times any input of the domain (up to 1e12) stays finite.
const float RF_DIFF_MAX_VALUE = 1099511627776.0;
// Largest triplanar blend sharpness.
const float RF_DIFF_MAX_SHARPNESS = 64.0;

// A ray differential (Igehy; RTG Eq. 7), 64 bytes: origin and unit-direction changes per pixel step.
// Each vec3 is followed by an explicit float pad (always 0) so std430, scalar, WGSL and Rust agree.
struct RfRayDiff {
    vec3 d_origin_dx;
    float pad0;
    vec3 d_origin_dy;
    float pad1;
    vec3 d_direction_dx;
    float pad2;
    vec3 d_direction_dy;
    float pad3;
};

// Change of a 2-vector (barycentrics (u, v), UVs) per pixel step right (dx) and down (dy).
struct RfDerivatives2 {
    vec2 dx;
    vec2 dy;
};

// Change of a 3-vector (position, normal, barycentrics (w, u, v)) per pixel step right and down.
struct RfDerivatives3 {
    vec3 dx;
    vec3 dy;
};

// World directions of the rays through the right and the lower neighbour pixel centres.
struct RfNeighbourDirections {
    vec3 right;
    vec3 below;
};

// A refracted differential; on total internal reflection, the reflected one and the flag set.
struct RfRefractedRayDiff {
    RfRayDiff diff;
    bool total_internal_reflection;
};

// One G-buffer pixel: unit eye direction, distance to the first hit, unit normal there.
struct RfGBufferSample {
    vec3 eye_direction;
    float distance;
    vec3 normal;
};

// Gradients of the three triplanar projections (sampled with p.yz, p.zx, p.xy).
struct RfTriplanarGradients {
    RfDerivatives2 yz;
    RfDerivatives2 zx;
    RfDerivatives2 xy;
};

// Half extents of the image plane at distance 1 (RTG Eq. 9): (a f, f), f = tan(fov_y / 2), a = W / H.
vec2 rf_eye_ray_extent(vec2 image_size, float fov_y) {
    vec2 size = max(image_size, vec2(1.0));
    float f = tan(0.5 * clamp(fov_y, 0.0, RF_DIFF_MAX_FOV_Y));
    return vec2(size.x / size.y * f, f);
}

// Normalized device coordinates of a pixel centre: ((pixel + 0.5) / size) * 2 - 1.
vec2 rf_pixel_ndc(vec2 pixel, vec2 image_size) {
    return (pixel + 0.5) / max(image_size, vec2(1.0)) * 2.0 - 1.0;
}

// Non-normalized eye-ray direction (RTG Eq. 8-9): c.x a f right - c.y f up - view (view points to the eye).
vec3 rf_eye_ray_direction(vec2 pixel, vec2 image_size, float fov_y, vec3 right, vec3 up, vec3 view) {
    vec2 c = rf_pixel_ndc(pixel, image_size);
    vec2 extent = rf_eye_ray_extent(image_size, fov_y);
    return c.x * extent.x * right - c.y * extent.y * up - view;
}

// Derivative of v / |v| (Igehy; RTG Eq. 10): (dv - v (v.dv / v.v)) / sqrt(v.v), v.v >= RF_DIFF_MIN_MAGNITUDE.
vec3 rf_normalized_derivative(vec3 v, vec3 dv) {
    float length2 = max(dot(v, v), RF_DIFF_MIN_MAGNITUDE);
    return (dv - v * (dot(v, dv) / length2)) / sqrt(length2);
}

// Eye-ray differential of a pinhole (RTG Eq. 8-11): dO = 0, dD = normalized derivative of
// dd/dx = (2 a f / W) right and dd/dy = -(2 f / H) up.
RfRayDiff rf_eye_ray_diff(vec2 pixel, vec2 image_size, float fov_y, vec3 right, vec3 up, vec3 view) {
    vec3 d = rf_eye_ray_direction(pixel, image_size, fov_y, right, up, view);
    vec2 size = max(image_size, vec2(1.0));
    vec2 extent = rf_eye_ray_extent(image_size, fov_y);
    vec3 dd_dx = 2.0 * extent.x / size.x * right;
    vec3 dd_dy = -(2.0 * extent.y / size.y) * up;
    return RfRayDiff(
        vec3(0.0), 0.0, vec3(0.0), 0.0,
        rf_normalized_derivative(d, dd_dx), 0.0, rf_normalized_derivative(d, dd_dy), 0.0);
}

// v / sqrt(max(v.v, RF_DIFF_MIN_MAGNITUDE)).
vec3 rf_safe_normalize(vec3 v) {
    return v / sqrt(max(dot(v, v), RF_DIFF_MIN_MAGNITUDE));
}

// World direction through ndc (wireframe tutorial): view_inv * (normalize((proj_inv * (ndc, 1, 1)).xyz), 0).
vec3 rf_matrix_ray_direction(vec2 ndc, mat4 view_inv, mat4 proj_inv) {
    vec4 far_point = proj_inv * vec4(ndc, 1.0, 1.0);
    return (view_inv * vec4(rf_safe_normalize(far_point.xyz), 0.0)).xyz;
}

// Eye-ray direction through a pixel centre from the inverse view and projection matrices.
vec3 rf_eye_ray_direction_from_matrices(vec2 pixel, vec2 image_size, mat4 view_inv, mat4 proj_inv) {
    return rf_matrix_ray_direction(rf_pixel_ndc(pixel, image_size), view_inv, proj_inv);
}

// Eye-ray differential from the inverse matrices: h = (proj_inv * (ndc, 1, 1)).xyz,
// dh/dx = proj_inv[0].xyz * 2 / W, dD/dx = view_inv * (normalized_derivative(h, dh/dx), 0); dO = 0.
RfRayDiff rf_eye_ray_diff_from_matrices(vec2 pixel, vec2 image_size, mat4 view_inv, mat4 proj_inv) {
    vec2 size = max(image_size, vec2(1.0));
    vec2 ndc = rf_pixel_ndc(pixel, image_size);
    vec3 far_point = (proj_inv * vec4(ndc, 1.0, 1.0)).xyz;
    vec3 dfar_dx = proj_inv[0].xyz * (2.0 / size.x);
    vec3 dfar_dy = proj_inv[1].xyz * (2.0 / size.y);
    vec3 dd_dx = (view_inv * vec4(rf_normalized_derivative(far_point, dfar_dx), 0.0)).xyz;
    vec3 dd_dy = (view_inv * vec4(rf_normalized_derivative(far_point, dfar_dy), 0.0)).xyz;
    return RfRayDiff(vec3(0.0), 0.0, vec3(0.0), 0.0, dd_dx, 0.0, dd_dy, 0.0);
}

// Pixel differentials (wireframe tutorial, computeDifferentials): directions through the centres of
// the right and lower neighbour pixels (ndc_offset = ((pixel + 1.5) / size) * 2 - 1).
RfNeighbourDirections rf_pixel_directions(vec2 pixel, vec2 image_size, mat4 view_inv, mat4 proj_inv) {
    vec2 ndc = rf_pixel_ndc(pixel, image_size);
    vec2 next = rf_pixel_ndc(pixel + 1.0, image_size);
    return RfNeighbourDirections(
        rf_matrix_ray_direction(vec2(next.x, ndc.y), view_inv, proj_inv),
        rf_matrix_ray_direction(vec2(ndc.x, next.y), view_inv, proj_inv));
}

// value, or min_magnitude with the sign of value (+ for 0) when |value| < min_magnitude. mix with a
// bool selector is OpSelect: no branch.
float rf_clamp_away_from_zero(float value, float min_magnitude) {
    float signed_minimum = mix(-min_magnitude, min_magnitude, value >= 0.0);
    return mix(value, signed_minimum, abs(value) < min_magnitude);
}

// Igehy's transfer for one axis: q = dO + t dD, dt = -dot(q, N) / cosine, dP = q + dt D.
vec3 rf_transferred_origin(vec3 d_origin, vec3 d_direction, vec3 direction, float t, vec3 normal,
    float cosine) {
    vec3 q = d_origin + t * d_direction;
    float dt = -dot(q, normal) / cosine;
    return q + dt * direction;
}

// Transfer to a hit at distance t on a surface with normal N (Igehy): origin differentials become dP,
// direction differentials are kept; dot(D, N) clamped away from 0 to |cos| >= RF_DIFF_MIN_COS.
RfRayDiff rf_transfer(RfRayDiff diff, vec3 direction, float t, vec3 normal) {
    float cosine = rf_clamp_away_from_zero(dot(direction, normal), RF_DIFF_MIN_COS);
    return RfRayDiff(
        rf_transferred_origin(diff.d_origin_dx, diff.d_direction_dx, direction, t, normal, cosine), 0.0,
        rf_transferred_origin(diff.d_origin_dy, diff.d_direction_dy, direction, t, normal, cosine), 0.0,
        diff.d_direction_dx, 0.0,
        diff.d_direction_dy, 0.0);
}

// Barycentric differentials, optimized (RTG Eq. 12-19): du/dx = dot(cross(e2, d), q) / k,
// dv/dx = dot(cross(d, e1), q) / k, k = dot(cross(e1, e2), d) clamped away from 0, results clamped.
RfDerivatives2 rf_barycentric_derivatives(RfRayDiff diff, vec3 direction, float t, vec3 p0, vec3 p1,
    vec3 p2) {
    vec3 e1 = p1 - p0;
    vec3 e2 = p2 - p0;
    float k = rf_clamp_away_from_zero(dot(cross(e1, e2), direction), RF_DIFF_MIN_MAGNITUDE);
    vec3 cu = cross(e2, direction);
    vec3 cv = cross(direction, e1);
    vec3 q = diff.d_origin_dx + t * diff.d_direction_dx;
    vec3 r = diff.d_origin_dy + t * diff.d_direction_dy;
    vec2 limit = vec2(RF_DIFF_MAX_VALUE);
    return RfDerivatives2(
        clamp(vec2(dot(cu, q), dot(cv, q)) / k, -limit, limit),
        clamp(vec2(dot(cu, r), dot(cv, r)) / k, -limit, limit));
}

// Differentials of w = 1 - u - v (RTG Eq. 20): (-du/dx - dv/dx, -du/dy - dv/dy).
vec2 rf_barycentric_w_derivatives(RfDerivatives2 barycentric) {
    return vec2(-barycentric.dx.x - barycentric.dx.y, -barycentric.dy.x - barycentric.dy.y);
}

// UV differentials (RTG Eq. 21 without W, H): du/dx g1 + dv/dx g2, g1 = T1 - T0, g2 = T2 - T0.
RfDerivatives2 rf_texture_derivatives(RfDerivatives2 barycentric, vec2 t0, vec2 t1, vec2 t2) {
    vec2 g1 = t1 - t0;
    vec2 g2 = t2 - t0;
    return RfDerivatives2(
        barycentric.dx.x * g1 + barycentric.dx.y * g2,
        barycentric.dy.x * g1 + barycentric.dy.y * g2);
}

// Texel differentials (RTG Eq. 21): UV differentials times the texture size (clamped to >= 1).
RfDerivatives2 rf_texel_derivatives(RfDerivatives2 barycentric, vec2 t0, vec2 t1, vec2 t2,
    vec2 texture_size) {
    vec2 size = max(texture_size, vec2(1.0));
    RfDerivatives2 uv = rf_texture_derivatives(barycentric, t0, t1, t2);
    return RfDerivatives2(uv.dx * size, uv.dy * size);
}

// Origin differentials of a secondary ray (RTG Eq. 22): du/dx e1 + dv/dx e2.
RfDerivatives3 rf_secondary_origin_derivatives(RfDerivatives2 barycentric, vec3 p0, vec3 p1, vec3 p2) {
    vec3 e1 = p1 - p0;
    vec3 e2 = p2 - p0;
    return RfDerivatives3(
        barycentric.dx.x * e1 + barycentric.dx.y * e2,
        barycentric.dy.x * e1 + barycentric.dy.y * e2);
}

// Isotropic LOD (RTG Eq. 1-2): 0.5 log2(max(max(|ddx|^2, |ddy|^2), RF_DIFF_MIN_MAGNITUDE)).
float rf_lod_isotropic(RfDerivatives2 texel_gradients) {
    float rho2 = max(dot(texel_gradients.dx, texel_gradients.dx), dot(texel_gradients.dy, texel_gradients.dy));
    return 0.5 * log2(max(rho2, RF_DIFF_MIN_MAGNITUDE));
}

// Conservative box LOD (RTG Sec. 20.1): log2(max(|ds/dx| + |ds/dy|, |dt/dx| + |dt/dy|)), clamped.
float rf_lod_box(RfDerivatives2 texel_gradients) {
    vec2 extent = abs(texel_gradients.dx) + abs(texel_gradients.dy);
    return log2(max(max(extent.x, extent.y), RF_DIFF_MIN_MAGNITUDE));
}

// Anisotropic textureGrad gradients: UV differentials times max(tex_grad_scale, 0).
RfDerivatives2 rf_sample_grad_gradients(RfDerivatives2 uv_gradients, float tex_grad_scale) {
    float scale = max(tex_grad_scale, 0.0);
    return RfDerivatives2(uv_gradients.dx * scale, uv_gradients.dy * scale);
}

// Differentials of the interpolated unit normal (Igehy): n = (1 - u - v) n0 + u n1 + v n2,
// dn/dx = du/dx (n1 - n0) + dv/dx (n2 - n0), dN/dx = normalized derivative of n along dn/dx.
RfDerivatives3 rf_normal_derivatives(vec3 n0, vec3 n1, vec3 n2, vec2 barycentrics,
    RfDerivatives2 barycentric) {
    vec3 n = (1.0 - barycentrics.x - barycentrics.y) * n0 + barycentrics.x * n1 + barycentrics.y * n2;
    vec3 dn_dx = barycentric.dx.x * (n1 - n0) + barycentric.dx.y * (n2 - n0);
    vec3 dn_dy = barycentric.dy.x * (n1 - n0) + barycentric.dy.y * (n2 - n0);
    return RfDerivatives3(rf_normalized_derivative(n, dn_dx), rf_normalized_derivative(n, dn_dy));
}

// Derivative of R = D - 2 dot(D, N) N (Igehy): dD - 2 (dot(D, N) dN + (dot(dD, N) + dot(D, dN)) N).
vec3 rf_reflected_direction(vec3 d_direction, vec3 direction, vec3 normal, vec3 d_normal) {
    float cosine = dot(direction, normal);
    return d_direction - 2.0 * (cosine * d_normal + (dot(d_direction, normal) + dot(direction, d_normal)) * normal);
}

// Reflected differential (Igehy): origin differentials kept, direction differentials reflected.
RfRayDiff rf_reflect_ray_diff(RfRayDiff diff, vec3 direction, vec3 normal, RfDerivatives3 d_normal) {
    return RfRayDiff(
        diff.d_origin_dx, 0.0,
        diff.d_origin_dy, 0.0,
        rf_reflected_direction(diff.d_direction_dx, direction, normal, d_normal.dx), 0.0,
        rf_reflected_direction(diff.d_direction_dy, direction, normal, d_normal.dy), 0.0);
}

// Derivative of T = eta D - mu N (Igehy): eta dD - (mu dN + rate (dot(dD, N) + dot(D, dN)) N).
vec3 rf_refracted_direction(vec3 d_direction, vec3 direction, vec3 normal, vec3 d_normal, float eta,
    float mu, float rate) {
    float d_cos = dot(d_direction, normal) + dot(direction, d_normal);
    return eta * d_direction - (mu * d_normal + rate * d_cos * normal);
}

// Refracted differential with relative index eta (Igehy): mu = eta dot(D, N) - dot(T, N),
// rate = eta - eta^2 dot(D, N) / dot(T, N) (dot(T, N) kept RF_DIFF_MIN_COS from 0 with its own sign,
// -sign(dot(D, N)), also at exactly the critical angle).
// Total internal reflection (k = 1 - eta^2 (1 - dot(D, N)^2) < 0): the reflected differential, the
// same derivative with eta = 1, mu = 2 dot(D, N), rate = 2 (selected, no branch), and the flag set.
RfRefractedRayDiff rf_refract_ray_diff(RfRayDiff diff, vec3 direction, vec3 normal, RfDerivatives3 d_normal,
    float eta) {
    float cosine = dot(direction, normal);
    float k = 1.0 - eta * eta * (1.0 - cosine * cosine);
    bool total_internal_reflection = k < 0.0;
    float root = sqrt(max(k, 0.0));
    float transmitted_cos = mix(root, -root, cosine <= 0.0);
    float mu = eta * cosine - transmitted_cos;
    float clamped_root = max(root, RF_DIFF_MIN_COS);
    float clamped_cos = mix(clamped_root, -clamped_root, cosine <= 0.0);
    float rate = eta - eta * eta * cosine / clamped_cos;
    float ratio = mix(eta, 1.0, total_internal_reflection);
    float normal_scale = mix(mu, 2.0 * cosine, total_internal_reflection);
    float normal_rate = mix(rate, 2.0, total_internal_reflection);
    RfRayDiff leaving = RfRayDiff(
        diff.d_origin_dx, 0.0,
        diff.d_origin_dy, 0.0,
        rf_refracted_direction(diff.d_direction_dx, direction, normal, d_normal.dx, ratio, normal_scale, normal_rate),
        0.0,
        rf_refracted_direction(diff.d_direction_dy, direction, normal, d_normal.dy, ratio, normal_scale, normal_rate),
        0.0);
    return RfRefractedRayDiff(leaving, total_internal_reflection);
}

// G-buffer neighbour choice (RTG Sec. 20.3.3): the backward neighbour when the forward distance step
// exceeds depth_epsilon and the backward step is smaller.
bool rf_gbuffer_use_backward(RfGBufferSample center, RfGBufferSample forward, RfGBufferSample backward,
    float depth_epsilon) {
    float forward_step = abs(forward.distance - center.distance);
    float backward_step = abs(backward.distance - center.distance);
    return forward_step > depth_epsilon && backward_step < forward_step;
}

// Hit position step (RTG Eq. 23): t(end) e(end) - t(start) e(start).
vec3 rf_gbuffer_position_step(RfGBufferSample start, RfGBufferSample end) {
    return end.distance * end.eye_direction - start.distance * start.eye_direction;
}

// Reflected direction step (RTG Eq. 24): reflect(e(end), n(end)) - reflect(e(start), n(start)).
vec3 rf_gbuffer_direction_step(RfGBufferSample start, RfGBufferSample end) {
    vec3 reflected_end = end.eye_direction - 2.0 * dot(end.normal, end.eye_direction) * end.normal;
    vec3 reflected_start = start.eye_direction - 2.0 * dot(start.normal, start.eye_direction) * start.normal;
    return reflected_end - reflected_start;
}

// G-buffer ray differentials of the first reflected ray (RTG Eq. 23-24), with the neighbour choice
// at depth discontinuities (backward neighbours sign-flipped).
RfRayDiff rf_gbuffer_ray_diff(RfGBufferSample center, RfGBufferSample right, RfGBufferSample left,
    RfGBufferSample below, RfGBufferSample above, float depth_epsilon) {
    bool backward_x = rf_gbuffer_use_backward(center, right, left, depth_epsilon);
    bool backward_y = rf_gbuffer_use_backward(center, below, above, depth_epsilon);
    RfGBufferSample start_x = center;
    RfGBufferSample end_x = right;
    if (backward_x) {
        start_x = left;
        end_x = center;
    }
    RfGBufferSample start_y = center;
    RfGBufferSample end_y = below;
    if (backward_y) {
        start_y = above;
        end_y = center;
    }
    return RfRayDiff(
        rf_gbuffer_position_step(start_x, end_x), 0.0,
        rf_gbuffer_position_step(start_y, end_y), 0.0,
        rf_gbuffer_direction_step(start_x, end_x), 0.0,
        rf_gbuffer_direction_step(start_y, end_y), 0.0);
}

// Tangent-plane neighbour offset (Quilez): t (rd_n dot(rd, n) / dot(rd_n, n) - rd), cos clamped.
vec3 rf_tangent_plane_offset(vec3 rd, vec3 rd_neighbour, float t, vec3 normal) {
    float cosine = rf_clamp_away_from_zero(dot(rd_neighbour, normal), RF_DIFF_MIN_COS);
    return t * (rd_neighbour * (dot(rd, normal) / cosine) - rd);
}

// Position differentials of a raymarched hit from the neighbour rays and the tangent plane (Quilez).
RfDerivatives3 rf_tangent_plane_offsets(vec3 rd, vec3 rdx, vec3 rdy, float t, vec3 normal) {
    return RfDerivatives3(rf_tangent_plane_offset(rd, rdx, t, normal), rf_tangent_plane_offset(rd, rdy, t, normal));
}

// Planar mapping uv = p.xz * scale (Quilez): duv/dx = dp/dx.xz * scale.
RfDerivatives2 rf_planar_mapping_gradients(RfDerivatives3 d_position, vec2 scale) {
    return RfDerivatives2(d_position.dx.xz * scale, d_position.dy.xz * scale);
}

// Triplanar weights (Quilez): |n|^k / sum, k clamped to [0, RF_DIFF_MAX_SHARPNESS], |n| and sum clamped.
vec3 rf_triplanar_weights(vec3 normal, float sharpness) {
    float k = clamp(sharpness, 0.0, RF_DIFF_MAX_SHARPNESS);
    vec3 size = abs(normal);
    float largest = max(max(size.x, size.y), max(size.z, RF_DIFF_MIN_MAGNITUDE));
    vec3 m = pow(max(size / largest, vec3(RF_DIFF_MIN_MAGNITUDE)), vec3(k));
    return m / max(m.x + m.y + m.z, RF_DIFF_MIN_MAGNITUDE);
}

// Gradients of the triplanar projections p.yz, p.zx, p.xy, times scale (Quilez).
RfTriplanarGradients rf_triplanar_gradients(RfDerivatives3 d_position, float scale) {
    vec3 dx = d_position.dx * scale;
    vec3 dy = d_position.dy * scale;
    return RfTriplanarGradients(
        RfDerivatives2(dx.yz, dy.yz),
        RfDerivatives2(dx.zx, dy.zx),
        RfDerivatives2(dx.xy, dy.xy));
}

// |v| as m |v / m|, m the largest |component| (>= RF_DIFF_MIN_MAGNITUDE), so squaring cannot overflow.
float rf_scaled_length(vec3 v) {
    float m = max(max(abs(v.x), abs(v.y)), max(abs(v.z), RF_DIFF_MIN_MAGNITUDE));
    return m * length(v / m);
}

// Barycentrics (w, u, v) of the ray's hit on the unbounded triangle plane (RTG Eq. 13, g = d):
// u = dot(cross(e2, d), s0) / k, v = dot(cross(d, e1), s0) / k, k = dot(cross(e1, e2), d) clamped
// away from 0 to RF_DIFF_MIN_MAGNITUDE (ray parallel to the plane), u and v clamped to RF_DIFF_MAX_VALUE.
vec3 rf_intersect_triangle_plane(vec3 origin, vec3 direction, vec3 p0, vec3 p1, vec3 p2) {
    vec3 e1 = p1 - p0;
    vec3 e2 = p2 - p0;
    vec3 s0 = origin - p0;
    float k = rf_clamp_away_from_zero(dot(cross(e1, e2), direction), RF_DIFF_MIN_MAGNITUDE);
    vec2 limit = vec2(RF_DIFF_MAX_VALUE);
    vec2 uv = clamp(vec2(dot(cross(e2, direction), s0), dot(cross(direction, e1), s0)) / k, -limit, limit);
    return vec3(1.0 - uv.x - uv.y, uv.x, uv.y);
}

// (matrix * (point, 1)).xyz: the 4x3 part of matrix (fourth row ignored).
vec3 rf_transform_point(mat4 matrix, vec3 point) {
    return (matrix * vec4(point, 1.0)).xyz;
}

// Signed barycentric differences to the neighbour pixels by re-intersection (wireframe tutorial,
// computeDerivative / Going Further): (b_x - b, b_y - b). world_to_object is the 4x3 matrix as a
// mat4 (fourth row ignored, e.g. mat4(gl_WorldToObjectEXT)); the object ray origin is computed from it.
RfDerivatives3 rf_barycentric_offsets(mat4 world_to_object, vec3 world_origin, vec3 p0, vec3 p1, vec3 p2,
    vec3 direction_x, vec3 direction_y, vec3 hit_barycentrics) {
    vec3 origin = rf_transform_point(world_to_object, world_origin);
    vec3 object_x = rf_transform_point(world_to_object, world_origin + direction_x) - origin;
    vec3 object_y = rf_transform_point(world_to_object, world_origin + direction_y) - origin;
    return RfDerivatives3(
        rf_intersect_triangle_plane(origin, object_x, p0, p1, p2) - hit_barycentrics,
        rf_intersect_triangle_plane(origin, object_y, p0, p1, p2) - hit_barycentrics);
}

// Barycentric deltas, the ray-tracing fwidth(barycentrics) (wireframe tutorial, computeDerivative):
// |b_x - b| + |b_y - b|.
vec3 rf_barycentric_deltas(mat4 world_to_object, vec3 world_origin, vec3 p0, vec3 p1, vec3 p2,
    vec3 direction_x, vec3 direction_y, vec3 hit_barycentrics) {
    RfDerivatives3 offsets = rf_barycentric_offsets(
        world_to_object, world_origin, p0, p1, p2, direction_x, direction_y, hit_barycentrics);
    return abs(offsets.dx) + abs(offsets.dy);
}

// Anisotropic UV gradients of a primary hit (wireframe tutorial, Going Further): sum_i (b_x - b)_i uv_i.
RfDerivatives2 rf_uv_gradients_from_offsets(RfDerivatives3 offsets, vec2 uv0, vec2 uv1, vec2 uv2) {
    return RfDerivatives2(
        offsets.dx.x * uv0 + offsets.dx.y * uv1 + offsets.dx.z * uv2,
        offsets.dy.x * uv0 + offsets.dy.y * uv1 + offsets.dy.z * uv2);
}

// Closed-form barycentric deltas from a ray cone: |footprint| |edge opposite vertex i| / |cross(e1, e2)|,
// |cross| clamped to >= RF_DIFF_MIN_MAGNITUDE, deltas to <= RF_DIFF_MAX_VALUE.
vec3 rf_cone_barycentric_deltas(float world_footprint, vec3 p0, vec3 p1, vec3 p2) {
    float area2 = max(rf_scaled_length(cross(p1 - p0, p2 - p0)), RF_DIFF_MIN_MAGNITUDE);
    vec3 edges = vec3(rf_scaled_length(p2 - p1), rf_scaled_length(p2 - p0), rf_scaled_length(p1 - p0));
    return min(abs(world_footprint) * edges / area2, vec3(RF_DIFF_MAX_VALUE));
}

// Smallest sine between a direction and a normal at which their cross product gives the minor axis
// of rf_anisotropic_cone_axes; nearer to normal incidence a fixed tangent is used.
const float RF_DIFF_MIN_SINE = 1.0e-4;

// A unit vector perpendicular to the unit vector n (Duff et al. 2017): s = sign(n.z) (+1 for 0),
// a = -1 / (s + n.z), (1 + s n.x^2 a, s n.x n.y a, -s n.x).
vec3 rf_orthonormal_tangent(vec3 n) {
    float sign_z = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (sign_z + n.z);
    return vec3(1.0 + sign_z * n.x * n.x * a, sign_z * n.x * n.y * a, -sign_z * n.x);
}

// Footprint axes of a cone (JCGT 2021, Falcor computeAnisotropicEllipseAxes, errata factor 2): the
// cylinder of diameter |width| around d cut by the plane of n; m = normalize(cross(n, d)),
// dx = cross(m, n) |width| / max(|n.d|, RF_DIFF_MIN_COS), dy = m |width|;
// m = cross(n, fixed tangent) when |cross(n, d)| < RF_DIFF_MIN_SINE.
RfDerivatives3 rf_anisotropic_cone_axes(float width, vec3 normal, vec3 direction) {
    vec3 across = cross(normal, direction);
    float length2 = dot(across, across);
    vec3 fixed_minor = cross(normal, rf_orthonormal_tangent(normal));
    vec3 minor = mix(across / sqrt(length2), fixed_minor, bvec3(length2 < RF_DIFF_MIN_SINE * RF_DIFF_MIN_SINE));
    float size = abs(width);
    return RfDerivatives3(cross(minor, normal) * (size / max(abs(dot(normal, direction)), RF_DIFF_MIN_COS)),
        minor * size);
}

// Unit triangle normal: cross(p1 - p0, p2 - p0) / max(scaled length, RF_DIFF_MIN_MAGNITUDE).
vec3 rf_triangle_unit_normal(vec3 p0, vec3 p1, vec3 p2) {
    vec3 area_normal = cross(p1 - p0, p2 - p0);
    return area_normal / max(rf_scaled_length(area_normal), RF_DIFF_MIN_MAGNITUDE);
}

// Anisotropic textureGrad gradients of a cone hitting a triangle (JCGT 2021, errata factor 2): UV at
// hit + axis minus UV at the hit for the rf_anisotropic_cone_axes in the triangle's plane.
RfDerivatives2 rf_anisotropic_cone_gradients(float width, vec3 direction, vec3 p0, vec3 p1, vec3 p2,
    vec2 uv0, vec2 uv1, vec2 uv2) {
    vec3 normal = rf_triangle_unit_normal(p0, p1, p2);
    RfDerivatives3 axes = rf_anisotropic_cone_axes(width, normal, direction);
    RfRayDiff offsets = RfRayDiff(axes.dx, 0.0, axes.dy, 0.0, vec3(0.0), 0.0, vec3(0.0), 0.0);
    RfDerivatives2 barycentric = rf_barycentric_derivatives(offsets, normal, 0.0, p0, p1, p2);
    return rf_texture_derivatives(barycentric, uv0, uv1, uv2);
}

// Isotropic differential of a cone (width, spread_angle) around d: u = tangent of d, v = cross(d, u),
// dO = width (u, v), dD = spread_angle (u, v).
RfRayDiff rf_ray_diff_from_cone(vec2 cone, vec3 direction) {
    vec3 u = rf_orthonormal_tangent(direction);
    vec3 v = cross(direction, u);
    return RfRayDiff(cone.x * u, 0.0, cone.x * v, 0.0, cone.y * u, 0.0, cone.y * v, 0.0);
}

// (width, spread) of one axis: the lengths of dO and dD across d, the spread negative when they point apart.
vec2 rf_transverse_cone(vec3 d_origin, vec3 d_direction, vec3 direction) {
    vec3 origin = d_origin - dot(d_origin, direction) * direction;
    vec3 turn = d_direction - dot(d_direction, direction) * direction;
    float sign_turn = dot(origin, turn) >= 0.0 ? 1.0 : -1.0;
    return vec2(rf_scaled_length(origin), sign_turn * rf_scaled_length(turn));
}

// Cone (width, spread_angle) of a differential around d: the mean of its two axes' transverse cones.
vec2 rf_cone_from_ray_diff(RfRayDiff diff, vec3 direction) {
    vec2 x = rf_transverse_cone(diff.d_origin_dx, diff.d_direction_dx, direction);
    vec2 y = rf_transverse_cone(diff.d_origin_dy, diff.d_direction_dy, direction);
    return 0.5 * (x + y);
}

#endif // RAY_FOOTPRINT_RAY_DIFF_GLSL
