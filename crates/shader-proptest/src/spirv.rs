//! What a SPIR-V module costs: its instructions inside functions, its branches, and its calls of
//! extended instructions (the `GLSL.std.450` set), read from the words; and `spirv-opt -O`
//! (SPIRV-Tools), so that modules from different compilers are compared after the same
//! optimisation; and `spirv-val`, for modules that no device runs.
//!
//! ```no_run
//! use shader_proptest::{spirv, Shader};
//!
//! let shader = Shader::wgsl("fn f(x: f32) -> f32 { return sin(x); }");
//! # let kernel = String::new();
//! let words = spirv::optimize(&shader.compile_kernel(&kernel)?)?;
//! println!("{}", spirv::Statistics::of(&words)?);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::tool::{tool_succeeded, CompileError, Target};
use std::fmt;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The first word of every SPIR-V module.
pub(crate) const MAGIC: u32 = 0x0723_0203;
/// Words in the module header (magic, version, generator, bound, schema).
const HEADER_WORDS: usize = 5;
/// `OpSource`, and the source-language values Slang writes in it and the one written instead.
const OP_SOURCE: u32 = 3;
const SOURCE_LANGUAGE_SLANG: u32 = 11;
const SOURCE_LANGUAGE_UNKNOWN: u32 = 0;

/// Opcodes the statistics look at (SPIR-V specification, section 3.52).
const OP_EXT_INST_IMPORT: u16 = 11;
const OP_EXT_INST: u16 = 12;
const OP_FUNCTION: u16 = 54;
const OP_FUNCTION_END: u16 = 56;
const OP_BRANCH_CONDITIONAL: u16 = 250;
const OP_SWITCH: u16 = 251;

/// The extended-instruction set whose calls are classified.
const GLSL_STD_450: &str = "GLSL.std.450";

/// The `GLSL.std.450` instructions counted as transcendental: the trigonometric, hyperbolic,
/// power, exponential and logarithmic functions and the square roots (numbers 13 to 32 of the
/// set). `Length`, `Distance` and `Normalize`, which take a square root inside, are counted as
/// extended calls only.
pub const TRANSCENDENTAL: [(u32, &str); 20] = [
    (13, "Sin"),
    (14, "Cos"),
    (15, "Tan"),
    (16, "Asin"),
    (17, "Acos"),
    (18, "Atan"),
    (19, "Sinh"),
    (20, "Cosh"),
    (21, "Tanh"),
    (22, "Asinh"),
    (23, "Acosh"),
    (24, "Atanh"),
    (25, "Atan2"),
    (26, "Pow"),
    (27, "Exp"),
    (28, "Log"),
    (29, "Exp2"),
    (30, "Log2"),
    (31, "Sqrt"),
    (32, "InverseSqrt"),
];

/// Counts of one SPIR-V module, over the instructions inside its functions.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Statistics {
    /// Instructions from each `OpFunction` to its `OpFunctionEnd`, both included.
    pub instructions: usize,
    /// `OpBranchConditional` instructions.
    pub conditional_branches: usize,
    /// `OpSwitch` instructions.
    pub switches: usize,
    /// `OpExtInst` instructions (calls of any extended-instruction set).
    pub extended_calls: usize,
    /// `OpExtInst` calls of a [`TRANSCENDENTAL`] instruction of `GLSL.std.450`.
    pub transcendental_calls: usize,
}

/// Why words are not a SPIR-V module the reader understands.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SpirvError {
    /// The module is shorter than its header.
    Truncated {
        /// The module's length in words.
        words: usize,
    },
    /// The first word is not the SPIR-V magic number.
    Magic(u32),
    /// The module's bytes are not a whole number of words.
    Length {
        /// The module's length in bytes.
        bytes: usize,
    },
    /// An instruction's word count is zero or runs past the end of the module.
    Instruction {
        /// Where the instruction starts, in words.
        offset: usize,
        /// Its word count.
        word_count: usize,
    },
}

