//! The plots, drawn with `plotters` into bitmaps (text in DejaVu Sans through `ab_glyph`) and
//! written as PNG: PSNR per scene and method (`psnr.png`, whole image and mask), mean FLIP per
//! scene and method (`flip.png`), and quality against cost per scene (`quality_cost.png`); and any
//! scatter plot of panels ([`scatter_plot`], which [`super::cost`] draws).

use super::lab::LabRun;
use super::LabError;
use crate::figure::{self, RgbaImage};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// Size of every plot, in pixels.
const PLOT_SIZE: (u32, u32) = (960, 600);
/// Width of the legend strip at the right of every plot, in pixels.
const LEGEND_WIDTH: u32 = 190;
/// The font family the plots ask for.
const FAMILY: &str = "sans-serif";

type Area<'a> = DrawingArea<BitMapBackend<'a>, Shift>;

/// A drawing error as the lab's error.
fn plot_error(error: impl std::fmt::Display) -> LabError {
    LabError::Plot(error.to_string())
}

/// Registers DejaVu Sans as the plots' `sans-serif` (once per process).
fn register_font() -> Result<(), LabError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        plotters::style::register_font(FAMILY, FontStyle::Normal, figure::font_bytes()).is_ok()
    });
    ok.then_some(())
        .ok_or_else(|| plot_error("the embedded font does not parse"))
}

/// Every method name of the run, in order of first appearance: the legend and the colours.
fn method_names(run: &LabRun) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    for scene in &run.scenes {
        for m in &scene.methods {
            if !names.contains(&m.method.name) {
                names.push(m.method.name.clone());
            }
        }
    }
    names
}

/// The colour of the method at `index` in [`method_names`].
fn colour(index: usize) -> RGBColor {
    let RGBAColor(r, g, b, _) = Palette99::pick(index).to_rgba();
    RGBColor(r, g, b)
}

/// A plot drawn by `draw` on a white bitmap with the method legend at its right, written to
/// `path` as PNG.
fn plot(
    path: &Path,
    names: &[String],
    draw: impl FnOnce(&Area<'_>) -> Result<(), LabError>,
) -> Result<PathBuf, LabError> {
    register_font()?;
    let (width, height) = PLOT_SIZE;
    let mut rgb = vec![255u8; (width * height * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, PLOT_SIZE).into_drawing_area();
        let (chart, legend) = root.split_horizontally(width - LEGEND_WIDTH);
        draw(&chart)?;
        draw_legend(&legend, names)?;
        root.present().map_err(plot_error)?;
    }
    let image = RgbaImage {
        width,
        height,
        pixels: rgb.chunks_exact(3).map(|p| [p[0], p[1], p[2], 255]).collect(),
    };
    figure::write_png(path, &image)?;
    Ok(path.to_path_buf())
}

/// A colour swatch and the name of every method, top to bottom.
fn draw_legend(area: &Area<'_>, names: &[String]) -> Result<(), LabError> {
    let style = TextStyle::from((FAMILY, 15).into_font()).color(&BLACK);
    for (index, name) in names.iter().enumerate() {
        let top = 60 + 22 * index as i32;
        let swatch = Rectangle::new([(8, top), (24, top + 14)], colour(index).filled());
        area.draw(&swatch).map_err(plot_error)?;
        area.draw(&Text::new(name.clone(), (30, top), style.clone()))
            .map_err(plot_error)?;
    }
    Ok(())
}

/// The smallest and largest finite value, padded by a tenth of the range (a unit if flat).
fn padded_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let finite: Vec<f64> = values.filter(|v| v.is_finite()).collect();
    let low = finite.iter().copied().fold(f64::INFINITY, f64::min);
    let high = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if !low.is_finite() {
        return (0.0, 1.0);
    }
    let pad = ((high - low) * 0.1).max(if high > low { 0.0 } else { 1.0 });
    (low - pad, high + pad)
}

