//! The procedural texture every diffuse surface takes its albedo from, its mip chain and a
//! trilinear sampler.
//!
//! The texture is 1024 x 1024 sRGB texels with the same energy at every scale: two colours mixed
//! by ten checkers of squares 1 to 512 texels wide ([`procedural_texel`]). Any minification of
//! level 0 aliases, and every level of the chain differs from the next. Its mip chain is `ray_footprint::mip::mip_chain_rgba8_srgb`
//! (box filter of the level above, averaged as linear light; Williams, "Pyramidal Parametrics",
//! SIGGRAPH 1983), decoded to linear f32 for sampling. The sampler is trilinear as a GPU's with
//! linear minification and mipmap filters: bilinear within a level (texel centres at
//! `(i + 0.5) / size`, wrap addressing), linear between the two levels around the LOD, the LOD
//! clamped to `[0, last level]`.

use glam::DVec3;
use ray_footprint::mip::{mip_chain_rgba8_srgb, srgb_to_linear, MipLevel};

/// Texels along each side of the texture.
pub const TEXTURE_SIZE: u32 = 1024;

/// Octaves of the checker: squares of 1, 2, 4, ... 512 texels.
const OCTAVES: u32 = 10;

/// The two colours the checkers mix, linear RGB.
const CHECKER_COLOURS: [[f64; 3]; 2] = [[0.95, 0.35, 0.1], [0.1, 0.55, 0.95]];

/// Texel `(x, y)` of level 0 in linear RGB: the two colours mixed by the mean `s` of ten checkers
/// of squares `2^k` texels wide (`k = 0..9`), each `((x >> k) + (y >> k)) mod 2`. Level `L` of the
/// box-filtered chain averages every checker finer than `2^L` to exactly one half and keeps the
/// others: each level removes one octave, so the level a footprint picks changes the image at
/// every scale.
pub fn procedural_texel(x: u32, y: u32) -> [f64; 3] {
    let squares: u32 = (0..OCTAVES).map(|k| ((x >> k) + (y >> k)) % 2).sum();
    let mix = f64::from(squares) / f64::from(OCTAVES);
    let [first, second] = CHECKER_COLOURS;
    std::array::from_fn(|c| first[c] + (second[c] - first[c]) * mix)
}

/// The nearest 8-bit sRGB value of linear light `value` (IEC 61966-2-1), by search over the
/// crate's decoder, so that encoding and decoding agree exactly.
fn linear_to_srgb8(value: f64) -> u8 {
    let target = value.clamp(0.0, 1.0) as f32;
    let below = (0..=255u8)
        .rev()
        .find(|&code| srgb_to_linear(code) <= target)
        .unwrap_or(0);
    let above = below.saturating_add(1);
    if (srgb_to_linear(above) - target).abs() < (target - srgb_to_linear(below)).abs() {
        above
    } else {
        below
    }
}

/// A texture's levels in linear RGB, level 0 first.
#[derive(Clone, Debug)]
pub struct Texture {
    /// Per level: its side in texels and its texels, row by row.
    pub levels: Vec<(u32, Vec<[f32; 3]>)>,
}

/// A level of the crate's chain decoded to linear RGB.
fn decoded(level: &MipLevel<u8>) -> (u32, Vec<[f32; 3]>) {
    let texels = level
        .texels
        .iter()
        .map(|t| [srgb_to_linear(t[0]), srgb_to_linear(t[1]), srgb_to_linear(t[2])])
        .collect();
    (level.width, texels)
}

impl Texture {
    /// The procedural texture ([`procedural_texel`]) stored as sRGB8 and its full mip chain.
    pub fn procedural() -> Texture {
        let size = TEXTURE_SIZE;
        let texels: Vec<[u8; 4]> = (0..size * size)
            .map(|i| {
                let [r, g, b] = procedural_texel(i % size, i / size).map(linear_to_srgb8);
                [r, g, b, 255]
            })
            .collect();
        let chain = mip_chain_rgba8_srgb(size, size, &texels).expect("a square texture of 1024 texels");
        Texture {
            levels: chain.iter().map(decoded).collect(),
        }
    }

    /// The last level's index.
    pub fn last_level(&self) -> usize {
        self.levels.len() - 1
    }

