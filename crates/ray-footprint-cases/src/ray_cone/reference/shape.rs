//! References of the shape operator and the normal curvature: spheres and cylinders, whose normals
//! change linearly along the surface so that the fit is exact for any triangle, and quadric
//! patches `z = (a x² + 2 b x y + c y²) / 2` (saddles among them), whose fit converges to the
//! shape operator at the origin as the triangle shrinks.
//!
//! Where the fit is exact, the check encloses twice: the function's interval enclosure evaluated on
//! inputs that hold both the exact f64 values and their f32 roundings contains the exact answer
//! and what the mirror (or a shader) computes from the rounded inputs, so the two are within its
//! width of each other.

use super::super::enclosure;
use super::propagation::Curved;
use crate::ray_cone::{
    IsotropicCurvatureArgs, NormalCurvatureArgs, PrincipalCurvaturesArgs, PrincipalDirectionArgs,
    ShapeOperatorArgs,
};
use crate::reference::{Deviation, Kind, Reference};
use glam::{DMat3, DVec3, Vec2, Vec3};
use proptest::prelude::*;
use shader_proptest::interval::{Interval, Interval3, IntervalVec};

/// Each component's interval holds both the exact value and its f32 rounding.
fn enclosing(v: DVec3) -> Interval3 {
    IntervalVec([v.x, v.y, v.z].map(|x| Interval::exact64(x).hull(Interval::exact(x as f32))))
}

/// The shape frame `(u, v)` of exact corners, as `triangle_shape_operator` defines it.
fn exact_frame(p: [DVec3; 3]) -> (DVec3, DVec3) {
    let u = (p[1] - p[0]).normalize();
    let face = u.cross((p[2] - p[0]).normalize()).normalize();
    (u, face.cross(u))
}

/// The shape operator of a sphere or cylinder as a 3 x 3 map `dn = S dp`: `I / R` on a sphere,
/// `(I - a aᵀ) / R` on a cylinder of axis `a`, times the normals' orientation.
fn linear_shape(curved: &Curved) -> DMat3 {
    let axis = curved.axis.unwrap_or(DVec3::ZERO);
    let across = DMat3::IDENTITY - DMat3::from_cols(axis * axis.x, axis * axis.y, axis * axis.z);
    across * (curved.orientation / curved.radius)
}

/// `(e, f, g) = (uᵀ S u, uᵀ S v, vᵀ S v)`, the exact shape operator in the frame `(u, v)`.
fn exact_shape_operator(curved: &Curved) -> [f64; 3] {
    let p = [0, 1, 2].map(|i| curved.points[i]);
    let (u, v) = exact_frame(p);
    let s = linear_shape(curved);
    [u.dot(s * u), u.dot(s * v), v.dot(s * v)]
}

/// The rounded corners of a drawn surface, or `None` where the fit is ill-conditioned.
fn conditioned_corners(curved: &Curved) -> Option<[Vec3; 3]> {
    let p = [0, 1, 2].map(|i| curved.points[i].as_vec3());
    enclosure::shape_well_conditioned(p).then_some(p)
}

/// `rf_triangle_shape_operator`.
pub(in crate::ray_cone) fn shape_operator_linear_normals() -> Reference<ShapeOperatorArgs, Vec3> {
    Reference::new(
        Kind::ExactGeometry,
        "triangles inscribed in spheres and cylinders with exact vertex normals (outward or inward): II = I / R on a sphere, (I - a a^T) / R on a cylinder of axis a, in the triangle's frame (Rusinkiewicz 2004 Sec. 3: the fit is exact where normals change linearly)",
        || Curved::strategy(3),
        |curved, triangle_shape_operator| {
            let p = conditioned_corners(curved)?;
            let n = [0, 1, 2].map(|i| curved.normals[i].as_vec3());
            let got = triangle_shape_operator((p[0], p[1], p[2], n[0], n[1], n[2]));
            let widths = enclosure::triangle_shape_operator(
                [0, 1, 2].map(|i| enclosing(curved.points[i])),
                [0, 1, 2].map(|i| enclosing(curved.normals[i])),
            );
            let expected = exact_shape_operator(curved);
            let deviations = (0..3).map(|i| {
                Deviation::within(f64::from(got[i]), expected[i], f64::from(widths.0[i].tolerance()))
            });
            Some(Deviation::worst(deviations))
        },
    )
}

