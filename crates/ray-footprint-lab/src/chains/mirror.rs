//! A chain as the shader follows it: the f32 inputs, the Rust mirror of `reflection_chain.wgsl` and
//! `reflection_chain.glsl` (same functions, same order, same order of operations), and that shader
//! in WGSL, GLSL and Slang.

use glam::{Vec2, Vec3};
use ray_footprint::ray_cone::{self as rc, RayCone};
use ray_footprint::ray_diff::{self as rd, Derivatives3, RayDiff};
use ray_footprint::shaders::{wgsl_prelude, Module, GLSL_INCLUDE_DIR, SLANG_INCLUDE_DIR};
use shader_proptest::{shader_struct, Language, Shader};

/// [`ChainCamera::kind`] of a pinhole camera.
pub const CHAIN_PINHOLE: u32 = 0;
/// [`ChainCamera::kind`] of an orthographic camera.
pub const CHAIN_ORTHOGRAPHIC: u32 = 1;
/// [`ChainCamera::kind`] of a thin-lens camera.
pub const CHAIN_THIN_LENS: u32 = 2;
/// Most mirrors in a chain; a chain has one leg more.
pub const CHAIN_MAX_BOUNCES: u32 = 4;

/// The directory of `reflection_chain.glsl`, for glslang's include path and slangc's search path.
pub const CHAIN_SHADER_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/src/chains");

/// The camera of a chain's primary ray, through the centre pixel of a square image
/// `image_height` pixels tall (an odd number), looking down -z from the origin; a pixel step
/// right moves along +x, a step down along -y.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ChainCamera {
    /// [`CHAIN_PINHOLE`], [`CHAIN_ORTHOGRAPHIC`] or [`CHAIN_THIN_LENS`].
    pub kind: u32,
    /// Vertical field of view in radians (pinhole and thin lens).
    pub fov_y: f32,
    /// Image height (and width) in pixels.
    pub image_height: f32,
    /// Height of an orthographic view in world units.
    pub view_height: f32,
    /// Aperture diameter of a thin lens.
    pub aperture: f32,
    /// Focus distance of a thin lens.
    pub focus_distance: f32,
}

shader_struct!(ChainCamera as "ChainCamera" {
    kind: u32, fov_y: f32, image_height: f32, view_height: f32, aperture: f32, focus_distance: f32,
});

impl ChainCamera {
    /// A pinhole camera.
    pub fn pinhole(fov_y: f32, image_height: f32) -> Self {
        ChainCamera {
            kind: CHAIN_PINHOLE,
            fov_y,
            image_height,
            ..ChainCamera::default()
        }
    }

    /// An orthographic camera whose view is `view_height` tall.
    pub fn orthographic(view_height: f32, image_height: f32) -> Self {
        ChainCamera {
            kind: CHAIN_ORTHOGRAPHIC,
            image_height,
            view_height,
            ..ChainCamera::default()
        }
    }

    /// A thin-lens camera.
    pub fn thin_lens(fov_y: f32, image_height: f32, aperture: f32, focus_distance: f32) -> Self {
        ChainCamera {
            kind: CHAIN_THIN_LENS,
            fov_y,
            image_height,
            aperture,
            focus_distance,
            ..ChainCamera::default()
        }
    }
}

/// One leg of a chain: the ray travels `distance` along `direction` to a plane with unit normal
/// `normal` (a mirror's stored normal, or the direction itself at the end of the chain).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ChainLeg {
    /// Distance travelled along the leg.
    pub distance: f32,
    /// Unit direction of the ray.
    pub direction: Vec3,
    /// Unit normal of the plane at the end: the mirror's stored normal.
    pub normal: Vec3,
    /// The curvature the cone is given (`curvature_spread_angle`).
    pub curvature: f32,
    /// Principal curvatures of the mirror, measured with its stored normals.
    pub principal_curvatures: Vec2,
    /// Unit principal direction of the first principal curvature.
    pub first_principal_direction: Vec3,
    /// Unit principal direction of the second principal curvature.
    pub second_principal_direction: Vec3,
    /// The axis across the ray along which a pixel step right moves the footprint.
    pub right: Vec3,
    /// The axis across the ray along which a pixel step down moves the footprint.
    pub down: Vec3,
}