    /// Texel `(x, y)` of `level`, with wrap addressing.
    pub fn texel(&self, level: usize, x: i64, y: i64) -> DVec3 {
        let (size, texels) = &self.levels[level];
        let side = i64::from(*size);
        let index = y.rem_euclid(side) * side + x.rem_euclid(side);
        DVec3::from(texels[index as usize].map(f64::from))
    }

    /// Bilinear lookup of `level` at `(u, v)` (repeats): the texel grid position
    /// `(u size - 0.5, v size - 0.5)` between its four surrounding texel centres, wrapped.
    pub fn bilinear(&self, level: usize, (u, v): (f64, f64)) -> DVec3 {
        let side = f64::from(self.levels[level].0);
        let (x, y) = (u * side - 0.5, v * side - 0.5);
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let (x0, y0) = (x0 as i64, y0 as i64);
        let top = self.texel(level, x0, y0).lerp(self.texel(level, x0 + 1, y0), fx);
        let bottom = self
            .texel(level, x0, y0 + 1)
            .lerp(self.texel(level, x0 + 1, y0 + 1), fx);
        top.lerp(bottom, fy)
    }

    /// Trilinear lookup at `(u, v)` and level of detail `lod`: clamped to `[0, last]`, the
    /// bilinear lookups of levels `floor(lod)` and `floor(lod) + 1` mixed by the fraction.
    pub fn trilinear(&self, uv: (f64, f64), lod: f64) -> DVec3 {
        let lod = if lod.is_nan() {
            0.0
        } else {
            lod.clamp(0.0, self.last_level() as f64)
        };
        let lower = lod.floor() as usize;
        let fraction = lod - lower as f64;
        if fraction == 0.0 || lower == self.last_level() {
            return self.bilinear(lower, uv);
        }
        self.bilinear(lower, uv)
            .lerp(self.bilinear(lower + 1, uv), fraction)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trilinear_at_integer_levels_is_that_levels_bilinear_lookup() {
        let texture = Texture::procedural();
        for level in 0..=texture.last_level() {
            for uv in [(0.1234, 0.777), (-3.31, 2.05), (0.5, 0.5)] {
                assert_eq!(texture.trilinear(uv, level as f64), texture.bilinear(level, uv));
            }
        }
        let below_last = texture.last_level() as f64 + 3.0;
        assert_eq!(
            texture.trilinear((0.3, 0.2), below_last),
            texture.bilinear(texture.last_level(), (0.3, 0.2))
        );
        assert_eq!(
            texture.trilinear((0.3, 0.2), -2.0),
            texture.bilinear(0, (0.3, 0.2))
        );
    }

    /// The IEC 61966-2-1 decoding, written here independently of the crate's.
    fn srgb_decode(code: f32) -> f64 {
        let c = f64::from(code) / 255.0;
        if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    }

    #[test]
    fn every_mip_texel_is_the_linear_average_of_its_four_children() {
        let texture = Texture::procedural();
        assert_eq!(texture.levels.len(), 11);
        for level in 1..=texture.last_level() {
            let side = i64::from(texture.levels[level].0);
            assert_eq!(side, 1024 >> level);
            for (x, y) in [(0, 0), (side - 1, side / 2), (side / 3, side - 1)] {
                let children = [(0, 0), (1, 0), (0, 1), (1, 1)]
                    .map(|(dx, dy)| texture.texel(level - 1, 2 * x + dx, 2 * y + dy));
                let average = children.iter().sum::<DVec3>() / 4.0;
                let parent = texture.texel(level, x, y);
                // Each parent is rounded to 8-bit sRGB: at most half a code step off in sRGB,
                // whose slope in linear light is below 1.1 / 255 * 2.4.
                let tolerance = 0.5 / 255.0 * 2.4 * 1.1;
                assert!(
                    (parent - average).abs().max_element() < tolerance,
                    "level {level} ({x}, {y}): {parent} against {average}"
                );
            }
        }
        let decoded_white = srgb_decode(255.0);
        assert!((decoded_white - 1.0).abs() < 1e-12);
        let code = linear_to_srgb8(0.2);
        assert!((srgb_decode(f32::from(code)) - 0.2).abs() < 2e-3);
    }
}
