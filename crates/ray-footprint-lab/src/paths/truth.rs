//! The true footprint of a path's vertices: the derivative of each vertex's position with respect
//! to the image position, the path's random numbers held fixed (Suykens and Willems 2001, Sec. 3),
//! by central differences in f64.

use super::sampling::NUMBERS_PER_VERTEX;
use super::scene::{Camera, Scene};
use super::tracer::{trace, Path, MAX_VERTICES};
use glam::DVec3;

/// The default step of the central differences, in pixels. With positions of order 10 m known to
/// about 1e-15 m and footprints of order 1e-3 m per pixel, the rounding in a difference over
/// `2 h` is about 1e-15 / (2e-4 x 1e-3), 5e-9 of it; the truncation, `h^2 / 6` times the
/// derivative's relative rate of change per pixel squared, is smaller still.
pub const DEFAULT_STEP: f64 = 1e-4;

/// A vertex's true footprint: how far one pixel step in `x` and in `y` moves it, each projected
/// onto the plane across the ray arriving there (the cone's cross-section).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Footprint {
    /// `dP/dx` across the incoming ray, per pixel.
    pub along_x: DVec3,
    /// `dP/dy` across the incoming ray, per pixel.
    pub along_y: DVec3,
}

impl Footprint {
    /// The footprint's width: the longer of the two projected steps, as a level of detail follows
    /// the longer side.
    pub fn width(&self) -> f64 {
        self.along_x.length().max(self.along_y.length())
    }
}

/// A path and the true footprint of each of its vertices, where it has one.
#[derive(Clone, Debug, PartialEq)]
pub struct TrueWidths {
    /// The path through the image position itself.
    pub path: Path,
    /// Per vertex of `path`: the footprint, or `None` where a neighbouring path (at `+-h` in `x` or
    /// `y`) met other surfaces or sampled other lobes up to that vertex (the vertex is not a
    /// differentiable function of the image position there).
    pub footprints: Vec<Option<Footprint>>,
}

/// The path through `pixel` drawing `numbers`, with its vertices' true footprints by central
/// differences of step `step` pixels: `dP/dx = (P(x + h) - P(x - h)) / 2h`, the same for `y`,
/// each made perpendicular to the vertex's incoming direction `d`, `v - d (d . v)`.
pub fn true_widths(
    scene: &Scene,
    camera: &Camera,
    pixel: (f64, f64),
    numbers: &[[f64; NUMBERS_PER_VERTEX]; MAX_VERTICES],
    step: f64,
) -> TrueWidths {
    let (x, y) = pixel;
    let path = trace(scene, camera, pixel, numbers);
    let neighbours = [(x + step, y), (x - step, y), (x, y + step), (x, y - step)]
        .map(|position| trace(scene, camera, position, numbers));
    let footprints = (0..path.vertices.len())
        .map(|k| {
            if !neighbours.iter().all(|other| same_history(&path, other, k)) {
                return None;
            }
            let incoming = path.vertices[k].incoming;
            let across = |v: DVec3| v - incoming * incoming.dot(v);
            let difference = |plus: &Path, minus: &Path| {
                (plus.vertices[k].position - minus.vertices[k].position) / (2.0 * step)
            };
            Some(Footprint {
                along_x: across(difference(&neighbours[0], &neighbours[1])),
                along_y: across(difference(&neighbours[2], &neighbours[3])),
            })
        })
        .collect();
    TrueWidths { path, footprints }
}

/// Whether `other` reaches vertex `k` (0-based) over the same surfaces as `path` and with the same
/// lobes sampled at the vertices before it.
fn same_history(path: &Path, other: &Path, k: usize) -> bool {
    if other.vertices.len() <= k {
        return false;
    }
    let same_surfaces = (0..=k).all(|i| path.vertices[i].surface == other.vertices[i].surface);
    let lobe = |p: &Path, i: usize| p.vertices[i].scatter.map(|s| s.lobe);
    same_surfaces && (0..k).all(|i| lobe(path, i) == lobe(other, i))
}
