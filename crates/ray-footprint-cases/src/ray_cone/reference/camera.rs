//! References of the camera-cone section: the `half` crate's conversions, the pixel's rays, its
//! footprint on a plane and on the plane across its ray, the rays of an orthographic camera and
//! of a thin lens.

use super::propagation::unit_excess;
use crate::exact::{angle_between, derivative, log_uniform, plane_hit, unit};
use crate::reference::{gamma, Deviation, Kind, Reference, U};
use glam::dcamera::rh::proj::{opengl, vulkan};
use glam::{DQuat, DVec2, DVec3, DVec4, Mat4, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::{PackedRayCone, RayCone, F16_MAX};

/// Any finite f32: every bit pattern but infinities and NaNs, and ordinary values.
fn finite_f32() -> BoxedStrategy<f32> {
    prop_oneof![
        any::<u32>()
            .prop_map(f32::from_bits)
            .prop_filter("finite", |x| x.is_finite()),
        -1.0e5f32..1.0e5,
    ]
    .boxed()
}

/// `rf_pack_ray_cone`.
pub(in crate::ray_cone) fn pack_ray_cone() -> Reference<(RayCone,), PackedRayCone> {
    Reference::new(
        Kind::PeerOriginal,
        "the `half` crate's f32 -> f16 conversion (round to nearest, ties to even) of each value clamped to [-F16_MAX, F16_MAX], bit for bit",
        || (finite_f32(), finite_f32()).boxed(),
        |&(width, spread_angle), pack| {
            let got = pack((RayCone { width, spread_angle },));
            let half = |x: f32| u32::from(half::f16::from_f32(x.clamp(-F16_MAX, F16_MAX)).to_bits());
            let expected = half(width) | (half(spread_angle) << 16);
            Some(Deviation::new(f64::from(u8::from(got.0 != expected)), 0.0))
        },
    )
}

/// `rf_unpack_ray_cone`.
pub(in crate::ray_cone) fn unpack_ray_cone() -> Reference<(PackedRayCone,), RayCone> {
    Reference::new(
        Kind::PeerOriginal,
        "the `half` crate's f16 -> f32 conversion of both halves, bit for bit (NaN as NaN), over every bit pattern",
        || any::<u32>().boxed(),
        |&bits, unpack| {
            let got = unpack((PackedRayCone(bits),));
            let same = |value: f32, half_bits: u32| {
                let expected = half::f16::from_bits(half_bits as u16).to_f32();
                value.to_bits() == expected.to_bits() || (value.is_nan() && expected.is_nan())
            };
            let both = same(got.width, bits & 0xffff) && same(got.spread_angle, bits >> 16);
            Some(Deviation::new(f64::from(u8::from(!both)), 0.0))
        },
    )
}

/// A field of view in `(0, MAX_FOV_Y]` and an image height of at least one pixel.
fn camera() -> BoxedStrategy<(f32, f32)> {
    let height = prop_oneof![(1u32..16384).prop_map(|h| h as f32), 1.0f32..16384.0];
    (prop_oneof![0.001f32..3.1, Just(3.1f32)], height).boxed()
}

/// `2 tan(fov / 2) / H` in f64: the height of one pixel on the image plane at distance 1.
fn pixel_height(fov: f32, height: f32) -> f64 {
    2.0 * (0.5 * f64::from(fov)).tan() / f64::from(height)
}

/// The angle between the central ray and the ray through the point one pixel above it on the
/// image plane at distance 1.
fn pixel_angle(fov: f32, height: f32) -> f64 {
    angle_between(DVec3::NEG_Z, DVec3::new(0.0, pixel_height(fov, height), -1.0))
}

/// `rf_pixel_spread_angle`.
pub(in crate::ray_cone) fn pixel_spread_angle() -> Reference<(f32, f32), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the angle between the central ray and the ray through the image-plane point one pixel above it (RTG Eq. 30)",
        camera,
        |&(fov, height), pixel_spread_angle| {
            let got = pixel_spread_angle((fov, height));
            let exact = pixel_angle(fov, height);
            // tan and atan within 2 ULP each (4 u), the division by H (u); atan carries its
            // argument's relative error at most once.
            Some(Deviation::within(f64::from(got), exact, gamma(10) * exact))
        },
    )
}

