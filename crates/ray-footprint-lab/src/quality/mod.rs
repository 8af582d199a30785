//! The quality lab: what each level-of-detail method buys, measured against a supersampled
//! ground truth rendered through the same ray-tracing pipeline.
//!
//! Seven scenes built in code ([`LabScene::all`]): the ground plane at grazing angles under a
//! high-frequency checker, the same plane under a 100-degree view measured in the image's corners
//! (where each primary ray's own cone matters), a mirror hyperbolic paraboloid in a textured room (the saddle reflector
//! of Ray Tracing Gems ch. 20, Fig. 20-10 and 20-11), the gallery's mirror sphere, a glass sphere
//! showing the plane through it, a rough mirror sphere, and the dense torus under the wireframe.
//! Each has a ground truth: its truth method (mip 0, on the rough mirror reflecting about normals
//! drawn from its GGX lobe; for the wireframe the same lines drawn hard) with N x N stratified
//! sub-pixel samples per pixel, averaged in
//! linear light (a box filter), cached on disk under a hash of everything it depends on
//! ([`truth::truth_key`]). Every method ([`LabScene::methods`]: every texture-filtering mode of
//! [`Mode::ALL`](crate::rt::Mode::ALL), or the wireframe's lines with and without anti-aliasing)
//! is rendered at one sample per pixel over K frames of a sub-pixel drift of the image, and scored
//! ([`metrics`]): PSNR over the whole image and over the scene's mask, SSIM, FLIP, the share of
//! the truth's fine detail kept, the mean change from frame to frame minus the truth's (shimmer),
//! and the time per frame. On the texture scenes [`footprint`] also measures how far the isotropic
//! and the anisotropic cone's footprints are from the ray differential's, on the per-pixel records.
//! [`report`] writes the tables, the goals, the images and the plots; [`cost`] joins the table
//! with the `mode_costs` bench's GPU times into the quality gained against the time added.

pub mod cost;
pub mod footprint;
pub mod image;
mod lab;
pub mod metrics;
pub mod plots;
pub mod report;
mod scenes;
pub mod truth;

pub use lab::{
    convergence, run, Convergence, LabRun, LabSettings, MethodResult, Progress, Quiet, SceneResult,
};
pub use scenes::{
    hard_lines, not_a_texture_method, LabScene, Mask, Measure, Method, CORNERS_FOV_Y_DEGREES,
    CORNERS_MASK_DEGREES, FINE_CHECKER_SQUARE, PLANE_MASK_DISTANCE,
};

use crate::figure::FigureError;
use metrics::MetricError;
use std::fmt;

/// Why the lab stopped.
#[derive(Debug)]
pub enum LabError {
    /// The renderer failed.
    Render(crate::rt::Error),
    /// A metric could not be computed.
    Metric(MetricError),
    /// A figure could not be made or written.
    Figure(FigureError),
    /// Reading or writing a file failed: what and why.
    Io(String),
    /// A plot could not be drawn: why.
    Plot(String),
    /// The run's settings are out of range: which and why.
    Settings(String),
}

impl fmt::Display for LabError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LabError::Render(error) => write!(f, "rendering: {error}"),
            LabError::Metric(error) => write!(f, "metric: {error}"),
            LabError::Figure(error) => write!(f, "figure: {error}"),
            LabError::Io(reason) => write!(f, "{reason}"),
            LabError::Plot(reason) => write!(f, "plot: {reason}"),
            LabError::Settings(reason) => write!(f, "settings: {reason}"),
        }
    }
}

impl std::error::Error for LabError {}

impl From<crate::rt::Error> for LabError {
    fn from(error: crate::rt::Error) -> LabError {
        LabError::Render(error)
    }
}

impl From<MetricError> for LabError {
    fn from(error: MetricError) -> LabError {
        LabError::Metric(error)
    }
}

impl From<FigureError> for LabError {
    fn from(error: FigureError) -> LabError {
        LabError::Figure(error)
    }
}
