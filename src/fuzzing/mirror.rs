//! `cpu_mirror`: every public function of the Rust mirror modules on arbitrary `f32` inputs.
//!
//! Each input is evaluated twice by every function, through a [`Draw`] that hands out the input's
//! words as arguments:
//!
//! - [`Mode::Raw`]: the words' bits as they are (NaN, infinities, subnormals, anything). Property:
//!   no panic; for the wireframe module, whose documentation promises it for every finite input, a
//!   finite coverage in `[0, 1]` whenever every argument is finite.
//! - [`Mode::Domain`]: the same words mapped into the documented domain (the README's Conventions,
//!   `shader_proptest::strategy`): a float becomes [`into_domain`] of itself (NaN to 0, magnitudes below
//!   1e-12 to 0, above 1e12 to 1e12, sign kept); a unit-vector argument is the normalized vector of
//!   three such floats (+Z when they are all 0); an angle is clamped to `[-3.2, 3.2]` radians; a
//!   camera-to-world matrix is a rotation plus a translation; a world-to-object matrix is a rotation, a
//!   uniform scale in `[1e-3, 1e3]` and a translation up to 1e9, with world ray origins up to 1e9 (the
//!   agreement suite's ranges, which keep object-space values within 1e12). Properties: every output
//!   is finite, and each function's documented clamps hold (ranges listed next to each call).

use super::Words;
use crate::ray_cone::{self as rc, PackedRayCone, RayCone, RefractedRayCone};
use crate::ray_diff::{
    self as rd, Derivatives2, Derivatives3, GBufferSample, NeighbourDirections, RayDiff, RefractedRayDiff,
    TriplanarGradients,
};
use crate::ray_diff_f64::{self as rd64, BarycentricOffsets};
use crate::registry::{registry, Registered};
use crate::shaders::Module;
use crate::wireframe::{self as wf, WireframeSettings, WireframeSettingsIo};
use glam::{Mat4, Quat, Vec2, Vec3, Vec3Swizzles};

/// Smallest non-zero magnitude of the documented domain (`gpu::strategy::TINY`).
pub const DOMAIN_MIN: f32 = 1.0e-12;
/// Largest magnitude of the documented domain (`gpu::strategy::HUGE`).
pub const DOMAIN_MAX: f32 = 1.0e12;
/// Largest world ray origin and world-to-object translation (the agreement suite's range).
pub const WORLD_MAX: f32 = 1.0e9;

/// How a [`Draw`] turns words into arguments.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// The bits as they are.
    Raw,
    /// Mapped into the documented domain.
    Domain,
}

/// `x` mapped into the documented domain: NaN to 0, `|x| < 1e-12` to 0, `|x| > 1e12` (infinities
/// included) to `1e12`, the sign kept.
pub fn into_domain(x: f32) -> f32 {
    if x.is_nan() || x.abs() < DOMAIN_MIN {
        0.0f32.copysign(x)
    } else {
        x.clamp(-DOMAIN_MAX, DOMAIN_MAX)
    }
}

/// Arguments drawn from an input's words, and the violated range checks.
pub struct Draw<'a> {
    words: Words<'a>,
    mode: Mode,
    finite: bool,
    violations: Vec<String>,
}

impl<'a> Draw<'a> {
    /// Arguments from `data`'s words in `mode`.
    pub fn new(data: &'a [u8], mode: Mode) -> Self {
        Draw {
            words: Words::new(data),
            mode,
            finite: true,
            violations: Vec::new(),
        }
    }

    fn raw(&mut self) -> f32 {
        let x = self.words.f32();
        self.finite &= x.is_finite();
        x
    }

    fn domain(&self) -> bool {
        self.mode == Mode::Domain
    }

    /// A float anywhere in the domain.
    pub fn scalar(&mut self) -> f32 {
        let x = self.raw();
        if self.domain() {
            into_domain(x)
        } else {
            x
        }
    }

    /// A non-negative distance.
    pub fn distance(&mut self) -> f32 {
        let x = self.scalar();
        if self.domain() {
            x.abs()
        } else {
            x
        }
    }

