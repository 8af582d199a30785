//! What glslang and slangc wrote into SPIR-V, read back: the layout of a struct in a storage
//! buffer (member offsets, matrix and array strides, type sizes) and the signatures of named
//! functions (parameter and result types, parameter names). The GLSL and Slang back ends read
//! their layout probes and kernels with it; naga's WGSL needs no reader (its module says it all).

use crate::layout::{FieldLayout, StructLayout};
#[cfg(feature = "gpu")]
use crate::signature::{DeclaredType, Signature};
use crate::spirv::literal_string;
#[cfg(feature = "gpu")]
use crate::value::ShaderType;
use std::collections::HashMap;

const OP_NAME: u32 = 5;
const OP_MEMBER_NAME: u32 = 6;
const OP_TYPE_BOOL: u32 = 20;
const OP_TYPE_INT: u32 = 21;
const OP_TYPE_FLOAT: u32 = 22;
const OP_TYPE_VECTOR: u32 = 23;
const OP_TYPE_MATRIX: u32 = 24;
const OP_TYPE_ARRAY: u32 = 28;
const OP_TYPE_RUNTIME_ARRAY: u32 = 29;
const OP_TYPE_STRUCT: u32 = 30;
const OP_TYPE_POINTER: u32 = 32;
const OP_TYPE_FUNCTION: u32 = 33;
const OP_CONSTANT: u32 = 43;
#[cfg(feature = "gpu")]
const OP_FUNCTION: u32 = 54;
#[cfg(feature = "gpu")]
const OP_FUNCTION_PARAMETER: u32 = 55;
#[cfg(feature = "gpu")]
const OP_FUNCTION_CALL: u32 = 57;
const OP_VARIABLE: u32 = 59;
const OP_DECORATE: u32 = 71;
const OP_MEMBER_DECORATE: u32 = 72;
const DECORATION_ARRAY_STRIDE: u32 = 6;
const DECORATION_MATRIX_STRIDE: u32 = 7;
const DECORATION_OFFSET: u32 = 35;

/// The instructions of a module the reader needs, by id.
#[derive(Default)]
struct Module {
    names: HashMap<u32, String>,
    member_names: HashMap<(u32, u32), String>,
    offsets: HashMap<(u32, u32), u32>,
    matrix_strides: HashMap<(u32, u32), u32>,
    array_strides: HashMap<u32, u32>,
    /// Type id to its opcode followed by its operands.
    types: HashMap<u32, Vec<u32>>,
    constants: HashMap<u32, u32>,
    /// Pointer type to pointee type.
    pointees: HashMap<u32, u32>,
    /// Variable to its pointer type.
    variables: HashMap<u32, u32>,
    /// Functions in module order: id, function type, parameter ids.
    #[cfg(feature = "gpu")]
    functions: Vec<(u32, u32, Vec<u32>)>,
    /// Ids of the functions some instruction calls.
    #[cfg(feature = "gpu")]
    callees: Vec<u32>,
}

fn parse(words: &[u32]) -> Module {
    let mut module = Module::default();
    let mut at = 5; // after the header
    while at < words.len() {
        let (count, opcode) = ((words[at] >> 16) as usize, words[at] & 0xffff);
        let operands = &words[at + 1..(at + count.max(1)).min(words.len())];
        match (opcode, operands) {
            (OP_NAME, [id, rest @ ..]) => {
                module.names.insert(*id, literal_string(rest));
            }
            (OP_MEMBER_NAME, [id, member, rest @ ..]) => {
                module.member_names.insert((*id, *member), literal_string(rest));
            }
            (OP_MEMBER_DECORATE, [id, member, DECORATION_OFFSET, offset, ..]) => {
                module.offsets.insert((*id, *member), *offset);
            }
            (OP_MEMBER_DECORATE, [id, member, DECORATION_MATRIX_STRIDE, stride, ..]) => {
                module.matrix_strides.insert((*id, *member), *stride);
            }
            (OP_DECORATE, [id, DECORATION_ARRAY_STRIDE, stride, ..]) => {
                module.array_strides.insert(*id, *stride);
            }
            (OP_CONSTANT, [_, id, value, ..]) => {
                module.constants.insert(*id, *value);
            }
            (OP_TYPE_POINTER, [id, _, pointee]) => {
                module.pointees.insert(*id, *pointee);
            }
            (OP_VARIABLE, [pointer, id, ..]) => {
                module.variables.insert(*id, *pointer);
            }
            #[cfg(feature = "gpu")]
            (OP_FUNCTION, [_, id, _, function_type]) => {
                module.functions.push((*id, *function_type, Vec::new()))
            }
            #[cfg(feature = "gpu")]
            (OP_FUNCTION_PARAMETER, [_, id]) => {
                if let Some((_, _, parameters)) = module.functions.last_mut() {
                    parameters.push(*id);
                }
            }
            #[cfg(feature = "gpu")]
            (OP_FUNCTION_CALL, [_, _, callee, ..]) => module.callees.push(*callee),
            (
                OP_TYPE_BOOL
                | OP_TYPE_INT
                | OP_TYPE_FLOAT
                | OP_TYPE_VECTOR
                | OP_TYPE_MATRIX
                | OP_TYPE_ARRAY
                | OP_TYPE_RUNTIME_ARRAY
                | OP_TYPE_STRUCT
                | OP_TYPE_FUNCTION,
                [id, ..],
            ) => {
                module.types.insert(*id, [&[opcode], operands].concat());
            }
            _ => {}
        }
        at += count.max(1);
    }
    module
}

