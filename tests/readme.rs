//! Every fenced block of the README and of the lab's README is compiled or checked, so that an
//! example that rots fails here: WGSL blocks are validated by naga after every module, GLSL and HLSL
//! blocks are compiled by glslangValidator (HLSL with `-D`) and Slang blocks by slangc, each with the
//! crate's include directory; shell blocks must name files, packages, examples, benches and tests
//! that exist, and the README's test command must be the one `.ci/run` runs; TOML blocks must name
//! this crate at its version. Rust blocks are doc tests (`src/lib.rs` includes the README, the lab's
//! `lib.rs` its README). Every relative link must lead to a file, and every `#anchor` to a heading.
//! A block of any other language fails; output and listings are marked `text`.

use ray_footprint::shaders::{wgsl_prelude, Module, GLSL_INCLUDE_DIR, HLSL_INCLUDE_DIR, SLANG_INCLUDE_DIR};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The READMEs, relative to the repository root.
const READMES: [&str; 2] = ["README.md", "crates/ray-footprint-lab/README.md"];

/// The info strings' first words this test knows, each checked by one test below.
const LANGUAGES: [&str; 8] = ["rust", "wgsl", "glsl", "slang", "hlsl", "sh", "toml", "text"];

/// A fenced code block.
struct Block {
    /// Where it starts: `README.md:23`.
    place: String,
    /// The info string's first word (`glsl` of "glsl rchit").
    language: String,
    /// The info string's second word, if any (`rchit`).
    stage: Option<String>,
    text: String,
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn read(readme: &str) -> String {
    let path = root().join(readme);
    std::fs::read_to_string(&path).unwrap_or_else(|error| panic!("{}: {error}", path.display()))
}

/// The fenced blocks of every README, in order.
fn blocks() -> Vec<Block> {
    let mut blocks = Vec::new();
    for readme in READMES {
        let text = read(readme);
        let mut open: Option<Block> = None;
        for (index, line) in text.lines().enumerate() {
            match (&mut open, line.strip_prefix("```")) {
                (None, Some(info)) => {
                    let mut words = info.split([' ', ',']).filter(|word| !word.is_empty());
                    open = Some(Block {
                        place: format!("{readme}:{}", index + 1),
                        language: words.next().unwrap_or_default().to_string(),
                        stage: words.next().map(str::to_string),
                        text: String::new(),
                    });
                }
                (Some(_), Some("")) => blocks.push(open.take().expect("an open block")),
                (Some(block), _) => {
                    block.text.push_str(line);
                    block.text.push('\n');
                }
                (None, None) => {}
            }
        }
        assert!(open.is_none(), "{readme}: a code block is not closed");
    }
    blocks
}

/// The blocks in `language`; fails when there is none, so that no check passes on nothing.
fn blocks_in(language: &str) -> Vec<Block> {
    let found: Vec<Block> = blocks()
        .into_iter()
        .filter(|block| block.language == language)
        .collect();
    assert!(!found.is_empty(), "no {language} block in the READMEs");
    println!("{} {language} blocks", found.len());
    found
}

/// Writes `text` to a file named `name` in a folder of this test's own and returns its path.
fn scratch_file(name: &str, text: &str) -> PathBuf {
    let folder = Path::new(env!("CARGO_TARGET_TMPDIR")).join("readme");
    std::fs::create_dir_all(&folder).expect("creating the scratch folder");
    let path = folder.join(name);
    std::fs::write(&path, text).expect("writing a block");
    path
}

/// Runs a compiler and fails with the block's place and the compiler's output unless it succeeds
/// without `forbidden` in its output.
fn assert_compiles(block: &Block, command: &mut Command, forbidden: &str) {
    let output = command.output().unwrap_or_else(|error| {
        panic!(
            "{}: {command:?} does not run ({error}); scripts/setup.sh installs it",
            block.place
        )
    });
    let log = format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(
        output.status.success() && (forbidden.is_empty() || !log.contains(forbidden)),
        "{}: {command:?} fails:\n{log}\n{}",
        block.place,
        block.text
    );
}

#[test]
fn every_block_has_a_known_language() {
    for block in blocks() {
        assert!(
            LANGUAGES.contains(&block.language.as_str()),
            "{}: a block in '{}', which no test checks (mark output `text`)",
            block.place,
            block.language
        );
    }
}

#[test]
fn wgsl_blocks_validate_after_every_module() {
    let capabilities = Module::ALL
        .iter()
        .fold(naga::valid::Capabilities::empty(), |all, module| {
            all | module.naga_capabilities()
        });
    for block in blocks_in("wgsl") {
        let source = format!("{}{}", wgsl_prelude(Module::ALL), block.text);
        let module = naga::front::wgsl::parse_str(&source)
            .unwrap_or_else(|error| panic!("{}: {}", block.place, error.emit_to_string(&source)));
        naga::valid::Validator::new(naga::valid::ValidationFlags::all(), capabilities)
            .validate(&module)
            .unwrap_or_else(|error| panic!("{}: {}", block.place, error.emit_to_string(&source)));
    }
}

/// Compiles every block in `language` with glslangValidator: `front_end` and the block's stage
/// (`comp` unless its info string names another), the include directory `include`.
fn compile_with_glslang(language: &str, front_end: &[&str], include: &str, forbidden: &str) {
    for (index, block) in blocks_in(language).iter().enumerate() {
        let stage = block.stage.as_deref().unwrap_or("comp");
        let input = scratch_file(&format!("block{index}.{stage}.{language}"), &block.text);
        let mut command = Command::new("glslangValidator");
        command
            .args(front_end)
            .args(["-S", stage])
            .arg(format!("-I{include}"))
            .arg("-o")
            .arg(input.with_extension("spv"))
            .arg(&input);
        assert_compiles(block, &mut command, forbidden);
    }
}

#[test]
fn glsl_blocks_compile_with_glslang() {
    compile_with_glslang("glsl", &["-V", "--target-env", "vulkan1.2"], GLSL_INCLUDE_DIR, "");
}

#[test]
fn hlsl_blocks_compile_with_glslang() {
    // glslang reports some HLSL it cannot translate ("Missing functionality") and succeeds.
    let front_end = ["-D", "-V", "--target-env", "vulkan1.1", "-e", "main"];
    compile_with_glslang("hlsl", &front_end, HLSL_INCLUDE_DIR, "Missing functionality");
}

#[test]
fn slang_blocks_compile_with_slangc() {
    for (index, block) in blocks_in("slang").iter().enumerate() {
        let input = scratch_file(&format!("block{index}.slang"), &block.text);
        let mut command = Command::new("slangc");
        command
            .arg(&input)
            .args(["-target", "spirv", "-O0", "-I", SLANG_INCLUDE_DIR, "-o"])
            .arg(input.with_extension("spv"));
        assert_compiles(block, &mut command, "");
    }
}

/// The workspace's packages: `(name, folder)`.
fn packages() -> Vec<(String, PathBuf)> {
    let manifest = std::fs::read_to_string(root().join("Cargo.toml")).expect("the workspace's Cargo.toml");
    let members = manifest
        .lines()
        .find_map(|line| line.strip_prefix("members = "))
        .expect("the workspace's members");
    members
        .split('"')
        .skip(1)
        .step_by(2)
        .map(|member| {
            let folder = root().join(member);
            let manifest = std::fs::read_to_string(folder.join("Cargo.toml")).expect("a member's Cargo.toml");
            let name = manifest
                .lines()
                .find_map(|line| line.strip_prefix("name = "))
                .expect("a package name")
                .trim_matches('"')
                .to_string();
            (name, folder)
        })
        .collect()
}

/// Whether `folder/kind` holds the target `name`, as `name.rs` or `name/main.rs`.
fn has_target(folder: &Path, kind: &str, name: &str) -> bool {
    let folder = folder.join(kind);
    folder.join(format!("{name}.rs")).is_file() || folder.join(name).join("main.rs").is_file()
}

/// Checks one shell command line: every path names a file of the repository, every `-p` a package
/// of the workspace, and every `--example`, `--bench` and `--test` a target of that package.
fn check_command(place: &str, line: &str, packages: &[(String, PathBuf)]) {
    let words: Vec<&str> = line.split_whitespace().collect();
    let mut folder = root();
    for (index, word) in words.iter().enumerate() {
        let value = words.get(index + 1).copied().unwrap_or_default();
        match *word {
            "-p" => {
                let package = packages.iter().find(|(name, _)| name == value);
                folder = package
                    .unwrap_or_else(|| panic!("{place}: no package '{value}' in the workspace"))
                    .1
                    .clone();
            }
            "--example" | "--bench" | "--test" => {
                let kind = format!("{}s", word.trim_start_matches('-'));
                let kind = if kind == "benchs" {
                    "benches".to_string()
                } else {
                    kind
                };
                assert!(
                    has_target(&folder, &kind, value),
                    "{place}: no {kind}/{value} in {}",
                    folder.display()
                );
            }
            _ if word.contains('/') && !word.starts_with('-') && !word.contains('=') => {
                assert!(
                    root().join(word).exists(),
                    "{place}: no file '{word}' in the repository"
                );
            }
            _ => {}
        }
    }
}

#[test]
fn shell_blocks_name_real_files_packages_and_targets() {
    let packages = packages();
    let mut commands = 0;
    for block in blocks_in("sh") {
        for line in block.text.lines() {
            let command = line.split(" #").next().unwrap_or_default();
            if command.trim().is_empty() || command.trim_start().starts_with('#') {
                continue;
            }
            for part in command.split("&&") {
                check_command(&block.place, part, &packages);
                commands += 1;
            }
        }
    }
    println!("{commands} commands checked");
}

#[test]
fn the_readme_test_command_is_the_one_ci_runs() {
    let ci = std::fs::read_to_string(root().join(".ci/run")).expect(".ci/run");
    let readme = read("README.md");
    let command = readme
        .lines()
        .find(|line| line.starts_with("scripts/setup.sh && cargo test"))
        .expect("the README's test command");
    assert!(
        ci.lines().any(|line| line == command),
        "the README's test command '{command}' is not in .ci/run"
    );
}

#[test]
fn toml_blocks_name_this_crate_at_its_version() {
    let version = env!("CARGO_PKG_VERSION");
    let major_minor: String = version.split('.').take(2).collect::<Vec<_>>().join(".");
    for block in blocks_in("toml") {
        let line = block
            .text
            .lines()
            .find(|line| line.starts_with("ray-footprint = "))
            .unwrap_or_else(|| panic!("{}: no ray-footprint dependency", block.place));
        assert!(
            line.contains(&format!("\"{major_minor}\"")),
            "{}: '{line}' does not ask for version {major_minor} ({version})",
            block.place
        );
    }
}

/// GitHub's anchor of a heading: lower case, punctuation other than `-` and `_` dropped, spaces as
/// hyphens.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter(|c| c.is_alphanumeric() || matches!(c, ' ' | '-' | '_'))
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// The anchors of a Markdown file's headings outside code blocks.
fn anchors(text: &str) -> Vec<String> {
    let mut in_code = false;
    let mut found = Vec::new();
    for line in text.lines() {
        if line.starts_with("```") {
            in_code = !in_code;
        } else if !in_code && line.starts_with('#') {
            found.push(anchor(line.trim_start_matches('#')));
        }
    }
    found
}

#[test]
fn relative_links_and_anchors_resolve() {
    let mut links = 0;
    for readme in READMES {
        let text = read(readme);
        let folder = root().join(readme).parent().expect("a folder").to_path_buf();
        for target in text.split("](").skip(1).filter_map(|rest| rest.split(')').next()) {
            if target.starts_with("http") {
                continue;
            }
            let (file, fragment) = target.split_once('#').unwrap_or((target, ""));
            let path = if file.is_empty() {
                root().join(readme)
            } else {
                folder.join(file)
            };
            assert!(path.exists(), "{readme}: the link '{target}' leads nowhere");
            if !fragment.is_empty() {
                let linked = std::fs::read_to_string(&path).expect("a Markdown file");
                assert!(
                    anchors(&linked).iter().any(|a| a == fragment),
                    "{readme}: no heading for '{target}'"
                );
            }
            links += 1;
        }
    }
    println!("{links} links resolve");
}
