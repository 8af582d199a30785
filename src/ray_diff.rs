//! Ray differentials (Igehy 1999; RTG ch. 20 Eq. 1-24): how a ray's origin and direction change from pixel to pixel, carried to hits, barycentrics and texture coordinates.
//!
//! The Rust mirror of `shaders/wgsl/ray_diff.wgsl` and `shaders/glsl/ray_diff.glsl`. Every function
//! here has a shader twin with the same name prefixed `rf_` (constants `RF_`, structs `Rf`), in the
//! same order, computing the same expression in the same order of operations.
//!
//! Sources: Igehy, "Tracing Ray Differentials", SIGGRAPH 1999 (cited as "Igehy"); Akenine-Möller et
//! al., "Texture Level of Detail Strategies for Real-Time Ray Tracing", Ray Tracing Gems ch. 20 (2019),
//! cited as "RTG Eq. N"; Quilez, "ray differentials and texturing" (2015), cited as "Quilez"; the
//! nvpro ray-tracing tutorial "20 Wireframe" (`computeDifferentials`, `computeDerivative` and its
//! "Going Further" section), cited as "wireframe tutorial"; Akenine-Möller et al., "Improved Shader
//! and Texture Level of Detail Using Ray Cones", JCGT 10(1), 2021, cited as "JCGT 2021"; Duff et al.,
//! "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017, cited as "Duff et al. 2017".
//!
//! Conventions (the README's Conventions): camera space is right-handed and looks down -Z; pixel (0, 0) is the
//! top-left pixel and pixel y grows downwards, so every `dy` below is the change for one pixel step
//! *down*. Normals and directions passed in are unit length unless a function says otherwise. A
//! "differential" is the change per one-pixel step: `dx` for a step to the right neighbour, `dy` for a
//! step to the lower neighbour.
//!
//! Robustness: where the math diverges (grazing angle, zero-area triangle, zero-length vector, ray
//! parallel to a plane) the functions clamp with the constants below, so finite inputs give finite
//! outputs. The constants are named `DIFF_*` (shader `RF_DIFF_*`) so that this module can be pasted
//! next to the ray-cone module without redeclaring its constants.

use bytemuck::{Pod, Zeroable};
use glam::{Mat4, Vec2, Vec3, Vec3Swizzles, Vec4, Vec4Swizzles};

/// Largest vertical field of view in radians; wider values are clamped so `tan(fov_y / 2)` stays finite.
pub const DIFF_MAX_FOV_Y: f32 = 3.1;
/// Smallest `|cos|` between two unit vectors used as a divisor (grazing-angle clamp), keeping its sign.
pub const DIFF_MIN_COS: f32 = 1.0e-4;
/// Smallest magnitude used as a divisor (squared lengths, triangle determinants) or passed to `log2`.
pub const DIFF_MIN_MAGNITUDE: f32 = 1.0e-30;
/// Largest magnitude of a barycentric coordinate, barycentric differential or closed-form delta: a
/// ray (nearly) parallel to the triangle's plane gives this instead of infinity. `2^40` (about
/// `1.1e12`, the top of the documented input domain): such a value times any input of the domain,
/// summed over three terms (the UV gradients of barycentric changes), stays finite in f32, so the
/// functions compose; a power of two, exact in every precision.
pub const DIFF_MAX_VALUE: f32 = 1_099_511_627_776.0;
/// Largest triplanar blend sharpness; larger exponents are clamped so the weights cannot all underflow.
pub const DIFF_MAX_SHARPNESS: f32 = 64.0;

/// A ray differential (Igehy; RTG Eq. 7): the change of a ray's origin and direction for a one-pixel
/// step right (`dx`) and down (`dy`).
///
/// Layout: 64 bytes, identical in Rust, WGSL (`RfRayDiff`), GLSL std430 and GLSL scalar layout. Each
/// vec3 is followed by an explicit `f32` pad (vec3 is 16-byte aligned in WGSL and std430), at offsets
/// 0 (`d_origin_dx`), 12 (`pad0`), 16 (`d_origin_dy`), 28 (`pad1`), 32 (`d_direction_dx`), 44 (`pad2`),
/// 48 (`d_direction_dy`), 60 (`pad3`). Functions returning a `RayDiff` set the pads to 0. The struct
/// is 16-byte aligned, as its vec3 fields make it in WGSL and std430.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct RayDiff {
    /// Change of the ray origin per pixel step right.
    pub d_origin_dx: Vec3,
    /// Padding, always 0.
    pub pad0: f32,
    /// Change of the ray origin per pixel step down.
    pub d_origin_dy: Vec3,
    /// Padding, always 0.
    pub pad1: f32,
    /// Change of the (unit) ray direction per pixel step right.
    pub d_direction_dx: Vec3,
    /// Padding, always 0.
    pub pad2: f32,
    /// Change of the (unit) ray direction per pixel step down.
    pub d_direction_dy: Vec3,
    /// Padding, always 0.
    pub pad3: f32,
}

impl RayDiff {
    /// The differential of a ray that does not change from pixel to pixel.
    pub const ZERO: RayDiff = RayDiff::new(Vec3::ZERO, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);

    /// A differential from its four vectors, pads 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec3;
    /// use ray_footprint::ray_diff::RayDiff;
    ///
    /// // An orthographic camera with 1 cm pixels: the origin moves from pixel to pixel, the direction not.
    /// let diff = RayDiff::new(Vec3::new(0.01, 0.0, 0.0), Vec3::new(0.0, -0.01, 0.0), Vec3::ZERO, Vec3::ZERO);
    /// // The shaders read 64 bytes: d_origin_dy starts at byte 16 (its y at 20), the pads at bytes
    /// // 12, 28, 44 and 60 are zero.
    /// let bytes = bytemuck::bytes_of(&diff);
    /// assert_eq!(bytes.len(), 64);
    /// assert_eq!(bytes[20..24], (-0.01f32).to_ne_bytes());
    /// assert!([12, 28, 44, 60].iter().all(|&at| bytes[at..at + 4] == [0; 4]));
    /// ```
    pub const fn new(
        d_origin_dx: Vec3,
        d_origin_dy: Vec3,
        d_direction_dx: Vec3,
        d_direction_dy: Vec3,
    ) -> Self {
        RayDiff {
            d_origin_dx,
            pad0: 0.0,
            d_origin_dy,
            pad1: 0.0,
            d_direction_dx,
            pad2: 0.0,
            d_direction_dy,
            pad3: 0.0,
        }
    }

    /// The origin differentials, `(d_origin_dx, d_origin_dy)`.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::{Vec2, Vec3};
    /// use ray_footprint::ray_diff::{eye_ray_diff, RayDiff};
    ///
    /// let size = Vec2::new(1920.0, 1080.0);
    /// let diff = eye_ray_diff(Vec2::new(100.0, 200.0), size, 1.0, Vec3::X, Vec3::Y, Vec3::Z);
    /// // A pinhole's rays all leave the eye: no origin change.
    /// assert_eq!(diff.d_origin().dx, Vec3::ZERO);
    /// assert_eq!(diff.d_origin().dy, Vec3::ZERO);
    /// // The two pairs make the differential again.
    /// let (origin, direction) = (diff.d_origin(), diff.d_direction());
    /// assert_eq!(RayDiff::new(origin.dx, origin.dy, direction.dx, direction.dy), diff);
    /// ```
    pub fn d_origin(&self) -> Derivatives3 {
        Derivatives3::new(self.d_origin_dx, self.d_origin_dy)
    }

    /// The direction differentials, `(d_direction_dx, d_direction_dy)`.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::{Vec2, Vec3};
    /// use ray_footprint::ray_diff::eye_ray_diff;
    ///
    /// // At the centre of a 1920 x 1080 image with a 60-degree field of view a one-pixel step turns the
    /// // ray by the pixel's height at distance 1, 2 tan(30°) / 1080, either way.
    /// let (size, fov_y) = (Vec2::new(1920.0, 1080.0), 60f32.to_radians());
    /// let diff = eye_ray_diff(Vec2::new(959.5, 539.5), size, fov_y, Vec3::X, Vec3::Y, Vec3::Z);
    /// let expected = 2.0 / (3f32.sqrt() * 1080.0);
    /// assert!((diff.d_direction().dx.length() - expected).abs() < 1e-6 * expected);
    /// assert!((diff.d_direction().dy.length() - expected).abs() < 1e-6 * expected);
    /// ```
    pub fn d_direction(&self) -> Derivatives3 {
        Derivatives3::new(self.d_direction_dx, self.d_direction_dy)
    }
}

/// The change of a 2-vector (barycentrics `(u, v)`, texture coordinates) per pixel step right (`dx`)
/// and down (`dy`). For texture coordinates these are the `ddx` / `ddy` gradients of `SampleGrad`.
///
/// A function result (shader `RfDerivatives2`), not laid out for host-shareable buffers.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Derivatives2 {
    /// Change per pixel step right.
    pub dx: Vec2,
    /// Change per pixel step down.
    pub dy: Vec2,
}

impl Derivatives2 {
    /// Both derivatives.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec2;
    /// use ray_footprint::ray_diff::{lod_isotropic, Derivatives2};
    ///
    /// // Texel gradients of a footprint 4 texels wide both ways: it shrinks to one texel at mip level 2.
    /// let texel_gradients = Derivatives2::new(Vec2::new(4.0, 0.0), Vec2::new(0.0, 4.0));
    /// assert_eq!(lod_isotropic(texel_gradients), 2.0);
    /// ```
    pub const fn new(dx: Vec2, dy: Vec2) -> Self {
        Derivatives2 { dx, dy }
    }
}

/// The change of a 3-vector (position, normal, barycentrics `(w, u, v)`) per pixel step right (`dx`)
/// and down (`dy`).
///
/// A function result (shader `RfDerivatives3`), not laid out for host-shareable buffers.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Derivatives3 {
    /// Change per pixel step right.
    pub dx: Vec3,
    /// Change per pixel step down.
    pub dy: Vec3,
}

impl Derivatives3 {
    /// Both derivatives.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::{Vec2, Vec3};
    /// use ray_footprint::ray_diff::{planar_mapping_gradients, Derivatives3};
    ///
    /// // Position differentials on a floor: 1 cm to the right per pixel step right, 2 cm towards the
    /// // camera (+z) per step down. With a texture repeating every 2 m (scale 0.5) that is 0.005 and
    /// // 0.01 UV units.
    /// let d_position = Derivatives3::new(Vec3::new(0.01, 0.0, 0.0), Vec3::new(0.0, 0.0, 0.02));
    /// let uv = planar_mapping_gradients(d_position, Vec2::splat(0.5));
    /// assert_eq!(uv.dx, Vec2::new(0.005, 0.0));
    /// assert_eq!(uv.dy, Vec2::new(0.0, 0.01));
    /// ```
    pub const fn new(dx: Vec3, dy: Vec3) -> Self {
        Derivatives3 { dx, dy }
    }
}

