//! Agreement checks of the ray_diff_f64 module, one per function, in the module's order.

use crate::gpu::check::Check;

/// Every check of the module.
pub fn checks() -> Vec<Box<dyn Check>> {
    vec![]
}
