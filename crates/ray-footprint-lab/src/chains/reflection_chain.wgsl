// A reflection chain followed by a ray cone and by a ray differential side by side: the primary
// ray of a camera, up to four curved mirrors, then a plane across the last ray. After every leg it
// records the cone's width and the differential's footprint along the two pixel axes.
//
// Compiled after shaders/wgsl/ray_cone.wgsl and ray_diff.wgsl. Twin of reflection_chain.glsl and
// of the Rust mirror in mirror.rs: same functions, same order, same order of operations.

// ChainCamera.kind: a pinhole camera, an orthographic one, a thin lens.
const CHAIN_PINHOLE: u32 = 0u;
const CHAIN_ORTHOGRAPHIC: u32 = 1u;
const CHAIN_THIN_LENS: u32 = 2u;
// Most mirrors in a chain; a chain has one leg more.
const CHAIN_MAX_BOUNCES: u32 = 4u;

// The camera of the primary ray through the centre pixel of a square image image_height pixels
// tall, looking down -z; a pixel step right moves along +x, a step down along -y.
struct ChainCamera {
    kind: u32,
    fov_y: f32,
    image_height: f32,
    view_height: f32,
    aperture: f32,
    focus_distance: f32,
}

// One leg: the ray travels distance along direction to a plane with unit normal normal (a mirror's
// stored normal, or the direction at the end). The cone is given curvature; the mirror's stored
// normal turns by principal_curvatures along the principal directions. right and down are the
// pixel-step axes across the ray.
struct ChainLeg {
    distance: f32,
    direction: vec3<f32>,
    normal: vec3<f32>,
    curvature: f32,
    principal_curvatures: vec2<f32>,
    first_principal_direction: vec3<f32>,
    second_principal_direction: vec3<f32>,
    right: vec3<f32>,
    down: vec3<f32>,
}

// At the end of a leg: the cone's signed width, and the differential's signed footprints
// dot(dO/dx, right) and dot(dO/dy, down).
struct ChainSample {
    width: f32,
    footprint: vec2<f32>,
}

// The samples at the end of each leg; those past the last leg are 0.
struct ChainSamples {
    first: ChainSample,
    second: ChainSample,
    third: ChainSample,
    fourth: ChainSample,
    fifth: ChainSample,
}

// A ray of the chain: its cone and its differential.
struct ChainRay {
    cone: RfRayCone,
    diff: RfRayDiff,
}

// A differential that moves along the pixel axes by the cone's width and turns by its spread.
fn chain_pixel_axis_diff(cone: RfRayCone) -> RfRayDiff {
    return RfRayDiff(
        vec3<f32>(cone.width, 0.0, 0.0), 0.0,
        vec3<f32>(0.0, -cone.width, 0.0), 0.0,
        vec3<f32>(cone.spread_angle, 0.0, 0.0), 0.0,
        vec3<f32>(0.0, -cone.spread_angle, 0.0), 0.0,
    );
}

// The primary ray: a pinhole's cone and eye-ray differential; an orthographic or thin-lens cone
// and the differential built from it.
fn chain_primary(camera: ChainCamera) -> ChainRay {
    if camera.kind == CHAIN_PINHOLE {
        let size = vec2<f32>(camera.image_height);
        let centre = floor(0.5 * size);
        let alpha = rf_pixel_spread_angle_small(camera.fov_y, camera.image_height);
        let diff = rf_eye_ray_diff(
            centre, size, camera.fov_y, vec3<f32>(1.0, 0.0, 0.0), vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(0.0, 0.0, 1.0),
        );
        return ChainRay(rf_pinhole_ray_cone(alpha), diff);
    }
    if camera.kind == CHAIN_ORTHOGRAPHIC {
        let cone = rf_orthographic_ray_cone(camera.view_height, camera.image_height);
        return ChainRay(cone, chain_pixel_axis_diff(cone));
    }
    let alpha = rf_pixel_spread_angle_small(camera.fov_y, camera.image_height);
    let cone = rf_thin_lens_ray_cone(alpha, camera.aperture, camera.focus_distance);
    return ChainRay(cone, chain_pixel_axis_diff(cone));
}

// The change of the mirror's stored normal when the hit moves by dp in the tangent plane:
// k1 (u1 . dp) u1 + k2 (u2 . dp) u2.
fn chain_normal_change(leg: ChainLeg, dp: vec3<f32>) -> vec3<f32> {
    let k = leg.principal_curvatures;
    return k.x * dot(leg.first_principal_direction, dp) * leg.first_principal_direction
        + k.y * dot(leg.second_principal_direction, dp) * leg.second_principal_direction;
}

// The ray reflected at the leg's mirror: the cone spread by the curvature, the differential
// (already transferred to the hit) reflected with the normal's change.
fn chain_reflect(ray: ChainRay, at_hit: RfRayDiff, width: f32, leg: ChainLeg) -> ChainRay {
    let normal_change = RfDerivatives3(
        chain_normal_change(leg, at_hit.d_origin_dx), chain_normal_change(leg, at_hit.d_origin_dy),
    );
    let beta = rf_curvature_spread_angle(leg.curvature, width, leg.normal, leg.direction);
    return ChainRay(
        rf_propagate(ray.cone, leg.distance, beta),
        rf_reflect_ray_diff(at_hit, leg.direction, leg.normal, normal_change),
    );
}

// The chain: the primary ray, reflected at the first bounces legs (at most CHAIN_MAX_BOUNCES),
// then followed along one more leg; a sample at the end of each leg.
fn reflection_chain(
    camera: ChainCamera, bounces: u32, leg0: ChainLeg, leg1: ChainLeg, leg2: ChainLeg, leg3: ChainLeg,
    leg4: ChainLeg,
) -> ChainSamples {
    var legs = array<ChainLeg, 5>(leg0, leg1, leg2, leg3, leg4);
    var samples: array<ChainSample, 5>;
    var ray = chain_primary(camera);
    let reflections = min(bounces, CHAIN_MAX_BOUNCES);
    for (var index = 0u; index <= reflections; index++) {
        let leg = legs[index];
        let at_hit = rf_transfer(ray.diff, leg.direction, leg.distance, leg.normal);
        let width = rf_width_at(ray.cone, leg.distance);
        samples[index] = ChainSample(
            width, vec2<f32>(dot(at_hit.d_origin_dx, leg.right), dot(at_hit.d_origin_dy, leg.down)),
        );
        if index < reflections {
            ray = chain_reflect(ray, at_hit, width, leg);
        }
    }
    return ChainSamples(samples[0], samples[1], samples[2], samples[3], samples[4]);
}
