//! The proof of [`texture_gradient`](ray_footprint::ray_cone::texture_gradient): its record and its
//! reference.

use crate::degenerate::value;
use crate::exact::signed_log;
use crate::record::Record;
use crate::reference::{Deviation, Kind, Reference, U};
use crate::special::Perturb;
use crate::strategy::scalar;
use crate::symmetry::Symmetry;
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use ray_footprint::shaders::Module;
use shader_proptest::draw::uniform;
use shader_proptest::{Args, Value};

/// The record of `rf_texture_gradient`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "texture_gradient",
        |(uv_footprint, scale)| rc::texture_gradient(uv_footprint, scale),
        || (scalar(), uniform(-1.0, 4.0)).boxed(),
    )
    // One correctly rounded product.
    .bound(|_, _, _| f32::MIN_POSITIVE)
    .reference(reference())
    .symmetry(Symmetry::scale(
        "the footprint scaled by s: the gradient by s",
        |&(footprint, scale): &(f32, f32), s| (footprint * s, scale),
        |gradient: f32, s| gradient / s,
    ))
    .symmetry(Symmetry::exchange(
        "the footprint negated: the same",
        |&(footprint, scale): &(f32, f32)| (-footprint, scale),
        |gradient: f32| gradient,
    ))
    .fuzz(|d| (d.scalar(), d.scalar()))
    .range(0.0, f32::MAX, "gradient")
    .degenerate(vec![
        value(
            "negative scale",
            "0 (scale clamped to >= 0)",
            (0.5, -2.0),
            vec![0.0],
        ),
        value("negative footprint", "|footprint| scale", (-0.5, 2.0), vec![1.0]),
        value("scale 0", "0 (samples mip 0)", (0.5, 0.0), vec![0.0]),
        value("zero footprint", "0", (0.0, 2.0), vec![0.0]),
    ])
}

/// The reference of `rf_texture_gradient`.
fn reference() -> Reference<(f32, f32), f32> {
    Reference::new(
        Kind::ClosedForm,
        "the diameter of the UV footprint circle, |footprint|, times max(tex_grad_scale, 0): mip 0 for a scale of 0 or below",
        || (signed_log(-6.0, 3.0), prop_oneof![-1.0f64..4.0, Just(0.0), Just(1.0)]).boxed(),
        |&(footprint, scale), texture_gradient| {
            let (footprint, scale) = (footprint as f32, scale as f32);
            let got = texture_gradient((footprint, scale));
            let expected = f64::from(footprint).abs() * f64::from(scale).max(0.0);
            Some(Deviation::within(f64::from(got), expected, U * expected))
        },
    )
}
