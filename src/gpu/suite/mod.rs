//! The agreement suite: every shader function of every module, checked against its mirror.

pub mod ray_cone;

use super::check::Check;

/// Every check of every module, in module order.
pub fn checks() -> Vec<Box<dyn Check>> {
    ray_cone::checks()
}
