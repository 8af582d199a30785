//! The structs and constants the renderer's shaders share with Rust, declared here once: `cargo
//! xtask codegen` writes them, with the render modes ([`Mode`](crate::rt::Mode)) and the scene's
//! constants ([`VERTEX_FLOATS`](crate::rt::VERTEX_FLOATS), ...), into `shaders/rt_abi.glsl`,
//! `shaders/rt_abi.slang` and `shaders/ray_query.wgsl` between marker lines, and lists their
//! layouts in [`layouts`]. The structs are `#[repr(C)]` bytemuck `Pod`; the renderer's layout test
//! compares each in Rust, WGSL, and std430 and scalar in GLSL and in Slang.

use bytemuck::{Pod, Zeroable};
use glam::Vec3;
use ray_footprint::abi::{RayCone, RayConePushConstants, WireframePushConstants, PUSH_CONSTANT_LIMIT};

/// The most bounces a path makes: glass passes rays on up to it. The ray-tracing pipelines'
/// recursion depth is one more (the primary ray's trace).
pub const MAX_DEPTH: u32 = 3;

/// Farthest hit distance a ray looks for, in world units.
pub const MAX_DISTANCE: f32 = 1.0e4;

/// How far a reflected or refracted ray's origin is lifted off the surface, in world units.
pub const SURFACE_OFFSET: f32 = 1.0e-3;

/// Share of the light a mirror reflects.
pub const MIRROR_REFLECTANCE: f32 = 0.9;

/// Direction towards the light (not unit length; the shaders normalize it).
pub const LIGHT: Vec3 = Vec3::new(0.4, 0.85, 0.35);

/// Push constants of [the ray-tracing renderer](crate::rt). 96 bytes, 16-byte aligned: the pinhole
/// camera, the render mode, the ray-cone push constants, the image size and the primary rays'
/// offset within their pixels.
///
/// The camera basis is orthonormal; pixel `(x, y)` looks along
/// `normalize(forward + c.x * aspect * tan_half_fov_y * right - c.y * tan_half_fov_y * up)` with
/// `c = 2 * ((x, y) + 0.5 + pixel_offset) / (width, height) - 1`.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct RtPushConstants {
    /// Camera position.
    pub eye: Vec3,
    /// `tan(fov_y / 2)`.
    pub tan_half_fov_y: f32,
    /// Camera right axis (unit).
    pub right: Vec3,
    /// Image width over height.
    pub aspect: f32,
    /// Camera up axis (unit).
    pub up: Vec3,
    /// Texture width (= height) in texels, for the texture LOD (RTG Eq. 34).
    pub texture_size: f32,
    /// Viewing direction (unit).
    pub forward: Vec3,
    /// The render mode ([`crate::rt::Mode::id`]).
    pub mode: u32,
    /// `textureGrad` scale and pixel spread angle.
    pub cone: RayConePushConstants,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Where each primary ray crosses its pixel, from the pixel's centre, in pixels (x right,
    /// y down); the ray differentials and re-intersected neighbour rays move with it. 0 traces
    /// through the centres; sub-pixel offsets supersample a frame, or move the image by less
    /// than a pixel.
    pub pixel_offset: glam::Vec2,
    /// What the frame renders besides its mode: a sum of the `FLAG_*` constants, 0 for none.
    pub flags: u32,
    /// The mip levels [`crate::rt::Mode::PathBias`] adds to the level of detail of every textured
    /// vertex past the first hit (-3 by default); no other mode reads it.
    pub lod_bias: f32,
}

/// [`RtPushConstants::flags`]: the mirrors reflect about a normal drawn from the GGX distribution of
/// their roughness (Walter, Marschner, Li, Torrance 2007, Eq. 35-36), one per ray, from a hash of
/// the pixel and `pixel_offset`, instead of about the shading normal: the glossy reflection a
/// supersampled ground truth integrates, which the ray-cone modes' roughness spread stands in for.
/// The rays' cones and differentials are those of the shading normal's reflection. Each reflected
/// ray keeps the mirror's reflectance: the directions follow the microfacet normals' distribution
/// `D(m) |m.n|`, without the weight `G |i.m| / (|i.n| |m.n|)` of a full GGX estimator
/// (shadowing-masking and the reflection's change of variables; 1 at normal incidence), and a
/// normal whose reflection would leave below the surface gives the shading normal's reflection.
pub const FLAG_GLOSSY_LOBE: u32 = 1;

/// [`RtPushConstants::flags`]: each pixel of the frame samples a sub-pixel position of its own,
/// drawn from a hash of the pixel and `pixel_offset` (uniform over the pixel, independent between
/// pixels and frames), instead of every pixel sampling at `pixel_offset`. A render averaging such
/// frames has errors that are independent from pixel to pixel, so that its noise and bias over the
/// image separate; with one offset per frame, the texture's error of a frame is the same function
/// of that offset at every pixel, and a render of `n` frames carries `n` draws of it. The
/// ray-tracing pipelines' ray generation reads it (the ray-query shader does not).
pub const FLAG_PIXEL_JITTER: u32 = 2;

