//! Interval enclosures of the ray-cone functions that chain dozens of operations (refraction and
//! roughness): each function here re-evaluates the shader function of its name, or a step of one,
//! in interval arithmetic ([`shader_proptest::interval`]) in the same order of operations as
//! `src/ray_cone.rs`, and its width is the record's tolerance. Also here: whether a refraction's decisions are certain, so that
//! the check keeps to cases whose enclosure says something. The shape operator's least-squares fit
//! and the normal curvature along a direction are here too, with their inputs as intervals so
//! that a reference can enclose an exact value with its f32 rounding.

use super::RefractArgs;
use crate::ray_diff::WELL_CONDITIONED;
use glam::Vec3;
use ray_footprint::ray_cone::{
    RayCone, MAX_INCIDENCE_ANGLE, MAX_NORMAL_SPREAD, MIN_COS, MIN_MAGNITUDE, MIN_ROUGHNESS_DENOMINATOR,
};
use shader_proptest::interval::{interval3, select, Interval, Interval2, Interval3, IntervalVec};

/// `(sin, cos)` of an interval.
fn angle_sin_cos(angle: Interval) -> Interval2 {
    IntervalVec([angle.sin(), angle.cos()])
}

fn incidence_sin_cos(normal: Vec3, direction: Vec3, cosine: Interval) -> Interval2 {
    let tangential = interval3(direction) - interval3(normal) * cosine;
    let sin_cos = IntervalVec([tangential.dot(tangential).sqrt(), cosine.abs()]);
    let length = sin_cos.dot(sin_cos).sqrt();
    let min = f64::from(MIN_MAGNITUDE);
    let components = select(
        length.hi < min,
        length.lo < min,
        || vec![Interval::c(0.0), Interval::c(1.0)],
        || (sin_cos / length.at_least(min)).components(),
    );
    IntervalVec([components[0], components[1]])
}

fn boundary_incidence(incidence: Interval2, local: Interval2, side: f64) -> Interval2 {
    let ([sin_i, cos_i], [sin_q, cos_q]) = (incidence.0, local.0);
    IntervalVec([
        sin_i * cos_q + Interval::c(side) * cos_i * sin_q,
        cos_i * cos_q - Interval::c(side) * sin_i * sin_q,
    ])
}

fn refracted_sin_cos(incidence: Interval2, eta: f32) -> Interval2 {
    let [sin, cos] = incidence.0;
    let eta = Interval::exact(eta);
    let cos2 = cos * cos + ((Interval::c(1.0) - eta) * sin) * ((Interval::c(1.0) + eta) * sin);
    IntervalVec([(eta * sin).clamp_c(-1.0, 1.0), cos2.max_c(0.0).sqrt()])
}

fn boundary_hit(width: f32, side: f64, incidence: Interval2, half_spread: Interval2) -> Interval {
    let [sin_i, cos_i] = incidence.0;
    let [sin_h, cos_h] = half_spread.0;
    let cos_boundary = cos_i * cos_h - Interval::c(side) * sin_i * sin_h;
    Interval::c(side) * Interval::c(0.5) * Interval::exact(width) * cos_h
        / cos_boundary.max_c(f64::from(MIN_COS))
}

fn boundary_offset(
    hit: Interval,
    side: f64,
    refracted: Interval2,
    tilt: Interval2,
    transmitted: Interval2,
) -> Interval {
    let ([sin_tau, cos_tau], [sin_tilt, cos_tilt]) = (refracted.0, tilt.0);
    let cos_rho = cos_tau * cos_tilt + Interval::c(side) * sin_tau * sin_tilt;
    let sin_rho = sin_tau * cos_tilt - Interval::c(side) * cos_tau * sin_tilt;
    hit * cos_rho / (cos_rho * transmitted.0[1] + sin_rho * transmitted.0[0]).max_c(f64::from(MIN_COS))
}

fn refracted_sine_gap(
    eta: f32,
    incidence: Interval2,
    local: Interval2,
    upper: Interval2,
    lower: Interval2,
) -> Interval {
    let eta = Interval::exact(eta);
    let (upper_sine, lower_sine) = (eta * upper.0[0], eta * lower.0[0]);
    let (upper_size, lower_size) = (upper_sine.abs(), lower_sine.abs());
    select(
        upper_size.hi <= 1.0 && lower_size.hi <= 1.0,
        upper_size.lo <= 1.0 && lower_size.lo <= 1.0,
        || vec![Interval::c(2.0) * eta * incidence.0[1] * local.0[0]],
        || vec![upper_sine.clamp_c(-1.0, 1.0) - lower_sine.clamp_c(-1.0, 1.0)],
    )[0]
}

