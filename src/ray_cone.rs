//! Ray cones: an isotropic pixel footprint carried along a ray.
//!
//! The Rust mirror of `shaders/wgsl/ray_cone.wgsl` and `shaders/glsl/ray_cone.glsl`. Every function
//! here has a shader twin with the same name prefixed `rf_` (constants `RF_`), in the same order,
//! computing the same expression in the same order of operations.
//!
//! Sources: Akenine-Möller et al., "Texture Level of Detail Strategies for Real-Time Ray Tracing",
//! Ray Tracing Gems ch. 20 (2019), cited as "RTG Eq. N"; Akenine-Möller et al., "Improved Shader and
//! Texture Level of Detail Using Ray Cones", JCGT 10(1), 2021, cited as "JCGT 2021"; Boksanský,
//! Crassin, Akenine-Möller, "Refraction Ray Cones for Texture Level of Detail", Ray Tracing Gems II
//! ch. 10 (2021), cited as "RTG II ch. 10", whose formulas use the half cone angle (this module uses
//! the whole angle throughout).
//!
//! Conventions: `width` is the full footprint diameter and `spread_angle` the full cone angle, both
//! signed (a converging thin-lens cone has a negative spread, and past its focus a negative width);
//! footprints use `|width|`. Normals and directions passed in are unit length. Normals are taken as
//! the mesh stores them, in either orientation: no function needs them turned towards the ray.
//! Where the math diverges, the functions clamp with the constants below, so finite inputs give
//! finite outputs.
//!
//! For a texture fetch at a closest hit, [`hit_texture_lod`] (or [`hit_texture_gradients`] for
//! `textureSampleGrad`) takes what the hit has: the cone at the ray's origin (for a primary ray
//! [`pinhole_ray_cone`] of [`pixel_spread_angle`], [`pixel_spread_angle_from_proj_inv`] or, for an
//! image-plane camera, [`pixel_spread_angle_from_image_plane`]), the ray, the hit distance, the
//! triangle's corners and UVs and the texture's size. The level only matters on a texture with its
//! mip chain ([`crate::mip`]) sampled with linear minification and mipmap filters.

use bytemuck::{Pod, Zeroable};
use glam::{Mat4, Vec2, Vec3, Vec4};

/// Smallest `|cos|` between a normal and a direction used as a divisor (grazing-angle clamp).
pub const MIN_COS: f32 = 1.0e-4;
/// Smallest magnitude passed to `log2` or used as a divisor (zero width, distance, spread).
pub const MIN_MAGNITUDE: f32 = 1.0e-20;
/// Smallest squared length or doubled area used as a divisor or passed to `log2` (a zero-length
/// edge, a zero-area triangle): far below the square of the shortest length the functions are
/// right for (1e-12), and a normal float, which no device flushes to zero.
pub const MIN_SQUARED_MAGNITUDE: f32 = 1.0e-36;
/// Largest vertical field of view in radians; wider values are clamped so `tan(fov_y / 2)` stays finite.
pub const MAX_FOV_Y: f32 = 3.1;
/// Largest finite f16; packed cone values are clamped to `[-F16_MAX, F16_MAX]`.
pub const F16_MAX: f32 = 65504.0;

/// A ray cone: footprint width at the ray origin and the cone's spread angle (RTG Sec. 20.3.4).
///
/// Layout: 8 bytes, two `f32`, identical in Rust, WGSL (`RfRayCone`) and GLSL (`RfRayCone`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct RayCone {
    /// Full footprint diameter at the ray origin, in world units.
    pub width: f32,
    /// Full cone angle in radians; negative while the cone converges.
    pub spread_angle: f32,
}

/// A ray cone packed as two f16 in one `u32`: width in the low half, spread angle in the high half.
///
/// RTG ch. 20 reports this 4-byte form as visually lossless. The shader type is a plain `u32`.
#[repr(transparent)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub struct PackedRayCone(pub u32);

// ---- Packing ----

/// Packs a cone into two f16 (`packHalf2x16` / `pack2x16float`), each value first clamped to
/// `[-F16_MAX, F16_MAX]` so that no finite value becomes infinite. Rounds to nearest, ties to even.
///
/// # Examples
///
/// ```
/// use ray_footprint::ray_cone::{pack_ray_cone, RayCone};
///
/// // In binary16, 0.5 is 0x3800 (biased exponent 14) and 2^-10 is 0x1400 (biased exponent 5).
/// let packed = pack_ray_cone(RayCone { width: 0.5, spread_angle: 1.0 / 1024.0 });
/// assert_eq!(packed.0, 0x1400_3800);
/// // A width beyond the f16 range saturates at 65504 (0x7bff), not at infinity (0x7c00).
/// let wide = pack_ray_cone(RayCone { width: 1.0e6, spread_angle: 0.0 });
/// assert_eq!(wide.0, 0x0000_7bff);
/// ```
pub fn pack_ray_cone(cone: RayCone) -> PackedRayCone {
    let width = f16::bits(cone.width.clamp(-F16_MAX, F16_MAX));
    let spread = f16::bits(cone.spread_angle.clamp(-F16_MAX, F16_MAX));
    PackedRayCone(u32::from(width) | (u32::from(spread) << 16))
}

/// Unpacks a cone packed by [`pack_ray_cone`] (`unpackHalf2x16` / `unpack2x16float`); exact.
///
/// # Examples
///
/// ```
/// use ray_footprint::ray_cone::{pack_ray_cone, unpack_ray_cone, PackedRayCone, RayCone};
///
/// // 0x3c00 is 1.0 and 0xb800 is -0.5 in binary16.
/// assert_eq!(
///     unpack_ray_cone(PackedRayCone(0xb800_3c00)),
///     RayCone { width: 1.0, spread_angle: -0.5 }
/// );
/// // A round trip rounds each value to 11 significant bits: off by at most 2^-11 of it.
/// let cone = RayCone { width: 0.0123, spread_angle: 9.8e-4 };
/// let back = unpack_ray_cone(pack_ray_cone(cone));
/// assert!((back.width - cone.width).abs() <= cone.width / 2048.0);
/// assert!((back.spread_angle - cone.spread_angle).abs() <= cone.spread_angle / 2048.0);
/// ```
pub fn unpack_ray_cone(packed: PackedRayCone) -> RayCone {
    RayCone {
        width: f16::value(packed.0 as u16),
        spread_angle: f16::value((packed.0 >> 16) as u16),
    }
}

// ---- Primary cones from cameras (RTG Eq. 30) ----

/// `2 * tan(fov_y / 2) / H` with the clamps of [`pixel_spread_angle`].
fn pixel_tan_ratio(fov_y: f32, image_height: f32) -> f32 {
    2.0 * (0.5 * fov_y.clamp(0.0, MAX_FOV_Y)).tan() / image_height.max(1.0)
}

/// Spread angle of one pixel of a pinhole camera, exact form (RTG Eq. 30):
/// `alpha = atan(2 * tan(fov_y / 2) / H)`.
///
/// `fov_y` is clamped to `[0, MAX_FOV_Y]`, `image_height` to `>= 1`.
///
/// # Examples
///
/// ```
/// use ray_footprint::ray_cone::pixel_spread_angle;
///
/// // 60-degree field of view, 1080 rows: at distance 1 the image is 2 tan(30°) = 2 / sqrt(3) tall,
/// // so a pixel is 2 / (sqrt(3) 1080) tall there and subtends the atan of that.
/// let alpha = pixel_spread_angle(60f32.to_radians(), 1080.0);
/// let expected = (2.0 / (3f64.sqrt() * 1080.0)).atan();
/// assert!((f64::from(alpha) - expected).abs() < 1e-6 * expected);
/// ```
pub fn pixel_spread_angle(fov_y: f32, image_height: f32) -> f32 {
    (pixel_tan_ratio(fov_y, image_height)).atan()
}

/// Spread angle of one pixel, small-angle form `2 * tan(fov_y / 2) / H` (the ray-cone tutorial's
/// approximation of RTG Eq. 30); clamps as [`pixel_spread_angle`].
///
/// # Examples
///
/// ```
/// use ray_footprint::ray_cone::pixel_spread_angle_small;
///
/// // The pixel's height at distance 1 itself, 2 / (sqrt(3) 1080) for 60 degrees and 1080 rows.
/// let alpha = pixel_spread_angle_small(60f32.to_radians(), 1080.0);
/// let expected = 2.0 / (3f64.sqrt() * 1080.0);
/// assert!((f64::from(alpha) - expected).abs() < 1e-6 * expected);
/// ```
pub fn pixel_spread_angle_small(fov_y: f32, image_height: f32) -> f32 {
    pixel_tan_ratio(fov_y, image_height)
}

/// Spread angle of one pixel from an inverse projection matrix, exact form (RTG Eq. 30) with
/// `tan(fov_y / 2) = |proj_inv[1][1]|` (column 1, row 1; holds for y-flipped Vulkan projections too).
///
/// # Examples
///
/// ```
/// use glam::camera::rh::proj::vulkan::perspective;
/// use ray_footprint::ray_cone::pixel_spread_angle_from_proj_inv;
///
/// // glam's Vulkan projection (y down) for 60 degrees, 16:9.
/// let proj = perspective(60f32.to_radians(), 16.0 / 9.0, 0.1, 1000.0);
/// let alpha = pixel_spread_angle_from_proj_inv(proj.inverse(), 1080.0);
/// // As from the field of view: atan(2 tan(30°) / 1080), with tan(30°) = 1 / sqrt(3).
/// let expected = (2.0 / (3f64.sqrt() * 1080.0)).atan();
/// assert!((f64::from(alpha) - expected).abs() < 1e-6 * expected);
/// ```
pub fn pixel_spread_angle_from_proj_inv(proj_inv: Mat4, image_height: f32) -> f32 {
    (2.0 * proj_inv.y_axis.y.abs() / image_height.max(1.0)).atan()
}

/// Spread angle of one pixel of an image-plane camera, exact form (RTG Eq. 30): the camera of "Ray
/// Tracing in One Weekend" and most hobby ray tracers, a plane `plane_height` world units tall at
/// `plane_distance` from the eye (its lower left corner plus its two spans), whose
/// `2 tan(fov_y / 2)` is `plane_height / plane_distance`:
/// `alpha = atan(|plane_height| / (max(|plane_distance|, MIN_MAGNITUDE) * max(image_height, 1)))`.
/// Only the ratio of the plane's height to its distance matters: scaling both changes nothing.
///
/// # Examples
///
/// ```
/// use ray_footprint::ray_cone::{pixel_spread_angle, pixel_spread_angle_from_image_plane};
///
/// // "Ray Tracing in One Weekend": a viewport 2 units tall at focal length 1, 225 pixels high:
/// // a vertical field of view of 2 atan(1) = 90 degrees.
/// let alpha = pixel_spread_angle_from_image_plane(2.0, 1.0, 225.0);
/// let from_fov = pixel_spread_angle(std::f32::consts::FRAC_PI_2, 225.0);
/// assert!((alpha - from_fov).abs() < 1e-6 * alpha);
/// assert_eq!(alpha, (2.0f32 / 225.0).atan());
/// ```
pub fn pixel_spread_angle_from_image_plane(plane_height: f32, plane_distance: f32, image_height: f32) -> f32 {
    (plane_height.abs() / (plane_distance.abs().max(MIN_MAGNITUDE) * image_height.max(1.0))).atan()
}