/// World-space unit directions of the rays through the centres of the right and the lower neighbour
/// pixel (wireframe tutorial, `computeDifferentials`). Shader `RfNeighbourDirections`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NeighbourDirections {
    /// Direction through the centre of pixel `(x + 1, y)`.
    pub right: Vec3,
    /// Direction through the centre of pixel `(x, y + 1)`.
    pub below: Vec3,
}

/// A refracted ray differential and whether the ray was totally internally reflected instead
/// (shader `RfRefractedRayDiff`). On total internal reflection `diff` is the *reflected* differential.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RefractedRayDiff {
    /// The differential of the transmitted ray, or of the reflected ray on total internal reflection.
    pub diff: RayDiff,
    /// True when `1 - eta^2 (1 - dot(D, N)^2) < 0`: no transmitted ray exists.
    pub total_internal_reflection: bool,
}

/// One G-buffer pixel as the G-buffer ray differentials read it (RTG Sec. 20.3.3; shader
/// `RfGBufferSample`): the unit eye-ray direction through the pixel, the distance to its first hit
/// and the unit surface normal there. A function argument, not laid out for host-shareable buffers.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GBufferSample {
    /// Unit direction of the eye ray through the pixel centre.
    pub eye_direction: Vec3,
    /// Distance from the camera to the first hit.
    pub distance: f32,
    /// Unit surface normal at the first hit.
    pub normal: Vec3,
}

/// Texture-coordinate gradients of the three projections of triplanar mapping (Quilez; shader
/// `RfTriplanarGradients`): the projection onto the yz plane samples with `p.yz`, and so on.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TriplanarGradients {
    /// Gradients of the projection along x, sampled with `p.yz`.
    pub yz: Derivatives2,
    /// Gradients of the projection along y, sampled with `p.zx`.
    pub zx: Derivatives2,
    /// Gradients of the projection along z, sampled with `p.xy`.
    pub xy: Derivatives2,
}

// ---- Camera rays and their differentials (RTG Eq. 8-11; wireframe tutorial) ----

/// Half extents of the image plane at distance 1 from a pinhole (RTG Eq. 9): `(a * f, f)` with
/// `f = tan(fov_y / 2)` and aspect `a = W / H`; `fov_y` is clamped to `[0, DIFF_MAX_FOV_Y]`, W and H
/// to `>= 1`.
fn eye_ray_extent(image_size: Vec2, fov_y: f32) -> Vec2 {
    let size = image_size.max(Vec2::ONE);
    let f = (0.5 * fov_y.clamp(0.0, DIFF_MAX_FOV_Y)).tan();
    Vec2::new(size.x / size.y * f, f)
}

/// Normalized device coordinates of a pixel centre (RTG Eq. 8 `c = 2p - 1`; wireframe tutorial):
/// `((pixel + 0.5) / size) * 2 - 1`, image size clamped to `>= 1`.
fn pixel_ndc(pixel: Vec2, image_size: Vec2) -> Vec2 {
    (pixel + 0.5) / image_size.max(Vec2::ONE) * 2.0 - 1.0
}

/// Non-normalized eye-ray direction through pixel `pixel` of a pinhole camera (RTG Eq. 8-9):
/// `d = c.x * a * f * right - c.y * f * up - view`, with `c = 2 (pixel + 0.5) / size - 1`,
/// `a = W / H`, `f = tan(fov_y / 2)`.
///
/// `right`, `up` and `view` are the camera's orthonormal basis; `view` points *towards* the camera
/// (the camera looks down `-view`). Clamps as `eye_ray_extent`.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::eye_ray_direction;
///
/// let (size, fov_y) = (Vec2::new(1920.0, 1080.0), 60f32.to_radians());
/// let eye = |pixel: Vec2| eye_ray_direction(pixel, size, fov_y, Vec3::X, Vec3::Y, Vec3::Z);
/// // The middle of the top edge (pixel centre (960, 0)) is fov_y / 2 = 30 degrees above the axis -Z,
/// let top = eye(Vec2::new(959.5, -0.5));
/// assert!((top.y.atan2(-top.z) - 30f32.to_radians()).abs() < 1e-6);
/// // and the middle of the right edge atan(16 / 9 tan(30°)) = atan(16 / (9 sqrt(3))) to the right.
/// let right = eye(Vec2::new(1919.5, 539.5));
/// let expected = (16.0 / (9.0 * 3f32.sqrt())).atan();
/// assert!((right.x.atan2(-right.z) - expected).abs() < 1e-6);
/// ```
pub fn eye_ray_direction(
    pixel: Vec2,
    image_size: Vec2,
    fov_y: f32,
    right: Vec3,
    up: Vec3,
    view: Vec3,
) -> Vec3 {
    let c = pixel_ndc(pixel, image_size);
    let extent = eye_ray_extent(image_size, fov_y);
    c.x * extent.x * right - c.y * extent.y * up - view
}

/// Derivative of the normalized vector `v / |v|` when `v` changes by `dv` (Igehy; RTG Eq. 10):
/// `((v.v) dv - (v.dv) v) / (v.v)^1.5`, evaluated as `(dv - v * ((v.dv) / (v.v))) / sqrt(v.v)` so
/// that no power of `v.v` can overflow or underflow; `v.v` is clamped to `>= DIFF_MIN_MAGNITUDE`.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_diff::normalized_derivative;
///
/// let (v, dv) = (Vec3::new(0.3, -0.4, -1.2), Vec3::new(0.001, 0.002, 0.0));
/// let derivative = normalized_derivative(v, dv).as_dvec3();
/// // A central difference of v / |v| in f64 (its error is of order h^2, here about 1e-14).
/// let (v, dv, h) = (v.as_dvec3(), dv.as_dvec3(), 1e-4);
/// let reference = ((v + h * dv).normalize() - (v - h * dv).normalize()) / (2.0 * h);
/// assert!((derivative - reference).length() < 1e-6 * reference.length());
/// ```
pub fn normalized_derivative(v: Vec3, dv: Vec3) -> Vec3 {
    let length2 = v.dot(v).max(DIFF_MIN_MAGNITUDE);
    (dv - v * (v.dot(dv) / length2)) / length2.sqrt()
}

/// Differential of the eye ray of a pinhole camera (Igehy; RTG Eq. 8-11): `dO = 0`,
/// `dD/dx = normalized_derivative(d, (2 a f / W) * right)`,
/// `dD/dy = normalized_derivative(d, -(2 f / H) * up)` with `d` from [`eye_ray_direction`].
/// The direction differentials are those of the *unit* direction `d / |d|`.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::eye_ray_diff;
///
/// // 1920 x 1080, 60 degrees: down the middle column the ray's angle above the axis is atan(f c),
/// // f = tan(30°), with c changing by 2 / 1080 per row; the derivative f (2 / 1080) cos^2 of that
/// // angle is, at the top edge (30 degrees), 2 / (sqrt(3) 1080) times cos^2(30°) = 3 / 4.
/// let (size, fov_y) = (Vec2::new(1920.0, 1080.0), 60f32.to_radians());
/// let diff = eye_ray_diff(Vec2::new(959.5, -0.5), size, fov_y, Vec3::X, Vec3::Y, Vec3::Z);
/// let expected = 2.0 / (3f32.sqrt() * 1080.0) * 0.75;
/// assert!((diff.d_direction_dy.length() - expected).abs() < 1e-6 * expected);
/// assert!(diff.d_direction_dy.y < 0.0); // a row down turns the ray down
/// ```
pub fn eye_ray_diff(pixel: Vec2, image_size: Vec2, fov_y: f32, right: Vec3, up: Vec3, view: Vec3) -> RayDiff {
    let d = eye_ray_direction(pixel, image_size, fov_y, right, up, view);
    let size = image_size.max(Vec2::ONE);
    let extent = eye_ray_extent(image_size, fov_y);
    let dd_dx = 2.0 * extent.x / size.x * right;
    let dd_dy = -(2.0 * extent.y / size.y) * up;
    RayDiff::new(
        Vec3::ZERO,
        Vec3::ZERO,
        normalized_derivative(d, dd_dx),
        normalized_derivative(d, dd_dy),
    )
}

/// `v / sqrt(max(v.v, DIFF_MIN_MAGNITUDE))`: `v` normalized, or a short vector when `v` is (nearly) 0.
fn safe_normalize(v: Vec3) -> Vec3 {
    v / v.dot(v).max(DIFF_MIN_MAGNITUDE).sqrt()
}

/// World direction of the ray through normalized device coordinates `ndc` (wireframe tutorial's
/// primary-ray generator): `view_inv * (normalize((proj_inv * (ndc, 1, 1)).xyz), 0)`, normalised as
/// [`eye_ray_direction_from_matrices`] says.
fn matrix_ray_direction(ndc: Vec2, view_inv: Mat4, proj_inv: Mat4) -> Vec3 {
    let far_point = proj_inv * Vec4::new(ndc.x, ndc.y, 1.0, 1.0);
    (view_inv * safe_normalize(far_point.xyz()).extend(0.0)).xyz()
}

/// Eye-ray direction through pixel `pixel` from the inverse view and projection matrices (wireframe
/// tutorial): `view_inv * (normalize((proj_inv * (ndc, 1, 1)).xyz), 0)` with
/// `ndc = ((pixel + 0.5) / size) * 2 - 1`, where the normalisation divides by
/// `sqrt(max(|h|^2, DIFF_MIN_MAGNITUDE))` for the far point `h`: unit length when `view_inv` is a
/// rigid transform and `|h|^2 >= DIFF_MIN_MAGNITUDE`, shorter (zero for a zero matrix) below. The ray
/// origin is `view_inv * (0, 0, 0, 1)`. The projection's y flip (Vulkan) is simply applied.
///
/// # Examples
///
/// ```
/// use glam::camera::rh::{proj::vulkan::perspective, view::look_at_mat4};
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::eye_ray_direction_from_matrices;
///
/// // A camera at (0, 2, 5) looking at the origin: 60 degrees, 16:9, Vulkan's projection (y down).
/// let view = look_at_mat4(Vec3::new(0.0, 2.0, 5.0), Vec3::ZERO, Vec3::Y);
/// let proj = perspective(60f32.to_radians(), 16.0 / 9.0, 0.1, 100.0);
/// let (view_inv, proj_inv) = (view.inverse(), proj.inverse());
/// let eye = |pixel: Vec2| eye_ray_direction_from_matrices(pixel, Vec2::new(1920.0, 1080.0), view_inv, proj_inv);
/// // The image centre looks at the origin; the middle of the top edge 30 degrees above that.
/// let centre = eye(Vec2::new(959.5, 539.5));
/// assert!((centre - Vec3::new(0.0, -2.0, -5.0).normalize()).length() < 1e-6);
/// let top = eye(Vec2::new(959.5, -0.5));
/// assert!((top.angle_between(centre) - 30f32.to_radians()).abs() < 1e-6);
/// assert!(top.y > centre.y);
/// ```
pub fn eye_ray_direction_from_matrices(
    pixel: Vec2,
    image_size: Vec2,
    view_inv: Mat4,
    proj_inv: Mat4,
) -> Vec3 {
    matrix_ray_direction(pixel_ndc(pixel, image_size), view_inv, proj_inv)
}

