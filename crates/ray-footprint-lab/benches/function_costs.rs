//! What each public shader function costs on the device, per language, with the timing loop's
//! own cost taken out, and beside it what the peers' originals cost.
//!
//! For every public function of every module (its Rust mirror's, in module order) and every
//! language (WGSL, GLSL, Slang, and HLSL through glslang and through slangc; and WGSL once more with
//! naga's loop bounding off, the counter naga puts in every loop unless told not to, as wgpu's
//! `create_shader_module_trusted` can), a compute kernel calls
//! the function in a loop whose every call depends on the last result
//! ([`ray_footprint_lab::timing::function`]): on a GPU 2^18 invocations of 2048 calls,
//! 536,870,912 evaluations per kernel. Beside it runs the language's *empty kernel* for the
//! function's signature: the same loop, the same dependence chain, with the call replaced by a
//! stand-in of a few adds that keeps the result depending on every argument ([`Body::Empty`]).
//! The kernels of one function are timed in rounds (at least 8), each language's function kernel
//! next to its empty kernel, in one order in even rounds and the reverse in odd ones, each round
//! one submission that starts with an untimed dispatch of its first kernel and then has a
//! timestamp pair around each kernel's dispatch and a barrier between two dispatches; each
//! function first has one untimed round (lavapipe compiles a pipeline at its first dispatch), and
//! the first function warm-up rounds until two successive round medians agree within 2%
//! ([`ray_footprint_lab::timing`]).
//!
//! One line per function and language: ns per evaluation (a kernel's time over its evaluations:
//! the whole device's throughput) of the function kernel and of the empty kernel, each the median
//! of the round medians and their spread, and the function's own: in each round the function
//! kernel's time less the empty kernel's, the median of those differences and their spread. Then
//! the SPIR-V instruction counts after `spirv-opt -O` (instructions inside functions) of the
//! function kernel and of the empty kernel, and their difference, the function's own instructions
//! (the stand-in's few count as the loop's, so the differences are a little low).
//!
//! Peers: with `--peers DIR` (or `RAY_FOOTPRINT_PEERS=DIR`), the directory that holds the peers'
//! sources (a Falcor checkout, the vk_raytracing_tutorial_KHR, nvpro_core2, or just their files),
//! the functions of [`PEERS`] get one more kernel in the same rounds: the peer's original, cut out
//! of its file at run time and compiled by slangc behind an adapter with the library function's
//! signature, on a line of its own after Slang's. It runs in the same loop as our Slang kernel (the
//! signature is the same), so Slang's empty kernel is subtracted from it too. The verdict on the
//! goal that no function is slower than its peer's original by more than 10% (Slang against
//! Slang) is taken on the subtracted times, each round's own difference: met where every round of
//! ours is within 1.1 times every round of the peer's, MISSED where every round is beyond it,
//! otherwise not separable at this load, and none where the peer's own time is not above zero in
//! some round (a function as cheap as the stand-in: a ratio of two such times means nothing); the
//! ratio of the raw medians is printed beside it.
//! Without a directory the peer's line says "not run". No peer code is in this repository.
//!
//! The peers with our guards: the five functions of [`PEERS`] with a guarded adapter
//! ([`Peer::guarded_adapter`]: the peer's same original, called with the library function's
//! guards for degenerate input added around it, the clamps, scalings and selects the peer lacks,
//! and where a guard sits inside the peer's function, added there: [`Peer::guards_inside`])
//! get one more kernel in the same rounds, compiled and timed as the peer's, on a line after the
//! peer's ("peer + our guards"), less Slang's empty kernel too. Its verdict is ours against it,
//! by the same rule: where the defined behaviour is what ours costs beyond the peer, ours is
//! within 1.1 times the peer with that behaviour added.
//!
//! On lavapipe (a CPU implementation) the run is a smoke run: 2^10 invocations of 16 calls, no
//! verdicts.
//!
//! `cargo bench -p ray-footprint-lab --bench function_costs [-- --function NAME] [--module NAME]
//! [--peers DIR] [--rounds N]`
//!
//! `--function` takes the shader name (`rf_process_wireframe`) or the mirror's
//! (`process_wireframe`); `--module` a module's file stem (`wireframe`).

