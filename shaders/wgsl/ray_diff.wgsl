// ray-footprint: Ray differentials (Igehy 1999; RTG ch. 20 Eq. 1-24): how a ray's origin and direction change from pixel to pixel, carried to hits, barycentrics and texture coordinates.
//
// Library module (no entry points). Twin of shaders/glsl/ray_diff.glsl and the Rust mirror
// src/ray_diff.rs: same functions, same order, same order of operations. Formulas and sources are
// documented in src/ray_diff.rs; "RTG Eq. N" is Ray Tracing Gems ch. 20 (Akenine-Moller et al. 2019),
// "Igehy" is "Tracing Ray Differentials" (1999), "Quilez" is "ray differentials and texturing" (2015),
// "wireframe tutorial" is nvpro's ray-tracing tutorial 20 (computeDifferentials, computeDerivative).
//
// Pixel (0, 0) is the top-left pixel; dx is the change for one pixel step right, dy for one step down.
// Normals and directions are unit length unless stated. Divergent cases are clamped with the RF_DIFF_
// constants: finite inputs give finite outputs.

// Largest vertical field of view in radians.
const RF_DIFF_MAX_FOV_Y: f32 = 3.1;
// Smallest |cos| between two unit vectors used as a divisor (grazing-angle clamp), keeping its sign.
const RF_DIFF_MIN_COS: f32 = 1.0e-4;
// Smallest magnitude used as a divisor (squared lengths, triangle determinants) or passed to log2.
const RF_DIFF_MIN_MAGNITUDE: f32 = 1.0e-30;
// Largest magnitude of a barycentric coordinate, differential or delta (ray parallel to a plane): 2^40,
// so that such a value times any input of the domain (up to 1e12) stays finite.
const RF_DIFF_MAX_VALUE: f32 = 1099511627776.0;
// Largest triplanar blend sharpness.
const RF_DIFF_MAX_SHARPNESS: f32 = 64.0;

// A ray differential (Igehy; RTG Eq. 7), 64 bytes: origin and unit-direction changes per pixel step.
// Each vec3 is followed by an explicit f32 pad (always 0) so WGSL, std430, scalar and Rust agree.
struct RfRayDiff {
    d_origin_dx: vec3<f32>,
    pad0: f32,
    d_origin_dy: vec3<f32>,
    pad1: f32,
    d_direction_dx: vec3<f32>,
    pad2: f32,
    d_direction_dy: vec3<f32>,
    pad3: f32,
}

// Change of a 2-vector (barycentrics (u, v), UVs) per pixel step right (dx) and down (dy).
struct RfDerivatives2 {
    dx: vec2<f32>,
    dy: vec2<f32>,
}

// Change of a 3-vector (position, normal, barycentrics (w, u, v)) per pixel step right and down.
struct RfDerivatives3 {
    dx: vec3<f32>,
    dy: vec3<f32>,
}

// World directions of the rays through the right and the lower neighbour pixel centres.
struct RfNeighbourDirections {
    right: vec3<f32>,
    below: vec3<f32>,
}

// A refracted differential; on total internal reflection, the reflected one and the flag set.
struct RfRefractedRayDiff {
    diff: RfRayDiff,
    total_internal_reflection: bool,
}

// One G-buffer pixel: unit eye direction, distance to the first hit, unit normal there.
struct RfGBufferSample {
    eye_direction: vec3<f32>,
    distance: f32,
    normal: vec3<f32>,
}

// Gradients of the three triplanar projections (sampled with p.yz, p.zx, p.xy).
struct RfTriplanarGradients {
    yz: RfDerivatives2,
    zx: RfDerivatives2,
    xy: RfDerivatives2,
}

// Half extents of the image plane at distance 1 (RTG Eq. 9): (a f, f), f = tan(fov_y / 2), a = W / H.
fn rf_eye_ray_extent(image_size: vec2<f32>, fov_y: f32) -> vec2<f32> {
    let size = max(image_size, vec2<f32>(1.0));
    let f = tan(0.5 * clamp(fov_y, 0.0, RF_DIFF_MAX_FOV_Y));
    return vec2<f32>(size.x / size.y * f, f);
}

// Normalized device coordinates of a pixel centre: ((pixel + 0.5) / size) * 2 - 1.
fn rf_pixel_ndc(pixel: vec2<f32>, image_size: vec2<f32>) -> vec2<f32> {
    return (pixel + 0.5) / max(image_size, vec2<f32>(1.0)) * 2.0 - 1.0;
}

