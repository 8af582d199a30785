//! Ray tracing with real acceleration structures.
//!
//! The GLSL, the Slang and the HLSL closest-hit shaders and the WGSL ray-query shader record, per
//! pixel, the primary hit (distance, normal, barycentrics, instance, triangle), every ray-cone
//! value they computed there, the ray-differential, re-intersection and wireframe values, the
//! material's values (a mirror's roughness spread; on glass the index ratio, the normal's spread,
//! the refracted cone and its sagittal section) and the anisotropic cone gradients, on the gallery
//! and on the materials scene. The Rust mirror
//! recomputes each value from the same hit data, the scene's own vertices and the frame's
//! uniforms; each function is given exactly the inputs the shader gave it, so each comparison
//! measures one library function, within the tolerance its record in `ray-footprint-cases` derives
//! (restated below for the ray-cone values, and reused where the suite exports the check: every
//! ray_diff and wireframe value).

use super::SETUP_COMMAND;
use glam::{Mat4, Vec2, Vec3};
use ray_footprint::layout::{self, GlslPacking, StructLayout};
use ray_footprint::ray_cone::{self as rc, RayCone, RefractedRayCone, MIN_COS, MIN_MAGNITUDE};
use ray_footprint::ray_diff::{Derivatives2, Derivatives3, NeighbourDirections, RayDiff};
use ray_footprint::shaders::{GLSL_INCLUDE_DIR, HLSL_INCLUDE_DIR, SLANG_INCLUDE_DIR};
use ray_footprint::wireframe::WireframeSettings;
use ray_footprint_cases as suite;
use ray_footprint_cases::ray_cone::curvature::curvature_spread_angle::curvature_spread_angle_error;
use ray_footprint_cases::ray_cone::curvature::isotropic_curvature::hit_curvature_error;
use ray_footprint_cases::ray_cone::footprint::shared::area_corners;
use ray_footprint_lab::rt::abi::{
    self, RtDiffRecord, RtPixelRecord, RtPushConstants, RtUniforms, FLAG_GLOSSY_LOBE, FLAG_PIXEL_JITTER,
};
use ray_footprint_lab::rt::{
    open_device, ray_query_source, Camera, ClosestHit, Error, Frame, Material, Mode, Renderer, Scene, Vertex,
    SHADER_DIR,
};
use shader_proptest::tolerance::{dot_error, log2_error, ulps};
use shader_proptest::{FunctionCheck, Gpu, Language, Shader, Value};
use std::path::Path;

/// The test image: small, so the test is quick on lavapipe, with every mesh in view.
const WIDTH: u32 = 64;
const HEIGHT: u32 = 48;
/// The torus close-up's image: large enough that its quads are over 10 pixels wide, so the
/// wireframe has gaps between its lines.
const TORUS_VIEW: (u32, u32) = (200, 150);
/// A `tex_grad_scale` other than 1, so the gradient's scaling is exercised.
const TEX_GRAD_SCALE: f32 = 2.0;
/// An offset of the primary rays from the pixel centres, in pixels, for the view that checks it.
const PIXEL_OFFSET: Vec2 = Vec2::new(0.375, -0.25);
/// The torus' mesh index in [`Scene::gallery`].
const TORUS: u32 = 2;

/// The renderer's device (ray tracing); panics with what to install when there is none.
pub(crate) fn gpu() -> Gpu {
    open_device().unwrap_or_else(|error| panic!("{error}\non Debian 12 run `{SETUP_COMMAND}`"))
}

/// The renderer's shared structs have one layout in Rust, WGSL (naga), std430 and scalar in GLSL
/// (glslang) and in Slang (slangc), and in HLSL's structured buffers (std430, glslang and slangc),
/// field by field; the uniform block's struct also under std140.
#[test]
fn renderer_structs_have_one_layout() {
    for rust in abi::layouts() {
        let packings: &[GlslPacking] = if rust.name == "RtUniforms" {
            &[GlslPacking::Std140, GlslPacking::Std430, GlslPacking::Scalar]
        } else {
            &[GlslPacking::Std430, GlslPacking::Scalar]
        };
        compare_layouts(&rust, packings);
    }
}

/// Compares `rust` with its WGSL declaration in the ray-query source, its GLSL declaration in
/// `rt_abi.glsl` and its Slang declaration in `rt_abi.slang` under each of `packings`, and its HLSL
/// declaration in `rt_abi.hlsl` under std430 with each HLSL compiler, and prints the table.
fn compare_layouts(rust: &StructLayout, packings: &[GlslPacking]) {
    let include_dirs = [Path::new(GLSL_INCLUDE_DIR), Path::new(SHADER_DIR)];
    let search_dirs = [Path::new(SLANG_INCLUDE_DIR), Path::new(SHADER_DIR)];
    let wgsl = layout::wgsl_layout(&ray_query_source(), &rust.name).unwrap_or_else(|e| panic!("{e}"));
    let glsl = packings.iter().map(|&packing| {
        let layout = layout::glsl_layout("#include \"rt_abi.glsl\"", &rust.name, packing, &include_dirs);
        (packing.qualifier().to_string(), layout)
    });
    let slang = packings.iter().map(|&packing| {
        let layout = layout::slang_layout("import rt_abi;", &rust.name, packing, &search_dirs);
        (format!("Slang {}", packing.qualifier()), layout)
    });
    let hlsl = [Language::HlslGlslang, Language::HlslSlangc].map(|language| {
        let shader = Shader::new(language, "#include \"rt_abi.hlsl\"")
            .include_dir(HLSL_INCLUDE_DIR)
            .include_dir(SHADER_DIR);
        (
            format!("{} std430", language.name()),
            shader.struct_layout(&rust.name),
        )
    });
    let shaders: Vec<_> = glsl
        .chain(slang)
        .chain(hlsl)
        .map(|(label, layout)| (label, layout.unwrap_or_else(|e| panic!("{e}"))))
        .collect();
    let mut columns = vec![("WGSL", &wgsl)];
    columns.extend(shaders.iter().map(|(label, layout)| (label.as_str(), layout)));
    for (_, shader) in &columns {
        layout::compare(rust, shader).unwrap_or_else(|e| panic!("{e}"));
    }
    println!("{}", layout::render_columns(rust, &columns));
}

