//! Special-value cases for every function: each record's own cases pushed towards the values real
//! scenes produce and uniform sampling almost never does ([`Perturb::perturb`]).
//!
//! - A float becomes, half of the time, a special value of either sign: zero, the smallest
//!   subnormal and normal numbers, 1 and the floats one ULP from it, and the bounds of the
//!   documented domain and of every clamp constant inside it ([`BOUNDS`]), each with its
//!   neighbours one ULP away ([`shader_proptest::strategy::special_values`]).
//! - A unit vector (a normal, a direction: length 1 within rounding) stays a unit vector: it
//!   becomes an axis, its opposite, or a neighbour one ULP away, or is tied to another unit
//!   vector of the case (equal, opposite, orthogonal); the documented precondition that
//!   normals and directions are unit length holds.
//! - Any other vector becomes zero, an axis times a special length, or made of special floats, or
//!   is tied to another vector of the case (equal, opposite, a multiple, one ULP away,
//!   orthogonal): a repeated or collinear vertex, a ray along an edge.
//!
//! A special-value check is the agreement check of the same function on these cases, where the
//! function is well-conditioned ([`crate::Record::conditioned`]): finite inputs must give finite
//! outputs in every language, and the shader must agree with the mirror within the function's
//! tolerance. The cases outside that domain (within rounding of a threshold, a ray parallel to a
//! plane within rounding), where the tolerance could only be the documented clamp, are run on
//! the device on their own and must keep the record's promises: finite, within the documented
//! range ([`crate::Function::ill_conditioned_gpu`]).

use crate::strategy::{HUGE, TINY};
use glam::{Mat4, Vec2, Vec3};
use proptest::prelude::*;
use proptest::test_runner::TestRng;
use ray_footprint::ray_cone::{
    PackedRayCone, RayCone, F16_MAX, MAX_FOV_Y, MAX_INCIDENCE_ANGLE, MIN_COS, MIN_ROUGHNESS_DENOMINATOR,
};
use ray_footprint::ray_diff::{
    Derivatives2, Derivatives3, GBufferSample, RayDiff, DIFF_MAX_SHARPNESS, DIFF_MIN_COS, DIFF_MIN_SINE,
};
use ray_footprint::wireframe::{WireframeSettings, WireframeSettingsIo, MAX_LINE_THICKNESS};
use shader_proptest::strategy::{next_f32, relate, special_values};
use std::sync::OnceLock;

/// The bounds of the documented domain (magnitudes 0 or in `[TINY, HUGE]`) and the clamp
/// constants of the modules that lie inside it.
pub const BOUNDS: [f32; 11] = [
    TINY,
    HUGE,
    MIN_COS,
    MAX_FOV_Y,
    F16_MAX,
    MAX_INCIDENCE_ANGLE,
    MIN_ROUGHNESS_DENOMINATOR,
    DIFF_MIN_COS,
    DIFF_MAX_SHARPNESS,
    DIFF_MIN_SINE,
    MAX_LINE_THICKNESS,
];

/// Largest `| |v| - 1 |` of a vector taken as a unit vector.
const UNIT_LENGTH_TOLERANCE: f32 = 1.0e-5;

/// [`special_values`] of [`BOUNDS`].
fn specials() -> &'static [f32] {
    static SPECIALS: OnceLock<Vec<f32>> = OnceLock::new();
    SPECIALS.get_or_init(|| special_values(&BOUNDS))
}

/// One of the special floats.
fn special(rng: &mut TestRng) -> f32 {
    specials()[rng.random_range(0..specials().len())]
}

/// A value whose cases can be pushed towards special values.
pub trait Perturb {
    /// Changes the value, at random, into a special value of its kind.
    fn perturb(&mut self, rng: &mut TestRng);
    /// The 3-vectors of the value, which may be tied to other vectors of a case.
    fn vectors(&mut self) -> Vec<&mut Vec3> {
        Vec::new()
    }
}

