// ray-footprint ray-tracing renderer: the peers' rules of the path modes (rt_path_cone), as
// functions of plain values, so that tests/gpu/path_rules.rs runs them in a compute kernel against
// the CPU lab's rules (src/paths/methods.rs) and the CPU path tracer's GGX pdf
// (src/paths/sampling.rs). rt_shading.glsl includes it; it needs the library's ray_cone module
// before it (RfRayCone, rf_width_at), and uses only the GLSL that Slang's `glsl` module also
// provides, as rt_shading.glsl does.

#ifndef RT_PATH_RULES_GLSL
#define RT_PATH_RULES_GLSL

// The density (per solid angle) of the direction a GGX lobe of width `alpha` reflects the ray
// `incoming` (unit) to, `direction` (unit), around the unit normal `facing` (Walter, Marschner,
// Li, Torrance 2007, Eq. 14 and 24: D(h) cos(theta_h) / (4 |o.h|), D of Eq. 33), with `h` the
// half vector of -incoming and direction. Example: alpha 1 (D = 1 / pi) at normal incidence and
// reflection gives 1 / (4 pi).
float rt_ggx_pdf(vec3 incoming, vec3 facing, vec3 direction, float alpha) {
    vec3 half_vector = normalize(direction - incoming);
    float cos_h = max(dot(half_vector, facing), 0.0);
    float alpha2 = max(alpha * alpha, 1e-12);
    float denominator = cos_h * cos_h * (alpha2 - 1.0) + 1.0;
    float distribution = alpha2 / (3.14159265359 * denominator * denominator);
    return distribution * cos_h / max(4.0 * abs(dot(direction, half_vector)), 1e-12);
}

// RTXPT's growth of the spread at a scatter whose direction was drawn with density `pdf`
// (ComputeRayConeSpreadAngleExpansionByScatterPDF): 0.3 times the whole angle 2 acos(1 - Omega /
// (2 pi)) of the spherical cap of solid angle Omega = 1 / pdf. Example: pdf 1 / (2 pi), a
// hemisphere's cap, gives 0.3 pi.
float rt_rtxpt_expansion(float pdf) {
    return 0.3 * 2.0 * acos(max(1.0 - 1.0 / (6.28318530718 * max(pdf, 1e-30)), -1.0));
}

// The OptiX Toolkit's cone leaving a vertex (ray_cone.h) that `cone` reaches at distance `t`, on
// a surface of curvature `seen_curvature` as the ray sees it (positive where convex towards it),
// for a direction of BSDF value `bsdf`: the cone carried to the vertex (both signs flipped where
// width and angle are both negative), `reflect` adding 2 seen_curvature |width| while the angle is
// below its diffuse angle 0.25, then `scatterBsdf` adding sign(angle) 0.25 min(1, 1 / (pi f_s)),
// the cone becoming the diffuse one (|width|, 0.25) where that reaches 0.25. Example: a pinhole
// cone (0, 0.001) at t = 10 on a plane with bsdf 4 leaves as (0.01, 0.001 + 0.25 / (4 pi)).
RfRayCone rt_optix_toolkit_cone(RfRayCone cone, float t, float seen_curvature, float bsdf) {
    float width = rf_width_at(cone, t);
    float angle = cone.spread_angle;
    if (angle < 0.0 && width < 0.0) {
        width = -width;
        angle = -angle;
    }
    if (angle < 0.25) {
        angle += 2.0 * seen_curvature * abs(width);
    }
    if (angle >= 0.25) {
        return RfRayCone(width, angle);
    }
    float grown = angle + (angle < 0.0 ? -0.25 : 0.25) * 0.318309886 / max(bsdf, 0.318309886);
    return abs(grown) < 0.25 ? RfRayCone(width, grown) : RfRayCone(abs(width), 0.25);
}

#endif // RT_PATH_RULES_GLSL
