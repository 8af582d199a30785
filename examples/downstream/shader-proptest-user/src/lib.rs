//! A user's colour helpers: Rust functions with twins in `shaders/colour.wgsl`,
//! `shaders/colour.glsl` and `shaders/colour.slang`, property-tested against them on a Vulkan device
//! in `tests/agreement.rs`, beside a shader function of the user's own that calls ray-footprint's
//! ray-cone module, checked against the module's Rust functions.

use glam::Vec3;

/// Relative luminance of a linear Rec. 709 colour (the weights of ITU-R BT.709).
pub fn luminance(colour: Vec3) -> f32 {
    colour.dot(Vec3::new(0.2126, 0.7152, 0.0722))
}

/// Reinhard's tone map of a linear colour, `c / (1 + c)`, per channel.
pub fn tone_map(colour: Vec3) -> Vec3 {
    colour / (Vec3::ONE + colour)
}
