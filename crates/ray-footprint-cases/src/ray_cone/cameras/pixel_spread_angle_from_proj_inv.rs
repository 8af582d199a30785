//! The proof of
//! [`pixel_spread_angle_from_proj_inv`](ray_footprint::ray_cone::pixel_spread_angle_from_proj_inv):
//! its record, its case strategy and its reference.

use crate::degenerate::{mirror, same, value, vulkan_inverse_projection, INF};
use crate::exact::{angle_between, log_uniform};
use crate::ray_cone::cameras::shared::camera;
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{perspective_proj_inv, pixels, scalar};
use crate::symmetry::Symmetry;
use glam::dcamera::rh::proj::{opengl, vulkan};
use glam::{DVec4, Mat4};
use proptest::prelude::*;
use ray_footprint::ray_cone as rc;
use ray_footprint::shaders::Module;
use shader_proptest::one_of;
use shader_proptest::tolerance::{atan_error, ulps};
use shader_proptest::{Args, Value};
use std::f32::consts::FRAC_PI_2;

/// The record of `rf_pixel_spread_angle_from_proj_inv`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let inverse_projection = vulkan_inverse_projection();
    Record::new(
        Module::RayCone,
        "pixel_spread_angle_from_proj_inv",
        |(inverse_projection, height)| rc::pixel_spread_angle_from_proj_inv(inverse_projection, height),
        || (proj_inv(), pixels()).boxed(),
    )
    // The ratio 2|m|/H has one division (2.5 ULP) and the mirror's rounding; then atan.
    .bound(|&(inverse_projection, height), _, _| {
        let ratio = 2.0 * inverse_projection.y_axis.y.abs() / height.max(1.0);
        atan_error(ratio, ulps(3.5, ratio))
    })
    .reference(reference())
    .symmetry(Symmetry::exchange(
        "the inverse projection's y axis negated (the image upside down): the same",
        |&(inverse_projection, image_height): &(Mat4, f32)| {
            let mut flipped = inverse_projection;
            flipped.y_axis = -flipped.y_axis;
            (flipped, image_height)
        },
        |spread: f32| spread,
    ))
    .fuzz(|d| (d.mat4(), d.scalar()))
    .range(0.0, FRAC_PI_2, "spread angle")
    .degenerate(vec![
        same(
            "zero viewport (H = 0)",
            "as H = 1",
            (inverse_projection, 0.0),
            (inverse_projection, 1.0),
        ),
        value("zero matrix", "0", (Mat4::ZERO, 1080.0), vec![0.0]),
        mirror(
            "infinity in (`proj_inv[1][1]`)",
            "CPU: pi / 2",
            (Mat4::from_diagonal(glam::Vec4::new(1.0, INF, 1.0, 1.0)), 1080.0),
            vec![std::f32::consts::FRAC_PI_2],
        ),
    ])
}

/// An inverse projection matrix of a perspective camera (y-flipped or not), or an arbitrary matrix.
fn proj_inv() -> BoxedStrategy<Mat4> {
    let arbitrary = prop::array::uniform16(scalar()).prop_map(|cols| Mat4::from_cols_array(&cols));
    one_of![3 => perspective_proj_inv(), 1 => arbitrary].boxed()
}

/// A perspective projection's inverse in f32 (OpenGL, Vulkan's y-flipped, or infinite with
/// reversed depth), computed in f64 and rounded entry by entry, and an image height.
fn inverse_projection() -> BoxedStrategy<(Mat4, f32)> {
    (
        0.05f64..3.0,
        0.2f64..5.0,
        log_uniform(-2.0, 1.0),
        0usize..3,
        camera(),
    )
        .prop_map(|(fov, aspect, near, kind, (_, height))| {
            let projection = match kind {
                0 => opengl::perspective(fov, aspect, near, near * 1000.0),
                1 => vulkan::perspective(fov, aspect, near, near * 1000.0),
                _ => vulkan::perspective_infinite_reverse(fov, aspect, near),
            };
            (projection.inverse().as_mat4(), height)
        })
        .boxed()
}

/// The reference of `rf_pixel_spread_angle_from_proj_inv`.
fn reference() -> Reference<(Mat4, f32), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the angle at the eye between the points that NDC (0, 0) and (0, 2 / H) unproject to through the matrix itself (f64, homogeneous division), for OpenGL, Vulkan (y-flipped) and infinite reversed-depth projections",
        inverse_projection,
        |&(proj_inv, height), from_proj_inv| {
            let got = from_proj_inv((proj_inv, height));
            let inverse = proj_inv.as_dmat4();
            let unproject = |ndc_y: f64| {
                let point = inverse * DVec4::new(0.0, ndc_y, 1.0, 1.0);
                point.truncate() / point.w
            };
            let exact = angle_between(unproject(0.0), unproject(2.0 / f64::from(height)));
            // The division by H (u) and atan (2 ULP, 4 u).
            Some(Deviation::within(f64::from(got), exact, gamma(5) * exact))
        },
    )
}
