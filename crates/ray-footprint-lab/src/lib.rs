//! ray-footprint on a GPU: the agreement suite that checks every shader function of the crate
//! against its Rust mirror with shader-proptest ([`checks`]), and a Vulkan ray-tracing renderer
//! that uses the modules as a user's renderer would ([`rt`]), with its gallery.
#![deny(missing_docs)]

pub mod checks;
pub mod rt;
