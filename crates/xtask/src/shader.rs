//! The shared declarations in WGSL, GLSL, Slang and HLSL: each item preceded by its doc comment's
//! first paragraph, struct fields by theirs.

use crate::comment;
use crate::rust_items::{Field, Item, Kind, RustItems, Type, Value};

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Language {
    Wgsl,
    Glsl,
    Slang,
    Hlsl,
}

impl Language {
    /// The languages of the shader modules with generated blocks; the Slang modules are generated
    /// whole from the HLSL ones (the renderer's Slang file has a block of its own).
    pub const WRITTEN: [Language; 3] = [Language::Wgsl, Language::Glsl, Language::Hlsl];

    /// The directory under `shaders/` and the file extension.
    pub fn extension(self) -> &'static str {
        match self {
            Language::Wgsl => "wgsl",
            Language::Glsl => "glsl",
            Language::Slang => "slang",
            Language::Hlsl => "hlsl",
        }
    }

    /// The marker of a documentation comment before a declaration.
    fn doc_marker(self) -> &'static str {
        match self {
            Language::Slang => "/// ",
            Language::Wgsl | Language::Glsl | Language::Hlsl => "// ",
        }
    }

    /// Declaration keywords before a constant's type (GLSL, Slang, HLSL) or name (WGSL).
    fn const_keywords(self) -> &'static str {
        match self {
            Language::Wgsl | Language::Glsl => "const",
            Language::Slang => "public static const",
            Language::Hlsl => "static const",
        }
    }

    fn type_name(self, ty: &Type, names: &RustItems) -> Result<String, String> {
        let name = match (self, ty) {
            (Language::Wgsl, Type::F32) => "f32",
            (Language::Wgsl, Type::F64) => "f64",
            (Language::Wgsl, Type::I32) => "i32",
            (Language::Wgsl, Type::U32) => "u32",
            (_, Type::F32) => "float",
            (_, Type::F64) => "double",
            (_, Type::I32) => "int",
            (_, Type::U32) => "uint",
            (_, Type::Bool) => "bool",
            (Language::Wgsl, Type::Matrix4) => "mat4x4<f32>",
            (Language::Glsl, Type::Matrix4) => "mat4",
            (Language::Slang | Language::Hlsl, Type::Matrix4) => "float4x4",
            (_, Type::Vector(components)) => return Ok(self.vector_type(*components)),
            (_, Type::UVector(components)) => return Ok(self.unsigned_vector_type(*components)),
            (_, Type::Struct(name)) => return Ok(names.get(name)?.shader_name.clone()),
        };
        Ok(name.to_string())
    }

    fn vector_type(self, components: usize) -> String {
        match self {
            Language::Wgsl => format!("vec{components}<f32>"),
            Language::Glsl => format!("vec{components}"),
            Language::Slang | Language::Hlsl => format!("float{components}"),
        }
    }

    fn unsigned_vector_type(self, components: usize) -> String {
        match self {
            Language::Wgsl => format!("vec{components}<u32>"),
            Language::Glsl => format!("uvec{components}"),
            Language::Slang | Language::Hlsl => format!("uint{components}"),
        }
    }

    /// A value of type `ty` in this language's syntax, with the exact value of the Rust literal.
    fn value(self, ty: &Type, value: &Value) -> Result<String, String> {
        match (ty, value) {
            (Type::Bool, Value::Bool(flag)) => Ok(flag.to_string()),
            (Type::F32, Value::Number(digits)) => float(digits),
            (Type::F64, Value::Number(digits)) => self.double(digits),
            (Type::I32, Value::Number(digits)) => integer::<i32>(digits),
            (Type::U32, Value::Number(digits)) => Ok(format!("{}u", integer::<u32>(digits)?)),
            (Type::Vector(components), Value::Vector(values)) if values.len() == *components => {
                let values: Vec<String> = values.iter().map(|v| float(v)).collect::<Result<_, _>>()?;
                Ok(format!(
                    "{}({})",
                    self.vector_type(*components),
                    values.join(", ")
                ))
            }
            _ => Err(format!("a value {value:?} that does not fit the type {ty:?}")),
        }
    }

    /// A double constant as a float literal widened to double: WGSL implementations and glslang
    /// disagreed on double literals, every compiler widens a float the same way. Only exact when
    /// the value is a float, which is checked.
    fn double(self, digits: &str) -> Result<String, String> {
        let value: f64 = digits.parse().map_err(|e| format!("{digits}: {e}"))?;
        if f64::from(value as f32) != value {
            return Err(format!(
                "the double {digits} is not a float value; a double constant must be one (it is written as a widened float literal)"
            ));
        }
        let literal = float(digits)?;
        Ok(match self {
            Language::Wgsl => format!("f64({literal}f)"),
            Language::Glsl => format!("double({literal})"),
            Language::Slang | Language::Hlsl => format!("double({literal}f)"),
        })
    }

    /// One item: its doc comment and declaration.
    pub fn item(self, item: &Item, names: &RustItems) -> Result<Vec<String>, String> {
        let mut lines = comment::lines(&item.docs, self.doc_marker(), names);
        let at = |error: String| format!("{}: `{}`: {error}", item.file, item.name);
        match &item.kind {
            Kind::Const { ty, value } => {
                let value = self.value(ty, value).map_err(at)?;
                let ty = self.type_name(ty, names).map_err(at)?;
                lines.push(self.constant(&item.shader_name, &ty, &value));
            }
            Kind::Preset { ty, values } => {
                let Kind::Struct { fields, .. } = &names.get(ty)?.kind else {
                    return Err(at(format!("`{ty}` is not a struct")));
                };
                let values: Vec<String> = fields
                    .iter()
                    .zip(values)
                    .map(|(field, value)| self.value(&field.ty, value))
                    .collect::<Result<_, _>>()
                    .map_err(at)?;
                let struct_name = &names.get(ty)?.shader_name;
                let value = self.struct_value(struct_name, &values);
                lines.push(self.constant(&item.shader_name, struct_name, &value));
            }
            Kind::Enum { variants } => {
                // The enum's own comment stands apart from its first variant's.
                if !lines.is_empty() {
                    lines.push(String::new());
                }
                let ty = self.type_name(&Type::U32, names)?;
                for variant in variants {
                    lines.extend(comment::lines(&variant.docs, self.doc_marker(), names));
                    let value = self
                        .value(&Type::U32, &Value::Number(variant.value.clone()))
                        .map_err(at)?;
                    lines.push(self.constant(&variant.shader_name, &ty, &value));
                }
            }
            Kind::Struct { fields, .. } => {
                lines.extend(self.structure(&item.shader_name, fields, names).map_err(at)?)
            }
            Kind::Unreadable(reason) => return Err(at(reason.clone())),
        }
        Ok(lines)
    }

    /// A struct value from its field values in order: a constructor call, or in HLSL (which has
    /// no struct constructors) an initializer list.
    fn struct_value(self, struct_name: &str, values: &[String]) -> String {
        match self {
            Language::Hlsl => format!("{{ {} }}", values.join(", ")),
            Language::Wgsl | Language::Glsl | Language::Slang => {
                format!("{struct_name}({})", values.join(", "))
            }
        }
    }

    fn constant(self, name: &str, ty: &str, value: &str) -> String {
        let keywords = self.const_keywords();
        match self {
            Language::Wgsl => format!("{keywords} {name}: {ty} = {value};"),
            Language::Glsl | Language::Slang | Language::Hlsl => format!("{keywords} {ty} {name} = {value};"),
        }
    }

    fn structure(self, name: &str, fields: &[Field], names: &RustItems) -> Result<Vec<String>, String> {
        let public = if self == Language::Slang { "public " } else { "" };
        let mut lines = vec![format!("{public}struct {name} {{")];
        for field in fields {
            let prefix = format!("    {}", self.doc_marker());
            lines.extend(comment::lines(&field.docs, &prefix, names));
            let ty = self.type_name(&field.ty, names)?;
            lines.push(match self {
                Language::Wgsl => format!("    {}: {ty},", field.name),
                Language::Glsl | Language::Slang | Language::Hlsl => {
                    format!("    {public}{ty} {};", field.name)
                }
            });
        }
        lines.push(match self {
            Language::Wgsl => "}".to_string(),
            Language::Glsl | Language::Slang | Language::Hlsl => "};".to_string(),
        });
        Ok(lines)
    }
}

/// A float literal: the Rust digits, with `.0` added to a whole number.
fn float(digits: &str) -> Result<String, String> {
    digits.parse::<f64>().map_err(|e| format!("{digits}: {e}"))?;
    if digits.contains(['.', 'e', 'E']) {
        Ok(digits.to_string())
    } else {
        Ok(format!("{digits}.0"))
    }
}

/// An integer literal whose value the shader type `T` holds.
fn integer<T: std::str::FromStr<Err = std::num::ParseIntError>>(digits: &str) -> Result<String, String> {
    digits.parse::<T>().map_err(|e| format!("{digits}: {e}"))?;
    Ok(digits.to_string())
}
