//! shader-proptest's [`Value`] for every struct of the modules (feature `shader-proptest`), so
//! that a check can pass them to and return them from shader functions. The structs that cross
//! the CPU/GPU boundary ([`crate::abi`]) are declared `pod`: every check that uses one first
//! compares its Rust layout with the shader's.

use crate::abi::{HitPayload, RayConePushConstants, WireframePushConstants};
use crate::ray_cone::{unpack_ray_cone, PackedRayCone, RayCone, RefractedRayCone};
use crate::ray_diff::{
    Derivatives2, Derivatives3, GBufferSample, NeighbourDirections, RayDiff, RefractedRayDiff,
    TriplanarGradients,
};
use crate::ray_diff_f64::BarycentricOffsets;
use crate::wireframe::{WireframeSettings, WireframeSettingsIo};
use glam::{Vec2, Vec3, Vec4};
use shader_proptest::{shader_struct, ShaderType, Value};

shader_struct!(pod RayCone as "RfRayCone" { width: f32, spread_angle: f32 });
shader_struct!(RefractedRayCone as "RfRefractedRayCone" { cone: RayCone, total_internal_reflection: bool });
shader_struct!(pod HitPayload as "RfHitPayload" { colour: Vec3, weight: f32, cone: RayCone, depth: u32, pad: u32 });
shader_struct!(pod RayConePushConstants as "RfRayConePushConstants" { tex_grad_scale: f32, pixel_spread_angle: f32 });
shader_struct!(pod RayDiff as "RfRayDiff" {
    d_origin_dx: Vec3, pad0: f32, d_origin_dy: Vec3, pad1: f32,
    d_direction_dx: Vec3, pad2: f32, d_direction_dy: Vec3, pad3: f32,
});
shader_struct!(Derivatives2 as "RfDerivatives2" { dx: Vec2, dy: Vec2 });
shader_struct!(Derivatives3 as "RfDerivatives3" { dx: Vec3, dy: Vec3 });
shader_struct!(NeighbourDirections as "RfNeighbourDirections" { right: Vec3, below: Vec3 });
shader_struct!(RefractedRayDiff as "RfRefractedRayDiff" { diff: RayDiff, total_internal_reflection: bool });
shader_struct!(GBufferSample as "RfGBufferSample" { eye_direction: Vec3, distance: f32, normal: Vec3 });
shader_struct!(TriplanarGradients as "RfTriplanarGradients" { yz: Derivatives2, zx: Derivatives2, xy: Derivatives2 });
shader_struct!(BarycentricOffsets as "RfBarycentricOffsets" { dx: Vec3, dy: Vec3 });
shader_struct!(WireframeSettings as "RfWireframeSettings" {
    thickness_var: Vec2, thickness: f32, smoothing: f32, stipple: bool,
    stipple_length: f32, stipple_repeats: i32, screen_space: bool,
});
shader_struct!(pod WireframeSettingsIo as "RfWireframeSettingsIo" {
    thickness_var: Vec2, thickness: f32, smoothing: f32, stipple: i32,
    stipple_length: f32, stipple_repeats: i32, screen_space: i32,
});
shader_struct!(pod WireframePushConstants as "RfWireframePushConstants" { colour: Vec4, settings: WireframeSettingsIo });

/// The packed cone travels as the shaders' `u32`; it is compared by its two unpacked halves,
/// because the rounding mode of `packHalf2x16` is left to the implementation.
impl Value for PackedRayCone {
    const TYPE: ShaderType = ShaderType::U32;
    fn write(&self, words: &mut Vec<u32>) {
        words.push(self.0);
    }
    fn read(words: &mut &[u32]) -> Self {
        PackedRayCone(shader_proptest::value::take(words))
    }
    fn components(&self, out: &mut Vec<f32>) {
        unpack_ray_cone(*self).components(out);
    }
    fn is_finite(&self) -> bool {
        true
    }
}
