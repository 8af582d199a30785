//! The plane of incidence that the references of reflections and refractions trace rays in.
//!
//! In the plane of incidence a surface passes through the origin with its normal `+y` there, and
//! every ray comes from `+y`. A cone's boundary ray on side `sigma` (+1 or -1) crosses the line
//! through the hit across the central ray `sigma * width_at_hit / 2` from it and is turned by
//! `sigma * spread / 2`; after the surface, each boundary ray is measured across the scattered
//! central ray: its offset on the line through the hit and its angle.

use crate::exact::{derivative, Derivative};
use glam::DVec2;

/// `v` turned counter-clockwise by `angle`.
pub(crate) fn rotate(v: DVec2, angle: f64) -> DVec2 {
    let (sin, cos) = angle.sin_cos();
    DVec2::new(v.x * cos - v.y * sin, v.x * sin + v.y * cos)
}

/// The 2-D cross product `a.x b.y - a.y b.x`.
fn cross(a: DVec2, b: DVec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The mirror image of the direction `d` at a surface with unit normal `n`.
pub(crate) fn reflect(d: DVec2, n: DVec2) -> DVec2 {
    d - n * (2.0 * d.dot(n))
}

/// Snell's law for a unit direction `d` meeting a surface with unit normal `n` (facing the ray),
/// `eta = n_incident / n_transmitted`; `None` on total internal reflection.
pub(crate) fn snell(d: DVec2, n: DVec2, eta: f64) -> Option<DVec2> {
    let cos_i = -d.dot(n);
    let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    (k >= 0.0).then(|| d * eta + n * (eta * cos_i - k.sqrt()))
}

/// A surface in the plane of incidence through the origin, normal `+y` there: the line `y = 0`
/// (`curvature` 0) or a circle of radius `1 / |curvature|`, convex towards `+y` (where the rays
/// come from) when `curvature > 0`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Surface {
    pub(crate) curvature: f64,
}

impl Surface {
    /// Where the ray `start + s d` (`s > 0`) meets the surface nearest to the origin, and the unit
    /// normal there on the `+y` side.
    fn hit(self, start: DVec2, d: DVec2) -> Option<(DVec2, DVec2)> {
        if self.curvature == 0.0 {
            let s = -start.y / d.y;
            return (s > 0.0).then(|| (start + d * s, DVec2::Y));
        }
        // The circle's centre is (0, -r) with r = 1 / curvature (signed); with o = start - centre,
        // |o + s d|^2 = r^2 is s^2 + 2 b s + c = 0, c = |o|^2 - r^2 written without cancellation.
        let r = 1.0 / self.curvature;
        let centre = DVec2::new(0.0, -r);
        let b = (start - centre).dot(d);
        let c = start.x * start.x + start.y * (start.y + 2.0 * r);
        let point = quadratic_roots(b, c)?
            .into_iter()
            .filter(|&s| s > 0.0 && s.is_finite())
            .map(|s| start + d * s)
            .min_by(|a, b| a.length().total_cmp(&b.length()))?;
        Some((point, (point - centre) / r))
    }
}

/// The two roots of `s^2 + 2 b s + c = 0`, `q = -b - sign(b) sqrt(b^2 - c)` and `c / q`, each
/// without cancellation; `None` where they are not real.
pub(crate) fn quadratic_roots(b: f64, c: f64) -> Option<[f64; 2]> {
    let discriminant = b * b - c;
    if discriminant < 0.0 {
        return None;
    }
    let q = -b - b.signum() * discriminant.sqrt();
    Some([q, c / q])
}

/// A cone after a surface, measured across its scattered central ray through the hit.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Scattered {
    /// Offset of the upper boundary ray minus that of the lower one, on the line through the hit.
    pub(crate) width: f64,
    /// Angle of the upper boundary ray minus that of the lower one.
    pub(crate) spread: f64,
    /// Angle by which the normal turns from the lower boundary's hit to the upper one's, positive
    /// where the normals spread apart.
    pub(crate) normal_spread: f64,
    /// Smallest cosine at which a boundary ray meets the surface (from the ray's side).
    pub(crate) min_landing_cos: f64,
    /// Smallest `|cos|` between a scattered boundary ray and the normal at its hit.
    pub(crate) min_leaving_cos: f64,
}

/// One boundary ray after the surface: offset and angle across the scattered central ray, normal
/// at its hit, landing and leaving `|cos|`.
struct Boundary {
    offset: f64,
    angle: f64,
    normal: DVec2,
    landing_cos: f64,
    leaving_cos: f64,
}

