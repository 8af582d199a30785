//! The proof of [`normal_spread_angle`](ray_footprint::ray_cone::normal_spread_angle): its record
//! and its reference.

use crate::degenerate::{mirror, value, INF};
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
use shader_proptest::tolerance::{atan_error, ulps};
use shader_proptest::{Args, Value};
use std::f32::consts::PI;

/// The record of `rf_normal_spread_angle`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "normal_spread_angle",
        |(dn_dx, dn_dy)| rc::normal_spread_angle(dn_dx, dn_dy),
        || (small_vec3(), small_vec3()).boxed(),
    )
    // sqrt of a 6-term sum (3 ULP of the sum -> 1.5 relative, sqrt ~4.5, mirror 1): 9 ULP
    // on the length, halved and propagated through atan, doubled; plus atan's 4096 ULP.
    .bound(|&(dn_dx, dn_dy), _, _| {
        let length = rc::normal_spread_angle_small(dn_dx, dn_dy);
        2.0 * atan_error(0.5 * length, ulps(9.0, 0.5 * length))
    })
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
    .fuzz(|d| (d.vec3(), d.vec3()))
    .range(0.0, PI, "normal spread angle")
    .degenerate(vec![
        flat_normal(),
        value(
            "one derivative zero, the other of length 2",
            "2 atan(1) = pi / 2",
            (Vec3::ZERO, Vec3::new(0.0, 0.0, -2.0)),
            vec![std::f32::consts::FRAC_PI_2],
        ),
        sub_normal_derivatives(),
        mirror(
            "infinity in",
            "CPU: pi (2 atan(inf))",
            (Vec3::new(INF, 0.0, 0.0), Vec3::ZERO),
            vec![std::f32::consts::PI],
        ),
    ])
}

/// The reference of `rf_normal_spread_angle`.
fn reference() -> Reference<(Vec3, Vec3), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the angle between the unit normals at the two ends of a pixel across which the normal changes by sqrt(|dn_dx|^2 + |dn_dy|^2) (RTG Eq. 31)",
        normal_derivatives,
        |&(dn_dx, dn_dy), normal_spread_angle| {
            let got = normal_spread_angle((dn_dx, dn_dy));
            let exact = normals_across_a_pixel(derivative_length(dn_dx, dn_dy));
            // The length: six products summed (gamma(6) of the square), a square root (u): 4 u;
            // atan: 2 ULP (4 u) and at most the argument's relative error; halving and doubling
            // are exact.
            Some(Deviation::within(f64::from(got), exact, gamma(8) * exact))
        },
    )
}
