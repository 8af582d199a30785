//! Bad command-line options of the examples (`verify`, `gallery`, `quality`, `path_image`): each must stop the
//! program before it opens a device, with exit status 2 and a first line on stderr that names the
//! option and the value received. The table of what was tried is rendered into the lab README's "Bad
//! input" section; regenerate it with
//! `RAY_FOOTPRINT_BLESS=1 cargo test --release -p ray-footprint-lab --test options`.
//!
//! Cargo builds the examples next to the test binaries (`target/<profile>/examples/`) whenever it
//! builds this test.

#[path = "../../../tests/common/mod.rs"]
mod common;

use common::assert_generated_block;
use std::fmt::Write;
use std::path::PathBuf;
use std::process::Command;

/// The README's markers around the rendered table.
const START: &str = "<!-- example options: start -->";
const END: &str = "<!-- example options: end -->";

/// One bad option: the example, its arguments and the texts its message must contain.
struct Case {
    example: &'static str,
    args: &'static [&'static str],
    names: &'static [&'static str],
}

/// A [`Case`], one line of [`CASES`].
const fn case(example: &'static str, args: &'static [&'static str], names: &'static [&'static str]) -> Case {
    Case { example, args, names }
}

const CASES: &[Case] = &[
    case("verify", &["--cases", "0"], &["--cases", "'0'"]),
    case("verify", &["--cases", "many"], &["--cases", "'many'"]),
    case("verify", &["--batch", "-1"], &["--batch", "'-1'"]),
    case("verify", &["--cases"], &["--cases"]),
    case("verify", &["--seed", "7"], &["'--seed'"]),
    case("gallery", &["--width", "0"], &["--width", "'0'"]),
    case("gallery", &["--height", "99999999"], &["--height", "'99999999'"]),
    case("gallery", &["--mode", "sharp"], &["mode", "'sharp'"]),
    case("gallery", &["--out", ""], &["--out"]),
    case("gallery", &["--width"], &["--width"]),
    case("gallery", &["--fast"], &["'--fast'"]),
    case("quality", &["--width", "0"], &["--width", "'0'"]),
    case("quality", &["--height", "abc"], &["--height", "'abc'"]),
    case("quality", &["--samples", "0"], &["--samples", "'0'"]),
    case("quality", &["--frames", "1"], &["--frames", "'1'"]),
    case("quality", &["--scene", "moon"], &["scene", "'moon'"]),
    case("quality", &["--out", ""], &["--out"]),
    case("quality", &["--truth"], &["'--truth'"]),
    case("path_image", &["--spread", "pupil"], &["--spread", "'pupil'"]),
    case("path_image_gpu", &["--offsets", "each"], &["--offsets", "'each'"]),
];

/// The folder cargo put the examples in: beside the `deps/` folder holding this test.
fn examples_dir() -> PathBuf {
    let test = std::env::current_exe().expect("the test's path");
    let profile = test
        .parent()
        .and_then(|deps| deps.parent())
        .expect("target/<profile>/deps");
    profile.join("examples")
}

/// Runs one case; the first line of stderr, or why the case failed.
fn run(case: &Case) -> Result<String, String> {
    let program = examples_dir().join(case.example);
    let output = Command::new(&program)
        .args(case.args)
        .current_dir(std::env::temp_dir())
        .output()
        .map_err(|error| format!("{}: {error}", program.display()))?;
    let stderr = String::from_utf8_lossy(&output.stderr);
    let first_line = stderr.lines().next().unwrap_or_default().to_string();
    if output.status.code() != Some(2) {
        return Err(format!(
            "exit status {:?}, stderr: {stderr}",
            output.status.code()
        ));
    }
    let missing: Vec<_> = case
        .names
        .iter()
        .filter(|name| !first_line.contains(*name))
        .collect();
    if !missing.is_empty() {
        return Err(format!("the message leaves out {missing:?}: {first_line}"));
    }
    Ok(first_line)
}

/// The README's table: example, arguments, the first line of the message.
fn render(rows: &[(&Case, String)]) -> String {
    let mut table = String::from("| example | arguments | message |\n| --- | --- | --- |\n");
    for (case, message) in rows {
        let args: Vec<String> = case.args.iter().map(|arg| format!("`{arg}`")).collect();
        let args = if args.iter().any(|arg| arg == "``") {
            args.join(" ").replace("``", "`\"\"`")
        } else {
            args.join(" ")
        };
        writeln!(
            table,
            "| `{}` | {args} | {} |",
            case.example,
            message.replace('|', "\\|")
        )
        .expect("a String");
    }
    table
}

#[test]
fn bad_options_are_refused_by_name() {
    let mut rows = Vec::new();
    let mut failures = Vec::new();
    for case in CASES {
        match run(case) {
            Ok(message) => rows.push((case, message)),
            Err(why) => failures.push(format!("{} {:?}: {why}", case.example, case.args)),
        }
    }
    println!(
        "{} bad options tried, {} refused by name",
        CASES.len(),
        rows.len()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("README.md");
    let block = format!("\n{}", render(&rows));
    assert_generated_block(
        &path,
        START,
        END,
        &block,
        "the README's table of bad example options",
    );
}