// Non-normalized eye-ray direction (RTG Eq. 8-9): c.x a f right - c.y f up - view (view points to the eye).
fn rf_eye_ray_direction(
    pixel: vec2<f32>, image_size: vec2<f32>, fov_y: f32, right: vec3<f32>, up: vec3<f32>, view: vec3<f32>,
) -> vec3<f32> {
    let c = rf_pixel_ndc(pixel, image_size);
    let extent = rf_eye_ray_extent(image_size, fov_y);
    return c.x * extent.x * right - c.y * extent.y * up - view;
}

// Derivative of v / |v| (Igehy; RTG Eq. 10): (dv - v (v.dv / v.v)) / sqrt(v.v), v.v >= RF_DIFF_MIN_MAGNITUDE.
fn rf_normalized_derivative(v: vec3<f32>, dv: vec3<f32>) -> vec3<f32> {
    let length2 = max(dot(v, v), RF_DIFF_MIN_MAGNITUDE);
    return (dv - v * (dot(v, dv) / length2)) / sqrt(length2);
}

// Eye-ray differential of a pinhole (RTG Eq. 8-11): dO = 0, dD = normalized derivative of
// dd/dx = (2 a f / W) right and dd/dy = -(2 f / H) up.
fn rf_eye_ray_diff(
    pixel: vec2<f32>, image_size: vec2<f32>, fov_y: f32, right: vec3<f32>, up: vec3<f32>, view: vec3<f32>,
) -> RfRayDiff {
    let d = rf_eye_ray_direction(pixel, image_size, fov_y, right, up, view);
    let size = max(image_size, vec2<f32>(1.0));
    let extent = rf_eye_ray_extent(image_size, fov_y);
    let dd_dx = 2.0 * extent.x / size.x * right;
    let dd_dy = -(2.0 * extent.y / size.y) * up;
    return RfRayDiff(
        vec3<f32>(0.0), 0.0, vec3<f32>(0.0), 0.0,
        rf_normalized_derivative(d, dd_dx), 0.0, rf_normalized_derivative(d, dd_dy), 0.0,
    );
}

// v / sqrt(max(v.v, RF_DIFF_MIN_MAGNITUDE)).
fn rf_safe_normalize(v: vec3<f32>) -> vec3<f32> {
    return v / sqrt(max(dot(v, v), RF_DIFF_MIN_MAGNITUDE));
}

// World direction through ndc (wireframe tutorial): view_inv * (normalize((proj_inv * (ndc, 1, 1)).xyz), 0).
fn rf_matrix_ray_direction(ndc: vec2<f32>, view_inv: mat4x4<f32>, proj_inv: mat4x4<f32>) -> vec3<f32> {
    let far_point = proj_inv * vec4<f32>(ndc, 1.0, 1.0);
    return (view_inv * vec4<f32>(rf_safe_normalize(far_point.xyz), 0.0)).xyz;
}

// Eye-ray direction through a pixel centre from the inverse view and projection matrices.
fn rf_eye_ray_direction_from_matrices(
    pixel: vec2<f32>, image_size: vec2<f32>, view_inv: mat4x4<f32>, proj_inv: mat4x4<f32>,
) -> vec3<f32> {
    return rf_matrix_ray_direction(rf_pixel_ndc(pixel, image_size), view_inv, proj_inv);
}

// Eye-ray differential from the inverse matrices: h = (proj_inv * (ndc, 1, 1)).xyz,
// dh/dx = proj_inv[0].xyz * 2 / W, dD/dx = view_inv * (normalized_derivative(h, dh/dx), 0); dO = 0.
fn rf_eye_ray_diff_from_matrices(
    pixel: vec2<f32>, image_size: vec2<f32>, view_inv: mat4x4<f32>, proj_inv: mat4x4<f32>,
) -> RfRayDiff {
    let size = max(image_size, vec2<f32>(1.0));
    let ndc = rf_pixel_ndc(pixel, image_size);
    let far_point = (proj_inv * vec4<f32>(ndc, 1.0, 1.0)).xyz;
    let dfar_dx = proj_inv[0].xyz * (2.0 / size.x);
    let dfar_dy = proj_inv[1].xyz * (2.0 / size.y);
    let dd_dx = (view_inv * vec4<f32>(rf_normalized_derivative(far_point, dfar_dx), 0.0)).xyz;
    let dd_dy = (view_inv * vec4<f32>(rf_normalized_derivative(far_point, dfar_dy), 0.0)).xyz;
    return RfRayDiff(vec3<f32>(0.0), 0.0, vec3<f32>(0.0), 0.0, dd_dx, 0.0, dd_dy, 0.0);
}