/// `rf_pixel_spread_angle_small`: the pixel's height on the image plane.
pub(in crate::ray_cone) fn pixel_spread_angle_small() -> Reference<(f32, f32), f32> {
    Reference::new(
        Kind::ClosedForm,
        "the height of the pixel next to the axis on the image plane at distance 1: NDC (0, 0) and (0, 2 / H) unprojected through the f64 inverse of the perspective matrix",
        camera,
        |&(fov, height), pixel_spread_angle_small| {
            let got = pixel_spread_angle_small((fov, height));
            let inverse = opengl::perspective(f64::from(fov), 1.0, 0.1, 100.0).inverse();
            let on_image_plane = |ndc_y: f64| {
                let point = inverse * DVec4::new(0.0, ndc_y, 1.0, 1.0);
                point.y / -point.z
            };
            let exact = on_image_plane(2.0 / f64::from(height)) - on_image_plane(0.0);
            // tan within 2 ULP (4 u), the division by H (u); the f64 path within 1e-14.
            Some(Deviation::within(f64::from(got), exact, (gamma(5) + 1.0e-14) * exact))
        },
    )
}

/// `rf_pixel_spread_angle_small`: the small-angle approximation.
pub(in crate::ray_cone) fn pixel_spread_angle_small_approximation() -> Reference<(f32, f32), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the small-angle form x = 2 tan(fov / 2) / H against the exact angle of the pixel next to the axis, atan(x): within x^3 / 3",
        camera,
        |&(fov, height), pixel_spread_angle_small| {
            let got = pixel_spread_angle_small((fov, height));
            let x = pixel_height(fov, height);
            // x - atan(x) <= x^3 / 3; the f32 evaluation of x within gamma(5).
            let bound = x.powi(3) / 3.0 + gamma(5) * x;
            Some(Deviation::within(f64::from(got), pixel_angle(fov, height), bound))
        },
    )
}

/// A perspective projection's inverse in f32 (OpenGL, Vulkan's y-flipped, or infinite with
/// reversed depth), computed in f64 and rounded entry by entry, and an image height.
fn inverse_projection() -> BoxedStrategy<(Mat4, f32)> {
    (
        0.05f64..3.0,
        0.2f64..5.0,
        log_uniform(-2.0, 1.0),
        0usize..3,
        camera(),
    )
        .prop_map(|(fov, aspect, near, kind, (_, height))| {
            let projection = match kind {
                0 => opengl::perspective(fov, aspect, near, near * 1000.0),
                1 => vulkan::perspective(fov, aspect, near, near * 1000.0),
                _ => vulkan::perspective_infinite_reverse(fov, aspect, near),
            };
            (projection.inverse().as_mat4(), height)
        })
        .boxed()
}

/// `rf_pixel_spread_angle_from_proj_inv`.
pub(in crate::ray_cone) fn pixel_spread_angle_from_proj_inv() -> Reference<(Mat4, f32), f32> {
    Reference::new(
        Kind::ExactGeometry,
        "the angle at the eye between the points that NDC (0, 0) and (0, 2 / H) unproject to through the matrix itself (f64, homogeneous division), for OpenGL, Vulkan (y-flipped) and infinite reversed-depth projections",
        inverse_projection,
        |&(proj_inv, height), from_proj_inv| {
            let got = from_proj_inv((proj_inv, height));
            let inverse = proj_inv.as_dmat4();
            let unproject = |ndc_y: f64| {
                let point = inverse * DVec4::new(0.0, ndc_y, 1.0, 1.0);
                point.truncate() / point.w
            };
            let exact = angle_between(unproject(0.0), unproject(2.0 / f64::from(height)));
            // The division by H (u) and atan (2 ULP, 4 u).
            Some(Deviation::within(f64::from(got), exact, gamma(5) * exact))
        },
    )
}

