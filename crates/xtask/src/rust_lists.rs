//! The Rust lists that repeat the shared structs' fields: shader-proptest's `Value` declarations
//! (`src/values.rs`), the layout list of `src/abi.rs` and the build script's table of structs
//! whose layouts it asserts (`build.rs`); the renderer's layout list (`rt/abi.rs` of the lab).

use crate::blocks::Block;
use crate::rust_items::{Item, Kind, RustItems, Type};

/// A struct of a shader module, with the module's stem.
pub struct ModuleStruct<'a> {
    pub stem: &'a str,
    pub item: &'a Item,
}

impl ModuleStruct<'_> {
    fn fields(&self) -> &[crate::rust_items::Field] {
        match &self.item.kind {
            Kind::Struct { fields, .. } => fields,
            _ => &[],
        }
    }

    /// Whether the struct crosses the CPU/GPU boundary: bytemuck `Pod`, so one byte layout.
    fn is_pod(&self) -> bool {
        matches!(self.item.kind, Kind::Struct { pod: true, .. })
    }

    /// `Module::RayCone` for `ray_cone`.
    fn module_variant(&self) -> String {
        let camel: String = self
            .stem
            .split('_')
            .map(|word| {
                let mut chars = word.chars();
                chars
                    .next()
                    .map(|first| first.to_uppercase().chain(chars).collect())
                    .unwrap_or_default()
            })
            .collect::<Vec<String>>()
            .concat();
        format!("Module::{camel}")
    }
}

fn rust_type(ty: &Type) -> String {
    match ty {
        Type::F32 => "f32".to_string(),
        Type::F64 => "f64".to_string(),
        Type::I32 => "i32".to_string(),
        Type::U32 => "u32".to_string(),
        Type::Bool => "bool".to_string(),
        Type::Vector(components) => format!("Vec{components}"),
        Type::UVector(components) => format!("[u32; {components}]"),
        Type::Matrix4 => "Mat4".to_string(),
        Type::Struct(name) => name.clone(),
    }
}

fn sources(structs: &[ModuleStruct]) -> Vec<String> {
    let mut files: Vec<String> = Vec::new();
    for module_struct in structs {
        if !files.contains(&module_struct.item.file) {
            files.push(module_struct.item.file.clone());
        }
    }
    files
}

/// `src/values.rs`: one `shader_struct!` per struct, `pod` for those that cross the boundary.
pub fn values(structs: &[ModuleStruct]) -> Block {
    let lines = structs
        .iter()
        .map(|module_struct| {
            let name = &module_struct.item.name;
            let fields: Vec<String> = module_struct
                .fields()
                .iter()
                .map(|field| format!("{}: {}", field.name, rust_type(&field.ty)))
                .collect();
            let pod = if module_struct.is_pod() { "pod " } else { "" };
            format!(
                "shader_struct!({pod}{name} as \"{}\" {{ {} }});",
                module_struct.item.shader_name,
                fields.join(", ")
            )
        })
        .collect();
    Block {
        sources: sources(structs),
        lines,
    }
}

/// `src/abi.rs`: `shared_layouts`, the Rust layout of every struct that crosses the boundary.
pub fn layouts(structs: &[ModuleStruct]) -> Block {
    let shared: Vec<&ModuleStruct> = structs.iter().filter(|s| s.is_pod()).collect();
    // The doc comment, with its example, stays above the block, written by hand.
    let mut lines = vec![
        "#[cfg(feature = \"validate\")]".to_string(),
        "#[rustfmt::skip]".to_string(),
        "pub fn shared_layouts() -> Vec<(crate::shaders::Module, crate::layout::StructLayout)> {".to_string(),
        "    use crate::rust_layout;".to_string(),
        "    use crate::shaders::Module;".to_string(),
        "    vec![".to_string(),
    ];
    for module_struct in &shared {
        let name = &module_struct.item.name;
        let fields: Vec<&str> = module_struct.fields().iter().map(|f| f.name.as_str()).collect();
        lines.push(format!(
            "        ({}, rust_layout!({name} as \"{}\" {{ {} }})),",
            module_struct.module_variant(),
            module_struct.item.shader_name,
            fields.join(", ")
        ));
    }
    lines.extend(["    ]".to_string(), "}".to_string()]);
    Block {
        sources: sources(structs),
        lines,
    }
}

/// `build.rs`: the module, shader name and Rust path of every struct that crosses the boundary.
pub fn build_table(structs: &[ModuleStruct]) -> Block {
    let lines = structs
        .iter()
        .filter(|s| s.is_pod())
        .map(|module_struct| {
            let item = module_struct.item;
            format!(
                "        ({}, \"{}\", \"{}\"),",
                module_struct.module_variant(),
                item.shader_name,
                item.path
            )
        })
        .collect();
    Block {
        sources: sources(structs),
        lines,
    }
}

/// The lab's `rt/abi.rs`: `layouts`, the Rust layout of each of the renderer's `structs`, under
/// the name its shaders give it.
pub fn renderer_layouts(structs: &[&Item]) -> Block {
    let mut lines = vec![
        "/// Every struct the renderer's shaders share with Rust, with its Rust layout.".to_string(),
        "#[rustfmt::skip]".to_string(),
        "pub fn layouts() -> Vec<shader_proptest::layout::StructLayout> {".to_string(),
        "    use shader_proptest::rust_layout;".to_string(),
        "    vec![".to_string(),
    ];
    let mut files: Vec<String> = Vec::new();
    for item in structs {
        let Kind::Struct { fields, .. } = &item.kind else {
            continue;
        };
        let fields: Vec<&str> = fields.iter().map(|f| f.name.as_str()).collect();
        lines.push(format!(
            "        rust_layout!({} as \"{}\" {{ {} }}),",
            item.name,
            item.shader_name,
            fields.join(", ")
        ));
        if !files.contains(&item.file) {
            files.push(item.file.clone());
        }
    }
    lines.extend(["    ]".to_string(), "}".to_string()]);
    Block {
        sources: files,
        lines,
    }
}

/// The structs of the shader blocks, in block order.
pub fn module_structs<'a>(
    shader_blocks: &[(&'a str, &[&[&str]])],
    names: &'a RustItems,
) -> Result<Vec<ModuleStruct<'a>>, String> {
    let mut structs = Vec::new();
    for (stem, blocks) in shader_blocks {
        for name in blocks.iter().flat_map(|items| items.iter()) {
            let item = names.get(name)?;
            if matches!(item.kind, Kind::Struct { .. }) {
                structs.push(ModuleStruct { stem, item });
            }
        }
    }
    Ok(structs)
}