shader_struct!(ChainLeg as "ChainLeg" {
    distance: f32,
    direction: Vec3,
    normal: Vec3,
    curvature: f32,
    principal_curvatures: Vec2,
    first_principal_direction: Vec3,
    second_principal_direction: Vec3,
    right: Vec3,
    down: Vec3,
});

/// At the end of a leg: the cone's signed width and the differential's signed footprints,
/// `dot(dO/dx, right)` and `dot(dO/dy, down)`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ChainSample {
    /// The cone's signed width.
    pub width: f32,
    /// The differential's signed footprints along the two pixel axes.
    pub footprint: Vec2,
}

shader_struct!(ChainSample as "ChainSample" { width: f32, footprint: Vec2 });

/// The samples at the end of each leg; those past the last leg are 0.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ChainSamples {
    /// After the first leg.
    pub first: ChainSample,
    /// After the second leg.
    pub second: ChainSample,
    /// After the third leg.
    pub third: ChainSample,
    /// After the fourth leg.
    pub fourth: ChainSample,
    /// After the fifth leg.
    pub fifth: ChainSample,
}

shader_struct!(ChainSamples as "ChainSamples" {
    first: ChainSample, second: ChainSample, third: ChainSample, fourth: ChainSample, fifth: ChainSample,
});

impl ChainSamples {
    /// The samples in leg order.
    pub fn in_order(&self) -> [ChainSample; 5] {
        [self.first, self.second, self.third, self.fourth, self.fifth]
    }
}

/// The arguments of `reflection_chain`: the camera, the number of bounces, and five legs (those
/// after the last are ignored).
pub type ChainArgs = (ChainCamera, u32, ChainLeg, ChainLeg, ChainLeg, ChainLeg, ChainLeg);

/// A ray of a chain: its cone and its differential.
#[derive(Clone, Copy, Debug)]
pub struct ChainRay {
    /// The ray cone.
    pub cone: RayCone,
    /// The ray differential.
    pub diff: RayDiff,
}

/// A differential whose origin moves along the pixel axes (+x right, -y down) by the cone's
/// width and whose direction turns by its spread.
pub fn chain_pixel_axis_diff(cone: RayCone) -> RayDiff {
    RayDiff::new(
        Vec3::new(cone.width, 0.0, 0.0),
        Vec3::new(0.0, -cone.width, 0.0),
        Vec3::new(cone.spread_angle, 0.0, 0.0),
        Vec3::new(0.0, -cone.spread_angle, 0.0),
    )
}

/// The primary ray of `camera`:
/// - pinhole: `pinhole_ray_cone` of the small-angle pixel spread `2 tan(fov_y / 2) / H`, and the
///   eye-ray differential `eye_ray_diff` (RTG Eq. 8-11);
/// - orthographic: `orthographic_ray_cone` (one pixel wide, spread 0), rays one pixel apart;
/// - thin lens: `thin_lens_ray_cone` with the pinhole's spread alpha; rays leave the lens
///   `aperture` apart and meet the pixel's footprint on the focal plane, `alpha * focus_distance`
///   wide, so they spread by the cone's `alpha - aperture / focus_distance` per unit.
pub fn chain_primary(camera: ChainCamera) -> ChainRay {
    if camera.kind == CHAIN_PINHOLE {
        let size = Vec2::splat(camera.image_height);
        let centre = (0.5 * size).floor();
        let alpha = rc::pixel_spread_angle_small(camera.fov_y, camera.image_height);
        let diff = rd::eye_ray_diff(centre, size, camera.fov_y, Vec3::X, Vec3::Y, Vec3::Z);
        return ChainRay {
            cone: rc::pinhole_ray_cone(alpha),
            diff,
        };
    }
    if camera.kind == CHAIN_ORTHOGRAPHIC {
        let cone = rc::orthographic_ray_cone(camera.view_height, camera.image_height);
        return ChainRay {
            cone,
            diff: chain_pixel_axis_diff(cone),
        };
    }
    let alpha = rc::pixel_spread_angle_small(camera.fov_y, camera.image_height);
    let cone = rc::thin_lens_ray_cone(alpha, camera.aperture, camera.focus_distance);
    ChainRay {
        cone,
        diff: chain_pixel_axis_diff(cone),
    }
}

