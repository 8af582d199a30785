// ray-footprint: Ray differentials in double precision, for scenes whose coordinate range defeats f32. Needs f64 in shaders (naga FLOAT64 / wgpu SHADER_F64; GLSL double with shaderFloat64).
//
// Library module (no entry points). Twin of shaders/glsl/ray_diff_f64.glsl and the Rust mirror
// src/ray_diff_f64.rs: same functions, same order, same order of operations. The barycentric
// re-intersection of ray_diff.wgsl (rf_intersect_triangle_plane, rf_barycentric_offsets,
// rf_barycentric_deltas) computed in f64, as the wireframe tutorial's computeDerivativeHighp: f32 in,
// f32 out, drop-in replacements with the suffix _f64. Independent of ray_diff.wgsl.

// Smallest magnitude of the triangle determinant used as a divisor (ray parallel to the plane): 2^-100,
// a power of two, so the f32 literal widened is this exact value whichever way a compiler reads it.
const RF_F64_MIN_MAGNITUDE: f64 = f64(7.888609052210118e-31f);
// Largest magnitude of a barycentric coordinate: 2^40, as RF_DIFF_MAX_VALUE; keeps the conversion to
// f32 finite.
const RF_F64_MAX_VALUE: f64 = f64(1099511627776.0f);

// Signed barycentric differences to the neighbour pixels: (b_x - b, b_y - b).
struct RfBarycentricOffsets {
    dx: vec3<f32>,
    dy: vec3<f32>,
}

// value, or min_magnitude with the sign of value (+ for 0) when |value| < min_magnitude.
fn rf_clamp_away_from_zero_f64(value: f64, min_magnitude: f64) -> f64 {
    return select(value, select(-min_magnitude, min_magnitude, value >= 0.0lf), abs(value) < min_magnitude);
}

// Barycentrics (w, u, v) of the ray's hit on the unbounded triangle plane, in f64 (RTG Eq. 13, g = d),
// k clamped away from 0 to RF_F64_MIN_MAGNITUDE, u and v clamped to RF_F64_MAX_VALUE.
fn rf_plane_barycentrics_f64(
    origin: vec3<f64>, direction: vec3<f64>, p0: vec3<f64>, p1: vec3<f64>, p2: vec3<f64>,
) -> vec3<f64> {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let s0 = origin - p0;
    let k = rf_clamp_away_from_zero_f64(dot(cross(e1, e2), direction), RF_F64_MIN_MAGNITUDE);
    let limit = vec2<f64>(RF_F64_MAX_VALUE);
    let uv = clamp(vec2<f64>(dot(cross(e2, direction), s0), dot(cross(direction, e1), s0)) / k, -limit, limit);
    return vec3<f64>(1.0lf - uv.x - uv.y, uv.x, uv.y);
}

// rf_intersect_triangle_plane computed in f64: f32 in, f32 out.
fn rf_intersect_triangle_plane_f64(
    origin: vec3<f32>, direction: vec3<f32>, p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>,
) -> vec3<f32> {
    return vec3<f32>(rf_plane_barycentrics_f64(
        vec3<f64>(origin), vec3<f64>(direction), vec3<f64>(p0), vec3<f64>(p1), vec3<f64>(p2),
    ));
}

// (matrix * (point, 1)).xyz in f64, column by column (the 4x3 part; fourth row ignored).
fn rf_transform_point_f64(matrix: mat4x4<f32>, point: vec3<f64>) -> vec3<f64> {
    return vec3<f64>(matrix[0].xyz) * point.x + vec3<f64>(matrix[1].xyz) * point.y
        + vec3<f64>(matrix[2].xyz) * point.z + vec3<f64>(matrix[3].xyz);
}

// rf_barycentric_offsets computed in f64 (wireframe tutorial, computeDerivativeHighp).
fn rf_barycentric_offsets_f64(
    world_to_object: mat4x4<f32>, world_origin: vec3<f32>, p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>,
    direction_x: vec3<f32>, direction_y: vec3<f32>, hit_barycentrics: vec3<f32>,
) -> RfBarycentricOffsets {
    let world = vec3<f64>(world_origin);
    let origin = rf_transform_point_f64(world_to_object, world);
    let object_x = rf_transform_point_f64(world_to_object, world + vec3<f64>(direction_x)) - origin;
    let object_y = rf_transform_point_f64(world_to_object, world + vec3<f64>(direction_y)) - origin;
    let q0 = vec3<f64>(p0);
    let q1 = vec3<f64>(p1);
    let q2 = vec3<f64>(p2);
    let hit = vec3<f64>(hit_barycentrics);
    return RfBarycentricOffsets(
        vec3<f32>(rf_plane_barycentrics_f64(origin, object_x, q0, q1, q2) - hit),
        vec3<f32>(rf_plane_barycentrics_f64(origin, object_y, q0, q1, q2) - hit),
    );
}

// rf_barycentric_deltas from rf_barycentric_offsets_f64: |b_x - b| + |b_y - b| (the sum in f32).
fn rf_barycentric_deltas_f64(
    world_to_object: mat4x4<f32>, world_origin: vec3<f32>, p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>,
    direction_x: vec3<f32>, direction_y: vec3<f32>, hit_barycentrics: vec3<f32>,
) -> vec3<f32> {
    let offsets = rf_barycentric_offsets_f64(
        world_to_object, world_origin, p0, p1, p2, direction_x, direction_y, hit_barycentrics,
    );
    return abs(offsets.dx) + abs(offsets.dy);
}
