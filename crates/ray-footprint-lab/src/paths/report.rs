//! The measurement and its tables: per scene, bounce and method, the mean and 95th percentile of
//! `|log2(|method width| / true width)|` in mip levels over the vertices that have a true
//! footprint, and a summary over all scenes by what the path sampled at the vertex before; and the
//! sweep of one global level-of-detail bias added to the cone without a scattering term past the
//! first hit, whose best value the summary carries as a rule of its own.

use super::methods::{method_widths, Method, METHODS};
use super::sampling::{pixel_position, vertex_numbers, Lobe, NUMBERS_PER_VERTEX};
use super::scene::Scene;
use super::tracer::MAX_VERTICES;
use super::truth::true_widths;
use std::fmt::Write;

/// What a run measures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// The seed of every random number.
    pub seed: u64,
    /// Image size in pixels, `(width, height)`.
    pub size: (u32, u32),
    /// Paths per scene, each through a random image position.
    pub paths: usize,
    /// The central differences' step in pixels.
    pub step: f64,
    /// Threads to trace on.
    pub threads: usize,
}

/// One vertex with a true footprint: its bounce, what was sampled before it, the true width and
/// each method's width.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexRecord {
    /// 1 for the primary hit, up to [`MAX_VERTICES`].
    pub bounce: usize,
    /// The lobe sampled at the vertex before (`None` at bounce 1).
    pub previous_lobe: Option<Lobe>,
    /// The true width (world units).
    pub true_width: f64,
    /// Each method's signed width, in [`METHODS`] order.
    pub widths: [f32; METHODS.len()],
}

impl VertexRecord {
    /// `log2(|width| / true width)` of method `method` (an index into [`METHODS`]); a zero width
    /// counts as 1e-30.
    pub fn log2_ratio(&self, method: usize) -> f64 {
        (f64::from(self.widths[method].abs()).max(1e-30) / self.true_width).log2()
    }
}

/// One scene's vertices.
#[derive(Clone, Debug, PartialEq)]
pub struct Measurement {
    /// The scene's name.
    pub scene: &'static str,
    /// Its description.
    pub description: &'static str,
    /// Every vertex with a true footprint.
    pub records: Vec<VertexRecord>,
    /// Per bounce, the vertices left out because a neighbouring path changed surfaces or lobes.
    pub dropped: [usize; MAX_VERTICES],
}

/// What one path gives: its vertices with a true footprint, and per bounce whether one was left
/// out.
type PathRecords = (Vec<VertexRecord>, [usize; MAX_VERTICES]);

/// Path `index` of the run: its image position and numbers from the seed, its true widths and
/// every method's widths.
fn measure_path(scene: &Scene, settings: &Settings, index: u64) -> PathRecords {
    let camera = scene.camera(settings.size);
    let pixel = pixel_position(settings.seed, index, camera.width, camera.height);
    let numbers: [[f64; NUMBERS_PER_VERTEX]; MAX_VERTICES] =
        std::array::from_fn(|k| vertex_numbers(settings.seed, index, k as u32 + 1));
    let truth = true_widths(scene, &camera, pixel, &numbers, settings.step);
    let widths: Vec<Vec<f32>> = METHODS
        .iter()
        .map(|&m| method_widths(m, &truth.path, &camera))
        .collect();
    let mut records = Vec::new();
    let mut dropped = [0; MAX_VERTICES];
    for (k, footprint) in truth.footprints.iter().enumerate() {
        let Some(footprint) = footprint else {
            dropped[k] += 1;
            continue;
        };
        records.push(VertexRecord {
            bounce: k + 1,
            previous_lobe: k
                .checked_sub(1)
                .and_then(|i| truth.path.vertices[i].scatter.map(|s| s.lobe)),
            true_width: footprint.width(),
            widths: std::array::from_fn(|m| widths[m][k]),
        });
    }
    (records, dropped)
}

/// Measures `settings.paths` paths of `scene` on `settings.threads` threads.
pub fn measure(scene: &Scene, settings: &Settings) -> Measurement {
    let threads = settings.threads.max(1);
    let chunk = settings.paths.div_ceil(threads).max(1);
    let parts: Vec<PathRecords> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..settings.paths)
            .step_by(chunk)
            .map(|start| {
                let end = (start + chunk).min(settings.paths);
                scope.spawn(move || measure_range(scene, settings, start..end))
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("a measuring thread panicked"))
            .collect()
    });
    let mut measurement = Measurement {
        scene: scene.name,
        description: scene.description,
        records: Vec::new(),
        dropped: [0; MAX_VERTICES],
    };
    for (records, dropped) in parts {
        measurement.records.extend(records);
        for (total, part) in measurement.dropped.iter_mut().zip(dropped) {
            *total += part;
        }
    }
    measurement
}