/// Primary cone of a pinhole camera: width 0 at the eye, spread `pixel_spread_angle` (RTG Eq. 30),
/// the same for every pixel (see [`pinhole_ray_cone_for_ray`] for off-axis pixels).
///
/// # Examples
///
/// ```
/// use ray_footprint::ray_cone::{pinhole_ray_cone, pixel_spread_angle, width_at};
///
/// let cone = pinhole_ray_cone(pixel_spread_angle(60f32.to_radians(), 1080.0));
/// // On a wall 10 m away facing the camera, a pixel at the image centre is 10 * 2 tan(30°) / 1080
/// // tall; the cone's width matches it to within (pixel angle)^2 / 3 = 4e-7 of it.
/// let pixel_height = 10.0 * 2.0 / (3f64.sqrt() * 1080.0);
/// let width = f64::from(width_at(cone, 10.0));
/// assert!((width - pixel_height).abs() < 1e-6 * pixel_height);
/// ```
pub fn pinhole_ray_cone(pixel_spread_angle: f32) -> RayCone {
    RayCone {
        width: 0.0,
        spread_angle: pixel_spread_angle,
    }
}

/// Primary cone of a pinhole camera for one ray, narrower off axis (the OptiX Toolkit's per-ray
/// pinhole cone): width 0, spread
/// `pixel_spread_angle * clamp(dot(direction, view_axis), 0, 1)`.
///
/// `direction` is the unit ray direction and `view_axis` the camera's unit viewing direction. A
/// pixel whose ray is `theta` off the axis subtends about `cos(theta)` of the centre pixel's angle
/// across the radial direction and `cos^2(theta)` along it; the isotropic LOD (RTG Eq. 2) follows
/// the longer side, so this cone fits every pixel to within half a LOD level, where
/// [`pinhole_ray_cone`] is `1 / cos(theta)` too wide. The cosine is clamped to `[0, 1]`: a ray at
/// 90 degrees to the view axis or behind the camera (outside any pinhole's view) gets spread 0, the
/// limit of a pixel at 90 degrees, and `|spread|` never exceeds `|pixel_spread_angle|`.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::{pinhole_ray_cone_for_ray, pixel_spread_angle};
///
/// let alpha = pixel_spread_angle(60f32.to_radians(), 1080.0);
/// // A pixel 30 degrees off the axis lies 1 / cos(30°) from the eye on the image plane at distance 1,
/// // sqrt(1 + tan^2(30°)) = sqrt(4 / 3), so it subtends the central pixel's angle over that distance.
/// let direction = Vec3::new(0.5, 0.0, -(0.75f32.sqrt()));
/// let cone = pinhole_ray_cone_for_ray(alpha, direction, Vec3::NEG_Z);
/// let expected = alpha / (4.0f32 / 3.0).sqrt();
/// assert!((cone.spread_angle - expected).abs() < 1e-6 * expected);
/// // No pixel of the camera sees a ray going backwards.
/// assert_eq!(pinhole_ray_cone_for_ray(alpha, Vec3::Z, Vec3::NEG_Z).spread_angle, 0.0);
/// ```
pub fn pinhole_ray_cone_for_ray(pixel_spread_angle: f32, direction: Vec3, view_axis: Vec3) -> RayCone {
    RayCone {
        width: 0.0,
        spread_angle: pixel_spread_angle * direction.dot(view_axis).clamp(0.0, 1.0),
    }
}

/// Primary cone of an orthographic camera whose view is `view_height` world units tall:
/// width = one pixel, `view_height / H`, spread 0. `image_height` is clamped to `>= 1`.
///
/// # Examples
///
/// ```
/// use ray_footprint::ray_cone::orthographic_ray_cone;
///
/// // A view 2 m tall on 1080 rows: 1080 pixel widths tile the 2 m, and the rays stay parallel.
/// let cone = orthographic_ray_cone(2.0, 1080.0);
/// assert!((cone.width * 1080.0 - 2.0).abs() <= 2.0 * f32::EPSILON);
/// assert_eq!(cone.spread_angle, 0.0);
/// ```
pub fn orthographic_ray_cone(view_height: f32, image_height: f32) -> RayCone {
    RayCone {
        width: view_height / image_height.max(1.0),
        spread_angle: 0.0,
    }
}

/// Primary cone of a thin-lens camera with aperture diameter `aperture` focused at
/// `focus_distance`: width `aperture` at the lens, spread `pixel_spread_angle - aperture / focus_distance`
/// (negative while the cone converges towards the focal plane). `focus_distance` is clamped to
/// `>= MIN_MAGNITUDE`.
///
/// # Examples
///
/// ```
/// use ray_footprint::ray_cone::{pixel_spread_angle, thin_lens_ray_cone, width_at};
///
/// // A 5 cm aperture focused at 4 m (60 degrees, 1080 rows): on the focal plane the pixel is
/// // in focus, so the cone has shrunk from the lens to the pinhole footprint, 4 m times the pixel
/// // angle. The tolerance is the rounding of 0.05 + (alpha - 0.0125) * 4, about 4e-9.
/// let alpha = pixel_spread_angle(60f32.to_radians(), 1080.0);
/// let cone = thin_lens_ray_cone(alpha, 0.05, 4.0);
/// assert!(cone.spread_angle < 0.0);
/// assert!((width_at(cone, 4.0) - 4.0 * alpha).abs() < 1e-8);
/// ```
pub fn thin_lens_ray_cone(pixel_spread_angle: f32, aperture: f32, focus_distance: f32) -> RayCone {
    RayCone {
        width: aperture,
        spread_angle: pixel_spread_angle - aperture / focus_distance.max(MIN_MAGNITUDE),
    }
}

// ---- Propagation (RTG Eq. 35) ----

/// Cone width after travelling `t` along the ray: `width + spread_angle * t` (RTG Eq. 35, first line).
///
/// # Examples
///
/// ```
/// use ray_footprint::ray_cone::{width_at, RayCone};
///
/// // A cone 1 cm wide spreading by 1 mrad has its apex width / spread = 10 m behind the origin;
/// // by similar triangles it is (10 + 25) / 10 times as wide 25 m further on.
/// let cone = RayCone { width: 0.01, spread_angle: 0.001 };
/// let expected = 0.01 * (10.0 + 25.0) / 10.0;
/// assert!((width_at(cone, 25.0) - expected).abs() < 1e-6 * expected);
/// ```
pub fn width_at(cone: RayCone, t: f32) -> f32 {
    cone.width + cone.spread_angle * t
}

/// The cone that leaves a hit at distance `t` whose surface spreads it by `surface_spread_angle`
/// (RTG Eq. 35): `width' = width + spread_angle * t`, `spread' = spread_angle + surface_spread_angle`.
///
/// This is the reflected (or transmitted) cone. Its width is the cone's cross-section at the hit,
/// not the slanted footprint on the surface, so a planar mirror (`surface_spread_angle = 0`) behaves
/// exactly like a mirror-image camera.
///
/// # Examples
///
/// ```
/// use ray_footprint::ray_cone::{pinhole_ray_cone, pixel_spread_angle, propagate, width_at};
///
/// // A flat mirror 3 m from the camera: the reflected cone is the cone of the camera's mirror image
/// // 3 m behind the mirror, so 2 m after the mirror it is as wide as a pinhole cone at 5 m.
/// let alpha = pixel_spread_angle(60f32.to_radians(), 1080.0);
/// let reflected = propagate(pinhole_ray_cone(alpha), 3.0, 0.0);
/// assert!((width_at(reflected, 2.0) - 5.0 * alpha).abs() < 1e-6 * 5.0 * alpha);
/// ```
pub fn propagate(cone: RayCone, t: f32, surface_spread_angle: f32) -> RayCone {
    RayCone {
        width: width_at(cone, t),
        spread_angle: cone.spread_angle + surface_spread_angle,
    }
}

// ---- Surface spread from G-buffer derivatives (RTG Eq. 31-33) ----

/// `sqrt(dot(dn_dx, dn_dx) + dot(dn_dy, dn_dy))`.
fn normal_derivative_length(dn_dx: Vec3, dn_dy: Vec3) -> f32 {
    (dn_dx.dot(dn_dx) + dn_dy.dot(dn_dy)).sqrt()
}

/// Angle spanned by the normal across one pixel, from G-buffer normal derivatives (RTG Eq. 31-32):
/// `phi = 2 * atan(0.5 * sqrt(dot(dn_dx, dn_dx) + dot(dn_dy, dn_dy)))`.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::normal_spread_angle;
///
/// // Across one pixel the normal (0, 0, 1) changes by (0.02, 0, 0): the normals half a pixel either
/// // side are (-+0.01, 0, 1), whose angle is atan2(|cross|, dot) = atan2(0.02, 0.9999).
/// let phi = normal_spread_angle(Vec3::new(0.02, 0.0, 0.0), Vec3::ZERO);
/// let expected = 0.02f64.atan2(0.9999);
/// assert!((f64::from(phi) - expected).abs() < 1e-6 * expected);
/// ```
pub fn normal_spread_angle(dn_dx: Vec3, dn_dy: Vec3) -> f32 {
    2.0 * (0.5 * normal_derivative_length(dn_dx, dn_dy)).atan()
}

/// Small-angle form of [`normal_spread_angle`]: `sqrt(dot(dn_dx, dn_dx) + dot(dn_dy, dn_dy))` (RTG Eq. 32).
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::normal_spread_angle_small;
///
/// // Normal changes of 0.003 and 0.004 per pixel at right angles: 0.005 by Pythagoras.
/// let phi = normal_spread_angle_small(Vec3::new(0.003, 0.0, 0.0), Vec3::new(0.0, 0.004, 0.0));
/// assert!((phi - 0.005).abs() < 1e-9);
/// ```
pub fn normal_spread_angle_small(dn_dx: Vec3, dn_dy: Vec3) -> f32 {
    normal_derivative_length(dn_dx, dn_dy)
}

/// Whether the surface is convex (1) or concave (-1) as seen by the ray (RTG Eq. 33):
/// `s = sign(dot(dp_dx, dn_dx) + dot(dp_dy, dn_dy))` with `sign(0) = -1`.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::curvature_sign;
///
/// // On a unit sphere the outward normal is the position, n = p: seen from outside, the normal
/// // changes with the position (convex); from inside, with normals n = -p, against it (concave).
/// let (dp_dx, dp_dy) = (Vec3::new(0.01, 0.0, 0.0), Vec3::new(0.0, -0.01, 0.0));
/// assert_eq!(curvature_sign(dp_dx, dp_dy, dp_dx, dp_dy), 1.0);
/// assert_eq!(curvature_sign(dp_dx, dp_dy, -dp_dx, -dp_dy), -1.0);
/// ```
pub fn curvature_sign(dp_dx: Vec3, dp_dy: Vec3, dn_dx: Vec3, dn_dy: Vec3) -> f32 {
    if dp_dx.dot(dn_dx) + dp_dy.dot(dn_dy) > 0.0 {
        1.0
    } else {
        -1.0
    }
}

/// Surface spread angle (RTG Eq. 32): `beta = 2 * k1 * s * phi + k2`, with `phi` from
/// [`normal_spread_angle`] and `s` from [`curvature_sign`] (or 1 for saddle-heavy scenes).
/// RTG uses `k1 = 1`, `k2 = 0` by default.
///
/// # Examples
///
/// ```
/// use glam::{DQuat, DVec3};
/// use ray_footprint::ray_cone::surface_spread_angle;
///
/// // RTG's defaults (k1 = 1, k2 = 0), a convex surface whose normal turns by 0.01 across the footprint.
/// let beta = surface_spread_angle(0.01, 1.0, 1.0, 0.0);
/// // Law of reflection: turning the normal by 0.01 turns the reflected ray by twice that.
/// let d = DVec3::new(0.6, 0.0, -0.8);
/// let reflect = |n: DVec3| d - 2.0 * d.dot(n) * n;
/// let (r0, r1) = (reflect(DVec3::Z), reflect(DQuat::from_rotation_y(0.01) * DVec3::Z));
/// let turn = r0.cross(r1).length().atan2(r0.dot(r1));
/// assert!((f64::from(beta) - turn).abs() < 1e-9); // 0.02 in f32 is 4.5e-10 off
/// ```
pub fn surface_spread_angle(normal_spread_angle: f32, curvature_sign: f32, k1: f32, k2: f32) -> f32 {
    2.0 * k1 * curvature_sign * normal_spread_angle + k2
}