impl Perturb for f32 {
    fn perturb(&mut self, rng: &mut TestRng) {
        if rng.random() {
            *self = special(rng);
        }
    }
}

impl Perturb for i32 {
    fn perturb(&mut self, rng: &mut TestRng) {
        const SPECIAL: [i32; 8] = [0, 1, -1, 2, i32::MAX, i32::MIN, i32::MAX - 1, i32::MIN + 1];
        if rng.random() {
            *self = SPECIAL[rng.random_range(0..SPECIAL.len())];
        }
    }
}

impl Perturb for u32 {
    fn perturb(&mut self, rng: &mut TestRng) {
        const SPECIAL: [u32; 6] = [0, 1, 2, u32::MAX, u32::MAX - 1, 0x8000_0000];
        if rng.random() {
            *self = SPECIAL[rng.random_range(0..SPECIAL.len())];
        }
    }
}

impl Perturb for bool {
    fn perturb(&mut self, rng: &mut TestRng) {
        *self = rng.random();
    }
}

/// Whether `v` is a unit vector (within [`UNIT_LENGTH_TOLERANCE`]).
fn is_unit(v: Vec3) -> bool {
    (v.length() - 1.0).abs() <= UNIT_LENGTH_TOLERANCE
}

const AXES: [Vec3; 6] = [Vec3::X, Vec3::Y, Vec3::Z, Vec3::NEG_X, Vec3::NEG_Y, Vec3::NEG_Z];

impl Perturb for Vec3 {
    fn perturb(&mut self, rng: &mut TestRng) {
        if !rng.random::<bool>() {
            return;
        }
        let axis = AXES[rng.random_range(0..AXES.len())];
        *self = if is_unit(*self) {
            match rng.random_range(0..3) {
                0 => axis,
                1 => -*self,
                _ => {
                    let mut nudged = *self;
                    let component = rng.random_range(0..3);
                    nudged[component] = next_f32(nudged[component], rng.random());
                    nudged
                }
            }
        } else {
            match rng.random_range(0..3) {
                0 => Vec3::ZERO,
                1 => axis * special(rng),
                _ => Vec3::new(special(rng), special(rng), special(rng)),
            }
        };
    }
    fn vectors(&mut self) -> Vec<&mut Vec3> {
        vec![self]
    }
}

impl Perturb for Vec2 {
    fn perturb(&mut self, rng: &mut TestRng) {
        if rng.random() {
            *self = match rng.random_range(0..3) {
                0 => Vec2::ZERO,
                1 => [Vec2::X, Vec2::Y, Vec2::NEG_X, Vec2::NEG_Y][rng.random_range(0..4)] * special(rng),
                _ => Vec2::new(special(rng), special(rng)),
            };
        }
    }
}

impl Perturb for Mat4 {
    /// One entry becomes a special value, or the matrix the identity.
    fn perturb(&mut self, rng: &mut TestRng) {
        match rng.random_range(0..4) {
            0 => *self = Mat4::IDENTITY,
            1 => {
                let mut columns = self.to_cols_array();
                columns[rng.random_range(0..16)] = special(rng);
                *self = Mat4::from_cols_array(&columns);
            }
            _ => {}
        }
    }
}

impl Perturb for RayCone {
    fn perturb(&mut self, rng: &mut TestRng) {
        self.width.perturb(rng);
        self.spread_angle.perturb(rng);
    }
}

impl Perturb for PackedRayCone {
    /// A half becomes zero (either sign), the largest finite half, the smallest subnormal or 1.
    fn perturb(&mut self, rng: &mut TestRng) {
        const SPECIAL: [u32; 8] = [0, 0x8000, 0x7bff, 0xfbff, 0x0001, 0x8001, 0x3c00, 0x0400];
        if rng.random() {
            let half = SPECIAL[rng.random_range(0..SPECIAL.len())];
            self.0 = if rng.random() {
                (self.0 & 0xffff_0000) | half
            } else {
                (self.0 & 0x0000_ffff) | (half << 16)
            };
        }
    }
}

