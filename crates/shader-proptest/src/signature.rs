//! Signatures: the parameter and result types of a shader function as its compiler reads them,
//! held against the Rust types of a check, so that a mismatch is reported in Rust and in shader
//! terms before anything runs, instead of as an error inside the generated kernel or, where the
//! language converts arguments implicitly (GLSL, Slang), as wrong results.

use crate::back::spelling::Spelling;
use crate::language::Language;
use crate::value::ShaderType;

/// The call a check makes: the shader function's name, and its argument and result types from
/// the Rust side.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Call<'a> {
    /// The shader function.
    pub function: &'a str,
    /// The argument types, from the Rust argument tuple.
    pub parameters: &'static [ShaderType],
    /// The result type, from the Rust result.
    pub result: ShaderType,
}

/// A type in a shader function's signature, as its compiler reads it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum DeclaredType {
    /// A type a value crosses as (a struct is [`DeclaredType::Struct`]).
    Value(ShaderType),
    /// A struct, by its name in the shader.
    Struct(String),
    /// Any other type, as the compiler spells it.
    Other(String),
}

impl DeclaredType {
    /// Whether a Rust value of type `ty` crosses as this type.
    fn takes(&self, ty: ShaderType) -> bool {
        match (self, ty) {
            (DeclaredType::Struct(name), ShaderType::Struct(s)) => name == s.name,
            (DeclaredType::Value(declared), ty) => *declared == ty,
            _ => false,
        }
    }

    /// The type as `spelling` names it.
    fn spelled(&self, spelling: &Spelling) -> String {
        match self {
            DeclaredType::Value(ty) => spelling.type_name(*ty).to_string(),
            DeclaredType::Struct(name) | DeclaredType::Other(name) => name.clone(),
        }
    }
}

/// A shader function's parameters (name, where the compiler keeps it, and type) and result.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Signature {
    /// The parameters in order: name (empty where the compiler gives none) and type.
    pub parameters: Vec<(String, DeclaredType)>,
    /// The result type.
    pub result: DeclaredType,
}

impl Signature {
    /// Whether `call`'s Rust types are exactly this signature's.
    fn takes(&self, call: &Call<'_>) -> bool {
        self.parameters.len() == call.parameters.len()
            && self
                .parameters
                .iter()
                .zip(call.parameters)
                .all(|((_, declared), &ty)| declared.takes(ty))
            && self.result.takes(call.result)
    }

    /// `function(d: float, r0: float, r1: float) -> float` in `spelling`'s type names.
    fn spelled(&self, spelling: &Spelling, function: &str) -> String {
        let parameters: Vec<String> = self
            .parameters
            .iter()
            .map(|(name, ty)| match name.as_str() {
                "" => ty.spelled(spelling),
                name => format!("{name}: {}", ty.spelled(spelling)),
            })
            .collect();
        format!(
            "{function}({}) -> {}",
            parameters.join(", "),
            self.result.spelled(spelling)
        )
    }
}

/// Why `call` cannot run against the functions of its name that the shader `declared`: `None`
/// where one of them takes exactly the Rust types. The message names the Rust types, the types
/// the kernel passes them as in `language` (spelled by `spelling`), and each declared signature;
/// for example
///
/// ```text
/// the Rust types of `falloff` are not those of the WGSL function:
///   Rust:   (Vec3, f32, f32) -> f32, passed to WGSL as (vec3<f32>, f32, f32) -> f32
///   shader: falloff(d: f32, r0: f32, r1: f32) -> f32
/// ```
pub(crate) fn mismatch(
    language: Language,
    spelling: &Spelling,
    call: &Call<'_>,
    declared: &[Signature],
) -> Option<String> {
    if declared.iter().any(|signature| signature.takes(call)) {
        return None;
    }
    let list = |names: Vec<&str>| names.join(", ");
    let rust = list(call.parameters.iter().map(|ty| ty.rust_name()).collect());
    let passed = list(call.parameters.iter().map(|&ty| spelling.type_name(ty)).collect());
    let function = call.function;
    let mut message = match declared {
        [] => format!("the {language} source declares no function named `{function}`:"),
        _ => format!("the Rust types of `{function}` are not those of the {language} function:"),
    };
    message.push_str(&format!(
        "\n  Rust:   ({rust}) -> {}, passed to {language} as ({passed}) -> {}",
        call.result.rust_name(),
        spelling.type_name(call.result),
    ));
    for signature in declared {
        message.push_str(&format!(
            "\n  shader: {}",
            signature.spelled(spelling, call.function)
        ));
    }
    Some(message)
}

#[cfg(test)]
mod tests {
    use super::*;

    const FALLOFF: Call<'static> = Call {
        function: "falloff",
        parameters: &[ShaderType::Vec3, ShaderType::F32, ShaderType::F32],
        result: ShaderType::F32,
    };

    fn scalar(name: &str) -> (String, DeclaredType) {
        (name.to_string(), DeclaredType::Value(ShaderType::F32))
    }

    /// A signature that takes the Rust types is no mismatch; one that does not is named in both
    /// terms, with every overload the shader declares.
    #[test]
    fn a_mismatch_names_both_sides() {
        let glsl = (Language::Glsl, Language::Glsl.backend().spelling());
        let scalars = Signature {
            parameters: vec![scalar("d"), scalar("r0"), scalar("r1")],
            result: DeclaredType::Value(ShaderType::F32),
        };
        let vector = Signature {
            parameters: vec![
                (String::new(), DeclaredType::Value(ShaderType::Vec3)),
                scalar(""),
                scalar(""),
            ],
            result: DeclaredType::Value(ShaderType::F32),
        };
        assert_eq!(
            mismatch(glsl.0, glsl.1, &FALLOFF, &[scalars.clone(), vector]),
            None
        );
        let message = mismatch(glsl.0, glsl.1, &FALLOFF, &[scalars]).expect("a mismatch");
        assert_eq!(
            message,
            "the Rust types of `falloff` are not those of the GLSL function:\n  \
             Rust:   (Vec3, f32, f32) -> f32, passed to GLSL as (vec3, float, float) -> float\n  \
             shader: falloff(d: float, r0: float, r1: float) -> float"
        );
        let missing = mismatch(glsl.0, glsl.1, &FALLOFF, &[]).expect("a mismatch");
        assert!(
            missing.starts_with("the GLSL source declares no function named `falloff`:"),
            "{missing}"
        );
    }
}