fn refracted_angle_between(sine_gap: Interval, upper: Interval2, lower: Interval2) -> Interval {
    let ([sin_u, cos_u], [sin_l, cos_l]) = (upper.0, lower.0);
    let cos_between = cos_u * cos_l + sin_u * sin_l;
    let cos_sum = (cos_u + cos_l)
        .max((sine_gap * (sin_u + sin_l)).abs().sqrt())
        .max_c(f64::from(MIN_MAGNITUDE));
    let sin_between = sine_gap * (Interval::c(1.0) + cos_between) / cos_sum;
    Interval::atan2(sin_between, cos_between)
}

/// What the two boundary rays of a transmitted cone share: the central ray's incidence and
/// transmitted `(sin, cos)`, the boundary rays' angle to it (`half spread + tilt`), the half
/// spread and the normal tilt as `(sin, cos)`, the cone's width and the relative index.
struct BoundaryInputs {
    incidence: Interval2,
    transmitted: Interval2,
    local: Interval2,
    half: Interval2,
    tilt: Interval2,
    width: f32,
    index: f32,
}

/// One boundary ray of a transmitted cone after refraction: its incidence, its refracted
/// `(sin, cos)`, and its offset from the central transmitted ray.
struct BoundaryRay {
    incidence: Interval2,
    refracted: Interval2,
    offset: Interval,
}

/// The boundary ray on `side` (+1 upper, -1 lower): the steps of `refract_ray_cone` that both
/// boundary rays take (`boundary_incidence`, `refracted_sin_cos`, `boundary_hit`,
/// `boundary_offset`).
fn boundary_ray(inputs: &BoundaryInputs, side: f64) -> BoundaryRay {
    let incidence = boundary_incidence(inputs.incidence, inputs.local, side);
    let refracted = refracted_sin_cos(incidence, inputs.index);
    let hit = boundary_hit(inputs.width, side, inputs.incidence, inputs.half);
    BoundaryRay {
        incidence,
        refracted,
        offset: boundary_offset(hit, side, refracted, inputs.tilt, inputs.transmitted),
    }
}

/// `normal_tilt`: half the clamped normal spread, with the width's sign.
fn normal_tilt(width: f32, facing_spread: f32) -> Interval {
    let signed_half = if width < 0.0 { -0.5 } else { 0.5 };
    Interval::c(signed_half) * Interval::exact(facing_spread.clamp(-MAX_NORMAL_SPREAD, MAX_NORMAL_SPREAD))
}

/// The transmitted cone (its clamps cover the part of `eta sin i`'s interval above 1).
fn transmitted_cone(cone: RayCone, incidence: Interval2, facing_spread: f32, index: f32) -> Vec<Interval> {
    let limit = (Interval::c(f64::from(MAX_INCIDENCE_ANGLE))
        - Interval::atan2(incidence.0[0], incidence.0[1]))
    .max_c(0.0);
    let half_spread = (Interval::c(0.5) * Interval::exact(cone.spread_angle))
        .max(-limit)
        .min(limit);
    let tilt = normal_tilt(cone.width, facing_spread);
    let inputs = BoundaryInputs {
        incidence,
        transmitted: refracted_sin_cos(incidence, index),
        local: angle_sin_cos(half_spread + tilt),
        half: angle_sin_cos(half_spread),
        tilt: angle_sin_cos(tilt),
        width: cone.width,
        index,
    };
    let (upper, lower) = (boundary_ray(&inputs, 1.0), boundary_ray(&inputs, -1.0));
    let sine_gap = refracted_sine_gap(index, incidence, inputs.local, upper.incidence, lower.incidence);
    vec![
        upper.offset - lower.offset,
        refracted_angle_between(sine_gap, upper.refracted, lower.refracted) - Interval::c(2.0) * tilt,
        Interval::c(0.0),
    ]
}

/// Both branches of `refract_ray_cone` for one normal orientation (`facing_spread`).
fn refract_facing(
    &(cone, normal, direction, _, eta): &RefractArgs,
    cosine: Interval,
    facing_spread: f32,
) -> Vec<Interval> {
    let incidence = incidence_sin_cos(normal, direction, cosine);
    let index = eta.max(0.0);
    let sin_t = Interval::exact(index) * incidence.0[0];
    select(
        sin_t.lo > 1.0,
        sin_t.hi > 1.0,
        || {
            vec![
                Interval::exact(cone.width),
                Interval::exact(cone.spread_angle) + Interval::c(2.0) * Interval::exact(facing_spread),
                Interval::c(1.0),
            ]
        },
        || transmitted_cone(cone, incidence, facing_spread, index),
    )
}

