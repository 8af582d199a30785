//! Reflection chains: the ray cone against the crate's ray differentials along the same paths, on
//! the CPU and, through a shader of the lab's own, in WGSL, GLSL and Slang on the device.
//!
//! A chain is a primary ray (pinhole, orthographic or thin lens) reflected by 1 to 4 curved mirrors
//! and followed to a plane across the last ray. The same path is followed by the cone
//! (`width_at`, `curvature_spread_angle`, `propagate`) and by the ray differential (`transfer`,
//! then `reflect_ray_diff` with the derivative of the stored normal field), both in f32, by
//! [`reflection_chain`] and its shader twins ([`chain_shader`]). The geometry between them
//! (directions, normals, principal directions, the pixel-step frame) is exact in f64 ([`Chain`])
//! and rounded to f32 where the crate's functions take it ([`Chain::args`]).
//!
//! Both are first-order models of the same beam, but the cone is isotropic and the differential is
//! not, so they can only be compared where the beam stays describable by one width:
//! - In-plane chains ([`in_plane_chain`]): every ray and normal lies in one plane, and a pixel step
//!   right moves the footprint within it. There the differential's in-plane footprint follows the
//!   cone exactly when the cone is given the mirror's normal curvature in that plane (for a sphere
//!   1/R, for a saddle whose principal directions lie along and across the plane, the principal
//!   curvature along it). The differential's other axis meets the curvature across the plane and,
//!   at oblique incidence, `cos` instead of `1 / cos` (Coddington's sagittal and tangential foci):
//!   no isotropic cone follows both.
//! - Head-on chains with one saddle ([`head_on_chain_with_one_saddle`]): a saddle's principal
//!   curvatures have opposite signs, and an isotropic estimate (`triangle_curvature`, the mean of
//!   normal curvatures over three edge directions) approaches its mean curvature. Given the mean
//!   curvature, the cone follows the mean of the differential's two signed footprints (half the
//!   trace of the footprint's map), exactly, as long as the beam meeting the saddle is isotropic
//!   (head-on hits, every other mirror a sphere); after that the two axes stay apart and only
//!   their mean is a cone.
//!
//! [`Chain::samples`] pairs the cone's width with the differential's footprint after every leg,
//! with a bound on their rounding that holds on the CPU and on a Vulkan device;
//! [`check_on_the_cpu`] and [`check_on_the_device`] run many chains against it, and
//! [`reflection_chain_check`] checks the shader against the mirror.

mod bound;
mod check;
mod enclosure;
mod mirror;

pub use bound::{ChainStats, Sample, CHAIN_PRIMARY_ULPS, CHAIN_ULPS_PER_LEG};
pub use check::{check_on_the_cpu, check_on_the_device, reflection_chain_check};
pub use mirror::{
    chain_normal_change, chain_pixel_axis_diff, chain_primary, chain_reflect, chain_shader, reflection_chain,
    ChainArgs, ChainCamera, ChainLeg, ChainRay, ChainSample, ChainSamples, CHAIN_MAX_BOUNCES,
    CHAIN_ORTHOGRAPHIC, CHAIN_PINHOLE, CHAIN_SHADER_DIR, CHAIN_THIN_LENS,
};

use bound::Scale;
use glam::{DVec3, Vec2};
use proptest::prelude::*;

/// A mirror as a ray meets it. Curvatures follow `edge_curvature`'s convention: how fast the normal
/// turns along a direction, positive where the normals spread apart.
#[derive(Clone, Copy, Debug)]
pub enum Surface {
    /// A sphere of radius `radius` met from outside (convex) or inside (concave); with outward
    /// normals its curvature is `1 / radius` in every direction.
    Sphere {
        /// The radius.
        radius: f64,
        /// Met from inside.
        inside: bool,
    },
    /// A saddle met at its vertex from its "up" side or from below. With the up normal its
    /// principal curvatures are `along`, on the principal direction `axis_angle` from the chain's
    /// plane, and `across`, of opposite signs: locally the height `-(along x^2 + across y^2) / 2`
    /// above its tangent plane.
    Saddle {
        /// The principal curvature along the first principal direction.
        along: f64,
        /// The principal curvature across it.
        across: f64,
        /// Angle of the first principal direction from the chain's plane.
        axis_angle: f64,
        /// Met from below.
        from_below: bool,
    },
}

