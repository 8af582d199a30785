//! Timing kernels for single shader functions: each invocation calls the function a fixed number
//! of times in a loop in which every argument depends on the last result, so that the compiler can
//! neither hoist a call out of the loop nor drop any of its work.
//!
//! A function's signature comes from its module's GLSL source ([`signatures`]): the parameter and
//! result types as shader-proptest's [`ShaderType`]s, structs with their fields. [`timing_source`]
//! writes, in any of the languages (WGSL, GLSL, Slang, HLSL), a function `time_<callee>` with the callee's parameters
//! and result and one more float, `zero`, that calls the callee a given number of times: after
//! each call it sums every component of the result, multiplies the sum by `zero`, and adds that
//! product `d` to every component of every argument (integers get `d` converted, booleans flip
//! when `d > 0.5`). The kernel reads `zero` from the input words like every argument, and it is 0,
//! so the arguments stay what they are; but no compiler can know it, so each call needs every
//! component of the last one. (A test of the sum against a bound the result never reaches does
//! not hold: a compiler that knows the result's range, a `sign` or a packed integer, drops the
//! dependence and runs the function once.) The loop's own work per call is a multiply, an add per
//! result component and an add per argument component, the same for any two callees of one
//! signature (a function and a peer's original behind an adapter with the function's signature).
//!
//! The *empty kernel* of a signature ([`Body::Empty`]) is the same loop with the call replaced by
//! a stand-in that sets every result component from argument components by a few adds and
//! conversions, every argument component read, so that the loop, its sum and its perturbations stay and nothing else: its time
//! is the loop's (with the stand-in's few operations), and a function kernel's time less it is
//! the function's.
//!
//! shader-proptest's [`kernel_source`] wraps `time_<callee>` in a compute kernel that reads each
//! invocation's arguments from a buffer and writes the last result back ([`inputs`] fills the
//! buffer).

use ray_footprint::shaders::Module;
use shader_proptest::{kernel_source, Language, Shader, ShaderType, StructType};

/// A shader function's name, parameter types and result type.
#[derive(Clone, Debug, PartialEq)]
pub struct Signature {
    /// The shader name (`rf_width_at`).
    pub name: String,
    /// The parameters' types, in order.
    pub parameters: Vec<ShaderType>,
    /// The result's type.
    pub result: ShaderType,
}

/// Every public function of `module` (its Rust mirror's, in module order) with its shader
/// signature, or why no kernel carries it: no GLSL function of that name, or a parameter or
/// result of a type without words in the kernels (`double`, `dvec3`).
pub fn signatures(module: Module) -> Vec<(String, Result<Signature, String>)> {
    let glsl = module.glsl();
    let structs = glsl_structs();
    let mut made = Vec::new();
    module
        .functions()
        .into_iter()
        .map(|function| {
            let name = format!("rf_{function}");
            let signature = glsl_signature(glsl, &name).and_then(|(result, parameters)| {
                Ok(Signature {
                    result: shader_type(&result, &structs, &mut made)?,
                    parameters: parameters
                        .iter()
                        .map(|ty| shader_type(ty, &structs, &mut made))
                        .collect::<Result<_, _>>()?,
                    name: name.clone(),
                })
            });
            (name, signature)
        })
        .collect()
}

/// The result type and parameter types of the GLSL function `name` in `source`.
fn glsl_signature(source: &str, name: &str) -> Result<(String, Vec<String>), String> {
    let opening = format!(" {name}(");
    let start = source
        .lines()
        .scan(0, |offset, line| {
            let at = *offset;
            *offset += line.len() + 1;
            Some((at, line))
        })
        .find(|(_, line)| {
            line.find(&opening)
                .is_some_and(|at| !line[..at].contains(' ') && !line.starts_with("//"))
        })
        .map(|(at, _)| at)
        .ok_or_else(|| format!("no GLSL function {name}"))?;
    let declaration = &source[start..];
    let open = declaration.find('(').unwrap_or(0);
    let close = declaration.find(')').ok_or_else(|| format!("{name}: no ')'"))?;
    let result = declaration[..open]
        .split_whitespace()
        .next()
        .unwrap_or("")
        .to_string();
    let parameters = declaration[open + 1..close]
        .split(',')
        .map(|parameter| {
            let words: Vec<&str> = parameter.split_whitespace().collect();
            match words.as_slice() {
                [ty, _name] => Ok(ty.to_string()),
                _ => Err(format!(
                    "{name}: a parameter '{}' other than 'TYPE NAME'",
                    parameter.trim()
                )),
            }
        })
        .collect::<Result<_, _>>()?;
    Ok((result, parameters))
}