/// Whether both of `refract_ray_cone`'s decisions are certain: which side of the normal the ray
/// meets, and whether it is totally internally reflected. Within rounding of either (a grazing ray,
/// the critical angle) both answers are right and the flag's tolerance would be vacuous; those
/// cases are checked separately (the degenerate table, the edge-case suite).
pub(super) fn refraction_decided(&(_, normal, direction, _, eta): &RefractArgs) -> bool {
    let cosine = interval3(normal).dot(interval3(direction));
    let incidence = incidence_sin_cos(normal, direction, cosine);
    let sin_t = Interval::exact(eta.max(0.0)) * incidence.0[0];
    let side_decided = cosine.lo > 0.0 || cosine.hi <= 0.0;
    let reflection_decided = sin_t.lo > 1.0 || sin_t.hi <= 1.0;
    side_decided && reflection_decided
}

/// `facing` (a refraction for one normal orientation) with the normal spread as the ray sees it:
/// negated where the normal faces away from the ray, the hull of both where `dot(n, d)` is within
/// rounding of 0.
fn either_facing(
    args: &RefractArgs,
    facing: fn(&RefractArgs, Interval, f32) -> Vec<Interval>,
) -> Vec<Interval> {
    let &(_, normal, direction, beta, _) = args;
    let cosine = interval3(normal).dot(interval3(direction));
    select(
        cosine.lo > 0.0,
        cosine.hi > 0.0,
        || facing(args, cosine, -beta),
        || facing(args, cosine, beta),
    )
}

pub(super) fn refract_ray_cone(args: &RefractArgs) -> Vec<Interval> {
    either_facing(args, refract_facing)
}

/// `rf_refract_sagittal_cone` for one normal orientation (`facing_spread`): the hull of the
/// reflected and the refracted section where `eta sin i` is within rounding of 1.
fn sagittal_facing(
    &(cone, normal, direction, _, eta): &RefractArgs,
    cosine: Interval,
    facing_spread: f32,
) -> Vec<Interval> {
    let incidence = incidence_sin_cos(normal, direction, cosine);
    let index = eta.max(0.0);
    let turn = Interval::c(2.0) * normal_tilt(cone.width, facing_spread);
    let spread = Interval::exact(cone.spread_angle);
    let sin_t = Interval::exact(index) * incidence.0[0];
    let leaving_spread = select(
        sin_t.lo > 1.0,
        sin_t.hi > 1.0,
        || vec![spread + Interval::c(2.0) * incidence.0[1] * turn],
        || {
            let transmitted = refracted_sin_cos(incidence, index);
            let index = Interval::exact(index);
            vec![index * spread + (index * incidence.0[1] - transmitted.0[1]) * turn]
        },
    )[0];
    vec![Interval::exact(cone.width), leaving_spread]
}

pub(super) fn refract_sagittal_cone(args: &RefractArgs) -> Vec<Interval> {
    either_facing(args, sagittal_facing)
}

/// `rf_two_section_width`, in the same order of operations.
pub(super) fn two_section_width(
    &(tangential_width, sagittal_width, axis, normal, direction): &(f32, f32, Vec3, Vec3, Vec3),
) -> Interval {
    let larger_width = Interval::exact(tangential_width.abs().max(sagittal_width.abs()));
    let (axis, normal, direction) = (interval3(axis), interval3(normal), interval3(direction));
    let across = axis - direction * axis.dot(direction);
    let across_length = across.dot(across).sqrt();
    let min = f64::from(MIN_MAGNITUDE);
    select(
        across_length.hi < min,
        across_length.lo < min,
        || vec![larger_width],
        || {
            let sagittal = across / across_length.at_least(min);
            let tangential = sagittal.cross(direction);
            let cosine = normal.dot(direction).abs().max_c(f64::from(MIN_COS));
            let scale = larger_width.max_c(min);
            let tangential_share = Interval::exact(tangential_width) / scale;
            let sagittal_share = Interval::exact(sagittal_width) / scale;
            let tangential_tilt = tangential_share * normal.dot(tangential);
            let sagittal_tilt = sagittal_share * normal.dot(sagittal);
            let squared_cos = cosine * cosine;
            let tangential_square =
                squared_cos * tangential_share * tangential_share + tangential_tilt * tangential_tilt;
            let sagittal_square =
                squared_cos * sagittal_share * sagittal_share + sagittal_tilt * sagittal_tilt;
            let half_sum = Interval::c(0.5) * (tangential_square + sagittal_square);
            let half_difference = Interval::c(0.5) * (tangential_square - sagittal_square);
            let off_diagonal = tangential_tilt * sagittal_tilt;
            let larger = half_sum + (half_difference * half_difference + off_diagonal * off_diagonal).sqrt();
            vec![scale * larger.sqrt()]
        },
    )[0]
}

