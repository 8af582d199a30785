//! The peers' rules of the renderer's path modes (`rt_path_rules.glsl`, which `rt_shading.glsl`
//! includes for every closest hit) run in a compute kernel in GLSL, against the CPU lab's rules
//! (`paths::methods`) and the CPU path tracer's GGX pdf (`paths::sampling`, in f64), value by
//! value. The Slang and HLSL closest hits compile the same file; `rt.rs` shows that they render
//! the GLSL closest hit's colours.
//!
//! Each tolerance is derived from the operations on both sides under Vulkan's precision rules
//! (`acos` inherits `atan`'s 4096 ULP), per case. Where a rule branches on a threshold, cases whose
//! branch value lies within four times its rounding bound of the threshold are not drawn: there
//! either branch is right.

use super::gpu;
use glam::{DVec3, Vec3};
use proptest::prelude::*;
use ray_footprint::ray_cone::RayCone;
use ray_footprint::shaders::Module;
use ray_footprint_lab::paths::methods::{optix_toolkit_cone, rtxpt_expansion};
use ray_footprint_lab::paths::sampling::{ggx_normal, pdf_and_bsdf};
use ray_footprint_lab::paths::scene::Material;
use ray_footprint_lab::rt::SHADER_DIR;
use shader_proptest::tolerance::{ulps, ATAN_ULPS, ULP};
use shader_proptest::{FunctionCheck, Language, RunConfig, Shader, Tolerance};

/// The library's GLSL ray_cone module with the renderer's path rules after it.
fn rules_shader() -> Shader {
    Module::RayCone
        .shader(Language::Glsl)
        .with_source("#include \"rt_path_rules.glsl\"")
        .include_dir(SHADER_DIR)
}

/// Runs `check` on the rules' shader and asserts that it passes.
fn assert_agrees<A: shader_proptest::Args, R: shader_proptest::Value>(check: FunctionCheck<A, R>) {
    let gpu = gpu();
    let report = check
        .run(&gpu, &rules_shader(), &RunConfig::default())
        .unwrap_or_else(|e| panic!("{e}"));
    println!("{report}");
    report.assert_passed();
}

/// `10^exponent` for an exponent drawn from `range`: magnitudes spread evenly over the decades.
fn decades(range: std::ops::Range<f32>) -> impl Strategy<Value = f32> {
    range.prop_map(|exponent| 10f32.powf(exponent))
}

/// The error of `acos(x)` on the device for an `x` off by `x_error`: the propagated error (at most
/// `sqrt(2 x_error)` where the slope is unbounded, at +-1), the rounding of `1 - x^2` inside
/// (Vulkan: acos inherits `atan2(sqrt(1 - x^2), x)`), and 4096 ULP of the result plus the
/// mirror's ULP.
fn acos_error(x: f64, x_error: f64) -> f64 {
    let x_error = x_error + f64::from(ulps(2.0, 1.0));
    let slope_bound = x_error / (1.0 - x * x).max(0.0).sqrt();
    let propagated = slope_bound.min((2.0 * x_error).sqrt());
    propagated + f64::from(ulps(ATAN_ULPS + 1.0, x.clamp(-1.0, 1.0).acos() as f32))
}

/// `rt_rtxpt_expansion` agrees with `rtxpt_expansion` for densities from 1e-3 (the clamp at a
/// full sphere's cap) to 1e5 (a needle lobe).
#[test]
fn rtxpt_expansion_agrees_with_the_cpu_rule() {
    let check = FunctionCheck::new(
        "rt_rtxpt_expansion",
        || decades(-3.0..5.0).prop_map(|pdf| (pdf,)),
        |(pdf,)| rtxpt_expansion(pdf),
    )
    .tolerance(Tolerance::per_case(|&(pdf,): &(f32,), expected: &[f32]| {
        // The cap's 1 / (2 pi pdf): a division and a product on the device, two divisions in the
        // mirror; then the subtraction from 1.
        let quotient = 1.0 / (std::f64::consts::TAU * f64::from(pdf));
        let x = (1.0 - quotient).max(-1.0);
        let x_error = f64::from(ulps(6.0, quotient as f32)) + f64::from(ulps(2.0, x as f32));
        let bound = 0.6 * acos_error(x, x_error) + f64::from(ulps(2.0, expected[0]));
        vec![bound as f32]
    }));
    assert_agrees(check);
}