/// Every struct the GLSL modules declare: its name and its fields' types and names, in order.
fn glsl_structs() -> Vec<(String, Vec<(String, String)>)> {
    let mut structs = Vec::new();
    for module in Module::ALL {
        let mut lines = module.glsl().lines();
        while let Some(line) = lines.next() {
            let Some(name) = line
                .strip_prefix("struct ")
                .and_then(|rest| rest.strip_suffix(" {"))
            else {
                continue;
            };
            let fields = lines
                .by_ref()
                .take_while(|line| !line.starts_with('}'))
                .filter_map(|line| {
                    let field = line.trim().strip_suffix(';')?;
                    let (ty, name) = field.split_once(' ')?;
                    Some((ty.to_string(), name.to_string()))
                })
                .collect();
            structs.push((name.to_string(), fields));
        }
    }
    structs
}

/// The kernels' type of the GLSL type `name`; structs from `structs`, each made `'static` once
/// and kept in `made` (once per [`signatures`] call: a bench's few dozen), so that a struct
/// appearing twice in a signature is one type (HLSL kernels declare one maker per struct type).
fn shader_type(
    name: &str,
    structs: &[(String, Vec<(String, String)>)],
    made: &mut Vec<&'static StructType>,
) -> Result<ShaderType, String> {
    Ok(match name {
        "float" => ShaderType::F32,
        "uint" => ShaderType::U32,
        "int" => ShaderType::I32,
        "bool" => ShaderType::Bool,
        "vec2" => ShaderType::Vec2,
        "vec3" => ShaderType::Vec3,
        "vec4" => ShaderType::Vec4,
        "mat2" => ShaderType::Mat2,
        "mat3" => ShaderType::Mat3,
        "mat4" => ShaderType::Mat4,
        _ => {
            if let Some(&made_before) = made.iter().find(|ty| ty.name == name) {
                return Ok(ShaderType::Struct(made_before));
            }
            let (struct_name, fields) = structs
                .iter()
                .find(|(struct_name, _)| struct_name == name)
                .ok_or_else(|| format!("the type {name}, which the kernels carry no words of"))?;
            let fields: Vec<(&'static str, ShaderType)> = fields
                .iter()
                .map(|(ty, field)| Ok((leak(field), shader_type(ty, structs, made)?)))
                .collect::<Result<_, String>>()?;
            let ty: &'static StructType = Box::leak(Box::new(StructType {
                name: leak(struct_name),
                rust_name: leak(struct_name),
                fields: Box::leak(fields.into_boxed_slice()),
                rust_layout: None,
            }));
            made.push(ty);
            ShaderType::Struct(ty)
        }
    })
}

fn leak(text: &str) -> &'static str {
    Box::leak(text.to_string().into_boxed_str())
}

/// A component of a value: its path (`a0.cone.width`, `a1[2]`) and type, a scalar or a vector.
fn leaves(path: &str, ty: ShaderType, out: &mut Vec<(String, ShaderType)>) {
    match ty {
        ShaderType::Struct(s) => {
            for &(field, field_ty) in s.fields {
                leaves(&format!("{path}.{field}"), field_ty, out);
            }
        }
        ShaderType::Mat2 | ShaderType::Mat3 | ShaderType::Mat4 => {
            let (count, vector) = match ty {
                ShaderType::Mat2 => (2, ShaderType::Vec2),
                ShaderType::Mat3 => (3, ShaderType::Vec3),
                _ => (4, ShaderType::Vec4),
            };
            out.extend((0..count).map(|i| (format!("{path}[{i}]"), vector)));
        }
        scalar_or_vector => out.push((path.to_string(), scalar_or_vector)),
    }
}

