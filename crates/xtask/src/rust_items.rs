//! Reads the shared declarations from Rust sources with `syn`: public constants of a scalar type,
//! public structs with named fields, presets (public constants of a struct type written as a struct
//! literal with its fields in declaration order), and public `#[repr(u32)]` enums whose variants
//! all have a literal discriminant. Each source file names its items in the shaders by its
//! [`Naming`].

use std::collections::BTreeMap;
use std::path::Path;

/// A type that crosses the CPU/GPU boundary.
#[derive(Clone, Debug, PartialEq)]
pub enum Type {
    F32,
    F64,
    I32,
    U32,
    Bool,
    /// glam's `Vec2`, `Vec3`, `Vec4`: the number of f32 components.
    Vector(usize),
    /// `[u32; N]` for N = 2 to 4, a `uvecN`: the number of components. The array's alignment is a
    /// `u32`'s, the vector's that of its size; the layout tests hold each field's offset.
    UVector(usize),
    /// glam's `Mat4`: four f32 columns of four.
    Matrix4,
    /// Another shared struct, by its Rust name.
    Struct(String),
}

/// A constant value, its literals as the Rust source spells them without `_` and suffix.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A float or integer literal, possibly negated.
    Number(String),
    Bool(bool),
    /// `VecN::new(..)`.
    Vector(Vec<String>),
}

#[derive(Clone, Debug)]
pub struct Field {
    pub name: String,
    pub ty: Type,
    pub docs: Vec<String>,
}

#[derive(Clone, Debug)]
pub enum Kind {
    Const {
        ty: Type,
        value: Value,
    },
    Struct {
        fields: Vec<Field>,
        pod: bool,
    },
    Preset {
        ty: String,
        values: Vec<Value>,
    },
    /// A `#[repr(u32)]` enum: one `u32` constant per variant.
    Enum {
        variants: Vec<Variant>,
    },
    /// A public item the generator cannot translate, with the reason; an error only when a
    /// generated block asks for it.
    Unreadable(String),
}

/// An enum variant: its constant's name in the shaders, its discriminant and its doc comment.
#[derive(Clone, Debug)]
pub struct Variant {
    pub name: String,
    pub shader_name: String,
    pub value: String,
    pub docs: Vec<String>,
}

/// How a source file's items are named in the shaders: a prefix before a struct's Rust name and
/// before a constant's, and the prefix of the shader twins of its public functions, if it has any.
#[derive(Clone, Copy, Debug)]
pub struct Naming {
    pub struct_prefix: &'static str,
    pub constant_prefix: &'static str,
    pub function_prefix: Option<&'static str>,
}

/// The library's modules: `RayCone` is `RfRayCone`, `MIN_COS` is `RF_MIN_COS`, `width_at` is
/// `rf_width_at`.
pub const LIBRARY: Naming = Naming {
    struct_prefix: "Rf",
    constant_prefix: "RF_",
    function_prefix: Some("rf_"),
};

/// The lab's renderer: its structs keep their Rust names (`RtPushConstants`), a constant gets
/// `RT_` (`RT_FLAG_GLOSSY_LOBE`), a variant of enum `Mode` is `RT_MODE_` and its name in capitals
/// (`Mode::ConeCurvature` is `RT_MODE_CONE_CURVATURE`); its functions have no shader twins.
pub const RENDERER: Naming = Naming {
    struct_prefix: "",
    constant_prefix: "RT_",
    function_prefix: None,
};

/// One shared declaration and where it is written.
#[derive(Clone, Debug)]
pub struct Item {
    pub name: String,
    /// The name the shaders give it (an enum's, which only its variants have, is its Rust name).
    pub shader_name: String,
    /// The file, relative to the repository root, e.g. `src/wireframe.rs`.
    pub file: String,
    /// The Rust module path of the item, e.g. `crate::wireframe::WireframeSettingsIo`.
    pub path: String,
    pub docs: Vec<String>,
    pub kind: Kind,
}

impl Item {
    /// The item `name` of `file`, named `shader_name` in the shaders, documented by the doc
    /// comments among `attrs`.
    fn new(file: &str, name: String, shader_name: String, attrs: &[syn::Attribute], kind: Kind) -> Item {
        Item {
            path: module_path(file, &name),
            shader_name,
            name,
            file: file.to_string(),
            docs: docs(attrs),
            kind,
        }
    }
}