impl fmt::Display for SpirvError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SpirvError::Truncated { words } => {
                write!(f, "a SPIR-V module of {words} words is shorter than its header")
            }
            SpirvError::Magic(word) => write!(f, "magic number {word:#010x} is not SPIR-V's {MAGIC:#010x}"),
            SpirvError::Length { bytes } => write!(f, "{bytes} bytes are not a whole number of 4-byte words"),
            SpirvError::Instruction { offset, word_count } => write!(
                f,
                "the instruction at word {offset} has a word count of {word_count}, which does not fit the module"
            ),
        }
    }
}

impl std::error::Error for SpirvError {}

impl Statistics {
    /// The counts of the module `words`.
    pub fn of(words: &[u32]) -> Result<Statistics, SpirvError> {
        let mut statistics = Statistics::default();
        let mut glsl_sets = Vec::new();
        let mut inside_function = false;
        for instruction in instructions(words)? {
            let (opcode, operands) = (instruction[0] as u16, &instruction[1..]);
            inside_function |= opcode == OP_FUNCTION;
            if inside_function {
                statistics.instructions += 1;
            }
            if opcode == OP_EXT_INST_IMPORT && literal_string(&operands[1..]) == GLSL_STD_450 {
                glsl_sets.push(operands[0]);
            }
            if !inside_function {
                continue;
            }
            match opcode {
                OP_EXT_INST => {
                    statistics.extended_calls += 1;
                    let (set, number) = (operands[2], operands[3]);
                    if glsl_sets.contains(&set) && TRANSCENDENTAL.iter().any(|&(n, _)| n == number) {
                        statistics.transcendental_calls += 1;
                    }
                }
                OP_FUNCTION_END => inside_function = false,
                OP_BRANCH_CONDITIONAL => statistics.conditional_branches += 1,
                OP_SWITCH => statistics.switches += 1,
                _ => {}
            }
        }
        Ok(statistics)
    }
}

impl fmt::Display for Statistics {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} instructions in functions, {} conditional branches, {} switches, {} extended calls ({} transcendental)",
            self.instructions,
            self.conditional_branches,
            self.switches,
            self.extended_calls,
            self.transcendental_calls
        )
    }
}

/// The words of a SPIR-V module stored as bytes, each word little-endian (a compiler's output file,
/// or one that `include_bytes!` embeds), once its header is checked.
///
/// ```
/// use shader_proptest::spirv;
///
/// let header = [0x0723_0203u32, 0x0001_0300, 0, 1, 0];
/// let bytes: Vec<u8> = header.iter().flat_map(|word| word.to_le_bytes()).collect();
/// assert_eq!(spirv::from_bytes(&bytes), Ok(header.to_vec()));
/// assert!(spirv::from_bytes(&bytes[..19]).is_err());
/// ```
pub fn from_bytes(bytes: &[u8]) -> Result<Vec<u32>, SpirvError> {
    if !bytes.len().is_multiple_of(4) {
        return Err(SpirvError::Length { bytes: bytes.len() });
    }
    let words: Vec<u32> = bytes
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    check_header(&words)?;
    Ok(words)
}

/// Sets the source language of every `OpSource` instruction that names Slang to Unknown. SPIR-V
/// tools older than Slang's enumerant (11), such as Debian 12's SPIRV-Tools 2023.1 and Vulkan
/// validation layer 1.3.239, reject a module that names it; newer ones need no such change.
/// Nothing else in the module changes. [`crate::compile::compile_slang`] does it to what slangc
/// writes; a build script that runs slangc itself leaves it to the program that loads the module.
pub fn without_slang_source_language(words: &mut [u32]) {
    let mut at = HEADER_WORDS;
    while at < words.len() {
        let count = (words[at] >> 16) as usize;
        if words[at] & 0xffff == OP_SOURCE && words.get(at + 1) == Some(&SOURCE_LANGUAGE_SLANG) {
            words[at + 1] = SOURCE_LANGUAGE_UNKNOWN;
        }
        at += count.max(1);
    }
}

