//! Path footprints: the true footprint of every vertex of a path tracer's paths, measured on the
//! CPU in f64, against the ray-cone rules that renderers use at scattering events.
//!
//! With its random numbers held fixed, a path is a function of the image position `(x, y)`; the
//! footprint of its vertex `k` is the derivative of that vertex's position with respect to the
//! image position, as path differentials define it (Suykens and Willems, "Path Differentials and
//! Applications", EGWR 2001, Sec. 3; for a mirror chain, Igehy, "Tracing Ray Differentials",
//! SIGGRAPH 1999). [`truth`] takes that derivative by central differences and keeps, as the true
//! width, the longer of the two pixel steps across the incoming ray; [`methods`] follows the same
//! path with each cone rule (the library's and the peer renderers'), in f32
//! through `ray_footprint::ray_cone`; [`report`] compares them per scene, bounce and method in mip
//! levels, `|log2(cone width / true width)|`, and sweeps one global level-of-detail bias added to
//! the cone without a scattering term past the first hit.
//!
//! - [`scene`]: analytic scenes (planes and spheres, a sphere seen from inside being concave),
//!   their materials (Lambert, GGX conductor, a GGX coat over Lambert) and the pinhole camera.
//! - [`sampling`]: the random-number streams, the shading frame and the two samplers (Lambert's
//!   cosine lobe; GGX by its distribution of normals, Walter et al. 2007), with the pdf and BSDF
//!   value of a sampled direction that the pdf- and BSDF-driven rules read.
//! - [`tracer`]: the f64 path tracer, up to [`MAX_VERTICES`] vertices.
//! - [`texture`] and [`image`]: the image error each rule gives when its width picks the level of
//!   a mip-mapped texture, against a reference rendered at level 0.

pub mod image;
pub mod methods;
pub mod report;
pub mod sampling;
pub mod scene;
pub mod texture;
pub mod tracer;
pub mod truth;

#[cfg(test)]
mod tests;

pub use image::{
    image_error_plot, image_methods, image_scene_table, image_summary_table, measure_image,
    noise_floor_table, ImageMethod, ImageSettings, SceneErrors,
};
pub use methods::{method_widths, Method, METHODS};
pub use report::{
    bias_sweep_table, measure, scene_table, summary_table, Measurement, Settings, VertexRecord,
};
pub use sampling::Lobe;
pub use scene::{scenes, scenes_named, Camera, Material, Scene, Shape, Surface};
pub use texture::Texture;
pub use tracer::{trace, Path, Scatter, Vertex, MAX_VERTICES};
pub use truth::{true_widths, Footprint, TrueWidths, DEFAULT_STEP};