/// The float that a component (`path`, a scalar or a vector) adds to the result's sum.
fn summand(language: Language, path: &str, ty: ShaderType) -> String {
    let float = language.type_name(ShaderType::F32);
    match ty {
        ShaderType::F32 => path.to_string(),
        ShaderType::Vec2 | ShaderType::Vec3 | ShaderType::Vec4 => {
            format!("dot({path}, {}(1.0))", language.type_name(ty))
        }
        _ => format!("{float}({path})"),
    }
}

/// The statement that adds the float `d` to a component of an argument.
fn perturbation(language: Language, path: &str, ty: ShaderType) -> String {
    match ty {
        ShaderType::Bool => format!("{path} = {path} != (d > 0.5);"),
        ShaderType::U32 | ShaderType::I32 => format!("{path} += {}(d);", language.type_name(ty)),
        _ => format!("{path} += d;"),
    }
}

/// What each turn of the timing loop computes its result with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Body {
    /// A call of the callee: the kernel that times the function.
    Call,
    /// No call: the *empty kernel*, the same loop with the call replaced by the least work that
    /// keeps a result depending on every argument component (see the module documentation). Its
    /// time is the loop's, to subtract from the function kernel's.
    Empty,
}

/// The statements that set every component of `r` (`result`, the result's components) from the
/// argument components (`arguments`) without a call, in place of `r = callee(...)` in the empty
/// kernel.
///
/// The argument components are dealt out over the result's in turn (the i-th to the
/// `i % result.len()`-th; a result with more components than the arguments reuses them), and each
/// result component is the sum of those dealt to it: the ones of its own type as they are, the
/// others as the float the loop's sum takes of them ([`summand`]: a vector's components added, an
/// integer or a boolean converted), converted to its type (a vector splat, an integer converted,
/// a boolean `> 0.5`). So every result component depends on an argument and every argument
/// component reaches the result: no compiler can fold the sum (`d` stays unknown), nor drop an
/// argument's perturbation (each is read), nor the loop (each turn needs the last one's `r`).
/// What the empty kernel does per turn is then the loop's own work (the counter, the sum over
/// the result, the multiply by `zero`, the adds to the arguments) and this stand-in's: about one
/// add per argument component beyond the result's count, plus conversions where the types
/// differ. The stand-in's part is counted as the loop's, so the subtraction takes slightly more
/// than the loop from the function, more for many argument components folded into few result
/// components.
fn stand_in(
    language: Language,
    result: &[(String, ShaderType)],
    arguments: &[(String, ShaderType)],
) -> Vec<String> {
    result
        .iter()
        .enumerate()
        .map(|(j, (path, ty))| {
            let dealt: Vec<&(String, ShaderType)> = if arguments.len() > result.len() {
                arguments.iter().skip(j).step_by(result.len()).collect()
            } else {
                arguments.get(j % arguments.len().max(1)).into_iter().collect()
            };
            format!("{path} = {};", component_from(language, *ty, &dealt))
        })
        .collect()
}

/// An expression of type `ty` that adds up the argument components `dealt`: those of type `ty`
/// (a float, a vector or an integer) as they are, the others summed as floats and converted.
fn component_from(language: Language, ty: ShaderType, dealt: &[&(String, ShaderType)]) -> String {
    let same_type = ty != ShaderType::Bool;
    let (own, others): (Vec<&(String, ShaderType)>, Vec<_>) =
        dealt.iter().copied().partition(|(_, t)| same_type && *t == ty);
    let mut terms: Vec<String> = own.iter().map(|(path, _)| path.clone()).collect();
    let floats: Vec<String> = others
        .iter()
        .map(|(path, t)| summand(language, path, *t))
        .collect();
    if !floats.is_empty() || terms.is_empty() {
        let float_sum = if floats.is_empty() {
            String::from("0.0")
        } else {
            floats.join(" + ")
        };
        terms.push(match ty {
            ShaderType::F32 => float_sum,
            ShaderType::Bool => format!("({float_sum}) > 0.5"),
            _ => format!("{}({float_sum})", language.type_name(ty)),
        });
    }
    terms.join(" + ")
}