/// The paths `range` of a run.
fn measure_range(scene: &Scene, settings: &Settings, range: std::ops::Range<usize>) -> PathRecords {
    let mut all = (Vec::new(), [0; MAX_VERTICES]);
    for index in range {
        let (records, dropped) = measure_path(scene, settings, index as u64);
        all.0.extend(records);
        for (total, part) in all.1.iter_mut().zip(dropped) {
            *total += part;
        }
    }
    all
}

/// The mean and the 95th percentile (nearest rank: the `ceil(0.95 n)`-th smallest) of `values`,
/// or `None` for none.
pub fn mean_and_p95(values: &mut [f64]) -> Option<(f64, f64)> {
    if values.is_empty() {
        return None;
    }
    values.sort_by(f64::total_cmp);
    let mean = values.iter().sum::<f64>() / values.len() as f64;
    let rank = (0.95 * values.len() as f64).ceil() as usize;
    Some((mean, values[rank.max(1) - 1]))
}

/// `mean / p95` of `|ratio|` over `records`, or a dash for none.
fn error_cell<'a>(
    records: impl Iterator<Item = &'a VertexRecord>,
    ratio: impl Fn(&VertexRecord) -> f64,
) -> String {
    let mut errors: Vec<f64> = records.map(|r| ratio(r).abs()).collect();
    match mean_and_p95(&mut errors) {
        Some((mean, p95)) => format!("{mean:.3} / {p95:.3}"),
        None => String::from("-"),
    }
}

/// The mean of the signed `ratio` over `records` (positive: too wide), or a dash.
fn signed_cell<'a>(
    records: impl Iterator<Item = &'a VertexRecord>,
    ratio: impl Fn(&VertexRecord) -> f64,
) -> String {
    let signed: Vec<f64> = records.map(ratio).collect();
    if signed.is_empty() {
        return String::from("-");
    }
    format!("{:+.3}", signed.iter().sum::<f64>() / signed.len() as f64)
}

/// The index of [`Method::NoScatteringTerm`] in [`METHODS`], the rule the global bias is added to.
fn unbiased_index() -> usize {
    METHODS
        .iter()
        .position(|&m| m == Method::NoScatteringTerm)
        .expect("METHODS holds the cone without a scattering term")
}

/// `log2(|width| / true width)` of the cone without a scattering term with `bias` mip levels added
/// past the first hit (a width `2^bias` times as wide at bounces 2 and later).
pub fn biased_log2_ratio(record: &VertexRecord, bias: f64) -> f64 {
    let added = if record.bounce >= 2 { bias } else { 0.0 };
    record.log2_ratio(unbiased_index()) + added
}

/// The global biases the sweep tries, in mip levels: -1 to 6 in steps of 1/4.
pub fn bias_sweep() -> impl Iterator<Item = f64> + Clone {
    (-4..=24).map(|quarter| f64::from(quarter) / 4.0)
}

/// The mean `|log2|` over every vertex at bounces 2 to 4 of the cone without a scattering term
/// with `bias` added.
fn mean_biased_error(measurements: &[Measurement], bias: f64) -> f64 {
    let records = measurements.iter().flat_map(|m| m.records.iter());
    mean(
        records
            .filter(|r| r.bounce >= 2)
            .map(|r| biased_log2_ratio(r, bias).abs()),
    )
}

/// The mean of `values`, NaN for none.
fn mean(values: impl Iterator<Item = f64>) -> f64 {
    let (sum, count) = values.fold((0.0, 0usize), |(sum, count), value| (sum + value, count + 1));
    sum / count as f64
}