/// The GLSL closest-hit shader's values agree with the Rust mirror at every hit pixel.
#[test]
fn glsl_closest_hit_agrees_with_the_mirror() {
    agree(
        "GLSL closest hit",
        ClosestHit::Glsl,
        |renderer, push, uniforms| renderer.render(push, uniforms),
    );
}

/// The Slang closest-hit shader's values agree with the Rust mirror at every hit pixel.
#[test]
fn slang_closest_hit_agrees_with_the_mirror() {
    agree(
        "Slang closest hit",
        ClosestHit::Slang,
        |renderer, push, uniforms| renderer.render(push, uniforms),
    );
}

/// The HLSL closest-hit shader's values agree with the Rust mirror at every hit pixel.
#[test]
fn hlsl_closest_hit_agrees_with_the_mirror() {
    agree(
        "HLSL closest hit",
        ClosestHit::Hlsl,
        |renderer, push, uniforms| renderer.render(push, uniforms),
    );
}

/// The WGSL ray-query shader's values agree with the Rust mirror at every hit pixel.
#[test]
fn wgsl_ray_query_agrees_with_the_mirror() {
    agree("WGSL ray query", ClosestHit::Glsl, |renderer, push, uniforms| {
        renderer.trace_wgsl(push, uniforms)
    });
}

/// [`FLAG_GLOSSY_LOBE`] changes what the rough mirror of the materials scene shows, at most of its
/// pixels, and nothing else: every pixel whose primary ray hits another mesh or nothing keeps its
/// colour (the flag turns only the mirrors' reflections, and the rough sphere is the only mirror).
#[test]
fn glossy_lobe_changes_only_the_rough_mirror() {
    const ROUGH_SPHERE: u32 = 2;
    let gpu = gpu();
    let renderer = Renderer::new(&gpu, Scene::materials()).unwrap_or_else(|e| panic!("{e}"));
    let camera = Camera::materials();
    let mut push = renderer.push_constants(&camera, Mode::Mip0, 1.0, WIDTH, HEIGHT);
    let uniforms = camera.uniforms((WIDTH, HEIGHT), WireframeSettings::default());
    let mirrored = renderer
        .render(&push, &uniforms)
        .unwrap_or_else(|e| panic!("{e}"));
    push.flags = FLAG_GLOSSY_LOBE;
    let glossy = renderer
        .render(&push, &uniforms)
        .unwrap_or_else(|e| panic!("{e}"));
    let (mut rough, mut rough_changed, mut other_changed) = (0, 0, 0);
    for ((record, a), b) in mirrored.records.iter().zip(&mirrored.pixels).zip(&glossy.pixels) {
        if record.hit == 1 && record.instance == ROUGH_SPHERE {
            rough += 1;
            rough_changed += usize::from(a != b);
        } else {
            other_changed += usize::from(a != b);
        }
    }
    println!("rough sphere: {rough_changed} of {rough} pixels changed; elsewhere {other_changed}");
    assert!(
        2 * rough_changed > rough,
        "the lobe changes most of the rough mirror"
    );
    assert_eq!(other_changed, 0, "the lobe changes nothing else");
}

/// `RtPushConstants::lod_bias` is read by `path_bias` alone, past the first hit: with a bias of 0
/// it renders `path_curvature`'s pixels exactly; a bias of 6 mip levels changes the colour of
/// pixels of the materials view whose paths reach the textured ground after the first hit (223 of
/// 3,072 on lavapipe) and none of `path_cone`'s.
#[test]
fn lod_bias_moves_only_path_bias() {
    let gpu = gpu();
    let renderer = Renderer::new(&gpu, Scene::materials()).unwrap_or_else(|e| panic!("{e}"));
    let camera = Camera::materials();
    let uniforms = camera.uniforms((WIDTH, HEIGHT), WireframeSettings::default());
    let render = |mode: Mode, lod_bias: f32| {
        let mut push = renderer.push_constants(&camera, mode, 1.0, WIDTH, HEIGHT);
        push.lod_bias = lod_bias;
        renderer
            .render(&push, &uniforms)
            .unwrap_or_else(|e| panic!("{mode}: {e}"))
            .pixels
    };
    let changed = |a: &[[u8; 4]], b: &[[u8; 4]]| a.iter().zip(b).filter(|(a, b)| a != b).count();
    let curvature = render(Mode::PathCurvature, 6.0);
    let unbiased = changed(&render(Mode::PathBias, 0.0), &curvature);
    let biased = changed(&render(Mode::PathBias, 6.0), &curvature);
    let cone = changed(&render(Mode::PathCone, 6.0), &render(Mode::PathCone, 0.0));
    let pixels = curvature.len();
    println!("of {pixels} pixels, against path_curvature: bias 0 changes {unbiased}, bias 6 {biased}; path_cone {cone}");
    assert_eq!(unbiased, 0, "path_bias at bias 0 is path_curvature");
    assert!(biased > 0, "a bias of 6 levels changes pixels");
    assert_eq!(cone, 0, "path_cone reads no bias");
}