/// What the renderer measured at a pixel's primary hit: the hit data, every ray-cone value the shader computed from it, the
/// ray-differential and wireframe values ([`RtDiffRecord`]), and the values of the hit's material
/// (the roughness spread of a mirror, the refraction of a glass surface) and the anisotropic cone
/// footprint. 320 bytes, 16-byte aligned. A miss has `hit == 0` and zeros elsewhere.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct RtPixelRecord {
    /// Unit shading normal at the hit (interpolated vertex normals).
    pub normal: Vec3,
    /// Hit distance along the unit ray direction.
    pub t: f32,
    /// Unit ray direction.
    pub direction: Vec3,
    /// Instance custom index: the mesh ([`crate::rt::Scene::meshes`]).
    pub instance: u32,
    /// Hit barycentrics `(u, v)` of vertices 1 and 2.
    pub barycentrics: glam::Vec2,
    /// Triangle index within the mesh.
    pub primitive: u32,
    /// 1 for a hit, 0 for a miss.
    pub hit: u32,
    /// The cone at the ray's origin.
    pub cone: RayCone,
    /// `rf_width_at(cone, t)`.
    pub width: f32,
    /// `rf_world_footprint(cone, t, normal, direction)`.
    pub footprint: f32,
    /// `rf_texel_density` of the triangle.
    pub texel_density: f32,
    /// `rf_triangle_base_lod` of the triangle.
    pub base_lod: f32,
    /// `rf_texture_lod(base_lod, width, texture size, normal, direction)`.
    pub lod: f32,
    /// `rf_texture_gradient(footprint * texel_density, tex_grad_scale)`.
    pub gradient: f32,
    /// `rf_isotropic_curvature(rf_principal_curvatures(rf_triangle_shape_operator(...)))` of the
    /// vertex normals: the curvature the triangle gives an isotropic cone.
    pub curvature: f32,
    /// `rf_curvature_spread_angle(curvature, width, normal, direction)`.
    pub curvature_spread: f32,
    /// `rf_propagate(cone, t, curvature_spread + 2 * roughness_spread)`: the cone a reflection
    /// leaves with in the `cone_roughness` mode (on a smooth mirror, in `cone_curvature` too).
    pub reflected: RayCone,
    /// The ray-differential, re-intersection and wireframe values.
    pub diff: RtDiffRecord,
    /// `rf_roughness_spread_angle(roughness)` of a mirror ([`crate::rt::Material::Mirror`]); 0 on
    /// other materials.
    pub roughness_spread: f32,
    /// On glass ([`crate::rt::Material::Glass`]), the index ratio at the hit,
    /// `n_incident / n_transmitted`: `1 / index_of_refraction` entering (the ray meets the side the
    /// stored normal points to, `dot(normal, direction) < 0`), `index_of_refraction` leaving; 0 on
    /// other materials.
    pub eta: f32,
    /// On glass, the normal's turn across the footprint that `rf_refract_ray_cone` takes,
    /// `curvature * footprint` (relative to the stored normal, as that function and
    /// `rf_curvature_spread_angle` take it); 0 elsewhere.
    pub normal_spread: f32,
    /// On glass, 1 where `rf_refract_ray_cone` reports total internal reflection; 0 elsewhere.
    pub total_internal_reflection: u32,
    /// On glass, `rf_refract_ray_cone((width, cone.spread_angle), normal, direction, normal_spread,
    /// eta)`: the cone leaving the hit in the `cone_refraction` mode; 0 elsewhere.
    pub refracted: RayCone,
    /// `rf_anisotropic_cone_gradients(width, direction, p0, p1, p2, uv0, uv1, uv2).dx`: the major
    /// axis of the cone's elliptical footprint in UV units.
    pub cone_uv_dx: glam::Vec2,
    /// `.dy` of the same call: the minor axis.
    pub cone_uv_dy: glam::Vec2,
    /// On glass, `rf_refract_sagittal_cone((width, cone.spread_angle), normal, direction,
    /// curvature * |width|, eta)`: the section across the plane of incidence (the sagittal one)
    /// leaving the hit beside `refracted` in the `cone_sections` mode; 0 elsewhere.
    pub sagittal: RayCone,
}

