//! Ray differentials in double precision, for scenes whose coordinate range defeats f32. Needs f64 in shaders (naga FLOAT64 / wgpu SHADER_F64; GLSL double with shaderFloat64).
//!
//! The Rust mirror of `shaders/wgsl/ray_diff_f64.wgsl` and `shaders/glsl/ray_diff_f64.glsl`: the
//! barycentric re-intersection of [`crate::ray_diff`] (the tutorial's `computeDerivative`) computed in f64, as the wireframe
//! tutorial's `computeDerivativeHighp`. The public functions take and return `f32` exactly like their
//! f32 twins in [`crate::ray_diff`] (drop-in replacements with the suffix `_f64`); every intermediate
//! is `f64`, in the shaders as here, in the same order of operations.
//!
//! Why: [`crate::ray_diff::barycentric_offsets`] moves the world ray origin `O` by a unit neighbour
//! direction and subtracts again. In f32, `O + direction` keeps only `24 - log2|O|` bits of the
//! direction: at `|O| = 1e4` the neighbour direction is off by about `1e-3`, as much as a pixel's
//! angular step, and the barycentric deltas of a far-away triangle become noise (thin wireframe lines
//! flicker). In f64 the same steps lose nothing that matters for any f32 scene.
//!
//! The module is independent of [`crate::ray_diff`] (its shaders can be included alone or next to
//! it); names carry `_f64` / `F64_` so that both can be included together.

use glam::{DVec2, DVec3, Mat4, Vec3, Vec4Swizzles};

/// Smallest magnitude of the triangle determinant used as a divisor (ray parallel to the plane):
/// `2^-100` (about `7.9e-31`). A power of two, so the shaders' float literal widened to double is
/// this exact value whichever way a compiler reads the literal (glslang folds a float literal at
/// double precision, naga's GLSL front end reads no double literals).
pub const F64_MIN_MAGNITUDE: f64 = 7.888_609_052_210_118e-31;
/// Largest magnitude of a barycentric coordinate, `DIFF_MAX_VALUE` of [`crate::ray_diff`] (`2^40`,
/// exact in every precision); it also keeps the conversion to f32 finite.
pub const F64_MAX_VALUE: f64 = 1_099_511_627_776.0;

/// Signed barycentric differences to the neighbour pixels, `(b_x - b, b_y - b)` (shader
/// `RfBarycentricOffsets`; the same values as [`crate::ray_diff::Derivatives3`] from
/// [`crate::ray_diff::barycentric_offsets`]). A function result, not laid out for host-shareable buffers.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BarycentricOffsets {
    /// `b_x - b`: towards the right neighbour pixel.
    pub dx: Vec3,
    /// `b_y - b`: towards the lower neighbour pixel.
    pub dy: Vec3,
}

/// `value`, or `min_magnitude` with the sign of `value` (+ for 0) when `|value| < min_magnitude`.
fn clamp_away_from_zero_f64(value: f64, min_magnitude: f64) -> f64 {
    if value.abs() < min_magnitude {
        if value >= 0.0 {
            min_magnitude
        } else {
            -min_magnitude
        }
    } else {
        value
    }
}

/// Barycentrics `(w, u, v)` of the ray's hit on the unbounded triangle plane, in f64 (RTG Eq. 13 with
/// `g = d`): `u = dot(cross(e2, d), s0) / k`, `v = dot(cross(d, e1), s0) / k`, `w = 1 - u - v`,
/// `k = dot(cross(e1, e2), d)` clamped away from 0 to `|k| >= F64_MIN_MAGNITUDE`, `u`, `v` clamped to
/// `[-F64_MAX_VALUE, F64_MAX_VALUE]`.
fn plane_barycentrics_f64(origin: DVec3, direction: DVec3, p0: DVec3, p1: DVec3, p2: DVec3) -> DVec3 {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let s0 = origin - p0;
    let k = clamp_away_from_zero_f64(e1.cross(e2).dot(direction), F64_MIN_MAGNITUDE);
    let limit = DVec2::splat(F64_MAX_VALUE);
    let uv = (DVec2::new(e2.cross(direction).dot(s0), direction.cross(e1).dot(s0)) / k).clamp(-limit, limit);
    DVec3::new(1.0 - uv.x - uv.y, uv.x, uv.y)
}

// ---- Re-intersection in double precision (wireframe tutorial) ----

/// [`crate::ray_diff::intersect_triangle_plane`] computed in f64: f32 in, f32 out.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_diff_f64::intersect_triangle_plane_f64;
///
/// // A triangle 10 km away with legs of 4 m along y and z (u = y / 4, v = z / 4), and
/// // the ray from the origin towards its point (10000, 1, 2): (w, u, v) = (0.25, 0.25, 0.5).
/// let (p0, p1, p2) = (Vec3::new(1.0e4, 0.0, 0.0), Vec3::new(1.0e4, 4.0, 0.0), Vec3::new(1.0e4, 0.0, 4.0));
/// let b = intersect_triangle_plane_f64(Vec3::ZERO, Vec3::new(1.0e4, 1.0, 2.0), p0, p1, p2);
/// assert!((b - Vec3::new(0.25, 0.25, 0.5)).length() < 1e-7);
/// ```
pub fn intersect_triangle_plane_f64(origin: Vec3, direction: Vec3, p0: Vec3, p1: Vec3, p2: Vec3) -> Vec3 {
    plane_barycentrics_f64(
        origin.as_dvec3(),
        direction.as_dvec3(),
        p0.as_dvec3(),
        p1.as_dvec3(),
        p2.as_dvec3(),
    )
    .as_vec3()
}