/// The bias of [`bias_sweep`] with the lowest mean error over every vertex at bounces 2 to 4 of
/// `measurements` (the first of equals).
pub fn best_bias(measurements: &[Measurement]) -> f64 {
    bias_sweep()
        .map(|bias| (bias, mean_biased_error(measurements, bias)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map_or(0.0, |(bias, _)| bias)
}

/// The sweep: per bias, the mean `|log2|` at bounces 2 to 4 by the lobe sampled before, and over
/// all of them, the best marked.
pub fn bias_sweep_table(measurements: &[Measurement]) -> String {
    let best = best_bias(measurements);
    let all = || measurements.iter().flat_map(|m| m.records.iter());
    let mut table = String::from(
        "### sweep: one global bias added to the cone without a scattering term past the first hit\n\n\
         | bias (mip levels) | after glossy GGX (r <= 0.3) | after rough GGX | after diffuse | all, bounces 2-4 |\n\
         |---:|---:|---:|---:|---:|",
    );
    for bias in bias_sweep() {
        let mark = if bias == best { " (best)" } else { "" };
        write!(table, "\n| {bias:+.2}{mark} |").unwrap();
        for group in GROUPS {
            let errors = all()
                .filter(|r| after(r) == Some(group))
                .map(|r| biased_log2_ratio(r, bias).abs());
            write!(table, " {:.3} |", mean(errors)).unwrap();
        }
        write!(table, " {:.3} |", mean_biased_error(measurements, bias)).unwrap();
    }
    table.push('\n');
    table
}

/// The scene's table: a row per method, a column per bounce, each cell
/// `mean / p95` of `|log2(method width / true width)|`, with the vertex counts (and those left
/// out) in the first rows.
pub fn scene_table(measurement: &Measurement) -> String {
    let bounces = 1..=MAX_VERTICES;
    let at = |bounce: usize| measurement.records.iter().filter(move |r| r.bounce == bounce);
    let mut table = format!(
        "### {}: {}\n\n| method |",
        measurement.scene, measurement.description
    );
    for bounce in bounces.clone() {
        write!(table, " bounce {bounce} |").unwrap();
    }
    table.push_str("\n|---|");
    table.push_str(&"---:|".repeat(MAX_VERTICES));
    table.push_str("\n| vertices |");
    for bounce in bounces.clone() {
        write!(table, " {} |", at(bounce).count()).unwrap();
    }
    table.push_str("\n| left out (history differs at +-h) |");
    for dropped in measurement.dropped {
        write!(table, " {dropped} |").unwrap();
    }
    for (m, method) in METHODS.iter().enumerate() {
        write!(table, "\n| {} |", method.name()).unwrap();
        for bounce in bounces.clone() {
            write!(table, " {} |", error_cell(at(bounce), |r| r.log2_ratio(m))).unwrap();
        }
    }
    table.push('\n');
    table
}

/// What the vertex before a vertex sampled, as the summary groups it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum After {
    /// A GGX lobe of roughness at most 0.3.
    Glossy,
    /// A GGX lobe rougher than 0.3.
    Rough,
    /// A Lambert lobe.
    Diffuse,
}

/// The groups in the order the tables print them.
const GROUPS: [After; 3] = [After::Glossy, After::Rough, After::Diffuse];

/// The group of a vertex at bounce 2 or later.
fn after(record: &VertexRecord) -> Option<After> {
    match record.previous_lobe? {
        Lobe::Diffuse => Some(After::Diffuse),
        Lobe::Glossy { roughness } if roughness <= 0.3 => Some(After::Glossy),
        Lobe::Glossy { .. } => Some(After::Rough),
    }
}

/// One row of [`summary_table`]: `name`, then per group the error and the signed mean of `ratio`.
fn summary_row(
    table: &mut String,
    name: &str,
    measurements: &[Measurement],
    ratio: impl Fn(&VertexRecord) -> f64,
) {
    write!(table, "\n| {name} |").unwrap();
    for group in GROUPS {
        let of = || {
            measurements
                .iter()
                .flat_map(|m| m.records.iter())
                .filter(move |r| after(r) == Some(group))
        };
        write!(
            table,
            " {} | {} |",
            error_cell(of(), &ratio),
            signed_cell(of(), &ratio)
        )
        .unwrap();
    }
}

/// The summary over all scenes: per method, over the vertices at bounces 2 to 4 after a glossy
/// GGX lobe (r <= 0.3), after a rough one (r > 0.3) and after a Lambert lobe, `mean / p95` of
/// `|log2|` and the mean signed `log2` (positive: too wide); last, the cone without a scattering
/// term with the sweep's best global bias ([`best_bias`]), which is fitted to these vertices.
pub fn summary_table(measurements: &[Measurement]) -> String {
    let all = || measurements.iter().flat_map(|m| m.records.iter());
    let of = move |group: After| all().filter(move |r| after(r) == Some(group));
    let mut table = String::from(
        "### summary: bounces 2-4 over all scenes, by the lobe sampled at the vertex before\n\n\
         | method | after glossy GGX (r <= 0.3) | signed | after rough GGX (r > 0.3) | signed \
         | after diffuse | signed |\n\
         |---|---:|---:|---:|---:|---:|---:|\n| vertices |",
    );
    for group in GROUPS {
        write!(table, " {} | |", of(group).count()).unwrap();
    }
    for (m, method) in METHODS.iter().enumerate() {
        summary_row(&mut table, method.name(), measurements, |r| r.log2_ratio(m));
    }
    let bias = best_bias(measurements);
    let name = format!("cone, no scattering term, global bias {bias:+.2} (the sweep's best, fitted here)");
    summary_row(&mut table, &name, measurements, |r| biased_log2_ratio(r, bias));
    table.push('\n');
    table
}