impl Perturb for RayDiff {
    fn perturb(&mut self, rng: &mut TestRng) {
        self.vectors().into_iter().for_each(|v| v.perturb(rng));
    }
    fn vectors(&mut self) -> Vec<&mut Vec3> {
        vec![
            &mut self.d_origin_dx,
            &mut self.d_origin_dy,
            &mut self.d_direction_dx,
            &mut self.d_direction_dy,
        ]
    }
}

impl Perturb for Derivatives2 {
    fn perturb(&mut self, rng: &mut TestRng) {
        self.dx.perturb(rng);
        self.dy.perturb(rng);
    }
}

impl Perturb for Derivatives3 {
    fn perturb(&mut self, rng: &mut TestRng) {
        self.vectors().into_iter().for_each(|v| v.perturb(rng));
    }
    fn vectors(&mut self) -> Vec<&mut Vec3> {
        vec![&mut self.dx, &mut self.dy]
    }
}

impl Perturb for GBufferSample {
    fn perturb(&mut self, rng: &mut TestRng) {
        self.distance.perturb(rng);
        self.vectors().into_iter().for_each(|v| v.perturb(rng));
    }
    fn vectors(&mut self) -> Vec<&mut Vec3> {
        vec![&mut self.eye_direction, &mut self.normal]
    }
}

impl Perturb for WireframeSettingsIo {
    fn perturb(&mut self, rng: &mut TestRng) {
        self.thickness_var.perturb(rng);
        self.thickness.perturb(rng);
        self.smoothing.perturb(rng);
        self.stipple.perturb(rng);
        self.stipple_length.perturb(rng);
        self.stipple_repeats.perturb(rng);
        self.screen_space.perturb(rng);
    }
}

impl Perturb for WireframeSettings {
    fn perturb(&mut self, rng: &mut TestRng) {
        let mut io = self.pack();
        io.perturb(rng);
        *self = io.unpack();
    }
}

/// Ties, in a third of the cases with two or more 3-vectors, one of them to another: a unit
/// vector only to a unit vector (equal, opposite or orthogonal, as a unit vector), any other to
/// any other ([`relate`]).
fn tie_vectors(mut vectors: Vec<&mut Vec3>, rng: &mut TestRng) {
    let count = vectors.len();
    if count < 2 || rng.random_range(0..3) != 0 {
        return;
    }
    let target = rng.random_range(0..count);
    let unit = is_unit(*vectors[target]);
    let sources: Vec<usize> = (0..count)
        .filter(|&i| i != target && is_unit(*vectors[i]) == unit)
        .collect();
    if sources.is_empty() {
        return;
    }
    let source = *vectors[sources[rng.random_range(0..sources.len())]];
    if unit {
        let orthogonal = source
            .cross(AXES[rng.random_range(0..3)])
            .normalize_or(source.any_orthonormal_vector());
        *vectors[target] = [source, -source, orthogonal][rng.random_range(0..3)];
    } else {
        relate(source, vectors[target], rng);
    }
}

macro_rules! perturb_tuple {
    ($($name:ident),+) => {
        impl<$($name: Perturb),+> Perturb for ($($name,)+) {
            #[allow(non_snake_case)]
            fn perturb(&mut self, rng: &mut TestRng) {
                let ($($name,)+) = self;
                $($name.perturb(rng);)+
                tie_vectors(self.vectors(), rng);
            }
            #[allow(non_snake_case)]
            fn vectors(&mut self) -> Vec<&mut Vec3> {
                let ($($name,)+) = self;
                let mut all = Vec::new();
                $(all.extend($name.vectors());)+
                all
            }
        }
    };
}

shader_proptest::for_each_args_tuple!(perturb_tuple);