/// One reflection of a chain.
#[derive(Clone, Copy, Debug)]
pub struct Bounce {
    /// The mirror.
    pub surface: Surface,
    /// The mesh stores its normals flipped: inward on a sphere, down on a saddle.
    pub flipped_normals: bool,
    /// Distance travelled to the hit.
    pub distance: f64,
    /// Signed angle, in the chain's plane, between the reversed ray and the normal facing the ray.
    pub incidence: f64,
}

impl Bounce {
    /// Whether the stored normal points to the side the ray comes from.
    pub fn stored_normal_faces_the_ray(&self) -> bool {
        let outward_faces_the_ray = match self.surface {
            Surface::Sphere { inside, .. } => !inside,
            Surface::Saddle { from_below, .. } => !from_below,
        };
        outward_faces_the_ray != self.flipped_normals
    }

    /// The principal curvatures measured with the stored normals, and the angle of the first
    /// principal direction from the chain's plane.
    fn principal_curvatures(&self) -> (f64, f64, f64) {
        let sign = if self.flipped_normals { -1.0 } else { 1.0 };
        match self.surface {
            Surface::Sphere { radius, .. } => (sign / radius, sign / radius, 0.0),
            Surface::Saddle {
                along,
                across,
                axis_angle,
                ..
            } => (sign * along, sign * across, axis_angle),
        }
    }

    /// The normal curvature along the chain's plane (Euler: `k1 cos^2 + k2 sin^2`).
    fn in_plane_curvature(&self) -> f64 {
        let (k1, k2, angle) = self.principal_curvatures();
        k1 * angle.cos().powi(2) + k2 * angle.sin().powi(2)
    }

    fn mean_curvature(&self) -> f64 {
        let (k1, k2, _) = self.principal_curvatures();
        0.5 * (k1 + k2)
    }

    fn largest_curvature(&self) -> f64 {
        let (k1, k2, _) = self.principal_curvatures();
        k1.abs().max(k2.abs())
    }

    /// The mirror's leg of the chain: the ray arrives along `direction` with the pixel-step frame
    /// `frame` and meets the stored normal `normal`. The principal directions lie in the tangent
    /// plane, the first `axis_angle` from the chain's plane (the xz plane).
    fn leg(&self, comparison: Comparison, direction: DVec3, normal: DVec3, frame: [DVec3; 2]) -> ChainLeg {
        let (k1, k2, angle) = self.principal_curvatures();
        let in_plane = DVec3::Y.cross(normal);
        let first = in_plane * angle.cos() + DVec3::Y * angle.sin();
        let second = DVec3::Y * angle.cos() - in_plane * angle.sin();
        ChainLeg {
            distance: self.distance as f32,
            direction: direction.as_vec3(),
            normal: normal.as_vec3(),
            curvature: comparison.curvature(self) as f32,
            principal_curvatures: Vec2::new(k1 as f32, k2 as f32),
            first_principal_direction: first.as_vec3(),
            second_principal_direction: second.as_vec3(),
            right: frame[0].as_vec3(),
            down: frame[1].as_vec3(),
        }
    }
}

/// What the cone is compared with, and which curvature it is given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Comparison {
    /// The cone given the normal curvature in the chain's plane, against the differential's
    /// signed footprint along the in-plane pixel axis.
    InPlane,
    /// The cone given the mean curvature, against the mean of the differential's signed
    /// footprints along both pixel axes.
    Mean,
}

impl Comparison {
    fn curvature(self, bounce: &Bounce) -> f64 {
        match self {
            Comparison::InPlane => bounce.in_plane_curvature(),
            Comparison::Mean => bounce.mean_curvature(),
        }
    }

    /// The differential's footprint this comparison measures, from its signed footprints along the
    /// two pixel axes.
    fn footprint(self, footprint: Vec2) -> f64 {
        let (right, down) = (f64::from(footprint.x), f64::from(footprint.y));
        match self {
            Comparison::InPlane => right,
            Comparison::Mean => 0.5 * (right + down),
        }
    }
}

/// The unit vectors along which a pixel step right and a pixel step down move a primary footprint.
const PIXEL_STEPS: [DVec3; 2] = [DVec3::X, DVec3::NEG_Y];