/// `rf_normal_curvature`.
pub(in crate::ray_cone) fn normal_curvature_euler() -> Reference<NormalCurvatureArgs, f32> {
    Reference::new(
        Kind::ClosedForm,
        "triangles of spheres and cylinders with their exact shape operator: Euler's formula in 3-D, t^T S t for t the direction's unit projection into the triangle's plane (1 / R on a sphere, (1 - (a . t)^2) / R on a cylinder)",
        || (Curved::strategy(3), crate::exact::unit()).boxed(),
        |(curved, direction), normal_curvature| {
            let p = conditioned_corners(curved)?;
            let [e, f, g] = exact_shape_operator(curved);
            let shape = DVec3::new(e, f, g);
            let d = direction.as_vec3();
            if !enclosure::projection_well_conditioned(p, d) {
                return None;
            }
            let got = normal_curvature((p[0], p[1], p[2], shape.as_vec3(), d));
            let exact = [0, 1, 2].map(|i| curved.points[i]);
            let (u, v) = exact_frame(exact);
            let d = d.as_dvec3();
            let in_plane = u * d.dot(u) + v * d.dot(v);
            let t = in_plane.normalize();
            let euler = t.dot(linear_shape(curved) * t);
            // The function's MIN_COS^2 terms move it from Euler's value by
            // MIN_COS^2 (mean - k) / (|d_t|^2 + MIN_COS^2), d the unit direction.
            let weight = f64::from(ray_footprint::ray_cone::MIN_COS).powi(2);
            let offset = weight * (0.5 * (e + g) - euler) / (in_plane.length_squared() / d.length_squared() + weight);
            let width = enclosure::normal_curvature(
                exact.map(enclosing),
                enclosing(shape),
                shader_proptest::interval::interval3(d.as_vec3()),
            )
            .tolerance();
            Some(Deviation::within(f64::from(got), euler, f64::from(width) + offset.abs()))
        },
    )
}

/// The component of a cylinder's axis in the plane of the triangle's exact corners (zero on a
/// sphere), and the plane's unit normal.
fn axis_in_plane(curved: &Curved) -> (DVec3, DVec3) {
    let (u, v) = exact_frame([0, 1, 2].map(|i| curved.points[i]));
    let face = u.cross(v);
    let axis = curved.axis.unwrap_or(DVec3::ZERO);
    (axis - face * axis.dot(face), face)
}

/// `rf_principal_curvatures`.
pub(in crate::ray_cone) fn principal_curvatures_euler() -> Reference<PrincipalCurvaturesArgs, Vec2> {
    Reference::new(
        Kind::ClosedForm,
        "the exact shape operators of triangles of spheres and cylinders: the extremes of the normal curvature over the triangle's plane (Euler's theorem), 1 / R twice on a sphere, 1 / R and (1 - |a_t|^2) / R on a cylinder whose axis has the component a_t in the plane, times the normals' orientation, the greater first",
        || Curved::strategy(3),
        |curved, principal_curvatures| {
            conditioned_corners(curved)?;
            let [e, f, g] = exact_shape_operator(curved);
            let shape = DVec3::new(e, f, g);
            let got = principal_curvatures((shape.as_vec3(),));
            let (in_plane, _) = axis_in_plane(curved);
            let extremes = [1.0, 1.0 - in_plane.length_squared()].map(|k| k * curved.orientation / curved.radius);
            let expected = [extremes[0].max(extremes[1]), extremes[0].min(extremes[1])];
            let widths = enclosure::principal_curvatures(enclosing(shape));
            let deviations = (0..2).map(|i| {
                Deviation::within(f64::from(got[i]), expected[i], f64::from(widths.0[i].tolerance()))
            });
            Some(Deviation::worst(deviations))
        },
    )
}