use ash::vk;
use ray_footprint::shaders::Module;
use ray_footprint_lab::cli::{command_options, count_at_least, options_or_exit};
use ray_footprint_lab::timing::function::{inputs, signatures, timing_kernel, Body, Callee, Signature};
use ray_footprint_lab::timing::peers::{add_guards_inside, extract, AdapterKind, Peer, PEERS};
use ray_footprint_lab::timing::{
    self, gpu_clocks, query_pool, read_queries, round_order, warm_up, write_timestamp, Spread, Timestamps,
};
use shader_proptest::compile::validate_wgsl;
use shader_proptest::spirv::{self, Statistics};
use shader_proptest::{
    barrier_shader_writes, DeviceRequest, Error, Feature, Gpu, Language, Location, Owner, Shader,
    WORKGROUP_SIZE,
};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, PoisonError};

/// The environment variable that names the peers' directory when `--peers` does not.
const PEERS_ENV: &str = "RAY_FOOTPRINT_PEERS";
/// Fewest timed rounds.
const MIN_ROUNDS: usize = 8;
/// Most warm-up rounds.
const MAX_WARM_UP_ROUNDS: usize = 20;
/// The goal: no function slower than its peer's original by more than this factor.
const PEER_GOAL: f64 = 1.1;

/// Invocations and calls per invocation of every kernel.
#[derive(Clone, Copy)]
struct Load {
    invocations: usize,
    iterations: u32,
}

impl Load {
    fn evaluations(self) -> f64 {
        self.invocations as f64 * f64::from(self.iterations)
    }
}

/// On a GPU: 2^18 invocations (a full wave on an H100's 132 multiprocessors) of 2048 calls,
/// so that a kernel runs for a millisecond or more, far above a dispatch's own cost.
const GPU_LOAD: Load = Load {
    invocations: 1 << 18,
    iterations: 2048,
};
/// On lavapipe: a smoke run.
const LAVAPIPE_LOAD: Load = Load {
    invocations: 1 << 10,
    iterations: 16,
};

/// Which functions to time, against which peers, in how many rounds.
struct Options {
    function: Option<String>,
    module: Option<String>,
    peers: Option<PathBuf>,
    rounds: usize,
}

impl Options {
    fn accepts(&self, module: Module, function: &str) -> bool {
        let function_matches = self
            .function
            .as_deref()
            .is_none_or(|wanted| function == wanted || function.strip_prefix("rf_") == Some(wanted));
        let module_matches = self
            .module
            .as_deref()
            .is_none_or(|wanted| module.stem() == wanted);
        function_matches && module_matches
    }
}

const USAGE: &str =
    "usage: function_costs [--function NAME] [--module NAME] [--peers DIR] [--rounds N (>= 8)]";

fn parse_args(args: impl Iterator<Item = String>) -> Result<Options, String> {
    let mut options = Options {
        function: None,
        module: None,
        peers: std::env::var_os(PEERS_ENV).map(PathBuf::from),
        rounds: MIN_ROUNDS,
    };
    for (flag, value) in command_options(args)? {
        match flag.as_str() {
            "--function" => options.function = Some(value),
            "--module" => options.module = Some(value),
            "--peers" => options.peers = Some(PathBuf::from(value)),
            "--rounds" => options.rounds = count_at_least(&flag, &value, MIN_ROUNDS)?,
            other => return Err(format!("unknown argument '{other}'")),
        }
    }
    Ok(options)
}

/// How a line of kernels is compiled: its language, and for WGSL whether naga bounds its loops.
#[derive(Clone, Copy)]
struct Line {
    language: Language,
    /// naga's `force_loop_bounding` (WGSL only): a counter in every loop, which wgpu adds unless a
    /// module is made by `create_shader_module_trusted` with the loop check off.
    bounded_loops: bool,
}