    /// An angle in radians.
    pub fn angle(&mut self) -> f32 {
        let x = self.scalar();
        if self.domain() {
            x.clamp(-3.2, 3.2)
        } else {
            x
        }
    }

    /// A float clamped to `[-limit, limit]` in the domain.
    fn bounded(&mut self, limit: f32) -> f32 {
        let x = self.scalar();
        if self.domain() {
            x.clamp(-limit, limit)
        } else {
            x
        }
    }

    /// An `i32` from the word's bits (every value is in the domain).
    pub fn int(&mut self) -> i32 {
        self.words.u32() as i32
    }

    /// A vector of [`Draw::scalar`]s.
    pub fn vec2(&mut self) -> Vec2 {
        Vec2::new(self.scalar(), self.scalar())
    }

    /// A vector of [`Draw::scalar`]s.
    pub fn vec3(&mut self) -> Vec3 {
        Vec3::new(self.scalar(), self.scalar(), self.scalar())
    }

    /// A unit vector in the domain (normalized, +Z for zero).
    pub fn unit(&mut self) -> Vec3 {
        let v = self.vec3();
        if self.domain() {
            v.try_normalize().unwrap_or(Vec3::Z)
        } else {
            v
        }
    }

    /// A matrix of [`Draw::scalar`]s.
    pub fn mat4(&mut self) -> Mat4 {
        Mat4::from_cols_array(&std::array::from_fn(|_| self.scalar()))
    }

    fn rotation(&mut self) -> Quat {
        let (axis, angle) = (self.unit(), self.angle());
        Quat::from_axis_angle(axis, angle)
    }

    /// A camera-to-world matrix: rotation and translation in the domain.
    pub fn rigid(&mut self) -> Mat4 {
        if !self.domain() {
            return self.mat4();
        }
        let rotation = self.rotation();
        Mat4::from_rotation_translation(rotation, self.vec3())
    }

    /// A world-to-object matrix in the domain: rotation, scale `10^[-3, 3]`, translation up to 1e9.
    pub fn world_to_object(&mut self) -> Mat4 {
        if !self.domain() {
            return self.mat4();
        }
        let rotation = self.rotation();
        let scale = 10f32.powf(self.bounded(3.0));
        let translation = self.world_point();
        Mat4::from_scale_rotation_translation(Vec3::splat(scale), rotation, translation)
    }

    /// A world-space point up to 1e9 in the domain.
    pub fn world_point(&mut self) -> Vec3 {
        Vec3::new(
            self.bounded(WORLD_MAX),
            self.bounded(WORLD_MAX),
            self.bounded(WORLD_MAX),
        )
    }

    /// A ray cone.
    pub fn cone(&mut self) -> RayCone {
        RayCone {
            width: self.scalar(),
            spread_angle: self.angle(),
        }
    }

    /// A packed cone; in the domain, a half whose exponent is all ones (infinity, NaN) gets a
    /// finite exponent.
    pub fn packed_cone(&mut self) -> PackedRayCone {
        let bits = self.words.u32();
        let finite_halves = |bits: u32| {
            let mut out = bits;
            for shift in [10, 26] {
                if (bits >> shift) & 0x1f == 0x1f {
                    out &= !(0x10 << shift);
                }
            }
            out
        };
        PackedRayCone(if self.domain() { finite_halves(bits) } else { bits })
    }

    /// A ray differential.
    pub fn ray_diff(&mut self) -> RayDiff {
        RayDiff::new(self.vec3(), self.vec3(), self.vec3(), self.vec3())
    }

    /// Two-vector derivatives.
    pub fn derivatives2(&mut self) -> Derivatives2 {
        Derivatives2::new(self.vec2(), self.vec2())
    }

    /// Three-vector derivatives.
    pub fn derivatives3(&mut self) -> Derivatives3 {
        Derivatives3::new(self.vec3(), self.vec3())
    }

    /// A G-buffer sample: unit direction, distance, unit normal.
    pub fn gbuffer_sample(&mut self) -> GBufferSample {
        GBufferSample {
            eye_direction: self.unit(),
            distance: self.distance(),
            normal: self.unit(),
        }
    }

    /// Wireframe settings from their host-shareable mirror.
    pub fn settings(&mut self) -> WireframeSettings {
        self.settings_io().unpack()
    }

