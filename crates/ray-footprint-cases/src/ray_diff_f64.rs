//! The records of the ray_diff_f64 module, one case file per function, in the folder of its one
//! section.
//!
//! Tolerances are enclosure widths as in [`crate::ray_diff`], with f64 budgets for every
//! intermediate operation (the same ULP counts in units of 2^-52) and half an f32 ULP for each
//! conversion back to f32. The references trace the same exact geometry as the f32
//! re-intersection's (the rays intersected with the triangle's plane as a 3x3 system in f64, the
//! neighbour rays taken to object space by the matrix's linear part), with the f64 functions' clamp
//! `F64_MAX_VALUE` and origins up to 1e8; their bounds are the enclosures' widths plus `1e-9` of
//! the largest value for the f64 inverse of the reference's well-conditioned 3x3 system.
//!
//! The module declarations and the record list are written by the build script from the folders.

include!(concat!(env!("OUT_DIR"), "/ray_diff_f64.rs"));
