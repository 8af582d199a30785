//! The inclusion paths, proven by the downstream crates of `examples/downstream/` built against the
//! packaged crate, as crates.io would serve it: `cargo package` of the working tree, unpacked
//! outside the repository, and a copy of the downstream workspace whose ray-footprint dependency
//! points at it. Each crate is built and run as a user's would be and checks its own results. A
//! package holds a subset of the repository's files, so what works from it works from the
//! repository too.
//!
//! The crates that need no particular feature set of their own are built in one cargo run, with
//! the union of their features, so that their shared dependencies (naga, ash, glam, ...) are
//! built once; each crate asks for the features it uses itself, so the union hides no missing
//! one. The CPU path tracer is built alone: its point is ray-footprint's default features.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// The crates built together, by package name.
const TOGETHER: &[&str] = &[
    "downstream-glsl-build-script",
    "downstream-hlsl-build-script",
    "downstream-naga-oil",
    "downstream-shader-proptest-user",
    "downstream-slang-build-script",
    "downstream-textured-ray-tracer",
    "downstream-wgpu-compute",
];

/// Where the package, its unpacked copy and the downstream workspace built against it go.
fn work_dir() -> PathBuf {
    Path::new(ROOT).join("target/downstream")
}

/// The output of `command`, which must succeed.
fn run(command: &mut Command) -> Output {
    let output = command
        .output()
        .unwrap_or_else(|error| panic!("cannot run {command:?}: {error}"));
    assert!(
        output.status.success(),
        "{command:?} failed:\n{}\n{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    output
}

/// Packages the working tree as `cargo publish` would (`cargo package` of shader-proptest and
/// ray-footprint: ray-footprint's lock file needs the other's package), unpacks ray-footprint's
/// `.crate` into `work/unpacked` and returns its directory.
fn unpacked_crate(work: &Path) -> PathBuf {
    let cargo_target = work.join("package");
    run(Command::new(env!("CARGO"))
        .current_dir(ROOT)
        .args(["package", "--quiet", "--no-verify", "--allow-dirty"])
        .args(["-p", "shader-proptest", "-p", "ray-footprint", "--target-dir"])
        .arg(&cargo_target));
    let unpacked = work.join("unpacked");
    let _ = fs::remove_dir_all(&unpacked);
    fs::create_dir_all(&unpacked).expect("creating the directory to unpack into");
    let name = format!("ray-footprint-{}", env!("CARGO_PKG_VERSION"));
    run(Command::new("tar")
        .arg("-xzf")
        .arg(cargo_target.join(format!("package/{name}.crate")))
        .arg("-C")
        .arg(&unpacked));
    unpacked.join(name)
}

/// Copies `from` into `to`, files and folders, leaving out `target`.
fn copy_tree(from: &Path, to: &Path) {
    fs::create_dir_all(to).expect("creating a copy's directory");
    for entry in fs::read_dir(from).expect("reading the downstream workspace") {
        let entry = entry.expect("reading the downstream workspace");
        let target = to.join(entry.file_name());
        if entry.path().is_dir() {
            if entry.file_name() != "target" {
                copy_tree(&entry.path(), &target);
            }
        } else {
            fs::copy(entry.path(), target).expect("copying the downstream workspace");
        }
    }
}

/// The downstream workspace copied to `work/workspace`, each crate's ray-footprint dependency
/// (`path = "../../.."`) on the unpacked `package` and its shader-proptest dependency, and the
/// package's, on the repository's.
fn workspace_against_package(package: &Path, work: &Path) -> PathBuf {
    let workspace = work.join("workspace");
    let _ = fs::remove_dir_all(&workspace);
    copy_tree(&Path::new(ROOT).join("examples/downstream"), &workspace);
    let shader_proptest = Path::new(ROOT).join("crates/shader-proptest");
    for entry in fs::read_dir(&workspace).expect("reading the copy") {
        let manifest = entry.expect("reading the copy").path().join("Cargo.toml");
        let Ok(text) = fs::read_to_string(&manifest) else {
            continue;
        };
        let text = text
            .replace(
                "path = \"../../../crates/shader-proptest\"",
                &format!("path = {:?}", shader_proptest.display().to_string()),
            )
            .replace(
                "path = \"../../..\"",
                &format!("path = {:?}", package.display().to_string()),
            );
        fs::write(&manifest, text).expect("rewriting a manifest");
    }
    // The package asks crates.io for shader-proptest (its optional dependency, which a crate
    // that enables ray-footprint's feature `shader-proptest` needs): the repository's.
    let root_manifest = workspace.join("Cargo.toml");
    let mut text = fs::read_to_string(&root_manifest).expect("reading the workspace manifest");
    text.push_str(&format!(
        "\n[patch.crates-io]\nshader-proptest = {{ path = {:?} }}\n",
        shader_proptest.display().to_string()
    ));
    fs::write(&root_manifest, text).expect("rewriting the workspace manifest");
    workspace
}

/// The packaged crate and the downstream workspace against it, with the crates of [`TOGETHER`]
/// built (`cargo build` and `cargo test --no-run`, the same packages, so the same features),
/// once for all tests: `(package directory, workspace directory)`, or what failed.
fn built_together() -> &'static Result<(PathBuf, PathBuf), String> {
    static BUILT: OnceLock<Result<(PathBuf, PathBuf), String>> = OnceLock::new();
    BUILT.get_or_init(|| {
        let work = work_dir();
        let package = unpacked_crate(&work);
        let workspace = workspace_against_package(&package, &work);
        for command in [&["build"][..], &["test", "--no-run"]] {
            let output = cargo_together(&workspace, command)
                .output()
                .map_err(|error| format!("cannot run cargo: {error}"))?;
            if !output.status.success() {
                return Err(format!(
                    "building the downstream crates failed:\n{}",
                    String::from_utf8_lossy(&output.stderr)
                ));
            }
        }
        Ok((package, workspace))
    })
}