// Pixel differentials (wireframe tutorial, computeDifferentials): directions through the centres of
// the right and lower neighbour pixels (ndc_offset = ((pixel + 1.5) / size) * 2 - 1).
fn rf_pixel_directions(
    pixel: vec2<f32>, image_size: vec2<f32>, view_inv: mat4x4<f32>, proj_inv: mat4x4<f32>,
) -> RfNeighbourDirections {
    let ndc = rf_pixel_ndc(pixel, image_size);
    let next = rf_pixel_ndc(pixel + 1.0, image_size);
    return RfNeighbourDirections(
        rf_matrix_ray_direction(vec2<f32>(next.x, ndc.y), view_inv, proj_inv),
        rf_matrix_ray_direction(vec2<f32>(ndc.x, next.y), view_inv, proj_inv),
    );
}

// value, or min_magnitude with the sign of value (+ for 0) when |value| < min_magnitude.
fn rf_clamp_away_from_zero(value: f32, min_magnitude: f32) -> f32 {
    return select(value, select(-min_magnitude, min_magnitude, value >= 0.0), abs(value) < min_magnitude);
}

// Igehy's transfer for one axis: q = dO + t dD, dt = -dot(q, N) / cos, dP = q + dt D.
fn rf_transferred_origin(
    d_origin: vec3<f32>, d_direction: vec3<f32>, direction: vec3<f32>, t: f32, normal: vec3<f32>, cosine: f32,
) -> vec3<f32> {
    let q = d_origin + t * d_direction;
    let dt = -dot(q, normal) / cosine;
    return q + dt * direction;
}

// Transfer to a hit at distance t on a surface with normal N (Igehy): origin differentials become dP,
// direction differentials are kept; dot(D, N) clamped away from 0 to |cos| >= RF_DIFF_MIN_COS.
fn rf_transfer(diff: RfRayDiff, direction: vec3<f32>, t: f32, normal: vec3<f32>) -> RfRayDiff {
    let cosine = rf_clamp_away_from_zero(dot(direction, normal), RF_DIFF_MIN_COS);
    return RfRayDiff(
        rf_transferred_origin(diff.d_origin_dx, diff.d_direction_dx, direction, t, normal, cosine), 0.0,
        rf_transferred_origin(diff.d_origin_dy, diff.d_direction_dy, direction, t, normal, cosine), 0.0,
        diff.d_direction_dx, 0.0,
        diff.d_direction_dy, 0.0,
    );
}

// Barycentric differentials, optimized (RTG Eq. 12-19): du/dx = dot(cross(e2, d), q) / k,
// dv/dx = dot(cross(d, e1), q) / k, k = dot(cross(e1, e2), d) clamped away from 0, results clamped.
fn rf_barycentric_derivatives(
    diff: RfRayDiff, direction: vec3<f32>, t: f32, p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>,
) -> RfDerivatives2 {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let k = rf_clamp_away_from_zero(dot(cross(e1, e2), direction), RF_DIFF_MIN_MAGNITUDE);
    let cu = cross(e2, direction);
    let cv = cross(direction, e1);
    let q = diff.d_origin_dx + t * diff.d_direction_dx;
    let r = diff.d_origin_dy + t * diff.d_direction_dy;
    let limit = vec2<f32>(RF_DIFF_MAX_VALUE);
    return RfDerivatives2(
        clamp(vec2<f32>(dot(cu, q), dot(cv, q)) / k, -limit, limit),
        clamp(vec2<f32>(dot(cu, r), dot(cv, r)) / k, -limit, limit),
    );
}

// Differentials of w = 1 - u - v (RTG Eq. 20): (-du/dx - dv/dx, -du/dy - dv/dy).
fn rf_barycentric_w_derivatives(barycentric: RfDerivatives2) -> vec2<f32> {
    return vec2<f32>(-barycentric.dx.x - barycentric.dx.y, -barycentric.dy.x - barycentric.dy.y);
}