/// A bar chart: one group of bars per scene (named under it), one bar per method of the scene
/// coloured as in the legend, heights from `value`, bars rising from the bottom of the range.
fn bar_chart(
    area: &Area<'_>,
    run: &LabRun,
    names: &[String],
    (title, unit): (&str, &str),
    value: impl Fn(&super::MethodResult) -> f64,
) -> Result<(), LabError> {
    let scenes: Vec<&str> = run.scenes.iter().map(|s| s.scene.name).collect();
    let values = run.scenes.iter().flat_map(|s| s.methods.iter().map(&value));
    let (low, high) = padded_range(values);
    let bottom = if low > 0.0 && unit != "dB" { 0.0 } else { low };
    let count = scenes.len() as f64;
    let mut chart = ChartBuilder::on(area)
        .caption(title, (FAMILY, 20))
        .margin(12)
        .x_label_area_size(32)
        .y_label_area_size(64)
        .build_cartesian_2d(0.0..count, bottom..high)
        .map_err(plot_error)?;
    let scene_label = |x: &f64| {
        let centre = x - 0.5;
        let index = centre.round();
        let is_centre = (centre - index).abs() < 1e-6 && index >= 0.0 && (index as usize) < scenes.len();
        if is_centre {
            scenes[index as usize].to_string()
        } else {
            String::new()
        }
    };
    chart
        .configure_mesh()
        .disable_x_mesh()
        .x_labels(2 * scenes.len() + 1)
        .x_label_formatter(&scene_label)
        .y_desc(unit)
        .label_style((FAMILY, 14))
        .draw()
        .map_err(plot_error)?;
    for (s, scene) in run.scenes.iter().enumerate() {
        let width = 0.8 / scene.methods.len() as f64;
        let bars = scene.methods.iter().enumerate().map(|(j, m)| {
            let index = names.iter().position(|n| *n == m.method.name).unwrap_or(0);
            let left = s as f64 + 0.1 + j as f64 * width;
            let top = value(m).clamp(bottom, high);
            Rectangle::new(
                [(left, bottom), (left + 0.9 * width, top)],
                colour(index).filled(),
            )
        });
        chart.draw_series(bars).map_err(plot_error)?;
    }
    Ok(())
}

/// `psnr.png`: PSNR per scene and method over the whole image (top) and the mask (bottom).
fn psnr_plot(run: &LabRun, names: &[String], out: &Path) -> Result<PathBuf, LabError> {
    plot(&out.join("psnr.png"), names, |area| {
        let (top, bottom) = area.split_vertically(PLOT_SIZE.1 / 2);
        bar_chart(
            &top,
            run,
            names,
            ("PSNR against the ground truth, whole image", "dB"),
            |m| m.psnr,
        )?;
        bar_chart(&bottom, run, names, ("PSNR over the mask", "dB"), |m| m.psnr_mask)
    })
}

/// `flip.png`: mean FLIP error per scene and method (lower is better).
fn flip_plot(run: &LabRun, names: &[String], out: &Path) -> Result<PathBuf, LabError> {
    plot(&out.join("flip.png"), names, |area| {
        bar_chart(
            area,
            run,
            names,
            ("Mean FLIP error (lower is better)", "FLIP"),
            |m| m.flip,
        )
    })
}

/// `quality_cost.png`: per scene, PSNR over the mask against the time per frame of each method.
fn quality_cost_plot(run: &LabRun, names: &[String], out: &Path) -> Result<PathBuf, LabError> {
    let panels: Vec<ScatterPanel> = run
        .scenes
        .iter()
        .map(|scene| ScatterPanel {
            title: format!("{}: quality against cost", scene.scene.name),
            points: scene
                .methods
                .iter()
                .map(|m| ScatterPoint {
                    x: m.ms_per_frame,
                    x_spread: None,
                    y: m.psnr_mask,
                    method: m.method.name.clone(),
                    separable: true,
                })
                .collect(),
        })
        .collect();
    plot(&out.join("quality_cost.png"), names, |area| {
        scatter_panels(area, &panels, names, ("ms per frame", "PSNR mask dB"))
    })
}