/// Differential of the eye ray of [`eye_ray_direction_from_matrices`] (Igehy; RTG Eq. 10 applied to the
/// matrix generator): with `h = (proj_inv * (ndc, 1, 1)).xyz`, `dh/dx = proj_inv[0].xyz * 2 / W` and
/// `dh/dy = proj_inv[1].xyz * 2 / H`, `dD/dx = view_inv * (normalized_derivative(h, dh/dx), 0)` (same
/// for y); `dO = 0`.
///
/// # Examples
///
/// ```
/// use glam::camera::rh::{proj::vulkan::perspective, view::look_at_mat4};
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::eye_ray_diff_from_matrices;
///
/// // A camera at (0, 2, 5) looking at the origin: 60 degrees, 16:9, Vulkan's projection (y down).
/// let view = look_at_mat4(Vec3::new(0.0, 2.0, 5.0), Vec3::ZERO, Vec3::Y);
/// let proj = perspective(60f32.to_radians(), 16.0 / 9.0, 0.1, 100.0);
/// let centre = Vec2::new(959.5, 539.5);
/// let diff = eye_ray_diff_from_matrices(centre, Vec2::new(1920.0, 1080.0), view.inverse(), proj.inverse());
/// // At the image centre a pixel step turns the ray by 2 tan(30°) / 1080, to the camera's right
/// // (+X) for a step right and down for a step down.
/// let expected = 2.0 / (3f32.sqrt() * 1080.0);
/// assert!((diff.d_direction_dx.length() - expected).abs() < 1e-6 * expected);
/// assert!((diff.d_direction_dy.length() - expected).abs() < 1e-6 * expected);
/// assert!(diff.d_direction_dx.x > 0.0 && diff.d_direction_dy.y < 0.0);
/// ```
pub fn eye_ray_diff_from_matrices(pixel: Vec2, image_size: Vec2, view_inv: Mat4, proj_inv: Mat4) -> RayDiff {
    let size = image_size.max(Vec2::ONE);
    let ndc = pixel_ndc(pixel, image_size);
    let far_point = (proj_inv * Vec4::new(ndc.x, ndc.y, 1.0, 1.0)).xyz();
    let dfar_dx = proj_inv.x_axis.xyz() * (2.0 / size.x);
    let dfar_dy = proj_inv.y_axis.xyz() * (2.0 / size.y);
    let dd_dx = (view_inv * normalized_derivative(far_point, dfar_dx).extend(0.0)).xyz();
    let dd_dy = (view_inv * normalized_derivative(far_point, dfar_dy).extend(0.0)).xyz();
    RayDiff::new(Vec3::ZERO, Vec3::ZERO, dd_dx, dd_dy)
}

/// Pixel differentials from the inverse matrices (wireframe tutorial, `computeDifferentials`): the
/// world directions of the rays through the centres of the right and the lower neighbour pixel, as
/// [`eye_ray_direction_from_matrices`] of `pixel + (1, 0)` and `pixel + (0, 1)`
/// (`ndc_offset = ((pixel + 1.5) / size) * 2 - 1`).
///
/// # Examples
///
/// ```
/// use glam::camera::rh::proj::vulkan::perspective;
/// use glam::{Mat4, Vec2};
/// use ray_footprint::ray_diff::{eye_ray_direction_from_matrices, pixel_directions};
///
/// // A camera at the origin looking down -Z: 60 degrees, 16:9, Vulkan's projection (y down).
/// let (view_inv, proj_inv) = (Mat4::IDENTITY, perspective(60f32.to_radians(), 16.0 / 9.0, 0.1, 100.0).inverse());
/// let size = Vec2::new(1920.0, 1080.0);
/// // Pixel (959, 539.5) and its right neighbour have their centres half a pixel either side of the
/// // image centre: on the plane at distance 1 they lie 16 / 9 tan(30°) / 1920 = 1 / (1080 sqrt(3))
/// // left and right of the axis, so the rays are 2 atan(1 / (1080 sqrt(3))) apart. Each f32
/// // direction carries about 6e-8 of rounding, 1e-4 of that angle.
/// let pixel = Vec2::new(959.0, 539.5);
/// let here = eye_ray_direction_from_matrices(pixel, size, view_inv, proj_inv).as_dvec3();
/// let right = pixel_directions(pixel, size, view_inv, proj_inv).right.as_dvec3();
/// let expected = 2.0 * (1.0 / (1080.0 * 3f64.sqrt())).atan();
/// assert!((here.angle_between(right) - expected).abs() < 2e-4 * expected);
/// ```
pub fn pixel_directions(
    pixel: Vec2,
    image_size: Vec2,
    view_inv: Mat4,
    proj_inv: Mat4,
) -> NeighbourDirections {
    let ndc = pixel_ndc(pixel, image_size);
    let next = pixel_ndc(pixel + 1.0, image_size);
    NeighbourDirections {
        right: matrix_ray_direction(Vec2::new(next.x, ndc.y), view_inv, proj_inv),
        below: matrix_ray_direction(Vec2::new(ndc.x, next.y), view_inv, proj_inv),
    }
}

// ---- Transfer to a hit (Igehy) ----

/// `value`, or `min_magnitude` with the sign of `value` (+ for 0) when `|value| < min_magnitude`.
fn clamp_away_from_zero(value: f32, min_magnitude: f32) -> f32 {
    if value.abs() < min_magnitude {
        if value >= 0.0 {
            min_magnitude
        } else {
            -min_magnitude
        }
    } else {
        value
    }
}

/// Change of the hit point on a plane for one pixel step (Igehy's transfer): with
/// `q = dO + t * dD`, `dt = -dot(q, N) / dot(D, N)` and `dP = q + dt * D`. `cosine` is `dot(D, N)`,
/// already clamped.
fn transferred_origin(
    d_origin: Vec3,
    d_direction: Vec3,
    direction: Vec3,
    t: f32,
    normal: Vec3,
    cosine: f32,
) -> Vec3 {
    let q = d_origin + t * d_direction;
    let dt = -q.dot(normal) / cosine;
    q + dt * direction
}

/// Transfers a differential over a distance `t` to a hit on a surface with unit normal `normal`
/// (Igehy, transfer): `dt/dx = -dot(dO/dx + t dD/dx, N) / dot(D, N)`,
/// `dP/dx = dO/dx + t dD/dx + (dt/dx) D`, same for y.
///
/// Returns the differential of the ray leaving the hit: origin differentials `dP`, direction
/// differentials unchanged (replace them with [`reflect_ray_diff`] / [`refract_ray_diff`]).
/// `direction` is the unit ray direction that `t` measures; `dot(D, N)` is clamped away from 0 to
/// `|cos| >= DIFF_MIN_COS`.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::{eye_ray_diff, eye_ray_direction, transfer};
///
/// // A camera at the origin looking down -Z (1920 x 1080, 60 degrees) and the floor y = -1.
/// let (size, fov_y) = (Vec2::new(1920.0, 1080.0), 60f32.to_radians());
/// let eye = |pixel: Vec2| eye_ray_direction(pixel, size, fov_y, Vec3::X, Vec3::Y, Vec3::Z);
/// let floor_hit = |pixel: Vec2| eye(pixel) / -eye(pixel).y;
/// let pixel = Vec2::new(1200.0, 900.0);
/// let diff = eye_ray_diff(pixel, size, fov_y, Vec3::X, Vec3::Y, Vec3::Z);
/// let hit = transfer(diff, eye(pixel).normalize(), floor_hit(pixel).length(), Vec3::Y);
/// // The rays of a row meet the floor on a line at even steps, so 100 pixels to the right is 100
/// // dP/dx away. The hits (about 3 m) carry about 3e-7 of rounding: 1e-6 of the 0.28 m step.
/// let step = (floor_hit(pixel + Vec2::new(100.0, 0.0)) - floor_hit(pixel)) / 100.0;
/// assert!((hit.d_origin_dx - step).length() < 1e-5 * step.length());
/// ```
pub fn transfer(diff: RayDiff, direction: Vec3, t: f32, normal: Vec3) -> RayDiff {
    let cosine = clamp_away_from_zero(direction.dot(normal), DIFF_MIN_COS);
    RayDiff::new(
        transferred_origin(
            diff.d_origin_dx,
            diff.d_direction_dx,
            direction,
            t,
            normal,
            cosine,
        ),
        transferred_origin(
            diff.d_origin_dy,
            diff.d_direction_dy,
            direction,
            t,
            normal,
            cosine,
        ),
        diff.d_direction_dx,
        diff.d_direction_dy,
    )
}

// ---- Barycentric, texture and LOD derivatives (RTG Eq. 12-24) ----

/// Barycentric differentials of a hit, optimized form (RTG Eq. 12-19): with `e1 = p1 - p0`,
/// `e2 = p2 - p0`, `k = dot(cross(e1, e2), d)`, `q = dO/dx + t dD/dx`, `r = dO/dy + t dD/dy`:
/// `du/dx = dot(cross(e2, d), q) / k`, `dv/dx = dot(cross(d, e1), q) / k`, and with `r` for y.
///
/// Returns `(du/dx, dv/dx)` in `dx` and `(du/dy, dv/dy)` in `dy`; `dw = -du - dv`
/// ([`barycentric_w_derivatives`]). `direction` need not be unit length, but `t` must measure it
/// (hit = origin + t * direction). `k` is clamped away from 0 to `|k| >= DIFF_MIN_MAGNITUDE` and the
/// results to `[-DIFF_MAX_VALUE, DIFF_MAX_VALUE]` (a ray in the triangle's plane).
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::{barycentric_derivatives, RayDiff};
///
/// // A floor triangle with legs of 4 m along x and -z: u = x / 4 and v = -z / 4.
/// let (p0, p1, p2) = (Vec3::ZERO, Vec3::new(4.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -4.0));
/// // A camera 10 m above looks straight down; a pixel step turns the ray by 1 mrad along x (right)
/// // or +z (down the image), so the hit moves by 1 cm: u by +0.0025, v by -0.0025.
/// let diff = RayDiff::new(Vec3::ZERO, Vec3::ZERO, Vec3::new(1e-3, 0.0, 0.0), Vec3::new(0.0, 0.0, 1e-3));
/// let b = barycentric_derivatives(diff, Vec3::NEG_Y, 10.0, p0, p1, p2);
/// assert!((b.dx - Vec2::new(0.0025, 0.0)).length() < 1e-9);
/// assert!((b.dy - Vec2::new(0.0, -0.0025)).length() < 1e-9);
/// ```
pub fn barycentric_derivatives(
    diff: RayDiff,
    direction: Vec3,
    t: f32,
    p0: Vec3,
    p1: Vec3,
    p2: Vec3,
) -> Derivatives2 {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let k = clamp_away_from_zero(e1.cross(e2).dot(direction), DIFF_MIN_MAGNITUDE);
    let cu = e2.cross(direction);
    let cv = direction.cross(e1);
    let q = diff.d_origin_dx + t * diff.d_direction_dx;
    let r = diff.d_origin_dy + t * diff.d_direction_dy;
    let limit = Vec2::splat(DIFF_MAX_VALUE);
    Derivatives2::new(
        (Vec2::new(cu.dot(q), cv.dot(q)) / k).clamp(-limit, limit),
        (Vec2::new(cu.dot(r), cv.dot(r)) / k).clamp(-limit, limit),
    )
}