// UV differentials (RTG Eq. 21 without W, H): du/dx g1 + dv/dx g2, g1 = T1 - T0, g2 = T2 - T0.
fn rf_texture_derivatives(
    barycentric: RfDerivatives2, t0: vec2<f32>, t1: vec2<f32>, t2: vec2<f32>,
) -> RfDerivatives2 {
    let g1 = t1 - t0;
    let g2 = t2 - t0;
    return RfDerivatives2(
        barycentric.dx.x * g1 + barycentric.dx.y * g2,
        barycentric.dy.x * g1 + barycentric.dy.y * g2,
    );
}

// Texel differentials (RTG Eq. 21): UV differentials times the texture size (clamped to >= 1).
fn rf_texel_derivatives(
    barycentric: RfDerivatives2, t0: vec2<f32>, t1: vec2<f32>, t2: vec2<f32>, texture_size: vec2<f32>,
) -> RfDerivatives2 {
    let size = max(texture_size, vec2<f32>(1.0));
    let uv = rf_texture_derivatives(barycentric, t0, t1, t2);
    return RfDerivatives2(uv.dx * size, uv.dy * size);
}

// Origin differentials of a secondary ray (RTG Eq. 22): du/dx e1 + dv/dx e2.
fn rf_secondary_origin_derivatives(
    barycentric: RfDerivatives2, p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>,
) -> RfDerivatives3 {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    return RfDerivatives3(
        barycentric.dx.x * e1 + barycentric.dx.y * e2,
        barycentric.dy.x * e1 + barycentric.dy.y * e2,
    );
}

// Isotropic LOD (RTG Eq. 1-2): 0.5 log2(max(max(|ddx|^2, |ddy|^2), RF_DIFF_MIN_MAGNITUDE)).
fn rf_lod_isotropic(texel_gradients: RfDerivatives2) -> f32 {
    let rho2 = max(dot(texel_gradients.dx, texel_gradients.dx), dot(texel_gradients.dy, texel_gradients.dy));
    return 0.5 * log2(max(rho2, RF_DIFF_MIN_MAGNITUDE));
}

// Conservative box LOD (RTG Sec. 20.1): log2(max(|ds/dx| + |ds/dy|, |dt/dx| + |dt/dy|)), clamped.
fn rf_lod_box(texel_gradients: RfDerivatives2) -> f32 {
    let extent = abs(texel_gradients.dx) + abs(texel_gradients.dy);
    return log2(max(max(extent.x, extent.y), RF_DIFF_MIN_MAGNITUDE));
}

// Anisotropic SampleGrad gradients: UV differentials times max(tex_grad_scale, 0).
fn rf_sample_grad_gradients(uv_gradients: RfDerivatives2, tex_grad_scale: f32) -> RfDerivatives2 {
    let scale = max(tex_grad_scale, 0.0);
    return RfDerivatives2(uv_gradients.dx * scale, uv_gradients.dy * scale);
}

// Differentials of the interpolated unit normal (Igehy): n = (1 - u - v) n0 + u n1 + v n2,
// dn/dx = du/dx (n1 - n0) + dv/dx (n2 - n0), dN/dx = normalized derivative of n along dn/dx.
fn rf_normal_derivatives(
    n0: vec3<f32>, n1: vec3<f32>, n2: vec3<f32>, barycentrics: vec2<f32>, barycentric: RfDerivatives2,
) -> RfDerivatives3 {
    let n = (1.0 - barycentrics.x - barycentrics.y) * n0 + barycentrics.x * n1 + barycentrics.y * n2;
    let dn_dx = barycentric.dx.x * (n1 - n0) + barycentric.dx.y * (n2 - n0);
    let dn_dy = barycentric.dy.x * (n1 - n0) + barycentric.dy.y * (n2 - n0);
    return RfDerivatives3(rf_normalized_derivative(n, dn_dx), rf_normalized_derivative(n, dn_dy));
}

// Derivative of R = D - 2 dot(D, N) N (Igehy): dD - 2 (dot(D, N) dN + (dot(dD, N) + dot(D, dN)) N).
fn rf_reflected_direction(
    d_direction: vec3<f32>, direction: vec3<f32>, normal: vec3<f32>, d_normal: vec3<f32>,
) -> vec3<f32> {
    let cosine = dot(direction, normal);
    return d_direction - 2.0 * (cosine * d_normal + (dot(d_direction, normal) + dot(direction, d_normal)) * normal);
}

