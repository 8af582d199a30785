//! The proof of [`eye_ray_direction`](ray_footprint::ray_diff::eye_ray_direction): its record, its
//! enclosure and its reference.

use crate::degenerate::{mirror, value, NAN};
use crate::ray_diff::camera::shared::{camera, centre_camera, eye_ray_extent, pinhole, pixel_ndc};
use crate::ray_diff::changes::*;
use crate::ray_diff::pinhole::{image_plane_point, Camera};
use crate::ray_diff::reference::{components, widths};
use crate::record::Record;
use crate::reference::{Kind, Reference};
use crate::special::Perturb;
use glam::{Vec2, Vec3};
use ray_footprint::ray_diff as rd;
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval3};
use shader_proptest::{Args, Value};

/// The record of `rf_eye_ray_direction`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let y = Vec3::Y;
    let z = Vec3::Z;
    Record::new(
        Module::RayDiff,
        "eye_ray_direction",
        |(pixel, size, fov, r, u, v)| rd::eye_ray_direction(pixel, size, fov, r, u, v),
        camera,
    )
    .enclosure(|a| enclosure(a).components())
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "the camera's axes turned: the direction turned with them",
        |&(pixel, size, fov, right, up, view): &(Vec2, Vec2, f32, Vec3, Vec3, Vec3), r| {
            (pixel, size, fov, r * right, r * up, r * view)
        },
        |direction: Vec3, r| r.transpose() * direction,
    ))
    .fuzz(|d| (d.vec2(), d.vec2(), d.angle(), d.unit(), d.unit(), d.unit()))
    .degenerate(vec![
        value(
            "zero viewport (0 x 0)",
            "-view (a 1 x 1 image: the centre ray)",
            centre_camera(Vec2::ZERO, 1.0),
            vec![0.0, 0.0, -1.0],
        ),
        value(
            "zero field of view",
            "-view for every pixel",
            (Vec2::new(10.0, 5.0), Vec2::new(100.0, 50.0), 0.0, x, y, z),
            vec![0.0, 0.0, -1.0],
        ),
        mirror(
            "NaN in (fov_y)",
            "CPU: NaN",
            centre_camera(Vec2::splat(64.0), NAN),
            vec![NAN; 3],
        ),
    ])
}

/// `rf_eye_ray_direction` in interval arithmetic, in the same order of operations.
pub(crate) fn enclosure(&(pixel, size, fov, right, up, view): &Camera) -> Interval3 {
    let c = pixel_ndc(pixel, size);
    let extent = eye_ray_extent(size, fov);
    interval3(right) * (c.0[0] * extent.0[0]) - interval3(up) * (c.0[1] * extent.0[1]) - interval3(view)
}

/// The reference of `rf_eye_ray_direction`.
fn reference() -> Reference<Camera, Vec3> {
    Reference::new(
        Kind::ExactGeometry,
        "the pixel centre's NDC unprojected through the f64 inverse of the perspective matrix times the view matrix, scaled to the image plane at distance 1 (RTG Eq. 8-9)",
        pinhole,
        |camera, eye_ray_direction| {
            let got = eye_ray_direction(*camera);
            let expected = image_plane_point(camera, camera.0.as_dvec2());
            // The mirror's rounding (the enclosure); the f64 unprojection within 1e-12.
            let rounding = enclosure(camera).components();
            let bounds = widths(&rounding);
            Some(components(got, &expected.to_array(), |i| bounds[i] + 1.0e-12 * expected.length()))
        },
    )
}