impl Module {
    /// Byte size of a type; a member's matrix stride comes from its struct.
    fn size(&self, ty: u32, matrix_stride: Option<u32>) -> u32 {
        match self.types.get(&ty).map(Vec::as_slice) {
            Some([OP_TYPE_INT | OP_TYPE_FLOAT, _, width, ..]) => width / 8,
            Some([OP_TYPE_VECTOR, _, component, count]) => self.size(*component, None) * count,
            Some([OP_TYPE_MATRIX, _, column, count]) => {
                matrix_stride.unwrap_or_else(|| self.size(*column, None)) * count
            }
            Some([OP_TYPE_ARRAY, _, _, length]) => {
                self.array_strides.get(&ty).copied().unwrap_or(0)
                    * self.constants.get(length).copied().unwrap_or(0)
            }
            Some([OP_TYPE_STRUCT, _, members @ ..]) => (0..members.len() as u32)
                .map(|m| self.offsets.get(&(ty, m)).copied().unwrap_or(0) + self.member_size(ty, m, members))
                .max()
                .unwrap_or(0),
            _ => 0,
        }
    }

    fn member_size(&self, structure: u32, member: u32, members: &[u32]) -> u32 {
        self.size(
            members[member as usize],
            self.matrix_strides.get(&(structure, member)).copied(),
        )
    }

    /// The layout of the struct type `id`, sized by the stride of a runtime array of it.
    fn element_layout(&self, id: u32) -> Option<StructLayout> {
        let [OP_TYPE_STRUCT, _, members @ ..] = self.types.get(&id)?.as_slice() else {
            return None;
        };
        let stride = self.types.iter().find_map(|(array, ty)| match ty.as_slice() {
            [OP_TYPE_RUNTIME_ARRAY, _, element] if *element == id => self.array_strides.get(array).copied(),
            _ => None,
        })?;
        let fields = (0..members.len() as u32)
            .map(|m| FieldLayout {
                name: self.member_names.get(&(id, m)).cloned().unwrap_or_default(),
                offset: self.offsets.get(&(id, m)).copied().unwrap_or(0),
                size: self.member_size(id, m, members),
            })
            .collect();
        Some(StructLayout {
            name: self.names.get(&id).cloned().unwrap_or_default(),
            size: stride,
            align: 0,
            fields,
        })
    }
}

#[cfg(feature = "gpu")]
impl Module {
    /// The type `ty` as a signature shows it; a pointer (how glslang passes every argument, and
    /// slangc a struct) as its pointee.
    fn declared_type(&self, ty: u32) -> DeclaredType {
        if let Some(&pointee) = self.pointees.get(&ty) {
            return self.declared_type(pointee);
        }
        let float = |component: &u32| {
            matches!(
                self.types.get(component).map(Vec::as_slice),
                Some([OP_TYPE_FLOAT, _, 32])
            )
        };
        let known = match self.types.get(&ty).map(Vec::as_slice) {
            Some([OP_TYPE_FLOAT, _, 32]) => Some(ShaderType::F32),
            Some([OP_TYPE_INT, _, 32, 0]) => Some(ShaderType::U32),
            Some([OP_TYPE_INT, _, 32, 1]) => Some(ShaderType::I32),
            Some([OP_TYPE_BOOL, _]) => Some(ShaderType::Bool),
            Some([OP_TYPE_VECTOR, _, component, count]) if float(component) => vector(*count),
            Some([OP_TYPE_MATRIX, _, column, count]) => match self.types.get(column).map(Vec::as_slice) {
                Some([OP_TYPE_VECTOR, _, component, rows]) if float(component) && rows == count => {
                    matrix(*count)
                }
                _ => None,
            },
            Some([OP_TYPE_STRUCT, ..]) => {
                return DeclaredType::Struct(self.names.get(&ty).cloned().unwrap_or_default())
            }
            _ => None,
        };
        known.map_or_else(|| DeclaredType::Other(self.spelling(ty)), DeclaredType::Value)
    }

