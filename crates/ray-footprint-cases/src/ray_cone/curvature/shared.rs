//! What the curvature functions share: the error of an edge's curvature (a tolerance); the shape
//! operator's frame and normal equations in interval arithmetic, with the inputs whose fit is
//! well-conditioned; the principal curvatures' half gap and radius; the corners of the degenerate
//! rows; and for the references, points and exact normals of spheres and cylinders, the error of a
//! chord's curvature, and the exact frame and shape operator of their triangles.

use crate::conditioning::WELL_CONDITIONED;
use crate::exact::{log_uniform, unit};
use crate::reference::{gamma, U};
use glam::{DMat3, DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MIN_MAGNITUDE, MIN_SQUARED_MAGNITUDE};
use shader_proptest::interval::{interval3, Interval, Interval3, IntervalVec};
use shader_proptest::tolerance::{dot_error, ulps};

/// Error of [`rc::edge_curvature`]: the dot product's rounding over the squared length, and the
/// relative error of the squared length (3 ULP) and the division (2.5 ULP) times the result.
pub(crate) fn edge_curvature_error(p_i: Vec3, p_j: Vec3, n_i: Vec3, n_j: Vec3) -> f32 {
    let edge = p_j - p_i;
    dot_error(n_j - n_i, edge) / edge.dot(edge).max(MIN_SQUARED_MAGNITUDE)
        + ulps(7.0, rc::edge_curvature(p_i, p_j, n_i, n_j))
}

/// `axis / max(|axis|, MIN_MAGNITUDE)`, as `clamped_unit`.
pub(crate) fn clamped_unit(axis: Interval3) -> Interval3 {
    axis / axis.dot(axis).sqrt().max_c(f64::from(MIN_MAGNITUDE))
}

/// The triangle's shape frame `(u, v)`, as `shape_frame_u` and `shape_frame_v`.
pub(crate) fn shape_frame(p: [Interval3; 3]) -> (Interval3, Interval3) {
    let u = clamped_unit(p[1] - p[0]);
    let face = clamped_unit(u.cross(clamped_unit(p[2] - p[0])));
    (u, face.cross(u))
}

/// The normal equations of `triangle_shape_operator` after the divisions by the largest edge
/// component and by `A + B`: `(A, B, C)`, the right-hand side `r`, and that largest component.
pub(crate) fn shape_normal_equations(
    p: [Interval3; 3],
    n: [Interval3; 3],
) -> ([Interval; 3], Interval3, Interval) {
    let (u, v) = shape_frame(p);
    let (a, b, extent) = shape_edge_components(p, u, v);
    let turns = [n[1] - n[0], n[2] - n[1], n[0] - n[2]];
    let (du, dv) = (along(turns, u), along(turns, v));
    let scale = shape_scale(a, b);
    let r = IntervalVec([a.dot(du), b.dot(du) + a.dot(dv), b.dot(dv)]) / scale;
    (shape_squares(a, b, scale), r, extent)
}

/// The components of `vectors` along `axis`.
fn along(vectors: [Interval3; 3], axis: Interval3) -> Interval3 {
    IntervalVec(vectors.map(|x| x.dot(axis)))
}

/// The edges' components along the frame `(u, v)` divided by the largest of them, and that
/// largest component (at least `MIN_MAGNITUDE`).
fn shape_edge_components(p: [Interval3; 3], u: Interval3, v: Interval3) -> (Interval3, Interval3, Interval) {
    let edges = [p[1] - p[0], p[2] - p[1], p[0] - p[2]];
    let (along_u, along_v) = (along(edges, u), along(edges, v));
    let extent = along_u
        .0
        .iter()
        .chain(&along_v.0)
        .fold(Interval::exact(MIN_MAGNITUDE), |largest, x| largest.max(x.abs()));
    (along_u / extent, along_v / extent, extent)
}

/// `A + B` of the scaled edge components `a` and `b`, at least `MIN_MAGNITUDE`.
fn shape_scale(a: Interval3, b: Interval3) -> Interval {
    (a.dot(a) + b.dot(b)).max_c(f64::from(MIN_MAGNITUDE))
}