/// A chain: the camera of its primary ray, its bounces and the distance travelled after the last
/// one. The camera looks down -z from the origin, and the chain's plane is the xz plane.
#[derive(Clone, Debug)]
pub struct Chain {
    /// The camera.
    pub camera: ChainCamera,
    /// The mirrors, in order.
    pub bounces: Vec<Bounce>,
    /// Distance travelled after the last mirror.
    pub final_distance: f64,
}

/// The reflection of `v` off a plane with unit normal `normal`, in f64.
fn reflect_exact(v: DVec3, normal: DVec3) -> DVec3 {
    v - 2.0 * v.dot(normal) * normal
}

impl Chain {
    /// The chain's legs, one per bounce and one to the plane across the last ray, with the cone
    /// given the curvature `comparison` compares: the geometry followed exactly in f64 and rounded
    /// to f32.
    pub fn legs(&self, comparison: Comparison) -> Vec<ChainLeg> {
        let (mut direction, mut frame) = (DVec3::NEG_Z, PIXEL_STEPS);
        let mut legs = Vec::with_capacity(self.bounces.len() + 1);
        for bounce in &self.bounces {
            let facing = -direction * bounce.incidence.cos() + frame[0] * bounce.incidence.sin();
            let normal = if bounce.stored_normal_faces_the_ray() {
                facing
            } else {
                -facing
            };
            legs.push(bounce.leg(comparison, direction, normal, frame));
            direction = reflect_exact(direction, facing);
            frame = frame.map(|axis| reflect_exact(axis, facing));
        }
        legs.push(ChainLeg {
            distance: self.final_distance as f32,
            direction: direction.as_vec3(),
            normal: direction.as_vec3(),
            right: frame[0].as_vec3(),
            down: frame[1].as_vec3(),
            ..ChainLeg::default()
        });
        legs
    }

    /// The arguments of `reflection_chain` for this chain: its legs, padded with zero legs.
    pub fn args(&self, comparison: Comparison) -> ChainArgs {
        let mut legs = self.legs(comparison).into_iter();
        let mut next = || legs.next().unwrap_or_default();
        let bounces = self.bounces.len() as u32;
        (self.camera, bounces, next(), next(), next(), next(), next())
    }

    /// The chain's samples as `traced` (by the mirror or a shader) reports them: the cone's width
    /// and the footprint `comparison` measures after every leg, with their rounding bound.
    pub fn samples(&self, comparison: Comparison, traced: &ChainSamples) -> Vec<Sample> {
        let traced = traced.in_order();
        let mut scale = Scale::new(chain_primary(self.camera).cone);
        let mut min_cos = 1.0f64;
        let mut samples = Vec::with_capacity(self.bounces.len() + 1);
        for (index, bounce) in self.bounces.iter().enumerate() {
            min_cos = min_cos.min(bounce.incidence.cos());
            let at_hit = scale.at(bounce.distance);
            samples.push(Sample::new(index + 1, traced[index], comparison, at_hit, min_cos));
            scale.reflect(
                bounce.distance,
                bounce.largest_curvature(),
                bounce.incidence.cos(),
            );
        }
        let legs = self.bounces.len() + 1;
        let at_end = scale.at(self.final_distance);
        samples.push(Sample::new(legs, traced[legs - 1], comparison, at_end, min_cos));
        samples
    }

    /// The chain followed by the Rust mirror.
    pub fn trace(&self, comparison: Comparison) -> ChainSamples {
        let (camera, bounces, leg0, leg1, leg2, leg3, leg4) = self.args(comparison);
        reflection_chain(camera, bounces, leg0, leg1, leg2, leg3, leg4)
    }
}

/// In-plane chains a test follows, on the CPU and in each shader language.
pub const IN_PLANE_CHAINS: u32 = 80_000;

/// Head-on chains with a saddle a test follows, on the CPU and in each shader language.
pub const HEAD_ON_CHAINS: u32 = 20_000;

/// Largest angle of incidence in the in-plane chains (`cos >= 0.5`).
const MAX_INCIDENCE: f64 = std::f64::consts::FRAC_PI_3;

fn log_uniform(lo: f64, hi: f64) -> BoxedStrategy<f64> {
    (lo.ln()..hi.ln()).prop_map(f64::exp).boxed()
}

