//! The gallery: renders what the ray-cone helpers do, with real acceleration structures and the
//! GLSL ray-tracing pipeline, on the local Vulkan device (lavapipe unless `SHADER_PROPTEST_DEVICE`
//! names another), validation layer on, into a folder of PNGs.
//!
//! For each mode: the ground plane at grazing angles (`ground_<mode>.png`), a close-up of the
//! mirror sphere (`reflection_<mode>.png`) and the glass and rough mirror spheres of the materials
//! scene (`materials_<mode>.png`). With the wireframe mode, also a close-up of the dense
//! torus under each wireframe preset (`wireframe_<preset>.png`) and all of them side by side
//! (`wireframe_presets.png`). With `--mode all` (the default) also side-by-side strips: every mode
//! on the ground plane (`ground_modes.png`, in the order of `--help`), the isotropic and the
//! anisotropic ways to pick a level of detail (`ground_gradients.png`: mip0, cone, ray_diff,
//! bary_gradients), the reflection without and with curvature (`reflection_curvature.png`), the
//! materials scene with and without the refracted and the rough cones (`materials_modes.png`:
//! cone_curvature, cone_refraction, cone_roughness, ray_diff), and `tex_grad_scale` 0, 1 and 3
//! (`tex_grad_scale.png`). Every panel of a strip is captioned with
//! its mode and what it was rendered with (the preset, the scale), in DejaVu Sans.
//!
//! `cargo run --release -p ray-footprint-lab --example gallery -- [--width N] [--height N] [--mode NAME|all] [--out DIR]`

use ray_footprint::wireframe::WireframeSettings;
use ray_footprint_lab::cli::options_or_exit;
use ray_footprint_lab::figure::{self, Panel, RgbaImage};
use ray_footprint_lab::rt::{open_device, Camera, Error, Frame, Mode, Renderer, Scene};
use std::path::PathBuf;
use std::process::ExitCode;

/// `tex_grad_scale` of the `tex_grad_scale` mode's own images: visibly blurred (1 matches `cone`).
const BLUR_SCALE: f32 = 3.0;
/// Largest accepted width or height.
const MAX_SIZE: u32 = 8192;

/// What to render, from the command line.
struct Options {
    width: u32,
    height: u32,
    modes: Vec<Mode>,
    out: PathBuf,
}

fn usage() -> String {
    let names: Vec<_> = Mode::ALL
        .iter()
        .map(|m| format!("  {:<16}{}", m.name(), m.description()))
        .collect();
    format!(
        "usage: gallery [--width N] [--height N] [--mode NAME|all] [--out DIR]\n\
         defaults: --width 480 --height 270 --mode all --out gallery\nmodes:\n{}",
        names.join("\n")
    )
}

fn parse_args(mut args: impl Iterator<Item = String>) -> Result<Options, String> {
    let mut options = Options {
        width: 480,
        height: 270,
        modes: Mode::ALL.to_vec(),
        out: PathBuf::from("gallery"),
    };
    while let Some(flag) = args.next() {
        if flag == "--help" || flag == "-h" {
            return Err(String::new());
        }
        if !["--width", "--height", "--mode", "--out"].contains(&flag.as_str()) {
            return Err(format!("unknown argument '{flag}'"));
        }
        let value = args.next().ok_or_else(|| format!("{flag} needs a value"))?;
        match flag.as_str() {
            "--width" => options.width = size(&flag, &value)?,
            "--height" => options.height = size(&flag, &value)?,
            "--mode" if value == "all" => options.modes = Mode::ALL.to_vec(),
            "--mode" => {
                let mode = Mode::from_name(&value).ok_or_else(|| format!("unknown mode '{value}'"))?;
                options.modes = vec![mode];
            }
            "--out" if value.is_empty() => return Err("--out needs a folder name".into()),
            _ => options.out = PathBuf::from(value),
        }
    }
    Ok(options)
}

fn size(flag: &str, value: &str) -> Result<u32, String> {
    match value.parse::<u32>() {
        Ok(n) if (1..=MAX_SIZE).contains(&n) => Ok(n),
        _ => Err(format!(
            "{flag} must be an integer from 1 to {MAX_SIZE}, got '{value}'"
        )),
    }
}

