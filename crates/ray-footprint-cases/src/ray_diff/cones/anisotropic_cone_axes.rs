//! The proof of [`anisotropic_cone_axes`](ray_footprint::ray_diff::anisotropic_cone_axes): its
//! record, its enclosure and its references, the cut cylinder, the axes' lengths and directions and
//! the OptiX Toolkit.

use crate::degenerate::{grazing, same, value};
use crate::exact::{log_uniform, signed_log, towards, unit};
use crate::ray_diff::changes::*;
use crate::ray_diff::cones::shared::{
    cut_cylinder, ellipse, ellipse_assumptions, ellipse_error, frobenius, hull3, incidence,
    orthonormal_tangent, F32_CHAIN,
};
use crate::ray_diff::intervals::{self};
use crate::ray_diff::reference::widths;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference};
use crate::strategy::{normal_and_direction, scalar};
use glam::{DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, Derivatives3, DIFF_MIN_COS, DIFF_MIN_SINE};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval, Interval3};

/// Whether the ray is off the normal's line by more than twice `DIFF_MIN_SINE` in sine, where the
/// axes follow the plane of incidence rather than the fixed basis the function falls back on.
fn off_the_normal(normal: Vec3, direction: Vec3) -> bool {
    let across = normal.as_dvec3().cross(direction.as_dvec3());
    across.length_squared() > 4.0 * f64::from(ray_footprint::ray_diff::DIFF_MIN_SINE).powi(2)
}

/// The record of `rf_anisotropic_cone_axes`: the enclosure of the axes.
pub fn record() -> Record<(f32, Vec3, Vec3), Derivatives3> {
    let x = Vec3::X;
    let z = Vec3::Z;
    Record::new(
        Module::RayDiff,
        "anisotropic_cone_axes",
        |(width, n, d)| rd::anisotropic_cone_axes(width, n, d),
        || {
            (scalar(), normal_and_direction(), any::<bool>())
                .prop_map(|(width, (n, d), behind)| (width, if behind { -n } else { n }, d))
                .boxed()
        },
    )
    .enclosure(|&(width, n, d)| {
        let (major, minor) = enclosure(width, interval3(n), interval3(d));
        intervals::derivatives3(major, minor)
    })
    .reference(reference())
    .reference(anisotropic_cone_axes_growth())
    .reference(anisotropic_cone_axes_optix())
    .symmetry(
        Symmetry::rotation(
            "the normal and the ray turned, off the normal's line: the axes turned",
            |&(width, normal, direction): &(f32, Vec3, Vec3), r| (width, r * normal, r * direction),
            |axes: Derivatives3, r| turned3(axes, r.transpose()),
        )
        .within(|&(_, normal, direction)| off_the_normal(normal, direction)),
    )
    .symmetry(Symmetry::scale(
        "the width scaled by s: the axes by s",
        |&(width, normal, direction): &(f32, Vec3, Vec3), s| (width * s, normal, direction),
        |axes: Derivatives3, s| Derivatives3::new(axes.dx / s, axes.dy / s),
    ))
    .symmetry(
        Symmetry::exchange(
            "the ray reversed, off the normal's line: both axes reversed",
            |&(width, normal, direction): &(f32, Vec3, Vec3)| (width, normal, -direction),
            |axes: Derivatives3| Derivatives3::new(-axes.dx, -axes.dy),
        )
        .within(|&(_, normal, direction)| off_the_normal(normal, direction)),
    )
    .fuzz(|d| (d.scalar(), d.unit(), d.unit()))
    .degenerate(vec![
        value(
            "normal incidence (d = -n)",
            "a circle: |width| along Duff et al.'s tangent of n and along cross(n, tangent)",
            (0.5, z, -z),
            vec![0.5, 0.0, 0.0, 0.0, 0.5, 0.0],
        ),
        value(
            "ray in the surface plane",
            "major axis |width| / DIFF_MIN_COS along d, minor |width|",
            (0.5, z, x),
            vec![0.5 / DIFF_MIN_COS, 0.0, 0.0, 0.0, 0.5, 0.0],
        ),
        value(
            "grazing (|dot(n, d)| = 1e-6)",
            "as the ray in the surface plane (|cos| clamped to DIFF_MIN_COS)",
            (0.5, z, grazing()),
            vec![0.5 / DIFF_MIN_COS, 0.0, 0.0, 0.0, 0.5, 0.0],
        ),
        value("zero width", "zero axes", (0.0, z, -z), vec![0.0; 6]),
        same("negative width", "as |width|", (-0.5, z, -z), (0.5, z, -z)),
    ])
}

/// The major and the minor axis; the hull of both choices of the minor axis where `|cross(n, d)|^2`
/// is within rounding of `DIFF_MIN_SINE^2`.
pub(crate) fn enclosure(width: f32, normal: Interval3, direction: Interval3) -> (Interval3, Interval3) {
    let across = normal.cross(direction);
    let length2 = across.dot(across);
    let min2 = f64::from(DIFF_MIN_SINE * DIFF_MIN_SINE);
    let fixed = || normal.cross(orthonormal_tangent(normal));
    let measured = || {
        across
            / Interval {
                lo: length2.lo.max(min2),
                ..length2
            }
            .sqrt()
    };
    let minor = if length2.hi < min2 {
        fixed()
    } else if length2.lo >= min2 {
        measured()
    } else {
        hull3(fixed(), measured())
    };
    let size = Interval::exact(width.abs());
    let cosine = normal.dot(direction).abs().max_c(f64::from(DIFF_MIN_COS));
    (minor.cross(normal) * (size / cosine), minor * size)
}