// Reflected differential (Igehy): origin differentials kept, direction differentials reflected.
fn rf_reflect_ray_diff(
    diff: RfRayDiff, direction: vec3<f32>, normal: vec3<f32>, d_normal: RfDerivatives3,
) -> RfRayDiff {
    return RfRayDiff(
        diff.d_origin_dx, 0.0,
        diff.d_origin_dy, 0.0,
        rf_reflected_direction(diff.d_direction_dx, direction, normal, d_normal.dx), 0.0,
        rf_reflected_direction(diff.d_direction_dy, direction, normal, d_normal.dy), 0.0,
    );
}

// Derivative of T = eta D - mu N (Igehy): eta dD - (mu dN + rate (dot(dD, N) + dot(D, dN)) N).
fn rf_refracted_direction(
    d_direction: vec3<f32>, direction: vec3<f32>, normal: vec3<f32>, d_normal: vec3<f32>,
    eta: f32, mu: f32, rate: f32,
) -> vec3<f32> {
    let d_cos = dot(d_direction, normal) + dot(direction, d_normal);
    return eta * d_direction - (mu * d_normal + rate * d_cos * normal);
}

// Refracted differential with relative index eta (Igehy): mu = eta dot(D, N) - dot(T, N),
// rate = eta - eta^2 dot(D, N) / dot(T, N) (dot(T, N) kept RF_DIFF_MIN_COS from 0 with its own sign,
// -sign(dot(D, N)), also at exactly the critical angle).
// Total internal reflection (k = 1 - eta^2 (1 - dot(D, N)^2) < 0): the reflected differential, the
// same derivative with eta = 1, mu = 2 dot(D, N), rate = 2 (selected, no branch), and the flag set.
fn rf_refract_ray_diff(
    diff: RfRayDiff, direction: vec3<f32>, normal: vec3<f32>, d_normal: RfDerivatives3, eta: f32,
) -> RfRefractedRayDiff {
    let cosine = dot(direction, normal);
    let k = 1.0 - eta * eta * (1.0 - cosine * cosine);
    let total_internal_reflection = k < 0.0;
    let root = sqrt(max(k, 0.0));
    let transmitted_cos = select(root, -root, cosine <= 0.0);
    let mu = eta * cosine - transmitted_cos;
    let clamped_root = max(root, RF_DIFF_MIN_COS);
    let clamped_cos = select(clamped_root, -clamped_root, cosine <= 0.0);
    let rate = eta - eta * eta * cosine / clamped_cos;
    let ratio = select(eta, 1.0, total_internal_reflection);
    let normal_scale = select(mu, 2.0 * cosine, total_internal_reflection);
    let normal_rate = select(rate, 2.0, total_internal_reflection);
    let leaving = RfRayDiff(
        diff.d_origin_dx, 0.0,
        diff.d_origin_dy, 0.0,
        rf_refracted_direction(diff.d_direction_dx, direction, normal, d_normal.dx, ratio, normal_scale, normal_rate),
        0.0,
        rf_refracted_direction(diff.d_direction_dy, direction, normal, d_normal.dy, ratio, normal_scale, normal_rate),
        0.0,
    );
    return RfRefractedRayDiff(leaving, total_internal_reflection);
}

// G-buffer neighbour choice (RTG Sec. 20.3.3): the backward neighbour when the forward distance step
// exceeds depth_epsilon and the backward step is smaller.
fn rf_gbuffer_use_backward(
    center: RfGBufferSample, forward: RfGBufferSample, backward: RfGBufferSample, depth_epsilon: f32,
) -> bool {
    let forward_step = abs(forward.distance - center.distance);
    let backward_step = abs(backward.distance - center.distance);
    return (forward_step > depth_epsilon) & (backward_step < forward_step);
}

// Hit position step (RTG Eq. 23): t(end) e(end) - t(start) e(start).
fn rf_gbuffer_position_step(start: RfGBufferSample, end: RfGBufferSample) -> vec3<f32> {
    return end.distance * end.eye_direction - start.distance * start.eye_direction;
}

// Reflected direction step (RTG Eq. 24): reflect(e(end), n(end)) - reflect(e(start), n(start)).
fn rf_gbuffer_direction_step(start: RfGBufferSample, end: RfGBufferSample) -> vec3<f32> {
    let reflected_end = end.eye_direction - 2.0 * dot(end.normal, end.eye_direction) * end.normal;
    let reflected_start = start.eye_direction - 2.0 * dot(start.normal, start.eye_direction) * start.normal;
    return reflected_end - reflected_start;
}

