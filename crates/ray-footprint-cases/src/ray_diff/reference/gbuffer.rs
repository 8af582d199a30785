//! References of the G-buffer section: a plane seen through a pinhole with one neighbour pixel
//! occluded (a depth discontinuity), its exact hits and reflections; neighbour rays intersected
//! with the tangent plane as a 3x3 system.

use super::super::{enclosure, GBufferArgs};
use super::{components, listed, widths};
use crate::exact::{log_uniform, mirrored, tangent, towards, unit};
use crate::reference::{Kind, Reference, U};
use glam::{DMat3, DVec2, DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{Derivatives3, GBufferSample, RayDiff};

/// A plane seen by a pinhole camera at the origin: the eye directions of a pixel and its four
/// neighbours (right, left, below, above), the plane's unit normal, and which neighbour (if any)
/// sees an occluder at another depth.
#[derive(Clone, Debug)]
struct Scene {
    directions: [DVec3; 5],
    plane_point: DVec3,
    normal: DVec3,
    /// 0: none; 1 to 4: the right, left, lower or upper neighbour.
    occluded: usize,
    /// The occluder's distance as a multiple of the plane's, and its unit normal.
    occluder: (f64, DVec3),
}

impl Scene {
    fn strategy() -> BoxedStrategy<Scene> {
        (
            (
                unit(),
                0.0f64..6.3,
                0.3f64..1.5,
                200.0f64..2000.0,
                0.5f64..2.0,
                (0.05f64..0.95, 0.05f64..0.95),
            ),
            (log_uniform(0.0, 2.0), 0.2f64..1.0, 0.0f64..6.3),
            (0usize..5, prop_oneof![0.3f64..0.7, 1.5f64..4.0], unit()),
        )
            .prop_map(
                |(
                    (view, roll, fov, height, aspect, (fx, fy)),
                    (distance, cosine, angle),
                    (occluded, factor, other),
                )| {
                    let right = tangent(view, roll);
                    let up = view.cross(right);
                    let size = DVec2::new((height * aspect).round(), height.round());
                    let pixel = (DVec2::new(fx, fy) * size).floor();
                    let f = (0.5 * fov).tan();
                    let direction = |at: DVec2| {
                        let c = (at + 0.5) / size * 2.0 - 1.0;
                        (c.x * size.x / size.y * f * right - c.y * f * up - view).normalize()
                    };
                    let steps = [DVec2::ZERO, DVec2::X, -DVec2::X, DVec2::Y, -DVec2::Y];
                    let directions = steps.map(|step| direction(pixel + step));
                    Scene {
                        directions,
                        plane_point: directions[0] * distance,
                        normal: towards(directions[0], cosine, angle),
                        occluded,
                        occluder: (factor, other),
                    }
                },
            )
            .boxed()
    }

    /// The exact G-buffer sample of pixel `i` (0 the centre, then right, left, below, above): the
    /// eye direction, the distance to its hit, the normal there.
    fn sample(&self, i: usize) -> (DVec3, f64, DVec3) {
        let e = self.directions[i];
        let distance = self.plane_point.dot(self.normal) / e.dot(self.normal);
        if i == self.occluded {
            (e, distance * self.occluder.0, self.occluder.1)
        } else {
            (e, distance, self.normal)
        }
    }

    /// A depth epsilon four times the plane's largest step between neighbours, plus 16 f32 ULP of
    /// the depth (the rounding of the f32 distances): every step on the plane stays below it, every
    /// step to the occluder (at 0.3 to 4 times the depth) far above.
    fn epsilon(&self) -> f64 {
        let centre = self.sample(0).1;
        let largest = (1..5)
            .filter(|&i| i != self.occluded)
            .map(|i| (self.plane_point.dot(self.normal) / self.directions[i].dot(self.normal) - centre).abs())
            .fold(0.0, f64::max);
        4.0 * largest + 16.0 * U * centre
    }

    fn arguments(&self) -> GBufferArgs {
        let sample = |i: usize| {
            let (e, distance, n) = self.sample(i);
            GBufferSample {
                eye_direction: e.as_vec3(),
                distance: distance as f32,
                normal: n.as_vec3(),
            }
        };
        (
            sample(0),
            sample(1),
            sample(2),
            sample(3),
            sample(4),
            self.epsilon() as f32,
        )
    }
}

/// How far the f32 sample `s` moves the hit `t e` and the reflected direction from the exact
/// `(e, t, n)` (both formulas evaluated in f64 on the rounded inputs).
fn input_rounding(s: GBufferSample, (e, t, n): (DVec3, f64, DVec3)) -> (f64, f64) {
    let (e32, t32, n32) = (
        s.eye_direction.as_dvec3(),
        f64::from(s.distance),
        s.normal.as_dvec3(),
    );
    let position = (e32 * t32 - e * t).length();
    let direction = (e32 - n32 * (2.0 * n32.dot(e32)) - mirrored(e, n)).length();
    (position, direction)
}

/// `rf_gbuffer_ray_diff`.
pub(in crate::ray_diff) fn gbuffer_ray_diff() -> Reference<GBufferArgs, RayDiff> {
    Reference::new(
        Kind::ExactGeometry,
        "a plane seen through a pinhole, one neighbour occluded at another depth: the exact one-pixel differences of the hits and of the reflected eye directions on the plane, from the side that stays on it (RTG Eq. 23-24, Sec. 20.3.3)",
        Scene::strategy,
        |scene, gbuffer_ray_diff| {
            let args = scene.arguments();
            let got = gbuffer_ray_diff(args);
            let samples = [args.0, args.1, args.2, args.3, args.4];
            // Per axis: the forward neighbour unless it is the occluder, then the backward one.
            let pair = |forward: usize, backward: usize| {
                if scene.occluded == forward {
                    (backward, 0)
                } else {
                    (0, forward)
                }
            };
            let ((x0, x1), (y0, y1)) = (pair(1, 2), pair(3, 4));
            let hit = |i: usize| {
                let (e, t, _) = scene.sample(i);
                e * t
            };
            let direction = |i: usize| {
                let (e, _, n) = scene.sample(i);
                mirrored(e, n)
            };
            let expected = listed(
                &[hit(x1) - hit(x0), hit(y1) - hit(y0), direction(x1) - direction(x0), direction(y1) - direction(y0)],
                1,
            );
            let rounding = |i: usize| input_rounding(samples[i], scene.sample(i));
            let moved = |a: usize, b: usize| {
                let ((pa, da), (pb, db)) = (rounding(a), rounding(b));
                (pa + pb, da + db)
            };
            let (x, y) = (moved(x0, x1), moved(y0, y1));
            let extra = [x.0, y.0, x.1, y.1];
            let bounds = widths(&enclosure::gbuffer_ray_diff(&args));
            Some(components(got, &expected, |i| bounds[i] + 1.01 * extra[i / 4] + 1.0e-12))
        },
    )
}

/// `rf_tangent_plane_offsets`.
pub(in crate::ray_diff) fn tangent_plane_offsets() -> Reference<(Vec3, Vec3, Vec3, f32, Vec3), Derivatives3> {
    Reference::new(
        Kind::ExactGeometry,
        "the neighbour rays from the eye intersected with the tangent plane at t rd, each solved as a 3x3 system (ray parameter and in-plane coordinates) in f64 (Quilez)",
        || {
            let offset = || (0.0f64..6.3, log_uniform(-4.0, -2.0));
            (unit(), (offset(), offset()), log_uniform(-1.0, 3.0), 0.05f64..1.0, 0.0f64..6.3).boxed()
        },
        |&(rd, ((ax, lx), (ay, ly)), t, cosine, angle), tangent_plane_offsets| {
            let neighbour = |a: f64, l: f64| (rd + tangent(rd, a) * l).normalize().as_vec3();
            let (rdx, rdy, normal) = (neighbour(ax, lx), neighbour(ay, ly), towards(rd, cosine, angle).as_vec3());
            let (rd, t) = (rd.as_vec3(), t as f32);
            let got = tangent_plane_offsets((rd, rdx, rdy, t, normal));
            let hit = rd.as_dvec3() * f64::from(t);
            let n = normal.as_dvec3();
            let (u, v) = (n.any_orthonormal_vector(), n.cross(n.any_orthonormal_vector()));
            let offset = |ray: Vec3| {
                let ray = ray.as_dvec3();
                let solution = DMat3::from_cols(ray, -u, -v).inverse() * hit;
                ray * solution.x - hit
            };
            let expected = listed(&[offset(rdx), offset(rdy)], 0);
            let rounding = [
                enclosure::tangent_plane_offset(rd, rdx, t, normal).components(),
                enclosure::tangent_plane_offset(rd, rdy, t, normal).components(),
            ]
            .concat();
            let bounds = widths(&rounding);
            Some(components(got, &expected, |i| bounds[i] + 1.0e-12 * hit.length()))
        },
    )
}
