//! The proof of [`surface_spread_angle`](ray_footprint::ray_cone::surface_spread_angle): its record
//! and its reference.

use crate::degenerate::value;
use crate::ray_cone::plane_of_incidence::{mirrored, reflect, rotate};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::angle;
use crate::symmetry::Symmetry;
use glam::DVec2;
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use ray_footprint::shaders::Module;
use shader_proptest::draw::uniform;
use shader_proptest::tolerance::ulps;
use shader_proptest::{Args, Value};

/// The record of `rf_surface_spread_angle`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "surface_spread_angle",
        |(phi, sign, k1, k2)| rc::surface_spread_angle(phi, sign, k1, k2),
        || {
            (
                angle(),
                prop::sample::select(vec![1.0f32, -1.0]),
                uniform(-4.0, 4.0),
                angle(),
            )
                .boxed()
        },
    )
    // Three products and a sum, possibly fused: 4 ULP of the larger term.
    .bound(|&(phi, sign, k1, k2), _, _| ulps(4.0, (2.0 * k1 * sign * phi).abs() + k2.abs()))
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the curvature sign and the normal spread both negated: the same",
        |&(phi, sign, k1, k2): &(f32, f32, f32, f32)| (-phi, -sign, k1, k2),
        |spread: f32| spread,
    ))
    .fuzz(|d| (d.angle(), d.scalar().signum(), d.scalar(), d.angle()))
    .degenerate(vec![
        value(
            "flat (phi = 0), RTG's k1 = 1, k2 = 0",
            "0",
            (0.0, 1.0, 1.0, 0.0),
            vec![0.0],
        ),
        value(
            "concave (s = -1), phi = 0.25",
            "-2 phi = -0.5: the cone narrows",
            (0.25, -1.0, 1.0, 0.0),
            vec![-0.5],
        ),
        value(
            "k1 = 0",
            "k2: the curvature is ignored",
            (0.25, 1.0, 0.0, 0.125),
            vec![0.125],
        ),
    ])
}

/// The reference of `rf_surface_spread_angle`.
fn reference() -> Reference<(f32, f32, f32, f32), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "parallel rays reflected at the two ends of a pixel whose normals are phi apart, spreading (s = 1) or converging (s = -1): the reflected rays are 2 s phi apart at any incidence; beta = k1 times that plus k2 (RTG Eq. 32-34)",
        || (0.0f64..1.4, any::<bool>(), -4.0f64..4.0, prop_oneof![Just(0.0f64), -0.5f64..0.5], 0.0f64..1.5).boxed(),
        |&(phi, concave, k1, k2, incidence), surface_spread_angle| {
            let (phi, sign, k1, k2) = (phi as f32, if concave { -1.0f32 } else { 1.0 }, k1 as f32, k2 as f32);
            let got = surface_spread_angle((phi, sign, k1, k2));
            let d = DVec2::new(incidence.sin(), -incidence.cos());
            let central = reflect(d, DVec2::Y);
            let across = mirrored(rotate(d, std::f64::consts::FRAC_PI_2), central);
            // At the upper end (along +across) a spreading surface's normal tilts towards it.
            let reflected_angle = |side: f64| {
                let normal = rotate(DVec2::Y, -side * f64::from(sign) * 0.5 * f64::from(phi));
                let r = reflect(d, normal);
                r.dot(across).atan2(r.dot(central))
            };
            let geometric = reflected_angle(1.0) - reflected_angle(-1.0);
            let expected = f64::from(k1) * geometric + f64::from(k2);
            // 2 k1 and the product with the sign are exact; the product with phi and the sum
            // round once each.
            let bound = gamma(2) * (2.0 * f64::from(k1 * phi).abs() + f64::from(k2).abs()) + 1.0e-14;
            Some(Deviation::within(f64::from(got), expected, bound))
        },
    )
}
