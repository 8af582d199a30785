//! The quality lab at a tiny size: every metric of every scene and method is finite, the ground
//! truth scores itself perfectly, the cache gives back what was rendered, every texture-filtering
//! mode has a row, and the folder is written. The numbers themselves are not asserted: they are
//! what the lab measures.

use ray_footprint_lab::quality::metrics::{self, FlipMap};
use ray_footprint_lab::quality::truth::{self, TruthSettings};
use ray_footprint_lab::quality::{self, report, LabScene, LabSettings, Measure, Quiet, SceneResult};
use ray_footprint_lab::rt::Mode;
use std::path::PathBuf;

/// Large enough for the 11 x 11 SSIM window and for every scene's mask to hold pixels.
const SIZE: (u32, u32) = (48, 32);
/// 2 x 2 samples per pixel over 2 drift frames: 6 ground-truth frames per scene.
const SETTINGS: TruthSettings = TruthSettings {
    samples_per_axis: 2,
    frames: 2,
};

/// A fresh folder under the system's temporary directory.
fn scratch_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ray-footprint-quality-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

#[test]
fn lab_metrics_are_finite_and_the_truth_scores_itself_perfectly() {
    let gpu = super::rt::gpu();
    let out = scratch_dir("lab");
    let settings = LabSettings {
        size: SIZE,
        truth: SETTINGS,
        cache_dir: out.join("truth"),
        rebuild: true,
    };
    let scenes = LabScene::all();
    let run = quality::run(&gpu, &scenes, &settings, &mut Quiet).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(run.scenes.len(), scenes.len());
    for scene in &run.scenes {
        check_rows(scene);
        check_truth_scores_itself(scene);
        check_cache(&gpu, scene, &settings);
    }
    let goals = report::goals(&run);
    let written = report::write(&run, &goals, &[], &out).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        written.iter().all(|path| path.is_file()),
        "every file listed was written"
    );
    println!(
        "{}\n{}{} files in {}",
        report::setup_markdown(&run),
        report::table_markdown(&run),
        written.len(),
        out.display()
    );
    let _ = std::fs::remove_dir_all(&out);
}

/// One row per method, every texture-filtering mode of `Mode::ALL` among them on the texture
/// scenes, every metric finite, a mask with pixels in it, and on the texture scenes footprints
/// compared over some of them (the differential's s1/s2 at least 1, every distance finite).
fn check_rows(scene: &SceneResult) {
    let name = scene.scene.name;
    assert!(scene.mask.iter().any(|&m| m), "{name}: the mask holds pixels");
    if scene.scene.measure == Measure::Texture {
        let rows: Vec<Mode> = scene.methods.iter().map(|m| m.method.mode).collect();
        for mode in Mode::ALL {
            let expected = quality::not_a_texture_method(mode).is_none();
            assert_eq!(
                rows.contains(&mode),
                expected,
                "{name}: a row for {mode} is {expected}"
            );
        }
        assert_eq!(rows[0], Mode::Mip0, "{name}: the baseline comes first");
        let f = scene
            .footprints
            .unwrap_or_else(|| panic!("{name}: footprints measured"));
        let distances = [
            f.anisotropy,
            f.cone_major,
            f.cone_minor,
            f.anisotropic_major,
            f.anisotropic_minor,
        ];
        assert!(
            f.pixels > 0 && f.anisotropy >= 1.0 && distances.iter().all(|v| v.is_finite() && *v >= 0.0),
            "{name}: footprints {f:?}"
        );
    }
    for m in &scene.methods {
        let values = [
            m.psnr,
            m.psnr_mask,
            m.ssim,
            m.flip,
            m.detail,
            m.change,
            m.shimmer,
            m.ms_per_frame,
        ];
        assert!(
            values.iter().all(|v| v.is_finite()),
            "{name} {}: every metric is finite: {values:?}",
            m.method.name
        );
    }
}

/// The ground truth against itself: PSNR infinite (zero error), SSIM 1, FLIP 0 everywhere, all
/// of its detail kept, no change between identical frames.
fn check_truth_scores_itself(scene: &SceneResult) {
    let (name, truth) = (scene.scene.name, &scene.truth);
    let score = |result: Result<f64, metrics::MetricError>| result.unwrap_or_else(|e| panic!("{name}: {e}"));
    assert_eq!(
        score(metrics::psnr(truth, truth, None)),
        f64::INFINITY,
        "{name}: PSNR"
    );
    assert_eq!(
        score(metrics::psnr(truth, truth, Some(&scene.mask))),
        f64::INFINITY,
        "{name}: mask PSNR"
    );
    // The five local statistics are the same sums for both images, so each window's ratio has
    // equal numerator and denominator up to their last rounding.
    let ssim = score(metrics::ssim(truth, truth));
    assert!((ssim - 1.0).abs() < 1e-12, "{name}: SSIM {ssim}");
    assert_eq!(
        score(metrics::detail_kept(truth, truth)),
        1.0,
        "{name}: detail kept"
    );
    let flip: FlipMap = metrics::flip(truth, truth).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(
        flip.values.iter().all(|&v| v == 0.0),
        "{name}: FLIP is 0 at every pixel"
    );
    let still = [truth.clone(), truth.clone()];
    assert_eq!(score(metrics::mean_change(&still)), 0.0, "{name}: change");
}

/// The cache holds the ground truth that was rendered, bit for bit: its still frame is the one
/// scored, and rendering it again gives the same frames (the renderer is deterministic).
fn check_cache(gpu: &shader_proptest::Gpu, scene: &SceneResult, settings: &LabSettings) {
    let lab = &scene.scene;
    let key = truth::truth_key(lab, SIZE, SETTINGS, gpu.name()).unwrap_or_else(|e| panic!("{e}"));
    let path = truth::cache_path(&settings.cache_dir, lab, SIZE, SETTINGS, key);
    let cached = truth::load(&path, SIZE, SETTINGS.frames)
        .unwrap_or_else(|| panic!("{}: no ground truth at {}", lab.name, path.display()));
    assert_eq!(cached.frames.len(), SETTINGS.frames as usize);
    assert_eq!(
        cached.frames[0], scene.truth,
        "{}: the cached still frame is the one scored",
        lab.name
    );
    let renderer = ray_footprint_lab::rt::Renderer::with_texture(gpu, lab.scene.clone(), lab.texture.clone())
        .unwrap_or_else(|e| panic!("{e}"));
    let again =
        truth::render_truth(&renderer, lab, SIZE, SETTINGS, &mut || {}).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        again, cached,
        "{}: rendering again gives the cached frames",
        lab.name
    );
}
