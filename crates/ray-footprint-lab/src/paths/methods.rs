//! The cone rules measured: each follows a traced path from the camera's cone, in f32, and gives
//! the cone's width at every vertex, `width_at(cone, t)` of the cone that left the vertex before.
//!
//! Every rule starts from `pinhole_ray_cone_for_ray(pixel_spread_angle(fov_y, H), d, view_axis)`
//! (the per-ray pinhole cone, narrower off axis) and differs only in the cone it sends on from a
//! vertex. Curvatures and normals are the stored ones of the surface, passed as
//! `curvature_spread_angle` takes them (they flip together; 0 for a plane).
//!
//! The true footprint holds the path's random numbers fixed, so it has no term for the width of
//! the lobe the direction was drawn from; the rules that add one (roughness, pdf, BSDF value)
//! estimate how wide the lobe spreads the texture around the sampled direction, which many samples
//! of a path tracer average over anyway, and read as footprints they are too wide by design.
//!
//! What the peer renderers do, as read in their sources:
//! - RTXPT (repository `NVIDIA-RTX/RTXPT`, commit `f08d1c7`: `GenerateScatterRay` in
//!   `Rtxpt/Shaders/PathTracer/PathTracer.hlsli`, `ComputeRayConeSpreadAngleExpansionByScatterPDF`
//!   in `Rtxpt/Shaders/PathTracer/PathTracerHelpers.hlsli`; the same in the older layout under
//!   `Rtxpt/PathTracer/`): on every scatter that is not a delta lobe the spread grows by
//!   `0.3 x 2 acos(max(-1, 1 - (1 / pdf) / (2 pi)))`, the whole angle of the spherical cap whose
//!   solid angle is `1 / pdf`, scaled down by 0.3 on purpose, and is clamped to `2 pi`. The width
//!   is carried on unchanged, and no curvature term is added on the path (Falcor's
//!   `computeSpreadAngleFromCurvatureIso` is in `Rendering/Materials/TexLODHelpers.hlsli` but
//!   nothing calls it). A GGX lobe with `alpha < 0.0064` (`kMinGGXAlpha` in `BxDF.hlsli`) is a
//!   delta lobe and adds nothing. A `sqrt(1 / max(pdf, 1e-4))` expansion, sometimes quoted as
//!   RTXPT's, is not in its stored versions but in a third-party port; both are measured.
//! - OptiX Toolkit (repository `NVIDIA/optix-toolkit`:
//!   `ShaderUtil/include/OptiXToolkit/ShaderUtil/ray_cone.h`, its notes
//!   `ShaderUtil/docs/rayCones/README.md`, and the sample
//!   `examples/DemandLoading/RayCones/RayCones.cu`, which calls `reflect` then `scatterBsdf` at
//!   every vertex): `reflect` adds `2 k |w|` (no `1 / cos`, and only while the angle is below
//!   0.25); `scatterBsdf` adds `sign(angle) 0.25 min(1, 1 / (pi f_s))` with `f_s` the BSDF value
//!   of the sampled direction, and where the angle reaches 0.25 the cone becomes the "diffuse"
//!   one of angle 0.25 (`setDiffuse`); `propagate` flips both signs where width and angle are
//!   both negative. The sample also carries a second cone (a thin lens one pixel wide at the
//!   image plane) and keeps the wider; that is left out here, as every rule starts from one
//!   pinhole cone.

use super::sampling::Lobe;
use super::scene::Camera;
use super::tracer::{Path, Vertex};
use glam::Vec3;
use ray_footprint::ray_cone::{
    curvature_spread_angle, pinhole_ray_cone_for_ray, pixel_spread_angle, propagate, roughness_spread_angle,
    scatter_ray_cone, width_at, RayCone, LOBE_DIFFUSE, LOBE_REFLECTION,
};
use std::f32::consts::{PI, TAU};

/// A cone rule for path vertices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Every vertex as a mirror, whatever the lobe: `propagate(cone, t, curvature_spread_angle(..))`
    /// (JCGT 2021's curvature, no roughness).
    NoScatteringTerm,
    /// As [`Method::NoScatteringTerm`] plus `2 roughness_spread_angle(r)` (JCGT 2021, Falcor's
    /// `roughnessToSpread`, doubled for a reflection) for a GGX lobe of roughness `r`; a Lambert
    /// lobe counts as roughness 1, which the function reads with its denominator clamped to
    /// `MIN_ROUGHNESS_DENOMINATOR`: `2 x 141` radians.
    JcgtRoughness,
    /// RTXPT's spread from the sampled direction's pdf (module doc).
    Rtxpt,
    /// A third-party reading of RTXPT: the spread grows by `sqrt(1 / max(pdf, 1e-4))`, clamped to
    /// `2 pi`, on every scatter that is not a delta lobe; no curvature term.
    PdfSquareRoot,
    /// The OptiX Toolkit's `reflect` and `scatterBsdf` (module doc).
    OptixToolkit,
    /// `scatter_ray_cone` of this crate with `LOBE_DIFFUSE` or `LOBE_REFLECTION` as sampled and
    /// the sampled direction as the leaving one.
    ScatterRayCone,
}