/// `(matrix * (point, 1)).xyz` in f64, column by column: `c0 x + c1 y + c2 z + c3` (the 4x3 part; the
/// fourth row is ignored).
fn transform_point_f64(matrix: Mat4, point: DVec3) -> DVec3 {
    matrix.x_axis.xyz().as_dvec3() * point.x
        + matrix.y_axis.xyz().as_dvec3() * point.y
        + matrix.z_axis.xyz().as_dvec3() * point.z
        + matrix.w_axis.xyz().as_dvec3()
}

/// [`crate::ray_diff::barycentric_offsets`] computed in f64 (wireframe tutorial,
/// `computeDerivativeHighp`): the moved origins `O + direction`, their object-space images and the
/// plane intersections are f64; the differences `b_x - b`, `b_y - b` are rounded to f32 once.
///
/// # Examples
///
/// ```
/// use glam::{Mat4, Vec3};
/// use ray_footprint::ray_diff::barycentric_offsets;
/// use ray_footprint::ray_diff_f64::barycentric_offsets_f64;
///
/// // 10 km from the world origin: a floor triangle with legs of 4 m along x and -z
/// // (u = (x - x0) / 4, v = -(z - z0) / 4), seen from 2 m above its point (1, 0, -1) relative to p0.
/// let p0 = Vec3::new(1.0e4, 0.0, -1.0e4);
/// let (p1, p2) = (p0 + Vec3::new(4.0, 0.0, 0.0), p0 + Vec3::new(0.0, 0.0, -4.0));
/// let origin = p0 + Vec3::new(1.0, 2.0, -1.0);
/// let hit = Vec3::new(0.5, 0.25, 0.25);
/// // The neighbour rays lean 1 mrad towards +x and +z and land 2 mm away: u grows by 0.002 / 4 and
/// // v drops by as much. Only the final rounding to f32 remains (6e-11 at 0.0005).
/// let right = Vec3::new(1e-3, -1.0, 0.0).normalize();
/// let below = Vec3::new(0.0, -1.0, 1e-3).normalize();
/// let offsets = barycentric_offsets_f64(Mat4::IDENTITY, origin, p0, p1, p2, right, below, hit);
/// let exact_dx = Vec3::new(-0.0005, 0.0005, 0.0);
/// assert!((offsets.dx - exact_dx).length() < 1e-9);
/// assert!((offsets.dy - Vec3::new(0.0005, 0.0, -0.0005)).length() < 1e-9);
/// // In f32, 1e4 + 0.001 keeps the lean only to the f32 spacing at 1e4, 0.00098: 2 % off.
/// let coarse = barycentric_offsets(Mat4::IDENTITY, origin, p0, p1, p2, right, below, hit);
/// assert!((coarse.dx - exact_dx).length() > 0.01 * exact_dx.length());
/// ```
#[allow(clippy::too_many_arguments)]
pub fn barycentric_offsets_f64(
    world_to_object: Mat4,
    world_origin: Vec3,
    p0: Vec3,
    p1: Vec3,
    p2: Vec3,
    direction_x: Vec3,
    direction_y: Vec3,
    hit_barycentrics: Vec3,
) -> BarycentricOffsets {
    let world = world_origin.as_dvec3();
    let origin = transform_point_f64(world_to_object, world);
    let object_x = transform_point_f64(world_to_object, world + direction_x.as_dvec3()) - origin;
    let object_y = transform_point_f64(world_to_object, world + direction_y.as_dvec3()) - origin;
    let (q0, q1, q2) = (p0.as_dvec3(), p1.as_dvec3(), p2.as_dvec3());
    let hit = hit_barycentrics.as_dvec3();
    BarycentricOffsets {
        dx: (plane_barycentrics_f64(origin, object_x, q0, q1, q2) - hit).as_vec3(),
        dy: (plane_barycentrics_f64(origin, object_y, q0, q1, q2) - hit).as_vec3(),
    }
}

/// [`crate::ray_diff::barycentric_deltas`] from [`barycentric_offsets_f64`]: `|b_x - b| + |b_y - b|`
/// (the final sum in f32).
///
/// # Examples
///
/// ```
/// use glam::{Mat4, Vec3};
/// use ray_footprint::ray_diff_f64::barycentric_deltas_f64;
///
/// // The scene of `barycentric_offsets_f64`, 10 km out: one step lands 2 mm away along x, the other
/// // along +z, so |du| = |dv| = 0.0005 and w changes by both.
/// let p0 = Vec3::new(1.0e4, 0.0, -1.0e4);
/// let (p1, p2) = (p0 + Vec3::new(4.0, 0.0, 0.0), p0 + Vec3::new(0.0, 0.0, -4.0));
/// let origin = p0 + Vec3::new(1.0, 2.0, -1.0);
/// let right = Vec3::new(1e-3, -1.0, 0.0).normalize();
/// let below = Vec3::new(0.0, -1.0, 1e-3).normalize();
/// let hit = Vec3::new(0.5, 0.25, 0.25);
/// let deltas = barycentric_deltas_f64(Mat4::IDENTITY, origin, p0, p1, p2, right, below, hit);
/// assert!((deltas - Vec3::new(0.001, 0.0005, 0.0005)).length() < 1e-9);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn barycentric_deltas_f64(
    world_to_object: Mat4,
    world_origin: Vec3,
    p0: Vec3,
    p1: Vec3,
    p2: Vec3,
    direction_x: Vec3,
    direction_y: Vec3,
    hit_barycentrics: Vec3,
) -> Vec3 {
    let offsets = barycentric_offsets_f64(
        world_to_object,
        world_origin,
        p0,
        p1,
        p2,
        direction_x,
        direction_y,
        hit_barycentrics,
    );
    offsets.dx.abs() + offsets.dy.abs()
}