impl Line {
    const fn of(language: Language) -> Line {
        Line {
            language,
            bounded_loops: true,
        }
    }

    fn label(self) -> &'static str {
        if self.bounded_loops {
            self.language.name()
        } else {
            "WGSL, loops unbounded"
        }
    }
}

/// The lines timed, each with its function kernel and its empty kernel: every language as its
/// compiler compiles it by default, then WGSL with naga's loop bounding off.
const LANGUAGES: [Line; 6] = [
    Line::of(Language::Wgsl),
    Line::of(Language::Glsl),
    Line::of(Language::Slang),
    Line::of(Language::HlslGlslang),
    Line::of(Language::HlslSlangc),
    Line {
        language: Language::Wgsl,
        bounded_loops: false,
    },
];
/// A row's kernels: each line's function kernel then its empty kernel, then the peer's, then the
/// guarded peer's.
const KERNELS: usize = 2 * LANGUAGES.len() + 2;
/// The peer's kernel's index.
const PEER: usize = KERNELS - 2;
/// The guarded peer's kernel's index (the peer's original with our guards added).
const GUARDED_PEER: usize = KERNELS - 1;
/// Slang's index in [`LANGUAGES`]: the peer's time is taken less Slang's empty kernel's.
const SLANG: usize = 2;

/// The index of the kernel of the `language`-th language (function or empty).
fn kernel_index(language: usize, body: Body) -> usize {
    match body {
        Body::Call => 2 * language,
        Body::Empty => 2 * language + 1,
    }
}

/// A kernel to compile: its shader, its source, its module and its line.
struct Job {
    shader: Shader,
    kernel: String,
    module: Module,
    line: Line,
}

/// A kernel's job, or why it cannot run here.
type Source = Result<Job, String>;
/// A kernel's SPIR-V and the statistics of its `spirv-opt -O` output, or why it cannot run.
type Compiled = Result<(Vec<u32>, Statistics), String>;

/// `source` compiled and counted.
fn compile(source: &Source) -> Compiled {
    let job = source.as_ref().map_err(Clone::clone)?;
    let words = if job.line.bounded_loops {
        job.shader
            .compile_kernel(&job.kernel)
            .map_err(|e| format!("error: {e}"))?
    } else {
        unbounded_wgsl(&job.kernel, job.module)?
    };
    let optimized = spirv::optimize(&words).map_err(|e| format!("error: {e}"))?;
    let statistics = Statistics::of(&optimized).map_err(|e| format!("error: {e}"))?;
    Ok((words, statistics))
}

/// A WGSL kernel compiled as the harness compiles it (SPIR-V 1.3, the module's capabilities and
/// immediates), but with naga's `force_loop_bounding` off.
fn unbounded_wgsl(kernel: &str, module: Module) -> Result<Vec<u32>, String> {
    let capabilities = module.naga_capabilities() | naga::valid::Capabilities::IMMEDIATES;
    let (parsed, info) =
        validate_wgsl(kernel, "kernel.wgsl", capabilities).map_err(|e| format!("error: {e}"))?;
    let options = naga::back::spv::Options {
        lang_version: (1, 3),
        force_loop_bounding: false,
        ..Default::default()
    };
    naga::back::spv::write_vec(&parsed, &info, &options, None)
        .map_err(|e| format!("error: naga SPIR-V output: {e}"))
}

/// Every source compiled, on every processor (the compilers are processes of their own; one at a
/// time, the 850 kernels of a full run took minutes), in the sources' order.
fn compile_all(sources: &[&Source]) -> Vec<Compiled> {
    let next = AtomicUsize::new(0);
    let compiled: Vec<Mutex<Option<Compiled>>> = sources.iter().map(|_| Mutex::new(None)).collect();
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| loop {
                let index = next.fetch_add(1, Ordering::Relaxed);
                let Some(source) = sources.get(index) else { break };
                *compiled[index].lock().unwrap_or_else(PoisonError::into_inner) = Some(compile(source));
            });
        }
    });
    compiled
        .into_iter()
        .map(|slot| {
            slot.into_inner()
                .unwrap_or_else(PoisonError::into_inner)
                .unwrap_or_else(|| Err(String::from("error: not compiled")))
        })
        .collect()
}