    /// The host-shareable wireframe settings.
    pub fn settings_io(&mut self) -> WireframeSettingsIo {
        WireframeSettingsIo {
            thickness_var: self.vec2(),
            thickness: self.scalar(),
            smoothing: self.scalar(),
            stipple: self.int(),
            stipple_length: self.scalar(),
            stipple_repeats: self.int(),
            screen_space: self.int(),
        }
    }

    /// Records a violation unless `lo <= value <= hi`; checked where the outputs must be finite.
    pub fn within(&mut self, value: f32, lo: f32, hi: f32, what: &str) {
        if !(lo..=hi).contains(&value) {
            self.violations
                .push(format!("{what} = {value:e} outside [{lo:e}, {hi:e}]"));
        }
    }
}

/// The floats of a mirror function's result.
pub trait Floats {
    /// Calls `visit` with every float of the value, in field order.
    fn each_float(&self, visit: &mut impl FnMut(f32));

    /// Every float of the value, in field order.
    fn floats(&self) -> Vec<f32> {
        let mut out = Vec::new();
        self.each_float(&mut |x| out.push(x));
        out
    }
}

macro_rules! floats {
    ($($ty:ty => |$v:ident| [$($field:expr),*];)+) => {
        $(impl Floats for $ty {
            fn each_float(&self, visit: &mut impl FnMut(f32)) {
                let $v = self;
                $($field.each_float(visit);)*
            }
        })+
    };
}

impl Floats for f32 {
    fn each_float(&self, visit: &mut impl FnMut(f32)) {
        visit(*self);
    }
}

floats! {
    Vec2 => |v| [v.x, v.y];
    Vec3 => |v| [v.x, v.y, v.z];
    RayCone => |v| [v.width, v.spread_angle];
    RefractedRayCone => |v| [v.cone];
    PackedRayCone => |v| [rc::unpack_ray_cone(*v)];
    RayDiff => |v| [v.d_origin_dx, v.pad0, v.d_origin_dy, v.pad1, v.d_direction_dx, v.pad2, v.d_direction_dy, v.pad3];
    Derivatives2 => |v| [v.dx, v.dy];
    Derivatives3 => |v| [v.dx, v.dy];
    NeighbourDirections => |v| [v.right, v.below];
    RefractedRayDiff => |v| [v.diff];
    TriplanarGradients => |v| [v.yz, v.zx, v.xy];
    BarycentricOffsets => |v| [v.dx, v.dy];
    WireframeSettings => |v| [v.thickness_var, v.thickness, v.smoothing, v.stipple_length];
}

/// Evaluates one public mirror function on drawn arguments; returns its result's floats when one
/// of them is not finite.
pub type Run = fn(&mut Draw) -> Option<Vec<f32>>;

/// One public mirror function and how to evaluate it.
pub type MirrorFunction = Registered<Run>;

/// The `cpu_mirror` target.
pub fn cpu_mirror(data: &[u8]) -> Result<(), String> {
    for function in functions() {
        for mode in [Mode::Raw, Mode::Domain] {
            evaluate(function, data, mode)?;
        }
    }
    Ok(())
}

fn evaluate(function: &MirrorFunction, data: &[u8], mode: Mode) -> Result<(), String> {
    let mut draw = Draw::new(data, mode);
    let non_finite = (function.item)(&mut draw);
    let promised = match mode {
        Mode::Domain => true,
        Mode::Raw => draw.finite && function.module == Module::Wireframe,
    };
    if !promised {
        return Ok(());
    }
    let mut problems = draw.violations;
    if let Some(floats) = non_finite {
        problems.push(format!("non-finite output {floats:?}"));
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(format!(
            "{}::{} ({mode:?} inputs): {}",
            function.module.stem(),
            function.function,
            problems.join("; ")
        ))
    }
}

/// Declares a [`MirrorFunction`]: `f!(Module, name, |d| expression)`.
macro_rules! f {
    ($module:ident, $name:ident, |$d:ident| $body:expr) => {
        MirrorFunction::new(Module::$module, stringify!($name), |$d| non_finite(&$body))
    };
}