/// The change of the mirror's stored normal when the hit moves by `dp` in the tangent plane:
/// `k1 (u1 . dp) u1 + k2 (u2 . dp) u2` (on a sphere simply `curvature * dp`).
pub fn chain_normal_change(leg: ChainLeg, dp: Vec3) -> Vec3 {
    let k = leg.principal_curvatures;
    k.x * leg.first_principal_direction.dot(dp) * leg.first_principal_direction
        + k.y * leg.second_principal_direction.dot(dp) * leg.second_principal_direction
}

/// The ray reflected at the leg's mirror: the cone spread by `curvature_spread_angle` and
/// `propagate`d, the differential (`at_hit`, already transferred to the hit) reflected by
/// `reflect_ray_diff` with the normal's change.
pub fn chain_reflect(ray: ChainRay, at_hit: RayDiff, width: f32, leg: ChainLeg) -> ChainRay {
    let normal_change = Derivatives3::new(
        chain_normal_change(leg, at_hit.d_origin_dx),
        chain_normal_change(leg, at_hit.d_origin_dy),
    );
    let beta = rc::curvature_spread_angle(leg.curvature, width, leg.normal, leg.direction);
    ChainRay {
        cone: rc::propagate(ray.cone, leg.distance, beta),
        diff: rd::reflect_ray_diff(at_hit, leg.direction, leg.normal, normal_change),
    }
}

/// The chain: the primary ray, reflected at the end of its first `bounces` legs (at most
/// [`CHAIN_MAX_BOUNCES`]) and followed along one more leg. At the end of every leg, the cone's
/// width (`width_at`) and the differential transferred there (`transfer`), measured along the
/// leg's pixel axes.
pub fn reflection_chain(
    camera: ChainCamera,
    bounces: u32,
    leg0: ChainLeg,
    leg1: ChainLeg,
    leg2: ChainLeg,
    leg3: ChainLeg,
    leg4: ChainLeg,
) -> ChainSamples {
    let legs = [leg0, leg1, leg2, leg3, leg4];
    let mut samples = [ChainSample::default(); 5];
    let mut ray = chain_primary(camera);
    let reflections = bounces.min(CHAIN_MAX_BOUNCES) as usize;
    for (index, &leg) in legs.iter().enumerate().take(reflections + 1) {
        let at_hit = rd::transfer(ray.diff, leg.direction, leg.distance, leg.normal);
        let width = rc::width_at(ray.cone, leg.distance);
        samples[index] = ChainSample {
            width,
            footprint: Vec2::new(
                at_hit.d_origin_dx.dot(leg.right),
                at_hit.d_origin_dy.dot(leg.down),
            ),
        };
        if index < reflections {
            ray = chain_reflect(ray, at_hit, width, leg);
        }
    }
    let [first, second, third, fourth, fifth] = samples;
    ChainSamples {
        first,
        second,
        third,
        fourth,
        fifth,
    }
}

/// The chain shader in `language`: the ray-cone and ray-differential modules of `language`
/// followed by the chain: the WGSL modules and `reflection_chain.wgsl`; the GLSL modules and
/// `reflection_chain.glsl`; or the Slang modules and `reflection_chain.glsl` through slangc's GLSL
/// compatibility. `Err` for either HLSL compiler: the chain shader is not written in HLSL.
pub fn chain_shader(language: Language) -> Result<Shader, String> {
    let modules = [Module::RayCone, Module::RayDiff];
    Ok(match language {
        Language::Wgsl => {
            let source = format!(
                "{}{}",
                wgsl_prelude(&modules),
                include_str!("reflection_chain.wgsl")
            );
            let capabilities = modules[0].naga_capabilities() | modules[1].naga_capabilities();
            Shader::wgsl(source).capabilities(capabilities)
        }
        Language::Glsl => Shader::glsl(
            "#include \"ray_cone.glsl\"\n#include \"ray_diff.glsl\"\n#include \"reflection_chain.glsl\"",
        )
        .include_dir(GLSL_INCLUDE_DIR)
        .include_dir(CHAIN_SHADER_DIR),
        Language::Slang => Shader::slang(
            "import glsl;\nimport ray_cone;\nimport ray_diff;\n#include \"reflection_chain.glsl\"",
        )
        .include_dir(SLANG_INCLUDE_DIR)
        .include_dir(CHAIN_SHADER_DIR),
        Language::HlslGlslang | Language::HlslSlangc => {
            return Err("the chain shader is not written in HLSL".into())
        }
    })
}
