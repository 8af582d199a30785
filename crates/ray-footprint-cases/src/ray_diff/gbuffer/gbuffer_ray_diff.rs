//! The proof of [`gbuffer_ray_diff`](ray_footprint::ray_diff::gbuffer_ray_diff): its record, its
//! enclosure and its reference, a plane with one neighbour occluded.

use crate::degenerate::{parts, value};
use crate::exact::{log_uniform, mirrored, tangent, towards, unit};
use crate::ray_diff::changes::*;
use crate::ray_diff::intervals;
use crate::ray_diff::reference::{components, listed, widths};
use crate::record::Record;
use crate::reference::{Kind, Reference, U};
use crate::special::Perturb;
use crate::strategy::{distance, magnitude, normal_and_direction};
use glam::{DVec2, DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_diff::{self as rd, GBufferSample, RayDiff};
use ray_footprint::shaders::Module;
use shader_proptest::interval::{interval3, Interval, Interval3};
use shader_proptest::{Args, Value};

/// The arguments of `gbuffer_ray_diff`: centre, right, left, below, above, depth epsilon.
pub type GBufferArgs = (
    GBufferSample,
    GBufferSample,
    GBufferSample,
    GBufferSample,
    GBufferSample,
    f32,
);

/// A G-buffer pixel: unit eye direction, distance, unit normal.
fn gbuffer_sample() -> BoxedStrategy<GBufferSample> {
    (normal_and_direction(), distance())
        .prop_map(|((normal, eye_direction), distance)| GBufferSample {
            eye_direction,
            distance,
            normal,
        })
        .boxed()
}

/// A G-buffer sample at `distance` straight down -Z onto a plane facing +Z.
fn sample_at(distance: f32) -> GBufferSample {
    GBufferSample {
        eye_direction: -Vec3::Z,
        distance,
        normal: Vec3::Z,
    }
}

/// The record of `rf_gbuffer_ray_diff`.
pub fn record() -> Record<impl Args + Perturb, impl Value> {
    let x = Vec3::X;
    let z = Vec3::Z;
    Record::new(
        Module::RayDiff,
        "gbuffer_ray_diff",
        |(c, r, l, b, a, eps)| rd::gbuffer_ray_diff(c, r, l, b, a, eps),
        // The neighbour choice compares correctly rounded differences: the device makes the same
        // choice as the mirror, so only the chosen branch is enclosed.
        || {
            (
                gbuffer_sample(),
                (gbuffer_sample(), gbuffer_sample()),
                (gbuffer_sample(), gbuffer_sample()),
                magnitude(),
            )
                .prop_map(|(c, (r, l), (b, a), eps)| (c, r, l, b, a, eps))
                .boxed()
        },
    )
    .enclosure(enclosure)
    .reference(reference())
    .symmetry(Symmetry::rotation(
        "every eye direction and normal turned: the differential turned",
        |&(c, right, left, below, above, eps): &(
            GBufferSample,
            GBufferSample,
            GBufferSample,
            GBufferSample,
            GBufferSample,
            f32,
        ),
         r| {
            let turn = |g: GBufferSample| GBufferSample {
                eye_direction: r * g.eye_direction,
                normal: r * g.normal,
                ..g
            };
            (turn(c), turn(right), turn(left), turn(below), turn(above), eps)
        },
        |diff: RayDiff, r| turned(diff, r.transpose()),
    ))
    .symmetry(Symmetry::scale(
        "the distances and the depth tolerance scaled by s: the origin parts by s",
        |&(c, right, left, below, above, eps): &(
            GBufferSample,
            GBufferSample,
            GBufferSample,
            GBufferSample,
            GBufferSample,
            f32,
        ),
         s| {
            let far = |g: GBufferSample| GBufferSample {
                distance: g.distance * s,
                ..g
            };
            (far(c), far(right), far(left), far(below), far(above), eps * s)
        },
        |diff: RayDiff, s| origins_scaled(diff, 1.0 / s),
    ))
    .symmetry(Symmetry::exchange(
        "the image axes swapped (right and left with below and above): the x and y parts exchanged",
        |&(c, right, left, below, above, eps): &(
            GBufferSample,
            GBufferSample,
            GBufferSample,
            GBufferSample,
            GBufferSample,
            f32,
        )| (c, below, above, right, left, eps),
        swapped,
    ))
    .fuzz(|d| {
        (
            d.gbuffer_sample(),
            d.gbuffer_sample(),
            d.gbuffer_sample(),
            d.gbuffer_sample(),
            d.gbuffer_sample(),
            d.distance(),
        )
    })
    .degenerate(vec![
        value(
            "all five samples equal",
            "zero differential",
            (
                sample_at(1.0),
                sample_at(1.0),
                sample_at(1.0),
                sample_at(1.0),
                sample_at(1.0),
                0.1,
            ),
            parts(RayDiff::ZERO),
        ),
        value(
            "depth edge on the right (t: left 1.5, centre 1, right 10), epsilon 0.1",
            "the left neighbour: dO/dx = t(0) e(0) - t(-1) e(-1) = (0, 0, 0.5)",
            (
                sample_at(1.0),
                sample_at(10.0),
                sample_at(1.5),
                sample_at(1.0),
                sample_at(1.0),
                0.1,
            ),
            parts(RayDiff::new(0.5 * z, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO)),
        ),
        value(
            "step to the right exactly depth_epsilon (right 1.5, left 1.25, epsilon 0.5)",
            "the right neighbour, dO/dx = (0, 0, -0.5): switching needs a larger step",
            (
                sample_at(1.0),
                sample_at(1.5),
                sample_at(1.25),
                sample_at(1.0),
                sample_at(1.0),
                0.5,
            ),
            parts(RayDiff::new(-0.5 * z, Vec3::ZERO, Vec3::ZERO, Vec3::ZERO)),
        ),
        value(
            "right neighbour's normal perpendicular to its eye ray",
            "dD/dx = e(+1) - reflect(e(0), n(0)) = (0, 0, -2)",
            (
                sample_at(1.0),
                GBufferSample {
                    normal: x,
                    ..sample_at(1.0)
                },
                sample_at(1.0),
                sample_at(1.0),
                sample_at(1.0),
                0.1,
            ),
            parts(RayDiff::new(Vec3::ZERO, Vec3::ZERO, -2.0 * z, Vec3::ZERO)),
        ),
    ])
}

/// The neighbour choice, in f32 exactly as the device makes it (a correctly rounded subtraction and
/// comparisons: no rounding freedom).
fn use_backward(
    center: GBufferSample,
    forward: GBufferSample,
    backward: GBufferSample,
    epsilon: f32,
) -> bool {
    let forward_step = (forward.distance - center.distance).abs();
    let backward_step = (backward.distance - center.distance).abs();
    forward_step > epsilon && backward_step < forward_step
}

fn gbuffer_steps(start: GBufferSample, end: GBufferSample) -> (Interval3, Interval3) {
    let reflect = |g: GBufferSample| {
        let (e, n) = (interval3(g.eye_direction), interval3(g.normal));
        e - n * (Interval::c(2.0) * n.dot(e))
    };
    (
        interval3(end.eye_direction) * Interval::exact(end.distance)
            - interval3(start.eye_direction) * Interval::exact(start.distance),
        reflect(end) - reflect(start),
    )
}

/// `rf_gbuffer_ray_diff` in interval arithmetic, in the same order of operations.
fn enclosure(&(center, right, left, below, above, epsilon): &GBufferArgs) -> Vec<Interval> {
    let pair = |forward, backward| {
        if use_backward(center, forward, backward, epsilon) {
            gbuffer_steps(backward, center)
        } else {
            gbuffer_steps(center, forward)
        }
    };
    let (x, y) = (pair(right, left), pair(below, above));
    intervals::ray_diff(x.0, y.0, x.1, y.1)
}

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

/// The reference of `rf_gbuffer_ray_diff`.
fn reference() -> Reference<GBufferArgs, RayDiff> {
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
            let bounds = widths(&enclosure(&args));
            Some(components(got, &expected, |i| bounds[i] + 1.01 * extra[i / 4] + 1.0e-12))
        },
    )
}