/// The floats of `value` when one of them is not finite.
fn non_finite<T: Floats>(value: &T) -> Option<Vec<f32>> {
    let mut finite = true;
    value.each_float(&mut |x| finite &= x.is_finite());
    (!finite).then(|| value.floats())
}

/// Evaluates `value`, records a range check on it, and returns it.
fn within<T: Floats>(d: &mut Draw, value: T, lo: f32, hi: f32, what: &str) -> T {
    value.each_float(&mut |x| d.within(x, lo, hi, what));
    value
}

/// Draws the arguments of a barycentric re-intersection function (`barycentric_offsets` and
/// `barycentric_deltas`, f32 and f64): world-to-object matrix, world ray origin, three vertices, two
/// unit neighbour directions and the hit's barycentrics, and calls `function` on them.
fn reintersection<T>(d: &mut Draw, function: fn(Mat4, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3, Vec3) -> T) -> T {
    function(
        d.world_to_object(),
        d.world_point(),
        d.vec3(),
        d.vec3(),
        d.vec3(),
        d.unit(),
        d.unit(),
        d.vec3(),
    )
}

/// `F64_MAX_VALUE` as the f32 the functions return.
const F64_MAX: f32 = rd64::F64_MAX_VALUE as f32;

/// Every public function of the mirror modules, in module order (built once).
pub fn functions() -> &'static [MirrorFunction] {
    static FUNCTIONS: std::sync::OnceLock<Vec<MirrorFunction>> = std::sync::OnceLock::new();
    FUNCTIONS.get_or_init(|| registry(module_functions))
}

/// The public functions of `module`, in the module's order.
fn module_functions(module: Module) -> Vec<MirrorFunction> {
    match module {
        Module::RayCone => ray_cone_functions(),
        Module::RayDiff => ray_diff_functions(),
        Module::RayDiffF64 => ray_diff_f64_functions(),
        Module::Wireframe => wireframe_functions(),
    }
}