/// With [`FLAG_PIXEL_JITTER`] each pixel's primary ray passes through a sub-pixel position of its
/// own. The offsets recovered from the recorded directions (the inverse of the camera's
/// projection) are the frame's offset at every pixel without the flag; with it they lie in the
/// pixel, their mean is near 0 and their variance near a uniform offset's 1/12 per axis (over the
/// ground's 2,000 or so pixels the variance's sampling error is about 2% of it, the mean's 0.0065;
/// the bounds allow 15% and 0.03).
#[test]
fn pixel_jitter_gives_every_pixel_an_offset_of_its_own() {
    let gpu = gpu();
    let renderer = Renderer::new(&gpu, Scene::gallery()).unwrap_or_else(|e| panic!("{e}"));
    let camera = Camera::ground();
    let uniforms = camera.uniforms((WIDTH, HEIGHT), WireframeSettings::default());
    let offsets = |flags: u32| -> Vec<Vec2> {
        let mut push = renderer.push_constants(&camera, Mode::Mip0, TEX_GRAD_SCALE, WIDTH, HEIGHT);
        push.pixel_offset = PIXEL_OFFSET;
        push.flags = flags;
        let frame = renderer
            .render(&push, &uniforms)
            .unwrap_or_else(|e| panic!("{e}"));
        let size = Vec2::new(WIDTH as f32, HEIGHT as f32);
        frame
            .records
            .iter()
            .enumerate()
            .filter(|(_, record)| record.hit == 1)
            .map(|(index, record)| {
                let d = record.direction / record.direction.dot(push.forward);
                let centred = Vec2::new(
                    d.dot(push.right) / (push.aspect * push.tan_half_fov_y),
                    -d.dot(push.up) / push.tan_half_fov_y,
                );
                let pixel = Vec2::new((index as u32 % WIDTH) as f32, (index as u32 / WIDTH) as f32);
                (centred + 1.0) * 0.5 * size - pixel - 0.5
            })
            .collect()
    };
    let shared = offsets(0);
    let largest = shared
        .iter()
        .map(|o| (*o - PIXEL_OFFSET).abs().max_element())
        .fold(0.0, f32::max);
    assert!(
        largest < 1e-2,
        "without the flag every pixel samples the frame's offset: off by {largest}"
    );
    let own = offsets(FLAG_PIXEL_JITTER);
    let count = own.len() as f32;
    let mean = own.iter().copied().sum::<Vec2>() / count;
    let variance = own.iter().map(|o| (*o - mean) * (*o - mean)).sum::<Vec2>() / count;
    println!(
        "{} pixels' own offsets: mean {mean}, variance {variance} (uniform: 0, 1/12 = 0.0833)",
        own.len()
    );
    assert!(
        own.iter().all(|o| o.abs().max_element() <= 0.5 + 1e-2),
        "an offset left its pixel"
    );
    assert!(
        mean.abs().max_element() < 0.03,
        "the offsets' mean {mean} is not near 0"
    );
    let uniform = 1.0 / 12.0;
    assert!(
        variance.cmpgt(Vec2::splat(0.85 * uniform)).all()
            && variance.cmplt(Vec2::splat(1.15 * uniform)).all(),
        "the offsets' variance {variance} is not a uniform offset's {uniform}"
    );
}

/// Each mode's colour-only pipeline, which computes only what its mode needs and records
/// nothing, renders the pixels of the recording pipeline in that mode in every [`colour_views`]
/// view, to one [`ROUNDING_STEP`].
#[test]
fn colour_pipelines_render_the_recorded_colours() {
    let gpu = gpu();
    println!("device: {}", gpu.name());
    for (scene, views) in colour_views() {
        let renderer = Renderer::new(&gpu, scene).unwrap_or_else(|e| panic!("{e}"));
        for mode in Mode::ALL {
            let colour = renderer
                .colour_pipeline(mode)
                .unwrap_or_else(|e| panic!("{mode}: {e}"));
            let label = format!("payload {:>2} bytes", colour.payload_bytes());
            compare_colours(&renderer, &views, mode, &label, |push, uniforms| {
                let rendered = colour.render(push, uniforms)?;
                assert!(rendered.records.is_empty());
                Ok(rendered)
            });
        }
    }
}

/// The recording pipeline with the Slang closest-hit shader renders the pixels of the one with the
/// GLSL closest-hit shader ([`closest_hit_renders_the_glsl_colours`]).
#[test]
fn slang_closest_hit_renders_the_glsl_colours() {
    closest_hit_renders_the_glsl_colours(ClosestHit::Slang, "Slang closest hit");
}

/// The recording pipeline with the HLSL closest-hit shader renders the pixels of the one with the
/// GLSL closest-hit shader ([`closest_hit_renders_the_glsl_colours`]).
#[test]
fn hlsl_closest_hit_renders_the_glsl_colours() {
    closest_hit_renders_the_glsl_colours(ClosestHit::Hlsl, "HLSL closest hit");
}

/// The recording pipeline with `closest_hit` (labelled `label`) renders the pixels of the one
/// with the GLSL closest-hit shader (to one [`ROUNDING_STEP`]), in every mode and
/// [`colour_views`] view: the two shade alike, the mirrors' reflected and the glass' refracted
/// cones and differentials included.
fn closest_hit_renders_the_glsl_colours(closest_hit: ClosestHit, label: &str) {
    let gpu = gpu();
    println!("device: {}", gpu.name());
    for (scene, views) in colour_views() {
        let other =
            Renderer::with_closest_hit(&gpu, scene.clone(), closest_hit).unwrap_or_else(|e| panic!("{e}"));
        let glsl = Renderer::new(&gpu, scene).unwrap_or_else(|e| panic!("{e}"));
        for mode in Mode::ALL {
            compare_colours(&glsl, &views, mode, label, |push, uniforms| {
                other.render(push, uniforms)
            });
        }
    }
}

