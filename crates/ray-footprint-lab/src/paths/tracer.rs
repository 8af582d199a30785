//! The f64 path tracer: from an image position and the numbers each vertex draws, the path's
//! vertices (closest hits on the analytic surfaces) and what was sampled at each.

pub use super::sampling::Lobe;
use super::sampling::{pdf_and_bsdf, sample_material, shading_frame, NUMBERS_PER_VERTEX};
use super::scene::{Camera, Scene};
use glam::DVec3;

/// Most vertices a path has: the primary hit and three bounces after it.
pub const MAX_VERTICES: usize = 4;

/// What a path sampled at a vertex, and the material's pdf and BSDF value for it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scatter {
    /// The lobe taken.
    pub lobe: Lobe,
    /// The unit direction leaving the vertex.
    pub direction: DVec3,
    /// The material's solid-angle pdf of `direction` (over all its lobes); infinite for a mirror.
    pub pdf: f64,
    /// The material's BSDF value (no cosine) for the incoming ray and `direction`; infinite for a
    /// mirror.
    pub bsdf: f64,
}

/// A vertex of a path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vertex {
    /// Where the ray met the surface.
    pub position: DVec3,
    /// The unit direction of the ray arriving here.
    pub incoming: DVec3,
    /// Its length, from the camera or the previous vertex.
    pub distance: f64,
    /// Index of the surface met.
    pub surface: usize,
    /// The surface's stored unit normal here (either side).
    pub normal: DVec3,
    /// The surface's curvature with the stored normals' sign.
    pub curvature: f64,
    /// What the path sampled here; `None` at the last vertex and where the sampled direction went
    /// below the surface.
    pub scatter: Option<Scatter>,
}

/// A path from the camera: its primary direction and its vertices (at most [`MAX_VERTICES`]; none
/// where the primary ray leaves the scene).
#[derive(Clone, Debug, PartialEq)]
pub struct Path {
    /// The unit direction of the primary ray.
    pub primary: DVec3,
    /// The vertices, primary hit first.
    pub vertices: Vec<Vertex>,
}

/// The path through the image position `(x, y)` of `camera` whose vertex `k` (1-based) reads the
/// numbers `numbers[k - 1]`. It ends where a ray leaves the scene, where a sampled direction goes
/// below the surface, or at vertex [`MAX_VERTICES`].
pub fn trace(
    scene: &Scene,
    camera: &Camera,
    (x, y): (f64, f64),
    numbers: &[[f64; NUMBERS_PER_VERTEX]; MAX_VERTICES],
) -> Path {
    let primary = camera.direction(x, y);
    let mut path = Path {
        primary,
        vertices: Vec::with_capacity(MAX_VERTICES),
    };
    let (mut origin, mut direction, mut leaving) = (camera.position, primary, None);
    for vertex_numbers in numbers {
        let Some(hit) = scene.closest_hit(origin, direction, leaving) else {
            break;
        };
        let is_last = path.vertices.len() + 1 == MAX_VERTICES;
        let vertex = visit(
            scene,
            origin,
            direction,
            hit.surface,
            hit.distance,
            (!is_last).then_some(*vertex_numbers),
        );
        path.vertices.push(vertex);
        let Some(scatter) = vertex.scatter else {
            break;
        };
        (origin, direction, leaving) = (vertex.position, scatter.direction, Some(hit.surface));
    }
    path
}

/// The vertex where the ray from `origin` along `direction` meets surface `surface` at `distance`,
/// sampling a direction there from `numbers` unless it is `None`.
fn visit(
    scene: &Scene,
    origin: DVec3,
    direction: DVec3,
    surface: usize,
    distance: f64,
    numbers: Option<[f64; NUMBERS_PER_VERTEX]>,
) -> Vertex {
    let material_surface = &scene.surfaces[surface];
    let position = origin + distance * direction;
    let normal = material_surface.shape.normal_at(position).normalize();
    let facing = if normal.dot(direction) < 0.0 {
        normal
    } else {
        -normal
    };
    let scatter = numbers.and_then(|numbers| {
        let frame = shading_frame(facing, material_surface.frame_axis);
        let (lobe, leaving) = sample_material(material_surface.material, &frame, direction, numbers)?;
        let (pdf, bsdf) = pdf_and_bsdf(material_surface.material, facing, direction, leaving);
        Some(Scatter {
            lobe,
            direction: leaving,
            pdf,
            bsdf,
        })
    });
    Vertex {
        position,
        incoming: direction,
        distance,
        surface,
        normal,
        curvature: material_surface.shape.curvature(),
        scatter,
    }
}