// G-buffer ray differentials of the first reflected ray (RTG Eq. 23-24), with the neighbour choice
// at depth discontinuities (backward neighbours sign-flipped).
fn rf_gbuffer_ray_diff(
    center: RfGBufferSample, right: RfGBufferSample, left: RfGBufferSample,
    below: RfGBufferSample, above: RfGBufferSample, depth_epsilon: f32,
) -> RfRayDiff {
    let backward_x = rf_gbuffer_use_backward(center, right, left, depth_epsilon);
    let backward_y = rf_gbuffer_use_backward(center, below, above, depth_epsilon);
    var start_x = center;
    var end_x = right;
    if backward_x {
        start_x = left;
        end_x = center;
    }
    var start_y = center;
    var end_y = below;
    if backward_y {
        start_y = above;
        end_y = center;
    }
    return RfRayDiff(
        rf_gbuffer_position_step(start_x, end_x), 0.0,
        rf_gbuffer_position_step(start_y, end_y), 0.0,
        rf_gbuffer_direction_step(start_x, end_x), 0.0,
        rf_gbuffer_direction_step(start_y, end_y), 0.0,
    );
}

// Tangent-plane neighbour offset (Quilez): t (rd_n dot(rd, n) / dot(rd_n, n) - rd), cos clamped.
fn rf_tangent_plane_offset(rd: vec3<f32>, rd_neighbour: vec3<f32>, t: f32, normal: vec3<f32>) -> vec3<f32> {
    let cosine = rf_clamp_away_from_zero(dot(rd_neighbour, normal), RF_DIFF_MIN_COS);
    return t * (rd_neighbour * (dot(rd, normal) / cosine) - rd);
}

// Position differentials of a raymarched hit from the neighbour rays and the tangent plane (Quilez).
fn rf_tangent_plane_offsets(
    rd: vec3<f32>, rdx: vec3<f32>, rdy: vec3<f32>, t: f32, normal: vec3<f32>,
) -> RfDerivatives3 {
    return RfDerivatives3(rf_tangent_plane_offset(rd, rdx, t, normal), rf_tangent_plane_offset(rd, rdy, t, normal));
}

// Planar mapping uv = p.xz * scale (Quilez): duv/dx = dp/dx.xz * scale.
fn rf_planar_mapping_gradients(d_position: RfDerivatives3, scale: vec2<f32>) -> RfDerivatives2 {
    return RfDerivatives2(d_position.dx.xz * scale, d_position.dy.xz * scale);
}

// Triplanar weights (Quilez): |n|^k / sum, k clamped to [0, RF_DIFF_MAX_SHARPNESS], |n| and sum clamped.
fn rf_triplanar_weights(normal: vec3<f32>, sharpness: f32) -> vec3<f32> {
    let k = clamp(sharpness, 0.0, RF_DIFF_MAX_SHARPNESS);
    let size = abs(normal);
    let largest = max(max(size.x, size.y), max(size.z, RF_DIFF_MIN_MAGNITUDE));
    let m = pow(max(size / largest, vec3<f32>(RF_DIFF_MIN_MAGNITUDE)), vec3<f32>(k));
    return m / max(m.x + m.y + m.z, RF_DIFF_MIN_MAGNITUDE);
}

// Gradients of the triplanar projections p.yz, p.zx, p.xy, times scale (Quilez).
fn rf_triplanar_gradients(d_position: RfDerivatives3, scale: f32) -> RfTriplanarGradients {
    let dx = d_position.dx * scale;
    let dy = d_position.dy * scale;
    return RfTriplanarGradients(
        RfDerivatives2(dx.yz, dy.yz),
        RfDerivatives2(dx.zx, dy.zx),
        RfDerivatives2(dx.xy, dy.xy),
    );
}

// |v| as m |v / m|, m the largest |component| (>= RF_DIFF_MIN_MAGNITUDE), so squaring cannot overflow.
fn rf_scaled_length(v: vec3<f32>) -> f32 {
    let m = max(max(abs(v.x), abs(v.y)), max(abs(v.z), RF_DIFF_MIN_MAGNITUDE));
    return m * length(v / m);
}