// ---- Curvature from vertex normals (JCGT 2021; Rusinkiewicz 2004) ----

/// Curvature along one triangle edge from its vertex normals (JCGT 2021, Sec. 3):
/// `k = dot(n_j - n_i, p_j - p_i) / |p_j - p_i|^2`; 1/R on a sphere of radius R with outward normals.
/// The squared length is clamped to `>= MIN_SQUARED_MAGNITUDE` (a zero-length edge gives 0), so
/// that edges down to 1e-18 long are measured as they are.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::edge_curvature;
///
/// // Two vertices of a sphere of radius 2 with their outward normals p / 2: curvature 1 / 2.
/// let (p_i, p_j) = (Vec3::new(2.0, 0.0, 0.0), Vec3::new(1.2, 1.6, 0.0));
/// let k = edge_curvature(p_i, p_j, p_i / 2.0, p_j / 2.0);
/// assert!((k - 0.5).abs() < 1e-6);
/// ```
pub fn edge_curvature(p_i: Vec3, p_j: Vec3, n_i: Vec3, n_j: Vec3) -> f32 {
    let edge = p_j - p_i;
    (n_j - n_i).dot(edge) / edge.dot(edge).max(MIN_SQUARED_MAGNITUDE)
}

/// Curvature estimate of a triangle: the mean of its three [`edge_curvature`] values (JCGT 2021).
/// Zero for a flat triangle (equal vertex normals).
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::triangle_curvature;
///
/// // A triangle of the unit sphere, each normal its vertex: curvature 1. The same triangle with one
/// // normal for all three vertices is flat: 0.
/// let (p0, p1, p2) = (Vec3::X, Vec3::Y, Vec3::Z);
/// assert!((triangle_curvature(p0, p1, p2, p0, p1, p2) - 1.0).abs() < 1e-6);
/// let flat = Vec3::ONE.normalize();
/// assert_eq!(triangle_curvature(p0, p1, p2, flat, flat, flat), 0.0);
/// ```
pub fn triangle_curvature(p0: Vec3, p1: Vec3, p2: Vec3, n0: Vec3, n1: Vec3, n2: Vec3) -> f32 {
    (edge_curvature(p0, p1, n0, n1) + edge_curvature(p1, p2, n1, n2) + edge_curvature(p2, p0, n2, n0)) / 3.0
}

/// `axis / max(|axis|, MIN_MAGNITUDE)`: unit length, or shorter when `|axis| < MIN_MAGNITUDE`
/// (zero stays zero).
fn clamped_unit(axis: Vec3) -> Vec3 {
    axis / axis.length().max(MIN_MAGNITUDE)
}

/// First axis of a triangle's shape frame: `u = (p1 - p0) / |p1 - p0|` ([`clamped_unit`]).
fn shape_frame_u(p0: Vec3, p1: Vec3) -> Vec3 {
    clamped_unit(p1 - p0)
}

/// A triangle's unit face normal given the first axis `u` of its shape frame ([`shape_frame_u`]):
/// `face = unit(u × unit(p2 - p0))`, the normal of the counter-clockwise winding `p0, p1, p2`. The
/// edges are made unit length before the cross product so that nothing overflows for coordinates
/// up to 1e18. A zero-area triangle whose edges are exactly parallel has `face = 0`.
fn face_normal(u: Vec3, p0: Vec3, p2: Vec3) -> Vec3 {
    clamped_unit(u.cross(clamped_unit(p2 - p0)))
}

/// Second axis of a triangle's shape frame, given its first, `u` ([`shape_frame_u`]): `v = face × u`
/// with the face normal `face` ([`face_normal`]). `(u, v, face)` is right-handed. A zero-area
/// triangle whose edges are exactly parallel has `v = 0`.
fn shape_frame_v(u: Vec3, p0: Vec3, p2: Vec3) -> Vec3 {
    face_normal(u, p0, p2).cross(u)
}

/// A triangle's shape operator (second fundamental form) `II = [[e, f], [f, g]]`, returned as
/// `(e, f, g)`, fitted to its vertex normals by least squares (Rusinkiewicz, "Estimating Curvatures
/// and Their Derivatives on Triangle Meshes", 3DPVT 2004, Sec. 3, the per-face least-squares fit).
///
/// The frame is the triangle's own: `u = unit(p1 - p0)`, `v = face × u` with the face normal of the
/// counter-clockwise winding `p0, p1, p2`. For each edge `p_j - p_i` with components `(a, b)` in
/// `(u, v)` and normal change `(du, dv) = ((n_j - n_i).u, (n_j - n_i).v)`, the fit asks
/// `II [a, b] = [du, dv]`: six equations in three unknowns. The edge components are first divided
/// by the largest of them, `extent = max |a|, |b|` (at least `MIN_MAGNITUDE`), so that the fit is
/// the same at every scale and nothing is squared but numbers of at most 1: the fit in these units
/// is `extent II`. With the sums over the three edges `A = Σa²`, `B = Σb²`, `C = Σab` (divided by `A + B`,
/// so that `A + B = 1`), `r = (Σa du, Σ(b du + a dv), Σb dv)` (divided by the same), the normal
/// equations `[[A, C, 0], [C, 1, C], [0, C, B]] (e, f, g) = r` are solved in closed form by
/// cofactors over the determinant `AB - C²` (which is `12 area² / (A + B)²` before the division:
/// 1/4 for an equilateral triangle, 0 for a degenerate one), and the solution divided by `extent`.
/// Scaling the corners by `s` divides the result by `s` exactly where `s` is a power of two.
///
/// Sign: as [`edge_curvature`], positive where the surface bends away from the side its normals
/// point to (a sphere of radius R with outward normals has `II = I / R`); flipping the normals
/// flips `II`. The fit is exact wherever the normals change linearly along the surface (spheres,
/// cylinders), and approaches a smooth surface's shape operator as the triangle shrinks.
///
/// Clamps: `extent`, `A + B` and the determinant are kept at least `MIN_MAGNITUDE`; a zero-area triangle
/// whose edges are exactly parallel (or coincident vertices) gives `(0, 0, 0)`, a flat one. The
/// solution's divisor, the determinant times `extent`, is kept at least `MIN_SQUARED_MAGNITUDE`: two
/// clamped values multiply to 1e-40, below the smallest normal float, which a device that flushes
/// subnormals to zero or divides through reciprocals turns into `0 * inf` (NaN). A nearly
/// degenerate sliver is ill-conditioned: its error grows as the inverse of the determinant.
///
/// One shape operator serves every ray that meets the triangle: compute it once per hit (or store
/// it per triangle, 12 bytes) and ask [`normal_curvature`] for each direction.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::triangle_shape_operator;
///
/// // A triangle of a sphere of radius 2 with its outward normals p / 2: II = I / 2 in any frame.
/// let (p0, p1, p2) = (Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.0, 0.0, 2.0));
/// let ii = triangle_shape_operator(p0, p1, p2, p0 / 2.0, p1 / 2.0, p2 / 2.0);
/// assert!((ii - Vec3::new(0.5, 0.0, 0.5)).abs().max_element() < 1e-6);
/// ```
pub fn triangle_shape_operator(p0: Vec3, p1: Vec3, p2: Vec3, n0: Vec3, n1: Vec3, n2: Vec3) -> Vec3 {
    let u = shape_frame_u(p0, p1);
    let v = shape_frame_v(u, p0, p2);
    let (e01, e12, e20) = (p1 - p0, p2 - p1, p0 - p2);
    let (t01, t12, t20) = (n1 - n0, n2 - n1, n0 - n2);
    let along_u = Vec3::new(e01.dot(u), e12.dot(u), e20.dot(u));
    let along_v = Vec3::new(e01.dot(v), e12.dot(v), e20.dot(v));
    let largest = along_u.abs().max(along_v.abs());
    let extent = largest.x.max(largest.y).max(largest.z.max(MIN_MAGNITUDE));
    let (a, b) = (along_u / extent, along_v / extent);
    let du = Vec3::new(t01.dot(u), t12.dot(u), t20.dot(u));
    let dv = Vec3::new(t01.dot(v), t12.dot(v), t20.dot(v));
    let scale = (a.dot(a) + b.dot(b)).max(MIN_MAGNITUDE);
    let (aa, bb, ab) = (a.dot(a) / scale, b.dot(b) / scale, a.dot(b) / scale);
    let r = Vec3::new(a.dot(du), b.dot(du) + a.dot(dv), b.dot(dv)) / scale;
    let determinant = (aa * bb - ab * ab).max(MIN_MAGNITUDE);
    let e = (bb - ab * ab) * r.x - bb * ab * r.y + ab * ab * r.z;
    let f = aa * bb * r.y - bb * ab * r.x - aa * ab * r.z;
    let g = (aa - ab * ab) * r.z - aa * ab * r.y + ab * ab * r.x;
    Vec3::new(e, f, g) / (determinant * extent).max(MIN_SQUARED_MAGNITUDE)
}

/// Normal curvature of a triangle along `direction`: `k = II(d, d) / |d|²` with `d = (a, b)` the
/// components of the unit direction in the triangle's frame `(u, v)` (its projection into the
/// triangle's plane) and `II = (e, f, g)` from [`triangle_shape_operator`] of the same corners
/// (Euler's formula; Rusinkiewicz 2004, Sec. 3):
/// `k = (e a² + 2 f a b + g b² + MIN_COS² (e + g) / 2) / (a² + b² + MIN_COS²)`.
///
/// Signed as [`edge_curvature`]: positive where the surface bends away from the side the normals
/// point to, so a saddle gives opposite signs along its two principal directions.
///
/// `direction` need not be unit length: it is made unit first, so any length
/// from 1e-12 up gives the same curvature. Its part in the triangle's plane, `sqrt(a² + b²)`, is
/// the sine of its angle with the face normal. Where that sine is well above `MIN_COS` the `MIN_COS²`
/// terms change the result by a share of at most `MIN_COS² / (a² + b²)` of `k - (e + g) / 2` (1e-6
/// at a sine of 0.1). Within about `MIN_COS` radians of the face normal the direction has no
/// reliable plane of incidence (a face normal rounded to f32 keeps in-plane components of about
/// 1e-7), and the result goes to the mean curvature `(e + g) / 2`, the normal curvature averaged
/// over every direction around the normal: exactly along either face normal, and for a zero
/// direction.
///
/// It takes the corners rather than the frame so that the frame stays private to this module and
/// one call per ray needs nothing but what a hit has.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::{normal_curvature, triangle_shape_operator};
///
/// // A triangle of a cylinder of radius 2 around the z axis, normals (x, y, 0) / 2: curvature 1/2
/// // around the cylinder, 0 along its axis.
/// let (p0, p1, p2) = (Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 2.0, 0.0), Vec3::new(2.0, 0.0, 1.0));
/// let flat = |p: Vec3| Vec3::new(p.x, p.y, 0.0) / 2.0;
/// let ii = triangle_shape_operator(p0, p1, p2, flat(p0), flat(p1), flat(p2));
/// assert!(normal_curvature(p0, p1, p2, ii, Vec3::Z).abs() < 1e-6);
/// // Across, in the plane of the triangle: along the chord p0 -> p1, (1 - 0) / 2.
/// assert!((normal_curvature(p0, p1, p2, ii, p1 - p0) - 0.5).abs() < 1e-6);
/// ```
pub fn normal_curvature(p0: Vec3, p1: Vec3, p2: Vec3, shape_operator: Vec3, direction: Vec3) -> f32 {
    let u = shape_frame_u(p0, p1);
    let unit = clamped_unit(direction);
    let a = unit.dot(u);
    let b = unit.dot(shape_frame_v(u, p0, p2));
    let (e, f, g) = (shape_operator.x, shape_operator.y, shape_operator.z);
    let mean = 0.5 * (e + g);
    let normal_weight = MIN_COS * MIN_COS;
    (e * a * a + 2.0 * f * a * b + g * b * b + normal_weight * mean) / (a * a + b * b + normal_weight)
}