/// `rf_principal_direction`.
pub(in crate::ray_cone) fn principal_direction_cylinder() -> Reference<PrincipalDirectionArgs, Vec3> {
    Reference::new(
        Kind::ClosedForm,
        "triangles of cylinders with their exact shape operator: the greater normal curvature lies across the axis (the plane's normal crossed with a_t, the axis's component in the plane) for outward normals, along a_t for inward ones; compared as an axis (either sign)",
        || Curved::strategy(3),
        |curved, principal_direction| {
            curved.axis?;
            let p = conditioned_corners(curved)?;
            let [e, f, g] = exact_shape_operator(curved);
            let shape = DVec3::new(e, f, g);
            if !enclosure::direction_well_conditioned(p, shape.as_vec3()) {
                return None;
            }
            let got = principal_direction((p[0], p[1], p[2], shape.as_vec3())).as_dvec3();
            let (in_plane, face) = axis_in_plane(curved);
            let axis = if curved.orientation > 0.0 { face.cross(in_plane) } else { in_plane }.normalize();
            let expected = if got.dot(axis) < 0.0 { -axis } else { axis };
            let widths = enclosure::principal_direction(
                [0, 1, 2].map(|i| enclosing(curved.points[i])),
                enclosing(shape),
            );
            let deviations = (0..3).map(|i| {
                Deviation::within(got[i], expected[i], f64::from(widths[i].tolerance()))
            });
            Some(Deviation::worst(deviations))
        },
    )
}

/// Directions the normal curvature is sampled along by `isotropic_curvature_directions`: every
/// tenth of a degree of a half turn (both principal directions among them).
const CURVATURE_DIRECTIONS: usize = 1800;

/// `rf_isotropic_curvature`.
pub(in crate::ray_cone) fn isotropic_curvature_directions() -> Reference<IsotropicCurvatureArgs, f32> {
    Reference::new(
        Kind::ClosedForm,
        "the normal curvature k1 cos^2 + k2 sin^2 (Euler's formula) sampled over 1,800 directions in f64: the sampled value of least magnitude when every sample has one sign, 0 when the samples change sign",
        || (-10.0f64..10.0, -10.0f64..10.0).boxed(),
        |&(k1, k2), isotropic_curvature| {
            let principal = Vec2::new(k1 as f32, k2 as f32);
            let got = isotropic_curvature((principal,));
            let samples: Vec<f64> = (0..CURVATURE_DIRECTIONS)
                .map(|i| {
                    let angle = std::f64::consts::PI * i as f64 / CURVATURE_DIRECTIONS as f64;
                    let (sin, cos) = angle.sin_cos();
                    f64::from(principal.x) * cos * cos + f64::from(principal.y) * sin * sin
                })
                .collect();
            let one_sign = samples.iter().all(|&k| k > 0.0) || samples.iter().all(|&k| k < 0.0);
            let least = samples.iter().copied().fold(f64::INFINITY, |least, k| {
                if k.abs() < least.abs() {
                    k
                } else {
                    least
                }
            });
            let expected = if one_sign { least } else { 0.0 };
            // The samples along the principal directions are the inputs within f64 rounding.
            let scale = f64::from(principal.abs().max_element());
            Some(Deviation::within(f64::from(got), expected, 1.0e-12 * scale))
        },
    )
}

/// A quadric patch `z = (a x² + 2 b x y + c y²) / 2` and a triangle around its origin: the
/// coefficients `(a, b, c)` and the corners' directions and distances from the origin (before the
/// triangle is scaled by `h`).
#[derive(Clone, Debug)]
struct Quadric {
    coefficients: [f64; 3],
    corners: [(f64, f64); 3],
}

/// The scales the fit is evaluated at, each a quarter of the one before.
const QUADRIC_SCALES: [f64; 2] = [1.0 / 8.0, 1.0 / 32.0];

/// Observed order of convergence the fit must reach between the two scales: its error shrinks
/// by at least `4^ORDER`. The fit is second order at the origin of a quadric (the patch is even in
/// `(x, y)`, so its shape operator changes only at second order, and the normals' tangential
/// change is linear up to third order), so its error shrinks by 16; a first-order or inconsistent
/// estimate shrinks by 4 or less.
const QUADRIC_ORDER: f64 = 1.5;