/// What the renderer measured at a pixel's primary hit with the `ray_diff` and `wireframe`
/// modules (inside [`RtPixelRecord`]). 176 bytes, 16-byte aligned; every pad is 0.
///
/// The eye-ray differential and the neighbour directions come from the inverse matrices of
/// [`RtUniforms`]; the re-intersection uses the world-to-object matrix of the hit instance (the
/// identity in the renderer's scenes) and the hit barycentrics `(1 - u - v, u, v)`. Texel
/// gradients for the LODs are the UV gradients times the texture size, a power of two (exact).
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct RtDiffRecord {
    /// `d_direction_dx` of `rf_eye_ray_diff_from_matrices` (its origin differentials are 0).
    pub eye_d_direction_dx: Vec3,
    /// `rf_lod_isotropic` of the ray-differential texel gradients (`uv_dx`, `uv_dy` times the size).
    pub lod: f32,
    /// `d_direction_dy` of `rf_eye_ray_diff_from_matrices`.
    pub eye_d_direction_dy: Vec3,
    /// `rf_lod_isotropic` of the re-intersection texel gradients (`offset_uv_*` times the size).
    pub offset_lod: f32,
    /// `rf_barycentric_derivatives(eye diff, direction, t, p0, p1, p2).dx`: `(du/dx, dv/dx)`.
    pub barycentric_dx: glam::Vec2,
    /// `(du/dy, dv/dy)` of the same call.
    pub barycentric_dy: glam::Vec2,
    /// `rf_texture_derivatives(barycentric, uv0, uv1, uv2).dx`: the `textureGrad` ddx at scale 1.
    pub uv_dx: glam::Vec2,
    /// `.dy` of the same call.
    pub uv_dy: glam::Vec2,
    /// `rf_pixel_directions(...).right`: the unit direction through the right neighbour.
    pub neighbour_right: Vec3,
    /// `rf_process_wireframe` of the frame's wireframe settings, `b` and `deltas`.
    pub coverage: f32,
    /// `rf_pixel_directions(...).below`: the unit direction through the lower neighbour.
    pub neighbour_below: Vec3,
    /// Always 0.
    pub pad0: u32,
    /// `rf_barycentric_offsets(...).dx`: `b_x - b` for the right neighbour, `(w, u, v)`.
    pub offset_dx: Vec3,
    /// Always 0.
    pub pad1: u32,
    /// `rf_barycentric_offsets(...).dy`: `b_y - b` for the lower neighbour.
    pub offset_dy: Vec3,
    /// Always 0.
    pub pad2: u32,
    /// `rf_uv_gradients_from_offsets(offsets, uv0, uv1, uv2).dx`.
    pub offset_uv_dx: glam::Vec2,
    /// `.dy` of the same call.
    pub offset_uv_dy: glam::Vec2,
    /// `rf_barycentric_deltas(...)`: the per-pixel barycentric deltas the wireframe uses.
    pub deltas: Vec3,
    /// Always 0.
    pub pad3: u32,
    /// `rf_cone_barycentric_deltas(footprint, p0, p1, p2)`: the closed-form alternative, used
    /// for the wireframe seen in reflections.
    pub cone_deltas: Vec3,
    /// Always 0.
    pub pad4: u32,
}

/// Per-frame uniforms of the ray-tracing renderer (a uniform buffer at binding 7):
/// the inverse view and projection matrices that `rf_eye_ray_diff_from_matrices` and
/// `rf_pixel_directions` take (128 bytes: they would not fit in the push constants next to
/// [`RtPushConstants`]), and the wireframe colour and settings. 176 bytes, 16-byte aligned; the
/// same layout under std140 (the uniform block), std430, scalar and WGSL.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct RtUniforms {
    /// Camera to world: columns right, up, view (towards the camera) and the eye.
    pub view_inv: glam::Mat4,
    /// Inverse of a Vulkan-style (y-down) perspective projection of the camera's field of view
    /// and aspect ratio, so `rf_pixel_ndc`'s y = -1 is the top row.
    pub proj_inv: glam::Mat4,
    /// Wireframe line colour and settings.
    pub wireframe: WireframePushConstants,
}

const _: () = assert!(std::mem::size_of::<RtPushConstants>() == 96);
const _: () = assert!(std::mem::size_of::<RtPushConstants>() <= PUSH_CONSTANT_LIMIT);
const _: () =
    assert!(std::mem::size_of::<RtPixelRecord>() == 320 && std::mem::size_of::<RtUniforms>() == 176);

// generated by `cargo xtask codegen` from crates/ray-footprint-lab/src/rt/abi.rs: do not edit
/// Every struct the renderer's shaders share with Rust, with its Rust layout.
#[rustfmt::skip]
pub fn layouts() -> Vec<shader_proptest::layout::StructLayout> {
    use shader_proptest::rust_layout;
    vec![
        rust_layout!(RtPushConstants as "RtPushConstants" { eye, tan_half_fov_y, right, aspect, up, texture_size, forward, mode, cone, width, height, pixel_offset, flags, lod_bias }),
        rust_layout!(RtDiffRecord as "RtDiffRecord" { eye_d_direction_dx, lod, eye_d_direction_dy, offset_lod, barycentric_dx, barycentric_dy, uv_dx, uv_dy, neighbour_right, coverage, neighbour_below, pad0, offset_dx, pad1, offset_dy, pad2, offset_uv_dx, offset_uv_dy, deltas, pad3, cone_deltas, pad4 }),
        rust_layout!(RtPixelRecord as "RtPixelRecord" { normal, t, direction, instance, barycentrics, primitive, hit, cone, width, footprint, texel_density, base_lod, lod, gradient, curvature, curvature_spread, reflected, diff, roughness_spread, eta, normal_spread, total_internal_reflection, refracted, cone_uv_dx, cone_uv_dy, sagittal }),
        rust_layout!(RtUniforms as "RtUniforms" { view_inv, proj_inv, wireframe }),
    ]
}
// end of generated code