/// Every shared declaration of the files, by name, and their public functions with their shader
/// names (where the file's [`Naming`] gives its functions shader twins).
pub struct RustItems {
    pub items: BTreeMap<String, Item>,
    pub functions: BTreeMap<String, String>,
}

impl RustItems {
    pub fn get(&self, name: &str) -> Result<&Item, String> {
        let item = self
            .items
            .get(name)
            .ok_or_else(|| format!("`{name}` is not a public constant or struct of the Rust sources"))?;
        match &item.kind {
            Kind::Unreadable(reason) => Err(format!("{}: `{name}`: {reason}", item.file)),
            _ => Ok(item),
        }
    }
}

/// Parses each file (relative to `root`) and collects its shared declarations, named by the
/// file's [`Naming`]. Two public items of one name are an error.
pub fn read(root: &Path, files: &[(&str, Naming)]) -> Result<RustItems, String> {
    let mut parsed = Vec::new();
    for &(file, naming) in files {
        let text = std::fs::read_to_string(root.join(file)).map_err(|e| format!("{file}: {e}"))?;
        let syntax = syn::parse_file(&text).map_err(|e| format!("{file}: {e}"))?;
        parsed.push((file, naming, syntax));
    }
    let mut items = BTreeMap::new();
    let mut functions = BTreeMap::new();
    // Structs first, so that a preset can be checked against its struct's fields.
    for (file, naming, syntax) in &parsed {
        for item in &syntax.items {
            let shared = match item {
                syn::Item::Struct(item) => read_struct(file, naming, item),
                syn::Item::Enum(item) if is_pub(&item.vis) => Some(read_enum(file, naming, item)),
                _ => None,
            };
            if let Some(shared) = shared {
                insert(&mut items, shared)?;
            }
        }
    }
    for (file, naming, syntax) in &parsed {
        for item in &syntax.items {
            match item {
                syn::Item::Const(item) if is_pub(&item.vis) => {
                    let shared = read_const(file, naming, item, &items);
                    insert(&mut items, shared)?;
                }
                syn::Item::Fn(item) if is_pub(&item.vis) => {
                    if let Some(prefix) = naming.function_prefix {
                        let name = item.sig.ident.to_string();
                        functions.insert(name.clone(), format!("{prefix}{name}"));
                    }
                }
                _ => {}
            }
        }
    }
    Ok(RustItems { items, functions })
}

/// Adds `item`, unless an item of its name is there already.
fn insert(items: &mut BTreeMap<String, Item>, item: Item) -> Result<(), String> {
    match items.get(&item.name) {
        Some(first) => Err(format!(
            "`{}` is declared in {} and in {}: shared items need one name each",
            item.name, first.file, item.file
        )),
        None => {
            items.insert(item.name.clone(), item);
            Ok(())
        }
    }
}

fn is_pub(vis: &syn::Visibility) -> bool {
    matches!(vis, syn::Visibility::Public(_))
}

fn module_path(file: &str, name: &str) -> String {
    let stem = Path::new(file)
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or(file);
    format!("crate::{stem}::{name}")
}

/// The doc comment, one entry per line, without the leading space.
fn docs(attrs: &[syn::Attribute]) -> Vec<String> {
    attrs
        .iter()
        .filter(|attr| attr.path().is_ident("doc"))
        .filter_map(|attr| match &attr.meta {
            syn::Meta::NameValue(syn::MetaNameValue {
                value:
                    syn::Expr::Lit(syn::ExprLit {
                        lit: syn::Lit::Str(text),
                        ..
                    }),
                ..
            }) => Some(text.value()),
            _ => None,
        })
        .map(|line| line.strip_prefix(' ').unwrap_or(&line).to_string())
        .collect()
}

/// Whether a `#[derive(..)]` of the item names `Pod`.
fn derives_pod(attrs: &[syn::Attribute]) -> bool {
    attrs
        .iter()
        .filter(|attr| attr.path().is_ident("derive"))
        .any(|attr| {
            let mut pod = false;
            let _ = attr.parse_nested_meta(|meta| {
                pod |= meta
                    .path
                    .segments
                    .last()
                    .is_some_and(|segment| segment.ident == "Pod");
                Ok(())
            });
            pod
        })
}