fn main() -> ExitCode {
    let options = options_or_exit(parse_args(std::env::args().skip(1)), &usage());
    if let Err(e) = std::fs::create_dir_all(&options.out) {
        eprintln!(
            "error: cannot create the output folder {}: {e}",
            options.out.display()
        );
        return ExitCode::from(2);
    }
    match run(&options) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

/// Renders every image and strip, printing progress, the files and the time per frame.
fn run(options: &Options) -> Result<(), String> {
    let gpu = open_device().map_err(|e| e.to_string())?;
    let renderer = Renderer::new(&gpu, Scene::gallery()).map_err(|e| e.to_string())?;
    let materials = Renderer::new(&gpu, Scene::materials()).map_err(|e| e.to_string())?;
    let triangles: usize = renderer.scene().meshes.iter().map(|m| m.triangle_count()).sum();
    println!("device: {}", gpu.name());
    println!(
        "image size: {} x {}; scene: {triangles} triangles",
        options.width, options.height
    );
    match renderer.anisotropy() {
        Some(max) => println!("sampler: trilinear, anisotropic up to {max}x"),
        None => println!("sampler: trilinear (the device has no samplerAnisotropy)"),
    }
    let mut gallery = Gallery {
        renderer: &renderer,
        materials: &materials,
        options,
        written: Vec::new(),
        timings: Vec::new(),
    };
    gallery.warm_up().map_err(|e| e.to_string())?;
    let views = [
        ("ground", Camera::ground()),
        ("reflection", Camera::reflection()),
        ("materials", Camera::materials()),
    ];
    let mut frames = Vec::new();
    for (index, &mode) in options.modes.iter().enumerate() {
        for (view, camera) in &views {
            println!(
                "[{}/{}] {view} view, mode {mode} ...",
                index + 1,
                options.modes.len()
            );
            let frame = gallery
                .render(view, camera, mode, scale_of(mode), DEFAULT_PRESET)
                .map_err(|e| e.to_string())?;
            gallery.save(&format!("{view}_{mode}.png"), &frame)?;
            frames.push(((*view, mode), frame));
        }
    }
    if options.modes.contains(&Mode::Wireframe) {
        gallery.wireframes()?;
    }
    if options.modes.len() == Mode::ALL.len() {
        gallery.strips(&frames)?;
    }
    gallery.report();
    Ok(())
}

/// A wireframe preset and its display name ([`WireframeSettings::PRESETS`]).
type Preset = (&'static str, WireframeSettings);

/// The preset of every image but the wireframe close-ups.
const DEFAULT_PRESET: Preset = WireframeSettings::PRESETS[0];

/// The file-name form of a preset's name: "Wire dot" -> "wire_dot".
fn slug(name: &str) -> String {
    name.to_lowercase().replace(' ', "_")
}

/// The caption of a panel: the mode, and what it was rendered with where that matters (the
/// preset of the wireframe, the scale of `tex_grad_scale`).
fn caption(mode: Mode, tex_grad_scale: f32, (preset, _): Preset) -> String {
    match mode {
        Mode::Wireframe => format!("wireframe, preset {preset}"),
        Mode::TexGradScale => format!("tex_grad_scale {tex_grad_scale}"),
        _ => mode.name().to_string(),
    }
}

/// The `tex_grad_scale` a mode renders with.
fn scale_of(mode: Mode) -> f32 {
    if mode == Mode::TexGradScale {
        BLUR_SCALE
    } else {
        1.0
    }
}

struct Gallery<'a, 'g> {
    /// The gallery scene's renderer.
    renderer: &'a Renderer<'g>,
    /// The materials scene's renderer (the `materials` view).
    materials: &'a Renderer<'g>,
    options: &'a Options,
    written: Vec<PathBuf>,
    timings: Vec<(String, f64)>,
}

impl Gallery<'_, '_> {
    /// One untimed frame per renderer, so the first timing does not include the driver's shader
    /// compilation.
    fn warm_up(&self) -> Result<(), Error> {
        println!("warming up (first frame compiles the pipeline) ...");
        let camera = Camera::ground();
        let uniforms = camera.uniforms((16, 16), WireframeSettings::default());
        for renderer in [self.renderer, self.materials] {
            let push = renderer.push_constants(&camera, Mode::Cone, 1.0, 16, 16);
            renderer.render(&push, &uniforms)?;
        }
        Ok(())
    }

    /// Traces one frame of `camera` in `mode`, timed, in the materials scene for the `materials`
    /// view and in the gallery scene otherwise; the wireframe mode draws `preset`.
    fn render(
        &mut self,
        view: &str,
        camera: &Camera,
        mode: Mode,
        tex_grad_scale: f32,
        (preset, settings): Preset,
    ) -> Result<Frame, Error> {
        let (width, height) = (self.options.width, self.options.height);
        let renderer = if view == "materials" {
            self.materials
        } else {
            self.renderer
        };
        let push = renderer.push_constants(camera, mode, tex_grad_scale, width, height);
        let uniforms = camera.uniforms((width, height), settings);
        let frame = renderer.render(&push, &uniforms)?;
        let ms = frame.trace_time.as_secs_f64() * 1e3;
        println!("    {ms:.1} ms per frame");
        let setting = if mode == Mode::Wireframe {
            format!("preset {preset}")
        } else {
            format!("tex_grad_scale {tex_grad_scale}")
        };
        self.timings
            .push((format!("{view:<10} {mode:<15} {setting}"), ms));
        Ok(frame)
    }

    /// The torus close-up under every wireframe preset, one image each and a strip.
    fn wireframes(&mut self) -> Result<(), String> {
        let mut frames = Vec::new();
        for (index, &preset) in WireframeSettings::PRESETS.iter().enumerate() {
            println!(
                "[wireframe {}/{}] torus view, preset {} ...",
                index + 1,
                WireframeSettings::PRESETS.len(),
                preset.0
            );
            let frame = self
                .render("torus", &Camera::torus(), Mode::Wireframe, 1.0, preset)
                .map_err(|e| e.to_string())?;
            self.save(&format!("wireframe_{}.png", slug(preset.0)), &frame)?;
            frames.push((caption(Mode::Wireframe, 1.0, preset), frame));
        }
        let panels: Vec<_> = frames.iter().map(|(text, frame)| (text.clone(), frame)).collect();
        self.save_strip("wireframe_presets.png", &panels)
    }

    /// The strips: every mode on the ground, the reflection without and with curvature, the
    /// materials scene with and without the refracted and rough cones, and tex_grad_scale 0, 1
    /// and 3.
    fn strips(&mut self, frames: &[((&str, Mode), Frame)]) -> Result<(), String> {
        let find = |view: &str, mode: Mode| {
            frames
                .iter()
                .find(|((v, m), _)| *v == view && *m == mode)
                .map(|(_, frame)| frame)
                .expect("every mode was rendered in every view")
        };
        let panel =
            |view: &str, mode: Mode| (caption(mode, scale_of(mode), DEFAULT_PRESET), find(view, mode));
        let ground: Vec<_> = Mode::ALL.iter().map(|&mode| panel("ground", mode)).collect();
        self.save_strip("ground_modes.png", &ground)?;
        let gradients = [Mode::Mip0, Mode::Cone, Mode::RayDiff, Mode::BaryGradients];
        self.save_strip(
            "ground_gradients.png",
            &gradients.map(|mode| panel("ground", mode)),
        )?;
        let reflection = [
            panel("reflection", Mode::Cone),
            panel("reflection", Mode::ConeCurvature),
        ];
        self.save_strip("reflection_curvature.png", &reflection)?;
        let materials = [
            Mode::ConeCurvature,
            Mode::ConeRefraction,
            Mode::ConeSections,
            Mode::ConeRoughness,
            Mode::RayDiff,
        ];
        self.save_strip(
            "materials_modes.png",
            &materials.map(|mode| panel("materials", mode)),
        )?;
        println!("[strip] ground view, tex_grad_scale 0 and 1 ...");
        let mut scaled = Vec::new();
        for scale in [0.0, 1.0] {
            scaled.push(
                self.render(
                    "ground",
                    &Camera::ground(),
                    Mode::TexGradScale,
                    scale,
                    DEFAULT_PRESET,
                )
                .map_err(|e| e.to_string())?,
            );
        }
        let strip = [
            (caption(Mode::TexGradScale, 0.0, DEFAULT_PRESET), &scaled[0]),
            (caption(Mode::TexGradScale, 1.0, DEFAULT_PRESET), &scaled[1]),
            panel("ground", Mode::TexGradScale),
        ];
        self.save_strip("tex_grad_scale.png", &strip)
    }

    /// Writes `frame` as `name` in the output folder.
    fn save(&mut self, name: &str, frame: &Frame) -> Result<(), String> {
        self.write(name, &RgbaImage::from_frame(frame))
    }

    /// Writes `panels` side by side, each frame under its caption, as `name` in the output folder.
    fn save_strip(&mut self, name: &str, panels: &[(String, &Frame)]) -> Result<(), String> {
        let row = panels
            .iter()
            .map(|(text, frame)| Panel::new(text.clone(), RgbaImage::from_frame(frame)))
            .collect();
        let strip = figure::grid(&[row]).map_err(|e| e.to_string())?;
        self.write(name, &strip)
    }

    fn write(&mut self, name: &str, image: &RgbaImage) -> Result<(), String> {
        let path = self.options.out.join(name);
        figure::write_png(&path, image).map_err(|e| e.to_string())?;
        self.written.push(path);
        Ok(())
    }

    fn report(&self) {
        println!(
            "\ntime per frame ({} x {}, trace only):",
            self.options.width, self.options.height
        );
        for (what, ms) in &self.timings {
            println!("  {what:<45} {ms:>8.1} ms");
        }
        println!("\nfiles written ({}):", self.written.len());
        for path in &self.written {
            println!("  {}", path.display());
        }
    }
}
