//! The records of the ray-cone module, one case file per function, in the folder of the function's
//! section.
//!
//! Each tolerance is derived from the operations the function performs (see
//! [`shader_proptest::tolerance`]); the comment next to it says how. The shape operator and its
//! curvatures, refraction and roughness, which chain dozens of operations, take the width of an
//! interval enclosure, in the function's case file.
//!
//! The module declarations and the record list are written by the build script from the folders.

include!(concat!(env!("OUT_DIR"), "/ray_cone.rs"));