pub(super) fn roughness_spread_angle(roughness: f32) -> Interval {
    let r = Interval::exact(roughness.clamp(0.0, 1.0));
    let alpha = r * r;
    let alpha2 = alpha * alpha;
    let variance =
        Interval::c(0.5) * alpha2 / (Interval::c(1.0) - alpha2).max_c(f64::from(MIN_ROUGHNESS_DENOMINATOR));
    Interval::c(2.0) * variance.sqrt()
}

/// `axis / max(|axis|, MIN_MAGNITUDE)`, as `clamped_unit`.
fn clamped_unit(axis: Interval3) -> Interval3 {
    axis / axis.dot(axis).sqrt().max_c(f64::from(MIN_MAGNITUDE))
}

/// The triangle's shape frame `(u, v)`, as `shape_frame_u` and `shape_frame_v`.
fn shape_frame(p: [Interval3; 3]) -> (Interval3, Interval3) {
    let u = clamped_unit(p[1] - p[0]);
    let face = clamped_unit(u.cross(clamped_unit(p[2] - p[0])));
    (u, face.cross(u))
}

/// The normal equations of `triangle_shape_operator` after the divisions by the largest edge
/// component and by `A + B`: `(A, B, C)`, the right-hand side `r`, and that largest component.
fn shape_normal_equations(p: [Interval3; 3], n: [Interval3; 3]) -> ([Interval; 3], Interval3, Interval) {
    let (u, v) = shape_frame(p);
    let edges = [p[1] - p[0], p[2] - p[1], p[0] - p[2]];
    let turns = [n[1] - n[0], n[2] - n[1], n[0] - n[2]];
    let along = |vectors: [Interval3; 3], axis: Interval3| IntervalVec(vectors.map(|x| x.dot(axis)));
    let (along_u, along_v) = (along(edges, u), along(edges, v));
    let extent = along_u
        .0
        .iter()
        .chain(&along_v.0)
        .fold(Interval::exact(MIN_MAGNITUDE), |largest, x| largest.max(x.abs()));
    let (a, b) = (along_u / extent, along_v / extent);
    let (du, dv) = (along(turns, u), along(turns, v));
    let scale = (a.dot(a) + b.dot(b)).max_c(f64::from(MIN_MAGNITUDE));
    let squares = [a.dot(a) / scale, b.dot(b) / scale, a.dot(b) / scale];
    let r = IntervalVec([a.dot(du), b.dot(du) + a.dot(dv), b.dot(dv)]) / scale;
    (squares, r, extent)
}

/// The determinant `AB - C²` of `triangle_shape_operator`'s normal equations, before its clamp.
fn shape_determinant([aa, bb, ab]: [Interval; 3]) -> Interval {
    aa * bb - ab.abs() * ab.abs()
}

/// `rf_triangle_shape_operator` of corners `p` and normals `n` given as intervals (an f32
/// input is an exact interval; a reference's may hold an exact value and its rounding too).
pub(super) fn triangle_shape_operator(p: [Interval3; 3], n: [Interval3; 3]) -> Interval3 {
    let ([aa, bb, ab], r, extent) = shape_normal_equations(p, n);
    let [r0, r1, r2] = r.0;
    let ab2 = ab.abs() * ab.abs();
    let determinant = shape_determinant([aa, bb, ab]).max_c(f64::from(MIN_MAGNITUDE));
    let e = (bb - ab2) * r0 - bb * ab * r1 + ab2 * r2;
    let f = aa * bb * r1 - bb * ab * r0 - aa * ab * r2;
    let g = (aa - ab2) * r2 - aa * ab * r1 + ab2 * r0;
    IntervalVec([e, f, g]) / (determinant * extent)
}

/// Whether the determinant of `triangle_shape_operator`'s normal equations is known to be
/// positive and known to [`WELL_CONDITIONED`] (a triangle that is not a sliver within rounding,
/// nor exactly flat: a repeated corner gives an exact 0) and its largest edge component known
/// above `MIN_MAGNITUDE`, where the clamp would begin.
pub(super) fn shape_well_conditioned(p: [Vec3; 3]) -> bool {
    let p = p.map(interval3);
    let ([aa, bb, ab], _, extent) = shape_normal_equations(p, [interval3(Vec3::ZERO); 3]);
    let determinant = shape_determinant([aa, bb, ab]);
    determinant.lo > 0.0
        && determinant.relative_width() <= WELL_CONDITIONED
        && extent.lo > f64::from(MIN_MAGNITUDE)
}

