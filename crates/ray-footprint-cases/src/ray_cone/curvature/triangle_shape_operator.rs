//! The proof of [`triangle_shape_operator`](ray_footprint::ray_cone::triangle_shape_operator): its
//! record, its enclosure and its references, spheres and cylinders (where the fit is exact) and
//! quadric patches (where it converges).

use crate::degenerate::{near, value, Row};
use crate::ray_cone::curvature::shared::{
    conditioned_corners, enclosing, exact_frame, exact_shape_operator, shape_determinant,
    shape_normal_equations, shape_well_conditioned, unit_corners, Curved,
};
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::strategy::{triangle, unit_vec3};
use crate::symmetry::Symmetry;
use glam::{DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MIN_MAGNITUDE, MIN_SQUARED_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval3, IntervalVec};

/// The arguments of `rf_triangle_shape_operator`: three corners, three normals.
pub type ShapeOperatorArgs = (Vec3, Vec3, Vec3, Vec3, Vec3, Vec3);

/// Why a record leaves a triangle out of its agreement and special-value checks.
const SLIVER: &str = "a sliver or a repeated vertex within rounding (the determinant of the normal \
     equations is not known to 2^-10), or every edge component below MIN_MAGNITUDE (1e-20): the fit may take \
     anything up to what the clamps allow";

/// The record of `rf_triangle_shape_operator`.
pub fn record() -> Record<ShapeOperatorArgs, Vec3> {
    let (p0, p1, p2) = unit_corners();
    let z = Vec3::Z;
    // Normals changing linearly along the triangle: n = z + S p, whose fit is S exactly.
    let linear = |s: fn(Vec3) -> Vec3| (p0, p1, p2, z + s(p0), z + s(p1), z + s(p2));
    Record::new(
        Module::RayCone,
        "triangle_shape_operator",
        |(p0, p1, p2, n0, n1, n2)| rc::triangle_shape_operator(p0, p1, p2, n0, n1, n2),
        || {
            (triangle(), (unit_vec3(), unit_vec3(), unit_vec3()))
                .prop_map(|(p, n)| (p[0], p[1], p[2], n.0, n.1, n.2))
                .boxed()
        },
    )
    .conditioned(SLIVER, |&(p0, p1, p2, ..)| shape_well_conditioned([p0, p1, p2]))
    .enclosure(|&(p0, p1, p2, n0, n1, n2)| {
        enclosure([p0, p1, p2].map(interval3), [n0, n1, n2].map(interval3)).components()
    })
    .reference(shape_operator_linear_normals())
    .reference(shape_operator_quadric())
    .symmetry(Symmetry::scale(
        "corners scaled by s: the shape operator by 1/s",
        |&(p0, p1, p2, n0, n1, n2), s| (p0 * s, p1 * s, p2 * s, n0, n1, n2),
        |shape_operator, s| shape_operator * s,
    ))
    .symmetry(Symmetry::rotation(
        "corners and normals turned: the same, in the triangle's own frame",
        |&(p0, p1, p2, n0, n1, n2), r| (r * p0, r * p1, r * p2, r * n0, r * n1, r * n2),
        |shape_operator, _| shape_operator,
    ))
    .symmetry(Symmetry::translation(
        "corners moved: the same",
        |&(p0, p1, p2, n0, n1, n2), t| (p0 + t, p1 + t, p2 + t, n0, n1, n2),
        |shape_operator, _| shape_operator,
    ))
    .symmetry(Symmetry::exchange(
        "normals flipped: the shape operator negated",
        |&(p0, p1, p2, n0, n1, n2)| (p0, p1, p2, -n0, -n1, -n2),
        |shape_operator| -shape_operator,
    ))
    .fuzz(|d| (d.vec3(), d.vec3(), d.vec3(), d.unit(), d.unit(), d.unit()))
    .degenerate(vec![
        value(
            "flat (equal vertex normals)",
            "(0, 0, 0)",
            (p0, p1, p2, z, z, z),
            vec![0.0; 3],
        ),
        value(
            "corners 0, x, y; normals z + p / 2 (a sphere of radius 2, linearised)",
            "(1/2, 0, 1/2)",
            linear(|p| p / 2.0),
            vec![0.5, 0.0, 0.5],
        ),
        value(
            "corners 0, x, y; normals z + (x, -y, 0) / 2 (a saddle, linearised)",
            "(1/2, 0, -1/2): opposite signs",
            linear(|p| Vec3::new(p.x, -p.y, 0.0) / 2.0),
            vec![0.5, 0.0, -0.5],
        ),
        value(
            "zero-area triangle (p2 = p0)",
            "(0, 0, 0): no second axis, so nothing to fit",
            (Vec3::ZERO, Vec3::X, Vec3::ZERO, z, Vec3::X, z),
            vec![0.0; 3],
        ),
        value(
            "collinear corners (p2 = 2 p1 - p0)",
            "(0, 0, 0)",
            (Vec3::ZERO, Vec3::X, 2.0 * Vec3::X, z, Vec3::X, Vec3::Y),
            vec![0.0; 3],
        ),
        value(
            "all three corners at one point",
            "(0, 0, 0)",
            (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, z, Vec3::X, Vec3::Y),
            vec![0.0; 3],
        ),
        small_sphere(
            "the unit sphere's triangle (1, 0, 0), (0, 1, 0), (0.6, 0, 0.8) times 1e-6, its normals kept",
            "(1e6, 0, 1e6) to 2^-20: a sphere of radius 1e-6",
            1.0e-6,
        ),
        small_sphere(
            "the same triangle times 1e-11",
            "(1e11, 0, 1e11) to 2^-20",
            1.0e-11,
        ),
        small_sphere(
            "the same triangle times 1e-16 (below the documented range)",
            "(1e16, 0, 1e16) to 2^-20",
            1.0e-16,
        ),
    ])
}