fn type_name(ty: &syn::Type) -> Option<String> {
    match ty {
        syn::Type::Path(path) if path.qself.is_none() => {
            path.path.segments.last().map(|segment| segment.ident.to_string())
        }
        _ => None,
    }
}

fn shared_type(ty: &syn::Type) -> Result<Type, String> {
    if let syn::Type::Array(array) = ty {
        let components = match number(&array.len).as_deref() {
            Ok("2") => 2,
            Ok("3") => 3,
            Ok("4") => 4,
            _ => 0,
        };
        return match type_name(&array.elem).as_deref() {
            Some("u32") if components > 0 => Ok(Type::UVector(components)),
            _ => Err("an array other than `[u32; N]` for N = 2 to 4".to_string()),
        };
    }
    let name = type_name(ty).ok_or("a type that is not a plain name")?;
    Ok(match name.as_str() {
        "f32" => Type::F32,
        "f64" => Type::F64,
        "i32" => Type::I32,
        "u32" => Type::U32,
        "bool" => Type::Bool,
        "Vec2" => Type::Vector(2),
        "Vec3" => Type::Vector(3),
        "Vec4" => Type::Vector(4),
        "Mat4" => Type::Matrix4,
        _ if name.chars().next().is_some_and(char::is_uppercase) => Type::Struct(name),
        _ => return Err(format!("the type `{name}`, which has no shader twin")),
    })
}

/// A public struct with named fields, or `None` for other structs (tuple structs, private ones).
fn read_struct(file: &str, naming: &Naming, item: &syn::ItemStruct) -> Option<Item> {
    let syn::Fields::Named(named) = &item.fields else {
        return None;
    };
    if !is_pub(&item.vis) {
        return None;
    }
    let name = item.ident.to_string();
    let fields: Result<Vec<Field>, String> = named
        .named
        .iter()
        .map(|field| {
            let field_name = field.ident.as_ref().map(ToString::to_string).unwrap_or_default();
            let ty = shared_type(&field.ty).map_err(|e| format!("field `{field_name}` has {e}"))?;
            Ok(Field {
                name: field_name,
                ty,
                docs: docs(&field.attrs),
            })
        })
        .collect();
    let kind = match fields {
        Ok(fields) => Kind::Struct {
            fields,
            pod: derives_pod(&item.attrs),
        },
        Err(reason) => Kind::Unreadable(reason),
    };
    let shader_name = format!("{}{name}", naming.struct_prefix);
    Some(Item::new(file, name, shader_name, &item.attrs, kind))
}

fn read_const(file: &str, naming: &Naming, item: &syn::ItemConst, structs: &BTreeMap<String, Item>) -> Item {
    let name = item.ident.to_string();
    // A count the host indexes with is a `usize` in Rust and a `u32` in the shaders.
    let ty = match type_name(&item.ty).as_deref() {
        Some("usize") => Ok(Type::U32),
        _ => shared_type(&item.ty),
    };
    let kind = match ty {
        Ok(Type::Struct(struct_name)) => match read_preset(&item.expr, &struct_name, structs) {
            Ok(values) => Kind::Preset {
                ty: struct_name,
                values,
            },
            Err(reason) => Kind::Unreadable(reason),
        },
        Ok(ty) => match read_value(&item.expr) {
            Ok(value) => Kind::Const { ty, value },
            Err(reason) => Kind::Unreadable(reason),
        },
        Err(reason) => Kind::Unreadable(format!("has {reason}")),
    };
    let shader_name = format!("{}{name}", naming.constant_prefix);
    Item::new(file, name, shader_name, &item.attrs, kind)
}