fn ray_cone_functions() -> Vec<MirrorFunction> {
    use std::f32::consts::{FRAC_PI_2, PI};
    vec![
        f!(RayCone, pack_ray_cone, |d| {
            let packed = rc::pack_ray_cone(d.cone());
            within(d, packed, -rc::F16_MAX, rc::F16_MAX, "unpacked half")
        }),
        f!(RayCone, unpack_ray_cone, |d| rc::unpack_ray_cone(d.packed_cone())),
        f!(RayCone, pixel_spread_angle, |d| {
            let angle = rc::pixel_spread_angle(d.angle(), d.scalar());
            within(d, angle, 0.0, FRAC_PI_2, "spread angle")
        }),
        f!(RayCone, pixel_spread_angle_small, |d| {
            let angle = rc::pixel_spread_angle_small(d.angle(), d.scalar());
            within(d, angle, 0.0, f32::MAX, "spread angle")
        }),
        f!(RayCone, pixel_spread_angle_from_proj_inv, |d| {
            let angle = rc::pixel_spread_angle_from_proj_inv(d.mat4(), d.scalar());
            within(d, angle, 0.0, FRAC_PI_2, "spread angle")
        }),
        f!(RayCone, pinhole_ray_cone, |d| rc::pinhole_ray_cone(d.angle())),
        f!(RayCone, pinhole_ray_cone_for_ray, |d| {
            let cone = rc::pinhole_ray_cone_for_ray(d.angle(), d.unit(), d.unit());
            within(d, cone, -3.2, 3.2, "width and spread")
        }),
        f!(RayCone, orthographic_ray_cone, |d| rc::orthographic_ray_cone(
            d.scalar(),
            d.scalar()
        )),
        f!(RayCone, thin_lens_ray_cone, |d| rc::thin_lens_ray_cone(
            d.angle(),
            d.scalar(),
            d.distance()
        )),
        f!(RayCone, width_at, |d| rc::width_at(d.cone(), d.distance())),
        f!(RayCone, propagate, |d| rc::propagate(
            d.cone(),
            d.distance(),
            d.angle()
        )),
        f!(RayCone, normal_spread_angle, |d| {
            let angle = rc::normal_spread_angle(d.vec3(), d.vec3());
            within(d, angle, 0.0, PI, "normal spread angle")
        }),
        f!(RayCone, normal_spread_angle_small, |d| {
            let angle = rc::normal_spread_angle_small(d.vec3(), d.vec3());
            within(d, angle, 0.0, f32::MAX, "normal spread angle")
        }),
        f!(RayCone, curvature_sign, |d| {
            let sign = rc::curvature_sign(d.vec3(), d.vec3(), d.vec3(), d.vec3());
            within(d, sign.abs(), 1.0, 1.0, "|sign|")
        }),
        f!(RayCone, surface_spread_angle, |d| {
            rc::surface_spread_angle(d.angle(), d.scalar().signum(), d.scalar(), d.angle())
        }),
        f!(RayCone, edge_curvature, |d| rc::edge_curvature(
            d.vec3(),
            d.vec3(),
            d.unit(),
            d.unit()
        )),
        f!(RayCone, triangle_curvature, |d| {
            rc::triangle_curvature(d.vec3(), d.vec3(), d.vec3(), d.unit(), d.unit(), d.unit())
        }),
        f!(RayCone, curvature_spread_angle, |d| {
            rc::curvature_spread_angle(d.scalar(), d.scalar(), d.unit(), d.unit())
        }),
        f!(RayCone, world_footprint, |d| {
            let footprint = rc::world_footprint(d.cone(), d.distance(), d.unit(), d.unit());
            within(d, footprint, 0.0, f32::MAX, "footprint")
        }),
        f!(RayCone, triangle_world_area2, |d| {
            let area = rc::triangle_world_area2(d.vec3(), d.vec3(), d.vec3());
            within(d, area, 0.0, f32::MAX, "area")
        }),
        f!(RayCone, triangle_uv_area2, |d| {
            let area = rc::triangle_uv_area2(d.vec2(), d.vec2(), d.vec2());
            within(d, area, 0.0, f32::MAX, "area")
        }),
        f!(RayCone, texel_density, |d| {
            let density = rc::texel_density(d.vec3(), d.vec3(), d.vec3(), d.vec2(), d.vec2(), d.vec2());
            within(d, density, 0.0, f32::MAX, "density")
        }),
        f!(RayCone, triangle_base_lod, |d| {
            rc::triangle_base_lod(d.vec3(), d.vec3(), d.vec3(), d.vec2(), d.vec2(), d.vec2())
        }),
        f!(RayCone, texture_lod, |d| {
            rc::texture_lod(d.scalar(), d.scalar(), d.vec2(), d.unit(), d.unit())
        }),
        f!(RayCone, texture_gradient, |d| {
            let gradient = rc::texture_gradient(d.scalar(), d.scalar());
            within(d, gradient, 0.0, f32::MAX, "gradient")
        }),
        f!(RayCone, environment_lod, |d| {
            let lod = rc::environment_lod(d.angle(), d.scalar());
            within(d, lod, rc::MIN_MAGNITUDE.log2(), f32::MAX, "environment LOD")
        }),
        f!(RayCone, refract_ray_cone, |d| rc::refract_ray_cone(
            d.cone(),
            d.unit(),
            d.unit(),
            d.angle(),
            d.scalar()
        )),
        f!(RayCone, roughness_spread_angle, |d| {
            let spread = rc::roughness_spread_angle(d.scalar());
            within(d, spread, 0.0, 142.0, "roughness spread")
        }),
    ]
}

