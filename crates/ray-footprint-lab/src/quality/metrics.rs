//! Image-quality metrics of a test image against a reference: PSNR (whole image or a mask),
//! SSIM, FLIP, the share of the reference's fine detail kept, and the mean change from frame to
//! frame of an image sequence.

use super::image::Image;
use crate::figure::RgbaImage;
use std::fmt;

/// Side of the SSIM window (Wang et al. 2004, Sec. III-C): 11 x 11 pixels.
pub const WINDOW: usize = 11;
/// Standard deviation of the SSIM window's Gaussian weights, in pixels (Wang et al. 2004).
pub const WINDOW_SIGMA: f64 = 1.5;
/// SSIM's K1 (Wang et al. 2004, Eq. 7): `C1 = (K1 L)^2` with dynamic range L = 1.
pub const SSIM_K1: f64 = 0.01;
/// SSIM's K2 (Wang et al. 2004, Eq. 9): `C2 = (K2 L)^2`.
pub const SSIM_K2: f64 = 0.03;
/// FLIP's viewing condition, pixels per degree of visual angle: the FLIP default (a 0.7 m
/// viewing distance from a 0.7 m wide 4K monitor).
pub const FLIP_PIXELS_PER_DEGREE: f32 = nv_flip::DEFAULT_PIXELS_PER_DEGREE;

/// Why a metric could not be computed.
#[derive(Clone, Debug, PartialEq)]
pub enum MetricError {
    /// The images (or a mask) differ in size.
    SizeMismatch {
        /// Width and height of the reference.
        reference: (u32, u32),
        /// Width and height (or pixel count, as `(count, 1)`) of the other.
        test: (u32, u32),
    },
    /// The mask selects no pixel.
    EmptyMask,
    /// The image is smaller than the [`WINDOW`].
    TooSmall {
        /// Width of the image.
        width: u32,
        /// Height of the image.
        height: u32,
    },
    /// The reference has no fine detail to keep (its high-pass energy is 0).
    FlatReference,
    /// A change from frame to frame needs at least two frames: the count given.
    TooFewFrames(usize),
}

impl fmt::Display for MetricError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MetricError::SizeMismatch { reference, test } => write!(
                f,
                "size mismatch: reference {} x {}, test {} x {}",
                reference.0, reference.1, test.0, test.1
            ),
            MetricError::EmptyMask => write!(f, "the mask selects no pixel"),
            MetricError::TooSmall { width, height } => write!(
                f,
                "a {width} x {height} image is smaller than the {WINDOW} x {WINDOW} window"
            ),
            MetricError::FlatReference => write!(f, "the reference has no high-frequency detail"),
            MetricError::TooFewFrames(count) => write!(f, "{count} frame(s): at least 2 are needed"),
        }
    }
}

impl std::error::Error for MetricError {}

fn same_size(reference: &Image, test: &Image) -> Result<(), MetricError> {
    if (reference.width, reference.height) == (test.width, test.height) {
        Ok(())
    } else {
        Err(MetricError::SizeMismatch {
            reference: (reference.width, reference.height),
            test: (test.width, test.height),
        })
    }
}

/// Peak signal-to-noise ratio in dB of `test` against `reference`, over the pixels `mask`
/// selects (all without one): `10 log10(1 / MSE)`, the MSE over the selected pixels' three
/// display-value channels (peak 1). Identical images give `f64::INFINITY`.
pub fn psnr(reference: &Image, test: &Image, mask: Option<&[bool]>) -> Result<f64, MetricError> {
    same_size(reference, test)?;
    if let Some(mask) = mask {
        if mask.len() != reference.len() {
            return Err(MetricError::SizeMismatch {
                reference: (reference.width, reference.height),
                test: (mask.len() as u32, 1),
            });
        }
    }
    let (mut squares, mut count) = (0.0f64, 0usize);
    for (index, (r, t)) in reference.pixels.iter().zip(&test.pixels).enumerate() {
        if mask.is_none_or(|m| m[index]) {
            squares += (0..3).map(|c| f64::from(r[c] - t[c]).powi(2)).sum::<f64>();
            count += 3;
        }
    }
    if count == 0 {
        return Err(MetricError::EmptyMask);
    }
    Ok(10.0 * (count as f64 / squares).log10())
}