/// Differentials of the third barycentric coordinate `w = 1 - u - v` (RTG Eq. 20):
/// `(dw/dx, dw/dy) = (-du/dx - dv/dx, -du/dy - dv/dy)`.
///
/// # Examples
///
/// ```
/// use glam::Vec2;
/// use ray_footprint::ray_diff::{barycentric_w_derivatives, Derivatives2};
///
/// // u + v + w = 1 everywhere: w changes by minus the change of u + v.
/// let b = Derivatives2::new(Vec2::new(0.0025, 0.001), Vec2::new(0.0, -0.0025));
/// let w = barycentric_w_derivatives(b);
/// assert!((w - Vec2::new(-0.0035, 0.0025)).length() < 1e-9);
/// ```
pub fn barycentric_w_derivatives(barycentric: Derivatives2) -> Vec2 {
    Vec2::new(
        -barycentric.dx.x - barycentric.dx.y,
        -barycentric.dy.x - barycentric.dy.y,
    )
}

/// Texture-coordinate differentials in UV units (RTG Eq. 21 without the texture size): with
/// `g1 = T1 - T0`, `g2 = T2 - T0`: `d(uv)/dx = du/dx * g1 + dv/dx * g2`, same for y. These are the
/// anisotropic `ddx` / `ddy` gradients for `SampleGrad` / `textureGrad`.
///
/// # Examples
///
/// ```
/// use glam::Vec2;
/// use ray_footprint::ray_diff::{texture_derivatives, Derivatives2};
///
/// // The floor triangle of legs 4 m (u = x / 4, v = -z / 4) with texture coordinates (0, 0), (2, 0),
/// // (0, 2): the texture repeats every 2 m. A step of 1 cm (du = 0.0025) is 0.005 UV units.
/// let b = Derivatives2::new(Vec2::new(0.0025, 0.0), Vec2::new(0.0, -0.0025));
/// let uv = texture_derivatives(b, Vec2::ZERO, Vec2::new(2.0, 0.0), Vec2::new(0.0, 2.0));
/// assert!((uv.dx - Vec2::new(0.005, 0.0)).length() < 1e-9);
/// assert!((uv.dy - Vec2::new(0.0, -0.005)).length() < 1e-9);
/// ```
pub fn texture_derivatives(barycentric: Derivatives2, t0: Vec2, t1: Vec2, t2: Vec2) -> Derivatives2 {
    let g1 = t1 - t0;
    let g2 = t2 - t0;
    Derivatives2::new(
        barycentric.dx.x * g1 + barycentric.dx.y * g2,
        barycentric.dy.x * g1 + barycentric.dy.y * g2,
    )
}

/// Texture-space differentials in texels (RTG Eq. 21): [`texture_derivatives`] times the texture size
/// `(W, H)`, clamped to `>= 1`: `ds/dx = W * (du/dx g1.x + dv/dx g2.x)`, `dt/dx = H * (...)`.
///
/// # Examples
///
/// ```
/// use glam::Vec2;
/// use ray_footprint::ray_diff::{texel_derivatives, Derivatives2};
///
/// // As for `texture_derivatives`: 0.005 UV units on a 1024 x 512 texture are 5.12 texels across
/// // and 2.56 texels up.
/// let b = Derivatives2::new(Vec2::new(0.0025, 0.0), Vec2::new(0.0, -0.0025));
/// let size = Vec2::new(1024.0, 512.0);
/// let texels = texel_derivatives(b, Vec2::ZERO, Vec2::new(2.0, 0.0), Vec2::new(0.0, 2.0), size);
/// assert!((texels.dx - Vec2::new(5.12, 0.0)).length() < 1e-5);
/// assert!((texels.dy - Vec2::new(0.0, -2.56)).length() < 1e-5);
/// ```
pub fn texel_derivatives(
    barycentric: Derivatives2,
    t0: Vec2,
    t1: Vec2,
    t2: Vec2,
    texture_size: Vec2,
) -> Derivatives2 {
    let size = texture_size.max(Vec2::ONE);
    let uv = texture_derivatives(barycentric, t0, t1, t2);
    Derivatives2::new(uv.dx * size, uv.dy * size)
}

/// Origin differentials of a secondary (reflected or refracted) ray from the barycentric
/// differentials (RTG Eq. 22): `dO'/dx = du/dx * e1 + dv/dx * e2`, same for y. Equal to the `dP` of
/// [`transfer`] for a hit on the triangle.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_diff::{barycentric_derivatives, secondary_origin_derivatives, transfer, RayDiff};
///
/// // A tilted triangle in front of a pinhole at the origin, and an eye ray differential.
/// let (p0, p1, p2) = (Vec3::new(-1.0, 0.0, -4.0), Vec3::new(3.0, 0.5, -5.0), Vec3::new(0.0, 3.0, -6.0));
/// let direction = Vec3::new(0.1, 0.2, -1.0).normalize();
/// let diff = RayDiff::new(Vec3::ZERO, Vec3::ZERO, Vec3::new(1e-3, 0.0, 1e-4), Vec3::new(0.0, -1e-3, -2e-4));
/// let normal = (p1 - p0).cross(p2 - p0).normalize();
/// let t = p0.dot(normal) / direction.dot(normal);
/// let b = barycentric_derivatives(diff, direction, t, p0, p1, p2);
/// let moved = secondary_origin_derivatives(b, p0, p1, p2);
/// // Igehy's transfer to the triangle's plane moves the hit the same way (RTG Eq. 22).
/// let transferred = transfer(diff, direction, t, normal);
/// assert!((moved.dx - transferred.d_origin_dx).length() < 1e-5 * transferred.d_origin_dx.length());
/// assert!((moved.dy - transferred.d_origin_dy).length() < 1e-5 * transferred.d_origin_dy.length());
/// ```
pub fn secondary_origin_derivatives(barycentric: Derivatives2, p0: Vec3, p1: Vec3, p2: Vec3) -> Derivatives3 {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    Derivatives3::new(
        barycentric.dx.x * e1 + barycentric.dx.y * e2,
        barycentric.dy.x * e1 + barycentric.dy.y * e2,
    )
}

/// Isotropic level of detail from texel gradients (RTG Eq. 1-2):
/// `rho = max(|(ds/dx, dt/dx)|, |(ds/dy, dt/dy)|)`, `lambda = log2(rho)`, evaluated as
/// `0.5 * log2(max(rho^2, DIFF_MIN_MAGNITUDE))`.
///
/// # Examples
///
/// ```
/// use glam::Vec2;
/// use ray_footprint::ray_diff::{lod_isotropic, Derivatives2};
///
/// // A footprint 8 texels long and 2 wide: the isotropic level follows the longer side, log2(8).
/// assert_eq!(lod_isotropic(Derivatives2::new(Vec2::new(8.0, 0.0), Vec2::new(0.0, 2.0))), 3.0);
/// // Lengths are Euclidean: a gradient of (3, 4) texels is 5 texels long.
/// let lod = lod_isotropic(Derivatives2::new(Vec2::new(3.0, 4.0), Vec2::ZERO));
/// assert!((lod - 5f32.log2()).abs() < 1e-6);
/// ```
pub fn lod_isotropic(texel_gradients: Derivatives2) -> f32 {
    let rho2 = texel_gradients
        .dx
        .dot(texel_gradients.dx)
        .max(texel_gradients.dy.dot(texel_gradients.dy));
    0.5 * rho2.max(DIFF_MIN_MAGNITUDE).log2()
}

/// Conservative level of detail from texel gradients (RTG Sec. 20.1): the side of the box around the
/// footprint, `rho = max(|ds/dx| + |ds/dy|, |dt/dx| + |dt/dy|)`, `lambda = log2(max(rho,
/// DIFF_MIN_MAGNITUDE))`.
///
/// # Examples
///
/// ```
/// use glam::Vec2;
/// use ray_footprint::ray_diff::{lod_box, Derivatives2};
///
/// // The gradients (3, 4) and (1, 0) span a parallelogram with corners (0, 0), (3, 4), (1, 0) and
/// // (4, 4): its bounding box is 4 x 4 texels, level log2(4) = 2.
/// assert_eq!(lod_box(Derivatives2::new(Vec2::new(3.0, 4.0), Vec2::new(1.0, 0.0))), 2.0);
/// ```
pub fn lod_box(texel_gradients: Derivatives2) -> f32 {
    let extent = texel_gradients.dx.abs() + texel_gradients.dy.abs();
    extent.x.max(extent.y).max(DIFF_MIN_MAGNITUDE).log2()
}

/// Anisotropic `SampleGrad` / `textureGrad` gradients: the UV differentials of
/// [`texture_derivatives`] scaled by `max(tex_grad_scale, 0)` (0 samples mip 0, 1 the matching level,
/// above 1 blurs), as the ray-cone tutorial's `texGradScale`.
///
/// # Examples
///
/// ```
/// use glam::Vec2;
/// use ray_footprint::ray_diff::{lod_isotropic, sample_grad_gradients, Derivatives2};
///
/// // tex_grad_scale 2 doubles the gradients: one mip level blurrier. 0 samples mip 0.
/// let gradients = Derivatives2::new(Vec2::new(4.0, 1.0), Vec2::new(-1.0, 3.0));
/// let blurred = sample_grad_gradients(gradients, 2.0);
/// assert_eq!(lod_isotropic(blurred), lod_isotropic(gradients) + 1.0);
/// assert_eq!(sample_grad_gradients(gradients, 0.0), Derivatives2::default());
/// ```
pub fn sample_grad_gradients(uv_gradients: Derivatives2, tex_grad_scale: f32) -> Derivatives2 {
    let scale = tex_grad_scale.max(0.0);
    Derivatives2::new(uv_gradients.dx * scale, uv_gradients.dy * scale)
}

// ---- Reflection and refraction (Igehy) ----