/// The source of `time_<callee>`: `signature`'s parameters and `zero`, `signature`'s result, a
/// loop of `iterations` turns whose each turn's arguments depend on the last result (see the
/// module documentation) and which calls `callee` (which takes `signature`'s parameters and
/// returns its result) or, for [`Body::Empty`], sets the result without a call.
pub fn timing_source(
    language: Language,
    signature: &Signature,
    callee: &str,
    iterations: u32,
    body: Body,
) -> String {
    let arguments: Vec<String> = (0..signature.parameters.len()).map(|i| format!("v{i}")).collect();
    let call = format!("{callee}({})", arguments.join(", "));
    let mut result_leaves = Vec::new();
    leaves("r", signature.result, &mut result_leaves);
    let sum: Vec<String> = result_leaves
        .iter()
        .map(|(path, ty)| summand(language, path, *ty))
        .collect();
    let mut argument_leaves = Vec::new();
    for (i, &ty) in signature.parameters.iter().enumerate() {
        leaves(&format!("v{i}"), ty, &mut argument_leaves);
    }
    let perturb: String = argument_leaves
        .iter()
        .map(|(path, ty)| format!("        {}\n", perturbation(language, path, *ty)))
        .collect();
    let result = language.type_name(signature.result);
    let sum = sum.join(" + ");
    let wgsl = language == Language::Wgsl;
    // The result before the loop and in each turn.
    let (first, turn) = match body {
        Body::Call if wgsl => (format!("    var r = {call};\n"), format!("        r = {call};\n")),
        Body::Call => (
            format!("    {result} r = {call};\n"),
            format!("        r = {call};\n"),
        ),
        Body::Empty => {
            let statements = stand_in(language, &result_leaves, &argument_leaves);
            let indented = |indent: &str| -> String {
                statements
                    .iter()
                    .map(|statement| format!("{indent}{statement}\n"))
                    .collect()
            };
            let declaration = if wgsl {
                format!("    var r: {result};\n")
            } else {
                format!("    {result} r;\n")
            };
            (declaration + &indented("    "), indented("        "))
        }
    };
    if wgsl {
        let parameters: Vec<String> = signature
            .parameters
            .iter()
            .enumerate()
            .map(|(i, &ty)| format!("a{i}: {}", language.type_name(ty)))
            .collect();
        let copies: String = (0..signature.parameters.len())
            .map(|i| format!("    var v{i} = a{i};\n"))
            .collect();
        format!(
            "fn time_{callee}({}, zero: f32) -> {result} {{
{copies}{first}    for (var k = 1u; k < {iterations}u; k++) {{
        let d = ({sum}) * zero;
{perturb}{turn}    }}
    return r;
}}
",
            parameters.join(", ")
        )
    } else {
        let parameters: Vec<String> = signature
            .parameters
            .iter()
            .enumerate()
            .map(|(i, &ty)| format!("{} a{i}", language.type_name(ty)))
            .collect();
        let copies: String = signature
            .parameters
            .iter()
            .enumerate()
            .map(|(i, &ty)| format!("    {} v{i} = a{i};\n", language.type_name(ty)))
            .collect();
        format!(
            "{result} time_{callee}({}, float zero) {{
{copies}{first}    for (uint k = 1u; k < {iterations}u; k++) {{
        float d = ({sum}) * zero;
{perturb}{turn}    }}
    return r;
}}
",
            parameters.join(", ")
        )
    }
}

/// What a timing kernel calls: `callee`, which has `signature`, defined by the module's shader or
/// by `extra` (an adapter and what it calls) appended to it, `iterations` times per invocation
/// (its empty kernel calls nothing, in as many turns).
#[derive(Clone, Copy, Debug)]
pub struct Callee<'a> {
    /// The function's signature.
    pub signature: &'a Signature,
    /// The name called.
    pub name: &'a str,
    /// Source appended to the module's (empty for the module's own function).
    pub extra: &'a str,
    /// Calls per invocation.
    pub iterations: u32,
}

