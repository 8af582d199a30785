//! Images in display values and the linear-light sums the ground truth averages.

use crate::figure::RgbaImage;
use crate::rt::Frame;

/// The display encoding of the renderer's colours: `display = linear^(1 / GAMMA)` (`raygen.rgen`).
pub const GAMMA: f32 = 2.2;

/// An RGB image in display values (gamma 2.2, 0 to 1, as the renderer writes them before
/// rounding to 8 bits), row by row from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height` RGB triples.
    pub pixels: Vec<[f32; 3]>,
}

impl Image {
    /// The colours of a traced frame: each 8-bit channel over 255.
    pub fn from_frame(frame: &Frame) -> Image {
        let pixels = frame
            .pixels
            .iter()
            .map(|p| [0, 1, 2].map(|c| f32::from(p[c]) / 255.0))
            .collect();
        Image {
            width: frame.width,
            height: frame.height,
            pixels,
        }
    }

    /// Number of pixels.
    pub fn len(&self) -> usize {
        self.pixels.len()
    }

    /// Whether the image has no pixels.
    pub fn is_empty(&self) -> bool {
        self.pixels.is_empty()
    }

    /// The image rounded to 8 bits per channel, RGB (what FLIP and PNG files take).
    pub fn to_rgb8(&self) -> Vec<u8> {
        self.pixels.iter().flat_map(|p| p.map(to_byte)).collect()
    }

    /// The image rounded to 8 bits per channel, opaque RGBA.
    pub fn to_rgba(&self) -> RgbaImage {
        let pixels = self.pixels.iter().map(|p| {
            let [r, g, b] = p.map(to_byte);
            [r, g, b, 255]
        });
        RgbaImage {
            width: self.width,
            height: self.height,
            pixels: pixels.collect(),
        }
    }

    /// Luma of each pixel from the display values, ITU-R BT.709 weights.
    pub fn luma(&self) -> Vec<f32> {
        self.pixels
            .iter()
            .map(|p| 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2])
            .collect()
    }
}

/// A display value in 0..1 rounded to 8 bits.
fn to_byte(value: f32) -> u8 {
    (value.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// A running sum of frames in linear light, for a box-filtered average of sub-pixel samples.
#[derive(Clone, Debug)]
pub struct LinearSum {
    width: u32,
    height: u32,
    sums: Vec<[f64; 3]>,
    count: u32,
    /// Linear value of each 8-bit display value.
    decode: [f64; 256],
}

impl LinearSum {
    /// An empty sum of `width` x `height` frames.
    pub fn new(width: u32, height: u32) -> LinearSum {
        let decode = std::array::from_fn(|byte| (byte as f64 / 255.0).powf(f64::from(GAMMA)));
        LinearSum {
            width,
            height,
            sums: vec![[0.0; 3]; (width * height) as usize],
            count: 0,
            decode,
        }
    }

    /// Adds a frame of the same size (its 8-bit colours decoded to linear light).
    pub fn add(&mut self, frame: &Frame) {
        debug_assert_eq!((frame.width, frame.height), (self.width, self.height));
        for (sum, pixel) in self.sums.iter_mut().zip(&frame.pixels) {
            for c in 0..3 {
                sum[c] += self.decode[pixel[c] as usize];
            }
        }
        self.count += 1;
    }

    /// Adds another sum of the same size.
    pub fn add_sum(&mut self, other: &LinearSum) {
        for (sum, more) in self.sums.iter_mut().zip(&other.sums) {
            for c in 0..3 {
                sum[c] += more[c];
            }
        }
        self.count += other.count;
    }

    /// The mean of the frames added, encoded for display (`mean^(1 / GAMMA)`), not rounded.
    pub fn mean(&self) -> Image {
        let count = f64::from(self.count.max(1));
        let encode = |linear: f64| (linear / count).powf(1.0 / f64::from(GAMMA)) as f32;
        Image {
            width: self.width,
            height: self.height,
            pixels: self.sums.iter().map(|s| s.map(encode)).collect(),
        }
    }
}