/// Principal curvatures of a shape operator `II = (e, f, g)` from [`triangle_shape_operator`],
/// the greater first: the eigenvalues of `[[e, f], [f, g]]`,
/// `k = mean ± radius` with `mean = (e + g) / 2` and `radius = |((e - g) / 2, f)|`
/// (do Carmo, *Differential Geometry of Curves and Surfaces*, 1976, Sec. 3-2).
///
/// Signed as [`normal_curvature`], whose extremes over all directions they are (Euler's theorem).
/// Their mean `(k1 + k2) / 2` is the mean curvature, the normal curvature averaged over every
/// direction around the normal; their product, the Gaussian curvature, is negative on a saddle.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_cone::principal_curvatures;
///
/// // A saddle bending by 1/2 one way and -1/2 the other.
/// assert_eq!(principal_curvatures(Vec3::new(0.5, 0.0, -0.5)), Vec2::new(0.5, -0.5));
/// // The same saddle with its frame turned by 45 degrees: only f is left.
/// assert_eq!(principal_curvatures(Vec3::new(0.0, 0.5, 0.0)), Vec2::new(0.5, -0.5));
/// ```
pub fn principal_curvatures(shape_operator: Vec3) -> Vec2 {
    let mean = 0.5 * (shape_operator.x + shape_operator.z);
    let radius = Vec2::new(0.5 * (shape_operator.x - shape_operator.z), shape_operator.y).length();
    Vec2::new(mean + radius, mean - radius)
}

/// Unit direction, in the world, of the greater principal curvature of a triangle's shape
/// operator `II = (e, f, g)` ([`triangle_shape_operator`] of the same corners): the eigenvector
/// of `[[e, f], [f, g]]` for `mean + radius` ([`principal_curvatures`]) in the triangle's frame
/// `(u, v)`. With `h = (e - g) / 2`, the eigenvector is `(h + radius, f)` where `h >= 0` and
/// `(f, radius - h)` where `h < 0`, the longer of the two, whose length is at least `radius`;
/// it is turned to a non-negative `u` component, so that a direction and its opposite, the same
/// axis, give one answer (the sign changes only across the axis `v`).
///
/// An umbilic (`e = g`, `f = 0`: a sphere, a plane) has every direction principal and gives
/// `(0, 0, 0)`. The direction of the lesser curvature is the face normal crossed with this one.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::principal_direction;
///
/// // Corners 0, x, y: the frame is (x, y). A saddle bending most along y.
/// let (p0, p1, p2) = (Vec3::ZERO, Vec3::X, Vec3::Y);
/// assert_eq!(principal_direction(p0, p1, p2, Vec3::new(-0.5, 0.0, 0.5)), Vec3::Y);
/// // A sphere: no principal direction.
/// assert_eq!(principal_direction(p0, p1, p2, Vec3::new(0.5, 0.0, 0.5)), Vec3::ZERO);
/// ```
pub fn principal_direction(p0: Vec3, p1: Vec3, p2: Vec3, shape_operator: Vec3) -> Vec3 {
    let u = shape_frame_u(p0, p1);
    let v = shape_frame_v(u, p0, p2);
    let half_gap = 0.5 * (shape_operator.x - shape_operator.z);
    let f = shape_operator.y;
    let radius = Vec2::new(half_gap, f).length();
    let axis = if half_gap >= 0.0 {
        Vec2::new(half_gap + radius, f)
    } else {
        Vec2::new(f, radius - half_gap)
    };
    let axis = if axis.x < 0.0 { -axis } else { axis };
    clamped_unit(axis.x * u + axis.y * v)
}

/// The curvature an isotropic cone takes from a surface's principal curvatures (in either order,
/// as [`principal_curvatures`] gives them): the one of lesser magnitude when both have one sign,
/// else 0 (a saddle, or a cylinder, straight along its axis). It is the bend every direction of a
/// round footprint shares: a round cone, widened by it through [`curvature_spread_angle`],
/// spreads no faster than the beam does along any direction, and on a saddle, where the beam
/// converges one way and diverges the other, it keeps the planar mirror's spread.
///
/// The OptiX Toolkit makes the same choice from a triangle's three edge curvatures
/// (`minTriangleCurvature` in its `ray_cone.h`); this takes it from the fitted shape operator.
///
/// # Examples
///
/// ```
/// use glam::Vec2;
/// use ray_footprint::ray_cone::isotropic_curvature;
///
/// assert_eq!(isotropic_curvature(Vec2::new(0.5, 0.25)), 0.25); // convex: the lesser
/// assert_eq!(isotropic_curvature(Vec2::new(-0.25, -0.5)), -0.25); // concave: the lesser magnitude
/// assert_eq!(isotropic_curvature(Vec2::new(0.5, -0.5)), 0.0); // a saddle
/// ```
pub fn isotropic_curvature(principal_curvatures: Vec2) -> f32 {
    let least = principal_curvatures.min_element();
    let most = principal_curvatures.max_element();
    if least > 0.0 {
        least
    } else if most < 0.0 {
        most
    } else {
        0.0
    }
}

/// The cosine of incidence seen from the side `normal` points to, `-dot(normal, direction)`,
/// kept at least `MIN_COS` away from 0 with its sign: positive when the ray meets the side the
/// normal points to. A cosine of exactly 0, `+0` or `-0`, becomes `+MIN_COS`.
fn facing_cos(normal: Vec3, direction: Vec3) -> f32 {
    let facing = -normal.dot(direction);
    if facing.abs() < MIN_COS {
        if facing >= 0.0 {
            MIN_COS
        } else {
            -MIN_COS
        }
    } else {
        facing
    }
}

/// Surface spread angle of a reflection from a curvature estimate (JCGT 2021, "optimized" form, as
/// Falcor's `computeSpreadAngleFromCurvatureIso` evaluates it): across the cone's
/// slanted footprint the normal turns by `curvature * width / dn` with `dn = -dot(normal, direction)`,
/// and the reflected direction turns twice as much:
/// `beta = 2 * curvature * width / dn`, `dn` kept at least `MIN_COS` away from 0 with its sign
/// (`|dn| < MIN_COS` becomes `+-MIN_COS`; `dn = 0`, of either sign, becomes `+MIN_COS`, as if the ray
/// met the side the normal points to).
///
/// - `curvature` is estimated from the mesh's stored normals ([`triangle_curvature`], or, signed
///   and in the plane of incidence, [`normal_curvature`] along `direction`), and
///   `normal` is the shading normal interpolated from the *same* stored normals, not turned towards
///   the ray: flipping the normals flips the sign of both `curvature` and `dn`, so `beta` does not
///   depend on which way the mesh's normals point, and a hit on either side of a surface is right.
///   A convex surface (its normals diverging on the side the ray comes from) spreads the cone, a
///   concave one focuses it. Flip both or neither.
/// - `width` is the *signed* cone width at the hit ([`width_at`]). Past a focus the width is
///   negative (the cone has turned inside out), and a spread of the width's sign widens it. A convex
///   mirror gives `beta` the width's sign and a concave one the opposite sign, on both sides of a
///   focus. The reflected cone is `propagate(cone, t, beta)`.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::curvature_spread_angle;
///
/// // A cone 1 cm wide meets a mirror ball of radius 1 (curvature 1) head on.
/// let beta = curvature_spread_angle(1.0, 0.01, Vec3::Z, Vec3::NEG_Z);
/// // Its edge rays, 5 mm off centre, meet normals tilted by asin(0.005) and leave turned by twice
/// // that, each to its own side: 4 asin(0.005) apart. asin x = x + x^3 / 6 puts the first-order
/// // beta 4e-6 (relative) below that.
/// let exact = 4.0 * 0.005f64.asin();
/// assert!((f64::from(beta) - exact).abs() < 1e-5 * exact);
/// ```
pub fn curvature_spread_angle(curvature: f32, width: f32, normal: Vec3, direction: Vec3) -> f32 {
    2.0 * curvature * width / facing_cos(normal, direction)
}

// ---- Footprint and texture LOD (RTG Eq. 34) ----

/// World-space footprint on the surface, slant-corrected (ray-cone tutorial, after RTG Eq. 34):
/// `|width + spread_angle * t| / max(|dot(normal, direction)|, MIN_COS)`.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::{orthographic_ray_cone, world_footprint};
///
/// // A parallel cone 1 cm wide meets the floor (normal +Y) 60 degrees from the normal: the strip it
/// // cuts out is 1 cm / cos(60°) = 2 cm long.
/// let cone = orthographic_ray_cone(10.8, 1080.0);
/// let angle = 60f32.to_radians();
/// let direction = Vec3::new(angle.sin(), -angle.cos(), 0.0);
/// let footprint = world_footprint(cone, 4.0, Vec3::Y, direction);
/// assert!((footprint - 0.02).abs() < 1e-6 * 0.02);
/// ```
pub fn world_footprint(cone: RayCone, t: f32, normal: Vec3, direction: Vec3) -> f32 {
    width_at(cone, t).abs() / normal.dot(direction).abs().max(MIN_COS)
}

