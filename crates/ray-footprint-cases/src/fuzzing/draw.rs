//! Arguments from fuzz input: a [`Draw`] hands out an input's words as the arguments of a mirror
//! function, in one of two modes:
//!
//! - [`Mode::Raw`]: the words' bits as they are (NaN, infinities, subnormals, anything). Property:
//!   no panic; for the wireframe module, whose documentation promises it for every finite input, a
//!   finite coverage in `[0, 1]` whenever every argument is finite.
//! - [`Mode::Domain`]: the same words mapped into the documented domain (the README's Conventions,
//!   [`crate::strategy`]): a float becomes [`into_domain`] of itself (NaN to 0, magnitudes below
//!   1e-12 to 0, above 1e12 to 1e12, sign kept); a unit-vector argument is the normalized vector of
//!   three such floats (+Z when they are all 0); an angle is clamped to `[-3.2, 3.2]` radians; a
//!   camera-to-world matrix is a rotation plus a translation; a world-to-object matrix is a rotation, a
//!   uniform scale in `[1e-3, 1e3]` and a translation up to 1e9, with world ray origins up to 1e9 (the
//!   agreement suite's ranges, which keep object-space values within 1e12). Properties: every output
//!   is finite, and each function's documented clamps hold ([`crate::Record::range`],
//!   [`crate::Record::promise`]).

use super::words::Words;
use crate::strategy::{HUGE, TINY};
use glam::{Mat4, Quat, Vec2, Vec3};
use ray_footprint::ray_cone::{PackedRayCone, RayCone};
use ray_footprint::ray_diff::{Derivatives2, Derivatives3, GBufferSample, RayDiff};
use ray_footprint::wireframe::{WireframeSettings, WireframeSettingsIo};

/// Largest world ray origin and world-to-object translation (the agreement suite's range).
pub const WORLD_MAX: f32 = 1.0e9;

/// How a [`Draw`] turns words into arguments.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// The bits as they are.
    Raw,
    /// Mapped into the documented domain.
    Domain,
}

/// `x` mapped into the documented domain: NaN to 0, `|x| < TINY` to 0, `|x| > HUGE` (infinities
/// included) to `1e12`, the sign kept.
pub fn into_domain(x: f32) -> f32 {
    if x.is_nan() || x.abs() < TINY {
        0.0f32.copysign(x)
    } else {
        x.clamp(-HUGE, HUGE)
    }
}

/// Arguments drawn from an input's words, and the violated range checks.
pub struct Draw<'a> {
    words: Words<'a>,
    mode: Mode,
    finite: bool,
}

impl<'a> Draw<'a> {
    /// Arguments from `data`'s words in `mode`.
    pub fn new(data: &'a [u8], mode: Mode) -> Self {
        Draw {
            words: Words::new(data),
            mode,
            finite: true,
        }
    }

    fn raw(&mut self) -> f32 {
        let x = self.words.f32();
        self.finite &= x.is_finite();
        x
    }

    fn domain(&self) -> bool {
        self.mode == Mode::Domain
    }

    /// A float anywhere in the domain.
    pub fn scalar(&mut self) -> f32 {
        let x = self.raw();
        if self.domain() {
            into_domain(x)
        } else {
            x
        }
    }

    /// A non-negative distance.
    pub fn distance(&mut self) -> f32 {
        let x = self.scalar();
        if self.domain() {
            x.abs()
        } else {
            x
        }
    }

    /// An angle in radians.
    pub fn angle(&mut self) -> f32 {
        let x = self.scalar();
        if self.domain() {
            x.clamp(-3.2, 3.2)
        } else {
            x
        }
    }

    /// A float clamped to `[-limit, limit]` in the domain.
    fn bounded(&mut self, limit: f32) -> f32 {
        let x = self.scalar();
        if self.domain() {
            x.clamp(-limit, limit)
        } else {
            x
        }
    }

    /// An `i32` from the word's bits (every value is in the domain).
    pub fn int(&mut self) -> i32 {
        self.words.u32() as i32
    }

    /// A `u32` from the word's bits (every value is in the domain).
    pub fn uint(&mut self) -> u32 {
        self.words.u32()
    }

    /// A vector of [`Draw::scalar`]s.
    pub fn vec2(&mut self) -> Vec2 {
        Vec2::new(self.scalar(), self.scalar())
    }

    /// A vector of [`Draw::scalar`]s.
    pub fn vec3(&mut self) -> Vec3 {
        Vec3::new(self.scalar(), self.scalar(), self.scalar())
    }

