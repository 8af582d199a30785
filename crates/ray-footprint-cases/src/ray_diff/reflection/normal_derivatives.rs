//! The proof of [`normal_derivatives`](ray_footprint::ray_diff::normal_derivatives): its record,
//! its enclosure and its reference.

use crate::degenerate::value;
use crate::exact::{derivative, log_uniform, unit};
use crate::ray_diff::camera::normalized_derivative;
use crate::ray_diff::changes::*;
use crate::ray_diff::intervals;
use crate::ray_diff::reference::{components, listed, widths};
use crate::ray_diff::strategy::derivatives2;
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{unit_vec3, vec2_of};
use glam::{DVec2, Vec2, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives2, Derivatives3, DIFF_MIN_MAGNITUDE};
use ray_footprint::shaders::Module;
use shader_proptest::draw::uniform;
use shader_proptest::interval::{interval3, Interval};
use shader_proptest::{Args, Value};

/// The record of `rf_normal_derivatives`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let z = Vec3::Z;
    let g = Derivatives2::new(Vec2::X, Vec2::ZERO);
    Record::new(
        Module::RayDiff,
        "normal_derivatives",
        |(n0, n1, n2, uv, b)| rd::normal_derivatives(n0, n1, n2, uv, b),
        || {
            (
                (unit_vec3(), unit_vec3(), unit_vec3()),
                vec2_of(uniform(-1.0, 2.0), uniform(-1.0, 2.0)),
                derivatives2(),
            )
                .prop_map(|((n0, n1, n2), uv, b)| (n0, n1, n2, uv, b))
                .boxed()
        },
    )
    .enclosure(enclosure)
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "the normals turned: the derivatives turned",
        |&(n0, n1, n2, uv, b): &(Vec3, Vec3, Vec3, Vec2, Derivatives2), r| (r * n0, r * n1, r * n2, uv, b),
        |d: Derivatives3, r| turned3(d, r.transpose()),
    ))
    .symmetry(Symmetry::scale(
        "the normals scaled by s: the same (the normal is made unit)",
        |&(n0, n1, n2, uv, b): &(Vec3, Vec3, Vec3, Vec2, Derivatives2), s| (n0 * s, n1 * s, n2 * s, uv, b),
        |d: Derivatives3, _| d,
    ))
    .symmetry(Symmetry::exchange(
        "the image axes swapped: the derivatives exchanged",
        |&(n0, n1, n2, uv, b): &(Vec3, Vec3, Vec3, Vec2, Derivatives2)| (n0, n1, n2, uv, swapped2(b)),
        swapped3,
    ))
    .fuzz(|d| (d.unit(), d.unit(), d.unit(), d.vec2(), d.derivatives2()))
    .degenerate(vec![
        value(
            "interpolated normal of length 0 (opposite vertex normals)",
            "dn / sqrt(DIFF_MIN_MAGNITUDE)",
            (z, -z, z, Vec2::new(0.5, 0.0), g),
            vec![0.0, 0.0, -2.0 / DIFF_MIN_MAGNITUDE.sqrt(), 0.0, 0.0, 0.0],
        ),
        value(
            "equal vertex normals (flat)",
            "0",
            (z, z, z, Vec2::splat(0.25), Derivatives2::new(Vec2::X, Vec2::Y)),
            vec![0.0; 6],
        ),
        value(
            "zero barycentric differentials",
            "0",
            (z, x, y, Vec2::splat(0.25), Derivatives2::default()),
            vec![0.0; 6],
        ),
    ])
}

type NormalArgs = (Vec3, Vec3, Vec3, Vec2, Derivatives2);

/// `rf_normal_derivatives` in interval arithmetic, in the same order of operations.
fn enclosure(&(n0, n1, n2, uv, b): &NormalArgs) -> Vec<Interval> {
    let (n0, n1, n2) = (interval3(n0), interval3(n1), interval3(n2));
    let n = n0 * (Interval::c(1.0) - Interval::exact(uv.x) - Interval::exact(uv.y))
        + n1 * Interval::exact(uv.x)
        + n2 * Interval::exact(uv.y);
    let dn_dx = (n1 - n0) * Interval::exact(b.dx.x) + (n2 - n0) * Interval::exact(b.dx.y);
    let dn_dy = (n1 - n0) * Interval::exact(b.dy.x) + (n2 - n0) * Interval::exact(b.dy.y);
    intervals::derivatives3(
        normalized_derivative::enclosure(n, dn_dx),
        normalized_derivative::enclosure(n, dn_dy),
    )
}

/// The reference of `rf_normal_derivatives`.
fn reference() -> Reference<(Vec3, Vec3, Vec3, Vec2, Derivatives2), Derivatives3> {
    Reference::new(
        Kind::FiniteDifference,
        "f64 central differences of the unit normal interpolated from the vertex normals of a smooth surface along the barycentric path (u + h du, v + h dv) (Igehy)",
        || {
            let normal = || (unit(), 0.0f64..0.5).prop_map(|(v, tilt)| v * tilt);
            let change = || (0.0f64..6.3, log_uniform(-4.0, 0.0)).prop_map(|(a, l)| DVec2::from_angle(a) * l);
            (unit(), (normal(), normal(), normal()), (-0.2f64..1.2, -0.2f64..1.2), (change(), change())).boxed()
        },
        |&(n, (a, b, c), (u, v), (dx, dy)), normal_derivatives| {
            let [n0, n1, n2] = [a, b, c].map(|tilt| (n + tilt).normalize().as_vec3());
            let uv = Vec2::new(u as f32, v as f32);
            let changes = Derivatives2::new(dx.as_vec2(), dy.as_vec2());
            let args = (n0, n1, n2, uv, changes);
            let got = normal_derivatives(args);
            let [m0, m1, m2] = [n0, n1, n2].map(Vec3::as_dvec3);
            let at = |b: DVec2| ((1.0 - b.x - b.y) * m0 + b.x * m1 + b.y * m2).normalize();
            let along = |step: Vec2| derivative(|h| at(uv.as_dvec2() + step.as_dvec2() * h), 1.0e-4 / f64::from(step.length()), 2.0);
            let (ex, ey) = (along(changes.dx), along(changes.dy));
            let bounds = widths(&enclosure(&args));
            let error = ex.error.max(ey.error);
            Some(components(got, &listed(&[ex.value, ey.value], 0), |i| bounds[i] + error))
        },
    )
}