fn ray_diff_functions() -> Vec<MirrorFunction> {
    vec![
        f!(RayDiff, eye_ray_direction, |d| {
            rd::eye_ray_direction(d.vec2(), d.vec2(), d.angle(), d.unit(), d.unit(), d.unit())
        }),
        f!(RayDiff, normalized_derivative, |d| rd::normalized_derivative(
            d.vec3(),
            d.vec3()
        )),
        f!(RayDiff, eye_ray_diff, |d| {
            rd::eye_ray_diff(d.vec2(), d.vec2(), d.angle(), d.unit(), d.unit(), d.unit())
        }),
        f!(RayDiff, eye_ray_direction_from_matrices, |d| {
            rd::eye_ray_direction_from_matrices(d.vec2(), d.vec2(), d.rigid(), d.mat4())
        }),
        f!(RayDiff, eye_ray_diff_from_matrices, |d| {
            rd::eye_ray_diff_from_matrices(d.vec2(), d.vec2(), d.rigid(), d.mat4())
        }),
        f!(RayDiff, pixel_directions, |d| {
            rd::pixel_directions(d.vec2(), d.vec2(), d.rigid(), d.mat4())
        }),
        f!(RayDiff, transfer, |d| rd::transfer(
            d.ray_diff(),
            d.unit(),
            d.distance(),
            d.unit()
        )),
        f!(RayDiff, barycentric_derivatives, |d| {
            let b = rd::barycentric_derivatives(
                d.ray_diff(),
                d.unit(),
                d.distance(),
                d.vec3(),
                d.vec3(),
                d.vec3(),
            );
            within(
                d,
                b,
                -rd::DIFF_MAX_VALUE,
                rd::DIFF_MAX_VALUE,
                "barycentric derivative",
            )
        }),
        f!(RayDiff, barycentric_w_derivatives, |d| {
            rd::barycentric_w_derivatives(d.derivatives2())
        }),
        f!(RayDiff, texture_derivatives, |d| {
            rd::texture_derivatives(d.derivatives2(), d.vec2(), d.vec2(), d.vec2())
        }),
        f!(RayDiff, texel_derivatives, |d| {
            rd::texel_derivatives(d.derivatives2(), d.vec2(), d.vec2(), d.vec2(), d.vec2())
        }),
        f!(RayDiff, secondary_origin_derivatives, |d| {
            rd::secondary_origin_derivatives(d.derivatives2(), d.vec3(), d.vec3(), d.vec3())
        }),
        f!(RayDiff, lod_isotropic, |d| {
            let lod = rd::lod_isotropic(d.derivatives2());
            within(d, lod, 0.5 * rd::DIFF_MIN_MAGNITUDE.log2(), f32::MAX, "LOD")
        }),
        f!(RayDiff, lod_box, |d| {
            let lod = rd::lod_box(d.derivatives2());
            within(d, lod, rd::DIFF_MIN_MAGNITUDE.log2(), f32::MAX, "LOD")
        }),
        f!(RayDiff, sample_grad_gradients, |d| rd::sample_grad_gradients(
            d.derivatives2(),
            d.scalar()
        )),
        f!(RayDiff, normal_derivatives, |d| {
            rd::normal_derivatives(d.unit(), d.unit(), d.unit(), d.vec2(), d.derivatives2())
        }),
        f!(RayDiff, reflect_ray_diff, |d| {
            rd::reflect_ray_diff(d.ray_diff(), d.unit(), d.unit(), d.derivatives3())
        }),
        f!(RayDiff, refract_ray_diff, |d| {
            rd::refract_ray_diff(d.ray_diff(), d.unit(), d.unit(), d.derivatives3(), d.scalar())
        }),
        f!(RayDiff, gbuffer_ray_diff, |d| {
            rd::gbuffer_ray_diff(
                d.gbuffer_sample(),
                d.gbuffer_sample(),
                d.gbuffer_sample(),
                d.gbuffer_sample(),
                d.gbuffer_sample(),
                d.distance(),
            )
        }),
        f!(RayDiff, tangent_plane_offsets, |d| {
            rd::tangent_plane_offsets(d.unit(), d.unit(), d.unit(), d.distance(), d.unit())
        }),
        f!(RayDiff, planar_mapping_gradients, |d| {
            rd::planar_mapping_gradients(d.derivatives3(), d.vec2())
        }),
        f!(RayDiff, triplanar_weights, |d| {
            let weights = rd::triplanar_weights(d.unit(), d.scalar());
            within(d, weights, 0.0, 1.0, "weight")
        }),
        f!(RayDiff, triplanar_gradients, |d| rd::triplanar_gradients(
            d.derivatives3(),
            d.scalar()
        )),
        f!(RayDiff, intersect_triangle_plane, |d| {
            let b = rd::intersect_triangle_plane(d.vec3(), d.vec3(), d.vec3(), d.vec3(), d.vec3());
            within(d, b.yz(), -rd::DIFF_MAX_VALUE, rd::DIFF_MAX_VALUE, "barycentric")
        }),
        f!(RayDiff, barycentric_offsets, |d| {
            reintersection(d, rd::barycentric_offsets)
        }),
        f!(RayDiff, barycentric_deltas, |d| {
            let deltas = reintersection(d, rd::barycentric_deltas);
            within(d, deltas, 0.0, f32::MAX, "delta")
        }),
        f!(RayDiff, uv_gradients_from_offsets, |d| {
            rd::uv_gradients_from_offsets(d.derivatives3(), d.vec2(), d.vec2(), d.vec2())
        }),
        f!(RayDiff, cone_barycentric_deltas, |d| {
            let deltas = rd::cone_barycentric_deltas(d.scalar(), d.vec3(), d.vec3(), d.vec3());
            within(d, deltas, 0.0, rd::DIFF_MAX_VALUE, "delta")
        }),
        f!(RayDiff, anisotropic_cone_axes, |d| rd::anisotropic_cone_axes(
            d.scalar(),
            d.unit(),
            d.unit()
        )),
        f!(RayDiff, anisotropic_cone_gradients, |d| {
            rd::anisotropic_cone_gradients(
                d.scalar(),
                d.unit(),
                d.vec3(),
                d.vec3(),
                d.vec3(),
                d.vec2(),
                d.vec2(),
                d.vec2(),
            )
        }),
        f!(RayDiff, ray_diff_from_cone, |d| rd::ray_diff_from_cone(
            d.vec2(),
            d.unit()
        )),
        f!(RayDiff, cone_from_ray_diff, |d| {
            let cone = rd::cone_from_ray_diff(d.ray_diff(), d.unit());
            d.within(cone.x, 0.0, f32::MAX, "width");
            cone
        }),
    ]
}