// Barycentrics (w, u, v) of the ray's hit on the unbounded triangle plane (RTG Eq. 13, g = d):
// u = dot(cross(e2, d), s0) / k, v = dot(cross(d, e1), s0) / k, k = dot(cross(e1, e2), d) clamped
// away from 0 to RF_DIFF_MIN_MAGNITUDE (ray parallel to the plane), u and v clamped to RF_DIFF_MAX_VALUE.
fn rf_intersect_triangle_plane(
    origin: vec3<f32>, direction: vec3<f32>, p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>,
) -> vec3<f32> {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let s0 = origin - p0;
    let k = rf_clamp_away_from_zero(dot(cross(e1, e2), direction), RF_DIFF_MIN_MAGNITUDE);
    let limit = vec2<f32>(RF_DIFF_MAX_VALUE);
    let uv = clamp(vec2<f32>(dot(cross(e2, direction), s0), dot(cross(direction, e1), s0)) / k, -limit, limit);
    return vec3<f32>(1.0 - uv.x - uv.y, uv.x, uv.y);
}

// (matrix * (point, 1)).xyz: the 4x3 part of matrix (fourth row ignored).
fn rf_transform_point(matrix: mat4x4<f32>, point: vec3<f32>) -> vec3<f32> {
    return (matrix * vec4<f32>(point, 1.0)).xyz;
}

// Signed barycentric differences to the neighbour pixels by re-intersection (wireframe tutorial,
// computeDerivative / Going Further): (b_x - b, b_y - b). world_to_object is the 4x3 matrix as a
// mat4 (fourth row ignored); the object ray origin is computed from it.
fn rf_barycentric_offsets(
    world_to_object: mat4x4<f32>, world_origin: vec3<f32>, p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>,
    direction_x: vec3<f32>, direction_y: vec3<f32>, hit_barycentrics: vec3<f32>,
) -> RfDerivatives3 {
    let origin = rf_transform_point(world_to_object, world_origin);
    let object_x = rf_transform_point(world_to_object, world_origin + direction_x) - origin;
    let object_y = rf_transform_point(world_to_object, world_origin + direction_y) - origin;
    return RfDerivatives3(
        rf_intersect_triangle_plane(origin, object_x, p0, p1, p2) - hit_barycentrics,
        rf_intersect_triangle_plane(origin, object_y, p0, p1, p2) - hit_barycentrics,
    );
}

// Barycentric deltas, the ray-tracing fwidth(barycentrics) (wireframe tutorial, computeDerivative):
// |b_x - b| + |b_y - b|.
fn rf_barycentric_deltas(
    world_to_object: mat4x4<f32>, world_origin: vec3<f32>, p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>,
    direction_x: vec3<f32>, direction_y: vec3<f32>, hit_barycentrics: vec3<f32>,
) -> vec3<f32> {
    let offsets = rf_barycentric_offsets(
        world_to_object, world_origin, p0, p1, p2, direction_x, direction_y, hit_barycentrics,
    );
    return abs(offsets.dx) + abs(offsets.dy);
}

// Anisotropic UV gradients of a primary hit (wireframe tutorial, Going Further): sum_i (b_x - b)_i uv_i.
fn rf_uv_gradients_from_offsets(
    offsets: RfDerivatives3, uv0: vec2<f32>, uv1: vec2<f32>, uv2: vec2<f32>,
) -> RfDerivatives2 {
    return RfDerivatives2(
        offsets.dx.x * uv0 + offsets.dx.y * uv1 + offsets.dx.z * uv2,
        offsets.dy.x * uv0 + offsets.dy.y * uv1 + offsets.dy.z * uv2,
    );
}

// Closed-form barycentric deltas from a ray cone: |footprint| |edge opposite vertex i| / |cross(e1, e2)|,
// |cross| clamped to >= RF_DIFF_MIN_MAGNITUDE, deltas to <= RF_DIFF_MAX_VALUE.
fn rf_cone_barycentric_deltas(world_footprint: f32, p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>) -> vec3<f32> {
    let area2 = max(rf_scaled_length(cross(p1 - p0, p2 - p0)), RF_DIFF_MIN_MAGNITUDE);
    let edges = vec3<f32>(rf_scaled_length(p2 - p1), rf_scaled_length(p2 - p0), rf_scaled_length(p1 - p0));
    return min(abs(world_footprint) * edges / area2, vec3<f32>(RF_DIFF_MAX_VALUE));
}

// Smallest sine between a direction and a normal at which their cross product gives the minor axis
// of rf_anisotropic_cone_axes; nearer to normal incidence a fixed tangent is used.
const RF_DIFF_MIN_SINE: f32 = 1.0e-4;