/// The timing kernel of `callee` in `language`, or its empty kernel (`body`): `module`'s shader
/// (its source, include directory, features and capabilities) with the callee's extra source and
/// `time_<callee>` appended, and the kernel's source.
pub fn timing_kernel(module: Module, language: Language, callee: Callee<'_>, body: Body) -> (Shader, String) {
    let Callee {
        signature,
        name: callee,
        extra,
        iterations,
    } = callee;
    let base = module.shader(language);
    let source = format!(
        "{}\n{extra}\n{}",
        base.source(),
        timing_source(language, signature, callee, iterations, body)
    );
    let mut timed = match language {
        Language::Wgsl => Shader::wgsl(source).capabilities(module.naga_capabilities()),
        _ => Shader::new(language, source),
    };
    for dir in base.include_dirs() {
        timed = timed.include_dir(dir);
    }
    for &feature in base.features() {
        timed = timed.requires(feature);
    }
    let parameters: Vec<ShaderType> = signature
        .parameters
        .iter()
        .copied()
        .chain([ShaderType::F32])
        .collect();
    let kernel = kernel_source(&timed, &format!("time_{callee}"), &parameters, signature.result);
    (timed, kernel)
}

/// A small deterministic generator (xorshift32) of the input words.
struct Words(u32);

impl Words {
    fn next(&mut self) -> u32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 17;
        self.0 ^= self.0 << 5;
        self.0
    }

    /// A float in [0.1, 1).
    fn unit(&mut self) -> f32 {
        0.1 + 0.9 * (self.next() >> 8) as f32 / 16_777_216.0
    }
}

/// The input words of `invocations` invocations of `time_<callee>` for a callee of `signature`:
/// its arguments, then `zero` (0.0). Every float of an argument is in [0.1, 1), every
/// `vec3` of unit length (normals, directions and positions alike: a triangle of three of them is
/// not degenerate), every matrix the identity plus up to 0.1 in each element, every integer in
/// 1 to 8, every boolean true in every other group of 32 invocations (so a warp of 32 never
/// diverges on it).
pub fn inputs(signature: &Signature, invocations: usize) -> Vec<u32> {
    let mut words = Words(0x9e37_79b9);
    let mut out = Vec::new();
    for invocation in 0..invocations {
        for &ty in &signature.parameters {
            write_value(ty, invocation, &mut words, &mut out);
        }
        out.push(0.0f32.to_bits());
    }
    out
}