/// The methods in the order the report prints them.
pub const METHODS: [Method; 6] = [
    Method::NoScatteringTerm,
    Method::JcgtRoughness,
    Method::Rtxpt,
    Method::PdfSquareRoot,
    Method::OptixToolkit,
    Method::ScatterRayCone,
];

impl Method {
    /// The method's name in the tables.
    pub fn name(self) -> &'static str {
        match self {
            Method::NoScatteringTerm => "cone, no scattering term",
            Method::JcgtRoughness => "cone + roughness (JCGT 2021)",
            Method::Rtxpt => "RTXPT (pdf cap x 0.3)",
            Method::PdfSquareRoot => "sqrt(1 / pdf) (a reading of RTXPT)",
            Method::OptixToolkit => "OptiX Toolkit",
            Method::ScatterRayCone => "scatter_ray_cone (this crate)",
        }
    }
}

/// RTXPT's smallest GGX alpha that is not a delta lobe (`kMinGGXAlpha`).
const RTXPT_MIN_GGX_ALPHA: f32 = 0.0064;
/// RTXPT's scale of the cap angle (`growthFactor`).
const RTXPT_GROWTH_FACTOR: f32 = 0.3;
/// The OptiX Toolkit's largest cone angle, the diffuse cone's (`MAX_CONE_ANGLE`).
const OTK_MAX_CONE_ANGLE: f32 = 0.25;

/// What a rule reads at a vertex, in f32.
struct ConeVertex {
    distance: f32,
    normal: Vec3,
    incoming: Vec3,
    curvature: f32,
    scatter: Option<(Lobe, f32, f32)>,
    outgoing: Vec3,
}

impl ConeVertex {
    fn from_vertex(vertex: &Vertex) -> ConeVertex {
        ConeVertex {
            distance: vertex.distance as f32,
            normal: vertex.normal.as_vec3(),
            incoming: vertex.incoming.as_vec3(),
            curvature: vertex.curvature as f32,
            scatter: vertex.scatter.map(|s| (s.lobe, s.pdf as f32, s.bsdf as f32)),
            outgoing: vertex.scatter.map_or(Vec3::ZERO, |s| s.direction.as_vec3()),
        }
    }

    /// `curvature_spread_angle` of the cone arriving here with `width`.
    fn curvature_spread(&self, width: f32) -> f32 {
        curvature_spread_angle(self.curvature, width, self.normal, self.incoming)
    }
}

/// The camera's cone for the primary direction: `pinhole_ray_cone_for_ray` of the pixel angle.
pub fn primary_cone(camera: &Camera, primary: Vec3) -> RayCone {
    let pixel_angle = pixel_spread_angle(camera.fov_y() as f32, camera.height as f32);
    pinhole_ray_cone_for_ray(pixel_angle, primary, camera.forward.as_vec3())
}

/// The method's cone width at each vertex of `path`, seen by `camera` (signed; footprints use the
/// magnitude).
pub fn method_widths(method: Method, path: &Path, camera: &Camera) -> Vec<f32> {
    let mut cone = primary_cone(camera, path.primary.as_vec3());
    let mut widths = Vec::with_capacity(path.vertices.len());
    for vertex in &path.vertices {
        let vertex = ConeVertex::from_vertex(vertex);
        let (width, leaving) = step(method, cone, &vertex);
        widths.push(width);
        cone = leaving;
    }
    widths
}

/// The width at the vertex of the cone arriving there, and the cone leaving it (the arriving one,
/// carried to the vertex, where the path sampled nothing).
fn step(method: Method, cone: RayCone, vertex: &ConeVertex) -> (f32, RayCone) {
    let width = width_at(cone, vertex.distance);
    let Some((lobe, pdf, bsdf)) = vertex.scatter else {
        return (width, propagate(cone, vertex.distance, 0.0));
    };
    match method {
        Method::NoScatteringTerm => (
            width,
            propagate(cone, vertex.distance, vertex.curvature_spread(width)),
        ),
        Method::JcgtRoughness => {
            let roughness_spread = 2.0 * roughness_spread_angle(jcgt_roughness(lobe));
            let spread = vertex.curvature_spread(width) + roughness_spread;
            (width, propagate(cone, vertex.distance, spread))
        }
        Method::Rtxpt => (
            width,
            pdf_widened(cone, vertex.distance, lobe, rtxpt_expansion(pdf)),
        ),
        Method::PdfSquareRoot => (
            width,
            pdf_widened(cone, vertex.distance, lobe, square_root_expansion(pdf)),
        ),
        Method::OptixToolkit => optix_toolkit_step(cone, vertex, bsdf),
        Method::ScatterRayCone => (width, library_scatter(cone, vertex, lobe)),
    }
}

/// `scatter_ray_cone` with the lobe as the path sampled it.
fn library_scatter(cone: RayCone, vertex: &ConeVertex, lobe: Lobe) -> RayCone {
    let lobe_id = match lobe {
        Lobe::Diffuse => LOBE_DIFFUSE,
        Lobe::Glossy { .. } => LOBE_REFLECTION,
    };
    scatter_ray_cone(
        cone,
        vertex.distance,
        vertex.curvature,
        vertex.normal,
        vertex.incoming,
        vertex.outgoing,
        lobe_id,
    )
}