/// Differentials of the unit shading normal interpolated from vertex normals (Igehy):
/// `n = (1 - u - v) n0 + u n1 + v n2`, `dn/dx = du/dx (n1 - n0) + dv/dx (n2 - n0)` and
/// `dN/dx = normalized_derivative(n, dn/dx)`, same for y. `barycentrics` is the hit's `(u, v)`,
/// `barycentric` its differentials ([`barycentric_derivatives`]).
///
/// # Examples
///
/// ```
/// use glam::{DVec2, DVec3, Vec2, Vec3};
/// use ray_footprint::ray_diff::{normal_derivatives, Derivatives2};
///
/// // A triangle with the vertex normals X, Y, Z, hit at (u, v) = (0.2, 0.3); a step right changes
/// // (u, v) by (0.004, 0.001).
/// let (barycentrics, step) = (Vec2::new(0.2, 0.3), Vec2::new(0.004, 0.001));
/// let dn = normal_derivatives(Vec3::X, Vec3::Y, Vec3::Z, barycentrics, Derivatives2::new(step, Vec2::ZERO));
/// // A central difference of the interpolated, normalized normal in f64 (error of order h^2).
/// let normal = |b: DVec2| ((1.0 - b.x - b.y) * DVec3::X + b.x * DVec3::Y + b.y * DVec3::Z).normalize();
/// let (b, step, h) = (barycentrics.as_dvec2(), step.as_dvec2(), 1e-3);
/// let reference = (normal(b + h * step) - normal(b - h * step)) / (2.0 * h);
/// assert!((dn.dx.as_dvec3() - reference).length() < 1e-6 * reference.length());
/// ```
pub fn normal_derivatives(
    n0: Vec3,
    n1: Vec3,
    n2: Vec3,
    barycentrics: Vec2,
    barycentric: Derivatives2,
) -> Derivatives3 {
    let n = (1.0 - barycentrics.x - barycentrics.y) * n0 + barycentrics.x * n1 + barycentrics.y * n2;
    let dn_dx = barycentric.dx.x * (n1 - n0) + barycentric.dx.y * (n2 - n0);
    let dn_dy = barycentric.dy.x * (n1 - n0) + barycentric.dy.y * (n2 - n0);
    Derivatives3::new(normalized_derivative(n, dn_dx), normalized_derivative(n, dn_dy))
}

/// Derivative of the reflected direction `R = D - 2 dot(D, N) N` (Igehy):
/// `dR = dD - 2 (dot(D, N) dN + (dot(dD, N) + dot(D, dN)) N)`.
fn reflected_direction(d_direction: Vec3, direction: Vec3, normal: Vec3, d_normal: Vec3) -> Vec3 {
    let cosine = direction.dot(normal);
    d_direction - 2.0 * (cosine * d_normal + (d_direction.dot(normal) + direction.dot(d_normal)) * normal)
}

/// The differential of the ray reflected at a hit (Igehy): origin differentials kept (pass the
/// differential returned by [`transfer`]), direction differentials
/// `dR/dx = dD/dx - 2 (dot(D, N) dN/dx + (dot(dD/dx, N) + dot(D, dN/dx)) N)`, same for y.
/// `direction` and `normal` are unit; `d_normal` from [`normal_derivatives`] (zero for a flat surface).
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::{eye_ray_diff, eye_ray_direction, reflect_ray_diff, Derivatives3};
///
/// // A flat mirror facing a camera that looks down -Z reflects its rays into those of its mirror
/// // image, a camera with the same right and up vectors looking down +Z.
/// let (pixel, size, fov_y) = (Vec2::new(300.0, 200.0), Vec2::new(1920.0, 1080.0), 60f32.to_radians());
/// let diff = eye_ray_diff(pixel, size, fov_y, Vec3::X, Vec3::Y, Vec3::Z);
/// let direction = eye_ray_direction(pixel, size, fov_y, Vec3::X, Vec3::Y, Vec3::Z).normalize();
/// let flat = Derivatives3::default();
/// let reflected = reflect_ray_diff(diff, direction, Vec3::Z, flat);
/// let mirror_image = eye_ray_diff(pixel, size, fov_y, Vec3::X, Vec3::Y, Vec3::NEG_Z);
/// let error = (reflected.d_direction_dx - mirror_image.d_direction_dx).length();
/// assert!(error < 1e-6 * mirror_image.d_direction_dx.length());
/// ```
pub fn reflect_ray_diff(diff: RayDiff, direction: Vec3, normal: Vec3, d_normal: Derivatives3) -> RayDiff {
    RayDiff::new(
        diff.d_origin_dx,
        diff.d_origin_dy,
        reflected_direction(diff.d_direction_dx, direction, normal, d_normal.dx),
        reflected_direction(diff.d_direction_dy, direction, normal, d_normal.dy),
    )
}

/// Derivative of the refracted direction `T = eta D - mu N` (Igehy): with
/// `d(dot(D, N)) = dot(dD, N) + dot(D, dN)`, `dmu = rate * d(dot(D, N))` and
/// `dT = eta dD - (mu dN + dmu N)`.
fn refracted_direction(
    d_direction: Vec3,
    direction: Vec3,
    normal: Vec3,
    d_normal: Vec3,
    eta: f32,
    mu: f32,
    rate: f32,
) -> Vec3 {
    let d_cos = d_direction.dot(normal) + direction.dot(d_normal);
    eta * d_direction - (mu * d_normal + rate * d_cos * normal)
}

/// The differential of the ray refracted at a hit with relative index `eta = n_incident /
/// n_transmitted` (Igehy): `T = eta D - mu N` with `mu = eta dot(D, N) - dot(T, N)`,
/// `dot(T, N) = -sign(dot(D, N)) sqrt(1 - eta^2 (1 - dot(D, N)^2))` (sign(0) = -1; for the usual
/// `dot(D, N) < 0` this is GLSL's `refract(D, N, eta)`),
/// `dmu/dx = (eta - eta^2 dot(D, N) / dot(T, N)) d(dot(D, N))/dx` and
/// `dT/dx = eta dD/dx - (mu dN/dx + dmu/dx N)`, same for y. Origin differentials are kept.
///
/// Total internal reflection (`k = 1 - eta^2 (1 - dot(D, N)^2) < 0`) is reported in the flag, and
/// `diff` is then the reflected differential ([`reflect_ray_diff`]): the same derivative with
/// `eta = 1`, `mu = 2 dot(D, N)` and `rate = 2`, since `R = D - 2 dot(D, N) N` is `T` with those.
/// The shaders compute both sets and select one (no branch); the products with 1 and 2 are exact,
/// so the result is `reflect_ray_diff`'s bit for bit. In `dmu`, `dot(T, N)` is kept at least
/// `DIFF_MIN_COS` from 0 with its own sign, `-sign(dot(D, N))`, also at exactly the critical angle
/// (`k = 0`, where `dmu` diverges and `sqrt(k)` carries no sign).
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_diff::{refract_ray_diff, Derivatives3, RayDiff};
///
/// // Air to glass (eta = 1 / 1.5), flat surface with normal +Y, 30 degrees from the normal; the
/// // direction turns by 1 mrad per pixel in the plane of incidence.
/// let eta = 1.0 / 1.5;
/// let direction = Vec3::new(0.5, -(0.75f32.sqrt()), 0.0);
/// let turn = Vec3::new(0.75f32.sqrt(), 0.5, 0.0) * 1e-3;
/// let diff = RayDiff::new(Vec3::ZERO, Vec3::ZERO, turn, Vec3::ZERO);
/// let refracted = refract_ray_diff(diff, direction, Vec3::Y, Derivatives3::default(), eta);
/// assert!(!refracted.total_internal_reflection);
/// // Snell's law sin t = eta sin i turns di into dt = eta cos i / cos t di.
/// let sin_t = eta * 0.5;
/// let expected = 1e-3 * eta * 0.75f32.sqrt() / (1.0 - sin_t * sin_t).sqrt();
/// assert!((refracted.diff.d_direction_dx.length() - expected).abs() < 1e-5 * expected);
/// // From glass into air at 60 degrees, past the critical angle asin(1 / 1.5) = 41.8 degrees.
/// let inside = Vec3::new(0.75f32.sqrt(), -0.5, 0.0);
/// assert!(refract_ray_diff(diff, inside, Vec3::Y, Derivatives3::default(), 1.5).total_internal_reflection);
/// ```
pub fn refract_ray_diff(
    diff: RayDiff,
    direction: Vec3,
    normal: Vec3,
    d_normal: Derivatives3,
    eta: f32,
) -> RefractedRayDiff {
    let cosine = direction.dot(normal);
    let k = 1.0 - eta * eta * (1.0 - cosine * cosine);
    let total_internal_reflection = k < 0.0;
    let root = k.max(0.0).sqrt();
    let transmitted_cos = if cosine <= 0.0 { -root } else { root };
    let mu = eta * cosine - transmitted_cos;
    let clamped_root = root.max(DIFF_MIN_COS);
    let clamped_cos = if cosine <= 0.0 {
        -clamped_root
    } else {
        clamped_root
    };
    let rate = eta - eta * eta * cosine / clamped_cos;
    let (ratio, normal_scale, normal_rate) = if total_internal_reflection {
        (1.0, 2.0 * cosine, 2.0)
    } else {
        (eta, mu, rate)
    };
    let direction_x = refracted_direction(
        diff.d_direction_dx,
        direction,
        normal,
        d_normal.dx,
        ratio,
        normal_scale,
        normal_rate,
    );
    let direction_y = refracted_direction(
        diff.d_direction_dy,
        direction,
        normal,
        d_normal.dy,
        ratio,
        normal_scale,
        normal_rate,
    );
    RefractedRayDiff {
        diff: RayDiff::new(diff.d_origin_dx, diff.d_origin_dy, direction_x, direction_y),
        total_internal_reflection,
    }
}

// ---- G-buffer differentials (RTG Sec. 20.3.3) ----

/// Whether the G-buffer differential uses the backward (left / upper) neighbour (RTG Sec. 20.3.3):
/// when `|t(+1) - t(0)| > depth_epsilon` and `|t(-1) - t(0)| < |t(+1) - t(0)|`.
fn gbuffer_use_backward(
    center: GBufferSample,
    forward: GBufferSample,
    backward: GBufferSample,
    depth_epsilon: f32,
) -> bool {
    let forward_step = (forward.distance - center.distance).abs();
    let backward_step = (backward.distance - center.distance).abs();
    forward_step > depth_epsilon && backward_step < forward_step
}

/// Change of the G-buffer hit position from `start` to `end` (RTG Eq. 23):
/// `t(end) e(end) - t(start) e(start)`.
fn gbuffer_position_step(start: GBufferSample, end: GBufferSample) -> Vec3 {
    end.distance * end.eye_direction - start.distance * start.eye_direction
}

/// Change of the reflected eye direction from `start` to `end` (RTG Eq. 24):
/// `reflect(e(end), n(end)) - reflect(e(start), n(start))`, with `reflect(e, n) = e - 2 dot(n, e) n`.
fn gbuffer_direction_step(start: GBufferSample, end: GBufferSample) -> Vec3 {
    let reflected_end = end.eye_direction - 2.0 * end.normal.dot(end.eye_direction) * end.normal;
    let reflected_start = start.eye_direction - 2.0 * start.normal.dot(start.eye_direction) * start.normal;
    reflected_end - reflected_start
}