/// `rf_normal_curvature` with every argument an interval.
pub(super) fn normal_curvature(
    p: [Interval3; 3],
    shape_operator: Interval3,
    direction: Interval3,
) -> Interval {
    let (u, v) = shape_frame(p);
    let unit = clamped_unit(direction);
    let (a, b) = (unit.dot(u), unit.dot(v));
    let [e, f, g] = shape_operator.0;
    let normal_weight = Interval::exact(MIN_COS) * Interval::exact(MIN_COS);
    let mean = Interval::c(0.5) * (e + g);
    let (a2, b2) = (a.abs() * a.abs(), b.abs() * b.abs());
    (e * a * a + Interval::c(2.0) * f * a * b + g * b * b + normal_weight * mean) / (a2 + b2 + normal_weight)
}

/// Whether `rf_normal_curvature`'s frame and the direction's squared length in the triangle's
/// plane are known to [`WELL_CONDITIONED`].
pub(super) fn projection_well_conditioned(p: [Vec3; 3], direction: Vec3) -> bool {
    let (u, v) = shape_frame(p.map(interval3));
    let d = clamped_unit(interval3(direction));
    let (a, b) = (d.dot(u), d.dot(v));
    let in_plane = a.abs() * a.abs() + b.abs() * b.abs();
    shape_well_conditioned(p) && in_plane.relative_width() <= WELL_CONDITIONED
}

/// `(e - g) / 2` and the radius `|((e - g) / 2, f)|` of `principal_curvatures` and
/// `principal_direction`.
fn principal_half_gap_radius(shape_operator: Interval3) -> (Interval, Interval) {
    let [e, f, g] = shape_operator.0;
    let half_gap = Interval::c(0.5) * (e - g);
    let radius = (half_gap.abs() * half_gap.abs() + f.abs() * f.abs()).sqrt();
    (half_gap, radius)
}

/// `rf_principal_curvatures` of a shape operator given as intervals.
pub(super) fn principal_curvatures(shape_operator: Interval3) -> Interval2 {
    let [e, _, g] = shape_operator.0;
    let mean = Interval::c(0.5) * (e + g);
    let (_, radius) = principal_half_gap_radius(shape_operator);
    IntervalVec([mean + radius, mean - radius])
}

/// `rf_principal_direction` with every argument an interval: each branch the device or the mirror
/// may take (the eigenvector's two forms, the turn to a non-negative `u` component) enclosed, and
/// their hull where the intervals leave the branch open.
pub(super) fn principal_direction(p: [Interval3; 3], shape_operator: Interval3) -> Vec<Interval> {
    let (u, v) = shape_frame(p);
    let f = shape_operator.0[1];
    let (half_gap, radius) = principal_half_gap_radius(shape_operator);
    let direction = |x: Interval, y: Interval| {
        let world = |x: Interval, y: Interval| clamped_unit(u * x + v * y).components();
        select(x.hi < 0.0, x.lo < 0.0, || world(-x, -y), || world(x, y))
    };
    select(
        half_gap.lo >= 0.0,
        half_gap.hi >= 0.0,
        || direction(half_gap + radius, f),
        || direction(f, radius - half_gap),
    )
}

/// `rf_isotropic_curvature` of principal curvatures given as intervals: exact (a minimum, a
/// maximum and a choice), so its width is the inputs'; where a sign is left open, the hull with
/// the other choices.
pub(super) fn isotropic_curvature(principal_curvatures: Interval2) -> Interval {
    let [k1, k2] = principal_curvatures.0;
    let (least, most) = (k1.min(k2), k1.max(k2));
    let zero = || vec![Interval::c(0.0)];
    let negative = || select(most.hi < 0.0, most.lo < 0.0, || vec![most], zero);
    select(least.lo > 0.0, least.hi > 0.0, || vec![least], negative)[0]
}

/// Whether `rf_principal_direction`'s frame is known to [`WELL_CONDITIONED`] and so is the
/// radius, the gap between the principal curvatures: away from an umbilic, where rounding turns
/// the direction freely.
pub(super) fn direction_well_conditioned(p: [Vec3; 3], shape_operator: Vec3) -> bool {
    let (_, radius) = principal_half_gap_radius(interval3(shape_operator));
    shape_well_conditioned(p) && radius.relative_width() <= WELL_CONDITIONED
}