/// A pinhole, orthographic or thin-lens camera, 101 to 1999 pixels square, with pixel spreads from
/// 2e-4 to 0.03.
fn camera() -> BoxedStrategy<ChainCamera> {
    let size = (50u32..1000).prop_map(|half| (2 * half + 1) as f32);
    let fov_y = 0.2f32..2.0;
    prop_oneof![
        (fov_y.clone(), size.clone()).prop_map(|(fov_y, size)| ChainCamera::pinhole(fov_y, size)),
        (0.1f32..10.0, size.clone()).prop_map(|(height, size)| ChainCamera::orthographic(height, size)),
        (fov_y, size, 0.001f32..0.2, 0.5f32..20.0).prop_map(|(fov_y, size, aperture, focus)| {
            ChainCamera::thin_lens(fov_y, size, aperture, focus)
        }),
    ]
    .boxed()
}

/// A sphere of radius 0.2 to 20, met from outside or inside.
fn sphere_mirror() -> BoxedStrategy<Surface> {
    (log_uniform(0.2, 20.0), any::<bool>())
        .prop_map(|(radius, inside)| Surface::Sphere { radius, inside })
        .boxed()
}

/// A saddle with principal curvatures of 0.05 to 5 in magnitude, of opposite signs, met from
/// either side.
fn saddle_mirror(axis_angle: BoxedStrategy<f64>) -> BoxedStrategy<Surface> {
    let magnitude = || log_uniform(0.05, 5.0);
    (magnitude(), magnitude(), any::<bool>(), axis_angle, any::<bool>())
        .prop_map(|(along, across, positive_along, axis_angle, from_below)| {
            let sign = if positive_along { 1.0 } else { -1.0 };
            Surface::Saddle {
                along: sign * along,
                across: -sign * across,
                axis_angle,
                from_below,
            }
        })
        .boxed()
}

/// A bounce off `surface`, its normals stored either way, 0.1 to 20 units from the last one.
fn bounce(surface: BoxedStrategy<Surface>, incidence: BoxedStrategy<f64>) -> BoxedStrategy<Bounce> {
    (surface, any::<bool>(), log_uniform(0.1, 20.0), incidence)
        .prop_map(|(surface, flipped_normals, distance, incidence)| Bounce {
            surface,
            flipped_normals,
            distance,
            incidence,
        })
        .boxed()
}

/// 1 to 4 bounces in one plane, off spheres and off saddles whose principal directions lie along
/// and across the plane, at incidences up to 60 degrees; compared [`Comparison::InPlane`].
pub fn in_plane_chain() -> BoxedStrategy<Chain> {
    let axis_angle = prop_oneof![Just(0.0), Just(std::f64::consts::FRAC_PI_2)].boxed();
    let surface = prop_oneof![2 => sphere_mirror(), 1 => saddle_mirror(axis_angle)].boxed();
    let incidence = (-MAX_INCIDENCE..MAX_INCIDENCE).boxed();
    let bounces = prop::collection::vec(bounce(surface, incidence), 1..=CHAIN_MAX_BOUNCES as usize);
    (camera(), bounces, log_uniform(0.1, 20.0))
        .prop_map(|(camera, bounces, final_distance)| Chain {
            camera,
            bounces,
            final_distance,
        })
        .boxed()
}

/// 1 to 4 head-on bounces: one saddle (principal directions at any angle) among up to 3 spheres;
/// compared [`Comparison::Mean`].
pub fn head_on_chain_with_one_saddle() -> BoxedStrategy<Chain> {
    let head_on = || Just(0.0).boxed();
    let spheres = prop::collection::vec(bounce(sphere_mirror(), head_on()), 0..CHAIN_MAX_BOUNCES as usize);
    let one_saddle = bounce(saddle_mirror((0.0..std::f64::consts::PI).boxed()), head_on());
    (camera(), spheres, one_saddle, 0usize..4, log_uniform(0.1, 20.0))
        .prop_map(|(camera, mut bounces, one_saddle, position, final_distance)| {
            bounces.insert(position % (bounces.len() + 1), one_saddle);
            Chain {
                camera,
                bounces,
                final_distance,
            }
        })
        .boxed()
}