fn write_value(ty: ShaderType, invocation: usize, words: &mut Words, out: &mut Vec<u32>) {
    match ty {
        ShaderType::F32 | ShaderType::Vec2 | ShaderType::Vec4 => {
            out.extend((0..ty.words()).map(|_| words.unit().to_bits()));
        }
        ShaderType::Vec3 => {
            let v = glam::Vec3::new(words.unit(), words.unit(), words.unit()).normalize();
            out.extend(v.to_array().map(f32::to_bits));
        }
        ShaderType::U32 | ShaderType::I32 => out.push(1 + words.next() % 8),
        ShaderType::Bool => out.push(u32::from((invocation / 32) % 2 == 1)),
        ShaderType::Mat2 | ShaderType::Mat3 | ShaderType::Mat4 => {
            let n = match ty {
                ShaderType::Mat2 => 2,
                ShaderType::Mat3 => 3,
                _ => 4,
            };
            for column in 0..n {
                for row in 0..n {
                    let identity = if row == column { 1.0 } else { 0.0 };
                    out.push((identity + 0.1 * words.unit()).to_bits());
                }
            }
        }
        ShaderType::Struct(s) => {
            for &(_, field) in s.fields {
                write_value(field, invocation, words, out);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The signature of `name`, a function of the ray_cone module.
    fn ray_cone_signature(name: &str) -> Signature {
        signatures(Module::RayCone)
            .into_iter()
            .find(|(function, _)| function == name)
            .and_then(|(_, signature)| signature.ok())
            .unwrap_or_else(|| panic!("no signature for {name}"))
    }

    #[test]
    fn every_function_of_a_module_has_its_signature() {
        let width_at = ray_cone_signature("rf_width_at");
        assert_eq!(width_at.result, ShaderType::F32);
        assert_eq!(width_at.parameters.len(), 2);
        let ShaderType::Struct(cone) = width_at.parameters[0] else {
            panic!("the cone is a struct");
        };
        assert_eq!((cone.name, cone.fields.len()), ("RfRayCone", 2));
        // A signature over two lines.
        let refract = ray_cone_signature("rf_refract_ray_cone");
        assert_eq!(refract.parameters.len(), 5);
    }

    #[test]
    fn a_type_without_words_is_named() {
        let error = shader_type("dvec3", &glsl_structs(), &mut Vec::new()).unwrap_err();
        assert!(error.contains("dvec3"), "{error}");
        let f64_module = signatures(Module::RayDiffF64);
        assert!(
            f64_module.iter().all(|(_, signature)| signature.is_ok()),
            "its public functions take floats"
        );
    }

    #[test]
    fn the_loop_perturbs_every_argument_component_by_the_result() {
        let signature = ray_cone_signature("rf_propagate");
        let glsl = timing_source(Language::Glsl, &signature, "rf_propagate", 8, Body::Call);
        for line in [
            "RfRayCone time_rf_propagate(RfRayCone a0, float a1, float a2, float zero) {",
            "float d = (r.width + r.spread_angle) * zero;",
            "v0.width += d;",
            "v0.spread_angle += d;",
            "v1 += d;",
            "v2 += d;",
            "for (uint k = 1u; k < 8u; k++) {",
        ] {
            assert!(glsl.contains(line), "{line} in\n{glsl}");
        }
        // Per invocation: the cone's two floats, t, the spread angle, zero.
        let words = inputs(&signature, 3);
        assert_eq!(words.len(), 3 * 5);
        assert_eq!(words[4], 0.0f32.to_bits());
    }

    /// Whether `source` calls `callee` (its name not inside a longer name, then a parenthesis).
    fn calls(source: &str, callee: &str) -> bool {
        source.match_indices(&format!("{callee}(")).any(|(at, _)| {
            !source[..at]
                .chars()
                .next_back()
                .is_some_and(|c| c.is_alphanumeric() || c == '_')
        })
    }

    /// Signatures that between them have every result type and every parameter type of the
    /// modules (each the first to add one).
    fn signatures_of_every_type() -> Vec<(Module, Signature)> {
        let mut seen: Vec<String> = Vec::new();
        let mut chosen = Vec::new();
        for &module in Module::ALL {
            for (_, signature) in signatures(module) {
                let Ok(signature) = signature else { continue };
                let types: Vec<String> = [format!("result {:?}", signature.result)]
                    .into_iter()
                    .chain(signature.parameters.iter().map(|ty| format!("{ty:?}")))
                    .collect();
                if types.iter().any(|ty| !seen.contains(ty)) {
                    seen.extend(types);
                    chosen.push((module, signature));
                }
            }
        }
        chosen
    }

    #[test]
    fn the_empty_kernel_calls_nothing_and_compiles_in_every_language() {
        let chosen = signatures_of_every_type();
        assert!(chosen.len() >= 5, "{} signatures", chosen.len());
        for (module, signature) in &chosen {
            let name = signature.name.as_str();
            for language in Language::ALL {
                let call = timing_source(language, signature, name, 8, Body::Call);
                assert!(calls(&call, name), "{language} {name}:\n{call}");
                let empty = timing_source(language, signature, name, 8, Body::Empty);
                assert!(!calls(&empty, name), "{language} {name}:\n{empty}");
                let callee = Callee {
                    signature,
                    name,
                    extra: "",
                    iterations: 8,
                };
                let (shader, kernel) = timing_kernel(*module, language, callee, Body::Empty);
                if let Err(error) = shader.compile_kernel(&kernel) {
                    panic!("{language} {name}: {error}\n{empty}");
                }
            }
        }
    }

    #[test]
    fn every_argument_component_reaches_the_empty_result() {
        let signature = ray_cone_signature("rf_width_at");
        let glsl = timing_source(Language::Glsl, &signature, "rf_width_at", 8, Body::Empty);
        for line in [
            "    float r;",
            "    r = v0.width + v0.spread_angle + v1;",
            "        float d = (r) * zero;",
            "        v1 += d;",
            "        r = v0.width + v0.spread_angle + v1;",
        ] {
            assert!(glsl.contains(line), "{line} in\n{glsl}");
        }
    }
}