/// [`built_together`]'s directories; panics with what failed.
fn built() -> &'static (PathBuf, PathBuf) {
    built_together()
        .as_ref()
        .unwrap_or_else(|error| panic!("{error}"))
}

/// `cargo <arguments>` on the crates of [`TOGETHER`] in `workspace`, in the dev profile (the
/// downstream workspace's, unoptimised and without debug information: the crates prove that
/// their inclusion paths work, and their programs run in seconds unoptimised).
fn cargo_together(workspace: &Path, arguments: &[&str]) -> Command {
    let mut command = Command::new(env!("CARGO"));
    command
        .args(arguments)
        .args(["--quiet", "--manifest-path"])
        .arg(workspace.join("Cargo.toml"))
        .arg("--target-dir")
        .arg(work_dir().join("target"));
    for name in TOGETHER {
        command.args(["-p", name]);
    }
    command
}

/// What `command` printed; it must succeed and print every one of `expected`.
fn stdout_of(mut command: Command, expected: &[&str]) -> String {
    let output = command
        .output()
        .unwrap_or_else(|error| panic!("cannot run {command:?}: {error}"));
    let stdout = String::from_utf8_lossy(&output.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&output.stderr);
    println!("{command:?}:\n{stdout}");
    assert!(output.status.success(), "{command:?} failed:\n{stdout}\n{stderr}");
    for text in expected {
        assert!(
            stdout.contains(text),
            "{command:?} did not print {text:?}:\n{stdout}"
        );
    }
    stdout
}

/// Runs the program of the downstream crate `name` (one of [`TOGETHER`], without the
/// `downstream-` prefix); it must succeed and print every one of `expected`.
fn run_together(name: &str, expected: &[&str]) {
    built();
    let program = work_dir().join("target/debug").join(format!("downstream-{name}"));
    stdout_of(Command::new(program), expected);
}

/// The directory of `language`'s modules in the package, as the build-script crates print it.
fn package_modules(language: &str) -> String {
    let (package, _) = built();
    let directory = package.join("shaders").join(language.to_lowercase());
    format!("{language} modules in {}", directory.display())
}

