//! Layouts proven on the device: values written from Rust as raw bytes are read field by field by
//! a shader, from a storage buffer and from push constants, and must come back bit for bit.

use super::compute::ComputeKernel;
use super::device::Gpu;
use super::error::Error;
use crate::kernel::echo_kernel_source;
use crate::layout::GlslPacking;
use crate::shader::Shader;
use crate::value::{ShaderType, Value};

/// Writes `values` from Rust as raw bytes into a storage buffer of the shader's struct and
/// `pushed` into a push-constant block of it (GLSL blocks use `packing`; WGSL has its own rules);
/// a kernel reads every field by name and writes them back as words, in declaration order. `Ok(Err)`
/// describes the first value whose words differ from [`Value::write`]'s, which happens when the
/// Rust layout is not the shader's. `T` must be a [`Value`] whose shader type is a struct.
///
/// # Panics
/// If `T`'s shader type is not a struct, or `values` is empty.
pub fn echo<T: Value + bytemuck::Pod>(
    gpu: &Gpu,
    shader: &Shader,
    packing: GlslPacking,
    values: &[T],
    pushed: &T,
) -> Result<Result<(), String>, Error> {
    let ShaderType::Struct(ty) = T::TYPE else {
        panic!("echo needs a struct type, not {:?}", T::TYPE)
    };
    assert!(!values.is_empty(), "echo needs at least one value");
    if let Some(reason) = gpu.missing_feature(shader.features()) {
        return Err(Error::Setup(reason));
    }
    let kernel = echo_kernel_source(shader, packing, ty);
    let size = std::mem::size_of::<T>();
    let spirv = shader
        .compile_kernel(&kernel)
        .map_err(|error| Error::Compile(format!("{error}\n--- kernel ---\n{kernel}")))?;
    let pipeline = ComputeKernel::new(gpu, &spirv, size as u32)?;
    let words = ShaderType::Struct(ty).words();
    let output = pipeline.dispatch_with_push_constants(
        values.len(),
        bytemuck::cast_slice(bytemuck::cast_slice::<T, u8>(values)),
        values.len() * 2 * words,
        bytemuck::bytes_of(pushed),
    )?;
    let mut expected_pushed = Vec::new();
    pushed.write(&mut expected_pushed);
    for (index, (value, echoed)) in values.iter().zip(output.chunks(2 * words)).enumerate() {
        let mut expected = Vec::new();
        value.write(&mut expected);
        if echoed[..words] != expected[..] {
            return Ok(Err(format!(
                "{}: value {index} from the storage buffer came back as {:08x?}, written as {:08x?}",
                ty.name,
                &echoed[..words],
                expected
            )));
        }
        if echoed[words..] != expected_pushed[..] {
            return Ok(Err(format!(
                "{}: the push constants came back as {:08x?}, written as {expected_pushed:08x?}",
                ty.name,
                &echoed[words..]
            )));
        }
    }
    Ok(Ok(()))
}