/// G-buffer ray differentials of the first reflected ray (RTG Eq. 23-24): along x,
/// `dO/dx = t(+1) e(+1) - t(0) e(0)` and `dD/dx = reflect(e(+1), n(+1)) - reflect(e(0), n(0))` from
/// the right neighbour; when `|t(+1) - t(0)| > depth_epsilon` and the left neighbour's distance step is
/// smaller, the left neighbour is used instead, sign-flipped (`t(0) e(0) - t(-1) e(-1)`, ...). The same
/// along y with the lower (forward) and upper (backward) neighbours. `e` are unit eye directions.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::{eye_ray_direction, gbuffer_ray_diff, GBufferSample};
///
/// // A camera at the origin looking down -Z (1920 x 1080, 60 degrees) sees the floor y = -1 ...
/// let (size, fov_y) = (Vec2::new(1920.0, 1080.0), 60f32.to_radians());
/// let floor = |x: f32, y: f32| {
///     let d = eye_ray_direction(Vec2::new(x, y), size, fov_y, Vec3::X, Vec3::Y, Vec3::Z);
///     GBufferSample { eye_direction: d.normalize(), distance: d.length() / -d.y, normal: Vec3::Y }
/// };
/// // ... but the right neighbour sees a wall 50 m away, across a depth edge.
/// let wall = GBufferSample { distance: 50.0, normal: Vec3::Z, ..floor(1201.0, 900.0) };
/// let (left, below, above) = (floor(1199.0, 900.0), floor(1200.0, 901.0), floor(1200.0, 899.0));
/// let diff = gbuffer_ray_diff(floor(1200.0, 900.0), wall, left, below, above, 0.1);
/// // The left neighbour is used. Along a row the floor hits are evenly spaced, so dO/dx is a
/// // hundredth of a 100-pixel step. Neighbouring f32 hits (about 3 m) differ by 3 mm: 1e-4 of
/// // that is rounding.
/// let hit = |x: f32| floor(x, 900.0).distance * floor(x, 900.0).eye_direction;
/// let step = (hit(1200.0) - hit(1100.0)) / 100.0;
/// assert!((diff.d_origin_dx - step).length() < 2e-4 * step.length());
/// ```
pub fn gbuffer_ray_diff(
    center: GBufferSample,
    right: GBufferSample,
    left: GBufferSample,
    below: GBufferSample,
    above: GBufferSample,
    depth_epsilon: f32,
) -> RayDiff {
    let (start_x, end_x) = if gbuffer_use_backward(center, right, left, depth_epsilon) {
        (left, center)
    } else {
        (center, right)
    };
    let (start_y, end_y) = if gbuffer_use_backward(center, below, above, depth_epsilon) {
        (above, center)
    } else {
        (center, below)
    };
    RayDiff::new(
        gbuffer_position_step(start_x, end_x),
        gbuffer_position_step(start_y, end_y),
        gbuffer_direction_step(start_x, end_x),
        gbuffer_direction_step(start_y, end_y),
    )
}

/// Offset between the hit of the neighbour ray `rd_neighbour` on the tangent plane and the hit at
/// distance `t` (Quilez, `calcDpDxy`): `t * (rd_neighbour * dot(rd, n) / dot(rd_neighbour, n) - rd)`,
/// with `dot(rd_neighbour, n)` clamped away from 0 to `|cos| >= DIFF_MIN_COS`.
fn tangent_plane_offset(rd: Vec3, rd_neighbour: Vec3, t: f32, normal: Vec3) -> Vec3 {
    let cosine = clamp_away_from_zero(rd_neighbour.dot(normal), DIFF_MIN_COS);
    t * (rd_neighbour * (rd.dot(normal) / cosine) - rd)
}

/// Position differentials of a raymarched hit from the neighbour rays (Quilez): the rays through the
/// right (`rdx`) and lower (`rdy`) neighbour pixels, all from the same origin, are intersected with the
/// tangent plane at the hit `ro + t rd` with unit normal `normal`:
/// `dp/dx = t (rdx dot(rd, n) / dot(rdx, n) - rd)`, same for y.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::{eye_ray_direction, tangent_plane_offsets};
///
/// // A raymarcher's camera at the origin looking down -Z (1920 x 1080, 60 degrees) finds the floor
/// // y = -1 (normal +Y) along the ray rd at distance t.
/// let (size, fov_y) = (Vec2::new(1920.0, 1080.0), 60f32.to_radians());
/// let eye = |x: f32, y: f32| eye_ray_direction(Vec2::new(x, y), size, fov_y, Vec3::X, Vec3::Y, Vec3::Z).normalize();
/// let (rd, rdx, rdy) = (eye(1200.0, 900.0), eye(1201.0, 900.0), eye(1200.0, 901.0));
/// let offsets = tangent_plane_offsets(rd, rdx, rdy, 1.0 / -rd.y, Vec3::Y);
/// // On a flat floor the tangent plane is the floor: the offsets are the neighbour rays' own floor
/// // hits, computed in f64, minus the hit. The f32 offsets, differences of hits 3 m away, hold
/// // about 3e-7 of rounding: 1e-4 of a 3 mm offset.
/// let floor_hit = |d: Vec3| d.as_dvec3() / -f64::from(d.y);
/// let exact = floor_hit(rdx) - floor_hit(rd);
/// assert!((offsets.dx.as_dvec3() - exact).length() < 2e-4 * exact.length());
/// let exact = floor_hit(rdy) - floor_hit(rd);
/// assert!((offsets.dy.as_dvec3() - exact).length() < 2e-4 * exact.length());
/// ```
pub fn tangent_plane_offsets(rd: Vec3, rdx: Vec3, rdy: Vec3, t: f32, normal: Vec3) -> Derivatives3 {
    Derivatives3::new(
        tangent_plane_offset(rd, rdx, t, normal),
        tangent_plane_offset(rd, rdy, t, normal),
    )
}

// ---- Planar and triplanar mapping (Quilez) ----

/// Texture gradients of the planar mapping `uv = p.xz * scale` (Quilez): `duv/dx = dp/dx.xz * scale`,
/// same for y.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::{planar_mapping_gradients, Derivatives3};
///
/// // uv = p.xz * scale on a slope: the height change does not move the texture. A texture 4 m wide
/// // and 2 m deep (scale (0.25, 0.5)) moves by 0.04 / 4 = 0.01 and 0.02 / 2 = 0.01 UV units.
/// let d_position = Derivatives3::new(Vec3::new(0.04, 0.03, 0.0), Vec3::new(0.0, 0.01, 0.02));
/// let uv = planar_mapping_gradients(d_position, Vec2::new(0.25, 0.5));
/// assert!((uv.dx - Vec2::new(0.01, 0.0)).length() < 1e-9);
/// assert!((uv.dy - Vec2::new(0.0, 0.01)).length() < 1e-9);
/// ```
pub fn planar_mapping_gradients(d_position: Derivatives3, scale: Vec2) -> Derivatives2 {
    Derivatives2::new(d_position.dx.xz() * scale, d_position.dy.xz() * scale)
}

/// Triplanar blend weights (Quilez): `m = |n|^k / (m.x + m.y + m.z)` with `k = sharpness` clamped to
/// `[0, DIFF_MAX_SHARPNESS]`. The weights of the yz, zx and xy projections, summing to 1. The
/// weights do not depend on `|n|`, so `|n|` is first divided by its largest component (at least
/// `DIFF_MIN_MAGNITUDE`): `|n|^k` can then neither overflow nor underflow to all zeros, for any
/// finite normal; each component is clamped to `>= DIFF_MIN_MAGNITUDE` (so `0^0` never occurs) and
/// the sum to `>= DIFF_MIN_MAGNITUDE`.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_diff::triplanar_weights;
///
/// // For a unit normal and sharpness 2 the weights are the squared components, which sum to 1.
/// let weights = triplanar_weights(Vec3::new(0.6, 0.8, 0.0), 2.0);
/// assert!((weights - Vec3::new(0.36, 0.64, 0.0)).length() < 1e-6);
/// // A normal along an axis gets that axis's projection alone, at any sharpness.
/// assert_eq!(triplanar_weights(Vec3::NEG_Y, 8.0), Vec3::Y);
/// ```
pub fn triplanar_weights(normal: Vec3, sharpness: f32) -> Vec3 {
    let k = sharpness.clamp(0.0, DIFF_MAX_SHARPNESS);
    let size = normal.abs();
    let largest = size.x.max(size.y).max(size.z.max(DIFF_MIN_MAGNITUDE));
    let m = (size / largest).max(Vec3::splat(DIFF_MIN_MAGNITUDE)).powf(k);
    m / (m.x + m.y + m.z).max(DIFF_MIN_MAGNITUDE)
}

/// Gradients of the three triplanar projections `p.yz * scale`, `p.zx * scale`, `p.xy * scale`
/// (Quilez): each projection is sampled with its own two components of the position differentials.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::{triplanar_gradients, Derivatives3};
///
/// // A texture every 2 m (scale 0.5). The projection along z samples p.xy: it sees the x and y
/// // steps and not the z step; the projection along x samples p.yz.
/// let d_position = Derivatives3::new(Vec3::new(0.02, 0.04, 0.0), Vec3::new(0.0, 0.0, 0.06));
/// let gradients = triplanar_gradients(d_position, 0.5);
/// assert!((gradients.xy.dx - Vec2::new(0.01, 0.02)).length() < 1e-9);
/// assert_eq!(gradients.xy.dy, Vec2::ZERO);
/// assert!((gradients.yz.dy - Vec2::new(0.0, 0.03)).length() < 1e-9);
/// ```
pub fn triplanar_gradients(d_position: Derivatives3, scale: f32) -> TriplanarGradients {
    let (dx, dy) = (d_position.dx * scale, d_position.dy * scale);
    TriplanarGradients {
        yz: Derivatives2::new(dx.yz(), dy.yz()),
        zx: Derivatives2::new(dx.zx(), dy.zx()),
        xy: Derivatives2::new(dx.xy(), dy.xy()),
    }
}

// ---- Re-intersection of the neighbour rays (RTG Eq. 13) ----

/// `|v|` measured as `m * |v / m|` with `m` the largest `|component|` (at least `DIFF_MIN_MAGNITUDE`),
/// so that squaring cannot overflow.
fn scaled_length(v: Vec3) -> f32 {
    let m = v.x.abs().max(v.y.abs()).max(v.z.abs().max(DIFF_MIN_MAGNITUDE));
    m * (v / m).length()
}