/// `rf_pinhole_ray_cone`.
pub(in crate::ray_cone) fn pinhole_ray_cone() -> Reference<(f32,), RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "the central pixel's footprint on the plane across the view axis at distance t: the rays through its top and bottom edges intersected with the plane, 2 t tan(fov / 2) / H apart, against the cone's width at t",
        || (camera(), log_uniform(-2.0, 4.0)).boxed(),
        |&((fov, height), t), pinhole_ray_cone| {
            let spread = pixel_height(fov, height) as f32;
            let cone = pinhole_ray_cone((spread,));
            let width = f64::from(cone.width) + f64::from(cone.spread_angle) * t;
            let edge = |ndc_y: f64| {
                let direction = DVec3::new(0.0, ndc_y * (0.5 * f64::from(fov)).tan(), -1.0);
                plane_hit(DVec3::ZERO, direction, DVec3::NEG_Z * t, DVec3::Z).y
            };
            let h = f64::from(height);
            let exact = edge(1.0 / h) - edge(-1.0 / h);
            // The spread is the footprint's angle rounded to f32 (u); f64 rounding below 1e-14.
            Some(Deviation::within(width, exact, (U + 1.0e-14) * exact))
        },
    )
}

/// A pinhole camera in a random orientation and one of its pixels.
#[derive(Clone, Debug)]
struct Pinhole {
    fov: f64,
    size: DVec2,
    pixel: DVec2,
    rotation: DQuat,
}

impl Pinhole {
    /// Fields of view up to 160 degrees, images of 200 to 4000 rows at aspects 0.5 to 2.5.
    fn strategy() -> BoxedStrategy<Pinhole> {
        (
            0.2f64..2.8,
            200.0f64..4000.0,
            0.5f64..2.5,
            (0.0f64..1.0, 0.0f64..1.0),
            (unit(), 0.0f64..6.3),
        )
            .prop_map(|(fov, height, aspect, (fx, fy), (axis, angle))| {
                let size = DVec2::new((height * aspect).round(), height.round());
                Pinhole {
                    fov,
                    size,
                    pixel: (DVec2::new(fx, fy) * size).floor(),
                    rotation: DQuat::from_axis_angle(axis, angle),
                }
            })
            .boxed()
    }

    /// Unit direction, in camera space (looking down -z, pixel y down), through the continuous
    /// pixel position `at`.
    fn direction(&self, at: DVec2) -> DVec3 {
        let ndc = (at + 0.5) / self.size * 2.0 - 1.0;
        let f = (0.5 * self.fov).tan();
        DVec3::new(ndc.x * self.size.x / self.size.y * f, -ndc.y * f, -1.0).normalize()
    }
}

/// `rf_pinhole_ray_cone_for_ray`.
pub(in crate::ray_cone) fn pinhole_ray_cone_for_ray() -> Reference<(f32, Vec3, Vec3), RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "the pixel's footprint on the plane across its ray (the pixel -> ray map differentiated by f64 central differences): the per-ray cone's LOD error lies in [log2(atan(x) / x), log2(2 / (1 + cos^2)) / 2] against the footprint's longer side",
        Pinhole::strategy,
        |camera, pinhole_ray_cone_for_ray| {
            let centre = camera.direction(camera.pixel);
            let on_plane = |step: DVec2| {
                let direction = camera.direction(camera.pixel + step);
                direction / direction.dot(centre)
            };
            let across = derivative(|h| on_plane(DVec2::new(h, 0.0)), 1.0e-3, 2.0);
            let down = derivative(|h| on_plane(DVec2::new(0.0, h)), 1.0e-3, 2.0);
            let longer = across.value.length().max(down.value.length());
            let x = 2.0 * (0.5 * camera.fov).tan() / camera.size.y;
            let alpha = x.atan() as f32;
            let (direction, axis) = ((camera.rotation * centre).as_vec3(), (camera.rotation * DVec3::NEG_Z).as_vec3());
            let cone = pinhole_ray_cone_for_ray((alpha, direction, axis));
            let cosine = -centre.z;
            // A pixel theta off axis spans x cos(theta) across the radial direction and
            // x cos^2(theta) along it (to first order); its longer side, at any angle to the
            // radial direction, lies between x cos sqrt((1 + cos^2) / 2) and x cos. The cone's
            // spread atan(x) cos(theta) is off by alpha's rounding, the dot product's rounding over
            // cos and the product's rounding; the footprint by its central differences' error.
            let terms = (direction.as_dvec3() * axis.as_dvec3()).abs().element_sum();
            let relative = gamma(2) + (gamma(3) * terms + unit_excess(direction, axis)) / cosine
                + across.error.max(down.error) / longer;
            let slack = 1.01 * relative / std::f64::consts::LN_2;
            let low = (f64::from(alpha) / x).log2() - slack;
            let high = 0.5 * (2.0 / (1.0 + cosine * cosine)).log2() + slack;
            let lod_error = (f64::from(cone.spread_angle) / longer).log2();
            Some(Deviation::in_interval(lod_error, low, high).and(Deviation::new(f64::from(cone.width).abs(), 0.0)))
        },
    )
}