/// A point of a [`ScatterPanel`]: where it is, the method it stands for (its colour in the
/// legend), and, for a measured time, the spread of x (drawn as a bar).
#[derive(Clone, Debug, PartialEq)]
pub struct ScatterPoint {
    /// Horizontal position.
    pub x: f64,
    /// Smallest and largest x measured, where x is a median of several.
    pub x_spread: Option<(f64, f64)>,
    /// Vertical position.
    pub y: f64,
    /// The method's name.
    pub method: String,
    /// Whether x differs from the baseline's by more than the spreads (drawn filled; hollow
    /// otherwise).
    pub separable: bool,
}

/// One panel of a scatter plot: its title and points.
#[derive(Clone, Debug, PartialEq)]
pub struct ScatterPanel {
    /// The caption.
    pub title: String,
    /// The points.
    pub points: Vec<ScatterPoint>,
}

/// `panels` in a grid of two columns on `area`, each point coloured by its method's place in
/// `names`, axes described by `(x_desc, y_desc)`.
fn scatter_panels(
    area: &Area<'_>,
    panels: &[ScatterPanel],
    names: &[String],
    (x_desc, y_desc): (&str, &str),
) -> Result<(), LabError> {
    let columns = panels.len().clamp(1, 2);
    let rows = panels.len().div_ceil(columns).max(1);
    for (panel, region) in panels.iter().zip(&area.split_evenly((rows, columns))) {
        let xs = panel.points.iter().flat_map(|p| {
            let (low, high) = p.x_spread.unwrap_or((p.x, p.x));
            [p.x, low, high]
        });
        let (x_low, x_high) = padded_range(xs);
        let (y_low, y_high) = padded_range(panel.points.iter().map(|p| p.y));
        let mut chart = ChartBuilder::on(region)
            .caption(&panel.title, (FAMILY, 17))
            .margin(10)
            .x_label_area_size(36)
            .y_label_area_size(56)
            .build_cartesian_2d(x_low..x_high, y_low..y_high)
            .map_err(plot_error)?;
        chart
            .configure_mesh()
            .x_desc(x_desc)
            .y_desc(y_desc)
            .label_style((FAMILY, 13))
            .draw()
            .map_err(plot_error)?;
        for point in &panel.points {
            let index = names.iter().position(|n| *n == point.method).unwrap_or(0);
            let style = colour(index);
            if let Some((low, high)) = point.x_spread {
                let bar = PathElement::new([(low, point.y), (high, point.y)], style.stroke_width(2));
                chart.draw_series([bar]).map_err(plot_error)?;
            }
            let marker = if point.separable {
                style.filled()
            } else {
                style.stroke_width(2)
            };
            chart
                .draw_series([Circle::new((point.x, point.y), 6, marker)])
                .map_err(plot_error)?;
        }
    }
    Ok(())
}

/// A scatter plot of `panels` written to `path` as PNG, with the legend of every method in order
/// of first appearance.
pub fn scatter_plot(path: &Path, panels: &[ScatterPanel], axes: (&str, &str)) -> Result<PathBuf, LabError> {
    let mut names: Vec<String> = Vec::new();
    for point in panels.iter().flat_map(|panel| &panel.points) {
        if !names.contains(&point.method) {
            names.push(point.method.clone());
        }
    }
    plot(path, &names, |area| scatter_panels(area, panels, &names, axes))
}

/// Writes every plot of `run` into `out` and returns their paths.
pub fn write_all(run: &LabRun, out: &Path) -> Result<Vec<PathBuf>, LabError> {
    let names = method_names(run);
    Ok(vec![
        psnr_plot(run, &names, out)?,
        flip_plot(run, &names, out)?,
        quality_cost_plot(run, &names, out)?,
    ])
}
