//! What a run publishes: the goals, the table as Markdown, CSV and JSON, and the images (every
//! frame, the FLIP error maps, captioned crops side by side) and plots in an output folder.

use super::footprint::Footprints;
use super::lab::{Convergence, LabRun, MethodResult, SceneResult};
use super::{plots, LabError};
use crate::figure::{self, Panel, RgbaImage};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// PSNR margin over mip 0 that ray differentials must reach on the paraboloid's reflector (RTG
/// ch. 20 measured 31.0 - 25.0 = 6 dB), dB.
pub const RAY_DIFF_MARGIN_DB: f64 = 6.0;
/// PSNR margin over mip 0 that the cone with curvature must reach on the reflector, dB.
pub const CURVATURE_MARGIN_DB: f64 = 3.0;
/// What the footprint table shows, above it.
pub const FOOTPRINTS_CAPTION: &str = "Mean distance in mip levels, |log2(cone / s)|, between each cone's \
    footprint and the axes s1 >= s2 of the ray differential's at the primary hits in the mask (the \
    per-pixel records, whatever the sampler does).\n\n";
/// Panels per row in the side-by-side crops.
const PANELS_PER_ROW: usize = 4;
/// Magnification of the crops (nearest neighbour).
const CROP_ZOOM: u32 = 2;

/// One goal, what was measured and whether it was met.
#[derive(Clone, Debug, PartialEq)]
pub struct Goal {
    /// The scene it is about.
    pub scene: String,
    /// What must hold.
    pub statement: String,
    /// What was measured.
    pub measured: String,
    /// Whether it holds.
    pub met: bool,
}

/// Per scene, the method that stands for what a mode adds and the method without it, whose
/// masked PSNR it must beat: the refracted cone on the glass sphere and the roughness spread on
/// the rough mirror, both against the cone with curvature (which carries the cone through glass
/// as if it were not there, and reflects it off the rough mirror as off a smooth one); the two
/// sections on the glass sphere against the refracted cone alone; the anisotropic cone at the
/// plane's grazing angles and in the wide view's corners, against the isotropic cone.
pub const IMPROVEMENTS: [(&str, &str, &str); 5] = [
    ("glass", "cone_refraction", "cone_curvature"),
    ("glass", "cone_sections", "cone_refraction"),
    ("rough", "cone_roughness", "cone_curvature"),
    ("plane", "cone_anisotropic", "cone"),
    ("corners", "cone_anisotropic", "cone"),
];

/// The scenes at grazing angles, where the anisotropic cone's footprint must be nearer the ray
/// differential's than the isotropic cone's along the minor axis (the [`Footprints`] of the
/// records, whatever the device's filtering).
pub const GRAZING_SCENES: [&str; 2] = ["plane", "corners"];

/// On the glass sphere, the share of the refracted cone's PSNR gap to the ray differential that
/// the two sections must close: `ray_diff_isotropic - cone_sections <= (1 - GAP_CLOSED)
/// (ray_diff_isotropic - cone_refraction)`. The target is the differential filtered isotropically,
/// as the cones are (`textureLod`), so that only the footprint's size differs; on a device without
/// anisotropic filtering (lavapipe) it renders as `ray_diff`.
pub const GAP_CLOSED: f64 = 0.5;

/// The scene, the method, the method without what it adds and the target of the gap goal
/// ([`GAP_CLOSED`]).
pub const GAP: (&str, &str, &str, &str) = ("glass", "cone_sections", "cone_refraction", "ray_diff_isotropic");

/// The scenes of the saddle reflector: its two triangulations.
pub const PARABOLOID_SCENES: [&str; 2] = ["paraboloid", "paraboloid_alternating"];

