//! The mip chains of `ray_footprint::mip` against a reference filter computed another way: each
//! level against the mean of each texel's footprint taken from a summed-area table of the level
//! above as stored, in f64, with sRGB's transfer function evaluated in f64 too. Every level of
//! every chain agrees to the last bit the 8-bit or half-float encoding can hold (one step where the
//! two land on either side of a rounding boundary), for square, odd, thin and one-texel textures.

use half::f16;
use ray_footprint::mip::{mip_chain_rgba16f, mip_chain_rgba8_srgb, mip_level_count, MipLevel};

/// A texture of `width x height` texels with channels from a fixed pseudo-random sequence.
fn noise(width: u32, height: u32, seed: u64) -> Vec<[f64; 4]> {
    let mut state = seed;
    let mut next = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..width * height)
        .map(|_| [next(), next(), next(), next()])
        .collect()
}

/// The mean of `level` (`width x height`, row by row) over the rectangle `[x0, x1) x [y0, y1)`,
/// from its summed-area table, which is bilinear between texel corners: exact for a box of any
/// size and position.
fn box_mean(level: &[[f64; 4]], width: usize, height: usize, rectangle: [f64; 4]) -> [f64; 4] {
    let mut table = vec![[0.0f64; 4]; (width + 1) * (height + 1)];
    for y in 0..height {
        for x in 0..width {
            for c in 0..4 {
                table[(y + 1) * (width + 1) + x + 1][c] = level[y * width + x][c]
                    + table[y * (width + 1) + x + 1][c]
                    + table[(y + 1) * (width + 1) + x][c]
                    - table[y * (width + 1) + x][c];
            }
        }
    }
    let corner = |x: f64, y: f64, c: usize| {
        let (x0, y0) = (
            (x.floor() as usize).min(width - 1),
            (y.floor() as usize).min(height - 1),
        );
        let (fx, fy) = (x - x0 as f64, y - y0 as f64);
        let at = |i: usize, j: usize| table[(y0 + j) * (width + 1) + x0 + i][c];
        at(0, 0) * (1.0 - fx) * (1.0 - fy)
            + at(1, 0) * fx * (1.0 - fy)
            + at(0, 1) * (1.0 - fx) * fy
            + at(1, 1) * fx * fy
    };
    let [x0, x1, y0, y1] = rectangle;
    let area = (x1 - x0) * (y1 - y0);
    [0, 1, 2, 3]
        .map(|c| (corner(x1, y1, c) - corner(x0, y1, c) - corner(x1, y0, c) + corner(x0, y0, c)) / area)
}

/// The reference filter of one level (linear texels, `width x height`): the next level's linear
/// texels.
fn reference_level(width: u32, height: u32, linear: &[[f64; 4]]) -> Vec<[f64; 4]> {
    let (w, h) = (width as usize, height as usize);
    let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
    let (sx, sy) = (w as f64 / nw as f64, h as f64 / nh as f64);
    (0..nh)
        .flat_map(|y| (0..nw).map(move |x| (x, y)))
        .map(|(x, y)| {
            box_mean(
                linear,
                w,
                h,
                [
                    x as f64 * sx,
                    (x + 1) as f64 * sx,
                    y as f64 * sy,
                    (y + 1) as f64 * sy,
                ],
            )
        })
        .collect()
}