/// The row of the triangle (1, 0, 0), (0, 1, 0), (0.6, 0, 0.8) of the unit sphere with its corners
/// times `scale` and its normals kept: a sphere of radius `scale`, whose shape operator is
/// `(1, 0, 1) / scale` to the f32 rounding of the inputs (2^-20 of its largest component).
fn small_sphere(input: &'static str, output: &'static str, scale: f32) -> Row<ShapeOperatorArgs> {
    let corners = [Vec3::X, Vec3::Y, Vec3::new(0.6, 0.0, 0.8)];
    let [p0, p1, p2] = corners.map(|corner| corner * scale);
    near(
        input,
        output,
        (p0, p1, p2, corners[0], corners[1], corners[2]),
        vec![1.0 / scale, 0.0, 1.0 / scale],
        2f32.powi(-20),
    )
}

/// `rf_triangle_shape_operator` of corners `p` and normals `n` given as intervals (an f32
/// input is an exact interval; a reference's may hold an exact value and its rounding too).
pub(crate) fn enclosure(p: [Interval3; 3], n: [Interval3; 3]) -> Interval3 {
    let ([aa, bb, ab], r, extent) = shape_normal_equations(p, n);
    let [r0, r1, r2] = r.0;
    let ab2 = ab.abs() * ab.abs();
    let determinant = shape_determinant([aa, bb, ab]).max_c(f64::from(MIN_MAGNITUDE));
    let e = (bb - ab2) * r0 - bb * ab * r1 + ab2 * r2;
    let f = aa * bb * r1 - bb * ab * r0 - aa * ab * r2;
    let g = (aa - ab2) * r2 - aa * ab * r1 + ab2 * r0;
    IntervalVec([e, f, g]) / (determinant * extent).max_c(f64::from(MIN_SQUARED_MAGNITUDE))
}

/// A reference of `rf_triangle_shape_operator`.
fn shape_operator_linear_normals() -> Reference<ShapeOperatorArgs, Vec3> {
    Reference::new(
        Kind::ExactGeometry,
        "triangles inscribed in spheres and cylinders with exact vertex normals (outward or inward): II = I / R on a sphere, (I - a a^T) / R on a cylinder of axis a, in the triangle's frame (Rusinkiewicz 2004 Sec. 3: the fit is exact where normals change linearly)",
        || Curved::strategy(3),
        |curved, triangle_shape_operator| {
            let p = conditioned_corners(curved)?;
            let n = [0, 1, 2].map(|i| curved.normals[i].as_vec3());
            let got = triangle_shape_operator((p[0], p[1], p[2], n[0], n[1], n[2]));
            let widths = enclosure(
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

/// A reference of `rf_triangle_shape_operator`.
fn shape_operator_quadric() -> Reference<ShapeOperatorArgs, Vec3> {
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
