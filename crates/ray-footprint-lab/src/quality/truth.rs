//! The ground truth: the truth method (mip 0, or the wireframe's hard lines) supersampled with
//! N x N stratified sub-pixel samples per pixel and a box filter, through the same renderer; one
//! image per frame of the camera's drift; cached on disk.

use super::image::{Image, LinearSum};
use super::scenes::{LabScene, Method};
use super::LabError;
use crate::rt::{Renderer, SHADER_DIR};
use glam::Vec2;
use ray_footprint::shaders::GLSL_INCLUDE_DIR;
use std::path::{Path, PathBuf};

/// Seed of the stratified jitter: the same samples on every run.
const JITTER_SEED: u64 = 0x5eed_0f7e_57da_7a11;
/// First bytes of a cached ground truth (and the cache format's version).
const CACHE_MAGIC: &[u8; 8] = b"RFTRUTH1";

/// How the ground truth is sampled and how many frames the camera drifts over.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TruthSettings {
    /// N: samples per pixel along each axis (N x N per pixel).
    pub samples_per_axis: u32,
    /// K: frames of the drift (1: the still image only).
    pub frames: u32,
}

/// The image-plane offset of drift frame `frame`: `frame / N` pixels to the right. Every frame
/// moves the image by one stratum of the ground truth, so consecutive frames' truths share all
/// but one column of their samples.
pub fn drift(settings: TruthSettings, frame: u32) -> Vec2 {
    Vec2::new(frame as f32 / settings.samples_per_axis as f32, 0.0)
}