/// The cone `(width, spread)` whose central ray `d` (unit, `d.y < 0`) meets `surface` at the origin
/// after `t`, each boundary ray traced to the surface exactly and scattered by `scatter`, then
/// measured across the central ray scattered at the origin, `across` turning with it as `turn`
/// says ([`mirrored`] for a reflection, [`rotated`] for a refraction). `scatter` gives a ray's
/// direction after the surface from its incoming one and the unit normal at its hit, or `None`
/// where it does not leave (total internal reflection of a refracted ray).
pub(crate) fn scatter_cone(
    surface: Surface,
    d: DVec2,
    t: f64,
    (width, spread): (f64, f64),
    scatter: impl Fn(DVec2, DVec2) -> Option<DVec2>,
    turn: fn(DVec2, DVec2) -> DVec2,
) -> Option<Scattered> {
    let across = rotate(d, std::f64::consts::FRAC_PI_2);
    let central = scatter(d, DVec2::Y)?;
    let across_out = turn(across, central);
    let boundary = |side: f64| {
        let direction = rotate(d, side * 0.5 * spread);
        // Where the boundary ray crosses the line through the hit across d, having started
        // side * width / 2 across the central ray t before the hit, turned by side * spread / 2;
        // traced from far enough back to lie above the surface.
        let crossing = across * (side * 0.5 * width + t * (side * 0.5 * spread).tan());
        let back = 2.0 * (crossing.length() + width.abs()) / direction.y.abs() + f64::MIN_POSITIVE;
        let (point, normal) = surface.hit(crossing - direction * back, direction)?;
        // A boundary ray turned away from the surface, or meeting it from the other side, does
        // not belong to the cone's hit.
        let landing_cos = -direction.dot(normal);
        if landing_cos <= 0.0 {
            return None;
        }
        let leaving = scatter(direction, normal)?;
        let reach = -point.dot(central) / leaving.dot(central);
        Some(Boundary {
            offset: (point + leaving * reach).dot(across_out),
            angle: leaving.dot(across_out).atan2(leaving.dot(central)),
            normal,
            landing_cos,
            leaving_cos: leaving.dot(normal).abs(),
        })
    };
    let (upper, lower) = (boundary(1.0)?, boundary(-1.0)?);
    Some(Scattered {
        width: upper.offset - lower.offset,
        spread: upper.angle - lower.angle,
        normal_spread: -cross(lower.normal, upper.normal).atan2(lower.normal.dot(upper.normal)),
        min_landing_cos: upper.landing_cos.min(lower.landing_cos),
        min_leaving_cos: upper.leaving_cos.min(lower.leaving_cos),
    })
}

/// The mirror image of `across` at the surface `+y`: a reflected cone's sides keep their order
/// along the mirror image of the incoming `across`.
pub(crate) fn mirrored(across: DVec2, _central: DVec2) -> DVec2 {
    DVec2::new(across.x, -across.y)
}

/// `across` of a refracted cone: the refracted central ray turned by a quarter turn, as the
/// incoming `across` is the incoming one (a refraction keeps the orientation).
pub(crate) fn rotated(_across: DVec2, central: DVec2) -> DVec2 {
    rotate(central, std::f64::consts::FRAC_PI_2)
}

/// The reflected cone's first order in its size: central differences of the cone `(h w, h s)`
/// scattered by `surface` (`h -> 0`), as `(width, spread)`, with step `step`.
pub(crate) fn reflected_first_order(
    surface: Surface,
    d: DVec2,
    t: f64,
    cone: (f64, f64),
    step: f64,
) -> Derivative<DVec2> {
    let reflected = |h: f64| {
        scatter_cone(
            surface,
            d,
            t,
            (h * cone.0, h * cone.1),
            |d, n| Some(reflect(d, n)),
            mirrored,
        )
        .map_or(DVec2::NAN, |s| DVec2::new(s.width, s.spread))
    };
    derivative(reflected, step, 1.0)
}

/// A step `h` that keeps the scaled cone `h * cone` at the hit within 1e-6 of a point: its
/// spread, its width (`|width| + |spread| t`) and that width's footprint over the radius of
/// curvature (`/ cos^2`) below 1e-6. Central differences are then exact to `O(1e-12)` relative.
pub(crate) fn step(cone: (f64, f64), t: f64, curvature: f64, cosine: f64) -> f64 {
    let size = cone.0.abs() + cone.1.abs() * t;
    let scale = cone
        .1
        .abs()
        .max(size)
        .max(size * curvature.abs() / (cosine * cosine));
    1.0e-6 / scale.max(1.0e-300)
}