/// The OptiX Toolkit's cone in f64 for the branches: (width at the vertex after the sign flip, the
/// angle after `reflect`, the angle grown by `scatterBsdf`) and their rounding bounds.
struct OptixBranches {
    width: f64,
    reflected: f64,
    grown: f64,
    width_error: f64,
    angle_error: f64,
}

/// [`OptixBranches`] of one case of `rt_optix_toolkit_cone`'s arguments.
fn optix_branches((cone, t, curvature, bsdf): (RayCone, f32, f32, f32)) -> OptixBranches {
    let (width, spread, t, curvature) = (
        f64::from(cone.width),
        f64::from(cone.spread_angle),
        f64::from(t),
        f64::from(curvature),
    );
    let mut carried = width + t * spread;
    let width_error = f64::from(ulps(3.0, (width.abs() + (t * spread).abs()) as f32));
    let mut angle = spread;
    if angle < 0.0 && carried < 0.0 {
        (carried, angle) = (-carried, -angle);
    }
    let turn = 2.0 * curvature * carried.abs();
    let reflected = if angle < 0.25 { angle + turn } else { angle };
    let term = 0.25 / std::f64::consts::PI / f64::from(bsdf).max(1.0 / std::f64::consts::PI);
    let grown = reflected + reflected.signum() * term;
    let angle_error = 2.0 * curvature.abs() * width_error
        + f64::from(ulps(4.0, turn as f32))
        + f64::from(ulps(6.0, term as f32))
        + f64::from(ulps(3.0, reflected.abs().max(grown.abs()) as f32));
    OptixBranches {
        width: carried,
        reflected,
        grown,
        width_error,
        angle_error,
    }
}

/// `rt_optix_toolkit_cone` agrees with `optix_toolkit_cone` at every scale: widths of either sign
/// from 1e-6 to 1e3, angles from -0.3 to 0.3 (diffuse cones past 0.25 included), distances from
/// 1e-3 to 1e4, curvatures of either sign from 1e-4 to 1e3 and 0, BSDF values from 1e-3 to 1e3.
#[test]
fn optix_toolkit_cone_agrees_with_the_cpu_rule() {
    let signed = |range: std::ops::Range<f32>| {
        (decades(range), any::<bool>())
            .prop_map(|(magnitude, negative)| if negative { -magnitude } else { magnitude })
    };
    let curvature = prop_oneof![1 => Just(0.0f32), 4 => signed(-4.0..3.0)];
    let check = FunctionCheck::new(
        "rt_optix_toolkit_cone",
        move || {
            (
                signed(-6.0..3.0),
                -0.3f32..0.3,
                decades(-3.0..4.0),
                curvature.clone(),
                decades(-3.0..3.0),
            )
                .prop_map(|(width, spread_angle, t, curvature, bsdf)| {
                    (RayCone { width, spread_angle }, t, curvature, bsdf)
                })
                .prop_filter("a branch within rounding of its threshold", |&args| {
                    let branches = optix_branches(args);
                    let margin = 4.0 * branches.angle_error;
                    branches.width.abs() > 4.0 * branches.width_error
                        && (branches.reflected - 0.25).abs() > margin
                        && branches.reflected.abs() > margin
                        && (branches.grown.abs() - 0.25).abs() > margin
                })
        },
        |(cone, t, curvature, bsdf)| optix_toolkit_cone(cone, t, curvature, bsdf),
    )
    .tolerance(Tolerance::per_case(
        |&args: &(RayCone, f32, f32, f32), _: &[f32]| {
            let branches = optix_branches(args);
            vec![branches.width_error as f32, branches.angle_error as f32]
        },
    ));
    assert_agrees(check);
}

