//! How far the ray cones' texture footprints are from the ray differential's, at a scene's mask
//! pixels, measured on the per-pixel records rather than in the image: the sampler's filtering
//! plays no part, so the anisotropic cone's ellipse is measured even on a device that filters
//! isotropically.
//!
//! The ray differential's footprint at a primary hit is the Jacobian `J = [uv_dx uv_dy]` (texels
//! per pixel step, Igehy); its singular values `s1 >= s2` are the axes of the ellipse it maps a
//! pixel to. The isotropic cone has one size, its `textureGrad` gradient (the footprint in UV units
//! at `tex_grad_scale` 1); the anisotropic cone has the singular values of its gradients
//! `[cone_uv_dx cone_uv_dy]` (JCGT 2021). Each is compared axis by axis as `|log2(cone / s)|`:
//! the distance in mip levels. The texture's size scales every footprint alike, so the ratios are
//! taken in UV units.

use crate::rt::abi::RtPixelRecord;
use glam::DVec2;

/// The mean distance in mip levels between the cones' footprints and the ray differential's over
/// a mask, and how elongated the differential's footprints are there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Footprints {
    /// Pixels compared: in the mask, hit, every axis above 0.
    pub pixels: usize,
    /// Median of the differential's `s1 / s2`: 1 for a round footprint, large at grazing angles.
    pub anisotropy: f64,
    /// Mean `|log2(isotropic / s1)|`: the isotropic cone against the major axis.
    pub cone_major: f64,
    /// Mean `|log2(isotropic / s2)|`: the isotropic cone against the minor axis.
    pub cone_minor: f64,
    /// Mean `|log2(a1 / s1)|`, `a1` the anisotropic cone's major axis.
    pub anisotropic_major: f64,
    /// Mean `|log2(a2 / s2)|`, `a2` its minor axis.
    pub anisotropic_minor: f64,
}

/// The singular values `(s1, s2)`, `s1 >= s2 >= 0`, of the 2 x 2 matrix with columns `dx` and
/// `dy`: with `S = |dx|^2 + |dy|^2` and `D = det`, `s1^2 = (S + sqrt(S^2 - 4 D^2)) / 2` and
/// `s2 = |D| / s1` (their product is `|D|`; this form does not cancel for thin ellipses).
pub fn singular_values(dx: DVec2, dy: DVec2) -> (f64, f64) {
    let (a, b, c, d) = (dx.x, dx.y, dy.x, dy.y);
    let sum = a * a + b * b + c * c + d * d;
    let det = a * d - b * c;
    let root = (sum * sum - 4.0 * det * det).max(0.0).sqrt();
    let major = (0.5 * (sum + root)).sqrt();
    let minor = if major > 0.0 { det.abs() / major } else { 0.0 };
    (major, minor)
}

/// The footprints of the `records` in `mask`, or `None` if no pixel there has every axis above 0.
/// The lab renders at `tex_grad_scale` 1, so a record's `gradient` is the isotropic cone's
/// footprint in UV units, like the gradients it is compared with (the texture's size scales all
/// of them alike and cancels in every ratio).
pub fn footprints(records: &[RtPixelRecord], mask: &[bool]) -> Option<Footprints> {
    let mut rows = Vec::new();
    for (record, _) in records.iter().zip(mask).filter(|(r, &m)| m && r.hit == 1) {
        let (s1, s2) = singular_values(record.diff.uv_dx.as_dvec2(), record.diff.uv_dy.as_dvec2());
        let (a1, a2) = singular_values(record.cone_uv_dx.as_dvec2(), record.cone_uv_dy.as_dvec2());
        let isotropic = f64::from(record.gradient);
        if [s1, s2, a1, a2, isotropic]
            .iter()
            .all(|&v| v > 0.0 && v.is_finite())
        {
            let levels = |cone: f64, differential: f64| (cone / differential).log2().abs();
            rows.push([
                s1 / s2,
                levels(isotropic, s1),
                levels(isotropic, s2),
                levels(a1, s1),
                levels(a2, s2),
            ]);
        }
    }
    if rows.is_empty() {
        return None;
    }
    let mean = |column: usize| rows.iter().map(|row| row[column]).sum::<f64>() / rows.len() as f64;
    let mut anisotropy: Vec<f64> = rows.iter().map(|row| row[0]).collect();
    anisotropy.sort_by(f64::total_cmp);
    Some(Footprints {
        pixels: rows.len(),
        anisotropy: anisotropy[anisotropy.len() / 2],
        cone_major: mean(1),
        cone_minor: mean(2),
        anisotropic_major: mean(3),
        anisotropic_minor: mean(4),
    })
}

#[cfg(test)]
mod tests {
    use super::singular_values;
    use glam::DVec2;

    /// A rotation times diag(3, 0.5) has singular values 3 and 0.5; a diagonal matrix its absolute
    /// entries; a rank-one matrix one value of 0.
    #[test]
    fn singular_values_of_known_matrices() {
        let (c, s) = (0.6f64, 0.8f64);
        let (s1, s2) = singular_values(DVec2::new(3.0 * c, 3.0 * s), DVec2::new(-0.5 * s, 0.5 * c));
        assert!((s1 - 3.0).abs() < 1e-6 && (s2 - 0.5).abs() < 1e-6, "{s1} {s2}");
        assert_eq!(
            singular_values(DVec2::new(-2.0, 0.0), DVec2::new(0.0, 4.0)),
            (4.0, 2.0)
        );
        let (r1, r2) = singular_values(DVec2::new(1.0, 2.0), DVec2::new(2.0, 4.0));
        assert_eq!((r1, r2), (5.0, 0.0));
    }
}