/// `rf_orthographic_ray_cone`.
pub(in crate::ray_cone) fn orthographic_ray_cone() -> Reference<(f32, f32), RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "an orthographic camera's parallel rays through the top and bottom edges of a random pixel row, V (1/2 - j / H) and V (1/2 - (j + 1) / H) up the image plane: their distance apart and the angle between them",
        || (log_uniform(-3.0, 3.0), camera(), 0.0f64..1.0).boxed(),
        |&(view_height, (_, height), row), orthographic_ray_cone| {
            let view_height = view_height as f32;
            let cone = orthographic_ray_cone((view_height, height));
            let (v, h) = (f64::from(view_height), f64::from(height));
            let j = (row * h).floor();
            let ray = |edge: f64| (DVec3::new(0.0, v * (0.5 - edge / h), 0.0), DVec3::NEG_Z);
            let ((top, top_direction), (bottom, bottom_direction)) = (ray(j), ray(j + 1.0));
            let at = |(origin, direction): (DVec3, DVec3)| plane_hit(origin, direction, DVec3::NEG_Z, DVec3::Z);
            let width = (at((top, top_direction)) - at((bottom, bottom_direction))).length();
            // One division (u); the f64 positions round within 4 ULP of V.
            let width_deviation = Deviation::within(f64::from(cone.width), width, U * width + 4.0 * f64::EPSILON * v);
            let spread = angle_between(top_direction, bottom_direction);
            Some(width_deviation.and(Deviation::within(f64::from(cone.spread_angle), spread, 0.0)))
        },
    )
}

/// `rf_thin_lens_ray_cone`.
pub(in crate::ray_cone) fn thin_lens_ray_cone() -> Reference<(f32, f32, f32), RayCone> {
    Reference::new(
        Kind::ExactGeometry,
        "a thin lens focused at F: the rays from the aperture's edges (+-A/2) through the pixel's edge points on the focal plane (+-F tan(alpha / 2)), intersected with the plane at t; the cone's width at t within t alpha^3 / (12 cos^4(alpha / 2))",
        || (log_uniform(-5.0, -0.3), 0.0f64..1.0, log_uniform(-1.0, 2.0), 0.0f64..1000.0).boxed(),
        |&(alpha, aperture, focus, t), thin_lens_ray_cone| {
            let (alpha, aperture, focus) = (alpha as f32, aperture as f32, focus as f32);
            let cone = thin_lens_ray_cone((alpha, aperture, focus));
            let (alpha, aperture, focus) = (f64::from(alpha), f64::from(aperture), f64::from(focus));
            let width = f64::from(cone.width) + f64::from(cone.spread_angle) * t;
            let marginal = |side: f64| {
                let lens = DVec3::new(0.0, side * 0.5 * aperture, 0.0);
                let focal = DVec3::new(0.0, side * focus * (0.5 * alpha).tan(), -focus);
                plane_hit(lens, focal - lens, DVec3::NEG_Z * t, DVec3::Z).y
            };
            let exact = marginal(1.0) - marginal(-1.0);
            // The marginal rays separate at 2 tan(alpha / 2) - A / F per unit, the cone at
            // alpha - A / F: t (2 tan(alpha / 2) - alpha) apart (see `width_at`); the spread's
            // division and difference round twice; the width is a copy.
            let approximation = t * alpha.powi(3) / (12.0 * (0.5 * alpha).cos().powi(4));
            let rounding = t * gamma(2) * (2.0 * aperture / focus + alpha) + 1.0e-13 * (aperture + t * alpha);
            Some(Deviation::within(width, exact, approximation + rounding))
        },
    )
}
