//! A call kernel made ready for a check, whatever runs it: the Rust layouts of its `pod` structs
//! compared with the shader's, the kernel compiled by the language's back end, and the shader
//! function's signature held against the Rust types; each fails with an error that says which,
//! before any case runs.

use super::error::Error;
use crate::layout::compare;
use crate::shader::Shader;
use crate::signature::{mismatch, Call};
use crate::value::StructType;

/// The SPIR-V of `kernel`, the call kernel of `call` written against `shader`. A kernel that
/// does not compile is explained by the function's declared signatures where they do not take
/// the Rust types ([`Error::Signature`]); a kernel that compiles, by the signature it calls, where
/// the language converted an argument on the way.
pub(crate) fn compile_call(shader: &Shader, call: &Call<'_>, kernel: &str) -> Result<Vec<u32>, Error> {
    compare_layouts(shader, call)?;
    let backend = shader.backend();
    match shader.compile_kernel(kernel) {
        Ok(spirv) => {
            let called = backend.called_signature(&spirv, call.function);
            match called
                .and_then(|signature| mismatch(shader.language(), backend.spelling(), call, &[signature]))
            {
                Some(message) => Err(Error::Signature(message)),
                None => Ok(spirv),
            }
        }
        Err(error) => {
            let declared = backend.declared_signatures(shader, call.function);
            let explained = declared
                .and_then(|declared| mismatch(shader.language(), backend.spelling(), call, &declared));
            Err(explained.map_or_else(
                || Error::Compile(format!("{error}\n--- kernel ---\n{kernel}")),
                Error::Signature,
            ))
        }
    }
}

/// Compares the Rust layout of every `pod` struct among `call`'s types (and the structs they
/// hold) with the shader's ([`Shader::struct_layout`]).
fn compare_layouts(shader: &Shader, call: &Call<'_>) -> Result<(), Error> {
    let mut structs: Vec<&'static StructType> = Vec::new();
    call.parameters
        .iter()
        .chain([&call.result])
        .for_each(|ty| ty.structs(&mut structs));
    for ty in structs {
        let Some(rust_layout) = ty.rust_layout else {
            continue;
        };
        let shader_layout = shader.struct_layout(ty.name).map_err(Error::Layout)?;
        compare(&rust_layout(), &shader_layout).map_err(Error::Layout)?;
    }
    Ok(())
}