/// `(A, B, C)` of the scaled edge components, divided by `scale`.
fn shape_squares(a: Interval3, b: Interval3, scale: Interval) -> [Interval; 3] {
    [a.dot(a) / scale, b.dot(b) / scale, a.dot(b) / scale]
}

/// The determinant `AB - C²` of `triangle_shape_operator`'s normal equations, before its clamp.
pub(crate) fn shape_determinant([aa, bb, ab]: [Interval; 3]) -> Interval {
    aa * bb - ab.abs() * ab.abs()
}

/// Whether the determinant of `triangle_shape_operator`'s normal equations is known to be
/// positive and known to [`WELL_CONDITIONED`] (a triangle that is not a sliver within rounding,
/// nor exactly flat: a repeated corner gives an exact 0) and its largest edge component known
/// above `MIN_MAGNITUDE`, where the clamp would begin.
pub(crate) fn shape_well_conditioned(p: [Vec3; 3]) -> bool {
    let p = p.map(interval3);
    let (u, v) = shape_frame(p);
    let (a, b, extent) = shape_edge_components(p, u, v);
    let determinant = shape_determinant(shape_squares(a, b, shape_scale(a, b)));
    determinant.lo > 0.0
        && determinant.relative_width() <= WELL_CONDITIONED
        && extent.lo > f64::from(MIN_MAGNITUDE)
}

/// `(e - g) / 2` and the radius `|((e - g) / 2, f)|` of `principal_curvatures` and
/// `principal_direction`.
pub(crate) fn principal_half_gap_radius(shape_operator: Interval3) -> (Interval, Interval) {
    let [e, f, g] = shape_operator.0;
    let half_gap = Interval::c(0.5) * (e - g);
    let radius = (half_gap.abs() * half_gap.abs() + f.abs() * f.abs()).sqrt();
    (half_gap, radius)
}

/// The corners `0, x, y`: the frame is `(x, y)` exactly, and every sum of the fit is a dyadic
/// number, so the documented values are exact.
pub(crate) fn unit_corners() -> (Vec3, Vec3, Vec3) {
    (Vec3::ZERO, Vec3::X, Vec3::Y)
}

/// Points and unit normals of a sphere or a cylinder, the normals stored outward or inward, and
/// the exact normal curvature of each chord.
#[derive(Clone, Debug)]
pub(crate) struct Curved {
    pub(crate) points: Vec<DVec3>,
    pub(crate) normals: Vec<DVec3>,
    /// Unit axis of a cylinder, `None` for a sphere.
    pub(crate) axis: Option<DVec3>,
    pub(crate) radius: f64,
    /// 1 for outward normals, -1 for inward ones.
    pub(crate) orientation: f64,
}

impl Curved {
    /// `count` points of a sphere or cylinder of radius `10^[-2, 2]` around a centre within 10.
    pub(crate) fn strategy(count: usize) -> BoxedStrategy<Curved> {
        let place = (unit(), -1.0f64..1.0);
        (
            any::<bool>(),
            (-10.0f64..10.0, -10.0f64..10.0, -10.0f64..10.0),
            log_uniform(-2.0, 2.0),
            unit(),
            any::<bool>(),
            prop::collection::vec(place, count),
        )
            .prop_map(|(cylinder, (x, y, z), radius, axis, inward, places)| {
                let centre = DVec3::new(x, y, z);
                let orientation = if inward { -1.0 } else { 1.0 };
                let (points, normals) = places
                    .iter()
                    .map(|&(u, height)| {
                        let radial = if cylinder {
                            (u - axis * u.dot(axis)).normalize_or(axis.any_orthonormal_vector())
                        } else {
                            u
                        };
                        let along = if cylinder {
                            axis * (2.0 * radius * height)
                        } else {
                            DVec3::ZERO
                        };
                        (centre + radial * radius + along, radial * orientation)
                    })
                    .unzip();
                Curved {
                    points,
                    normals,
                    axis: cylinder.then_some(axis),
                    radius,
                    orientation,
                }
            })
            .boxed()
    }