/// The normalized 1-D Gaussian of the window (the 2-D window is its outer product).
fn gaussian_weights() -> [f64; WINDOW] {
    let centre = (WINDOW / 2) as f64;
    let raw: [f64; WINDOW] =
        std::array::from_fn(|i| (-((i as f64 - centre).powi(2)) / (2.0 * WINDOW_SIGMA * WINDOW_SIGMA)).exp());
    let sum: f64 = raw.iter().sum();
    raw.map(|w| w / sum)
}

/// A plane of values with its size.
struct Plane {
    width: usize,
    height: usize,
    values: Vec<f64>,
}

/// `plane` filtered with the Gaussian window where the window fits inside (a "valid"
/// convolution): `(width - 10) x (height - 10)` values, one per window centre.
fn blur_valid(plane: &Plane) -> Plane {
    let weights = gaussian_weights();
    let (width, height) = (plane.width + 1 - WINDOW, plane.height + 1 - WINDOW);
    let mut rows = vec![0.0; width * plane.height];
    for y in 0..plane.height {
        for x in 0..width {
            let start = y * plane.width + x;
            rows[y * width + x] = (0..WINDOW).map(|k| weights[k] * plane.values[start + k]).sum();
        }
    }
    let mut values = vec![0.0; width * height];
    for y in 0..height {
        for x in 0..width {
            values[y * width + x] = (0..WINDOW).map(|k| weights[k] * rows[(y + k) * width + x]).sum();
        }
    }
    Plane {
        width,
        height,
        values,
    }
}

/// The luma planes of both images, checked to be the same size and at least a window large.
fn luma_planes(reference: &Image, test: &Image) -> Result<(Plane, Plane), MetricError> {
    same_size(reference, test)?;
    let (width, height) = (reference.width as usize, reference.height as usize);
    if width < WINDOW || height < WINDOW {
        return Err(MetricError::TooSmall {
            width: reference.width,
            height: reference.height,
        });
    }
    let plane = |image: &Image| Plane {
        width,
        height,
        values: image.luma().into_iter().map(f64::from).collect(),
    };
    Ok((plane(reference), plane(test)))
}

/// A plane of pointwise products.
fn product(a: &Plane, b: &Plane) -> Plane {
    Plane {
        width: a.width,
        height: a.height,
        values: a.values.iter().zip(&b.values).map(|(x, y)| x * y).collect(),
    }
}

/// Mean structural similarity (MSSIM) of the luma of `test` against `reference` (Z. Wang,
/// A. C. Bovik, H. R. Sheikh, E. P. Simoncelli, "Image Quality Assessment: From Error Visibility
/// to Structural Similarity", IEEE TIP 13(4), 2004): per window position, Eq. 13
/// `((2 mu_x mu_y + C1)(2 sigma_xy + C2)) / ((mu_x^2 + mu_y^2 + C1)(sigma_x^2 + sigma_y^2 + C2))`
/// with the local statistics weighted by an 11 x 11 Gaussian of sigma 1.5 (Sec. III-C, Eq. 14-16),
/// `C1 = (0.01 L)^2`, `C2 = (0.03 L)^2`, L = 1; averaged over every position where the window
/// fits (Eq. 17). Luma is BT.709 of the display values. 1 for identical images.
pub fn ssim(reference: &Image, test: &Image) -> Result<f64, MetricError> {
    let (x, y) = luma_planes(reference, test)?;
    let (mu_x, mu_y) = (blur_valid(&x), blur_valid(&y));
    let (xx, yy, xy) = (
        blur_valid(&product(&x, &x)),
        blur_valid(&product(&y, &y)),
        blur_valid(&product(&x, &y)),
    );
    let (c1, c2) = (SSIM_K1 * SSIM_K1, SSIM_K2 * SSIM_K2);
    let total: f64 = (0..mu_x.values.len())
        .map(|i| {
            let (mx, my) = (mu_x.values[i], mu_y.values[i]);
            let var_x = xx.values[i] - mx * mx;
            let var_y = yy.values[i] - my * my;
            let cov = xy.values[i] - mx * my;
            ((2.0 * mx * my + c1) * (2.0 * cov + c2)) / ((mx * mx + my * my + c1) * (var_x + var_y + c2))
        })
        .sum();
    Ok(total / mu_x.values.len() as f64)
}

