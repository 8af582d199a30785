//! Mip chains for the textures a LOD samples: every function of this crate that returns a LOD
//! or gradients assumes the texture has one.
//!
//! A texture LOD only changes what a sampler returns when the texture has its mip levels and the
//! sampler filters between them: a full chain (`mip_level_count(width, height)` levels, each half
//! the size of the one above, rounded down, to 1 x 1), a sampler with linear minification and mipmap
//! filters (`FilterMode::Linear` / `MipmapFilterMode::Linear` in wgpu, `VK_FILTER_LINEAR` and
//! `VK_SAMPLER_MIPMAP_MODE_LINEAR` in Vulkan), and a LOD clamp that lets it reach the last level
//! (wgpu's default `lod_max_clamp` of 32; `VK_LOD_CLAMP_NONE` in Vulkan, whose `maxLod = 0` samples
//! mip 0 only). A LOD at or below 0 samples mip 0 (magnification): nothing is lost by clamping.
//!
//! Each level here is the box filter of the level above over the exact area each of its texels
//! covers: the 2 x 2 average for even sizes, weights of 1, 1 and 1/2 along an odd side (a width of 5
//! becomes 2, each new texel covering 2.5 old ones). Colours are averaged as light, not as
//! numbers: sRGB texels are decoded to linear values first and encoded after, alpha is linear.
//!
//! ```
//! use ray_footprint::mip::{mip_chain_rgba8_srgb, mip_level_count};
//!
//! // A 4 x 2 texture, black and white columns: every level below is mid grey as light, which sRGB
//! // encodes as 188, not 128.
//! let texels: Vec<[u8; 4]> = (0..8).map(|i| if i % 2 == 0 { [0, 0, 0, 255] } else { [255; 4] }).collect();
//! let chain = mip_chain_rgba8_srgb(4, 2, &texels)?;
//! assert_eq!(chain.len() as u32, mip_level_count(4, 2));
//! assert_eq!((chain[1].width, chain[1].height), (2, 1));
//! assert_eq!(chain[2].texels, vec![[188, 188, 188, 255]]);
//! # Ok::<(), ray_footprint::mip::MipError>(())
//! ```
//!
//! With the feature `wgpu`, [`crate::wgpu::generate_mipmaps`] fills the levels of a texture on
//! the GPU with the same filter.

use std::fmt;

/// One mip level: `width x height` RGBA texels, row by row from the top.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MipLevel<T> {
    /// Texels per row.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// The texels, `width * height` of them.
    pub texels: Vec<[T; 4]>,
}

/// Why a mip chain was not made.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum MipError {
    /// A dimension is 0.
    Size {
        /// `width` or `height`.
        field: &'static str,
        /// Its value.
        value: u32,
    },
    /// The texel count is not `width * height`.
    Texels {
        /// Texels given.
        count: usize,
        /// Texels expected.
        expected: u64,
    },
    /// A GPU texture the levels cannot be rendered into ([`crate::wgpu::generate_mipmaps`]).
    Texture {
        /// The texture descriptor's field.
        field: &'static str,
        /// Its value.
        value: String,
        /// What it must be.
        expected: &'static str,
    },
}

impl fmt::Display for MipError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MipError::Size { field, value } => write!(f, "mip chain: {field} = {value}: expected at least 1"),
            MipError::Texels { count, expected } => write!(
                f,
                "mip chain: texels = {count}: expected width * height = {expected}"
            ),
            MipError::Texture {
                field,
                value,
                expected,
            } => {
                write!(f, "mip chain: texture {field} = {value}: expected {expected}")
            }
        }
    }
}

impl std::error::Error for MipError {}

/// Levels of a full mip chain of a `width x height` texture, the texture itself included:
/// `floor(log2(max(width, height))) + 1` (1 for 0).
///
/// ```
/// use ray_footprint::mip::mip_level_count;
///
/// assert_eq!(mip_level_count(4096, 4096), 13);
/// assert_eq!(mip_level_count(640, 480), 10); // 640 320 160 80 40 20 10 5 2 1
/// ```
pub fn mip_level_count(width: u32, height: u32) -> u32 {
    32 - (width.max(height).max(1)).leading_zeros()
}

/// The full mip chain of an sRGB RGBA8 texture (`Rgba8UnormSrgb`), level 0 first (the texture
/// itself): each level the area-weighted box filter of the one above, colours averaged as linear
/// light (IEC 61966-2-1's transfer function), alpha as stored, rounded to the nearest 8-bit value.
/// An error names a zero dimension, or a texel count that is not `width * height`.
pub fn mip_chain_rgba8_srgb(
    width: u32,
    height: u32,
    texels: &[[u8; 4]],
) -> Result<Vec<MipLevel<u8>>, MipError> {
    mip_chain(width, height, texels, decode_srgb8, encode_srgb8)
}

/// The full mip chain of a half-float RGBA texture (`Rgba16Float`; each texel four IEEE 754
/// binary16 values as bits), level 0 first: each level the area-weighted box filter of the one
/// above, every channel averaged as stored (linear), rounded to the nearest half float. An error
/// names a zero dimension, or a texel count that is not `width * height`.
pub fn mip_chain_rgba16f(
    width: u32,
    height: u32,
    texels: &[[u16; 4]],
) -> Result<Vec<MipLevel<u16>>, MipError> {
    mip_chain(width, height, texels, decode_f16, encode_f16)
}