/// The goals: on the paraboloid (either triangulation), ray differentials (isotropic and anisotropic) at least
/// [`RAY_DIFF_MARGIN_DB`] and the cone with curvature at least [`CURVATURE_MARGIN_DB`] above mip 0
/// in PSNR over the reflector; every [`IMPROVEMENTS`] pair, the mode above the method without
/// what it adds in PSNR over the mask; on the glass sphere, the two sections closing
/// [`GAP_CLOSED`] of the refracted cone's gap to the isotropic ray differential ([`GAP`]); on the
/// [`GRAZING_SCENES`], the anisotropic cone's minor axis nearer the ray differential's than the
/// isotropic cone; on every scene, every method beats the baseline in mean FLIP and in shimmer.
pub fn goals(run: &LabRun) -> Vec<Goal> {
    let mut goals = Vec::new();
    for scene in &run.scenes {
        let improvements = IMPROVEMENTS.iter().filter(|(name, ..)| *name == scene.scene.name);
        goals.extend(
            improvements.filter_map(|&(_, method, reference)| improvement_goal(scene, method, reference)),
        );
        if scene.scene.name == GAP.0 {
            goals.extend(gap_goal(scene, GAP.1, GAP.2, GAP.3));
        }
        if GRAZING_SCENES.contains(&scene.scene.name) {
            goals.extend(scene.footprints.map(|f| footprint_goal(scene.scene.name, f)));
        }
        if PARABOLOID_SCENES.contains(&scene.scene.name) {
            let margins = [
                ("ray_diff", RAY_DIFF_MARGIN_DB),
                ("ray_diff_isotropic", RAY_DIFF_MARGIN_DB),
                ("cone_curvature", CURVATURE_MARGIN_DB),
            ];
            goals.extend(
                margins
                    .into_iter()
                    .filter_map(|(name, margin)| margin_goal(scene, name, margin)),
            );
        }
        goals.extend(beats_baseline(scene));
    }
    goals
}

/// `name`'s masked PSNR at least `margin` dB above the baseline's, if the scene has `name`.
fn margin_goal(scene: &SceneResult, name: &str, margin: f64) -> Option<Goal> {
    let method = scene.method(name)?;
    let baseline = scene.baseline();
    let gain = method.psnr_mask - baseline.psnr_mask;
    Some(Goal {
        scene: scene.scene.name.to_string(),
        statement: format!(
            "{name} PSNR over the mask >= {} + {margin} dB",
            baseline.method.name
        ),
        measured: format!(
            "{:+.2} dB ({:.2} vs {:.2} dB)",
            gain, method.psnr_mask, baseline.psnr_mask
        ),
        met: gain >= margin,
    })
}

/// `name`'s masked PSNR above `reference`'s, if the scene has both.
fn improvement_goal(scene: &SceneResult, name: &str, reference: &str) -> Option<Goal> {
    let method = scene.method(name)?;
    let other = scene.method(reference)?;
    let gain = method.psnr_mask - other.psnr_mask;
    Some(Goal {
        scene: scene.scene.name.to_string(),
        statement: format!("{name} PSNR over the mask > {reference}"),
        measured: format!(
            "{:+.2} dB ({:.2} vs {:.2} dB)",
            gain, method.psnr_mask, other.psnr_mask
        ),
        met: gain > 0.0,
    })
}

/// `name` closing [`GAP_CLOSED`] of `reference`'s masked PSNR gap to `target`, if the scene has all
/// three.
fn gap_goal(scene: &SceneResult, name: &str, reference: &str, target: &str) -> Option<Goal> {
    let (method, other) = (scene.method(name)?, scene.method(reference)?);
    let goal = scene.method(target)?.psnr_mask;
    let (gap, reference_gap) = (goal - method.psnr_mask, goal - other.psnr_mask);
    Some(Goal {
        scene: scene.scene.name.to_string(),
        statement: format!(
            "{name}'s PSNR gap to {target} over the mask <= {:.0}% of {reference}'s",
            100.0 * (1.0 - GAP_CLOSED)
        ),
        measured: format!(
            "{gap:.2} vs {reference_gap:.2} dB ({:.2}, {:.2}, {goal:.2} dB)",
            method.psnr_mask, other.psnr_mask
        ),
        met: gap <= (1.0 - GAP_CLOSED) * reference_gap,
    })
}

/// The anisotropic cone's minor axis nearer the ray differential's than the isotropic cone.
fn footprint_goal(scene: &str, footprints: Footprints) -> Goal {
    Goal {
        scene: scene.to_string(),
        statement: String::from(
            "cone_anisotropic's minor axis nearer the ray differential's than cone's (mip levels)",
        ),
        measured: format!(
            "{:.3} vs {:.3} levels",
            footprints.anisotropic_minor, footprints.cone_minor
        ),
        met: footprints.anisotropic_minor < footprints.cone_minor,
    }
}

/// The cones' footprints against the ray differential's per texture scene, in Markdown.
pub fn footprints_markdown(run: &LabRun) -> String {
    let mut table = String::from(
        "| scene | pixels | differential s1/s2 (median) | cone vs s1 | cone vs s2 | anisotropic cone vs s1 | \
         anisotropic cone vs s2 |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n",
    );
    for scene in &run.scenes {
        if let Some(f) = scene.footprints {
            let _ = writeln!(
                table,
                "| {} | {} | {:.2} | {:.3} | {:.3} | {:.3} | {:.3} |",
                scene.scene.name,
                f.pixels,
                f.anisotropy,
                f.cone_major,
                f.cone_minor,
                f.anisotropic_major,
                f.anisotropic_minor
            );
        }
    }
    table
}