    /// A unit vector in the domain (normalized, +Z for zero).
    pub fn unit(&mut self) -> Vec3 {
        let v = self.vec3();
        if self.domain() {
            v.try_normalize().unwrap_or(Vec3::Z)
        } else {
            v
        }
    }

    /// A matrix of [`Draw::scalar`]s.
    pub fn mat4(&mut self) -> Mat4 {
        Mat4::from_cols_array(&std::array::from_fn(|_| self.scalar()))
    }

    fn rotation(&mut self) -> Quat {
        let (axis, angle) = (self.unit(), self.angle());
        Quat::from_axis_angle(axis, angle)
    }

    /// A camera-to-world matrix: rotation and translation in the domain.
    pub fn rigid(&mut self) -> Mat4 {
        if !self.domain() {
            return self.mat4();
        }
        let rotation = self.rotation();
        Mat4::from_rotation_translation(rotation, self.vec3())
    }

    /// A world-to-object matrix in the domain: rotation, scale `10^[-3, 3]`, translation up to 1e9.
    pub fn world_to_object(&mut self) -> Mat4 {
        if !self.domain() {
            return self.mat4();
        }
        let rotation = self.rotation();
        let scale = 10f32.powf(self.bounded(3.0));
        let translation = self.world_point();
        Mat4::from_scale_rotation_translation(Vec3::splat(scale), rotation, translation)
    }

    /// A world-space point up to 1e9 in the domain.
    pub fn world_point(&mut self) -> Vec3 {
        Vec3::new(
            self.bounded(WORLD_MAX),
            self.bounded(WORLD_MAX),
            self.bounded(WORLD_MAX),
        )
    }

    /// A ray cone.
    pub fn cone(&mut self) -> RayCone {
        RayCone {
            width: self.scalar(),
            spread_angle: self.angle(),
        }
    }

    /// A packed cone; in the domain, a half whose exponent is all ones (infinity, NaN) gets a
    /// finite exponent.
    pub fn packed_cone(&mut self) -> PackedRayCone {
        let bits = self.words.u32();
        let finite_halves = |bits: u32| {
            let mut out = bits;
            for shift in [10, 26] {
                if (bits >> shift) & 0x1f == 0x1f {
                    out &= !(0x10 << shift);
                }
            }
            out
        };
        PackedRayCone(if self.domain() { finite_halves(bits) } else { bits })
    }

    /// A ray differential.
    pub fn ray_diff(&mut self) -> RayDiff {
        RayDiff::new(self.vec3(), self.vec3(), self.vec3(), self.vec3())
    }

    /// Two-vector derivatives.
    pub fn derivatives2(&mut self) -> Derivatives2 {
        Derivatives2::new(self.vec2(), self.vec2())
    }

    /// Three-vector derivatives.
    pub fn derivatives3(&mut self) -> Derivatives3 {
        Derivatives3::new(self.vec3(), self.vec3())
    }

    /// A G-buffer sample: unit direction, distance, unit normal.
    pub fn gbuffer_sample(&mut self) -> GBufferSample {
        GBufferSample {
            eye_direction: self.unit(),
            distance: self.distance(),
            normal: self.unit(),
        }
    }

    /// Wireframe settings from their host-shareable mirror.
    pub fn settings(&mut self) -> WireframeSettings {
        self.settings_io().unpack()
    }

    /// The host-shareable wireframe settings.
    pub fn settings_io(&mut self) -> WireframeSettingsIo {
        WireframeSettingsIo {
            thickness_var: self.vec2(),
            thickness: self.scalar(),
            smoothing: self.scalar(),
            stipple: self.int(),
            stipple_length: self.scalar(),
            stipple_repeats: self.int(),
            screen_space: self.int(),
        }
    }

    /// The arguments of a barycentric re-intersection function (`barycentric_offsets` and
    /// `barycentric_deltas`, f32 and f64): world-to-object matrix, world ray origin, three vertices,
    /// two unit neighbour directions and the hit's barycentrics.
    pub fn reintersection(&mut self) -> (Mat4, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3) {
        (
            self.world_to_object(),
            self.world_point(),
            self.vec3(),
            self.vec3(),
            self.vec3(),
            self.unit(),
            self.unit(),
            self.vec3(),
        )
    }

    /// Whether every float drawn so far was finite.
    pub fn finite(&self) -> bool {
        self.finite
    }
}
