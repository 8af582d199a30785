//! The proof of [`triangle_uv_area2`](ray_footprint::ray_cone::triangle_uv_area2): its record and its
//! reference, the shoelace formula.

use crate::degenerate::value;
use crate::ray_cone::footprint::shared::uv_area2_error;
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::uv_triangle;
use crate::symmetry::Symmetry;
use glam::Vec2;
use glam::Vec2Swizzles;
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use ray_footprint::shaders::Module;
use shader_proptest::{Args, Value};

/// The record of `rf_triangle_uv_area2`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let unit_uv = (Vec2::ZERO, Vec2::X, Vec2::Y);
    let collinear_uv = (Vec2::ZERO, Vec2::splat(0.5), Vec2::ONE);
    Record::new(
        Module::RayCone,
        "triangle_uv_area2",
        |(uv0, uv1, uv2)| rc::triangle_uv_area2(uv0, uv1, uv2),
        || uv_triangle().prop_map(|uv| (uv[0], uv[1], uv[2])).boxed(),
    )
    .bound(|&(uv0, uv1, uv2), _, _| uv_area2_error([uv0, uv1, uv2]))
    .reference(reference())
    .symmetry(Symmetry::scale(
        "the UVs scaled by s: the area by s^2",
        |&(uv0, uv1, uv2): &(Vec2, Vec2, Vec2), s| (uv0 * s, uv1 * s, uv2 * s),
        |area: f32, s| area / (s * s),
    ))
    .symmetry(Symmetry::translation(
        "the UVs moved: the same",
        |&(uv0, uv1, uv2): &(Vec2, Vec2, Vec2), t| {
            (uv0 + t.truncate(), uv1 + t.truncate(), uv2 + t.truncate())
        },
        |area: f32, _| area,
    ))
    .symmetry(Symmetry::exchange(
        "the vertex order turned: the same",
        |&(uv0, uv1, uv2): &(Vec2, Vec2, Vec2)| (uv1, uv2, uv0),
        |area: f32| area,
    ))
    .symmetry(Symmetry::exchange(
        "u and v exchanged (a mirrored mapping): the same",
        |&(uv0, uv1, uv2): &(Vec2, Vec2, Vec2)| (uv0.yx(), uv1.yx(), uv2.yx()),
        |area: f32| area,
    ))
    .fuzz(|d| (d.vec2(), d.vec2(), d.vec2()))
    .range(0.0, f32::MAX, "area")
    .degenerate(vec![
        value("collinear UVs", "0", collinear_uv, vec![0.0]),
        value(
            "repeated vertex",
            "0",
            (Vec2::ZERO, Vec2::X, Vec2::ZERO),
            vec![0.0],
        ),
        value("unit right triangle", "1", unit_uv, vec![1.0]),
        value(
            "clockwise unit right triangle",
            "1 (the absolute value)",
            (Vec2::ZERO, Vec2::Y, Vec2::X),
            vec![1.0],
        ),
    ])
}

/// The reference of `rf_triangle_uv_area2`.
fn reference() -> Reference<(Vec2, Vec2, Vec2), f32> {
    Reference::new(
        Kind::ClosedForm,
        "the shoelace formula over the three corners in f64, |x0 (y1 - y2) + x1 (y2 - y0) + x2 (y0 - y1)|",
        uv_triangle,
        |&[a, b, c], triangle_uv_area2| {
            let got = triangle_uv_area2((a, b, c));
            let [a, b, c] = [a, b, c].map(Vec2::as_dvec2);
            let exact = (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y)).abs();
            // The edges round (2 u |g1| |g2|), the cross product by gamma(2) of its terms.
            let bound = gamma(4) * (b - a).length() * (c - a).length()
                + 8.0 * f64::EPSILON * (a.length() + b.length() + c.length()).powi(2);
            Some(Deviation::within(f64::from(got), exact, bound))
        },
    )
}
