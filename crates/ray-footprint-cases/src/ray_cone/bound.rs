//! Error bounds of the ray-cone checks that are derived by hand, one term per operation (Vulkan's
//! precision rules, [`shader_proptest::tolerance`]), where more than one check (or the ray-tracing
//! pipeline's test) needs the same bound.

use glam::{Vec2, Vec3, Vec3Swizzles};
use ray_footprint::ray_cone::{self as rc, RayCone, MAX_FOV_Y, MIN_COS, MIN_SQUARED_MAGNITUDE};
use shader_proptest::tolerance::{dot_error, tan_error, ulps};

/// `|cos|` as the functions clamp it.
pub(super) fn clamped_cos(normal: Vec3, direction: Vec3) -> f32 {
    normal.dot(direction).abs().max(MIN_COS)
}

/// Error of `2 * tan(fov / 2) / H` with the clamps: `tan`'s error scaled by `2 / H`, plus 3.5 ULP.
pub(super) fn tan_ratio_error(fov: f32, height: f32) -> f32 {
    let angle = 0.5 * fov.clamp(0.0, MAX_FOV_Y);
    2.0 * tan_error(angle) / height.max(1.0) + ulps(3.5, rc::pixel_spread_angle_small(fov, height))
}

/// Error of [`rc::width_at`], `width + spread_angle * t`, possibly fused: 2 ULP of the larger term.
pub(super) fn width_at_error(cone: RayCone, t: f32) -> f32 {
    ulps(2.0, cone.width.abs() + (cone.spread_angle * t).abs())
}

/// Error of a triangle's doubled world area: each cross-product component `a*b - c*d` is off by at
/// most 2 ULP of `|a*b| + |c*d|` (the edges are computed identically); the scaling division
/// (2.5 ULP), `length` (8 ULP) and the rescaling product (0.5 ULP) add 11 ULP of the result.
pub(super) fn world_area2_error(p: [Vec3; 3]) -> f32 {
    let (e1, e2) = (p[1] - p[0], p[2] - p[0]);
    let terms = (e1.yzx() * e2.zxy()).abs() + (e1.zxy() * e2.yzx()).abs();
    ulps(2.0, terms.element_sum()) + ulps(11.0, rc::triangle_world_area2(p[0], p[1], p[2]))
}

/// Error of a triangle's doubled UV area: 2 ULP of `|e1.x*e2.y| + |e1.y*e2.x|`.
pub(super) fn uv_area2_error(uv: [Vec2; 3]) -> f32 {
    let (e1, e2) = (uv[1] - uv[0], uv[2] - uv[0]);
    ulps(2.0, (e1.x * e2.y).abs() + (e1.y * e2.x).abs())
}

/// Widest change of `f(uv_area2, world_area2)` when each area moves within its error bound; `f` is
/// monotonic in each area, so the extremes lie at the corners. Evaluated in f64.
pub fn area_corners(p: [Vec3; 3], uv: [Vec2; 3], f: impl Fn(f64, f64) -> f64) -> f32 {
    let uv_area = f64::from(rc::triangle_uv_area2(uv[0], uv[1], uv[2]));
    let world_area = f64::from(rc::triangle_world_area2(p[0], p[1], p[2]));
    let (uv_err, world_err) = (f64::from(uv_area2_error(uv)), f64::from(world_area2_error(p)));
    let centre = f(uv_area, world_area);
    [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)]
        .iter()
        .map(|(a, b)| {
            (f(
                (uv_area + a * uv_err).max(0.0),
                (world_area + b * world_err).max(0.0),
            ) - centre)
                .abs()
        })
        .fold(0.0, f64::max) as f32
}

/// Error of [`rc::edge_curvature`]: the dot product's rounding over the squared length, and the
/// relative error of the squared length (3 ULP) and the division (2.5 ULP) times the result.
pub fn edge_curvature_error(p_i: Vec3, p_j: Vec3, n_i: Vec3, n_j: Vec3) -> f32 {
    let edge = p_j - p_i;
    dot_error(n_j - n_i, edge) / edge.dot(edge).max(MIN_SQUARED_MAGNITUDE)
        + ulps(7.0, rc::edge_curvature(p_i, p_j, n_i, n_j))
}

/// Error of [`rc::triangle_curvature`] of the corners `p` and normals `n`: the three edges'
/// `edge_curvature_error`s, then two additions and a division by 3 (5 ULP of the sum of the
/// edges' magnitudes), all divided by 3.
pub fn triangle_curvature_error(p: [Vec3; 3], n: [Vec3; 3]) -> f32 {
    let edges = [(0, 1), (1, 2), (2, 0)].map(|(i, j)| (p[i], p[j], n[i], n[j]));
    let errors: f32 = edges
        .iter()
        .map(|&(p_i, p_j, n_i, n_j)| edge_curvature_error(p_i, p_j, n_i, n_j))
        .sum();
    let sizes: f32 = edges
        .iter()
        .map(|&(p_i, p_j, n_i, n_j)| rc::edge_curvature(p_i, p_j, n_i, n_j).abs())
        .sum();
    (errors + ulps(5.0, sizes)) / 3.0
}

/// Error of [`rc::curvature_spread_angle`] returning `expected`: relative, two products and a
/// division (5 ULP with the mirror's), and the rounding of `dot(normal, direction)` over the
/// clamped `|cos|`. Where the dot product lies within its rounding of 0, the device may find the
/// ray on the other side of the normal and return `-expected`, which is as right: 2 `|expected|`
/// more.
pub fn curvature_spread_angle_error(normal: Vec3, direction: Vec3, expected: f32) -> f32 {
    let dot_rounding = dot_error(normal, direction);
    let error = ulps(5.0, expected) + expected.abs() * dot_rounding / clamped_cos(normal, direction);
    if normal.dot(direction).abs() <= dot_rounding {
        error + 2.0 * expected.abs()
    } else {
        error
    }
}
