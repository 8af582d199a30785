//! Figures: images laid out side by side, each panel under a caption drawn in DejaVu Sans (the
//! `dejavu` crate embeds the font; `ab_glyph` rasterizes it), and PNG files.
//!
//! ```
//! use ray_footprint_lab::figure::{Panel, RgbaImage};
//!
//! let red = RgbaImage::filled(64, 32, [200, 30, 30, 255]);
//! let blue = RgbaImage::filled(64, 32, [30, 30, 200, 255]);
//! let row = ray_footprint_lab::figure::grid(&[vec![
//!     Panel::new("red", red),
//!     Panel::new("blue", blue),
//! ]])?;
//! assert_eq!(row.width, 2 * 64 + ray_footprint_lab::figure::GAP);
//! # Ok::<(), ray_footprint_lab::figure::FigureError>(())
//! ```

use ab_glyph::{point, Font, FontRef, PxScale, ScaleFont};
use std::fmt;
use std::path::Path;

/// Gap between panels and between rows, in pixels (white).
pub const GAP: u32 = 4;
/// Caption text height in pixels, shrunk to fit a narrow panel down to [`MIN_CAPTION_PX`].
pub const CAPTION_PX: f32 = 15.0;
/// The smallest caption text height a narrow panel gets, in pixels: still legible.
pub const MIN_CAPTION_PX: f32 = 10.0;
/// Space above and below a caption's text, in pixels.
const CAPTION_MARGIN: u32 = 3;
/// Caption text colour (RGB).
const INK: [u8; 3] = [20, 20, 20];

/// An RGBA8 image, row by row from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct RgbaImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height` pixels.
    pub pixels: Vec<[u8; 4]>,
}

impl RgbaImage {
    /// An image of one colour.
    pub fn filled(width: u32, height: u32, colour: [u8; 4]) -> RgbaImage {
        RgbaImage {
            width,
            height,
            pixels: vec![colour; (width * height) as usize],
        }
    }

    /// The colours of a traced frame.
    pub fn from_frame(frame: &crate::rt::Frame) -> RgbaImage {
        RgbaImage {
            width: frame.width,
            height: frame.height,
            pixels: frame.pixels.clone(),
        }
    }

    /// The `width` x `height` part whose top-left pixel is `(left, top)`, each pixel repeated
    /// `zoom` x `zoom` times (nearest neighbour, so single pixels stay visible). Parts outside the
    /// image are white.
    pub fn crop(&self, (left, top): (u32, u32), (width, height): (u32, u32), zoom: u32) -> RgbaImage {
        let zoom = zoom.max(1);
        let mut out = RgbaImage::filled(width * zoom, height * zoom, [255; 4]);
        for y in 0..out.height {
            for x in 0..out.width {
                let (sx, sy) = (left + x / zoom, top + y / zoom);
                if sx < self.width && sy < self.height {
                    out.pixels[(y * out.width + x) as usize] = self.pixels[(sy * self.width + sx) as usize];
                }
            }
        }
        out
    }

    /// The part `fraction` (left, top, width and height, as fractions of the image's size) of
    /// the image, magnified `zoom` times as [`RgbaImage::crop`] does.
    pub fn crop_part(&self, fraction: [f32; 4], zoom: u32) -> RgbaImage {
        let (w, h) = (self.width as f32, self.height as f32);
        let corner = ((fraction[0] * w) as u32, (fraction[1] * h) as u32);
        let size = (
            ((fraction[2] * w) as u32).max(1),
            ((fraction[3] * h) as u32).max(1),
        );
        self.crop(corner, size, zoom)
    }

    /// Copies `image` into this one with its top-left pixel at `(left, top)`, clipped.
    fn paste(&mut self, image: &RgbaImage, (left, top): (u32, u32)) {
        for y in 0..image.height.min(self.height.saturating_sub(top)) {
            for x in 0..image.width.min(self.width.saturating_sub(left)) {
                self.pixels[((top + y) * self.width + left + x) as usize] =
                    image.pixels[(y * image.width + x) as usize];
            }
        }
    }

    /// Blends `colour` over the pixel at `(x, y)` with weight `coverage` (0 to 1); outside: nothing.
    fn blend(&mut self, (x, y): (i32, i32), colour: [u8; 3], coverage: f32) {
        if x < 0 || y < 0 || x as u32 >= self.width || y as u32 >= self.height {
            return;
        }
        let pixel = &mut self.pixels[(y as u32 * self.width + x as u32) as usize];
        let weight = coverage.clamp(0.0, 1.0);
        for (channel, &ink) in pixel.iter_mut().zip(&colour) {
            *channel = (f32::from(*channel) * (1.0 - weight) + f32::from(ink) * weight).round() as u8;
        }
    }

    /// The RGBA bytes, row by row.
    pub fn bytes(&self) -> &[u8] {
        bytemuck::cast_slice(&self.pixels)
    }
}

/// One panel of a figure: an image and the caption above it.
#[derive(Clone, Debug)]
pub struct Panel {
    /// The text above the image (one line).
    pub caption: String,
    /// The image.
    pub image: RgbaImage,
}

impl Panel {
    /// A panel of `image` under `caption`.
    pub fn new(caption: impl Into<String>, image: RgbaImage) -> Panel {
        Panel {
            caption: caption.into(),
            image,
        }
    }
}