/// A colour comparison's view: its name, the camera, the primary rays' offset from the pixel
/// centres and the push constants' flags.
type ColourView = (&'static str, Camera, Vec2, u32);

/// The views the colour comparisons render, per scene: on the gallery the ground view, through the
/// pixel centres, through points off them ([`PIXEL_OFFSET`]) and through each pixel's own point
/// ([`FLAG_PIXEL_JITTER`]), the mirror close-up and the torus
/// close-up; on the materials scene the glass close-up, the glass from inside ([`inside_glass`],
/// where rays reflect totally), and both spheres with the rough mirror reflecting about the
/// shading normal and about GGX-drawn normals ([`FLAG_GLOSSY_LOBE`]).
fn colour_views() -> [(Scene, Vec<ColourView>); 2] {
    let gallery = vec![
        ("ground", Camera::ground(), Vec2::ZERO, 0),
        ("ground off centre", Camera::ground(), PIXEL_OFFSET, 0),
        (
            "ground, own offsets",
            Camera::ground(),
            PIXEL_OFFSET,
            FLAG_PIXEL_JITTER,
        ),
        ("reflection", Camera::reflection(), Vec2::ZERO, 0),
        ("torus", Camera::torus(), Vec2::ZERO, 0),
    ];
    let materials = vec![
        ("glass", Camera::glass(), Vec2::ZERO, 0),
        ("inside glass", inside_glass(), Vec2::ZERO, 0),
        ("materials", Camera::materials(), Vec2::ZERO, 0),
        (
            "materials glossy",
            Camera::materials(),
            PIXEL_OFFSET,
            FLAG_GLOSSY_LOBE,
        ),
    ];
    [(Scene::gallery(), gallery), (Scene::materials(), materials)]
}

/// Renders every view of `views` in `mode` with `recording`'s recording pipeline and with
/// `render`, prints how many pixels differ after `label` and by how much in a channel, and
/// asserts that none differs by more than [`ROUNDING_STEP`].
fn compare_colours(
    recording: &Renderer<'_>,
    views: &[ColourView],
    mode: Mode,
    label: &str,
    render: impl Fn(&RtPushConstants, &RtUniforms) -> Result<Frame, Error>,
) {
    let (width, height) = (WIDTH, HEIGHT);
    for &(view, camera, offset, flags) in views {
        let mut push = recording.push_constants(&camera, mode, TEX_GRAD_SCALE, width, height);
        push.pixel_offset = offset;
        push.flags = flags;
        let uniforms = camera.uniforms((width, height), WireframeSettings::default());
        let recorded = recording
            .render(&push, &uniforms)
            .unwrap_or_else(|e| panic!("{e}"));
        let rendered = render(&push, &uniforms).unwrap_or_else(|e| panic!("{mode}: {e}"));
        assert_eq!(rendered.pixels.len(), recorded.pixels.len());
        let channel_differences: Vec<u8> = recorded
            .pixels
            .iter()
            .zip(&rendered.pixels)
            .filter(|(a, b)| a != b)
            .map(|(a, b)| (0..4).map(|c| a[c].abs_diff(b[c])).max().unwrap_or(0))
            .collect();
        let largest = channel_differences.iter().copied().max().unwrap_or(0);
        println!(
            "{mode:<18} {view:<17} {label}: {} of {} pixels differ, by at most {largest} in a channel",
            channel_differences.len(),
            rendered.pixels.len()
        );
        assert!(
            largest <= ROUNDING_STEP,
            "{mode}, {view} view ({label}): other pixels"
        );
    }
}

/// The largest difference in an 8-bit channel between two pipelines that compute a colour with
/// the same expressions: one step. SPIR-V lets a driver fuse a multiply and an add in one pipeline
/// and not in the other, so a colour's last bits may differ, and one that close to the middle
/// between two steps is stored as either. The H100 showed it in one pixel of 3,072 (`ray_diff`,
/// ground view, by 1) in one build of the shaders and in none in another; lavapipe in none. A
/// different texel or mip level differs by more.
const ROUNDING_STEP: u8 = 1;

/// A view: camera, mode, wireframe settings, image size and the primary rays' offset from the
/// pixel centres.
type View = (Camera, Mode, WireframeSettings, (u32, u32), Vec2);

/// The scenes every path traces, each with its views: the gallery ([`gallery_views`]) and the
/// materials scene ([`material_views`]).
fn scenes() -> [(Scene, Vec<View>); 2] {
    [
        (Scene::gallery(), gallery_views()),
        (Scene::materials(), material_views()),
    ]
}

/// The gallery's views: the ground view, through the pixel centres and through points off them
/// ([`PIXEL_OFFSET`]), the mirror close-up, and the torus close-up once per wireframe preset, each
/// with its mode, wireframe settings, image size and pixel offset.
fn gallery_views() -> Vec<View> {
    let small = (WIDTH, HEIGHT);
    let default = WireframeSettings::default();
    let mut views = vec![
        (Camera::ground(), Mode::ConeCurvature, default, small, Vec2::ZERO),
        (
            Camera::ground(),
            Mode::ConeCurvature,
            default,
            small,
            PIXEL_OFFSET,
        ),
        (
            Camera::reflection(),
            Mode::ConeCurvature,
            default,
            small,
            Vec2::ZERO,
        ),
    ];
    let presets = WireframeSettings::PRESETS.iter();
    views.extend(
        presets.map(|&(_, settings)| (Camera::torus(), Mode::Wireframe, settings, TORUS_VIEW, Vec2::ZERO)),
    );
    views
}

/// The materials scene's views: the glass close-up, both spheres over the ground plane, and the
/// glass sphere from inside ([`inside_glass`]).
fn material_views() -> Vec<View> {
    let (small, default) = ((WIDTH, HEIGHT), WireframeSettings::default());
    vec![
        (Camera::glass(), Mode::ConeSections, default, small, Vec2::ZERO),
        (
            Camera::materials(),
            Mode::ConeRoughness,
            default,
            small,
            PIXEL_OFFSET,
        ),
        (inside_glass(), Mode::ConeRefraction, default, small, Vec2::ZERO),
    ]
}

/// An eye inside the glass sphere of [`Scene::materials`] (centre (-1.3, 1, -1.5), radius 1), 0.7
/// off its centre, looking along -z: every primary ray meets the sphere from inside, where the
/// index ratio is the index itself, and those meeting it more than asin(1 / 1.5) = 41.8 degrees
/// off its normal (the view's centre among them: sin i = 0.7) are totally internally reflected.
fn inside_glass() -> Camera {
    Camera {
        eye: Vec3::new(-0.6, 1.0, -1.5),
        target: Vec3::new(-0.6, 1.0, -3.0),
        fov_y: 60f32.to_radians(),
    }
}

/// What a frame was traced with: the push constants and the uniforms.
struct Inputs {
    push: RtPushConstants,
    uniforms: RtUniforms,
}

/// Traces every view of every scene with `trace` on a renderer whose recording pipeline has
/// `closest_hit`, checks every pixel and prints, per value, the pixels checked and the largest
/// error, and per wireframe preset how much of the torus view its lines cover.
fn agree(
    path: &str,
    closest_hit: ClosestHit,
    trace: impl Fn(&Renderer<'_>, &RtPushConstants, &RtUniforms) -> Result<Frame, Error>,
) {
    let gpu = gpu();
    println!(
        "device: {}; {path}, {WIDTH} x {HEIGHT} per view, the torus at {} x {}",
        gpu.name(),
        TORUS_VIEW.0,
        TORUS_VIEW.1
    );
    let mut stats = Stats::default();
    for (scene, views) in scenes() {
        let renderer = Renderer::with_closest_hit(&gpu, scene, closest_hit).unwrap_or_else(|e| panic!("{e}"));
        trace_views(&renderer, &views, &trace, &mut stats);
    }
    print!("{}", stats.table());
    println!(
        "glass hits totally internally reflected: {}",
        stats.total_internal_reflections
    );
    assert!(stats.misses > 0, "some pixels must see the sky");
    assert!(
        stats.total_internal_reflections > 0,
        "the view from inside the glass must reflect totally"
    );
    assert!(
        stats.failures.is_empty(),
        "{} value(s) out of tolerance:\n{}",
        stats.failures.len(),
        stats.failures.join("\n")
    );
}

/// Traces `views` of `renderer`'s scene with `trace`, checks every pixel into `stats`, prints the
/// hits per mesh and asserts that every mesh is hit.
fn trace_views(
    renderer: &Renderer<'_>,
    views: &[View],
    trace: impl Fn(&Renderer<'_>, &RtPushConstants, &RtUniforms) -> Result<Frame, Error>,
    stats: &mut Stats,
) {
    let mut hits_per_mesh = vec![0usize; renderer.scene().meshes.len()];
    for &(camera, mode, settings, (width, height), offset) in views {
        let mut push = renderer.push_constants(&camera, mode, TEX_GRAD_SCALE, width, height);
        push.pixel_offset = offset;
        let inputs = Inputs {
            push,
            uniforms: camera.uniforms((width, height), settings),
        };
        let frame = trace(renderer, &inputs.push, &inputs.uniforms).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(frame.records.len(), (width * height) as usize);
        for (index, record) in frame.records.iter().enumerate() {
            let centre = Vec2::new((index as u32 % width) as f32, (index as u32 / width) as f32);
            // The matrix functions take the pixel's coordinates plus the offset.
            let pixel = centre + offset;
            check_pixel(renderer.scene(), &inputs, pixel, record, stats);
            if record.hit == 1 {
                hits_per_mesh[record.instance as usize] += 1;
            }
        }
        if mode == Mode::Wireframe {
            check_line_coverage(&frame, settings);
        }
    }
    let names: Vec<_> = renderer.scene().meshes.iter().map(|m| m.name).collect();
    println!(
        "hits per mesh {names:?}: {hits_per_mesh:?}; misses so far: {}",
        stats.misses
    );
    assert!(hits_per_mesh.iter().all(|&n| n > 0), "every mesh must be hit");
}

/// Largest error and largest error over tolerance of one value, over the pixels checked.
#[derive(Default)]
struct Stat {
    pixels: usize,
    max_error: f32,
    max_ratio: f32,
}

/// Every value's [`Stat`], in the order first seen, and the first disagreements.
#[derive(Default)]
struct Stats {
    values: Vec<(&'static str, Stat)>,
    misses: usize,
    /// Glass hits whose record says total internal reflection.
    total_internal_reflections: usize,
    failures: Vec<String>,
}

impl Stats {
    /// Compares `got` (shader) with `expected` (mirror) for `value` within `tolerance`.
    fn compare(
        &mut self,
        value: &'static str,
        got: f32,
        expected: f32,
        tolerance: f32,
        record: &RtPixelRecord,
    ) {
        self.compare_components(value, &[(got, expected, tolerance)], record);
    }

    /// Compares one pixel's `value`, given as (shader, mirror, tolerance) per component.
    fn compare_components(
        &mut self,
        value: &'static str,
        components: &[(f32, f32, f32)],
        record: &RtPixelRecord,
    ) {
        let index = match self.values.iter().position(|(name, _)| *name == value) {
            Some(index) => index,
            None => {
                self.values.push((value, Stat::default()));
                self.values.len() - 1
            }
        };
        for &(got, expected, tolerance) in components {
            let error = if got == expected {
                0.0
            } else {
                (got - expected).abs()
            };
            if (error.is_nan() || error > tolerance) && self.failures.len() < 10 {
                self.failures.push(format!(
                    "{value}: shader {got:e}, mirror {expected:e}, error {error:e} > tolerance {tolerance:e}\n  {record:?}"
                ));
            }
            let stat = &mut self.values[index].1;
            stat.max_error = stat.max_error.max(error);
            if tolerance > 0.0 {
                stat.max_ratio = stat.max_ratio.max(error / tolerance);
            }
        }
        self.values[index].1.pixels += 1;
    }

    fn table(&self) -> String {
        self.values
            .iter()
            .map(|(name, s)| {
                format!(
                    "{name:<20} {:>6} pixels  max error {:>9.3e}  ({:.4} of tolerance)\n",
                    s.pixels, s.max_error, s.max_ratio
                )
            })
            .collect()
    }
}

/// Checks one pixel's record: a miss carries only the primary cone; a hit is looked up in the
/// scene and every value is recomputed by the mirror from the shader's own inputs.
fn check_pixel(scene: &Scene, inputs: &Inputs, pixel: Vec2, record: &RtPixelRecord, stats: &mut Stats) {
    let push = &inputs.push;
    // The primary cone: the push constant's spread narrowed by the ray's cosine to the view axis.
    let cone_args = (push.cone.pixel_spread_angle, record.direction, push.forward);
    let cone_check = suite::ray_cone::cameras::pinhole_ray_cone_for_ray::record().check();
    compare_with(
        stats,
        "primary cone",
        cone_check,
        (cone_args, record.cone),
        record,
    );
    if record.hit == 0 {
        assert_eq!(record.diff, RtDiffRecord::default(), "a miss measures nothing");
        stats.misses += 1;
        return;
    }
    assert_eq!(record.hit, 1, "hit flag: {record:?}");
    let mesh = scene
        .meshes
        .get(record.instance as usize)
        .expect("instance names a mesh");
    assert!(
        (record.primitive as usize) < mesh.triangle_count(),
        "primitive in range: {record:?}"
    );
    let tri = mesh.triangle(record.primitive);
    check_hit_data(&tri, push, record, stats);
    check_values(&tri, push, record, stats);
    check_material_values(mesh.material, &tri, record, stats);
    check_differentials(&tri, inputs, pixel, record, stats);
    check_reintersection(&tri, inputs, record, stats);
}

/// Compares the shader's `got` with the mirror of the suite's `check` on `args`, component by
/// component, each within the check's own tolerance for it.
fn compare_with<A: shader_proptest::Args, R: Value>(
    stats: &mut Stats,
    value: &'static str,
    check: FunctionCheck<A, R>,
    (args, got): (A, R),
    record: &RtPixelRecord,
) {
    let expected = check.mirror(args.clone());
    let bounds = check.bounds(&args, &expected);
    let (mut shader, mut mirror) = (Vec::new(), Vec::new());
    got.components(&mut shader);
    expected.components(&mut mirror);
    assert_eq!(shader.len(), mirror.len());
    let components: Vec<_> = shader
        .iter()
        .zip(&mirror)
        .zip(bounds)
        .map(|((&got, &expected), bound)| (got, expected, bound))
        .collect();
    stats.compare_components(value, &components, record);
}

/// The shader's `lod` of the UV gradients `uv` against `rf_lod_isotropic` of them in texels of the
/// renderer's square texture (a power of two: the conversion is exact).
fn compare_lod(
    stats: &mut Stats,
    value: &'static str,
    (uv, lod): (Derivatives2, f32),
    push: &RtPushConstants,
    record: &RtPixelRecord,
) {
    let texels = Derivatives2::new(uv.dx * push.texture_size, uv.dy * push.texture_size);
    compare_with(
        stats,
        value,
        suite::ray_diff::derivatives::lod_isotropic::record().check(),
        ((texels,), lod),
        record,
    );
}

/// The hit barycentrics `(w, u, v)` as the shaders form them.
fn weights(record: &RtPixelRecord) -> Vec3 {
    let (u, v) = (record.barycentrics.x, record.barycentrics.y);
    Vec3::new(1.0 - u - v, u, v)
}

/// The eye-ray differential of `pixel` from the uniforms' matrices, carried to the hit as
/// barycentric and UV derivatives, and their LOD: each against the mirror on the shader's inputs.
fn check_differentials(
    tri: &[Vertex; 3],
    inputs: &Inputs,
    pixel: Vec2,
    record: &RtPixelRecord,
    stats: &mut Stats,
) {
    let (d, push, uniforms) = (&record.diff, &inputs.push, &inputs.uniforms);
    let size = Vec2::new(push.width as f32, push.height as f32);
    let (p, uv) = (tri.map(|v| v.position), tri.map(|v| v.uv));
    let matrices = (pixel, size, uniforms.view_inv, uniforms.proj_inv);
    let eye = RayDiff::new(Vec3::ZERO, Vec3::ZERO, d.eye_d_direction_dx, d.eye_d_direction_dy);
    let eye_check = suite::ray_diff::camera::eye_ray_diff_from_matrices::record().check();
    compare_with(stats, "eye ray diff", eye_check, (matrices, eye), record);
    let barycentric = Derivatives2::new(d.barycentric_dx, d.barycentric_dy);
    let transfer_args = (eye, record.direction, record.t, p[0], p[1], p[2]);
    let barycentric_check = suite::ray_diff::derivatives::barycentric_derivatives::record().check();
    compare_with(
        stats,
        "barycentric derivs",
        barycentric_check,
        (transfer_args, barycentric),
        record,
    );
    let gradients = Derivatives2::new(d.uv_dx, d.uv_dy);
    let uv_args = (barycentric, uv[0], uv[1], uv[2]);
    compare_with(
        stats,
        "uv gradients",
        suite::ray_diff::derivatives::texture_derivatives::record().check(),
        (uv_args, gradients),
        record,
    );
    compare_lod(stats, "ray diff lod", (gradients, d.lod), push, record);
}

/// The neighbour pixels' directions, the re-intersected barycentric offsets, their UV gradients
/// and LOD, the deltas and the wireframe coverage they give, and the closed-form cone deltas:
/// each against the mirror on the shader's inputs. The scene's instances have identity
/// transforms, so the world-to-object matrix is the identity; primary rays start at the eye.
fn check_reintersection(tri: &[Vertex; 3], inputs: &Inputs, record: &RtPixelRecord, stats: &mut Stats) {
    let (d, push) = (&record.diff, &inputs.push);
    let (p, uv) = (tri.map(|v| v.position), tri.map(|v| v.uv));
    let next = NeighbourDirections {
        right: d.neighbour_right,
        below: d.neighbour_below,
    };
    let w = weights(record);
    let offset_args = (
        Mat4::IDENTITY,
        push.eye,
        p[0],
        p[1],
        p[2],
        next.right,
        next.below,
        w,
    );
    let offsets = Derivatives3::new(d.offset_dx, d.offset_dy);
    compare_with(
        stats,
        "bary offsets",
        suite::ray_diff::reintersection::barycentric_offsets::record().check(),
        (offset_args, offsets),
        record,
    );
    let gradients = Derivatives2::new(d.offset_uv_dx, d.offset_uv_dy);
    let uv_args = (offsets, uv[0], uv[1], uv[2]);
    let uv_check = suite::ray_diff::reintersection::uv_gradients_from_offsets::record().check();
    compare_with(
        stats,
        "offset uv gradients",
        uv_check,
        (uv_args, gradients),
        record,
    );
    compare_lod(stats, "offset lod", (gradients, d.offset_lod), push, record);
    compare_with(
        stats,
        "bary deltas",
        suite::ray_diff::reintersection::barycentric_deltas::record().check(),
        (offset_args, d.deltas),
        record,
    );
    let settings = inputs.uniforms.wireframe.settings.unpack();
    let coverage_check = suite::wireframe::coverage::process_wireframe::record().check();
    compare_with(
        stats,
        "coverage",
        coverage_check,
        ((settings, w, d.deltas), d.coverage),
        record,
    );
    let cone_args = (record.footprint, p[0], p[1], p[2]);
    let cone_check = suite::ray_diff::cones::cone_barycentric_deltas::record().check();
    compare_with(
        stats,
        "cone deltas",
        cone_check,
        (cone_args, d.cone_deltas),
        record,
    );
    assert_eq!([d.pad0, d.pad1, d.pad2, d.pad3, d.pad4], [0; 5], "pads are 0");
}

/// The wireframe of `settings` on the torus view: some pixels on a line, some between lines,
/// and, where the preset anti-aliases (smoothing > 0), some partly covered. Prints the shares.
fn check_line_coverage(frame: &Frame, settings: WireframeSettings) {
    let torus: Vec<f32> = frame
        .records
        .iter()
        .filter(|r| r.hit == 1 && r.instance == TORUS)
        .map(|r| r.diff.coverage)
        .collect();
    let share =
        |keep: fn(f32) -> bool| torus.iter().filter(|&&c| keep(c)).count() as f32 / torus.len() as f32;
    let (none, partial, full) = (
        share(|c| c == 0.0),
        share(|c| c > 0.0 && c < 1.0),
        share(|c| c == 1.0),
    );
    println!(
        "wireframe {settings:?}\n  torus pixels {}: uncovered {:.1}%, partly covered {:.1}%, fully covered {:.1}%",
        torus.len(),
        100.0 * none,
        100.0 * partial,
        100.0 * full
    );
    assert!(!torus.is_empty(), "the torus view must show the torus");
    assert!(none > 0.0 && none < 1.0, "lines and gaps between them");
    if settings.smoothing > 0.0 {
        assert!(partial > 0.0, "anti-aliased lines have partly covered pixels");
    }
}

/// The hit data is the scene's: the normal is the interpolated vertex normal at the recorded
/// barycentrics, and the hit point lies on the recorded triangle.
fn check_hit_data(tri: &[Vertex; 3], push: &RtPushConstants, record: &RtPixelRecord, stats: &mut Stats) {
    let (u, v) = (record.barycentrics.x, record.barycentrics.y);
    let w = [1.0 - u - v, u, v];
    let terms = [0, 1, 2].map(|i| w[i] * tri[i].normal);
    let sum = terms[0] + terms[1] + terms[2];
    let normal = sum.normalize();
    // Each component: two products and two additions, possibly fused (2.5 ULP of the sum of
    // the terms' magnitudes on each side: 5). A perturbation d of the sum moves its
    // normalization by at most |d| / |sum|; normalize itself (dot 3 ULP -> 1.5, inversesqrt 2,
    // product 0.5) adds 4 ULP, the mirror's 3 more.
    let magnitudes = terms[0].abs() + terms[1].abs() + terms[2].abs();
    let tolerance = ulps(5.0, magnitudes.element_sum()) / sum.length() + ulps(7.0, 1.0);
    let (worst, _) = (0..3)
        .map(|axis| (axis, (record.normal[axis] - normal[axis]).abs()))
        .fold((0, -1.0), |best, next| if next.1 > best.1 { next } else { best });
    stats.compare("normal", record.normal[worst], normal[worst], tolerance, record);
    // Not a Vulkan precision rule (ray-triangle intersection has none): the point at distance t
    // along the ray and the point at the barycentrics must coincide to a part in 10^4 of the
    // distance travelled, which a hit attributed to a wrong triangle or instance misses by far.
    let along_ray = push.eye + record.t * record.direction; // primary rays start at the eye
    let on_triangle = w[0] * tri[0].position + w[1] * tri[1].position + w[2] * tri[2].position;
    let gap = (along_ray - on_triangle).length();
    stats.compare(
        "hit point",
        gap,
        0.0,
        1.0e-4 * (record.t + push.eye.length()),
        record,
    );
}

/// Every ray-cone value, recomputed by the mirror from the inputs the shader used.
fn check_values(tri: &[Vertex; 3], push: &RtPushConstants, record: &RtPixelRecord, stats: &mut Stats) {
    let r = record;
    let (cone, t, n, d) = (r.cone, r.t, r.normal, r.direction);
    let p = tri.map(|v| v.position);
    let uv = tri.map(|v| v.uv);
    let normals = tri.map(|v| v.normal);
    let cos = n.dot(d).abs().max(MIN_COS);
    let width_error = ulps(2.0, cone.width.abs() + (cone.spread_angle * t).abs());

    // width_at: width + spread * t, possibly fused: 2 ULP of the larger term.
    stats.compare("width", r.width, rc::width_at(cone, t), width_error, r);

    // world_footprint: the width's error over |cos|, the division (3 ULP), and the dot
    // product's rounding over |cos| as a relative error.
    let footprint = rc::world_footprint(cone, t, n, d);
    let footprint_error = width_error / cos + ulps(3.0, footprint) + footprint.abs() * dot_error(n, d) / cos;
    stats.compare("footprint", r.footprint, footprint, footprint_error, r);

    // texel_density: the areas' errors through sqrt(uv) / sqrt(world), two square roots, a
    // division and the mirror (14.5 ULP).
    let density = rc::texel_density(p[0], p[1], p[2], uv[0], uv[1], uv[2]);
    let density_error = area_corners(p, uv, |uv, world| {
        uv.sqrt() / world.max(f64::from(MIN_MAGNITUDE)).sqrt()
    }) + ulps(14.5, density);
    stats.compare("texel_density", r.texel_density, density, density_error, r);

    // triangle_base_lod: the areas' errors through 0.5 * (log2 uv - log2 world), half of each
    // log2's own error, the subtraction and the halving (2 ULP).
    let base_lod = rc::triangle_base_lod(p[0], p[1], p[2], uv[0], uv[1], uv[2]);
    let uv_area2 = rc::triangle_uv_area2(uv[0], uv[1], uv[2]).max(MIN_MAGNITUDE);
    let world_area2 = rc::triangle_world_area2(p[0], p[1], p[2]).max(MIN_MAGNITUDE);
    let min = f64::from(MIN_MAGNITUDE);
    let base_lod_error = area_corners(p, uv, |uv, world| {
        0.5 * (uv.max(min).log2() - world.max(min).log2())
    }) + 0.5 * (log2_error(uv_area2.log2()) + log2_error(world_area2.log2()))
        + ulps(2.0, base_lod);
    stats.compare("base_lod", r.base_lod, base_lod, base_lod_error, r);

    // texture_lod: the suite's own tolerance, on the shader's base LOD and width.
    let size = Vec2::splat(push.texture_size);
    let lod_args = (r.base_lod, r.width, size, n, d);
    let lod = rc::texture_lod(r.base_lod, r.width, size, n, d);
    let lod_check = suite::ray_cone::footprint::texture_lod::record().check();
    stats.compare("lod", r.lod, lod, lod_check.bounds(&lod_args, &lod)[0], r);

    // texture_gradient of footprint * density: two correctly rounded products, the same on both
    // sides (the denormal floor only).
    let gradient = rc::texture_gradient(r.footprint * r.texel_density, push.cone.tex_grad_scale);
    stats.compare("gradient", r.gradient, gradient, f32::MIN_POSITIVE, r);

    // The curvature an isotropic cone takes: isotropic_curvature of the principal curvatures of
    // triangle_shape_operator, within the three enclosures chained.
    let shape_operator = rc::triangle_shape_operator(p[0], p[1], p[2], normals[0], normals[1], normals[2]);
    let curvature = rc::isotropic_curvature(rc::principal_curvatures(shape_operator));
    let curvature_error = hit_curvature_error(p, normals);
    stats.compare("curvature", r.curvature, curvature, curvature_error, r);

    // curvature_spread_angle: the suite's own tolerance, on the shader's curvature, width and
    // stored normal.
    let spread = rc::curvature_spread_angle(r.curvature, r.width, n, d);
    let spread_error = curvature_spread_angle_error(n, d, spread);
    stats.compare("curvature_spread", r.curvature_spread, spread, spread_error, r);

    // propagate: the width as width_at; the spread is the cone's plus the curvature spread plus
    // twice the roughness spread (the doubling is exact): two additions, which a driver may
    // associate either way (GLSL without `precise`; the H100 does). Each side rounds twice, by at
    // most half an ULP of a partial sum each: 2 ULPs of the terms' magnitudes together.
    let extra_spread = r.curvature_spread + 2.0 * r.roughness_spread;
    let reflected = rc::propagate(cone, t, extra_spread);
    let spread_terms = cone.spread_angle.abs() + r.curvature_spread.abs() + 2.0 * r.roughness_spread.abs();
    stats.compare(
        "reflected width",
        r.reflected.width,
        reflected.width,
        width_error,
        r,
    );
    stats.compare(
        "reflected spread",
        r.reflected.spread_angle,
        reflected.spread_angle,
        ulps(2.0, spread_terms),
        r,
    );
}

/// The material's values and the anisotropic cone gradients, recomputed by the mirror from the
/// inputs the shader used: a mirror's roughness spread; on glass the index ratio, the normal's
/// spread, the refracted cone and its sagittal section; zeros where the material has none.
fn check_material_values(material: Material, tri: &[Vertex; 3], record: &RtPixelRecord, stats: &mut Stats) {
    let r = record;
    match material {
        Material::Mirror { roughness } => {
            // roughness_spread_angle: the suite's own tolerance, on the mesh's roughness.
            let check = suite::ray_cone::refraction::roughness_spread_angle::record().check();
            compare_with(
                stats,
                "roughness spread",
                check,
                ((roughness,), r.roughness_spread),
                r,
            );
        }
        _ => assert_eq!(r.roughness_spread, 0.0, "no roughness spread off a mirror: {r:?}"),
    }
    match material {
        Material::Glass { index_of_refraction } => check_refraction(index_of_refraction, r, stats),
        _ => {
            let none = (
                r.eta,
                r.normal_spread,
                r.total_internal_reflection,
                r.refracted,
                r.sagittal,
            );
            assert_eq!(
                none,
                (0.0, 0.0, 0, RayCone::default(), RayCone::default()),
                "no refraction off glass: {r:?}"
            );
        }
    }
    // anisotropic_cone_gradients: the suite's own tolerance, on the shader's width and direction
    // and the triangle's vertices.
    let (p, uv) = (tri.map(|v| v.position), tri.map(|v| v.uv));
    let gradient_args = (r.width, r.direction, p[0], p[1], p[2], uv[0], uv[1], uv[2]);
    let gradients = Derivatives2::new(r.cone_uv_dx, r.cone_uv_dy);
    let gradient_check = suite::ray_diff::cones::anisotropic_cone_gradients::record().check();
    compare_with(
        stats,
        "cone uv gradients",
        gradient_check,
        (gradient_args, gradients),
        r,
    );
}

/// A glass hit's index ratio, the normal's spread across the footprint, the refracted cone and its
/// sagittal section, against the mirror on the shader's inputs.
fn check_refraction(index_of_refraction: f32, record: &RtPixelRecord, stats: &mut Stats) {
    let r = record;
    let (n, d) = (r.normal, r.direction);
    // The side the ray meets: the sign of the shader's dot(n, d), certain beyond its rounding
    // (3 ULP of the terms); within it either side's ratio is right. Entering, 1 / index: one
    // division (2.5 ULP); leaving, the index itself.
    let cosine = n.dot(d);
    let sides = if cosine.abs() <= dot_error(n, d) {
        vec![true, false]
    } else {
        vec![cosine < 0.0]
    };
    let ratios = sides.into_iter().map(|entering| {
        if entering {
            1.0 / index_of_refraction
        } else {
            index_of_refraction
        }
    });
    let eta = ratios
        .min_by(|a, b| (a - r.eta).abs().total_cmp(&(b - r.eta).abs()))
        .expect("a side");
    stats.compare("eta", r.eta, eta, ulps(2.5, eta), r);
    // The curvature times the footprint: one correctly rounded product, the same on both sides
    // (the denormal floor only).
    let normal_spread = r.curvature * r.footprint;
    stats.compare(
        "normal spread",
        r.normal_spread,
        normal_spread,
        f32::MIN_POSITIVE,
        r,
    );
    // rf_refract_ray_cone of the cone propagated to the hit (the recorded width, the spread plus an
    // exact 0), with the suite's own tolerance.
    let at_hit = RayCone {
        width: r.width,
        spread_angle: r.cone.spread_angle,
    };
    let args = (at_hit, n, d, r.normal_spread, r.eta);
    let refracted = RefractedRayCone {
        cone: r.refracted,
        total_internal_reflection: r.total_internal_reflection == 1,
    };
    assert!(r.total_internal_reflection <= 1, "a flag: {r:?}");
    stats.total_internal_reflections += r.total_internal_reflection as usize;
    let check = suite::ray_cone::refraction::refract_ray_cone::record().check();
    compare_with(stats, "refracted cone", check, (args, refracted), r);
    // rf_refract_sagittal_cone of the same cone, with the curvature times |width| (one correctly
    // rounded product), with the suite's own tolerance.
    let sagittal_args = (at_hit, n, d, r.curvature * r.width.abs(), r.eta);
    let sagittal_check = suite::ray_cone::refraction::refract_sagittal_cone::record().check();
    compare_with(
        stats,
        "sagittal section",
        sagittal_check,
        (sagittal_args, r.sagittal),
        r,
    );
}