fn srgb_decode(value: u8) -> f64 {
    let v = f64::from(value) / 255.0;
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

fn srgb_encode(linear: f64) -> f64 {
    let l = linear.clamp(0.0, 1.0);
    255.0
        * if l <= 0.0031308 {
            12.92 * l
        } else {
            1.055 * l.powf(1.0 / 2.4) - 0.055
        }
}

const SIZES: [(u32, u32); 6] = [(8, 8), (7, 5), (64, 48), (1, 13), (130, 3), (1, 1)];

fn srgb_linear(texel: &[u8; 4]) -> [f64; 4] {
    [
        srgb_decode(texel[0]),
        srgb_decode(texel[1]),
        srgb_decode(texel[2]),
        f64::from(texel[3]) / 255.0,
    ]
}

#[test]
fn srgb_chains_follow_the_reference_filter() {
    for (index, &(width, height)) in SIZES.iter().enumerate() {
        let texels: Vec<[u8; 4]> = noise(width, height, index as u64)
            .iter()
            .map(|t| t.map(|x| (x * 255.0).round() as u8))
            .collect();
        let chain = mip_chain_rgba8_srgb(width, height, &texels).expect("a valid texture");
        assert_eq!(chain.len() as u32, mip_level_count(width, height));
        let mut worst = 0.0f64;
        for (level, pair) in chain.windows(2).enumerate() {
            let above: Vec<[f64; 4]> = pair[0].texels.iter().map(srgb_linear).collect();
            let reference = reference_level(pair[0].width, pair[0].height, &above);
            for (texel, (got, want)) in pair[1].texels.iter().zip(&reference).enumerate() {
                let exact = [
                    srgb_encode(want[0]),
                    srgb_encode(want[1]),
                    srgb_encode(want[2]),
                    255.0 * want[3],
                ];
                for c in 0..4 {
                    let error = (f64::from(got[c]) - exact[c]).abs();
                    worst = worst.max(error);
                    // Half a step of rounding, and as much again where the f32 filter and the
                    // f64 reference fall on either side of a rounding boundary.
                    assert!(
                        error <= 1.0,
                        "{width} x {height}, level {}, texel {texel}, channel {c}: {} against {}",
                        level + 1,
                        got[c],
                        exact[c]
                    );
                }
            }
        }
        println!(
            "RGBA8 sRGB {width} x {height}: {} levels, largest difference {worst:.3} of an 8-bit step",
            chain.len()
        );
    }
}

#[test]
fn half_float_chains_follow_the_reference_filter() {
    for (index, &(width, height)) in SIZES.iter().enumerate() {
        let texels: Vec<[u16; 4]> = noise(width, height, 100 + index as u64)
            .iter()
            .map(|t| t.map(|x| f16::from_f64(8.0 * x - 2.0).to_bits()))
            .collect();
        let chain: Vec<MipLevel<u16>> = mip_chain_rgba16f(width, height, &texels).expect("a valid texture");
        let mut worst = 0.0f64;
        for (level, pair) in chain.windows(2).enumerate() {
            let above: Vec<[f64; 4]> = pair[0]
                .texels
                .iter()
                .map(|t| t.map(|bits| f64::from(f16::from_bits(bits))))
                .collect();
            let reference = reference_level(pair[0].width, pair[0].height, &above);
            for (got, want) in pair[1].texels.iter().zip(&reference) {
                for c in 0..4 {
                    let value = f64::from(f16::from_bits(got[c]));
                    // Half a half-float step (2^-11 relative) of rounding, and as much again
                    // across a rounding boundary, as for 8 bits.
                    let step = f64::from(f16::EPSILON) * want[c].abs().max(f64::from(f16::MIN_POSITIVE));
                    worst = worst.max((value - want[c]).abs() / step);
                    assert!(
                        (value - want[c]).abs() <= step,
                        "{width} x {height}, level {}: {value} against {}",
                        level + 1,
                        want[c]
                    );
                }
            }
        }
        println!(
            "RGBA16 float {width} x {height}: {} levels, largest difference {worst:.3} of a half-float step",
            chain.len()
        );
    }
}

/// A texture of one colour keeps it at every level, to the bit.
#[test]
fn a_flat_texture_stays_flat() {
    let texels = vec![[200u8, 17, 90, 128]; 37 * 11];
    for level in mip_chain_rgba8_srgb(37, 11, &texels).expect("a valid texture") {
        assert!(
            level.texels.iter().all(|&t| t == [200, 17, 90, 128]),
            "{}x{}",
            level.width,
            level.height
        );
    }
}
