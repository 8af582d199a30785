// ray-footprint: Ray differentials in double precision, for scenes whose coordinate range defeats f32. Needs f64 in shaders (naga FLOAT64 / wgpu SHADER_F64; GLSL double with shaderFloat64).
//
// Library module for GLSL 460 (no main): #include "ray_diff_f64.glsl". Twin of shaders/wgsl/ray_diff_f64.wgsl
// and the Rust mirror src/ray_diff_f64.rs: same functions, same order, same order of operations. The
// barycentric re-intersection of ray_diff.glsl (rf_intersect_triangle_plane, rf_barycentric_offsets,
// rf_barycentric_deltas) computed in double, as the wireframe tutorial's computeDerivativeHighp: float
// in, float out, drop-in replacements with the suffix _f64. Independent of ray_diff.glsl.

#ifndef RAY_FOOTPRINT_RAY_DIFF_F64_GLSL
#define RAY_FOOTPRINT_RAY_DIFF_F64_GLSL

// Smallest magnitude of the triangle determinant used as a divisor (ray parallel to the plane): 2^-100,
// a power of two, so the float literal widened is this exact value whichever way a compiler reads it.
const double RF_F64_MIN_MAGNITUDE = double(7.888609052210118e-31);
// Largest magnitude of a barycentric coordinate: 2^40, as RF_DIFF_MAX_VALUE; keeps the conversion to
// float finite.
const double RF_F64_MAX_VALUE = double(1099511627776.0);

// Signed barycentric differences to the neighbour pixels: (b_x - b, b_y - b).
struct RfBarycentricOffsets {
    vec3 dx;
    vec3 dy;
};

// value, or min_magnitude with the sign of value (+ for 0) when |value| < min_magnitude.
double rf_clamp_away_from_zero_f64(double value, double min_magnitude) {
    double signed_minimum = mix(-min_magnitude, min_magnitude, value >= double(0.0));
    return mix(value, signed_minimum, abs(value) < min_magnitude);
}

// Barycentrics (w, u, v) of the ray's hit on the unbounded triangle plane, in double (RTG Eq. 13,
// g = d), k clamped away from 0 to RF_F64_MIN_MAGNITUDE, u and v clamped to RF_F64_MAX_VALUE.
dvec3 rf_plane_barycentrics_f64(dvec3 origin, dvec3 direction, dvec3 p0, dvec3 p1, dvec3 p2) {
    dvec3 e1 = p1 - p0;
    dvec3 e2 = p2 - p0;
    dvec3 s0 = origin - p0;
    double k = rf_clamp_away_from_zero_f64(dot(cross(e1, e2), direction), RF_F64_MIN_MAGNITUDE);
    dvec2 limit = dvec2(RF_F64_MAX_VALUE);
    dvec2 uv = clamp(dvec2(dot(cross(e2, direction), s0), dot(cross(direction, e1), s0)) / k, -limit, limit);
    return dvec3(double(1.0) - uv.x - uv.y, uv.x, uv.y);
}

// rf_intersect_triangle_plane computed in double: float in, float out.
vec3 rf_intersect_triangle_plane_f64(vec3 origin, vec3 direction, vec3 p0, vec3 p1, vec3 p2) {
    return vec3(rf_plane_barycentrics_f64(dvec3(origin), dvec3(direction), dvec3(p0), dvec3(p1), dvec3(p2)));
}

// (matrix * (point, 1)).xyz in double, column by column (the 4x3 part; fourth row ignored).
dvec3 rf_transform_point_f64(mat4 matrix, dvec3 point) {
    return dvec3(matrix[0].xyz) * point.x + dvec3(matrix[1].xyz) * point.y
        + dvec3(matrix[2].xyz) * point.z + dvec3(matrix[3].xyz);
}

// rf_barycentric_offsets computed in double (wireframe tutorial, computeDerivativeHighp).
RfBarycentricOffsets rf_barycentric_offsets_f64(mat4 world_to_object, vec3 world_origin, vec3 p0, vec3 p1,
    vec3 p2, vec3 direction_x, vec3 direction_y, vec3 hit_barycentrics) {
    dvec3 world = dvec3(world_origin);
    dvec3 origin = rf_transform_point_f64(world_to_object, world);
    dvec3 object_x = rf_transform_point_f64(world_to_object, world + dvec3(direction_x)) - origin;
    dvec3 object_y = rf_transform_point_f64(world_to_object, world + dvec3(direction_y)) - origin;
    dvec3 q0 = dvec3(p0);
    dvec3 q1 = dvec3(p1);
    dvec3 q2 = dvec3(p2);
    dvec3 hit = dvec3(hit_barycentrics);
    return RfBarycentricOffsets(
        vec3(rf_plane_barycentrics_f64(origin, object_x, q0, q1, q2) - hit),
        vec3(rf_plane_barycentrics_f64(origin, object_y, q0, q1, q2) - hit));
}

// rf_barycentric_deltas from rf_barycentric_offsets_f64: |b_x - b| + |b_y - b| (the sum in float).
vec3 rf_barycentric_deltas_f64(mat4 world_to_object, vec3 world_origin, vec3 p0, vec3 p1, vec3 p2,
    vec3 direction_x, vec3 direction_y, vec3 hit_barycentrics) {
    RfBarycentricOffsets offsets = rf_barycentric_offsets_f64(
        world_to_object, world_origin, p0, p1, p2, direction_x, direction_y, hit_barycentrics);
    return abs(offsets.dx) + abs(offsets.dy);
}

#endif // RAY_FOOTPRINT_RAY_DIFF_F64_GLSL