/// A compiled kernel, ready to dispatch.
struct Kernel {
    pipeline: vk::Pipeline,
    statistics: Statistics,
}

/// One function: its kernels (by [`kernel_index`], then [`PEER`] and [`GUARDED_PEER`]; or why
/// there is none) and their buffers.
struct Row {
    module: Module,
    name: String,
    peer: Option<&'static Peer>,
    kernels: Vec<Result<Kernel, String>>,
    set: vk::DescriptorSet,
    /// Each kernel's round medians, in ns per evaluation, round by round.
    times: Vec<Vec<f64>>,
}

/// The device objects every kernel shares: the owner, the descriptor-set and pipeline layouts.
struct Bench<'g> {
    gpu: &'g Gpu,
    owner: Owner<'g>,
    set_layout: vk::DescriptorSetLayout,
    layout: vk::PipelineLayout,
    load: Load,
}

impl<'g> Bench<'g> {
    fn new(gpu: &'g Gpu, load: Load) -> Result<Bench<'g>, Error> {
        let mut owner = Owner::new(gpu);
        let (set_layout, layout) = owner.compute_storage_layouts(2, &[])?;
        Ok(Bench {
            gpu,
            owner,
            set_layout,
            layout,
            load,
        })
    }

    /// The kernel of `callee` in `language` for `module`, or its empty kernel (`body`): its shader
    /// and kernel source, or why it cannot run here.
    fn source(&self, module: Module, line: Line, callee: Callee<'_>, body: Body) -> Source {
        let (shader, kernel) = timing_kernel(module, line.language, callee, body);
        match shader.features().iter().find(|&&f| !self.gpu.has(f)) {
            Some(feature) => Err(format!("not run: the device lacks {}", feature.name())),
            None => Ok(Job {
                shader,
                kernel,
                module,
                line,
            }),
        }
    }

    /// `compiled` made a pipeline.
    fn kernel(&mut self, compiled: Compiled) -> Result<Kernel, String> {
        let (words, statistics) = compiled?;
        let pipeline = self
            .owner
            .compute_pipeline(&words, self.layout)
            .map_err(|e| format!("error: {e}"))?;
        Ok(Kernel { pipeline, statistics })
    }

    /// A descriptor set over fresh input words of `signature` and an output buffer of its results.
    fn buffers(&mut self, signature: &Signature) -> Result<vk::DescriptorSet, Error> {
        let input = inputs(signature, self.load.invocations);
        let storage = vk::BufferUsageFlags::STORAGE_BUFFER;
        let input = self.owner.upload(bytemuck::cast_slice(&input), storage, 4)?;
        let output_bytes = (self.load.invocations * signature.result.words() * 4) as u64;
        let output = self.owner.buffer(output_bytes, storage, Location::Device, 4)?;
        let sizes = [vk::DescriptorPoolSize::default()
            .ty(vk::DescriptorType::STORAGE_BUFFER)
            .descriptor_count(2)];
        let set = self.owner.descriptor_set(self.set_layout, &sizes)?;
        let infos = [input, output].map(|buffer| {
            [vk::DescriptorBufferInfo::default()
                .buffer(buffer.buffer)
                .range(vk::WHOLE_SIZE)]
        });
        let writes: Vec<_> = infos
            .iter()
            .enumerate()
            .map(|(binding, info)| {
                vk::WriteDescriptorSet::default()
                    .dst_set(set)
                    .dst_binding(binding as u32)
                    .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                    .buffer_info(info)
            })
            .collect();
        // SAFETY: the writes match the layout's two storage-buffer bindings.
        unsafe { self.owner.device().update_descriptor_sets(&writes, &[]) };
        Ok(set)
    }

    /// One round over `row`'s kernels, in the round's order: each kernel's time in ns per
    /// evaluation, by kernel index (`None` where there is no kernel).
    fn round(&self, row: &Row, round: usize, timestamps: Timestamps) -> Result<Vec<Option<f64>>, Error> {
        let columns: Vec<usize> = round_order(KERNELS, round)
            .into_iter()
            .filter(|&column| row.kernels[column].is_ok())
            .collect();
        let mut frame = Owner::new(self.gpu);
        let queries = 2 * columns.len() as u32;
        let pool = query_pool(&mut frame, queries)?;
        let groups = (self.load.invocations as u32).div_ceil(WORKGROUP_SIZE);
        frame.submit(|device, command_buffer| {
            let bind_point = vk::PipelineBindPoint::COMPUTE;
            // The next kernel writes the same results, so it waits for this one.
            let (compute, written) = (
                vk::PipelineStageFlags::COMPUTE_SHADER,
                vk::AccessFlags::SHADER_WRITE,
            );
            // SAFETY: recording into a command buffer in the recording state; every handle is
            // alive and every query reset before it is written.
            unsafe {
                device.cmd_reset_query_pool(command_buffer, pool, 0, queries);
                device.cmd_bind_descriptor_sets(command_buffer, bind_point, self.layout, 0, &[row.set], &[]);
                // Untimed: whichever kernel comes first in a submission would pay its start.
                if let Some(Ok(first)) = columns.first().map(|&column| &row.kernels[column]) {
                    device.cmd_bind_pipeline(command_buffer, bind_point, first.pipeline);
                    device.cmd_dispatch(command_buffer, groups, 1, 1);
                    barrier_shader_writes(device, command_buffer, compute, (compute, written));
                }
                for (slot, &column) in columns.iter().enumerate() {
                    let Ok(kernel) = &row.kernels[column] else {
                        continue;
                    };
                    write_timestamp(device, command_buffer, pool, 2 * slot as u32);
                    device.cmd_bind_pipeline(command_buffer, bind_point, kernel.pipeline);
                    device.cmd_dispatch(command_buffer, groups, 1, 1);
                    write_timestamp(device, command_buffer, pool, 2 * slot as u32 + 1);
                    barrier_shader_writes(device, command_buffer, compute, (compute, written));
                }
            }
        })?;
        let times = timestamps.pairs(&read_queries(&frame, pool, queries as usize)?);
        let mut by_column = vec![None; KERNELS];
        for (&column, time) in columns.iter().zip(times) {
            by_column[column] = Some(time.as_secs_f64() * 1e9 / self.load.evaluations());
        }
        Ok(by_column)
    }
}

/// The peers' directory's extraction for `peer`, with the guards of `kind` inside it, followed by
/// `peer`'s adapter of `kind`, or why its column is not run.
fn peer_source(peers: Option<&PathBuf>, peer: &Peer, kind: AdapterKind) -> Result<String, String> {
    let adapter = peer
        .adapter_of(kind)
        .ok_or_else(|| String::from("no guarded adapter"))?;
    let dir = peers.ok_or_else(|| format!("not run: no peers' directory (--peers DIR or {PEERS_ENV})"))?;
    let path = peer.source.find(dir).ok_or_else(|| {
        format!(
            "not run: no {} under {}",
            peer.source.file_names().join(" or "),
            dir.display()
        )
    })?;
    let text = std::fs::read_to_string(&path).map_err(|e| format!("not run: {}: {e}", path.display()))?;
    let items = extract(&text, peer.items).map_err(|e| format!("error: {}: {e}", path.display()))?;
    let items = match kind {
        AdapterKind::Plain => items,
        AdapterKind::Guarded => add_guards_inside(&items, peer.guards_inside)
            .map_err(|e| format!("error: {}: {e}", path.display()))?,
    };
    Ok(format!("{items}\n{adapter}\n"))
}

/// The Slang kernel that times `peer`'s adapter of `kind` in the loop of `own` (the library
/// function's callee), or why there is none.
fn peer_kernel(
    bench: &Bench<'_>,
    module: Module,
    own: Callee<'_>,
    (peers, peer): (Option<&PathBuf>, Option<&Peer>),
    kind: AdapterKind,
) -> Source {
    let peer = peer.ok_or_else(|| String::from("no peer"))?;
    let extra = peer_source(peers, peer, kind)?;
    let name = kind.name(own.name);
    let callee = Callee {
        name: &name,
        extra: &extra,
        ..own
    };
    bench.source(module, Line::of(Language::Slang), callee, Body::Call)
}

/// A selected function before its kernels are compiled: its sources, by [`kernel_index`] then
/// [`PEER`] and [`GUARDED_PEER`], or why it has none.
struct Planned {
    module: Module,
    name: String,
    peer: Option<&'static Peer>,
    signature: Result<Signature, String>,
    sources: Vec<Source>,
}

/// Every selected function with its kernels' sources.
fn plan(bench: &Bench<'_>, options: &Options) -> Vec<Planned> {
    let mut planned = Vec::new();
    for &module in Module::ALL {
        for (name, signature) in signatures(module) {
            if !options.accepts(module, &name) {
                continue;
            }
            let peer = PEERS.iter().find(|peer| peer.function == name);
            let sources = match &signature {
                Err(reason) => (0..KERNELS).map(|_| Err(format!("not run: {reason}"))).collect(),
                Ok(signature) => {
                    let own = Callee {
                        signature,
                        name: &name,
                        extra: "",
                        iterations: bench.load.iterations,
                    };
                    let mut sources: Vec<Source> = LANGUAGES
                        .iter()
                        .flat_map(|&line| [(line, Body::Call), (line, Body::Empty)])
                        .map(|(line, body)| bench.source(module, line, own, body))
                        .collect();
                    let peers = (options.peers.as_ref(), peer);
                    sources.extend(
                        [AdapterKind::Plain, AdapterKind::Guarded]
                            .map(|kind| peer_kernel(bench, module, own, peers, kind)),
                    );
                    sources
                }
            };
            planned.push(Planned {
                module,
                name,
                peer,
                signature,
                sources,
            });
        }
    }
    planned
}

/// Every selected function's row, its kernels compiled and its buffers made.
fn rows(bench: &mut Bench<'_>, options: &Options) -> Result<Vec<Row>, Error> {
    let planned = plan(bench, options);
    let sources: Vec<&Source> = planned.iter().flat_map(|p| &p.sources).collect();
    let mut compiled = compile_all(&sources).into_iter();
    let mut rows = Vec::new();
    for function in planned {
        let kernels = compiled
            .by_ref()
            .take(KERNELS)
            .map(|compiled| bench.kernel(compiled))
            .collect();
        let set = match &function.signature {
            Ok(signature) => bench.buffers(signature)?,
            Err(_) => vk::DescriptorSet::null(),
        };
        rows.push(Row {
            module: function.module,
            name: function.name,
            peer: function.peer,
            kernels,
            set,
            times: vec![Vec::new(); KERNELS],
        });
    }
    Ok(rows)
}

/// A spread of ns per evaluation: the median and the smallest to the largest.
fn spread_cell(spread: Spread) -> String {
    format!("{:.6} ({:.6}-{:.6})", spread.median, spread.min, spread.max)
}

/// A cell of ns per evaluation: the median and the spread, or why there is none.
fn time_cell(kernel: &Result<Kernel, String>, times: &[f64]) -> String {
    match kernel {
        Ok(_) => spread_cell(Spread::of(times)),
        Err(reason) => reason.clone(),
    }
}

/// Round by round, kernel `function`'s time less kernel `empty`'s (the rounds time both), or
/// `None` where either has no kernel.
fn differences(row: &Row, function: usize, empty: usize) -> Option<Vec<f64>> {
    let (Ok(_), Ok(_)) = (&row.kernels[function], &row.kernels[empty]) else {
        return None;
    };
    Some(
        row.times[function]
            .iter()
            .zip(&row.times[empty])
            .map(|(with_call, without)| with_call - without)
            .collect(),
    )
}

/// The instruction counts of kernel `function` and kernel `empty`, and the difference.
fn instructions_cell(row: &Row, function: usize, empty: usize) -> String {
    match (&row.kernels[function], &row.kernels[empty]) {
        (Ok(with_call), Ok(without)) => {
            let (with_call, without) = (with_call.statistics.instructions, without.statistics.instructions);
            format!("{with_call} - {without} = {}", with_call as i64 - without as i64)
        }
        (Ok(with_call), Err(_)) => format!("{} - ?", with_call.statistics.instructions),
        _ => String::from("-"),
    }
}

/// The verdict on the goal against the peer's kernel `peer_kernel` ([`PEER`] or [`GUARDED_PEER`];
/// Slang against Slang), on each round's time less Slang's empty kernel's; beside it the ratio of
/// the raw medians.
fn peer_verdict(row: &Row, peer_kernel: usize, verdicts: bool) -> String {
    let slang = kernel_index(SLANG, Body::Call);
    let empty = kernel_index(SLANG, Body::Empty);
    let (Ok(_), Ok(_)) = (&row.kernels[slang], &row.kernels[peer_kernel]) else {
        return String::new();
    };
    let raw = Spread::of(&row.times[slang]).median / Spread::of(&row.times[peer_kernel]).median;
    let (Some(ours), Some(peer)) = (
        differences(row, slang, empty),
        differences(row, peer_kernel, empty),
    ) else {
        return format!("raw {raw:.2}x, no empty kernel: no verdict");
    };
    let (ours, peer) = (Spread::of(&ours), Spread::of(&peer));
    if peer.min <= 0.0 {
        return format!(
            "raw {raw:.2}x; the peer costs no more than the loop in some round: no ratio, no verdict"
        );
    }
    let ratio = format!("raw {raw:.2}x, less the loop {:.2}x", ours.median / peer.median);
    if !verdicts {
        return format!("{ratio}, no verdict (lavapipe)");
    }
    if ours.max <= PEER_GOAL * peer.min {
        format!("{ratio}: met")
    } else if ours.min > PEER_GOAL * peer.max {
        format!("{ratio}: MISSED")
    } else {
        format!("{ratio}: not separable at this load")
    }
}

/// A line of the table: kernel `function` against kernel `empty`, under `label`, with `verdict`.
fn print_line(row: &Row, label: &str, (function, empty): (usize, usize), verdict: &str) {
    let own = match (&row.kernels[function], differences(row, function, empty)) {
        (_, Some(differences)) => spread_cell(Spread::of(&differences)),
        (Err(reason), None) => reason.clone(),
        (Ok(_), None) => String::from("no empty kernel"),
    };
    println!(
        "| {} | `{}` | {label} | {} | {} | {own} | {} | {verdict} |",
        row.module.stem(),
        row.name,
        time_cell(&row.kernels[function], &row.times[function]),
        time_cell(&row.kernels[empty], &row.times[empty]),
        instructions_cell(row, function, empty),
    );
}

/// The peer's line and, where it has a guarded adapter, the guarded peer's with ours against it;
/// each less Slang's empty kernel.
fn print_peer_lines(row: &Row, peer: &Peer, verdicts: bool) {
    let empty = kernel_index(SLANG, Body::Empty);
    let label = format!("peer: {} (Slang)", peer.source.name());
    print_line(row, &label, (PEER, empty), "");
    if peer.guarded_adapter.is_some() {
        let label = format!("peer + our guards: {} (Slang)", peer.source.name());
        let verdict = peer_verdict(row, GUARDED_PEER, verdicts);
        print_line(row, &label, (GUARDED_PEER, empty), &verdict);
    }
}

fn print_rows(rows: &[Row], verdicts: bool) {
    println!(
        "| module | function | language | ns | empty kernel ns | function ns (less the empty kernel) | \
         instructions (kernel - empty = function) | Slang vs peer, on a guarded peer's line Slang vs it \
         (goal <= {PEER_GOAL}x) |"
    );
    println!("| --- | --- | --- | ---: | ---: | ---: | ---: | --- |");
    for row in rows {
        for (index, line) in LANGUAGES.iter().enumerate() {
            let kernels = (kernel_index(index, Body::Call), kernel_index(index, Body::Empty));
            let verdict = if index == SLANG {
                peer_verdict(row, PEER, verdicts)
            } else {
                String::new()
            };
            print_line(row, line.label(), kernels, &verdict);
            if let (SLANG, Some(peer)) = (index, row.peer) {
                print_peer_lines(row, peer, verdicts);
            }
        }
    }
}

fn run(options: &Options) -> Result<usize, Error> {
    let gpu = Gpu::open(DeviceRequest {
        required: &[],
        optional: &[Feature::ShaderFloat64],
    })?;
    let lavapipe = gpu.driver().contains("llvmpipe");
    let load = if lavapipe { LAVAPIPE_LOAD } else { GPU_LOAD };
    println!("device: {} ({})", gpu.name(), gpu.driver());
    println!("GPU clocks at the start: {}", gpu_clocks());
    if lavapipe {
        println!("lavapipe runs on the CPU: a smoke run of the method ({} evaluations per kernel, not 10^8); its times say nothing of a GPU, and no verdict is given", load.evaluations());
    }
    let timestamps = Timestamps::of(&gpu).map_err(Error::Setup)?;
    let mut bench = Bench::new(&gpu, load)?;
    let mut rows = rows(&mut bench, options)?;
    let Some(first) = rows.iter().position(|row| row.kernels.iter().any(Result::is_ok)) else {
        print_rows(&rows, false);
        return Ok(failures(&rows));
    };
    let warm = warm_up(MAX_WARM_UP_ROUNDS, || {
        let times = bench.round(&rows[first], 0, timestamps)?;
        Ok::<f64, Error>(timing::median(
            &times.iter().flatten().copied().collect::<Vec<_>>(),
        ))
    })?;
    println!(
        "{} invocations x {} calls = {} evaluations per kernel; {} rounds per function after {} warm-up rounds ({}); \
         ns per evaluation: median of the round medians (smallest-largest)\n",
        load.invocations,
        load.iterations,
        load.evaluations(),
        options.rounds,
        warm.medians.len(),
        if warm.settled { "settled within 2%" } else { "NOT settled within 2%" }
    );
    for row in &mut rows {
        // Untimed: lavapipe compiles a pipeline at its first dispatch.
        bench.round(row, 0, timestamps)?;
        for round in 0..options.rounds {
            let times = bench.round(row, round, timestamps)?;
            for (kernel, time) in times.iter().enumerate() {
                row.times[kernel].extend(*time);
            }
        }
    }
    print_rows(&rows, !lavapipe);
    println!("\nGPU clocks at the end: {}", gpu_clocks());
    Ok(failures(&rows))
}

/// How many kernels failed to compile or to become a pipeline.
fn failures(rows: &[Row]) -> usize {
    rows.iter()
        .flat_map(|row| &row.kernels)
        .filter(|kernel| {
            kernel
                .as_ref()
                .err()
                .is_some_and(|reason| reason.starts_with("error"))
        })
        .count()
}

fn main() -> ExitCode {
    let options = options_or_exit(parse_args(std::env::args().skip(1)), USAGE);
    if Module::ALL.iter().all(|&module| {
        signatures(module)
            .iter()
            .all(|(name, _)| !options.accepts(module, name))
    }) {
        eprintln!("error: no function matches");
        return ExitCode::from(2);
    }
    match run(&options) {
        Ok(0) => ExitCode::SUCCESS,
        Ok(failed) => {
            eprintln!("{failed} kernel(s) failed (see the table)");
            ExitCode::FAILURE
        }
        Err(error) => {
            eprintln!("error: {error}");
            ExitCode::FAILURE
        }
    }
}