/// Every method but the baseline: lower mean FLIP and lower shimmer than the baseline.
fn beats_baseline(scene: &SceneResult) -> Vec<Goal> {
    let baseline = scene.baseline();
    let mut goals = Vec::new();
    for method in &scene.methods[1..] {
        let name = &method.method.name;
        goals.push(Goal {
            scene: scene.scene.name.to_string(),
            statement: format!("{name} FLIP < {}", baseline.method.name),
            measured: format!("{:.4} vs {:.4}", method.flip, baseline.flip),
            met: method.flip < baseline.flip,
        });
        goals.push(Goal {
            scene: scene.scene.name.to_string(),
            statement: format!("{name} shimmer < {}", baseline.method.name),
            measured: format!("{:.3} vs {:.3} levels", method.shimmer, baseline.shimmer),
            met: method.shimmer < baseline.shimmer,
        });
    }
    goals
}

/// The goals as Markdown list items: met or MISSED, the goal and the measurement.
pub fn goals_markdown(goals: &[Goal]) -> String {
    goals
        .iter()
        .map(|g| {
            let verdict = if g.met { "met" } else { "**MISSED**" };
            format!("- {verdict}: {}: {} ({})\n", g.scene, g.statement, g.measured)
        })
        .collect()
}

/// The table in Markdown: one row per scene and method.
pub fn table_markdown(run: &LabRun) -> String {
    let rows = method_rows(run, |scene, m| {
        format!(
            "| {scene} | {} | {:.2} | {:.2} | {:.4} | {:.4} | {:.3} | {:.1}% | {:.1} |\n",
            m.method.name,
            m.psnr,
            m.psnr_mask,
            m.ssim,
            m.flip,
            m.shimmer,
            100.0 * m.detail,
            m.ms_per_frame
        )
    });
    String::from(
        "| scene | method | PSNR dB | PSNR mask dB | SSIM | FLIP | shimmer | detail kept | ms/frame |\n\
         | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n",
    ) + &rows.concat()
}

/// One row per scene and method of `run`, scene by scene: `row` of the scene's name and the
/// method's result.
fn method_rows(run: &LabRun, row: impl Fn(&str, &MethodResult) -> String) -> Vec<String> {
    run.scenes
        .iter()
        .flat_map(|scene| scene.methods.iter().map(|m| row(scene.scene.name, m)))
        .collect()
}

/// How the run was made, in Markdown: device, size, N, K, and per scene its mask, the share
/// of pixels in it, the truth's own change from frame to frame and where the truth came from.
pub fn setup_markdown(run: &LabRun) -> String {
    let s = &run.settings;
    let n = s.truth.samples_per_axis;
    let mut text = format!(
        "Device: {}. Images {} x {}; ground truth: mip 0 (the wireframe: hard lines) with {n} x {n} \
         stratified samples per pixel, box filter in linear light; {} frames of drift, 1/{n} pixel \
         to the right per frame.\n\n",
        run.device, s.size.0, s.size.1, s.truth.frames
    );
    for scene in &run.scenes {
        let share = scene.mask.iter().filter(|&&m| m).count() as f64 / scene.mask.len().max(1) as f64;
        let source = if scene.truth_cached {
            String::from("from the cache")
        } else {
            format!("rendered in {:.1} s", scene.truth_time.as_secs_f64())
        };
        let _ = writeln!(
            text,
            "- {}: {}; mask: {} ({:.1}% of the pixels); ground truth {source}, its own change \
             from frame to frame {:.3} levels.",
            scene.scene.name,
            scene.scene.description,
            scene.scene.mask.describe(&scene.scene.scene),
            100.0 * share,
            scene.truth_change
        );
    }
    text
}

/// The table as CSV, one row per scene and method, a header first.
pub fn table_csv(run: &LabRun) -> String {
    let rows = method_rows(run, |scene, m| {
        format!(
            "{scene},{},{:.4},{:.4},{:.6},{:.6},{:.4},{:.4},{:.6},{:.3}\n",
            m.method.name, m.psnr, m.psnr_mask, m.ssim, m.flip, m.change, m.shimmer, m.detail, m.ms_per_frame
        )
    });
    String::from("scene,method,psnr_db,psnr_mask_db,ssim,flip,change,shimmer,detail_kept,ms_per_frame\n")
        + &rows.concat()
}