/// Why a figure was not made or written.
#[derive(Debug)]
pub enum FigureError {
    /// A figure without panels, or a row without panels.
    Empty,
    /// The embedded font did not parse (a broken `dejavu` crate).
    Font,
    /// Writing the PNG failed: the path and the reason.
    Write(String),
}

impl fmt::Display for FigureError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FigureError::Empty => write!(f, "a figure needs at least one panel in every row"),
            FigureError::Font => write!(f, "the embedded DejaVu Sans font does not parse"),
            FigureError::Write(reason) => write!(f, "{reason}"),
        }
    }
}

impl std::error::Error for FigureError {}

/// DejaVu Sans (regular), from the `dejavu` crate (Bitstream Vera licence, permissive).
pub fn font_bytes() -> &'static [u8] {
    dejavu::sans::regular()
}

fn font() -> Result<FontRef<'static>, FigureError> {
    FontRef::try_from_slice(font_bytes()).map_err(|_| FigureError::Font)
}

/// Width in pixels of `text` set at `px` pixels.
fn text_width(font: &FontRef<'_>, text: &str, px: f32) -> f32 {
    let scaled = font.as_scaled(PxScale::from(px));
    let mut previous = None;
    let mut width = 0.0;
    for c in text.chars() {
        let id = scaled.glyph_id(c);
        if let Some(before) = previous {
            width += scaled.kern(before, id);
        }
        width += scaled.h_advance(id);
        previous = Some(id);
    }
    width
}

/// The caption height that fits `text` into `width` pixels: [`CAPTION_PX`], or less down to
/// [`MIN_CAPTION_PX`] (a longer text is clipped at the panel's edge).
fn caption_px(font: &FontRef<'_>, text: &str, width: u32) -> f32 {
    let room = width.saturating_sub(2 * CAPTION_MARGIN) as f32;
    let natural = text_width(font, text, CAPTION_PX);
    if natural <= room {
        CAPTION_PX
    } else {
        (CAPTION_PX * room / natural).max(MIN_CAPTION_PX)
    }
}

/// Draws `text` at `px` pixels into `image`, its left end at `left` and the top of its line at
/// `top`, anti-aliased, in [`INK`].
fn draw_text(image: &mut RgbaImage, font: &FontRef<'_>, text: &str, px: f32, (left, top): (f32, f32)) {
    let scaled = font.as_scaled(PxScale::from(px));
    let baseline = top + scaled.ascent();
    let mut caret = left;
    let mut previous = None;
    for c in text.chars() {
        let id = scaled.glyph_id(c);
        if let Some(before) = previous {
            caret += scaled.kern(before, id);
        }
        let glyph = id.with_scale_and_position(PxScale::from(px), point(caret, baseline));
        caret += scaled.h_advance(id);
        previous = Some(id);
        if let Some(outline) = font.outline_glyph(glyph) {
            let bounds = outline.px_bounds();
            outline.draw(|x, y, coverage| {
                let at = (bounds.min.x as i32 + x as i32, bounds.min.y as i32 + y as i32);
                image.blend(at, INK, coverage);
            });
        }
    }
}

/// Height of the caption band above every panel: the text height plus margins.
fn band_height() -> u32 {
    CAPTION_PX.ceil() as u32 + 2 * CAPTION_MARGIN + 2
}

/// Rows of captioned panels on white, [`GAP`] pixels apart; each caption is centred over its
/// panel, in a band of its own so it hides nothing of the image. Panels may differ in size: a row
/// is as tall as its tallest panel.
pub fn grid(rows: &[Vec<Panel>]) -> Result<RgbaImage, FigureError> {
    if rows.is_empty() || rows.iter().any(|row| row.is_empty()) {
        return Err(FigureError::Empty);
    }
    let font = font()?;
    let band = band_height();
    let row_width =
        |row: &Vec<Panel>| row.iter().map(|p| p.image.width).sum::<u32>() + GAP * (row.len() as u32 - 1);
    let row_height = |row: &Vec<Panel>| band + row.iter().map(|p| p.image.height).max().unwrap_or(0);
    let width = rows.iter().map(row_width).max().unwrap_or(0);
    let height = rows.iter().map(row_height).sum::<u32>() + GAP * (rows.len() as u32 - 1);
    let mut figure = RgbaImage::filled(width, height, [255; 4]);
    let mut top = 0;
    for row in rows {
        let mut left = 0;
        for panel in row {
            let px = caption_px(&font, &panel.caption, panel.image.width);
            let text = text_width(&font, &panel.caption, px);
            let start = left as f32 + ((panel.image.width as f32 - text) / 2.0).max(CAPTION_MARGIN as f32);
            let text_top = top as f32 + CAPTION_MARGIN as f32 + (CAPTION_PX - px);
            draw_text(&mut figure, &font, &panel.caption, px, (start, text_top));
            figure.paste(&panel.image, (left, top + band));
            left += panel.image.width + GAP;
        }
        top += row_height(row) + GAP;
    }
    Ok(figure)
}

/// Writes `image` as an 8-bit RGBA PNG.
pub fn write_png(path: &Path, image: &RgbaImage) -> Result<(), FigureError> {
    let fail = |e: &dyn fmt::Display| FigureError::Write(format!("writing {}: {e}", path.display()));
    let file = std::fs::File::create(path).map_err(|e| fail(&e))?;
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), image.width, image.height);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|e| fail(&e))?;
    writer.write_image_data(image.bytes()).map_err(|e| fail(&e))?;
    writer.finish().map_err(|e| fail(&e))
}