/// The roughness the JCGT 2021 rule reads: the GGX lobe's, 1 for a Lambert lobe.
fn jcgt_roughness(lobe: Lobe) -> f32 {
    match lobe {
        Lobe::Diffuse => 1.0,
        Lobe::Glossy { roughness } => roughness as f32,
    }
}

/// Whether RTXPT reads the lobe as a delta lobe: a GGX lobe with `alpha = r^2 < 0.0064`.
fn is_rtxpt_delta(lobe: Lobe) -> bool {
    match lobe {
        Lobe::Diffuse => false,
        Lobe::Glossy { roughness } => ((roughness * roughness) as f32) < RTXPT_MIN_GGX_ALPHA,
    }
}

/// The cone carried to the vertex with no curvature term, its spread grown by `expansion` and
/// clamped to `2 pi` unless RTXPT reads the lobe as a delta lobe.
fn pdf_widened(cone: RayCone, distance: f32, lobe: Lobe, expansion: f32) -> RayCone {
    let carried = propagate(cone, distance, 0.0);
    if is_rtxpt_delta(lobe) {
        return carried;
    }
    RayCone {
        width: carried.width,
        spread_angle: (carried.spread_angle + expansion).min(TAU),
    }
}

/// RTXPT's expansion: `0.3 x 2 acos(max(-1, 1 - (1 / pdf) / (2 pi)))`, the whole angle of a
/// spherical cap of solid angle `1 / pdf` (`Omega = 2 pi (1 - cos(theta))`), times 0.3.
pub fn rtxpt_expansion(pdf: f32) -> f32 {
    RTXPT_GROWTH_FACTOR * 2.0 * (1.0 - (1.0 / pdf) / TAU).max(-1.0).acos()
}

/// The third-party expansion: `sqrt(1 / max(pdf, 1e-4))`.
pub fn square_root_expansion(pdf: f32) -> f32 {
    (1.0 / pdf.max(1e-4)).sqrt()
}

/// The OptiX Toolkit's vertex: the arriving cone's width there, and [`optix_toolkit_cone`] with
/// the curvature as the ray sees it (positive for a convex surface, the stored curvature times the
/// sign of `-dot(n, d)`) and the BSDF value `bsdf`.
fn optix_toolkit_step(cone: RayCone, vertex: &ConeVertex, bsdf: f32) -> (f32, RayCone) {
    let seen_curvature = if vertex.normal.dot(vertex.incoming) < 0.0 {
        vertex.curvature
    } else {
        -vertex.curvature
    };
    (
        width_at(cone, vertex.distance),
        optix_toolkit_cone(cone, vertex.distance, seen_curvature, bsdf),
    )
}

/// The OptiX Toolkit's cone leaving a vertex that `cone` reaches at `distance`, on a surface of
/// curvature `seen_curvature` as the ray sees it, for a direction of BSDF value `bsdf`:
/// `propagate` (both signs flipped where width and angle are both negative), `reflect` (twice the
/// curvature times `|w|`, only while the angle is below 0.25), then [`optix_toolkit_scatter`].
/// The toolkit's `setDiffuse` writes `RayCone{fabsf(width), MAX_CONE_ANGLE}` into a struct whose
/// fields are `{angle, width}`; this follows what its comment and notes say it does: angle 0.25,
/// width `|w|`. The renderer's `path_optix` runs the same rule (`rt_optix_toolkit_cone`).
pub fn optix_toolkit_cone(cone: RayCone, distance: f32, seen_curvature: f32, bsdf: f32) -> RayCone {
    let mut width = width_at(cone, distance);
    let mut angle = cone.spread_angle;
    if angle < 0.0 && width < 0.0 {
        (width, angle) = (-width, -angle);
    }
    if angle < OTK_MAX_CONE_ANGLE {
        angle += 2.0 * seen_curvature * width.abs();
    }
    optix_toolkit_scatter(width, angle, bsdf)
}

/// The OptiX Toolkit's `scatterBsdf`: unless the angle has reached 0.25 already, it grows by
/// `sign(angle) 0.25 (1 / pi) / max(f_s, 1 / pi)`, and where that reaches 0.25 in magnitude the
/// cone becomes the diffuse one, angle 0.25 and width `|w|`.
pub fn optix_toolkit_scatter(width: f32, angle: f32, bsdf: f32) -> RayCone {
    if angle >= OTK_MAX_CONE_ANGLE {
        return RayCone {
            width,
            spread_angle: angle,
        };
    }
    let sign = if angle < 0.0 { -1.0 } else { 1.0 };
    let grown = angle + sign * OTK_MAX_CONE_ANGLE * (1.0 / PI) / bsdf.max(1.0 / PI);
    if grown.abs() < OTK_MAX_CONE_ANGLE {
        RayCone {
            width,
            spread_angle: grown,
        }
    } else {
        RayCone {
            width: width.abs(),
            spread_angle: OTK_MAX_CONE_ANGLE,
        }
    }
}