/// The width of a round cone whose footprint on the surface is as long as the longer axis of the
/// footprint of a beam with two sections (an astigmatic beam): `tangential_width` across the ray in
/// the direction `cross(s, direction)` and `sagittal_width` along `s`, the unit part of
/// `sagittal_axis` perpendicular to `direction`. Feed it to [`texture_lod`] or [`world_footprint`]
/// (with spread 0) in place of a round cone's width; [`refract_sagittal_cone`] gives the sagittal
/// section a refraction passes on, with `sagittal_axis = cross(direction, normal)` there.
///
/// The two sections span the ellipse `a cos phi + b sin phi` across the ray, `a = w_t t`,
/// `b = w_s s`; projected along the unit `direction` onto the plane of the unit `normal` a vector
/// `v` across the ray becomes `v - direction (n . v) / (n . d)`, so the ellipse on the surface has
/// the Gram matrix `G = diag(w_t^2, w_s^2) + g g^T / c^2` with `g = (w_t n . t, w_s n . s)` and
/// `c = max(|n . d|, MIN_COS)`. Its longer semi-axis is `sqrt(lambda)`, `lambda` the larger
/// eigenvalue of `G`, and the width returned is `c sqrt(lambda)`: the round cone of that width has
/// the footprint `c sqrt(lambda) / c` ([`world_footprint`]). The widths are divided by the larger
/// magnitude (at least `MIN_MAGNITUDE`) before squaring and the result multiplied back. With equal
/// widths this is `|w|` (a round cone); head on (`c = 1`) it is `max(|w_t|, |w_s|)`; where
/// `sagittal_axis` has no part across the ray (below `MIN_MAGNITUDE`: zero, or along the ray) it is
/// `max(|w_t|, |w_s|)` too.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::two_section_width;
///
/// // A beam 1 cm wide in the plane of incidence (xz) and 3 cm across it (y) meets the floor 60
/// // degrees from the normal: the in-plane section is stretched to 1 / cos 60° = 2 cm, so the
/// // longer axis is the 3 cm one, left as it was: the round cone with that footprint at 60 degrees
/// // is 3 cm x cos 60° = 1.5 cm wide.
/// let angle = 60f32.to_radians();
/// let direction = Vec3::new(angle.sin(), 0.0, -angle.cos());
/// let width = two_section_width(0.01, 0.03, Vec3::Y, Vec3::Z, direction);
/// assert!((width - 0.015).abs() < 1e-6);
/// // With the sections swapped the stretched 3 cm section is 6 cm long: the round cone is 3 cm.
/// let swapped = two_section_width(0.03, 0.01, Vec3::Y, Vec3::Z, direction);
/// assert!((swapped - 0.03).abs() < 1e-6);
/// ```
pub fn two_section_width(
    tangential_width: f32,
    sagittal_width: f32,
    sagittal_axis: Vec3,
    normal: Vec3,
    direction: Vec3,
) -> f32 {
    let larger_width = tangential_width.abs().max(sagittal_width.abs());
    let across = sagittal_axis - sagittal_axis.dot(direction) * direction;
    let across_length = across.length();
    if across_length < MIN_MAGNITUDE {
        return larger_width;
    }
    let sagittal = across / across_length;
    let tangential = sagittal.cross(direction);
    let cosine = normal.dot(direction).abs().max(MIN_COS);
    let scale = larger_width.max(MIN_MAGNITUDE);
    let (tangential_share, sagittal_share) = (tangential_width / scale, sagittal_width / scale);
    let tangential_tilt = tangential_share * normal.dot(tangential);
    let sagittal_tilt = sagittal_share * normal.dot(sagittal);
    let squared_cos = cosine * cosine;
    let tangential_square =
        squared_cos * tangential_share * tangential_share + tangential_tilt * tangential_tilt;
    let sagittal_square = squared_cos * sagittal_share * sagittal_share + sagittal_tilt * sagittal_tilt;
    let half_sum = 0.5 * (tangential_square + sagittal_square);
    let half_difference = 0.5 * (tangential_square - sagittal_square);
    let off_diagonal = tangential_tilt * sagittal_tilt;
    let larger = half_sum + (half_difference * half_difference + off_diagonal * off_diagonal).sqrt();
    scale * larger.sqrt()
}

/// Twice the world-space area of a triangle: `|cross(p1 - p0, p2 - p0)|` (RTG Eq. 4, `p_a`).
///
/// The cross product `c` is measured as `m * |c / m|` with `m` its largest component (at least
/// `MIN_MAGNITUDE`), so that squaring cannot overflow for coordinates up to about 1e18.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::triangle_world_area2;
///
/// let (p0, p1, p2) = (Vec3::new(1.0, 1.0, 1.0), Vec3::new(2.0, 3.0, 3.0), Vec3::new(3.0, 2.0, -1.0));
/// // Heron's formula from the side lengths (3, 3 and 3 sqrt(2)): area 4.5.
/// let (a, b, c) = (p0.distance(p1), p1.distance(p2), p2.distance(p0));
/// let s = (a + b + c) / 2.0;
/// let heron = (s * (s - a) * (s - b) * (s - c)).sqrt();
/// assert!((triangle_world_area2(p0, p1, p2) - 2.0 * heron).abs() < 1e-5);
/// ```
pub fn triangle_world_area2(p0: Vec3, p1: Vec3, p2: Vec3) -> f32 {
    let cross = (p1 - p0).cross(p2 - p0);
    let scale = cross
        .x
        .abs()
        .max(cross.y.abs())
        .max(cross.z.abs().max(MIN_MAGNITUDE));
    scale * (cross / scale).length()
}

/// Twice the UV-space area of a triangle: `|cross(uv1 - uv0, uv2 - uv0)|` (RTG Eq. 4, `t_a` without
/// the texture size).
///
/// # Examples
///
/// ```
/// use glam::Vec2;
/// use ray_footprint::ray_cone::triangle_uv_area2;
///
/// // Half of the square [0.25, 0.75]^2 of the texture: area 0.125, either winding.
/// let (uv0, uv1, uv2) = (Vec2::new(0.25, 0.25), Vec2::new(0.75, 0.25), Vec2::new(0.25, 0.75));
/// assert_eq!(triangle_uv_area2(uv0, uv1, uv2), 2.0 * 0.125);
/// assert_eq!(triangle_uv_area2(uv0, uv2, uv1), 2.0 * 0.125);
/// ```
pub fn triangle_uv_area2(uv0: Vec2, uv1: Vec2, uv2: Vec2) -> f32 {
    (uv1 - uv0).perp_dot(uv2 - uv0).abs()
}

/// Texel density of a triangle, UV units per world unit: `sqrt(uv_area2) / sqrt(world_area2)`
/// (ray-cone tutorial), with `world_area2` clamped to `>= MIN_SQUARED_MAGNITUDE`.
///
/// Cost: the area's scaling by its largest component (no square overflows or underflows from
/// 1e-12 to 1e12) is what it costs beyond the tutorial's `length(cross)`. On an NVIDIA H200 the
/// shader function takes 2.3 times the tutorial's time, and 0.53 times the tutorial's given the
/// same guards (the lab README's "peers with our guards added").
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_cone::texel_density;
///
/// // Half of a 2 m x 2 m floor tile whose texture spans it once: 1 UV unit per 2 m.
/// let (p0, p1, p2) = (Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -2.0));
/// let density = texel_density(p0, p1, p2, Vec2::ZERO, Vec2::X, Vec2::Y);
/// assert!((density - 0.5).abs() < 1e-7);
/// ```
pub fn texel_density(p0: Vec3, p1: Vec3, p2: Vec3, uv0: Vec2, uv1: Vec2, uv2: Vec2) -> f32 {
    triangle_uv_area2(uv0, uv1, uv2).sqrt()
        / triangle_world_area2(p0, p1, p2).max(MIN_SQUARED_MAGNITUDE).sqrt()
}

/// Base level of detail of a triangle in UV units (RTG Eq. 4):
/// `Delta = 0.5 * (log2(uv_area2) - log2(world_area2))`, both areas clamped to
/// `>= MIN_SQUARED_MAGNITUDE`.
///
/// Cost: the scaled area and the two clamped logarithms, where Falcor takes one logarithm of the
/// quotient (infinite or NaN for a degenerate triangle). On an NVIDIA H200 the shader function
/// takes 2.8 times Falcor's time, and 0.71 times Falcor's given the same guards.
/// Add `0.5 * log2(W * H)` for a W x H texture (see [`texture_lod`]).
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_cone::triangle_base_lod;
///
/// // The 2 m tile with its texture spanning it once: 0.5 UV units per metre, log2(0.5) = -1. A
/// // 1024 x 1024 texture adds 0.5 log2(1024 * 1024) = 10: 512 texels per metre, log2(512) = 9.
/// let (p0, p1, p2) = (Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -2.0));
/// let base = triangle_base_lod(p0, p1, p2, Vec2::ZERO, Vec2::X, Vec2::Y);
/// assert!((base - -1.0).abs() < 1e-6);
/// ```
pub fn triangle_base_lod(p0: Vec3, p1: Vec3, p2: Vec3, uv0: Vec2, uv1: Vec2, uv2: Vec2) -> f32 {
    let uv_area2 = triangle_uv_area2(uv0, uv1, uv2).max(MIN_SQUARED_MAGNITUDE);
    let world_area2 = triangle_world_area2(p0, p1, p2).max(MIN_SQUARED_MAGNITUDE);
    0.5 * (uv_area2.log2() - world_area2.log2())
}

/// Texture level of detail of a ray-cone hit (RTG Eq. 34 with the texture-size term of its listing):
/// `lambda = base_lod + log2(|width|) + 0.5 * (log2(W) + log2(H)) - log2(|dot(normal, direction)|)`,
/// with `|width| >= MIN_MAGNITUDE`, `W, H >= 1` and `|dot| >= MIN_COS`.
///
/// Cost: the clamps and four logarithms, where Falcor takes two of unclamped values (infinite at
/// a grazing hit or a zero width). On an NVIDIA H200 the shader function takes 1.6 times Falcor's
/// time, and 0.86 times Falcor's given the same clamps.
///
/// `width` is the cone width at the hit ([`width_at`]). For a square texture this equals
/// `log2(world_footprint * texel_density * W)`.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_cone::{texture_lod, triangle_base_lod};
///
/// // The 2 m floor tile with a 1024 x 1024 texture spanning it (512 texels per metre), hit head on by
/// // a cone 1/64 m wide: the footprint covers 512 / 64 = 8 texels, mip level log2(8) = 3.
/// let (p0, p1, p2) = (Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -2.0));
/// let base = triangle_base_lod(p0, p1, p2, Vec2::ZERO, Vec2::X, Vec2::Y);
/// let size = Vec2::splat(1024.0);
/// let head_on = texture_lod(base, 1.0 / 64.0, size, Vec3::Y, Vec3::NEG_Y);
/// assert!((head_on - 3.0).abs() < 1e-5);
/// // 60 degrees from the normal the footprint is 1 / cos(60°) = 2 times as long: one level up.
/// let angle = 60f32.to_radians();
/// let slanted = texture_lod(base, 1.0 / 64.0, size, Vec3::Y, Vec3::new(angle.sin(), -angle.cos(), 0.0));
/// assert!((slanted - 4.0).abs() < 1e-5);
/// ```
pub fn texture_lod(base_lod: f32, width: f32, texture_size: Vec2, normal: Vec3, direction: Vec3) -> f32 {
    let size = texture_size.max(Vec2::ONE);
    base_lod + width.abs().max(MIN_MAGNITUDE).log2() + 0.5 * (size.x.log2() + size.y.log2())
        - normal.dot(direction).abs().max(MIN_COS).log2()
}

/// Isotropic `textureGrad` gradient length in UV units (ray-cone tutorial):
/// `g = |uv_footprint| * max(tex_grad_scale, 0)`; sample with `ddx = (g, 0)`, `ddy = (0, g)`.
/// `tex_grad_scale` 0 samples mip 0, 1 the matching level, above 1 blurs.
///
/// # Examples
///
/// ```
/// use ray_footprint::ray_cone::texture_gradient;
///
/// // A footprint 1/128 UV units wide (1/64 m on a tile of 0.5 UV units per metre) is 8 texels of a
/// // 1024-texel texture: the sampler picks mip level log2(8) = 3.
/// let g = texture_gradient(1.0 / 128.0, 1.0);
/// assert_eq!((g * 1024.0).log2(), 3.0);
/// // tex_grad_scale 2 blurs by one level; 0 samples mip 0.
/// assert_eq!((texture_gradient(1.0 / 128.0, 2.0) * 1024.0).log2(), 4.0);
/// assert_eq!(texture_gradient(1.0 / 128.0, 0.0), 0.0);
/// ```
pub fn texture_gradient(uv_footprint: f32, tex_grad_scale: f32) -> f32 {
    uv_footprint.abs() * tex_grad_scale.max(0.0)
}