/// A public enum: with `#[repr(u32)]` and a literal discriminant on every (fieldless) variant, one
/// constant per variant, `{constant prefix}{ENUM}_{VARIANT}` in capitals with `_` between words.
fn read_enum(file: &str, naming: &Naming, item: &syn::ItemEnum) -> Item {
    let name = item.ident.to_string();
    let repr_u32 = item.attrs.iter().any(|attr| {
        attr.path().is_ident("repr") && attr.parse_args::<syn::Ident>().is_ok_and(|ty| ty == "u32")
    });
    let variants: Result<Vec<Variant>, String> = item
        .variants
        .iter()
        .map(|variant| {
            let value = match (&variant.fields, &variant.discriminant) {
                (syn::Fields::Unit, Some((_, expr))) if repr_u32 => number(expr)?,
                _ => {
                    return Err(format!(
                        "variant `{}` is not a unit variant with a literal discriminant under `#[repr(u32)]`",
                        variant.ident
                    ))
                }
            };
            let variant_name = variant.ident.to_string();
            Ok(Variant {
                shader_name: format!(
                    "{}{}_{}",
                    naming.constant_prefix,
                    capitals(&name),
                    capitals(&variant_name)
                ),
                name: variant_name,
                value,
                docs: docs(&variant.attrs),
            })
        })
        .collect();
    let kind = variants.map_or_else(Kind::Unreadable, |variants| Kind::Enum { variants });
    Item::new(file, name.clone(), name, &item.attrs, kind)
}

/// A camel-case name in capitals with `_` between its words: `RayDiffIsotropic` is
/// `RAY_DIFF_ISOTROPIC`, `Mip0` is `MIP0`.
fn capitals(camel: &str) -> String {
    let mut out = String::new();
    for (index, c) in camel.chars().enumerate() {
        if c.is_uppercase() && index > 0 {
            out.push('_');
        }
        out.extend(c.to_uppercase());
    }
    out
}

/// A struct literal whose fields appear in declaration order, each a plain value.
fn read_preset(
    expr: &syn::Expr,
    struct_name: &str,
    structs: &BTreeMap<String, Item>,
) -> Result<Vec<Value>, String> {
    let syn::Expr::Struct(literal) = expr else {
        return Err(format!(
            "a preset must be a `{struct_name} {{ .. }}` literal with every field in order"
        ));
    };
    let Some(Kind::Struct { fields, .. }) = structs.get(struct_name).map(|item| &item.kind) else {
        return Err(format!("`{struct_name}` is not a shared struct"));
    };
    let written: Vec<String> = literal
        .fields
        .iter()
        .map(|field| match &field.member {
            syn::Member::Named(ident) => ident.to_string(),
            syn::Member::Unnamed(index) => index.index.to_string(),
        })
        .collect();
    let declared: Vec<&str> = fields.iter().map(|field| field.name.as_str()).collect();
    if written != declared || literal.rest.is_some() {
        return Err(format!(
            "the literal lists the fields {written:?}; it must list {declared:?}, in that order"
        ));
    }
    literal
        .fields
        .iter()
        .map(|field| read_value(&field.expr))
        .collect()
}

/// A literal, a negated literal, or `VecN::new(literals)`.
fn read_value(expr: &syn::Expr) -> Result<Value, String> {
    match expr {
        syn::Expr::Lit(syn::ExprLit {
            lit: syn::Lit::Bool(value),
            ..
        }) => Ok(Value::Bool(value.value)),
        syn::Expr::Call(call) => {
            let callee = match &*call.func {
                syn::Expr::Path(path) => path.path.segments.iter().map(|s| s.ident.to_string()).collect(),
                _ => Vec::new(),
            };
            let components = match callee.iter().map(String::as_str).collect::<Vec<_>>().as_slice() {
                ["Vec2", "new"] => 2,
                ["Vec3", "new"] => 3,
                ["Vec4", "new"] => 4,
                _ => return Err("a call other than `VecN::new`".to_string()),
            };
            let values: Vec<String> = call.args.iter().map(number).collect::<Result<_, _>>()?;
            if values.len() != components {
                return Err(format!("{} components for a Vec{components}", values.len()));
            }
            Ok(Value::Vector(values))
        }
        _ => number(expr).map(Value::Number),
    }
}

fn number(expr: &syn::Expr) -> Result<String, String> {
    match expr {
        syn::Expr::Lit(syn::ExprLit {
            lit: syn::Lit::Float(value),
            ..
        }) => Ok(value.base10_digits().to_string()),
        syn::Expr::Lit(syn::ExprLit {
            lit: syn::Lit::Int(value),
            ..
        }) => Ok(value.base10_digits().to_string()),
        syn::Expr::Unary(syn::ExprUnary {
            op: syn::UnOp::Neg(_),
            expr,
            ..
        }) => Ok(format!("-{}", number(expr)?)),
        _ => Err("a value that is not a literal (write the number itself)".to_string()),
    }
}