/// An error where `words` are shorter than a header or do not start with the magic number.
fn check_header(words: &[u32]) -> Result<(), SpirvError> {
    match words.first() {
        _ if words.len() < HEADER_WORDS => Err(SpirvError::Truncated { words: words.len() }),
        Some(&word) if word != MAGIC => Err(SpirvError::Magic(word)),
        _ => Ok(()),
    }
}

/// The module's instructions after the header, each as its words (opcode word first).
fn instructions(words: &[u32]) -> Result<Vec<&[u32]>, SpirvError> {
    check_header(words)?;
    let mut list = Vec::new();
    let mut offset = HEADER_WORDS;
    while offset < words.len() {
        let word_count = (words[offset] >> 16) as usize;
        if word_count == 0 || offset + word_count > words.len() {
            return Err(SpirvError::Instruction { offset, word_count });
        }
        list.push(&words[offset..offset + word_count]);
        offset += word_count;
    }
    Ok(list)
}

/// A SPIR-V literal string: UTF-8 bytes packed little-endian into words, ended by a zero byte.
pub(crate) fn literal_string(words: &[u32]) -> String {
    let bytes: Vec<u8> = words
        .iter()
        .flat_map(|word| word.to_le_bytes())
        .take_while(|&byte| byte != 0)
        .collect();
    String::from_utf8_lossy(&bytes).into_owned()
}

/// The module `words` after `spirv-opt -O` (SPIRV-Tools' size-neutral performance passes, which
/// inline every function into the entry points). Needs `spirv-opt` on the `PATH`.
pub fn optimize(words: &[u32]) -> Result<Vec<u32>, CompileError> {
    let stem = temporary_stem("opt");
    let (input, output) = (stem.with_extension("in.spv"), stem.with_extension("out.spv"));
    write_module(&input, words)?;
    let result = Command::new("spirv-opt")
        .arg("-O")
        .arg(&input)
        .arg("-o")
        .arg(&output)
        .output();
    let bytes = std::fs::read(&output);
    let _ = std::fs::remove_file(&input);
    let _ = std::fs::remove_file(&output);
    let result = result.map_err(|e| {
        CompileError::NotRun(format!(
            "cannot run spirv-opt (SPIRV-Tools, Debian package spirv-tools): {e}"
        ))
    })?;
    tool_output("spirv-opt", &result, bytes, "spirv-opt -O: ", &input)
}

/// Whether `spirv-val` accepts the module `words` for `target`'s Vulkan version: `Failed` with its
/// log where it rejects them. Needs `spirv-val` on the `PATH`.
///
/// ```no_run
/// use shader_proptest::compile::Target;
/// use shader_proptest::spirv;
///
/// # let words: Vec<u32> = Vec::new();
/// spirv::validate(&words, Target::Vulkan1_1)?;
/// # Ok::<(), shader_proptest::CompileError>(())
/// ```
pub fn validate(words: &[u32], target: Target) -> Result<(), CompileError> {
    let input = temporary_stem("val").with_extension("spv");
    write_module(&input, words)?;
    let result = Command::new("spirv-val")
        .args(["--target-env", target.glslang_env()])
        .arg(&input)
        .output();
    let _ = std::fs::remove_file(&input);
    let result = result.map_err(|e| {
        CompileError::NotRun(format!(
            "cannot run spirv-val (SPIRV-Tools, Debian package spirv-tools): {e}"
        ))
    })?;
    tool_succeeded(&result, "spirv-val: ", &input)
}

/// The SPIR-V words that the command-line tool `tool` wrote to its output file (`written`, as read
/// back), or, when the tool failed, its log (`log_prefix`, then stdout and stderr) naming `input`.
pub(crate) fn tool_output(
    tool: &str,
    run: &Output,
    written: std::io::Result<Vec<u8>>,
    log_prefix: &str,
    input: &Path,
) -> Result<Vec<u32>, CompileError> {
    tool_succeeded(run, log_prefix, input)?;
    let bytes = written.map_err(|e| CompileError::NotRun(format!("reading {tool}'s output: {e}")))?;
    from_bytes(&bytes).map_err(|e| CompileError::NotRun(format!("{tool}'s output: {e}")))
}