/// The length of an enclosure's widths, per vector.
fn vector_errors(vectors: &[Interval3]) -> Vec<f64> {
    vectors
        .iter()
        .map(|v| widths(&v.components()).iter().map(|w| w * w).sum::<f64>().sqrt())
        .collect()
}

/// A reference of `rf_anisotropic_cone_axes`: the cut cylinder.
fn reference() -> Reference<(f32, Vec3, Vec3), Derivatives3> {
    Reference::new(
        Kind::ExactGeometry,
        "the cone as a cylinder of diameter |w| around d cut by the surface: two perpendicular diameters of its cross-section projected along d onto the plane span the same ellipse as the axes (JCGT 2021, with its errata's factor 2)",
        || (signed_log(-4.0, 2.0), unit()).prop_flat_map(|(w, n)| (Just(w), Just(n), incidence(n))).boxed(),
        |&(w, n, d), anisotropic_cone_axes| {
            let (w, n, d) = (w as f32, n.as_vec3(), d.as_vec3());
            let got = anisotropic_cone_axes((w, n, d));
            let axes = [got.dx.as_dvec3(), got.dy.as_dvec3()];
            let exact = ellipse(&cut_cylinder(f64::from(w).abs(), n.as_dvec3().normalize(), d.as_dvec3().normalize()));
            let (major, minor) = enclosure(w, interval3(n), interval3(d));
            let bound = ellipse_error(&axes, &vector_errors(&[major, minor]))
                + ellipse_assumptions(n, d, f64::from(w), exact)
                + 1.0e-12 * frobenius(exact);
            Some(Deviation::new(frobenius(ellipse(&axes) - exact), bound))
        },
    )
}

/// A reference of `rf_anisotropic_cone_axes`: the axes' lengths and directions.
fn anisotropic_cone_axes_growth() -> Reference<(f32, Vec3, Vec3), Derivatives3> {
    Reference::new(
        Kind::Identity,
        "the major axis is |w| / |cos| long and the minor one |w|, perpendicular to each other, to the normal and (the minor one) to the ray, from head-on down to |cos| = 1e-3 (JCGT 2021)",
        || (unit(), log_uniform(-3.0, 0.0), 0.0f64..6.3, log_uniform(-4.0, 2.0)).boxed(),
        |&(normal, cosine, angle, width), anisotropic_cone_axes| {
            let direction = towards(normal, cosine, angle);
            let width32 = width as f32;
            let a = anisotropic_cone_axes((width32, normal.as_vec3(), direction.as_vec3()));
            let (major, minor) = (a.dx.as_dvec3(), a.dy.as_dvec3());
            let w = f64::from(width32);
            let errors = [
                (major.length() * cosine - w).abs() / w,
                (minor.length() - w).abs() / w,
                major.dot(minor).abs() / (major.length() * minor.length()),
                major.dot(normal).abs() / major.length(),
                minor.dot(direction).abs() / minor.length(),
            ];
            // A chain of about 40 roundings, amplified by 1 / cos for the major axis.
            Some(Deviation::worst(errors.map(|e| Deviation::new(e, F32_CHAIN / cosine))))
        },
    )
}

/// The OptiX Toolkit's `projectToRayDifferentialsOnSurface`, in f64: `dPdx = normalize(d - dot(d, n)
/// n) * w / max(|dot(d, n)|, 1 / 16)` (a fixed tangent when `|dot| >= 0.999`), `dPdy =
/// normalize(cross(dPdx, n)) * w`.
fn optix_projection(width: f64, d: DVec3, n: DVec3) -> [DVec3; 2] {
    let cosine = d.dot(n);
    let dpdx = (d - n * cosine).normalize() * (width / cosine.abs().max(1.0 / 16.0));
    [dpdx, dpdx.cross(n).normalize() * width]
}

/// A reference of `rf_anisotropic_cone_axes`: the OptiX Toolkit.
fn anisotropic_cone_axes_optix() -> Reference<(f32, Vec3, Vec3), Derivatives3> {
    Reference::new(
        Kind::PeerOriginal,
        "the OptiX Toolkit's projectToRayDifferentialsOnSurface where it applies neither its anisotropy cap nor its fixed tangent (1/16 <= |cos| < 0.999): the same ellipse",
        || (unit(), 1.0f64 / 16.0..0.999, 0.0f64..6.3, log_uniform(-4.0, 2.0)).boxed(),
        |&(normal, cosine, angle, width), anisotropic_cone_axes| {
            let direction = towards(normal, cosine, angle);
            let ours = anisotropic_cone_axes((width as f32, normal.as_vec3(), direction.as_vec3()));
            let theirs = ellipse(&optix_projection(width, direction, normal));
            let error = frobenius(ellipse(&[ours.dx.as_dvec3(), ours.dy.as_dvec3()]) - theirs) / frobenius(theirs);
            // The f32 chain's error, squared by the ellipse matrix's major axis: 1 / cos^2.
            Some(Deviation::new(error, F32_CHAIN / (cosine * cosine)))
        },
    )
}