/// A case of `rt_ggx_pdf`: a unit normal, a unit ray arriving at it from above (at least 0.05
/// off the plane), the ray reflected about a GGX normal of width `alpha` drawn as the renderer
/// draws it, kept where it leaves at least 0.05 above the plane.
fn ggx_case() -> impl Strategy<Value = (Vec3, Vec3, Vec3, f32)> {
    let unit = (-1.0f64..1.0, 0.0f64..std::f64::consts::TAU).prop_map(|(z, phi)| {
        let ring = (1.0 - z * z).sqrt();
        DVec3::new(ring * phi.cos(), ring * phi.sin(), z)
    });
    (unit.clone(), unit, 0.1f64..1.0, 0.0f64..1.0, 0.0f64..1.0)
        .prop_map(|(normal, towards, roughness, u1, u2)| {
            let alpha = (roughness * roughness) as f32;
            let incoming = (towards - normal * (towards.dot(normal) + 1.0)).normalize();
            let tangent = normal.any_orthonormal_vector();
            let local = ggx_normal(f64::from(alpha), u1, u2);
            let microfacet = tangent * local.x + normal.cross(tangent) * local.y + normal * local.z;
            let direction = incoming - 2.0 * incoming.dot(microfacet) * microfacet;
            (normal.as_vec3(), incoming.as_vec3(), direction.as_vec3(), alpha)
        })
        .prop_filter(
            "a ray within 0.05 of the plane",
            |(normal, incoming, direction, _)| incoming.dot(*normal) < -0.05 && direction.dot(*normal) > 0.05,
        )
        .prop_map(|(normal, incoming, direction, alpha)| (incoming, normal, direction, alpha))
}

/// `rt_ggx_pdf` agrees with the CPU path tracer's GGX pdf (f64, `pdf_and_bsdf` of a conductor
/// whose roughness is `sqrt(alpha)`) for roughness 0.1 to 1 (alpha 0.01 to 1).
#[test]
fn ggx_pdf_agrees_with_the_cpu_path_tracer() {
    let check = FunctionCheck::new("rt_ggx_pdf", ggx_case, |(incoming, facing, direction, alpha)| {
        let conductor = Material::Conductor {
            roughness: f64::from(alpha).sqrt(),
        };
        pdf_and_bsdf(
            conductor,
            facing.as_dvec3(),
            incoming.as_dvec3(),
            direction.as_dvec3(),
        )
        .0 as f32
    })
    .tolerance(Tolerance::per_case(
        |&(incoming, facing, direction, alpha): &(Vec3, Vec3, Vec3, f32), expected: &[f32]| {
            // The half vector's cosines carry the normalize's and the dots' roundings, 12 ULP;
            // D's denominator c^2 (alpha^2 - 1) + 1 cancels towards alpha^2 near c = 1, and
            // enters squared.
            let (incoming, facing, direction) =
                (incoming.as_dvec3(), facing.as_dvec3(), direction.as_dvec3());
            let half = (direction - incoming).normalize();
            let (cos_h, cos_out) = (half.dot(facing), direction.dot(half).abs());
            let alpha2 = f64::from(alpha) * f64::from(alpha);
            let denominator = cos_h * cos_h * (alpha2 - 1.0) + 1.0;
            let cosine_error = 12.0 * f64::from(ULP);
            let denominator_error = 2.0 * cos_h * (1.0 - alpha2).abs() * cosine_error + 3.0 * f64::from(ULP);
            let relative = 2.0 * denominator_error / denominator
                + cosine_error / cos_h
                + cosine_error / cos_out
                + 10.0 * f64::from(ULP);
            vec![(relative * f64::from(expected[0])) as f32 + f32::MIN_POSITIVE]
        },
    ));
    assert_agrees(check);
}