impl Quadric {
    fn strategy() -> BoxedStrategy<Quadric> {
        let coefficient = -2.0f64..2.0;
        let corner = (0.5f64..1.0, 0.0f64..std::f64::consts::PI / 3.0);
        (
            (coefficient.clone(), coefficient.clone(), coefficient),
            [corner.clone(), corner.clone(), corner],
        )
            .prop_map(|((a, b, c), corners)| Quadric {
                coefficients: [a, b, c],
                corners: [0, 1, 2].map(|i| {
                    let (distance, turn) = corners[i];
                    // One corner in the first half of each third of the circle: counter-clockwise,
                    // the corners between 60 and 180 degrees apart seen from the origin, so the
                    // triangle holds the origin and is never a sliver.
                    let angle = turn + std::f64::consts::TAU * i as f64 / 3.0;
                    (distance * angle.cos(), distance * angle.sin())
                }),
            })
            .boxed()
    }

    /// The point of the patch over `(x, y)` and its unit normal (on the `+z` side).
    fn point_and_normal(&self, x: f64, y: f64) -> (DVec3, DVec3) {
        let [a, b, c] = self.coefficients;
        let z = 0.5 * (a * x * x + 2.0 * b * x * y + c * y * y);
        let slope = (a * x + b * y, b * x + c * y);
        (
            DVec3::new(x, y, z),
            DVec3::new(-slope.0, -slope.1, 1.0).normalize(),
        )
    }

    /// The exact normal curvature at the origin along the unit horizontal `(cos, sin)`: the
    /// normals `(-(a x + b y), -(b x + c y), 1)` turn by `-H t` per unit step, so `k = -tᵀ H t`.
    fn curvature(&self, angle: f64) -> f64 {
        let [a, b, c] = self.coefficients;
        let (s, c_) = angle.sin_cos();
        -(a * c_ * c_ + 2.0 * b * c_ * s + c * s * s)
    }

    /// The largest error of the fitted normal curvature along three horizontal directions (which
    /// fix a quadratic form) at scale `h`, and the f32 rounding it may hold.
    fn error(&self, h: f64, fit: impl Fn(ShapeOperatorArgs) -> Vec3) -> (f64, f64) {
        let samples = self.corners.map(|(x, y)| self.point_and_normal(h * x, h * y));
        let p = samples.map(|(p, _)| p.as_vec3());
        let n = samples.map(|(_, n)| n.as_vec3());
        let ii = fit((p[0], p[1], p[2], n[0], n[1], n[2])).as_dvec3();
        let (u, v) = exact_frame(p.map(Vec3::as_dvec3));
        let error = [0.0, 1.0, 2.0]
            .map(|j| j * std::f64::consts::PI / 3.0)
            .iter()
            .map(|&angle| {
                let (sin, cos) = f64::sin_cos(angle);
                let t = DVec3::new(cos, sin, 0.0);
                let (a, b) = (t.dot(u), t.dot(v));
                let fitted = (ii.x * a * a + 2.0 * ii.y * a * b + ii.z * b * b) / (a * a + b * b);
                (fitted - self.curvature(angle)).abs()
            })
            .fold(0.0, f64::max);
        // The normals' f32 rounding (2^-24 of each component) over edges of about h.
        (error, 8.0 * crate::reference::U / h)
    }
}

/// `rf_triangle_shape_operator`.
pub(in crate::ray_cone) fn shape_operator_quadric() -> Reference<ShapeOperatorArgs, Vec3> {
    Reference::new(
        Kind::ExactGeometry,
        "triangles around the origin of quadric patches z = (a x^2 + 2 b x y + c y^2) / 2 (saddles among them) with exact normals, at scales 1/8 and 1/32: the fitted normal curvature along three directions converges to -t^T H t at order >= 1.5 (second order expected)",
        Quadric::strategy,
        |quadric, triangle_shape_operator| {
            let [coarse, fine] = QUADRIC_SCALES.map(|h| quadric.error(h, triangle_shape_operator));
            // Only where the coarse error stands far above the fine scale's rounding does the ratio
            // measure the fit rather than rounding.
            if coarse.0 < 1.0e3 * fine.1 {
                return None;
            }
            let shrink = QUADRIC_SCALES[0] / QUADRIC_SCALES[1];
            let allowed = coarse.0 / shrink.powf(QUADRIC_ORDER) + fine.1;
            Some(Deviation::new(fine.0, allowed))
        },
    )
}
