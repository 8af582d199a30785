// A reflection chain followed by a ray cone and by a ray differential side by side: the primary
// ray of a camera, up to four curved mirrors, then a plane across the last ray. After every leg it
// records the cone's width and the differential's footprint along the two pixel axes.
//
// GLSL 460 (no main), included after the library modules that define its rf_ calls: in GLSL after
// ray_cone.glsl and ray_diff.glsl; in Slang after `import glsl; import ray_cone; import ray_diff;`,
// which slangc compiles through its GLSL compatibility, so that every rf_ call is a call of the
// Slang modules. Its constants are macros because slangc refuses a global const without static.
// Twin of reflection_chain.wgsl and of the Rust mirror in mirror.rs: same functions, same order,
// same order of operations.

#ifndef RAY_FOOTPRINT_LAB_REFLECTION_CHAIN_GLSL
#define RAY_FOOTPRINT_LAB_REFLECTION_CHAIN_GLSL

// ChainCamera.kind: a pinhole camera, an orthographic one, a thin lens.
#define CHAIN_PINHOLE 0u
#define CHAIN_ORTHOGRAPHIC 1u
#define CHAIN_THIN_LENS 2u
// Most mirrors in a chain; a chain has one leg more.
#define CHAIN_MAX_BOUNCES 4u

// The camera of the primary ray through the centre pixel of a square image image_height pixels
// tall, looking down -z; a pixel step right moves along +x, a step down along -y.
struct ChainCamera {
    uint kind;
    float fov_y;
    float image_height;
    float view_height;
    float aperture;
    float focus_distance;
};

// One leg: the ray travels distance along direction to a plane with unit normal normal (a mirror's
// stored normal, or the direction at the end). The cone is given curvature; the mirror's stored
// normal turns by principal_curvatures along the principal directions. right and down are the
// pixel-step axes across the ray.
struct ChainLeg {
    float distance;
    vec3 direction;
    vec3 normal;
    float curvature;
    vec2 principal_curvatures;
    vec3 first_principal_direction;
    vec3 second_principal_direction;
    vec3 right;
    vec3 down;
};

// At the end of a leg: the cone's signed width, and the differential's signed footprints
// dot(dO/dx, right) and dot(dO/dy, down).
struct ChainSample {
    float width;
    vec2 footprint;
};

// The samples at the end of each leg; those past the last leg are 0.
struct ChainSamples {
    ChainSample first;
    ChainSample second;
    ChainSample third;
    ChainSample fourth;
    ChainSample fifth;
};

// A ray of the chain: its cone and its differential.
struct ChainRay {
    RfRayCone cone;
    RfRayDiff diff;
};

// A differential that moves along the pixel axes by the cone's width and turns by its spread.
RfRayDiff chain_pixel_axis_diff(RfRayCone cone) {
    return RfRayDiff(
        vec3(cone.width, 0.0, 0.0), 0.0,
        vec3(0.0, -cone.width, 0.0), 0.0,
        vec3(cone.spread_angle, 0.0, 0.0), 0.0,
        vec3(0.0, -cone.spread_angle, 0.0), 0.0);
}

// The primary ray: a pinhole's cone and eye-ray differential; an orthographic or thin-lens cone
// and the differential built from it.
ChainRay chain_primary(ChainCamera camera) {
    if (camera.kind == CHAIN_PINHOLE) {
        vec2 size = vec2(camera.image_height);
        vec2 centre = floor(0.5 * size);
        float alpha = rf_pixel_spread_angle_small(camera.fov_y, camera.image_height);
        RfRayDiff diff = rf_eye_ray_diff(
            centre, size, camera.fov_y, vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0));
        return ChainRay(rf_pinhole_ray_cone(alpha), diff);
    }
    if (camera.kind == CHAIN_ORTHOGRAPHIC) {
        RfRayCone cone = rf_orthographic_ray_cone(camera.view_height, camera.image_height);
        return ChainRay(cone, chain_pixel_axis_diff(cone));
    }
    float alpha = rf_pixel_spread_angle_small(camera.fov_y, camera.image_height);
    RfRayCone cone = rf_thin_lens_ray_cone(alpha, camera.aperture, camera.focus_distance);
    return ChainRay(cone, chain_pixel_axis_diff(cone));
}

// The change of the mirror's stored normal when the hit moves by dp in the tangent plane:
// k1 (u1 . dp) u1 + k2 (u2 . dp) u2.
vec3 chain_normal_change(ChainLeg leg, vec3 dp) {
    vec2 k = leg.principal_curvatures;
    return k.x * dot(leg.first_principal_direction, dp) * leg.first_principal_direction
        + k.y * dot(leg.second_principal_direction, dp) * leg.second_principal_direction;
}

// The ray reflected at the leg's mirror: the cone spread by the curvature, the differential
// (already transferred to the hit) reflected with the normal's change.
ChainRay chain_reflect(ChainRay ray, RfRayDiff at_hit, float width, ChainLeg leg) {
    RfDerivatives3 normal_change = RfDerivatives3(
        chain_normal_change(leg, at_hit.d_origin_dx), chain_normal_change(leg, at_hit.d_origin_dy));
    float beta = rf_curvature_spread_angle(leg.curvature, width, leg.normal, leg.direction);
    return ChainRay(
        rf_propagate(ray.cone, leg.distance, beta),
        rf_reflect_ray_diff(at_hit, leg.direction, leg.normal, normal_change));
}

// The chain: the primary ray, reflected at the first bounces legs (at most CHAIN_MAX_BOUNCES),
// then followed along one more leg; a sample at the end of each leg.
ChainSamples reflection_chain(
    ChainCamera camera, uint bounces, ChainLeg leg0, ChainLeg leg1, ChainLeg leg2, ChainLeg leg3,
    ChainLeg leg4) {
    ChainLeg legs[5] = ChainLeg[5](leg0, leg1, leg2, leg3, leg4);
    ChainSample zero = ChainSample(0.0, vec2(0.0));
    ChainSample samples[5] = ChainSample[5](zero, zero, zero, zero, zero);
    ChainRay ray = chain_primary(camera);
    uint reflections = min(bounces, CHAIN_MAX_BOUNCES);
    for (uint index = 0u; index <= reflections; index++) {
        ChainLeg leg = legs[index];
        RfRayDiff at_hit = rf_transfer(ray.diff, leg.direction, leg.distance, leg.normal);
        float width = rf_width_at(ray.cone, leg.distance);
        samples[index] = ChainSample(
            width, vec2(dot(at_hit.d_origin_dx, leg.right), dot(at_hit.d_origin_dy, leg.down)));
        if (index < reflections) {
            ray = chain_reflect(ray, at_hit, width, leg);
        }
    }
    return ChainSamples(samples[0], samples[1], samples[2], samples[3], samples[4]);
}

#endif
