//! The agreement suite: every shader function of every module, checked against its mirror.

pub mod ray_cone;
pub mod ray_diff;
pub mod ray_diff_f64;
pub mod wireframe;

use super::check::Check;
use crate::shaders::Module;

/// Every check of one module, in the module's function order.
pub fn checks(module: Module) -> Vec<Box<dyn Check>> {
    match module {
        Module::RayCone => ray_cone::checks(),
        Module::RayDiff => ray_diff::checks(),
        Module::RayDiffF64 => ray_diff_f64::checks(),
        Module::Wireframe => wireframe::checks(),
    }
}

/// Every check of every module, in module order.
pub fn all_checks() -> Vec<Box<dyn Check>> {
    Module::ALL.iter().copied().flat_map(checks).collect()
}