// A unit vector perpendicular to the unit vector n (Duff et al. 2017): s = sign(n.z) (+1 for 0),
// a = -1 / (s + n.z), (1 + s n.x^2 a, s n.x n.y a, -s n.x).
fn rf_orthonormal_tangent(n: vec3<f32>) -> vec3<f32> {
    let sign_z = select(-1.0, 1.0, n.z >= 0.0);
    let a = -1.0 / (sign_z + n.z);
    return vec3<f32>(1.0 + sign_z * n.x * n.x * a, sign_z * n.x * n.y * a, -sign_z * n.x);
}

// Footprint axes of a cone (JCGT 2021, Falcor computeAnisotropicEllipseAxes, errata factor 2): the
// cylinder of diameter |width| around d cut by the plane of n; m = normalize(cross(n, d)),
// dx = cross(m, n) |width| / max(|n.d|, RF_DIFF_MIN_COS), dy = m |width|;
// m = cross(n, fixed tangent) when |cross(n, d)| < RF_DIFF_MIN_SINE.
fn rf_anisotropic_cone_axes(width: f32, normal: vec3<f32>, direction: vec3<f32>) -> RfDerivatives3 {
    let across = cross(normal, direction);
    let length2 = dot(across, across);
    let fixed_minor = cross(normal, rf_orthonormal_tangent(normal));
    let minor = select(across / sqrt(length2), fixed_minor, length2 < RF_DIFF_MIN_SINE * RF_DIFF_MIN_SINE);
    let size = abs(width);
    return RfDerivatives3(
        cross(minor, normal) * (size / max(abs(dot(normal, direction)), RF_DIFF_MIN_COS)),
        minor * size,
    );
}

// Unit triangle normal: cross(p1 - p0, p2 - p0) / max(scaled length, RF_DIFF_MIN_MAGNITUDE).
fn rf_triangle_unit_normal(p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>) -> vec3<f32> {
    let area_normal = cross(p1 - p0, p2 - p0);
    return area_normal / max(rf_scaled_length(area_normal), RF_DIFF_MIN_MAGNITUDE);
}

// Anisotropic textureGrad gradients of a cone hitting a triangle (JCGT 2021, errata factor 2): UV at
// hit + axis minus UV at the hit for the rf_anisotropic_cone_axes in the triangle's plane.
fn rf_anisotropic_cone_gradients(
    width: f32, direction: vec3<f32>, p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>,
    uv0: vec2<f32>, uv1: vec2<f32>, uv2: vec2<f32>,
) -> RfDerivatives2 {
    let normal = rf_triangle_unit_normal(p0, p1, p2);
    let axes = rf_anisotropic_cone_axes(width, normal, direction);
    let offsets = RfRayDiff(axes.dx, 0.0, axes.dy, 0.0, vec3<f32>(0.0), 0.0, vec3<f32>(0.0), 0.0);
    let barycentric = rf_barycentric_derivatives(offsets, normal, 0.0, p0, p1, p2);
    return rf_texture_derivatives(barycentric, uv0, uv1, uv2);
}

// Isotropic differential of a cone (width, spread_angle) around d: u = tangent of d, v = cross(d, u),
// dO = width (u, v), dD = spread_angle (u, v).
fn rf_ray_diff_from_cone(cone: vec2<f32>, direction: vec3<f32>) -> RfRayDiff {
    let u = rf_orthonormal_tangent(direction);
    let v = cross(direction, u);
    return RfRayDiff(cone.x * u, 0.0, cone.x * v, 0.0, cone.y * u, 0.0, cone.y * v, 0.0);
}

// (width, spread) of one axis: the lengths of dO and dD across d, the spread negative when they point apart.
fn rf_transverse_cone(d_origin: vec3<f32>, d_direction: vec3<f32>, direction: vec3<f32>) -> vec2<f32> {
    let origin = d_origin - dot(d_origin, direction) * direction;
    let turn = d_direction - dot(d_direction, direction) * direction;
    let sign_turn = select(-1.0, 1.0, dot(origin, turn) >= 0.0);
    return vec2<f32>(rf_scaled_length(origin), sign_turn * rf_scaled_length(turn));
}

// Cone (width, spread_angle) of a differential around d: the mean of its two axes' transverse cones.
fn rf_cone_from_ray_diff(diff: RfRayDiff, direction: vec3<f32>) -> vec2<f32> {
    let x = rf_transverse_cone(diff.d_origin_dx, diff.d_direction_dx, direction);
    let y = rf_transverse_cone(diff.d_origin_dy, diff.d_direction_dy, direction);
    return 0.5 * (x + y);
}
