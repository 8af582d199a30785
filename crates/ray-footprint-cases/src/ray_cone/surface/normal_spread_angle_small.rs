//! The proof of [`normal_spread_angle_small`](ray_footprint::ray_cone::normal_spread_angle_small): its
//! record and its reference.

use crate::degenerate::value;
use crate::ray_cone::surface::shared::{
    derivative_length, flat_normal, normal_derivatives, normals_across_a_pixel, sub_normal_derivatives,
};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::small_vec3;
use crate::symmetry::Symmetry;
use glam::Vec3;
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use ray_footprint::shaders::Module;
use shader_proptest::tolerance::ulps;
use shader_proptest::{Args, Value};

/// The record of `rf_normal_spread_angle_small`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "normal_spread_angle_small",
        |(dn_dx, dn_dy)| rc::normal_spread_angle_small(dn_dx, dn_dy),
        || (small_vec3(), small_vec3()).boxed(),
    )
    // As above, without atan: 9 ULP.
    .bound(|_, _, expected| ulps(9.0, expected))
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "both normal derivatives turned: the same",
        |&(dn_dx, dn_dy): &(Vec3, Vec3), r| (r * dn_dx, r * dn_dy),
        |spread: f32, _| spread,
    ))
    .symmetry(Symmetry::exchange(
        "the image axes swapped (x and y derivatives exchanged): the same",
        |&(dn_dx, dn_dy): &(Vec3, Vec3)| (dn_dy, dn_dx),
        |spread: f32| spread,
    ))
    .symmetry(Symmetry::scale(
        "both normal derivatives scaled by s: the spread by s",
        |&(dn_dx, dn_dy): &(Vec3, Vec3), s| (dn_dx * s, dn_dy * s),
        |spread: f32, s| spread / s,
    ))
    .fuzz(|d| (d.vec3(), d.vec3()))
    .range(0.0, f32::MAX, "normal spread angle")
    .degenerate(vec![
        flat_normal(),
        value(
            "derivatives (3, 0, 0) and (0, -4, 0)",
            "5, the length of both together",
            (Vec3::new(3.0, 0.0, 0.0), Vec3::new(0.0, -4.0, 0.0)),
            vec![5.0],
        ),
        sub_normal_derivatives(),
    ])
}

/// The reference of `rf_normal_spread_angle_small`: the approximation's bound.
fn reference() -> Reference<(Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the small-angle form L against the angle between the normals at the pixel's ends, 2 atan(L / 2): within L^3 / 12 (RTG Eq. 32)",
        normal_derivatives,
        |&(dn_dx, dn_dy), normal_spread_angle_small| {
            let got = normal_spread_angle_small((dn_dx, dn_dy));
            let length = derivative_length(dn_dx, dn_dy);
            let exact = normals_across_a_pixel(length);
            // L - 2 atan(L / 2) <= L^3 / 12 (the alternating series of atan); the length's
            // rounding is 4 u.
            let bound = length.powi(3) / 12.0 + gamma(4) * length;
            Some(Deviation::within(f64::from(got), exact, bound))
        },
    )
}