fn ray_diff_f64_functions() -> Vec<MirrorFunction> {
    vec![
        f!(RayDiffF64, intersect_triangle_plane_f64, |d| {
            let b = rd64::intersect_triangle_plane_f64(d.vec3(), d.vec3(), d.vec3(), d.vec3(), d.vec3());
            within(d, b.yz(), -F64_MAX, F64_MAX, "barycentric")
        }),
        f!(RayDiffF64, barycentric_offsets_f64, |d| {
            reintersection(d, rd64::barycentric_offsets_f64)
        }),
        f!(RayDiffF64, barycentric_deltas_f64, |d| {
            let deltas = reintersection(d, rd64::barycentric_deltas_f64);
            within(d, deltas, 0.0, f32::MAX, "delta")
        }),
    ]
}

fn wireframe_functions() -> Vec<MirrorFunction> {
    vec![
        f!(Wireframe, unpack_wireframe_settings, |d| {
            wf::unpack_wireframe_settings(d.settings_io())
        }),
        f!(Wireframe, edge_position, |d| {
            let b = d.vec3();
            let e = wf::edge_position(b);
            within(d, e - b.max_element(), 0.0, 0.0, "edge position - max(b)")
        }),
        f!(Wireframe, edge_thickness, |d| {
            let thickness = wf::edge_thickness(d.vec2(), d.scalar());
            within(d, thickness, 0.0, wf::MAX_LINE_THICKNESS, "thickness")
        }),
        f!(Wireframe, stipple, |d| {
            let on = wf::stipple(d.int(), d.scalar(), d.scalar());
            within(d, on * (1.0 - on), 0.0, 0.0, "stipple * (1 - stipple)")
        }),
        f!(Wireframe, edge_ramp, |d| {
            let ramp = wf::edge_ramp(d.vec3(), d.vec3(), d.vec3());
            within(d, ramp, 0.0, 1.0, "ramp")
        }),
        f!(Wireframe, line_width, |d| {
            let coverage = wf::line_width(d.vec3(), d.scalar(), d.scalar(), d.vec3());
            within(d, coverage, 0.0, 1.0, "coverage")
        }),
        f!(Wireframe, process_wireframe, |d| {
            let coverage = wf::process_wireframe(d.settings(), d.vec3(), d.vec3());
            within(d, coverage, 0.0, 1.0, "coverage")
        }),
    ]
}