/// A wgpu user: the same compute shader with the WGSL modules pasted in front
/// (`ray_footprint::wgpu::shader_with_modules`) and with the WESL package imported by path (linked
/// by wesl-rs in its build script), each validated by wgpu and run through its Vulkan backend on
/// lavapipe, compared with the Rust mirror.
#[test]
fn wgpu_compute_shader_agrees_with_the_mirror() {
    run_together(
        "wgpu-compute",
        &[
            "WGSL modules pasted in front: 4096 cases",
            "WESL package imported by path: 4096 cases",
        ],
    );
}

/// A hobby ray tracer's first cone LOD: an image-plane camera and triangles traced in one wgpu
/// compute shader on lavapipe, its brick texture sampled at mip 0 and at `rf_hit_texture_lod`'s
/// level (mips from `generate_mipmaps`), each image's PSNR against 8 x 8 rays per pixel. The crate
/// fails unless the cone's image gains at least 6 dB at both sizes and its marked lines (what cone
/// LOD adds or changes) are at most 20; it prints both.
#[test]
fn textured_ray_tracer_gains_from_cone_lod() {
    run_together(
        "textured-ray-tracer",
        &["cone LOD takes", "320 x 240: PSNR", "480 x 360: PSNR"],
    );
}

/// A Bevy user: `#import ray_footprint::ray_cone::...` through naga_oil, validated by naga.
#[test]
fn naga_oil_composes_the_modules() {
    run_together("naga-oil", &["composed with naga_oil, validated by naga"]);
}

/// A Vulkan user: a closest-hit shader `#include`s the GLSL modules through the include directory
/// the crate exports to dependents' build scripts (`DEP_RAY_FOOTPRINT_GLSL_INCLUDE`, from
/// `links`), compiled by glslang, accepted by spirv-val. The crate checks that directory against
/// `GLSL_INCLUDE_DIR` and the embedded modules and prints it: it must lie in the package.
#[test]
fn glsl_build_script_compiles_a_closest_hit_shader() {
    run_together(
        "glsl-build-script",
        &["accepted by spirv-val", &package_modules("GLSL")],
    );
}

/// A Vulkan user writing Slang: a compute shader `import`s the Slang ray-cone module through the
/// directory the crate exports to dependents' build scripts (`DEP_RAY_FOOTPRINT_SLANG_INCLUDE`),
/// compiled by slangc, run on lavapipe with the validation layer on and checked against the
/// mirror. The crate checks that directory against `SLANG_INCLUDE_DIR` and prints it: it must lie
/// in the package.
#[test]
fn slang_build_script_compiles_a_compute_shader() {
    run_together(
        "slang-build-script",
        &["cases agree with the mirror", &package_modules("Slang")],
    );
}

/// A Vulkan user writing HLSL: a compute shader `#include`s the HLSL ray-differential module
/// through the directory the crate exports to dependents' build scripts
/// (`DEP_RAY_FOOTPRINT_HLSL_INCLUDE`, checked against `HLSL_INCLUDE_DIR`), compiled by glslang's HLSL
/// front end, run on lavapipe with the validation layer on, its eye rays (from glam's matrices in
/// HLSL float4x4s) checked against the mirror.
#[test]
fn hlsl_build_script_compiles_a_compute_shader() {
    run_together(
        "hlsl-build-script",
        &["eye rays agree with the mirror", &package_modules("HLSL")],
    );
}

/// A CPU path tracer: the Rust mirror alone, default features, no Vulkan; built alone, so that
/// no other crate's features reach it.
#[test]
fn cpu_path_tracer_uses_the_mirror_alone() {
    let (_, workspace) = built();
    let mut command = Command::new(env!("CARGO"));
    command
        .args(["run", "--quiet", "--manifest-path"])
        .arg(workspace.join("cpu-path-tracer/Cargo.toml"))
        .arg("--target-dir")
        .arg(work_dir().join("target"));
    stdout_of(command, &["ground rows"]);
}

/// A user of the harness: their own WGSL, GLSL and Slang functions checked against their own Rust
/// functions with shader-proptest, alone and beside ray-footprint's ray-cone module
/// (`Shader::with_source`), as an outside crate's tests, on lavapipe.
#[test]
fn shader_proptest_checks_a_users_functions() {
    let (_, workspace) = built();
    let command = cargo_together(workspace, &["test", "--test", "agreement"]);
    stdout_of(command, &["test result: ok. 3 passed"]);
}
