//! The independent references of the ray_diff records ([`crate::reference`]), by section.
//!
//! Their bounds take the f32 rounding of the mirror from the record's interval enclosure (its
//! width encloses both the exact value of the function's formula on the same inputs and the
//! mirror's result), and add what the reference itself leaves open: the error of its central
//! differences and, where it starts from exact geometry, the rounding of the inputs.

mod camera;
mod cones;
mod derivatives;
mod gbuffer;
mod mapping;
mod reflection;
mod reintersection;

pub(super) use camera::{
    eye_ray_diff, eye_ray_diff_from_matrices, eye_ray_direction, eye_ray_direction_from_matrices,
    normalized_derivative, pixel_directions,
};
pub(super) use cones::{
    anisotropic_cone_axes, anisotropic_cone_axes_growth, anisotropic_cone_axes_optix,
    anisotropic_cone_gradients, anisotropic_cone_gradients_isotropic, cone_barycentric_deltas,
    cone_from_ray_diff, cone_from_ray_diff_propagation, ray_diff_from_cone, ray_diff_from_cone_round_trip,
};
pub(super) use derivatives::{
    barycentric_derivatives, barycentric_w_derivatives, lod_box, lod_isotropic, sample_grad_gradients,
    secondary_origin_derivatives, texel_derivatives, texture_derivatives, transfer,
};
pub(super) use gbuffer::{gbuffer_ray_diff, tangent_plane_offsets};
pub(super) use mapping::{planar_mapping_gradients, triplanar_gradients, triplanar_weights};
pub(super) use reflection::{
    normal_derivatives, reflect_ray_diff, reflect_ray_diff_mirror_camera, refract_ray_diff,
};
pub(super) use reintersection::{
    barycentric_deltas, barycentric_offsets, intersect_triangle_plane, uv_gradients_from_offsets,
};
pub(crate) use reintersection::{exact_offsets, unclamped};

use crate::degenerate::parts;
use crate::reference::Deviation;
use glam::DVec3;
use shader_proptest::interval::Interval;
use shader_proptest::Value;

/// The widths of an enclosure's intervals: bounds of the mirror's rounding, component by component.
pub(crate) fn widths(enclosure: &[Interval]) -> Vec<f64> {
    enclosure
        .iter()
        .map(|interval| interval.hi - interval.lo)
        .collect()
}

/// The worst of the components of `got` (as the harness lists them) against `expected`, each within
/// `bound(index)`.
pub(crate) fn components<R: Value>(got: R, expected: &[f64], bound: impl Fn(usize) -> f64) -> Deviation {
    let got = parts(got);
    assert_eq!(got.len(), expected.len(), "one expected value per component");
    Deviation::worst(
        got.iter()
            .zip(expected)
            .enumerate()
            .map(|(index, (&g, &e))| Deviation::within(f64::from(g), e, bound(index))),
    )
}

/// The components of vectors as a list, each vector followed by `pad` zeros (a `RayDiff`'s
/// padding: 1; `Derivatives3`: 0).
fn listed(vectors: &[DVec3], pad: usize) -> Vec<f64> {
    vectors
        .iter()
        .flat_map(|v| v.to_array().into_iter().chain(std::iter::repeat_n(0.0, pad)))
        .collect()
}