/// Texture level of detail of a ray cone's hit on a triangle, in one call from what a closest hit
/// has (RTG Eq. 34): [`texture_lod`] of the triangle's [`triangle_base_lod`], the cone's width at
/// the hit ([`width_at`]), the texture's size and the triangle's face normal (either orientation).
///
/// - `cone`: the cone at the ray's origin; for a primary ray `pinhole_ray_cone(pixel_spread_angle)`.
/// - `direction`: the unit ray direction, and `t` the hit distance along it.
/// - `p0, p1, p2`: the triangle's corners, in the space the ray is in.
/// - `uv0, uv1, uv2`: the texture coordinates the sampler sees (in an atlas, the atlas's, after any
///   texture transform such as glTF's `KHR_texture_transform`), and `texture_size` the bound
///   texture's size in texels.
///
/// Sample with `textureSampleLevel(texture, sampler, uv, lod)` on a texture with its full mip chain
/// ([`crate::mip`]) through a sampler whose minification and mipmap filters are linear. A LOD at or
/// below 0 samples mip 0.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_cone::{hit_texture_lod, RayCone};
///
/// // The 2 m floor tile with a 1024 x 1024 texture spanning it (512 texels per metre), seen head
/// // on through a cone 1/64 m wide at the hit: 512 / 64 = 8 texels, mip level 3.
/// let (p0, p1, p2) = (Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -2.0));
/// let cone = RayCone { width: 1.0 / 64.0, spread_angle: 0.0 };
/// let lod = hit_texture_lod(cone, Vec3::NEG_Y, 5.0, p0, p1, p2, Vec2::ZERO, Vec2::X, Vec2::Y, Vec2::splat(1024.0));
/// assert!((lod - 3.0).abs() < 1e-5);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn hit_texture_lod(
    cone: RayCone,
    direction: Vec3,
    t: f32,
    p0: Vec3,
    p1: Vec3,
    p2: Vec3,
    uv0: Vec2,
    uv1: Vec2,
    uv2: Vec2,
    texture_size: Vec2,
) -> f32 {
    let normal = face_normal(shape_frame_u(p0, p1), p0, p2);
    let base_lod = triangle_base_lod(p0, p1, p2, uv0, uv1, uv2);
    texture_lod(base_lod, width_at(cone, t), texture_size, normal, direction)
}

/// The `textureSampleGrad` gradients of a ray cone's hit on a triangle, in one call, the twin of
/// [`hit_texture_lod`] for samplers given gradients: `(ddx.x, ddx.y, ddy.x, ddy.y) = (g, 0, 0, g)`
/// in UV units, with `g` the cone's slant-corrected footprint ([`world_footprint`] with the face
/// normal) times the triangle's [`texel_density`] (the ray-cone tutorial's `textureGrad` form).
/// For a square texture `log2(g * W)` is `hit_texture_lod`'s LOD. `g` is clamped to `<= F16_MAX`
/// UV units (the footprint to `<= F16_MAX / max(density, MIN_MAGNITUDE)` before the product, so that
/// it cannot overflow): any gradient above 1 already samples a texture's last level, so the clamp
/// changes no sample. The arguments are
/// `hit_texture_lod`'s without the texture size; for anisotropic filtering see
/// `ray_diff::anisotropic_cone_gradients`.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3, Vec4};
/// use ray_footprint::ray_cone::{hit_texture_gradients, RayCone};
///
/// // The floor tile seen head on through a cone 1/64 m wide: 1/128 UV units (8 texels of 1024).
/// let (p0, p1, p2) = (Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -2.0));
/// let cone = RayCone { width: 1.0 / 64.0, spread_angle: 0.0 };
/// let gradients = hit_texture_gradients(cone, Vec3::NEG_Y, 5.0, p0, p1, p2, Vec2::ZERO, Vec2::X, Vec2::Y);
/// assert!((gradients - Vec4::new(1.0, 0.0, 0.0, 1.0) / 128.0).abs().max_element() < 1e-8);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn hit_texture_gradients(
    cone: RayCone,
    direction: Vec3,
    t: f32,
    p0: Vec3,
    p1: Vec3,
    p2: Vec3,
    uv0: Vec2,
    uv1: Vec2,
    uv2: Vec2,
) -> Vec4 {
    let normal = face_normal(shape_frame_u(p0, p1), p0, p2);
    let density = texel_density(p0, p1, p2, uv0, uv1, uv2);
    let footprint = world_footprint(cone, t, normal, direction).min(F16_MAX / density.max(MIN_MAGNITUDE));
    let gradient = footprint * density;
    Vec4::new(gradient, 0.0, 0.0, gradient)
}

/// Level of detail for a latitude-longitude environment map `map_height` texels tall (RTG ch. 21,
/// as in Falcor): `log2(max(|spread_angle| * H / pi, MIN_MAGNITUDE))`, `map_height` clamped to `>= 1`.
///
/// # Examples
///
/// ```
/// use std::f32::consts::PI;
/// use ray_footprint::ray_cone::environment_lod;
///
/// // A latitude-longitude map 2048 texels tall spans pi radians of latitude, pi / 2048 per texel:
/// // a cone 8 texels wide, 8 pi / 2048, reads level log2(8) = 3.
/// let lod = environment_lod(8.0 * PI / 2048.0, 2048.0);
/// assert!((lod - 3.0).abs() < 1e-6);
/// ```
pub fn environment_lod(spread_angle: f32, map_height: f32) -> f32 {
    (spread_angle.abs() * map_height.max(1.0) / std::f32::consts::PI)
        .max(MIN_MAGNITUDE)
        .log2()
}

// ---- Refraction and roughness (RTG II ch. 10; JCGT 2021) ----

/// Largest angle, in radians, between a boundary ray of a refracted cone and the surface normal:
/// `pi / 2 - 1e-4`, so that every boundary ray meets the surface with `|cos| >= MIN_COS` (see
/// [`refract_ray_cone`]).
pub const MAX_INCIDENCE_ANGLE: f32 = 1.570_696_3;
/// Largest `|normal_spread_angle|`, in radians, that [`refract_ray_cone`] applies, and largest turn
/// of the normal across a footprint that [`scatter_ray_cone`] applies; larger values are clamped, so
/// that the normals across a footprint stay within a half turn of each other.
pub const MAX_NORMAL_SPREAD: f32 = 3.1;
/// Smallest `1 - alpha^2` in [`roughness_spread_angle`] (Falcor's clamp): roughness 1 gives
/// `2 * sqrt(0.5 / MIN_ROUGHNESS_DENOMINATOR)`, about 141 radians.
pub const MIN_ROUGHNESS_DENOMINATOR: f32 = 1.0e-4;

/// A refracted ray cone and whether the central ray was totally internally reflected instead
/// (shader `RfRefractedRayCone`, a function result, not laid out for host-shareable buffers). On
/// total internal reflection `cone` is the *reflected* cone.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RefractedRayCone {
    /// The cone leaving the hit: transmitted, or reflected on total internal reflection.
    pub cone: RayCone,
    /// True when `eta * sin(i) > 1`: no transmitted central ray exists.
    pub total_internal_reflection: bool,
}

/// `(sin i, cos i)` of the angle `i` between `direction` and the normal line, from
/// `(|d - cosine * n|, |cosine|)` with `cosine = dot(n, d)`, scaled to unit length. A zero
/// direction counts as normal incidence, `(0, 1)`.
fn incidence_sin_cos(normal: Vec3, direction: Vec3, cosine: f32) -> Vec2 {
    let sin_cos = Vec2::new((direction - cosine * normal).length(), cosine.abs());
    let length = sin_cos.length();
    if length < MIN_MAGNITUDE {
        Vec2::new(0.0, 1.0)
    } else {
        sin_cos / length
    }
}

/// `(sin(angle), cos(angle))`.
fn angle_sin_cos(angle: f32) -> Vec2 {
    Vec2::new(angle.sin(), angle.cos())
}

/// Half the cone angle, limited so that both boundary rays of a cone at incidence `i` meet the
/// surface no closer to grazing than `MAX_INCIDENCE_ANGLE`:
/// `clamp(spread_angle / 2, -limit, limit)`, `limit = max(MAX_INCIDENCE_ANGLE - atan2(sin i, cos i), 0)`.
fn refraction_half_spread(spread_angle: f32, incidence: Vec2) -> f32 {
    let limit = (MAX_INCIDENCE_ANGLE - incidence.x.atan2(incidence.y)).max(0.0);
    (0.5 * spread_angle).clamp(-limit, limit)
}

/// Half the angle between the normals at the two boundary hits, signed for the upper boundary:
/// `+-clamp(facing_spread, -MAX_NORMAL_SPREAD, MAX_NORMAL_SPREAD) / 2`, negated for a negative
/// width (whose upper boundary lands on the other side of the hit).
fn normal_tilt(width: f32, facing_spread: f32) -> f32 {
    let signed_half = if width < 0.0 { -0.5 } else { 0.5 };
    signed_half * facing_spread.clamp(-MAX_NORMAL_SPREAD, MAX_NORMAL_SPREAD)
}

/// `(sin, cos)` of the angle `i + side * q` from those of `i` and `q`.
fn boundary_incidence(incidence: Vec2, local: Vec2, side: f32) -> Vec2 {
    Vec2::new(
        incidence.x * local.y + side * incidence.y * local.x,
        incidence.y * local.y - side * incidence.x * local.x,
    )
}

/// `(sin, cos)` of the angle refracted by Snell's law from the incidence `(sin phi, cos phi)`:
/// `clamp(eta sin phi, -1, 1)` and `sqrt(max(cos^2 phi + ((1 - eta) sin phi) ((1 + eta) sin phi), 0))`,
/// which is `sqrt(1 - eta^2 sin^2 phi)` evaluated from `cos phi`, so that it keeps its precision
/// near grazing. Past the critical angle the ray leaves along the surface: `(+-1, 0)`.
fn refracted_sin_cos(incidence: Vec2, eta: f32) -> Vec2 {
    let cos2 = incidence.y * incidence.y + ((1.0 - eta) * incidence.x) * ((1.0 + eta) * incidence.x);
    Vec2::new((eta * incidence.x).clamp(-1.0, 1.0), cos2.max(0.0).sqrt())
}

/// Signed distance along the surface from the hit to where the boundary ray on `side` (+1 upper,
/// -1 lower) lands: it starts `side * width / 2` across the central ray and makes the angle
/// `i + side * h` with the inward normal, so it lands at
/// `side * (width / 2) * cos(h) / max(cos(i + side * h), MIN_COS)`. `incidence` and `half_spread`
/// are `(sin, cos)` of `i` and `h`.
fn boundary_hit(width: f32, side: f32, incidence: Vec2, half_spread: Vec2) -> f32 {
    let cos_boundary = incidence.y * half_spread.y - side * incidence.x * half_spread.x;
    side * 0.5 * width * half_spread.y / cos_boundary.max(MIN_COS)
}

/// Signed distance, across the refracted central ray, from the hit to the refracted boundary ray on
/// `side` that leaves the surface at `hit`: the boundary's normal is turned by `-side * tilt`, so
/// its refracted direction makes the angle `rho = tau - side * tilt` with the inward normal (`tau`
/// its angle to its own normal) and the offset is `hit * cos(rho) / max(cos(rho - t), MIN_COS)`.
/// `refracted`, `tilt` and `transmitted` are `(sin, cos)` of `tau`, `tilt` and `t`.
fn boundary_offset(hit: f32, side: f32, refracted: Vec2, tilt: Vec2, transmitted: Vec2) -> f32 {
    let cos_rho = refracted.y * tilt.y + side * refracted.x * tilt.x;
    let sin_rho = refracted.x * tilt.y - side * refracted.y * tilt.x;
    hit * cos_rho / (cos_rho * transmitted.y + sin_rho * transmitted.x).max(MIN_COS)
}

/// `s_u - s_l`, the difference of the sines of the refracted boundaries, from the boundaries'
/// incidences `upper`, `lower` (`(sin, cos)` of `i +- q`): `2 eta cos i sin q`, exact, while
/// neither `eta sin(i +- q)` exceeds 1; else the difference of the clamped sines.
fn refracted_sine_gap(eta: f32, incidence: Vec2, local: Vec2, upper: Vec2, lower: Vec2) -> f32 {
    let (upper_sine, lower_sine) = (eta * upper.x, eta * lower.x);
    if upper_sine.abs() <= 1.0 && lower_sine.abs() <= 1.0 {
        2.0 * eta * incidence.y * local.x
    } else {
        upper_sine.clamp(-1.0, 1.0) - lower_sine.clamp(-1.0, 1.0)
    }
}