/// A path in the temporary directory that no other call of this process uses, for `job`'s files.
fn temporary_stem(job: &str) -> PathBuf {
    static COUNTER: AtomicUsize = AtomicUsize::new(0);
    std::env::temp_dir().join(format!(
        "shader-proptest-{job}-{}-{}",
        std::process::id(),
        COUNTER.fetch_add(1, Ordering::Relaxed)
    ))
}

/// Writes the module `words` to `path` as a SPIR-V file.
fn write_module(path: &Path, words: &[u32]) -> Result<(), CompileError> {
    std::fs::write(path, to_bytes(words))
        .map_err(|e| CompileError::NotRun(format!("writing {}: {e}", path.display())))
}

/// The little-endian bytes of `words`, as SPIR-V files hold them.
fn to_bytes(words: &[u32]) -> Vec<u8> {
    words.iter().flat_map(|word| word.to_le_bytes()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One instruction: the word count and opcode, then the operands.
    fn instruction(opcode: u16, operands: &[u32]) -> Vec<u32> {
        let mut words = vec![((operands.len() as u32 + 1) << 16) | u32::from(opcode)];
        words.extend_from_slice(operands);
        words
    }

    /// A literal string as words.
    fn string(text: &str) -> Vec<u32> {
        let mut bytes = text.as_bytes().to_vec();
        bytes.resize(text.len() / 4 * 4 + 4, 0);
        bytes
            .chunks_exact(4)
            .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
            .collect()
    }

    /// A module with two extended-instruction sets and one function of 12 instructions: two
    /// `GLSL.std.450` calls (Sin, a transcendental, and FAbs, which is not), one call of number 13
    /// in another set (not Sin there), a conditional branch and a switch. Outside the function:
    /// one more `GLSL.std.450` Sqrt (a made-up position), which is not counted.
    fn hand_built() -> Vec<u32> {
        let mut words = vec![MAGIC, 0x0001_0300, 0, 20, 0];
        let mut push = |opcode: u16, operands: &[u32]| words.extend(instruction(opcode, operands));
        push(17, &[1]); // OpCapability Shader
        push(
            OP_EXT_INST_IMPORT,
            &[[1].as_slice(), &string(GLSL_STD_450)].concat(),
        );
        push(
            OP_EXT_INST_IMPORT,
            &[[2].as_slice(), &string("NonSemantic.Example")].concat(),
        );
        push(OP_EXT_INST, &[3, 4, 1, 31, 5]); // Sqrt outside any function
        push(OP_FUNCTION, &[6, 7, 0, 8]);
        push(248, &[9]); // OpLabel
        push(OP_EXT_INST, &[3, 10, 1, 13, 5]); // Sin
        push(OP_EXT_INST, &[3, 11, 1, 4, 10]); // FAbs
        push(OP_EXT_INST, &[3, 12, 2, 13, 11]); // number 13 of the other set
        push(OP_BRANCH_CONDITIONAL, &[13, 14, 15]);
        push(248, &[14]);
        push(OP_SWITCH, &[16, 15, 1, 17]);
        push(248, &[15]);
        push(248, &[17]);
        push(253, &[]); // OpReturn
        push(OP_FUNCTION_END, &[]);
        words
    }

    #[test]
    fn counts_a_hand_built_module() {
        let statistics = Statistics::of(&hand_built()).expect("a valid module");
        assert_eq!(
            statistics,
            Statistics {
                instructions: 12,
                conditional_branches: 1,
                switches: 1,
                extended_calls: 3,
                transcendental_calls: 1,
            }
        );
    }

    #[test]
    fn malformed_modules_are_errors() {
        assert_eq!(Statistics::of(&[MAGIC]), Err(SpirvError::Truncated { words: 1 }));
        assert_eq!(Statistics::of(&[1, 0, 0, 0, 0]), Err(SpirvError::Magic(1)));
        let complete = hand_built();
        let mut cut = complete.clone();
        cut.extend([(5 << 16) | u32::from(OP_EXT_INST), 3]);
        let past_the_end = SpirvError::Instruction {
            offset: complete.len(),
            word_count: 5,
        };
        assert_eq!(Statistics::of(&cut), Err(past_the_end));
        let mut empty = complete.clone();
        empty.push(u32::from(OP_EXT_INST));
        let zero_words = SpirvError::Instruction {
            offset: complete.len(),
            word_count: 0,
        };
        assert_eq!(Statistics::of(&empty), Err(zero_words));
    }

    /// Bytes of a module are its words, little-endian; bytes that are not whole words or not a
    /// module's header are errors.
    #[test]
    fn bytes_are_read_as_little_endian_words() {
        let module = hand_built();
        let bytes: Vec<u8> = module.iter().flat_map(|word| word.to_le_bytes()).collect();
        assert_eq!(bytes[..4], [0x03, 0x02, 0x23, 0x07]);
        assert_eq!(from_bytes(&bytes), Ok(module));
        assert_eq!(from_bytes(&bytes[..21]), Err(SpirvError::Length { bytes: 21 }));
        assert_eq!(from_bytes(&bytes[..16]), Err(SpirvError::Truncated { words: 4 }));
        assert_eq!(from_bytes(&bytes[4..24]), Err(SpirvError::Magic(0x0001_0300)));
    }

    /// Only the source-language operand of an `OpSource` that names Slang changes.
    #[test]
    fn slang_source_language_becomes_unknown() {
        let mut module = vec![MAGIC, 0x0001_0300, 0, 20, 0];
        module.extend(instruction(OP_SOURCE as u16, &[SOURCE_LANGUAGE_SLANG, 1]));
        module.extend(instruction(OP_SOURCE as u16, &[2, 450]));
        module.extend(instruction(OP_EXT_INST_IMPORT, &[SOURCE_LANGUAGE_SLANG]));
        let mut expected = module.clone();
        expected[6] = SOURCE_LANGUAGE_UNKNOWN;
        without_slang_source_language(&mut module);
        assert_eq!(module, expected);
    }

    /// naga's module of a function with one `sin` and one `sqrt` keeps both after `spirv-opt -O`,
    /// which inlines the function into the entry point.
    #[test]
    fn optimised_naga_output_keeps_its_calls() {
        let source = "@group(0) @binding(0) var<storage, read_write> data: array<f32>;
fn wave(x: f32) -> f32 { return sin(x) * sqrt(abs(x)); }
@compute @workgroup_size(1)
fn main() { data[0] = wave(data[0]); }";
        let words = crate::compile::compile_wgsl(
            source,
            "wave.wgsl",
            crate::compile::base_capabilities(),
            crate::compile::Target::Vulkan1_1,
        )
        .expect("valid WGSL");
        let optimized = optimize(&words).unwrap_or_else(|e| panic!("{e}"));
        let (before, after) = (
            Statistics::of(&words).unwrap(),
            Statistics::of(&optimized).unwrap(),
        );
        println!("naga: {before}\nspirv-opt -O: {after}");
        assert_eq!(after.transcendental_calls, 2);
        assert_eq!(after.extended_calls, 3);
        assert!(after.instructions < before.instructions);
    }

    /// `spirv-val` accepts naga's module of a WGSL kernel and rejects the hand-built module, which
    /// declares no memory model.
    #[test]
    fn validate_accepts_a_compiled_kernel_and_rejects_a_module_without_memory_model() {
        let source = "@group(0) @binding(0) var<storage, read_write> data: array<f32>;
@compute @workgroup_size(1)
fn main() { data[0] = 2.0 * data[0]; }";
        let words = crate::compile::compile_wgsl(
            source,
            "double.wgsl",
            crate::compile::base_capabilities(),
            Target::Vulkan1_1,
        )
        .expect("valid WGSL");
        validate(&words, Target::Vulkan1_1).unwrap_or_else(|e| panic!("{e}"));
        match validate(&hand_built(), Target::Vulkan1_1) {
            Err(CompileError::Failed { log, .. }) => assert!(log.starts_with("spirv-val: "), "{log}"),
            other => panic!("spirv-val accepted a module without OpMemoryModel: {other:?}"),
        }
    }
}
