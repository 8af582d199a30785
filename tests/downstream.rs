//! The inclusion paths, proven by downstream crates in `examples/downstream/`: each is built and run
//! as a user would (`cargo run`), with a path dependency on this crate, and checks its own results.
//! The build-script crates are also built against the packaged crate, as crates.io serves it.
//!
//! The downstream crates form a workspace of their own (one lock file); each is built alone, so
//! that it gets the features it asks for, into one target directory, so that the dependencies two
//! crates share with the same features are built once.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// The downstream crate `name` in the repository.
fn repository_crate(name: &str) -> PathBuf {
    Path::new(ROOT).join("examples/downstream").join(name)
}

/// Builds and runs the downstream crate `name` with `cargo run`; it must succeed and print
/// `expected`.
fn run_downstream(name: &str, expected: &str) {
    cargo_downstream("run", &repository_crate(name), expected);
}

/// Runs `cargo <command>` (`run` or `test`) on the downstream crate in `dir`, in the target
/// directory every downstream crate shares; it must succeed and print `expected`. Returns what
/// it printed.
fn cargo_downstream(command: &str, dir: &Path, expected: &str) -> String {
    let name = dir.display();
    let output = Command::new(env!("CARGO"))
        .args([command, "--release", "--quiet", "--manifest-path"])
        .arg(dir.join("Cargo.toml"))
        .arg("--target-dir")
        .arg(Path::new(ROOT).join("target/downstream"))
        .output()
        .unwrap_or_else(|error| panic!("{name}: cannot run cargo: {error}"));
    let stdout = String::from_utf8_lossy(&output.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&output.stderr);
    println!("{name}:\n{stdout}");
    assert!(output.status.success(), "{name} failed:\n{stdout}\n{stderr}");
    assert!(
        stdout.contains(expected),
        "{name} did not print {expected:?}:\n{stdout}"
    );
    stdout
}

/// Runs `command`, which must succeed.
fn run(command: &mut Command) {
    let output = command
        .output()
        .unwrap_or_else(|error| panic!("cannot run {command:?}: {error}"));
    assert!(
        output.status.success(),
        "{command:?} failed:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

/// Packages the working tree as `cargo publish` would (`cargo package` of shader-proptest and
/// ray-footprint: ray-footprint's lock file needs the other's package), unpacks ray-footprint's
/// `.crate` into `work/unpacked` and returns its directory.
fn unpacked_crate(work: &Path) -> PathBuf {
    let cargo_target = work.join("target");
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
    for entry in fs::read_dir(from).expect("reading a downstream crate") {
        let entry = entry.expect("reading a downstream crate");
        let target = to.join(entry.file_name());
        if entry.path().is_dir() {
            if entry.file_name() != "target" {
                copy_tree(&entry.path(), &target);
            }
        } else {
            fs::copy(entry.path(), target).expect("copying a downstream crate");
        }
    }
}

/// The downstream crate `name` copied to `work/users/name` as a workspace of its own (with the
/// downstream workspace's lock file), its ray-footprint dependency on the unpacked `package`
/// (shader-proptest stays the repository's), renamed `packaged-*` so that its binary does not
/// replace the repository build's in the shared target directory.
fn copy_against_package(name: &str, package: &Path, work: &Path) -> PathBuf {
    let copy = work.join("users").join(name);
    let _ = fs::remove_dir_all(&copy);
    copy_tree(&repository_crate(name), &copy);
    let shader_proptest = Path::new(ROOT).join("crates/shader-proptest");
    let manifest = fs::read_to_string(copy.join("Cargo.toml")).expect("reading the manifest");
    assert!(
        manifest.contains("path = \"../../..\""),
        "{name}: no ray-footprint path dependency"
    );
    let manifest = manifest
        .replace(
            "path = \"../../../crates/shader-proptest\"",
            &format!("path = {:?}", shader_proptest.display().to_string()),
        )
        .replace(
            "path = \"../../..\"",
            &format!("path = {:?}", package.display().to_string()),
        )
        + "\n[workspace]\n";
    let lock = fs::read_to_string(Path::new(ROOT).join("examples/downstream/Cargo.lock"))
        .expect("reading the downstream lock file");
    for (file, text) in [("Cargo.toml", manifest), ("Cargo.lock", lock)] {
        fs::write(copy.join(file), text.replace("\"downstream-", "\"packaged-")).expect("rewriting");
    }
    copy
}

/// A wgpu user: the WGSL prelude in a compute shader, validated by wgpu and run through its Vulkan
/// backend on lavapipe, compared with the Rust mirror.
#[test]
fn wgpu_compute_shader_agrees_with_the_mirror() {
    run_downstream("wgpu-compute", "LODs computed by wgpu");
}

/// A Bevy user: `#import ray_footprint::ray_cone::...` through naga_oil, validated by naga.
#[test]
fn naga_oil_composes_the_modules() {
    run_downstream("naga-oil", "composed with naga_oil, validated by naga");
}

/// A Vulkan user: a closest-hit shader `#include`s the GLSL modules through the include directory
/// the crate exports to dependents' build scripts, compiled by glslang, accepted by spirv-val.
#[test]
fn glsl_build_script_compiles_a_closest_hit_shader() {
    run_downstream("glsl-build-script", "accepted by spirv-val");
}

/// A Vulkan user writing Slang: a compute shader `import`s the Slang ray-cone module through the
/// directory the crate exports to dependents' build scripts, compiled by slangc, run on lavapipe
/// with the validation layer on and checked against the mirror.
#[test]
fn slang_build_script_compiles_a_compute_shader() {
    run_downstream("slang-build-script", "cases agree with the mirror");
}

/// A user of the published crate: the GLSL and the Slang build-script crates against the
/// packaged `.crate` of ray-footprint (the working tree through `cargo package`, unpacked outside
/// the repository). Their shaders compile only if the package holds the modules and its build
/// script exports their directories (`DEP_RAY_FOOTPRINT_GLSL_INCLUDE`,
/// `DEP_RAY_FOOTPRINT_SLANG_INCLUDE`, from `links`); each crate checks that directory against
/// the package's `GLSL_INCLUDE_DIR` / `SLANG_INCLUDE_DIR` and prints it, and it must lie in the
/// package.
#[test]
fn build_scripts_compile_against_the_packaged_crate() {
    let work = Path::new(ROOT).join("target/downstream-package");
    let package = unpacked_crate(&work);
    for (name, language, expected) in [
        ("glsl-build-script", "GLSL", "accepted by spirv-val"),
        ("slang-build-script", "Slang", "cases agree with the mirror"),
    ] {
        let stdout = cargo_downstream("run", &copy_against_package(name, &package, &work), expected);
        let directory = package.join("shaders").join(language.to_lowercase());
        let line = format!("{language} modules in {}", directory.display());
        assert!(stdout.contains(&line), "{name} did not print {line:?}:\n{stdout}");
    }
}

/// A CPU path tracer: the Rust mirror alone, default features, no Vulkan.
#[test]
fn cpu_path_tracer_uses_the_mirror_alone() {
    run_downstream("cpu-path-tracer", "ground rows");
}

/// A user of the harness: their own WGSL, GLSL and Slang functions checked against their own Rust
/// functions with shader-proptest, as an outside crate's tests, on lavapipe.
#[test]
fn shader_proptest_checks_a_users_functions() {
    cargo_downstream(
        "test",
        &repository_crate("shader-proptest-user"),
        "test result: ok. 3 passed",
    );
}
