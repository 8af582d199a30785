//! Generated kernels hand every argument type to the shader and every result back as the Rust
//! value means it, in each language: matrices column by column (a transposed matrix would change
//! `m * v`), signed integers and booleans bit for bit. The values are small integers, so every
//! product and sum is exact and the results must be equal bit for bit.

use glam::{Mat2, Mat3, Mat4, Vec2, Vec3, Vec4};
use proptest::prelude::*;
use shader_proptest::{Args, FunctionCheck, Gpu, Language, RunConfig, Shader, Tolerance, Value};

const WGSL: &str = "
fn apply2(m: mat2x2<f32>, v: vec2<f32>) -> vec2<f32> { return m * v; }
fn apply3(m: mat3x3<f32>, v: vec3<f32>) -> vec3<f32> { return m * v; }
fn apply4(m: mat4x4<f32>, v: vec4<f32>) -> vec4<f32> { return m * v; }
fn scale4(m: mat4x4<f32>, s: f32) -> mat4x4<f32> { return m * s; }
fn scale3(m: mat3x3<f32>, s: f32) -> mat3x3<f32> { return m * s; }
fn pick(a: i32, b: i32, first: bool) -> i32 { return select(b, a, first); }
";

const GLSL: &str = "
vec2 apply2(mat2 m, vec2 v) { return m * v; }
vec3 apply3(mat3 m, vec3 v) { return m * v; }
vec4 apply4(mat4 m, vec4 v) { return m * v; }
mat4 scale4(mat4 m, float s) { return m * s; }
mat3 scale3(mat3 m, float s) { return m * s; }
int pick(int a, int b, bool first) { return first ? a : b; }
";

/// Plain HLSL, which slangc also reads as Slang.
const HLSL_AND_SLANG: &str = "
float2 apply2(float2x2 m, float2 v) { return mul(m, v); }
float3 apply3(float3x3 m, float3 v) { return mul(m, v); }
float4 apply4(float4x4 m, float4 v) { return mul(m, v); }
float4x4 scale4(float4x4 m, float s) { return m * s; }
float3x3 scale3(float3x3 m, float s) { return m * s; }
int pick(int a, int b, bool first) { return first ? a : b; }
";

/// Whole numbers in [-8, 8].
fn small() -> impl Strategy<Value = f32> {
    (-8i32..=8).prop_map(|n| n as f32)
}

fn floats(count: usize) -> impl Strategy<Value = Vec<f32>> {
    proptest::collection::vec(small(), count)
}

fn shaders() -> [Shader; 5] {
    [
        Shader::wgsl(WGSL),
        Shader::glsl(GLSL),
        Shader::slang(HLSL_AND_SLANG),
        Shader::new(Language::HlslGlslang, HLSL_AND_SLANG),
        Shader::new(Language::HlslSlangc, HLSL_AND_SLANG),
    ]
}

/// Checks the shader function `function` against `mirror` bit for bit in every language on 4,096
/// cases of `strategy`; prints the reports.
fn exact_in_every_language<A: Args, R: Value, S: Strategy<Value = A> + 'static>(
    function: &str,
    strategy: impl Fn() -> S + Send + Sync + 'static,
    mirror: impl Fn(A) -> R + Send + Sync + 'static,
) {
    let check = FunctionCheck::new(function, strategy, mirror).tolerance(Tolerance::Exact);
    let gpu = Gpu::new().unwrap_or_else(|error| panic!("{error}"));
    let config = RunConfig {
        cases: 4096,
        batch: 1024,
        ..RunConfig::default()
    };
    for shader in shaders() {
        let report = check
            .run(&gpu, &shader, &config)
            .unwrap_or_else(|error| panic!("{}: {error}", shader.language()));
        println!("{report}");
        report.assert_passed();
    }
    assert_eq!(Language::ALL.len(), shaders().len(), "every language is covered");
}

#[test]
fn matrices_times_vectors_agree() {
    exact_in_every_language(
        "apply2",
        || (floats(4), floats(2)).prop_map(|(m, v)| (Mat2::from_cols_slice(&m), Vec2::from_slice(&v))),
        |(m, v)| m * v,
    );
    exact_in_every_language(
        "apply3",
        || (floats(9), floats(3)).prop_map(|(m, v)| (Mat3::from_cols_slice(&m), Vec3::from_slice(&v))),
        |(m, v)| m * v,
    );
    exact_in_every_language(
        "apply4",
        || (floats(16), floats(4)).prop_map(|(m, v)| (Mat4::from_cols_slice(&m), Vec4::from_slice(&v))),
        |(m, v)| m * v,
    );
}

#[test]
fn matrix_results_come_back_column_by_column() {
    exact_in_every_language(
        "scale4",
        || (floats(16), small()).prop_map(|(m, s)| (Mat4::from_cols_slice(&m), s)),
        |(m, s)| m * s,
    );
    exact_in_every_language(
        "scale3",
        || (floats(9), small()).prop_map(|(m, s)| (Mat3::from_cols_slice(&m), s)),
        |(m, s)| m * s,
    );
}

#[test]
fn signed_integers_and_booleans_cross_bit_for_bit() {
    exact_in_every_language(
        "pick",
        // Within +-2^24, where the comparison's f32 components hold every integer exactly.
        || (-(1 << 24)..(1 << 24), -(1 << 24)..(1 << 24), any::<bool>()),
        |(a, b, first)| if first { a } else { b },
    );
}