/// Barycentrics `(w, u, v)` of the point where the ray `origin + s * direction` meets the unbounded
/// plane of the triangle (RTG Eq. 13 with `g = d`; Cramer's rule): with `e1 = p1 - p0`,
/// `e2 = p2 - p0`, `k = dot(cross(e1, e2), d)` and `s0 = origin - p0`:
/// `u = dot(cross(e2, d), s0) / k`, `v = dot(cross(d, e1), s0) / k`, `w = 1 - u - v`.
///
/// The parallel case (the wireframe tutorial's intersection divides by zero there) is clamped: `k`
/// to `|k| >= DIFF_MIN_MAGNITUDE`, keeping its sign, and `u`, `v` to
/// `[-DIFF_MAX_VALUE, DIFF_MAX_VALUE]`. The hit may lie behind the origin or outside the triangle.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_diff::intersect_triangle_plane;
///
/// // A right triangle in the plane z = 0 with legs of 2 along x and y: u = x / 2, v = y / 2.
/// let (p0, p1, p2) = (Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 2.0, 0.0));
/// // The ray from (0.5, 0.5, 3) along (0.1, 0.2, -1) reaches z = 0 at (0.8, 1.1, 0).
/// let b = intersect_triangle_plane(Vec3::new(0.5, 0.5, 3.0), Vec3::new(0.1, 0.2, -1.0), p0, p1, p2);
/// assert!((b - Vec3::new(1.0 - 0.4 - 0.55, 0.4, 0.55)).length() < 1e-6);
/// ```
pub fn intersect_triangle_plane(origin: Vec3, direction: Vec3, p0: Vec3, p1: Vec3, p2: Vec3) -> Vec3 {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let s0 = origin - p0;
    let k = clamp_away_from_zero(e1.cross(e2).dot(direction), DIFF_MIN_MAGNITUDE);
    let limit = Vec2::splat(DIFF_MAX_VALUE);
    let uv = (Vec2::new(e2.cross(direction).dot(s0), direction.cross(e1).dot(s0)) / k).clamp(-limit, limit);
    Vec3::new(1.0 - uv.x - uv.y, uv.x, uv.y)
}

/// `(matrix * (point, 1)).xyz`: a point through the 4x3 part of `matrix` (its fourth row is ignored).
fn transform_point(matrix: Mat4, point: Vec3) -> Vec3 {
    (matrix * point.extend(1.0)).xyz()
}

/// Signed barycentric differences to the neighbour pixels by re-intersection (wireframe tutorial,
/// `computeDerivative` and "Going Further"): the world ray origin `O` is moved by each neighbour
/// direction ([`pixel_directions`]); `O` and both moved points go to object space with
/// `world_to_object`; each neighbour ray (object origin, moved point - object origin) is intersected
/// with the unbounded plane of the object-space triangle ([`intersect_triangle_plane`]); the result is
/// `(b_x - b, b_y - b)` with `b = hit_barycentrics = (w, u, v)`.
///
/// `world_to_object` is the 4x3 world-to-object matrix passed as a `mat4` whose fourth row is ignored
/// (GLSL `mat4(gl_WorldToObjectEXT)`); the object ray origin is computed from it. In f32 the moved
/// points lose the low bits of `O + direction` when `|O|` is large; see [`crate::ray_diff_f64`].
///
/// # Examples
///
/// ```
/// use glam::{Mat4, Vec3};
/// use ray_footprint::ray_diff::barycentric_offsets;
///
/// // An instance placed at (1, 0, -1): in object space its floor triangle has legs of 4 m along x and
/// // -z, so u = x / 4 and v = -z / 4.
/// let world_to_object = Mat4::from_translation(Vec3::new(-1.0, 0.0, 1.0));
/// let (p0, p1, p2) = (Vec3::ZERO, Vec3::new(4.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -4.0));
/// // A ray from 2 m above the object point (1, 0, -1) goes straight down: (w, u, v) = (0.5, 0.25, 0.25).
/// let origin = Vec3::new(2.0, 2.0, -2.0);
/// let hit = Vec3::new(0.5, 0.25, 0.25);
/// // The neighbour rays lean 1 mrad towards +x and +z and land 2 mm away: u grows by 0.002 / 4 and
/// // v drops by as much. In f32, O + direction rounds the 1e-3 lean by up to 1.2e-7 (half the
/// // f32 spacing at 2), 1.2e-4 of it: up to 6e-8 of each 0.0005, twice (moving, transforming).
/// let right = Vec3::new(1e-3, -1.0, 0.0).normalize();
/// let below = Vec3::new(0.0, -1.0, 1e-3).normalize();
/// let offsets = barycentric_offsets(world_to_object, origin, p0, p1, p2, right, below, hit);
/// assert!((offsets.dx - Vec3::new(-0.0005, 0.0005, 0.0)).length() < 2e-7);
/// assert!((offsets.dy - Vec3::new(0.0005, 0.0, -0.0005)).length() < 2e-7);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn barycentric_offsets(
    world_to_object: Mat4,
    world_origin: Vec3,
    p0: Vec3,
    p1: Vec3,
    p2: Vec3,
    direction_x: Vec3,
    direction_y: Vec3,
    hit_barycentrics: Vec3,
) -> Derivatives3 {
    let origin = transform_point(world_to_object, world_origin);
    let object_x = transform_point(world_to_object, world_origin + direction_x) - origin;
    let object_y = transform_point(world_to_object, world_origin + direction_y) - origin;
    Derivatives3::new(
        intersect_triangle_plane(origin, object_x, p0, p1, p2) - hit_barycentrics,
        intersect_triangle_plane(origin, object_y, p0, p1, p2) - hit_barycentrics,
    )
}

/// Per-pixel barycentric deltas by re-intersection, the ray-tracing analogue of `fwidth(barycentrics)`
/// (wireframe tutorial, `computeDerivative`): `|b_x - b| + |b_y - b|` per component, from
/// [`barycentric_offsets`] (same arguments and clamps).
///
/// # Examples
///
/// ```
/// use glam::{Mat4, Vec3};
/// use ray_footprint::ray_diff::barycentric_deltas;
///
/// // The floor triangle with legs of 4 m along x and -z (u = x / 4, v = -z / 4), seen from 2 m
/// // above its point (1, 0, -1); the neighbour rays lean 1 mrad towards +x and +z and land 2 mm
/// // away: |du| = |dv| = 0.0005 for one step each, and w changes by both. The tolerance is the
/// // rounding of O + direction, as in `barycentric_offsets`.
/// let (p0, p1, p2) = (Vec3::ZERO, Vec3::new(4.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -4.0));
/// let right = Vec3::new(1e-3, -1.0, 0.0).normalize();
/// let below = Vec3::new(0.0, -1.0, 1e-3).normalize();
/// let origin = Vec3::new(1.0, 2.0, -1.0);
/// let hit = Vec3::new(0.5, 0.25, 0.25);
/// let deltas = barycentric_deltas(Mat4::IDENTITY, origin, p0, p1, p2, right, below, hit);
/// assert!((deltas - Vec3::new(0.001, 0.0005, 0.0005)).length() < 2e-7);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn barycentric_deltas(
    world_to_object: Mat4,
    world_origin: Vec3,
    p0: Vec3,
    p1: Vec3,
    p2: Vec3,
    direction_x: Vec3,
    direction_y: Vec3,
    hit_barycentrics: Vec3,
) -> Vec3 {
    let offsets = barycentric_offsets(
        world_to_object,
        world_origin,
        p0,
        p1,
        p2,
        direction_x,
        direction_y,
        hit_barycentrics,
    );
    offsets.dx.abs() + offsets.dy.abs()
}

/// Anisotropic UV gradients of a primary hit from the signed barycentric differences (wireframe
/// tutorial, "Going Further"): `ddx_uv = sum_i (b_x - b)_i * uv_i`, same for y, with `b = (w, u, v)`
/// matching `(uv0, uv1, uv2)`.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::{uv_gradients_from_offsets, Derivatives3};
///
/// // The floor triangle with legs of 4 m, its texture spanning them (UVs (0, 0), (1, 0), (0, 1)):
/// // neighbour hits 2 mm away along x and +z are 0.002 / 4 UV units away.
/// let offsets = Derivatives3::new(Vec3::new(-0.0005, 0.0005, 0.0), Vec3::new(0.0005, 0.0, -0.0005));
/// let gradients = uv_gradients_from_offsets(offsets, Vec2::ZERO, Vec2::X, Vec2::Y);
/// assert!((gradients.dx - Vec2::new(0.0005, 0.0)).length() < 1e-9);
/// assert!((gradients.dy - Vec2::new(0.0, -0.0005)).length() < 1e-9);
/// ```
pub fn uv_gradients_from_offsets(offsets: Derivatives3, uv0: Vec2, uv1: Vec2, uv2: Vec2) -> Derivatives2 {
    Derivatives2::new(
        offsets.dx.x * uv0 + offsets.dx.y * uv1 + offsets.dx.z * uv2,
        offsets.dy.x * uv0 + offsets.dy.y * uv1 + offsets.dy.z * uv2,
    )
}

// ---- Ray cones and ray differentials together ----

/// Closed-form barycentric deltas from a ray cone, without re-intersection (as in nvpro's glTF
/// renderer): `delta_i = |world_footprint| * |edge opposite vertex i| / |cross(e1, e2)|`, i.e. the
/// footprint divided by the distance from vertex i to its opposite edge. The edges are
/// `p2 - p1`, `p2 - p0`, `p1 - p0` for `(w, u, v)`; `|cross|` is clamped to `>= DIFF_MIN_MAGNITUDE` and
/// the deltas to `<= DIFF_MAX_VALUE`. `world_footprint` is the slant-corrected cone footprint.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_diff::cone_barycentric_deltas;
///
/// // A 3-4-5 right triangle with the right angle at p0: the heights onto the edges opposite p0, p1
/// // and p2 are 12 / 5 (onto the hypotenuse), 3 and 4 (the legs).
/// let (p0, p1, p2) = (Vec3::ZERO, Vec3::new(3.0, 0.0, 0.0), Vec3::new(0.0, 4.0, 0.0));
/// let deltas = cone_barycentric_deltas(0.012, p0, p1, p2);
/// assert!((deltas - Vec3::new(0.012 / 2.4, 0.012 / 3.0, 0.012 / 4.0)).length() < 1e-6 * 0.005);
/// ```
pub fn cone_barycentric_deltas(world_footprint: f32, p0: Vec3, p1: Vec3, p2: Vec3) -> Vec3 {
    let area2 = scaled_length((p1 - p0).cross(p2 - p0)).max(DIFF_MIN_MAGNITUDE);
    let edges = Vec3::new(
        scaled_length(p2 - p1),
        scaled_length(p2 - p0),
        scaled_length(p1 - p0),
    );
    (world_footprint.abs() * edges / area2).min(Vec3::splat(DIFF_MAX_VALUE))
}

/// Smallest sine of the angle between a direction and a normal at which their cross product still
/// gives the footprint's minor axis ([`anisotropic_cone_axes`]); nearer to normal incidence the
/// footprint is a circle to within 5e-9 and a fixed tangent is used instead.
pub const DIFF_MIN_SINE: f32 = 1.0e-4;