/// A JSON string literal of `text`.
fn json_string(text: &str) -> String {
    let mut out = String::from("\"");
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A JSON number, or `null` for a value JSON cannot hold (infinite PSNR).
fn json_number(value: f64) -> String {
    if value.is_finite() {
        format!("{value}")
    } else {
        String::from("null")
    }
}

/// The run as JSON: the setup, every row, the footprints, the goals, and the convergence rows if
/// given.
pub fn json(run: &LabRun, goals: &[Goal], convergence: &[Convergence]) -> String {
    let s = &run.settings;
    let rows = method_rows(run, |scene, m| {
        let fields = [
            ("psnr_db", m.psnr),
            ("psnr_mask_db", m.psnr_mask),
            ("ssim", m.ssim),
            ("flip", m.flip),
            ("change", m.change),
            ("shimmer", m.shimmer),
            ("detail_kept", m.detail),
            ("ms_per_frame", m.ms_per_frame),
        ];
        let numbers: Vec<String> = fields
            .iter()
            .map(|(name, value)| format!("\"{name}\": {}", json_number(*value)))
            .collect();
        format!(
            "    {{\"scene\": {}, \"method\": {}, {}}}",
            json_string(scene),
            json_string(&m.method.name),
            numbers.join(", ")
        )
    });
    let goals: Vec<String> = goals
        .iter()
        .map(|g| {
            format!(
                "    {{\"scene\": {}, \"goal\": {}, \"measured\": {}, \"met\": {}}}",
                json_string(&g.scene),
                json_string(&g.statement),
                json_string(&g.measured),
                g.met
            )
        })
        .collect();
    let footprints: Vec<String> = run
        .scenes
        .iter()
        .filter_map(|scene| scene.footprints.map(|f| (scene.scene.name, f)))
        .map(|(name, f)| {
            format!(
                "    {{\"scene\": {}, \"pixels\": {}, \"differential_anisotropy\": {}, \"cone_major_levels\": {}, \"cone_minor_levels\": {}, \"anisotropic_major_levels\": {}, \"anisotropic_minor_levels\": {}}}",
                json_string(name),
                f.pixels,
                json_number(f.anisotropy),
                json_number(f.cone_major),
                json_number(f.cone_minor),
                json_number(f.anisotropic_major),
                json_number(f.anisotropic_minor)
            )
        })
        .collect();
    let convergence: Vec<String> = convergence
        .iter()
        .map(|c| {
            format!(
                "    {{\"scene\": {}, \"method\": {}, \"psnr_n_db\": {}, \"psnr_2n_db\": {}, \"psnr_mask_n_db\": {}, \"psnr_mask_2n_db\": {}}}",
                json_string(c.scene),
                json_string(&c.method),
                json_number(c.psnr_n.0),
                json_number(c.psnr_2n.0),
                json_number(c.psnr_n.1),
                json_number(c.psnr_2n.1)
            )
        })
        .collect();
    format!(
        "{{\n  \"device\": {},\n  \"width\": {},\n  \"height\": {},\n  \"samples_per_axis\": {},\n  \"frames\": {},\n  \
         \"rows\": [\n{}\n  ],\n  \"footprints\": [\n{}\n  ],\n  \"goals\": [\n{}\n  ],\n  \"convergence\": [\n{}\n  ]\n}}\n",
        json_string(&run.device),
        s.size.0,
        s.size.1,
        s.truth.samples_per_axis,
        s.truth.frames,
        rows.join(",\n"),
        footprints.join(",\n"),
        goals.join(",\n"),
        convergence.join(",\n")
    )
}

/// The convergence rows in Markdown: PSNR against N and 2N samples per axis and the change.
pub fn convergence_markdown(rows: &[Convergence], n: u32) -> String {
    let mut table = format!(
        "| scene | method | PSNR vs {n}x{n} | PSNR vs {m}x{m} | change | mask vs {n}x{n} | mask vs {m}x{m} | change |\n\
         | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n",
        m = 2 * n
    );
    for c in rows {
        let _ = writeln!(
            table,
            "| {} | {} | {:.2} | {:.2} | {:+.3} | {:.2} | {:.2} | {:+.3} |",
            c.scene,
            c.method,
            c.psnr_n.0,
            c.psnr_2n.0,
            c.psnr_2n.0 - c.psnr_n.0,
            c.psnr_n.1,
            c.psnr_2n.1,
            c.psnr_2n.1 - c.psnr_n.1
        );
    }
    table
}

/// The largest change of PSNR (whole image or mask) from N to 2N over all rows, dB.
pub fn largest_convergence_change(rows: &[Convergence]) -> f64 {
    rows.iter()
        .flat_map(|c| [(c.psnr_2n.0 - c.psnr_n.0).abs(), (c.psnr_2n.1 - c.psnr_n.1).abs()])
        .fold(0.0, f64::max)
}

/// Writes `text` to `path`.
fn write_text(path: &Path, text: &str) -> Result<(), LabError> {
    std::fs::write(path, text).map_err(|e| LabError::Io(format!("writing {}: {e}", path.display())))
}

fn create_dir(path: &Path) -> Result<(), LabError> {
    std::fs::create_dir_all(path).map_err(|e| LabError::Io(format!("creating {}: {e}", path.display())))
}

/// The part of `image` the scene's crop covers, magnified.
fn crop(image: &RgbaImage, fraction: [f32; 4]) -> RgbaImage {
    image.crop_part(fraction, CROP_ZOOM)
}

/// `panels` in rows of [`PANELS_PER_ROW`].
fn rows_of(panels: Vec<Panel>) -> Vec<Vec<Panel>> {
    panels.chunks(PANELS_PER_ROW).map(<[Panel]>::to_vec).collect()
}

/// A method's caption: its name and, for the wireframe scene, the preset drawn.
fn caption(scene: &SceneResult, name: &str) -> String {
    match scene.scene.measure {
        super::Measure::Texture => name.to_string(),
        super::Measure::Wireframe { preset, .. } => format!("{name}, {preset}"),
    }
}

/// Writes one scene's images: every still frame and the truth (`images/`), every FLIP map
/// (`flip/`), and the captioned crops side by side (`crops/<scene>.png`, `crops/<scene>_flip.png`).
fn write_scene_images(
    scene: &SceneResult,
    n: u32,
    out: &Path,
    written: &mut Vec<PathBuf>,
) -> Result<(), LabError> {
    let name = scene.scene.name;
    let mut save = |path: PathBuf, image: &RgbaImage| -> Result<(), LabError> {
        figure::write_png(&path, image)?;
        written.push(path);
        Ok(())
    };
    let truth = scene.truth.to_rgba();
    save(out.join(format!("images/{name}_truth.png")), &truth)?;
    let mut crops = vec![Panel::new(
        caption(scene, &format!("ground truth {n}x{n}")),
        crop(&truth, scene.scene.crop),
    )];
    let mut flips = Vec::new();
    for m in &scene.methods {
        let method = &m.method.name;
        let frame = m.frame.to_rgba();
        let flip = m.flip_map.to_rgba();
        save(out.join(format!("images/{name}_{method}.png")), &frame)?;
        save(out.join(format!("flip/{name}_{method}.png")), &flip)?;
        let label = caption(scene, method);
        crops.push(Panel::new(
            format!("{label}: {:.2} dB", m.psnr_mask),
            crop(&frame, scene.scene.crop),
        ));
        flips.push(Panel::new(
            format!("{label}: FLIP {:.3}", m.flip),
            crop(&flip, scene.scene.crop),
        ));
    }
    save(
        out.join(format!("crops/{name}.png")),
        &figure::grid(&rows_of(crops))?,
    )?;
    save(
        out.join(format!("crops/{name}_flip.png")),
        &figure::grid(&rows_of(flips))?,
    )
}

/// Writes everything a run publishes into `out`: `table.md` (setup, table, goals, and the
/// convergence table if given), `table.csv`, `table.json`, the images of every scene, and the
/// plots. Returns the files written.
pub fn write(
    run: &LabRun,
    goals: &[Goal],
    convergence: &[Convergence],
    out: &Path,
) -> Result<Vec<PathBuf>, LabError> {
    for dir in ["images", "flip", "crops"] {
        create_dir(&out.join(dir))?;
    }
    let n = run.settings.truth.samples_per_axis;
    let mut markdown = format!(
        "# Quality lab\n\n{}\n{}\n## Footprints against the ray differential\n\n{}{}\n## Goals\n\n{}",
        setup_markdown(run),
        table_markdown(run),
        FOOTPRINTS_CAPTION,
        footprints_markdown(run),
        goals_markdown(goals)
    );
    if !convergence.is_empty() {
        let _ = write!(
            markdown,
            "\n## Convergence of the ground truth\n\n{}\nLargest change: {:.3} dB.\n",
            convergence_markdown(convergence, n),
            largest_convergence_change(convergence)
        );
    }
    let mut written = Vec::new();
    let texts = [
        ("table.md", markdown),
        ("table.csv", table_csv(run)),
        ("table.json", json(run, goals, convergence)),
    ];
    for (file, text) in texts {
        write_text(&out.join(file), &text)?;
        written.push(out.join(file));
    }
    for scene in &run.scenes {
        write_scene_images(scene, n, out, &mut written)?;
    }
    written.extend(plots::write_all(run, out)?);
    Ok(written)
}