/// SplitMix64 (Steele, Lea, Flood 2014): a well-mixed 64-bit hash of `value`.
fn splitmix64(value: u64) -> u64 {
    let mut z = value.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce5_e9b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// A uniform number in [0, 1) for stratum `(column, row)` and `axis`, the same on every run.
fn jitter(column: u32, row: u32, axis: u32) -> f32 {
    let key = (u64::from(column) << 40) ^ (u64::from(row) << 20) ^ u64::from(axis);
    (splitmix64(JITTER_SEED ^ splitmix64(key)) >> 40) as f32 / (1u64 << 24) as f32
}

/// Offset from the pixel centre of the sample in stratum `(column, row)`: a random point of the
/// stratum, `((column + u) / N - 0.5, (row + v) / N - 0.5)` pixels. Columns run past N - 1 for
/// the drift: column `c` of frame `k` is stratum `c - k` of that frame's pixel.
pub fn sample_offset(settings: TruthSettings, (column, row): (u32, u32)) -> Vec2 {
    let n = settings.samples_per_axis as f32;
    let u = jitter(column, row, 0);
    let v = jitter(column, row, 1);
    Vec2::new((column as f32 + u) / n - 0.5, (row as f32 + v) / n - 0.5)
}

/// The samples a ground truth renders: `(N + K - 1) * N` frames.
pub fn sample_count(settings: TruthSettings) -> u64 {
    let n = u64::from(settings.samples_per_axis);
    (n + u64::from(settings.frames) - 1) * n
}

/// The ground truth of a scene: one image per drift frame, `frames[0]` the still image.
#[derive(Clone, Debug, PartialEq)]
pub struct Truth {
    /// The box-filtered images, frame after frame.
    pub frames: Vec<Image>,
}

/// Renders one frame of `method` with the primary rays offset by `offset` pixels.
pub fn render(
    renderer: &Renderer<'_>,
    lab: &LabScene,
    method: &Method,
    (width, height): (u32, u32),
    offset: Vec2,
) -> Result<crate::rt::Frame, LabError> {
    let mut push = renderer.push_constants(&lab.camera, method.mode, 1.0, width, height);
    push.pixel_offset = offset;
    push.flags = method.flags;
    let uniforms = lab.camera.uniforms((width, height), method.settings);
    Ok(renderer.render(&push, &uniforms)?)
}

/// Renders the ground truth: for every column of strata (N + K - 1 of them) N samples, summed
/// in linear light; frame `k` is the mean of columns `k` to `k + N - 1`, encoded for display.
/// Calls `tick` after every frame rendered.
pub fn render_truth(
    renderer: &Renderer<'_>,
    lab: &LabScene,
    size: (u32, u32),
    settings: TruthSettings,
    tick: &mut dyn FnMut(),
) -> Result<Truth, LabError> {
    let method = lab.truth_method();
    let n = settings.samples_per_axis;
    let mut columns = Vec::new();
    for column in 0..n + settings.frames - 1 {
        let mut sum = LinearSum::new(size.0, size.1);
        for row in 0..n {
            let offset = sample_offset(settings, (column, row));
            sum.add(&render(renderer, lab, &method, size, offset)?);
            tick();
        }
        columns.push(sum);
    }
    let frames = (0..settings.frames as usize)
        .map(|k| {
            let mut total = LinearSum::new(size.0, size.1);
            columns[k..k + n as usize].iter().for_each(|c| total.add_sum(c));
            total.mean()
        })
        .collect();
    Ok(Truth { frames })
}

/// FNV-1a, 64 bits: a hash that is the same on every platform and Rust version.
#[derive(Clone, Copy, Debug)]
struct Fnv(u64);

impl Fnv {
    fn new() -> Fnv {
        Fnv(0xcbf2_9ce4_8422_2325)
    }

    fn bytes(&mut self, bytes: &[u8]) {
        for &byte in bytes {
            self.0 = (self.0 ^ u64::from(byte)).wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
}

/// The text of every file in `dir`, sorted by name (the shaders the renderer compiles).
fn directory_text(dir: &str) -> Result<Vec<(String, Vec<u8>)>, LabError> {
    let io = |e: std::io::Error| LabError::Io(format!("reading {dir}: {e}"));
    let mut files = Vec::new();
    for entry in std::fs::read_dir(dir).map_err(io)? {
        let path = entry.map_err(io)?.path();
        if path.is_file() {
            let name = path
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default();
            files.push((name, std::fs::read(&path).map_err(io)?));
        }
    }
    files.sort();
    Ok(files)
}

/// What a ground truth depends on, hashed: the scene as built (vertices, indices, materials,
/// texture, camera), the truth method (mode, flags and wireframe settings), the image size, N and K,
/// the device, every shader the renderer compiles (its own and the library's GLSL), and the source
/// of the sampling and the averaging (this file and `image.rs`).
pub fn truth_key(
    lab: &LabScene,
    size: (u32, u32),
    settings: TruthSettings,
    device: &str,
) -> Result<u64, LabError> {
    let mut hash = Fnv::new();
    let scene = &lab.scene;
    hash.bytes(bytemuck::cast_slice(&scene.vertex_floats()));
    hash.bytes(bytemuck::cast_slice(&scene.indices()));
    hash.bytes(bytemuck::cast_slice(&scene.mesh_table()));
    hash.bytes(&lab.texture.size.to_le_bytes());
    lab.texture
        .levels
        .iter()
        .for_each(|level| hash.bytes(bytemuck::cast_slice(level)));
    let camera = [lab.camera.eye.to_array(), lab.camera.target.to_array()];
    hash.bytes(bytemuck::cast_slice(&camera));
    hash.bytes(&lab.camera.fov_y.to_le_bytes());
    let method = lab.truth_method();
    hash.bytes(&method.mode.id().to_le_bytes());
    hash.bytes(&method.flags.to_le_bytes());
    hash.bytes(bytemuck::bytes_of(&method.settings.pack()));
    for value in [size.0, size.1, settings.samples_per_axis, settings.frames] {
        hash.bytes(&value.to_le_bytes());
    }
    hash.bytes(device.as_bytes());
    for dir in [SHADER_DIR, GLSL_INCLUDE_DIR] {
        for (name, text) in directory_text(dir)? {
            hash.bytes(name.as_bytes());
            hash.bytes(&text);
        }
    }
    hash.bytes(include_str!("truth.rs").as_bytes());
    hash.bytes(include_str!("image.rs").as_bytes());
    Ok(hash.0)
}

/// Where the ground truth of `lab` at `size` with `settings` is cached in `dir`.
pub fn cache_path(
    dir: &Path,
    lab: &LabScene,
    size: (u32, u32),
    settings: TruthSettings,
    key: u64,
) -> PathBuf {
    let TruthSettings {
        samples_per_axis: n,
        frames: k,
    } = settings;
    dir.join(format!(
        "{}-{}x{}-n{n}-k{k}-{key:016x}.truth",
        lab.name, size.0, size.1
    ))
}

/// Writes `truth` to `path`: the magic, width, height and frame count (u32 little-endian), then
/// every frame's RGB display values (f32 little-endian).
pub fn save(path: &Path, truth: &Truth) -> Result<(), LabError> {
    let first = truth
        .frames
        .first()
        .ok_or_else(|| LabError::Io("a truth without frames".into()))?;
    let mut bytes = CACHE_MAGIC.to_vec();
    for value in [first.width, first.height, truth.frames.len() as u32] {
        bytes.extend(value.to_le_bytes());
    }
    for frame in &truth.frames {
        frame
            .pixels
            .iter()
            .flatten()
            .for_each(|v| bytes.extend(v.to_le_bytes()));
    }
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(|e| LabError::Io(format!("creating {}: {e}", dir.display())))?;
    }
    std::fs::write(path, bytes).map_err(|e| LabError::Io(format!("writing {}: {e}", path.display())))
}

/// Reads a truth [`save`] wrote, if `path` holds one of `size` with `frames` frames; `None` if
/// there is no such file or it does not match (it is then rendered again).
pub fn load(path: &Path, size: (u32, u32), frames: u32) -> Option<Truth> {
    let bytes = std::fs::read(path).ok()?;
    let header = CACHE_MAGIC.len() + 12;
    let word = |at: usize| u32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]);
    let pixels = size.0 as usize * size.1 as usize;
    let expected = header + 12 * pixels * frames as usize;
    if bytes.len() != expected
        || &bytes[..8] != CACHE_MAGIC
        || (word(8), word(12), word(16)) != (size.0, size.1, frames)
    {
        return None;
    }
    let values: Vec<f32> = bytes[header..]
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    let frames = values
        .chunks_exact(3 * pixels)
        .map(|frame| Image {
            width: size.0,
            height: size.1,
            pixels: frame.chunks_exact(3).map(|p| [p[0], p[1], p[2]]).collect(),
        })
        .collect();
    Some(Truth { frames })
}