    /// The curvature of the chord from point `i` to point `j`: `1 / R` on a sphere, `(1 - (a . e)^2)
    /// / R` on a cylinder of axis `a` for the chord's unit direction `e` (Euler's formula), signed
    /// by the normals' orientation.
    pub(crate) fn chord_curvature(&self, i: usize, j: usize) -> f64 {
        let along = self.axis.map_or(0.0, |axis| {
            axis.dot((self.points[j] - self.points[i]).normalize())
        });
        self.orientation * (1.0 - along * along) / self.radius
    }
}

/// How far `edge_curvature` of f32 inputs may be from the exact chord curvature `k` of the points
/// the inputs round: each input is off by up to `u` relative (its rounding), each difference
/// rounds once more, the dot product and the squared length by `gamma(3)` of their terms, the
/// quotient once:
/// `dN <= d(dn) |dp| + |dn| d(dp) + gamma(3) |dn| |dp|`, `dD <= 2 |dp| d(dp) + gamma(3) |dp|^2`,
/// `dk <= dN / D + |k| dD / D + u |k|`.
pub(crate) fn chord_error(p_i: Vec3, p_j: Vec3, n_i: Vec3, n_j: Vec3, k: f64) -> f64 {
    let (p_i, p_j, n_i, n_j) = (p_i.as_dvec3(), p_j.as_dvec3(), n_i.as_dvec3(), n_j.as_dvec3());
    let (dp, dn) = ((p_j - p_i).length(), (n_j - n_i).length());
    let dp_error = U * (p_i.length() + p_j.length() + dp);
    let dn_error = U * (n_i.length() + n_j.length() + dn);
    let numerator = dn_error * dp + dn * dp_error + gamma(3) * dn * dp;
    let denominator = 2.0 * dp * dp_error + gamma(3) * dp * dp;
    (numerator + k.abs() * denominator) / (dp * dp) + U * k.abs()
}

/// Each component's interval holds both the exact value and its f32 rounding.
pub(crate) fn enclosing(v: DVec3) -> Interval3 {
    IntervalVec([v.x, v.y, v.z].map(|x| Interval::exact64(x).hull(Interval::exact(x as f32))))
}

/// The shape frame `(u, v)` of exact corners, as `triangle_shape_operator` defines it.
pub(crate) fn exact_frame(p: [DVec3; 3]) -> (DVec3, DVec3) {
    let u = (p[1] - p[0]).normalize();
    let face = u.cross((p[2] - p[0]).normalize()).normalize();
    (u, face.cross(u))
}

/// The shape operator of a sphere or cylinder as a 3 x 3 map `dn = S dp`: `I / R` on a sphere,
/// `(I - a aᵀ) / R` on a cylinder of axis `a`, times the normals' orientation.
pub(crate) fn linear_shape(curved: &Curved) -> DMat3 {
    let axis = curved.axis.unwrap_or(DVec3::ZERO);
    let across = DMat3::IDENTITY - DMat3::from_cols(axis * axis.x, axis * axis.y, axis * axis.z);
    across * (curved.orientation / curved.radius)
}

/// `(e, f, g) = (uᵀ S u, uᵀ S v, vᵀ S v)`, the exact shape operator in the frame `(u, v)`.
pub(crate) fn exact_shape_operator(curved: &Curved) -> [f64; 3] {
    let p = [0, 1, 2].map(|i| curved.points[i]);
    let (u, v) = exact_frame(p);
    let s = linear_shape(curved);
    [u.dot(s * u), u.dot(s * v), v.dot(s * v)]
}

/// The rounded corners of a drawn surface, or `None` where the fit is ill-conditioned.
pub(crate) fn conditioned_corners(curved: &Curved) -> Option<[Vec3; 3]> {
    let p = [0, 1, 2].map(|i| curved.points[i].as_vec3());
    shape_well_conditioned(p).then_some(p)
}

/// The component of a cylinder's axis in the plane of the triangle's exact corners (zero on a
/// sphere), and the plane's unit normal.
pub(crate) fn axis_in_plane(curved: &Curved) -> (DVec3, DVec3) {
    let (u, v) = exact_frame([0, 1, 2].map(|i| curved.points[i]));
    let face = u.cross(v);
    let axis = curved.axis.unwrap_or(DVec3::ZERO);
    (axis - face * axis.dot(face), face)
}