/// Angle from the lower to the upper refracted boundary, each measured from its own normal:
/// `atan2(sin, cos)` of their difference, with `cos = c_u c_l + s_u s_l` and
/// `sin = s_u c_l - s_l c_u = (s_u - s_l) (1 + cos) / (c_u + c_l)`, the same value without
/// cancellation for nearly equal angles (`sine_gap` is `s_u - s_l`, [`refracted_sine_gap`]). The
/// divisor is kept at or above its lower bound `sqrt(|(s_u - s_l) (s_u + s_l)|)` (from
/// `c_l^2 - c_u^2 = s_u^2 - s_l^2`), which rounding can undercut when both boundaries refract at
/// their critical angle, and at or above `MIN_MAGNITUDE`.
fn refracted_angle_between(sine_gap: f32, upper: Vec2, lower: Vec2) -> f32 {
    let cos_between = upper.y * lower.y + upper.x * lower.x;
    let cos_sum = (upper.y + lower.y)
        .max((sine_gap * (upper.x + lower.x)).abs().sqrt())
        .max(MIN_MAGNITUDE);
    let sin_between = sine_gap * (1.0 + cos_between) / cos_sum;
    sin_between.atan2(cos_between)
}

/// The cone leaving a refraction (Boksansky, Crassin, Akenine-Möller, "Refraction Ray Cones for
/// Texture Level of Detail", Ray Tracing Gems II ch. 10, 2021; the construction of Falcor's
/// `computeRayConeForRefraction`), in the plane of incidence, with the crate's whole angles (the
/// chapter writes its formulas with the half angle).
///
/// `cone` is the incoming cone *at the hit* (propagate it first: `propagate(cone, t, 0.0)`);
/// `normal` and `direction` are unit; `normal_spread_angle` is the angle by which the surface
/// normal turns across the footprint, positive where the normals spread apart (convex on the side
/// `normal` points to; `k * |width| / |dot(n, d)|` for a curvature `k`, or `s * phi` from RTG
/// Eq. 31-33); `eta = n_incident / n_transmitted`, as GLSL `refract` takes it (clamped to `>= 0`).
/// The normal may face either way: when `dot(n, d) > 0` it is flipped, and the normal spread with
/// it.
///
/// With `i` the angle of incidence (`sin i = |d - dot(n, d) n|`) and `eta sin i > 1`, the central ray
/// is totally internally reflected: the result is the reflected cone, `(width, spread + 2 beta)`
/// with `beta` the normal spread as the ray sees it, and the flag is set. Otherwise the two
/// boundary rays start `+-width / 2` across the central ray at the angles `i +- h` to the inward
/// normal (`h = spread / 2`), land at `x = +-(width / 2) cos h / cos(i +- h)` along the surface,
/// where the normal is tilted by `-+beta / 2`, and refract by Snell's law there; a boundary past
/// its critical angle leaves along the surface. The new spread is the angle between the refracted
/// boundaries (`atan2`), the new width the distance between them across the refracted central ray
/// at the hit. To first order, `width' = width cos t / cos i` and
/// `spread' = m (spread + beta) - beta` with `m = eta cos i / cos t`; at normal incidence this is the
/// OptiX Toolkit's `(n_out / n_in) (angle + k |w|) - k |w|`.
///
/// Defined where Falcor's construction is not: at exact normal incidence the plane of incidence is
/// any plane (only `sin i` and `cos i` enter); the half spread is limited so that both boundary rays
/// meet the surface, at most `MAX_INCIDENCE_ANGLE` from the normal (a near-grazing cone whose edge
/// would miss the surface grazes it instead); `|beta|` is clamped to `MAX_NORMAL_SPREAD`; the
/// landing and leaving cosines to `>= MIN_COS`. A zero direction counts as normal incidence.
///
/// Cost: both answers (refracted and reflected) computed and one selected, with the clamps above.
/// On an NVIDIA H200 the shader function takes 1.4 times Falcor's time, and 0.98 times Falcor's
/// given the same guards around it.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::{refract_ray_cone, RayCone};
///
/// // A cone converging to a point (width 0) meets flat glass head on, from air (eta = 1 / 1.5):
/// // its edge rays, 0.01 rad from the normal, bend by Snell's law to asin(eta sin 0.01) each.
/// let cone = RayCone { width: 0.0, spread_angle: 0.02 };
/// let eta = 1.0 / 1.5;
/// let refracted = refract_ray_cone(cone, Vec3::Y, Vec3::NEG_Y, 0.0, eta);
/// let exact = 2.0 * (f64::from(eta) * 0.01f64.sin()).asin();
/// assert!(!refracted.total_internal_reflection);
/// assert!((f64::from(refracted.cone.spread_angle) - exact).abs() < 1e-6 * exact);
/// // From glass into air at 60 degrees, beyond the critical angle asin(1 / 1.5) = 41.8 degrees.
/// let angle = 60f32.to_radians();
/// let inside = Vec3::new(angle.sin(), -angle.cos(), 0.0);
/// assert!(refract_ray_cone(cone, Vec3::Y, inside, 0.0, 1.5).total_internal_reflection);
/// ```
pub fn refract_ray_cone(
    cone: RayCone,
    normal: Vec3,
    direction: Vec3,
    normal_spread_angle: f32,
    eta: f32,
) -> RefractedRayCone {
    let cosine = normal.dot(direction);
    let facing_spread = if cosine > 0.0 {
        -normal_spread_angle
    } else {
        normal_spread_angle
    };
    let incidence = incidence_sin_cos(normal, direction, cosine);
    let index = eta.max(0.0);
    let sin_transmitted = index * incidence.x;
    if sin_transmitted > 1.0 {
        return RefractedRayCone {
            cone: RayCone {
                width: cone.width,
                spread_angle: cone.spread_angle + 2.0 * facing_spread,
            },
            total_internal_reflection: true,
        };
    }
    let transmitted = refracted_sin_cos(incidence, index);
    let half_spread = refraction_half_spread(cone.spread_angle, incidence);
    let tilt = normal_tilt(cone.width, facing_spread);
    let local = angle_sin_cos(half_spread + tilt);
    let upper_incidence = boundary_incidence(incidence, local, 1.0);
    let lower_incidence = boundary_incidence(incidence, local, -1.0);
    let upper = refracted_sin_cos(upper_incidence, index);
    let lower = refracted_sin_cos(lower_incidence, index);
    let sine_gap = refracted_sine_gap(index, incidence, local, upper_incidence, lower_incidence);
    let half_sin_cos = angle_sin_cos(half_spread);
    let tilt_sin_cos = angle_sin_cos(tilt);
    let upper_hit = boundary_hit(cone.width, 1.0, incidence, half_sin_cos);
    let lower_hit = boundary_hit(cone.width, -1.0, incidence, half_sin_cos);
    RefractedRayCone {
        cone: RayCone {
            width: boundary_offset(upper_hit, 1.0, upper, tilt_sin_cos, transmitted)
                - boundary_offset(lower_hit, -1.0, lower, tilt_sin_cos, transmitted),
            spread_angle: refracted_angle_between(sine_gap, upper, lower) - 2.0 * tilt,
        },
        total_internal_reflection: false,
    }
}

/// The sagittal section of a cone crossing a refraction: the section across the plane of incidence,
/// which [`refract_ray_cone`] (the section in that plane, the tangential one) does not follow.
/// Coddington's sagittal equation for a thin astigmatic pencil (Coddington 1829; as stated in
/// Kingslake and Johnson, *Lens Design Fundamentals*, 2nd ed., 2010, on astigmatism),
/// `n' / s' - n / s = (n' cos t - n cos i) k` for a surface of curvature `k` across the plane of
/// incidence, written for a cone of width `w` and spread `alpha` and divided by `n'`: the width is
/// kept and `spread' = eta alpha + (eta cos i - cos t) beta`, with `beta = k w` the normal's turn
/// across the section (the section lies in the surface's tangent plane, so it is not slanted).
/// At normal incidence this is the tangential section's `eta (alpha + beta) - beta`
/// ([`refract_ray_cone`] to first order): the two sections differ only off the normal.
///
/// Arguments as [`refract_ray_cone`] takes them, for the sagittal section: `cone` at the hit, unit
/// `normal` and `direction`, `normal_spread_angle` the normal's turn across the section, positive
/// where the normals spread apart (`k |w|` for a curvature `k` across the plane of incidence, convex
/// on the side `normal` points to), `eta = n_incident / n_transmitted` (clamped to `>= 0`); the
/// normal may face either way (flipped with the normal spread when `dot(n, d) > 0`). `beta` takes
/// the width's sign and is clamped to `MAX_NORMAL_SPREAD` in magnitude. Where `eta sin i > 1` the
/// central ray is totally internally reflected, and the reflected section is returned:
/// `spread' = alpha + 2 cos i beta`, the sagittal mirror equation `1 / s' + 1 / s = 2 cos i k`.
/// The section's axis is `cross(direction, normal)`, the same before and after the surface.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::{refract_sagittal_cone, RayCone};
///
/// // A parallel beam 2 mm wide enters a glass ball of radius 1 (eta = 1 / 1.5) at 30 degrees. Its
/// // edge rays across the plane of incidence meet normals turned by +-0.001 about the ray's axis
/// // and bend toward each other: (eta cos i - cos t) beta with beta = 0.002.
/// let angle = 30f32.to_radians();
/// let direction = Vec3::new(angle.sin(), 0.0, -angle.cos());
/// let eta = 1.0 / 1.5;
/// let cone = RayCone { width: 0.002, spread_angle: 0.0 };
/// let sagittal = refract_sagittal_cone(cone, Vec3::Z, direction, 0.002, eta);
/// let cos_t = (1.0 - eta * eta * angle.sin() * angle.sin()).sqrt();
/// let expected = (eta * angle.cos() - cos_t) * 0.002;
/// assert_eq!(sagittal.width, 0.002);
/// assert!((sagittal.spread_angle - expected).abs() < 1e-6 * expected.abs());
/// ```
pub fn refract_sagittal_cone(
    cone: RayCone,
    normal: Vec3,
    direction: Vec3,
    normal_spread_angle: f32,
    eta: f32,
) -> RayCone {
    let cosine = normal.dot(direction);
    let facing_spread = if cosine > 0.0 {
        -normal_spread_angle
    } else {
        normal_spread_angle
    };
    let incidence = incidence_sin_cos(normal, direction, cosine);
    let index = eta.max(0.0);
    let turn = 2.0 * normal_tilt(cone.width, facing_spread);
    let spread_angle = if index * incidence.x > 1.0 {
        cone.spread_angle + 2.0 * incidence.y * turn
    } else {
        let transmitted = refracted_sin_cos(incidence, index);
        index * cone.spread_angle + (index * incidence.y - transmitted.y) * turn
    };
    RayCone {
        width: cone.width,
        spread_angle,
    }
}

