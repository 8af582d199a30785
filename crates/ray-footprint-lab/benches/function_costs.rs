//! What each public shader function costs on the device, per language, and beside it what the
//! peers' original functions cost.
//!
//! For every public function of every module (its Rust mirror's, in module order) and every
//! language but HLSL (not timed yet), a compute kernel calls the function in a loop whose every call depends on the last
//! result ([`ray_footprint_lab::timing::function`]): on a GPU 2^18 invocations of 2048 calls,
//! 536,870,912 evaluations per kernel. The kernels of one function are timed in rounds (at least
//! 8), the languages in one order in even rounds and the reverse in odd ones, each round one
//! submission that starts with an untimed dispatch of its first kernel and then has a timestamp
//! pair around each kernel's dispatch and a barrier between two dispatches; each function first
//! has one untimed round (lavapipe compiles a pipeline at its first dispatch), and the first
//! function warm-up rounds until two successive round medians agree within 2%
//! ([`ray_footprint_lab::timing`]). Per kernel: ns per evaluation (the kernel's time over its
//! evaluations: the whole device's throughput), the median of the round medians and their spread,
//! and the SPIR-V of the same kernel after `spirv-opt -O` (instructions inside functions; the
//! loop's own are in every column).
//!
//! Peers: with `--peers DIR` (or `RAY_FOOTPRINT_PEERS=DIR`), the directory that holds the peers'
//! sources (a Falcor checkout, the vk_raytracing_tutorial_KHR, nvpro_core2, or just their files),
//! the functions of [`PEERS`] get a fourth kernel in the same rounds: the peer's original, cut out
//! of its file at run time and compiled by slangc behind an adapter with the library function's
//! signature, and the verdict on the goal that no function is slower than its peer's original by
//! more than 10% (Slang against Slang): met where every round of ours is within 1.1 times every
//! round of the peer's, MISSED where every round is beyond it, otherwise not separable at this
//! load. Without a directory the peer columns say "not run". No peer code is in this repository.
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
use ray_footprint_lab::cli::{bench_options, count_at_least, options_or_exit};
use ray_footprint_lab::timing::function::{inputs, signatures, timing_kernel, Callee, Signature};
use ray_footprint_lab::timing::peers::{extract, Peer, PEERS};
use ray_footprint_lab::timing::{
    self, gpu_clocks, query_pool, read_queries, round_order, warm_up, write_timestamp, Spread, Timestamps,
};
use shader_proptest::spirv::{self, Statistics};
use shader_proptest::{
    barrier_shader_writes, DeviceRequest, Error, Feature, Gpu, Language, Location, Owner, WORKGROUP_SIZE,
};
use std::path::PathBuf;
use std::process::ExitCode;

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
    for (flag, value) in bench_options(args)? {
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

/// The columns of a row: the three languages, then the peer's original (Slang).
const COLUMNS: [&str; 4] = ["WGSL", "GLSL", "Slang", "peer"];

/// A compiled kernel, ready to dispatch.
struct Kernel {
    pipeline: vk::Pipeline,
    statistics: Statistics,
}

/// One function: its kernels (per column, or why there is none) and their buffers.
struct Row {
    module: Module,
    name: String,
    peer: Option<&'static Peer>,
    kernels: [Result<Kernel, String>; 4],
    set: vk::DescriptorSet,
    /// Each column's round medians, in ns per evaluation.
    times: [Vec<f64>; 4],
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

    /// The kernel of `callee` in `language` for `module`, compiled and made a pipeline; the
    /// reason where it cannot run here.
    fn kernel(&mut self, module: Module, language: Language, callee: Callee<'_>) -> Result<Kernel, String> {
        let (shader, kernel) = timing_kernel(module, language, callee);
        if let Some(feature) = shader.features().iter().find(|&&f| !self.gpu.has(f)) {
            return Err(format!("not run: the device lacks {}", feature.name()));
        }
        let words = shader
            .compile_kernel(&kernel)
            .map_err(|e| format!("error: {e}"))?;
        let optimized = spirv::optimize(&words).map_err(|e| format!("error: {e}"))?;
        let statistics = Statistics::of(&optimized).map_err(|e| format!("error: {e}"))?;
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
    /// evaluation, by column (`None` where the column has no kernel).
    fn round(&self, row: &Row, round: usize, timestamps: Timestamps) -> Result<[Option<f64>; 4], Error> {
        let columns: Vec<usize> = round_order(COLUMNS.len(), round)
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
        let mut by_column = [None; 4];
        for (&column, time) in columns.iter().zip(times) {
            by_column[column] = Some(time.as_secs_f64() * 1e9 / self.load.evaluations());
        }
        Ok(by_column)
    }
}

/// The peers' directory's extraction for `peer`, or why its column is not run.
fn peer_source(peers: Option<&PathBuf>, peer: &Peer) -> Result<String, String> {
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
    Ok(format!("{items}\n{}\n", peer.adapter))
}

/// Every selected function's row, its kernels compiled and its buffers made.
fn rows(bench: &mut Bench<'_>, options: &Options) -> Result<Vec<Row>, Error> {
    let mut rows = Vec::new();
    for &module in Module::ALL {
        for (name, signature) in signatures(module) {
            if !options.accepts(module, &name) {
                continue;
            }
            let peer = PEERS.iter().find(|peer| peer.function == name);
            let signature = match signature {
                Ok(signature) => signature,
                Err(reason) => {
                    rows.push(Row {
                        module,
                        name,
                        peer,
                        kernels: [0, 1, 2, 3].map(|_| Err(format!("not run: {reason}"))),
                        set: vk::DescriptorSet::null(),
                        times: Default::default(),
                    });
                    continue;
                }
            };
            let iterations = bench.load.iterations;
            let own = Callee {
                signature: &signature,
                name: &name,
                extra: "",
                iterations,
            };
            let [wgsl, glsl, slang] = [Language::Wgsl, Language::Glsl, Language::Slang]
                .map(|language| bench.kernel(module, language, own));
            let peer_kernel = match peer {
                None => Err(String::from("no peer")),
                Some(peer) => peer_source(options.peers.as_ref(), peer).and_then(|extra| {
                    let adapter = format!("peer_{name}");
                    let callee = Callee {
                        name: &adapter,
                        extra: &extra,
                        ..own
                    };
                    bench.kernel(module, Language::Slang, callee)
                }),
            };
            let set = bench.buffers(&signature)?;
            rows.push(Row {
                module,
                name,
                peer,
                kernels: [wgsl, glsl, slang, peer_kernel],
                set,
                times: Default::default(),
            });
        }
    }
    Ok(rows)
}

/// A cell of ns per evaluation: the median and the spread, or why there is none.
fn time_cell(kernel: &Result<Kernel, String>, times: &[f64]) -> String {
    match kernel {
        Ok(_) => {
            let spread = Spread::of(times);
            format!("{:.6} ({:.6}-{:.6})", spread.median, spread.min, spread.max)
        }
        Err(reason) => reason.clone(),
    }
}

/// The verdict on the goal against the peer (Slang against Slang).
fn peer_verdict(row: &Row, verdicts: bool) -> String {
    let (Ok(_), Ok(_)) = (&row.kernels[2], &row.kernels[3]) else {
        return String::new();
    };
    let (ours, peer) = (Spread::of(&row.times[2]), Spread::of(&row.times[3]));
    let ratio = format!("{:.2}x", ours.median / peer.median);
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

fn print_rows(rows: &[Row], verdicts: bool) {
    println!(
        "| module | function | WGSL ns | GLSL ns | Slang ns | peer | peer ns (Slang) | Slang vs peer (goal <= {PEER_GOAL}x) | \
         instructions WGSL / GLSL / Slang / peer |"
    );
    println!("| --- | --- | ---: | ---: | ---: | --- | ---: | --- | ---: |");
    for row in rows {
        let cells: Vec<String> = row
            .kernels
            .iter()
            .zip(&row.times)
            .map(|(kernel, times)| time_cell(kernel, times))
            .collect();
        let instructions: Vec<String> = row
            .kernels
            .iter()
            .map(|kernel| {
                kernel
                    .as_ref()
                    .map_or(String::from("-"), |k| k.statistics.instructions.to_string())
            })
            .collect();
        let peer = row.peer.map_or("", |peer| peer.source.name());
        let peer_time = if row.peer.is_some() { cells[3].as_str() } else { "" };
        println!(
            "| {} | `{}` | {} | {} | {} | {peer} | {peer_time} | {} | {} |",
            row.module.stem(),
            row.name,
            cells[0],
            cells[1],
            cells[2],
            peer_verdict(row, verdicts),
            instructions.join(" / ")
        );
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
            for (column, time) in times.iter().enumerate() {
                row.times[column].extend(*time);
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
