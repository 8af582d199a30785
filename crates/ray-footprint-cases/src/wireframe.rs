//! The records of the wireframe module, one case file per function, in the folder of the
//! function's section: `settings/` (Settings from the host) and `coverage/` (Coverage).
//!
//! Each tolerance is derived from the operations the function performs (see
//! [`shader_proptest::tolerance`]); the comment next to it says how. The wireframe's outputs have
//! thresholds (a dash boundary, a hard step) and a steep smoothstep: where a few ULP of difference
//! in an input may legitimately move the output across a threshold, the tolerance accepts either
//! side (as the ray-cone `curvature_sign` check does), and a smoothstep's error is its input's error
//! times its largest slope nearby.
//!
//! The module declarations and the record list are written by the build script from the folders.

include!(concat!(env!("OUT_DIR"), "/wireframe.rs"));
