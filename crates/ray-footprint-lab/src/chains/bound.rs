//! How far the cone and the differential may be apart after each leg of a chain, and what a run of
//! chains covered.

use super::{Chain, ChainSample, Comparison, Surface};
use ray_footprint::ray_cone::RayCone;

/// Roundings (in f32 ULP of the chain's scale, see `Scale`, over the cube of its smallest cosine
/// of incidence so far) by which the cone's width and the differential's footprint may differ per
/// leg of a chain, computed in f32 on the CPU or on a Vulkan device.
///
/// Per leg, `transfer` rounds about a dozen times on vectors no longer than the slanted footprint
/// (`scale / c`, c the cosine of incidence), and its division by the rounded `dot(D, N)` adds
/// `3 ULP / c` twice: 12. `reflect_ray_diff` and the normal field round about a dozen times on terms
/// no larger than the spread scale: 12. The cone rounds 4 times: 4. The footprint, a dot product of
/// the transferred origin differential (at most `scale / c` long) with the pixel axis rounded to
/// f32, rounds 3 times and inherits the axis's half ULP per component: 4. A device may return a
/// quotient 2.5 ULP from the exact one where the CPU rounds it by 0.5 (Vulkan's precision rules;
/// `+ - *` are correctly rounded on both, and a fused multiply-add only drops a rounding): 2 more
/// for `transfer`'s division and 2 for `curvature_spread_angle`'s. That is 36 per leg. An error
/// made on one leg grows on the later ones no faster than the scale itself, which follows the same
/// recurrence with absolute values, so after `n` legs the two differ by less than
/// `CHAIN_PRIMARY_ULPS + 36 n` ULP of `scale / c_min^3`.
pub const CHAIN_ULPS_PER_LEG: f64 = 36.0;

/// Roundings of the primary ray, once per chain, in the units of [`CHAIN_ULPS_PER_LEG`]. A pinhole's
/// cone and eye-ray differential are computed apart: the cone's spread `2 tan(fov_y / 2) / H`
/// divides once (2.5 ULP on a device); `eye_ray_diff` divides for the aspect ratio (3 with its
/// product) and for the pixel step (2.5), and `normalized_derivative` subtracts (0.5), takes the
/// square root of a squared length within an ULP of 1 (5: Vulkan's `sqrt` inherits `1 /
/// inversesqrt`, 4.5 ULP) and divides by it (2.5): 16 in all (4 on the CPU). Both scale the same
/// `tan(fov_y / 2)` of the same argument, so its own error (up to 2^-11 absolute on a device)
/// scales the cone and the differential alike. The orthographic and thin-lens differentials are
/// built from their cones' own width and spread, and add nothing.
pub const CHAIN_PRIMARY_ULPS: f64 = 16.0;

/// Bounds on a chain's widths and spreads: the cone's recurrences with absolute values (and the
/// larger principal curvature), which bound every term either computation rounds.
pub(super) struct Scale {
    width: f64,
    spread: f64,
}

impl Scale {
    /// The scale of a chain whose primary cone is `cone`.
    pub(super) fn new(cone: RayCone) -> Self {
        Scale {
            width: f64::from(cone.width.abs()),
            spread: f64::from(cone.spread_angle.abs()),
        }
    }

    /// The scale `t` further along.
    pub(super) fn at(&self, t: f64) -> f64 {
        self.width + self.spread * t
    }

    /// The scale after a mirror at `t` with the largest principal curvature `curvature` and the
    /// cosine of incidence `cos`.
    pub(super) fn reflect(&mut self, t: f64, curvature: f64, cos: f64) {
        self.width = self.at(t);
        self.spread += 2.0 * curvature * self.width / cos;
    }
}

/// The cone's width and the differential's footprint at the end of one leg of a chain, with the
/// bound on their rounding and the chain's scale there.
#[derive(Clone, Copy, Debug)]
pub struct Sample {
    /// The cone's signed width.
    pub cone: f64,
    /// The differential's signed footprint, as the comparison measures it.
    pub diff: f64,
    /// The bound on `|cone - diff|`.
    pub bound: f64,
    /// The chain's scale there.
    pub scale: f64,
}