/// Spread angle added by a rough surface (JCGT 2021, its roughness-to-spread mapping; Falcor's
/// `roughnessToSpread`): the GGX lobe of perceptual roughness `r` (clamped to `[0, 1]`) has
/// `alpha = r^2` and is read as a Gaussian of variance
/// `sigma^2 = 0.5 * alpha^2 / max(1 - alpha^2, MIN_ROUGHNESS_DENOMINATOR)`; the added spread is the
/// whole angle `2 * sigma`, about `sqrt(2) * r^2` for small `r`, 0 for `r = 0`, and beyond pi for
/// `r > 0.96` (about 141 radians at `r = 1`).
///
/// The input is perceptual roughness (the material parameter), not GGX alpha. Falcor adds the
/// result to the normal's spread before a reflection's factor 2: for a reflection add
/// `2 * roughness_spread_angle(r)` to the surface spread angle passed to [`propagate`].
///
/// # Examples
///
/// ```
/// use ray_footprint::ray_cone::roughness_spread_angle;
///
/// // With alpha = r^2, 2 sqrt(0.5 alpha^2 / (1 - alpha^2)) is sqrt(2) r^2 / sqrt(1 - r^4).
/// let r = 0.5f64;
/// let expected = 2f64.sqrt() * r * r / (1.0 - r.powi(4)).sqrt();
/// assert!((f64::from(roughness_spread_angle(0.5)) - expected).abs() < 1e-6 * expected);
/// // A perfect mirror adds nothing.
/// assert_eq!(roughness_spread_angle(0.0), 0.0);
/// ```
pub fn roughness_spread_angle(roughness: f32) -> f32 {
    let r = roughness.clamp(0.0, 1.0);
    let alpha = r * r;
    let alpha2 = alpha * alpha;
    let variance = 0.5 * alpha2 / (1.0 - alpha2).max(MIN_ROUGHNESS_DENOMINATOR);
    2.0 * variance.sqrt()
}

// ---- Scattering at path vertices (Suykens and Willems 2001) ----

/// The lobe a path sampled at a vertex, for [`scatter_ray_cone`]: a direction drawn in the shading
/// frame alone (Lambert's cosine-weighted lobe, any diffuse lobe).
pub const LOBE_DIFFUSE: u32 = 0;
/// The lobe a path sampled at a vertex, for [`scatter_ray_cone`]: the incoming direction reflected
/// about a normal drawn in the shading frame (a mirror; a GGX or Beckmann lobe whose microfacet
/// normal is drawn from the distribution of normals).
pub const LOBE_REFLECTION: u32 = 1;

/// How much longer than the incoming cross-section the footprint looks from `leaving`, with
/// `facing` the clamped `-dot(normal, direction)`: see [`scatter_ray_cone`].
fn footprint_stretch(normal: Vec3, direction: Vec3, leaving: Vec3, facing: f32) -> f32 {
    let mirrored = direction + 2.0 * facing * normal;
    let sum = (leaving - direction).length() * (leaving + mirrored).length();
    let difference = (leaving + direction).length() * (leaving - mirrored).length();
    (sum + difference) / (4.0 * facing.abs())
}

/// The cone that leaves a path vertex in the direction `leaving` drawn from the lobe the path
/// sampled there, with the vertex's random numbers held fixed: the footprint of a path as a
/// function of the image position, which is how path differentials differentiate a sampled path
/// (Suykens and Willems 2001, Sec. 3).
///
/// Width: the cone's cross-section at the hit, `width_at(cone, t)`, laid on the surface along the
/// ray (Igehy 1999, Eq. 12) and seen across `leaving`, is an ellipse; the leaving width is its
/// longest axis, `width_at(cone, t) * stretch` with
/// `stretch = (|o - d| |o + r| + |o + d| |o - r|) / (4 |dn|)`, where `d` is `direction`, `o` is
/// `leaving`, `r = d + 2 dn normal` the mirror direction and `dn = -dot(normal, direction)`
/// clamped as in [`curvature_spread_angle`]. (The two products over `2 |dn|` are the sum and the
/// difference of the map's singular values, derived here.) A mirror gives `stretch = 1`, a
/// direction leaving along the normal `1 / |dn|`, the footprint's own slant.
///
/// Spread: across the footprint the shading normal, and the whole shading frame with it, turns by
/// `normal_turn = curvature * width_at(cone, t) / dn` (half of [`curvature_spread_angle`]'s `beta`,
/// RTG Eq. 32 with JCGT 2021's curvature), kept within `[-MAX_NORMAL_SPREAD, MAX_NORMAL_SPREAD]`
/// (a footprint that wraps a surface further turns no further, and the result stays finite). A
/// direction drawn from the random numbers in that frame turns with it:
/// - [`LOBE_REFLECTION`]: the incoming direction reflected about a normal that turns with the
///   frame (the shading normal itself, or a GGX microfacet normal drawn from the distribution of
///   normals, Walter et al. 2007 Eq. 35-36). A reflection turns its output by twice its normal's
///   turn and keeps the incoming spread: `spread' = spread_angle + 2 * normal_turn`. For a mirror
///   this is `propagate(cone, t, curvature_spread_angle(curvature, width, normal, direction))`.
/// - [`LOBE_DIFFUSE`]: the direction turns with the frame alone and does not depend on the
///   incoming one, whose spread is forgotten: `spread' = normal_turn`, the largest turn of a
///   direction that rides a frame turned by `normal_turn`. On a flat diffuse surface the cone
///   leaves as a beam (`spread' = 0`) as wide as the footprint seen from `leaving`.
///
/// Any `lobe` other than [`LOBE_DIFFUSE`] counts as [`LOBE_REFLECTION`]. `curvature`, `normal` and
/// `width` carry signs as in [`curvature_spread_angle`]: flipping the normal and the curvature
/// together changes nothing, and the width keeps its sign. With visible-normal sampling (Heitz
/// 2018) the microfacet normal also follows the incoming direction, by an amount that grows with
/// the roughness, which this rule leaves out. Transmission is [`refract_ray_cone`]'s.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_cone::{scatter_ray_cone, RayCone, LOBE_DIFFUSE, LOBE_REFLECTION};
///
/// // A pinhole cone of 1 mrad meets a flat floor 3 m away, head on, and a diffuse direction leaves
/// // along the normal. Neighbouring image positions hit points 3 mm apart and leave in the same
/// // direction of the (unturned) frame: a beam 3 mm wide.
/// let cone = RayCone { width: 0.0, spread_angle: 0.001 };
/// let up = Vec3::Z;
/// let diffuse = scatter_ray_cone(cone, 3.0, 0.0, up, Vec3::NEG_Z, up, LOBE_DIFFUSE);
/// assert!((diffuse.width - 0.003).abs() < 1e-9 && diffuse.spread_angle == 0.0);
/// // Met at 60 degrees from the normal, the footprint is 3 mm / cos 60° = 6 mm long on the floor,
/// // and seen from straight above that is the beam's width.
/// let slanted = Vec3::new(0.75f32.sqrt(), 0.0, -0.5);
/// let diffuse = scatter_ray_cone(cone, 3.0, 0.0, up, slanted, up, LOBE_DIFFUSE);
/// assert!((diffuse.width - 0.006).abs() < 1e-8);
/// // On a ball of radius 1, head on: across 3 mm the normal turns by 3 mrad (1 / R per unit
/// // length); a diffuse direction turns with it, a reflected one by twice that plus the pixel's.
/// let diffuse = scatter_ray_cone(cone, 3.0, 1.0, up, Vec3::NEG_Z, up, LOBE_DIFFUSE);
/// assert!((diffuse.spread_angle - 0.003).abs() < 1e-9);
/// let glossy = scatter_ray_cone(cone, 3.0, 1.0, up, Vec3::NEG_Z, up, LOBE_REFLECTION);
/// assert!((glossy.spread_angle - (0.001 + 2.0 * 0.003)).abs() < 1e-9);
/// ```
pub fn scatter_ray_cone(
    cone: RayCone,
    t: f32,
    curvature: f32,
    normal: Vec3,
    direction: Vec3,
    leaving: Vec3,
    lobe: u32,
) -> RayCone {
    let width = width_at(cone, t);
    let facing = facing_cos(normal, direction);
    let turn = curvature * width / facing;
    let normal_turn = turn.clamp(-MAX_NORMAL_SPREAD, MAX_NORMAL_SPREAD);
    let spread_angle = if lobe == LOBE_DIFFUSE {
        normal_turn
    } else {
        cone.spread_angle + 2.0 * normal_turn
    };
    RayCone {
        width: width * footprint_stretch(normal, direction, leaving, facing),
        spread_angle,
    }
}

/// IEEE 754 binary16 conversions for the packed cone (the shaders use `packHalf2x16` and
/// `unpackHalf2x16`).
mod f16 {
    /// IEEE 754 binary16 bits of `value`, rounded to nearest, ties to even; overflow gives infinity,
    /// NaN stays NaN.
    pub(super) fn bits(value: f32) -> u16 {
        let bits = value.to_bits();
        let sign = ((bits >> 16) & 0x8000) as u16;
        let exponent = ((bits >> 23) & 0xff) as i32;
        let mantissa = bits & 0x007f_ffff;
        if exponent == 0xff {
            return sign | 0x7c00 | if mantissa != 0 { 0x0200 } else { 0 };
        }
        let half_exponent = exponent - 127 + 15;
        if half_exponent >= 0x1f {
            return sign | 0x7c00;
        }
        // A normal half keeps the top 10 mantissa bits; a subnormal one shifts the implicit bit in too.
        let (kept, shift) = if half_exponent > 0 {
            (((half_exponent as u32) << 10) | (mantissa >> 13), 13)
        } else if half_exponent >= -10 {
            let shift = (14 - half_exponent) as u32;
            ((mantissa | 0x0080_0000) >> shift, shift)
        } else {
            return sign;
        };
        let full = if half_exponent > 0 {
            mantissa
        } else {
            mantissa | 0x0080_0000
        };
        let remainder = full & ((1 << shift) - 1);
        let halfway = 1 << (shift - 1);
        let round_up = remainder > halfway || (remainder == halfway && kept & 1 == 1);
        sign | (kept + u32::from(round_up)) as u16
    }

    /// The f32 value of IEEE 754 binary16 bits (exact).
    pub(super) fn value(bits: u16) -> f32 {
        let sign = u32::from(bits & 0x8000) << 16;
        let exponent = u32::from((bits >> 10) & 0x1f);
        let mantissa = u32::from(bits & 0x03ff);
        match exponent {
            0 => f32::from_bits(sign | (mantissa as f32 * (1.0 / 16_777_216.0)).to_bits()),
            0x1f => f32::from_bits(sign | 0x7f80_0000 | (mantissa << 13)),
            _ => f32::from_bits(sign | ((exponent + 112) << 23) | (mantissa << 13)),
        }
    }

    #[cfg(test)]
    mod tests {
        /// Every f16 converts exactly, as the `half` crate does.
        #[test]
        fn every_half_converts_to_the_same_f32() {
            for bits in 0..=u16::MAX {
                let expected = half::f16::from_bits(bits).to_f32();
                let got = super::value(bits);
                assert!(
                    got.to_bits() == expected.to_bits() || (got.is_nan() && expected.is_nan()),
                    "{bits:#06x}"
                );
            }
        }

        /// f32 to f16 rounds to nearest, ties to even, as the `half` crate does: every f32 whose bit
        /// pattern is a multiple of 7, and every f32 next to an f16 or halfway between two.
        #[test]
        fn f32_rounds_to_the_same_f16() {
            let near_halves = (0..=u16::MAX).flat_map(|h| {
                let centre = half::f16::from_bits(h).to_f32().to_bits() as u64;
                (centre.saturating_sub(2)..=centre + 2).chain([centre + 0x1000])
            });
            for pattern in (0..=u32::MAX as u64).step_by(7).chain(near_halves) {
                let value = f32::from_bits(pattern as u32);
                let expected = half::f16::from_f32(value).to_bits();
                let got = super::bits(value);
                assert!(
                    got == expected || (value.is_nan() && got & 0x7c00 == 0x7c00 && got & 0x3ff != 0),
                    "{value:e}: {got:#06x} vs {expected:#06x}"
                );
            }
        }
    }
}
