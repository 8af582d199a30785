//! The enclosure of `reflection_chain`: the chain re-evaluated in interval arithmetic
//! ([`shader_proptest::interval`]) on the same f32 inputs, in the mirror's order of operations
//! (`mirror.rs`), widened after every operation by the rounding that Vulkan allows the device (and
//! that the mirror makes).

use super::mirror::{ChainArgs, ChainCamera, ChainLeg};
use super::{CHAIN_MAX_BOUNCES, CHAIN_ORTHOGRAPHIC, CHAIN_PINHOLE};
use glam::{Vec2, Vec3};
use ray_footprint::ray_cone::{MAX_FOV_Y, MIN_COS, MIN_MAGNITUDE};
use ray_footprint_cases::ray_diff::camera::eye_ray_diff::eye_ray_direction_derivatives;
use ray_footprint_cases::ray_diff::reflection::reflect_ray_diff::reflected_direction;
use ray_footprint_cases::ray_diff::transfer::transfer::transferred_origin;
use shader_proptest::interval::{interval3, Interval, Interval3, IntervalVec};

/// A ray of the chain in intervals: the cone, and the differential's origin and direction changes
/// per pixel step right and down.
#[derive(Clone, Copy)]
struct IntervalRay {
    width: Interval,
    spread: Interval,
    d_origin: [Interval3; 2],
    d_direction: [Interval3; 2],
}

fn pixel_spread_angle_small(fov_y: f32, image_height: f32) -> Interval {
    Interval::c(2.0) * Interval::tan_exact(0.5 * fov_y.clamp(0.0, MAX_FOV_Y))
        / Interval::exact(image_height.max(1.0))
}

fn chain_pixel_axis_ray(width: Interval, spread: Interval) -> IntervalRay {
    let zero = Interval::c(0.0);
    IntervalRay {
        width,
        spread,
        d_origin: [
            IntervalVec([width, zero, zero]),
            IntervalVec([zero, -width, zero]),
        ],
        d_direction: [
            IntervalVec([spread, zero, zero]),
            IntervalVec([zero, -spread, zero]),
        ],
    }
}

fn chain_primary(camera: ChainCamera) -> IntervalRay {
    if camera.kind == CHAIN_PINHOLE {
        let size = Vec2::splat(camera.image_height);
        let centre = (0.5 * size).floor();
        let eye = (centre, size, camera.fov_y, Vec3::X, Vec3::Y, Vec3::Z);
        let (dd_dx, dd_dy) = eye_ray_direction_derivatives(&eye);
        let zero = IntervalVec([Interval::c(0.0); 3]);
        return IntervalRay {
            width: Interval::c(0.0),
            spread: pixel_spread_angle_small(camera.fov_y, camera.image_height),
            d_origin: [zero, zero],
            d_direction: [dd_dx, dd_dy],
        };
    }
    if camera.kind == CHAIN_ORTHOGRAPHIC {
        let width = Interval::exact(camera.view_height) / Interval::exact(camera.image_height.max(1.0));
        return chain_pixel_axis_ray(width, Interval::c(0.0));
    }
    let alpha = pixel_spread_angle_small(camera.fov_y, camera.image_height);
    let spread =
        alpha - Interval::exact(camera.aperture) / Interval::exact(camera.focus_distance.max(MIN_MAGNITUDE));
    chain_pixel_axis_ray(Interval::exact(camera.aperture), spread)
}

fn chain_normal_change(leg: &ChainLeg, dp: Interval3) -> Interval3 {
    let (first, second) = (
        interval3(leg.first_principal_direction),
        interval3(leg.second_principal_direction),
    );
    let k = leg.principal_curvatures;
    first * (Interval::exact(k.x) * first.dot(dp)) + second * (Interval::exact(k.y) * second.dot(dp))
}

fn chain_reflect(ray: IntervalRay, at_hit: [Interval3; 2], width: Interval, leg: &ChainLeg) -> IntervalRay {
    let facing = -interval3(leg.normal).dot(interval3(leg.direction));
    let beta =
        (Interval::c(2.0) * Interval::exact(leg.curvature) * width).div_away(facing, f64::from(MIN_COS));
    let reflected = |axis: usize| {
        let normal_change = chain_normal_change(leg, at_hit[axis]);
        reflected_direction(ray.d_direction[axis], leg.direction, leg.normal, normal_change)
    };
    IntervalRay {
        width,
        spread: ray.spread + beta,
        d_origin: at_hit,
        d_direction: [reflected(0), reflected(1)],
    }
}

/// The 15 outputs of `reflection_chain`: width and the two footprints after each leg, exactly 0
/// past the last.
pub(super) fn reflection_chain(
    &(camera, bounces, leg0, leg1, leg2, leg3, leg4): &ChainArgs,
) -> Vec<Interval> {
    let legs = [leg0, leg1, leg2, leg3, leg4];
    let reflections = bounces.min(CHAIN_MAX_BOUNCES) as usize;
    let mut outputs = vec![Interval::c(0.0); 15];
    let mut ray = chain_primary(camera);
    for (index, leg) in legs.iter().enumerate().take(reflections + 1) {
        let at_hit = [0, 1].map(|axis| {
            transferred_origin(
                ray.d_origin[axis],
                ray.d_direction[axis],
                leg.direction,
                leg.distance,
                leg.normal,
            )
        });
        let width = ray.width + ray.spread * Interval::exact(leg.distance);
        outputs[3 * index] = width;
        outputs[3 * index + 1] = at_hit[0].dot(interval3(leg.right));
        outputs[3 * index + 2] = at_hit[1].dot(interval3(leg.down));
        if index < reflections {
            ray = chain_reflect(ray, at_hit, width, leg);
        }
    }
    outputs
}
