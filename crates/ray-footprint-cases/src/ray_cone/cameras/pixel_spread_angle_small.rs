//! The proof of [`pixel_spread_angle_small`](ray_footprint::ray_cone::pixel_spread_angle_small): its
//! record and its references.

use crate::degenerate::{mirror, same, INF, NAN};
use crate::ray_cone::cameras::shared::{camera, pixel_angle, pixel_height, tan_ratio_error};
use crate::record::Record;
use crate::reference::{gamma, Deviation, Kind, Reference};
use crate::special::Perturb;
use crate::strategy::{fov_y, pixels};
use crate::symmetry::Symmetry;
use glam::dcamera::rh::proj::opengl;
use glam::DVec4;
use proptest::prelude::*;
use ray_footprint::ray_cone::{self as rc, MAX_FOV_Y};
use ray_footprint::shaders::Module;
use shader_proptest::{Args, Value};

/// The record of `rf_pixel_spread_angle_small`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    Record::new(
        Module::RayCone,
        "pixel_spread_angle_small",
        |(fov, height)| rc::pixel_spread_angle_small(fov, height),
        || (fov_y(), pixels()).boxed(),
    )
    // tan's error (inherited from sin / cos) scaled by 2 / H.
    .bound(|&(fov, height), _, _| tan_ratio_error(fov, height))
    .reference(reference())
    .reference(pixel_spread_angle_small_approximation())
    .symmetry(Symmetry::exchange(
        "the image height (at least 1, as clamped) doubled: the spread halved",
        |&(fov_y, image_height): &(f32, f32)| (fov_y, 2.0 * image_height.max(1.0)),
        |spread: f32| 2.0 * spread,
    ))
    .fuzz(|d| (d.angle(), d.scalar()))
    .range(0.0, f32::MAX, "spread angle")
    .degenerate(vec![
        same("zero viewport (H = 0)", "as H = 1", (1.0, 0.0), (1.0, 1.0)),
        mirror(
            "NaN in (H)",
            "CPU: as H = 1 (Rust's `max` ignores NaN)",
            (1.0, NAN),
            vec![rc::pixel_spread_angle_small(1.0, 1.0)],
        ),
        mirror(
            "infinity in (fov_y = +inf)",
            "CPU: as fov_y = MAX_FOV_Y",
            (INF, 1080.0),
            vec![rc::pixel_spread_angle_small(MAX_FOV_Y, 1080.0)],
        ),
    ])
}

/// A reference of `rf_pixel_spread_angle_small`: the pixel's height on the image plane.
fn reference() -> Reference<(f32, f32), f32> {
    Reference::new(
        Kind::ClosedForm,
        "the height of the pixel next to the axis on the image plane at distance 1: NDC (0, 0) and (0, 2 / H) unprojected through the f64 inverse of the perspective matrix",
        camera,
        |&(fov, height), pixel_spread_angle_small| {
            let got = pixel_spread_angle_small((fov, height));
            let inverse = opengl::perspective(f64::from(fov), 1.0, 0.1, 100.0).inverse();
            let on_image_plane = |ndc_y: f64| {
                let point = inverse * DVec4::new(0.0, ndc_y, 1.0, 1.0);
                point.y / -point.z
            };
            let exact = on_image_plane(2.0 / f64::from(height)) - on_image_plane(0.0);
            // tan within 2 ULP (4 u), the division by H (u); the f64 path within 1e-14.
            Some(Deviation::within(f64::from(got), exact, (gamma(5) + 1.0e-14) * exact))
        },
    )
}

/// A reference of `rf_pixel_spread_angle_small`: the small-angle approximation.
fn pixel_spread_angle_small_approximation() -> Reference<(f32, f32), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the small-angle form x = 2 tan(fov / 2) / H against the exact angle of the pixel next to the axis, atan(x): within x^3 / 3",
        camera,
        |&(fov, height), pixel_spread_angle_small| {
            let got = pixel_spread_angle_small((fov, height));
            let x = pixel_height(fov, height);
            // x - atan(x) <= x^3 / 3; the f32 evaluation of x within gamma(5).
            let bound = x.powi(3) / 3.0 + gamma(5) * x;
            Some(Deviation::within(f64::from(got), pixel_angle(fov, height), bound))
        },
    )
}