impl Sample {
    /// The sample at the end of leg `legs` as `traced` reports it, where the chain's scale is
    /// `scale` and its smallest cosine of incidence so far `min_cos`.
    pub(super) fn new(
        legs: usize,
        traced: ChainSample,
        comparison: Comparison,
        scale: f64,
        min_cos: f64,
    ) -> Self {
        let ulps = CHAIN_PRIMARY_ULPS + CHAIN_ULPS_PER_LEG * legs as f64;
        Sample {
            cone: f64::from(traced.width),
            diff: comparison.footprint(traced.footprint),
            bound: ulps * f64::from(f32::EPSILON) * scale / min_cos.powi(3),
            scale,
        }
    }

    /// Whether the cone and the differential are finite and within the bound of each other.
    pub fn within_bound(&self) -> bool {
        self.cone.is_finite() && self.diff.is_finite() && (self.cone - self.diff).abs() <= self.bound
    }
}

/// Samples whose differential footprint is at least this fraction of the chain's scale count for
/// the relative and LOD discrepancies; nearer a focus the width is the difference of larger terms,
/// and only the absolute rounding bound means anything there.
const AWAY_FROM_A_FOCUS: f64 = 0.1;

/// What the chains covered and how far the cone and the differential were apart.
#[derive(Clone, Debug, Default)]
pub struct ChainStats {
    /// Chains followed.
    pub chains: usize,
    /// Samples compared.
    pub samples: usize,
    /// Chains whose cone width turned negative somewhere.
    pub crossed_a_focus: usize,
    /// Chains that met a mirror from behind its stored normals.
    pub back_side_hits: usize,
    /// Chains that met a saddle.
    pub saddles: usize,
    /// Largest `|cone - differential|` as a fraction of the rounding bound.
    pub worst_ratio: f64,
    /// Samples away from a focus.
    pub away_from_a_focus: usize,
    /// Largest relative discrepancy away from a focus.
    pub worst_relative: f64,
    /// Largest LOD difference (`|log2(cone / differential)|`) away from a focus.
    pub worst_lod: f64,
}

impl ChainStats {
    /// Counts one chain and its samples.
    pub fn add(&mut self, chain: &Chain, samples: &[Sample]) {
        let count = |yes: bool| usize::from(yes);
        self.chains += 1;
        self.samples += samples.len();
        self.crossed_a_focus += count(samples.iter().any(|s| s.cone < 0.0));
        self.back_side_hits += count(chain.bounces.iter().any(|b| !b.stored_normal_faces_the_ray()));
        self.saddles += count(
            chain
                .bounces
                .iter()
                .any(|b| matches!(b.surface, Surface::Saddle { .. })),
        );
        for sample in samples {
            self.worst_ratio = self
                .worst_ratio
                .max((sample.cone - sample.diff).abs() / sample.bound);
            if sample.diff.abs() >= AWAY_FROM_A_FOCUS * sample.scale {
                self.away_from_a_focus += 1;
                let relative = (sample.cone - sample.diff).abs() / sample.diff.abs();
                self.worst_relative = self.worst_relative.max(relative);
                self.worst_lod = self.worst_lod.max((sample.cone / sample.diff).abs().log2().abs());
            }
        }
    }
}

impl std::fmt::Display for ChainStats {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} chains ({} crossed a focus, {} met a mirror from behind its stored normals, {} met a \
             saddle), {} samples; largest |cone - differential| {:.4} of the rounding bound; away \
             from a focus ({} samples): largest relative discrepancy {:.2e}, largest LOD difference \
             {:.2e}",
            self.chains,
            self.crossed_a_focus,
            self.back_side_hits,
            self.saddles,
            self.samples,
            self.worst_ratio,
            self.away_from_a_focus,
            self.worst_relative,
            self.worst_lod
        )
    }
}