/// The share of the reference's fine detail that `test` keeps: with `h(I)` the luma of I minus
/// its blur by the SSIM window (11 x 11 Gaussian, sigma 1.5: what varies over a few pixels), at
/// every pixel where the window fits, `sum h(test) h(reference) / sum h(reference)^2`. The
/// projection of the test's detail onto the reference's: 1 keeps all of it, 0 none (a blur of
/// everything), and detail the reference lacks (aliasing, noise) does not count as kept. Above
/// 1, the test has the reference's detail with more contrast than the reference (unfiltered
/// point samples, as mip 0 takes, where the reference averages several texels).
pub fn detail_kept(reference: &Image, test: &Image) -> Result<f64, MetricError> {
    let (x, y) = luma_planes(reference, test)?;
    let (blur_x, blur_y) = (blur_valid(&x), blur_valid(&y));
    let offset = WINDOW / 2;
    let (mut kept, mut energy) = (0.0, 0.0);
    for row in 0..blur_x.height {
        for column in 0..blur_x.width {
            let full = (row + offset) * x.width + column + offset;
            let blurred = row * blur_x.width + column;
            let high_x = x.values[full] - blur_x.values[blurred];
            let high_y = y.values[full] - blur_y.values[blurred];
            kept += high_y * high_x;
            energy += high_x * high_x;
        }
    }
    if energy == 0.0 {
        return Err(MetricError::FlatReference);
    }
    Ok(kept / energy)
}

/// A FLIP error map: per pixel, the perceived difference, 0 (none) to 1.
#[derive(Clone, Debug, PartialEq)]
pub struct FlipMap {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Error per pixel, row by row from the top.
    pub values: Vec<f32>,
}

impl FlipMap {
    /// The mean error: the single number the FLIP authors recommend.
    pub fn mean(&self) -> f64 {
        self.values.iter().map(|&v| f64::from(v)).sum::<f64>() / self.values.len().max(1) as f64
    }

    /// The map in FLIP's magma colour map (black: no error, yellow-white: the largest).
    pub fn to_rgba(&self) -> RgbaImage {
        let map = nv_flip::FlipImageFloat::with_data(self.width, self.height, &self.values);
        let rgb = map.apply_color_lut(&nv_flip::magma_lut()).to_vec();
        RgbaImage {
            width: self.width,
            height: self.height,
            pixels: rgb.chunks_exact(3).map(|p| [p[0], p[1], p[2], 255]).collect(),
        }
    }
}

/// FLIP (P. Andersson, J. Nilsson, T. Akenine-Moller, M. Oskarsson, K. Astrom, M. D. Fairchild,
/// "FLIP: A Difference Evaluator for Alternating Images", HPG 2020; LDR-FLIP) of `test` against
/// `reference`, both rounded to 8-bit sRGB as the `nv-flip` bindings take them, at
/// [`FLIP_PIXELS_PER_DEGREE`].
pub fn flip(reference: &Image, test: &Image) -> Result<FlipMap, MetricError> {
    same_size(reference, test)?;
    let image = |i: &Image| nv_flip::FlipImageRgb8::with_data(i.width, i.height, &i.to_rgb8());
    let map = nv_flip::flip(image(reference), image(test), FLIP_PIXELS_PER_DEGREE);
    Ok(FlipMap {
        width: reference.width,
        height: reference.height,
        values: map.to_vec(),
    })
}

/// The mean change from one frame to the next, in 8-bit levels: over every consecutive pair,
/// the mean absolute difference of the display values over all pixels and channels, times 255,
/// averaged over the pairs.
pub fn mean_change(frames: &[Image]) -> Result<f64, MetricError> {
    if frames.len() < 2 {
        return Err(MetricError::TooFewFrames(frames.len()));
    }
    let mut total = 0.0;
    for pair in frames.windows(2) {
        same_size(&pair[0], &pair[1])?;
        let differences: f64 = pair[0]
            .pixels
            .iter()
            .zip(&pair[1].pixels)
            .map(|(a, b)| (0..3).map(|c| f64::from((a[c] - b[c]).abs())).sum::<f64>())
            .sum();
        total += 255.0 * differences / (3 * pair[0].len()) as f64;
    }
    Ok(total / (frames.len() - 1) as f64)
}