/// A unit vector perpendicular to the unit vector `n` (Duff et al., "Building an Orthonormal Basis,
/// Revisited", JCGT 6(1), 2017, the first tangent): with `s = 1` for `n.z >= 0` and -1 otherwise,
/// `a = -1 / (s + n.z)`: `(1 + s n.x^2 a, s n.x n.y a, -s n.x)`. Defined for every finite `n`
/// (`|s + n.z| >= 1`).
fn orthonormal_tangent(n: Vec3) -> Vec3 {
    let sign_z = if n.z >= 0.0 { 1.0 } else { -1.0 };
    let a = -1.0 / (sign_z + n.z);
    Vec3::new(
        1.0 + sign_z * n.x * n.x * a,
        sign_z * n.x * n.y * a,
        -sign_z * n.x,
    )
}

/// The elliptical footprint of a ray cone on a surface, as the two world-space axes to pass as
/// position differentials (JCGT 2021, its anisotropic filter, as Falcor's
/// `computeAnisotropicEllipseAxes`): the cone is taken as a cylinder of diameter `|width|` (its
/// width at the hit) around the unit direction `d`, cut by the plane with unit normal `n`. The
/// minor axis is perpendicular to the ray and the normal, along `m = normalize(cross(n, d))`, the
/// major one along the direction projected onto the plane, `cross(m, n)`:
/// `dx = cross(m, n) * |width| / max(|dot(n, d)|, DIFF_MIN_COS)`, `dy = m * |width|`.
///
/// This is the paper's `r / |a - dot(d, a) d|` scaling with the errata's factor 2 applied (JCGT
/// 2021 errata: `SampleGrad(2 g1, 2 g2)`; Falcor passes the width where its parameter says radius):
/// at normal incidence both axes have the isotropic cone's length `|width|`, and the major axis grows
/// as `1 / |cos|` towards grazing. It is also the OptiX Toolkit's
/// `projectToRayDifferentialsOnSurface` without its anisotropy cap of 16. Within `DIFF_MIN_SINE` of
/// normal incidence (`|cross(n, d)| < DIFF_MIN_SINE`), `m` is `cross(n, u)` for a fixed tangent `u` of
/// `n` (Duff et al. 2017). Both axes are built by cross products with `n`, so they lie in the plane
/// to rounding however close to normal incidence.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use ray_footprint::ray_diff::anisotropic_cone_axes;
///
/// // A cone 1 cm wide meets the floor 60 degrees from the normal: a cylinder cut at that angle is an
/// // ellipse with axes 1 cm (across the ray) and 1 cm / cos(60°) = 2 cm (along it), in the floor.
/// let angle = 60f32.to_radians();
/// let direction = Vec3::new(angle.sin(), -angle.cos(), 0.0);
/// let axes = anisotropic_cone_axes(0.01, Vec3::Y, direction);
/// assert!((axes.dx.length() - 0.02).abs() < 1e-8);
/// assert!((axes.dy.length() - 0.01).abs() < 1e-8);
/// assert!(axes.dx.y.abs() < 1e-9 && axes.dy.y.abs() < 1e-9);
/// ```
pub fn anisotropic_cone_axes(width: f32, normal: Vec3, direction: Vec3) -> Derivatives3 {
    let across = normal.cross(direction);
    let length2 = across.dot(across);
    let minor = if length2 < DIFF_MIN_SINE * DIFF_MIN_SINE {
        normal.cross(orthonormal_tangent(normal))
    } else {
        across / length2.sqrt()
    };
    let size = width.abs();
    Derivatives3::new(
        minor.cross(normal) * (size / normal.dot(direction).abs().max(DIFF_MIN_COS)),
        minor * size,
    )
}

/// Unit normal of a triangle: `cross(p1 - p0, p2 - p0) / |cross|`, the length measured as
/// [`scaled_length`] and clamped to `>= DIFF_MIN_MAGNITUDE` (a zero-area triangle gives 0).
fn triangle_unit_normal(p0: Vec3, p1: Vec3, p2: Vec3) -> Vec3 {
    let area_normal = (p1 - p0).cross(p2 - p0);
    area_normal / scaled_length(area_normal).max(DIFF_MIN_MAGNITUDE)
}

/// Anisotropic `SampleGrad` / `textureGrad` gradients (UV units) of a ray cone hitting a triangle
/// (JCGT 2021, its anisotropic filter; Falcor's `computeAnisotropicEllipseAxes`, with the errata's
/// factor 2): the texture coordinates at `hit + axis` minus those at the hit, for the two axes of
/// [`anisotropic_cone_axes`] in the triangle's plane (normal `n = normalize(cross(p1 - p0, p2 - p0))`).
/// The axes' barycentric changes are [`barycentric_derivatives`] of a differential with origin
/// changes `(dx, dy)` along `n` (`t = 0`), and the gradients are [`texture_derivatives`] of those.
///
/// `width` is the cone's width at the hit, `direction` the unit ray direction. At normal incidence
/// both gradients have the isotropic cone's length ([`crate::ray_cone::texture_gradient`] of the
/// footprint) for a texture mapped without shear. A zero-area triangle gives zero gradients; the
/// clamps are those of the functions named.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::anisotropic_cone_gradients;
///
/// // The floor triangle of a 2 m tile, its texture spanning it once (0.5 UV units per metre), hit
/// // 60 degrees from the normal in the x-y plane by a cone 1 cm wide: the footprint ellipse has axes
/// // 2 cm along x (u) and 1 cm along z (v), half as many UV units.
/// let angle = 60f32.to_radians();
/// let direction = Vec3::new(angle.sin(), -angle.cos(), 0.0);
/// let (p0, p1, p2) = (Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -2.0));
/// let g = anisotropic_cone_gradients(0.01, direction, p0, p1, p2, Vec2::ZERO, Vec2::X, Vec2::Y);
/// assert!((g.dx.abs() - Vec2::new(0.01, 0.0)).length() < 1e-8);
/// assert!((g.dy.abs() - Vec2::new(0.0, 0.005)).length() < 1e-8);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn anisotropic_cone_gradients(
    width: f32,
    direction: Vec3,
    p0: Vec3,
    p1: Vec3,
    p2: Vec3,
    uv0: Vec2,
    uv1: Vec2,
    uv2: Vec2,
) -> Derivatives2 {
    let normal = triangle_unit_normal(p0, p1, p2);
    let axes = anisotropic_cone_axes(width, normal, direction);
    let offsets = RayDiff::new(axes.dx, axes.dy, Vec3::ZERO, Vec3::ZERO);
    let barycentric = barycentric_derivatives(offsets, normal, 0.0, p0, p1, p2);
    texture_derivatives(barycentric, uv0, uv1, uv2)
}

/// The isotropic ray differential of a ray cone `(width, spread_angle)` around the unit direction
/// `d` (a conversion derived for this crate; neither Falcor nor the OptiX Toolkit has one): with
/// `u` a unit tangent of `d` (Duff et al. 2017) and `v = cross(d, u)`,
/// `dO/dx = width u`, `dO/dy = width v`, `dD/dx = spread_angle u`, `dD/dy = spread_angle v`. A step
/// of one pixel moves the ray by the cone's width and turns it by the cone's angle, in two
/// perpendicular directions. [`cone_from_ray_diff`] converts back; [`transfer`] of the result is the
/// differential of [`crate::ray_cone::propagate`]'s cone.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::{ray_diff_from_cone, transfer};
///
/// // A pixel's cone from the eye (width 0, spread 1 mrad) along -Z, transferred 10 m to a wall facing
/// // it: the hit moves by the cone's width there, 1 cm, in each of two perpendicular directions.
/// let diff = ray_diff_from_cone(Vec2::new(0.0, 1e-3), Vec3::NEG_Z);
/// let hit = transfer(diff, Vec3::NEG_Z, 10.0, Vec3::Z);
/// assert!((hit.d_origin_dx.length() - 0.01).abs() < 1e-6 * 0.01);
/// assert!((hit.d_origin_dy.length() - 0.01).abs() < 1e-6 * 0.01);
/// assert!(hit.d_origin_dx.dot(hit.d_origin_dy).abs() < 1e-12);
/// ```
pub fn ray_diff_from_cone(cone: Vec2, direction: Vec3) -> RayDiff {
    let u = orthonormal_tangent(direction);
    let v = direction.cross(u);
    RayDiff::new(cone.x * u, cone.x * v, cone.y * u, cone.y * v)
}

/// `(width, spread)` of one axis of a differential: the lengths of the origin and direction changes
/// across the unit direction `d` (`v - dot(v, d) d`, measured as [`scaled_length`]), the spread
/// negative when the two point apart (`dot < 0`: the rays converge).
fn transverse_cone(d_origin: Vec3, d_direction: Vec3, direction: Vec3) -> Vec2 {
    let origin = d_origin - d_origin.dot(direction) * direction;
    let turn = d_direction - d_direction.dot(direction) * direction;
    let sign_turn = if origin.dot(turn) >= 0.0 { 1.0 } else { -1.0 };
    Vec2::new(scaled_length(origin), sign_turn * scaled_length(turn))
}

/// The ray cone `(width, spread_angle)` of a ray differential around the unit direction `d`: the
/// mean of its two axes' transverse widths and signed spreads (`transverse_cone`: the lengths of
/// `dO` and `dD` across `d`, the spread negative where the origin and direction changes point
/// apart). Converting [`ray_diff_from_cone`]'s differential back returns the cone with a
/// non-negative width (`(w, s)` and `(-w, -s)` describe the same cone), and since both steps are
/// linear in each axis, converting commutes with propagation ([`transfer`] versus
/// [`crate::ray_cone::propagate`]) for every differential whose origin and direction changes are
/// parallel across `d` in each axis. For a pinhole eye ray (`dO = 0`) this is the pixel's mean
/// angular size.
///
/// # Examples
///
/// ```
/// use glam::{Vec2, Vec3};
/// use ray_footprint::ray_diff::{cone_from_ray_diff, eye_ray_diff, ray_diff_from_cone};
///
/// // The eye ray at the centre of a 1920 x 1080, 60-degree image, along -Z: width 0, and a pixel's
/// // angle 2 tan(30°) / 1080 both ways.
/// let (size, fov_y) = (Vec2::new(1920.0, 1080.0), 60f32.to_radians());
/// let diff = eye_ray_diff(Vec2::new(959.5, 539.5), size, fov_y, Vec3::X, Vec3::Y, Vec3::Z);
/// let cone = cone_from_ray_diff(diff, Vec3::NEG_Z);
/// let expected = 2.0 / (3f32.sqrt() * 1080.0);
/// assert_eq!(cone.x, 0.0);
/// assert!((cone.y - expected).abs() < 1e-6 * expected);
/// // A converging cone survives the round trip through a differential.
/// let direction = Vec3::new(0.0, 0.6, -0.8);
/// let back = cone_from_ray_diff(ray_diff_from_cone(Vec2::new(0.02, -0.001), direction), direction);
/// assert!((back - Vec2::new(0.02, -0.001)).length() < 1e-8);
/// ```
pub fn cone_from_ray_diff(diff: RayDiff, direction: Vec3) -> Vec2 {
    let x = transverse_cone(diff.d_origin_dx, diff.d_direction_dx, direction);
    let y = transverse_cone(diff.d_origin_dy, diff.d_direction_dy, direction);
    0.5 * (x + y)
}