/// The chain of a texture whose texels `decode` to linear RGBA and `encode` back.
fn mip_chain<T: Copy>(
    width: u32,
    height: u32,
    texels: &[[T; 4]],
    decode: fn([T; 4]) -> [f32; 4],
    encode: fn([f32; 4]) -> [T; 4],
) -> Result<Vec<MipLevel<T>>, MipError> {
    for (field, value) in [("width", width), ("height", height)] {
        if value == 0 {
            return Err(MipError::Size { field, value });
        }
    }
    let expected = u64::from(width) * u64::from(height);
    if texels.len() as u64 != expected {
        return Err(MipError::Texels {
            count: texels.len(),
            expected,
        });
    }
    let mut levels = vec![MipLevel {
        width,
        height,
        texels: texels.to_vec(),
    }];
    while let Some(above) = levels.last().filter(|level| level.width > 1 || level.height > 1) {
        let linear: Vec<[f32; 4]> = above.texels.iter().map(|&texel| decode(texel)).collect();
        let (width, height) = ((above.width / 2).max(1), (above.height / 2).max(1));
        let filtered = downsample(&linear, (above.width, above.height), (width, height));
        levels.push(MipLevel {
            width,
            height,
            texels: filtered.into_iter().map(encode).collect(),
        });
    }
    Ok(levels)
}

/// The texels of a row or column of `from` texels that texel `index` of a row or column of `to`
/// covers, each with the share of the new texel it makes up: texel `index` spans
/// `[index, index + 1) * from / to`, so texel `t` makes up `|[t, t + 1) ∩ that span| * to / from`
/// of it, computed exactly in integers (in units of `1 / to`) and rounded once. The shares sum to 1.
pub fn footprint_weights(index: u32, from: u32, to: u32) -> Vec<(u32, f32)> {
    let (from, to) = (u64::from(from), u64::from(to.max(1)));
    let (start, end) = (u64::from(index) * from, (u64::from(index) + 1) * from);
    (start / to..end.div_ceil(to).min(from))
        .map(|texel| {
            let covered = end.min((texel + 1) * to) - start.max(texel * to);
            (texel as u32, (covered as f64 / from as f64) as f32)
        })
        .filter(|&(_, weight)| weight > 0.0)
        .collect()
}

/// The box filter of `level` (`size`, linear RGBA) down to `next` texels.
fn downsample(level: &[[f32; 4]], size: (u32, u32), next: (u32, u32)) -> Vec<[f32; 4]> {
    let mut out = Vec::with_capacity((next.0 * next.1) as usize);
    for y in 0..next.1 {
        let rows = footprint_weights(y, size.1, next.1);
        for x in 0..next.0 {
            let columns = footprint_weights(x, size.0, next.0);
            let mut sum = [0.0f32; 4];
            for &(row, row_weight) in &rows {
                for &(column, column_weight) in &columns {
                    let texel = level[(row * size.0 + column) as usize];
                    let weight = row_weight * column_weight;
                    (0..4).for_each(|channel| sum[channel] += weight * texel[channel]);
                }
            }
            out.push(sum);
        }
    }
    out
}

/// sRGB's transfer function undone: the linear light of an 8-bit sRGB value (IEC 61966-2-1).
pub fn srgb_to_linear(value: u8) -> f32 {
    let encoded = f32::from(value) / 255.0;
    if encoded <= 0.04045 {
        encoded / 12.92
    } else {
        ((encoded + 0.055) / 1.055).powf(2.4)
    }
}

/// sRGB's transfer function: the 8-bit sRGB value nearest to linear light `value` (clamped to
/// `[0, 1]`; NaN gives 0).
pub fn linear_to_srgb(value: f32) -> u8 {
    let linear = if value.is_nan() {
        0.0
    } else {
        value.clamp(0.0, 1.0)
    };
    let encoded = if linear <= 0.003_130_8 {
        12.92 * linear
    } else {
        1.055 * linear.powf(1.0 / 2.4) - 0.055
    };
    (encoded * 255.0).round() as u8
}

fn decode_srgb8(texel: [u8; 4]) -> [f32; 4] {
    let [r, g, b, a] = texel;
    [
        srgb_to_linear(r),
        srgb_to_linear(g),
        srgb_to_linear(b),
        f32::from(a) / 255.0,
    ]
}

fn encode_srgb8(texel: [f32; 4]) -> [u8; 4] {
    let [r, g, b, a] = texel;
    let alpha = (a.clamp(0.0, 1.0) * 255.0).round() as u8;
    [linear_to_srgb(r), linear_to_srgb(g), linear_to_srgb(b), alpha]
}

fn decode_f16(texel: [u16; 4]) -> [f32; 4] {
    texel.map(|bits| half::f16::from_bits(bits).to_f32())
}

fn encode_f16(texel: [f32; 4]) -> [u16; 4] {
    texel.map(|value| half::f16::from_f32(value).to_bits())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A texel of an even side covers two, of an odd one two and a half; the weights sum to 1.
    #[test]
    fn footprints_cover_their_area() {
        assert_eq!(footprint_weights(1, 4, 2), vec![(2, 0.5), (3, 0.5)]);
        assert_eq!(footprint_weights(0, 5, 2), vec![(0, 0.4), (1, 0.4), (2, 0.2)]);
        assert_eq!(footprint_weights(1, 5, 2), vec![(2, 0.2), (3, 0.4), (4, 0.4)]);
        assert_eq!(footprint_weights(0, 1, 1), vec![(0, 1.0)]);
        for (from, to) in [(7, 3), (1023, 511), (3, 1), (640, 320)] {
            for index in 0..to {
                let sum: f32 = footprint_weights(index, from, to).iter().map(|w| w.1).sum();
                assert!((sum - 1.0).abs() < 1e-5, "{from} -> {to}, texel {index}: {sum}");
            }
        }
    }

    /// Every 8-bit sRGB value survives decoding and encoding.
    #[test]
    fn srgb_round_trips() {
        for value in 0..=255u8 {
            assert_eq!(linear_to_srgb(srgb_to_linear(value)), value);
        }
    }
}
