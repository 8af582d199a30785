//! The records of the ray_diff module, one case file per function, in the folder of the function's
//! section.
//!
//! Every tolerance is the width of an enclosure: the record re-evaluates its function in interval
//! arithmetic on the same inputs, widening after each operation by the rounding error that Vulkan's
//! precision rules allow the device (and that the mirror makes), so both results lie inside. A
//! function's re-evaluation, in the module's order of operations, is in its case file; where the
//! mirror calls another public function, the enclosure calls that function's. The references'
//! bounds take the mirror's rounding from the same enclosures (`reference.rs`).
//!
//! The module declarations and the record list are written by the build script from the folders.

include!(concat!(env!("OUT_DIR"), "/ray_diff.rs"));
