//! The pinhole camera that the camera and the reflection sections share: its arguments and, for the
//! references, the exact point its pixel unprojects to.

use glam::dcamera::rh::proj::opengl;
use glam::{DMat4, DVec2, DVec3, DVec4, Vec2, Vec3};

/// The arguments of the pinhole camera functions: pixel, image size, fov_y, right, up, view.
pub type Camera = (Vec2, Vec2, f32, Vec3, Vec3, Vec3);

/// The point with camera-space `z = -1` on the ray through the continuous pixel position `at`:
/// the pixel's NDC (y up) unprojected through the f64 inverse of the OpenGL perspective matrix
/// times the view matrix (the inverse of the basis `right, up, view`; eye at the origin).
pub(crate) fn image_plane_point(&(_, size, fov, right, up, view): &Camera, at: DVec2) -> DVec3 {
    let size = size.as_dvec2();
    let camera_to_world = DMat4::from_cols(
        right.as_dvec3().extend(0.0),
        up.as_dvec3().extend(0.0),
        view.as_dvec3().extend(0.0),
        DVec4::W,
    );
    let world_to_camera = camera_to_world.inverse();
    let projection = opengl::perspective(f64::from(fov), size.x / size.y, 1.0, 10.0);
    let unproject = (projection * world_to_camera).inverse();
    let ndc = (at + 0.5) / size * 2.0 - 1.0;
    let point = unproject * DVec4::new(ndc.x, -ndc.y, 0.0, 1.0);
    let point = point.truncate() / point.w;
    let depth = (world_to_camera * point.extend(1.0)).z;
    point * (-1.0 / depth)
}