    /// A SPIR-V spelling of a type no [`ShaderType`] stands for: `float64`, `vector of 3 int32`.
    fn spelling(&self, ty: u32) -> String {
        match self.types.get(&ty).map(Vec::as_slice) {
            Some([OP_TYPE_FLOAT, _, width]) => format!("float{width}"),
            Some([OP_TYPE_INT, _, width, signed]) => {
                format!("{}int{width}", if *signed == 1 { "" } else { "u" })
            }
            Some([OP_TYPE_VECTOR, _, component, count]) => {
                format!("vector of {count} {}", self.spelling(*component))
            }
            Some([OP_TYPE_MATRIX, _, column, count]) => {
                format!("matrix of {count} {}", self.spelling(*column))
            }
            Some([OP_TYPE_ARRAY | OP_TYPE_RUNTIME_ARRAY, _, element, ..]) => {
                format!("array of {}", self.spelling(*element))
            }
            _ => format!("SPIR-V type %{ty}"),
        }
    }

    /// Whether the function `id` is named `name`: exactly (slangc), or followed by glslang's
    /// mangled parameter list (`falloff(f1;f1;f1;`).
    fn is_named(&self, id: u32, name: &str) -> bool {
        self.names
            .get(&id)
            .is_some_and(|full| full.split('(').next() == Some(name))
    }

    /// The signature of the function `(id, function_type, parameters)`.
    fn signature(&self, function_type: u32, parameters: &[u32]) -> Option<Signature> {
        let [OP_TYPE_FUNCTION, _, result, types @ ..] = self.types.get(&function_type)?.as_slice() else {
            return None;
        };
        Some(Signature {
            parameters: parameters
                .iter()
                .zip(types)
                .map(|(id, &ty)| {
                    (
                        self.names.get(id).cloned().unwrap_or_default(),
                        self.declared_type(ty),
                    )
                })
                .collect(),
            result: self.declared_type(*result),
        })
    }
}

/// The `ShaderType` of a float vector of `count` components.
#[cfg(feature = "gpu")]
fn vector(count: u32) -> Option<ShaderType> {
    match count {
        2 => Some(ShaderType::Vec2),
        3 => Some(ShaderType::Vec3),
        4 => Some(ShaderType::Vec4),
        _ => None,
    }
}

/// The `ShaderType` of a square float matrix of `count` columns.
#[cfg(feature = "gpu")]
fn matrix(count: u32) -> Option<ShaderType> {
    match count {
        2 => Some(ShaderType::Mat2),
        3 => Some(ShaderType::Mat3),
        4 => Some(ShaderType::Mat4),
        _ => None,
    }
}

/// The layout of the struct `name` used as a runtime-array element.
pub(crate) fn struct_layout(words: &[u32], name: &str) -> Option<StructLayout> {
    let module = parse(words);
    let id = module.types.iter().find_map(|(id, ty)| match ty.as_slice() {
        [OP_TYPE_STRUCT, ..] if module.names.get(id).map(String::as_str) == Some(name) => Some(*id),
        _ => None,
    })?;
    module.element_layout(id)
}

/// The layout of the element struct of the storage buffer held by the variable `variable`: a
/// block whose first member is a runtime array of that struct. The layout is named as the
/// SPIR-V names the struct.
pub(crate) fn buffer_element_layout(words: &[u32], variable: &str) -> Option<StructLayout> {
    let module = parse(words);
    let pointer = module.variables.iter().find_map(|(id, pointer)| {
        (module.names.get(id).map(String::as_str) == Some(variable)).then_some(pointer)
    })?;
    let block = module.pointees.get(pointer)?;
    let [OP_TYPE_STRUCT, _, array, ..] = module.types.get(block)?.as_slice() else {
        return None;
    };
    let [OP_TYPE_RUNTIME_ARRAY, _, element] = module.types.get(array)?.as_slice() else {
        return None;
    };
    module.element_layout(*element)
}

/// The signatures of the functions named `name` in the module, in module order; with `called`,
/// only those some instruction calls (in a kernel: the overload the kernel chose).
#[cfg(feature = "gpu")]
pub(crate) fn signatures(words: &[u32], name: &str, called: bool) -> Vec<Signature> {
    let module = parse(words);
    module
        .functions
        .iter()
        .filter(|(id, _, _)| module.is_named(*id, name) && (!called || module.callees.contains(id)))
        .filter_map(|(_, function_type, parameters)| module.signature(*function_type, parameters))
        .collect()
}
