//! One record per public function of ray-footprint, and the runners that iterate the records.
//!
//! A [`Record`] declares once everything the verification of one function needs: its Rust mirror,
//! the strategy of its agreement cases, its tolerance (a bound derived from Vulkan's precision rules
//! or an interval enclosure), its documented degenerate inputs, and how the fuzzer draws its
//! arguments and what it promises. [`records`] lists every record in module order, and
//! [`order::check_order`] holds that list to the modules' public functions. The runners iterate it:
//!
//! - [`agreement::run_all_checks`]: the agreement checks in every language on one device (the
//!   lab's `verify` and its GPU tests), and each record's special-value check ([`special`]);
//! - [`degenerate`]: the degenerate-input table, rendered into the root crate's
//!   `src/degenerate.md` and run on the CPU and the GPU;
//! - [`fuzzing`]: the cargo-fuzz targets and the replay of their corpora;
//! - [`reference`](mod@reference): each function against independent references (exact geometry, f64 finite
//!   differences, closed forms computed another way, identities, peer originals), and the table of
//!   the root crate's `src/proven.md`.
//!
//! Not published: the product (`ray-footprint`) is the shader modules and the Rust mirror.

/// `records![function, ...]`: the records the named functions make, boxed, in the order given;
/// each section of a module lists its own functions with it.
macro_rules! records {
    ($($function:ident),+ $(,)?) => {
        vec![$(Box::new($function()) as Box<dyn $crate::Function>,)+]
    };
}

pub mod agreement;
pub mod degenerate;
pub mod exact;
pub mod fuzzing;
pub mod order;
pub mod ray_cone;
pub mod ray_diff;
pub mod ray_diff_f64;
mod record;
pub mod reference;
pub mod special;
pub mod strategy;
pub mod symmetry;
pub mod wireframe;

pub use record::{Function, IllConditioned, Promises, Record};

use ray_footprint::shaders::Module;
use std::sync::OnceLock;

/// Every record, in module order (built once): each module gathers its sections' records.
pub fn records() -> &'static [Box<dyn Function>] {
    static RECORDS: OnceLock<Vec<Box<dyn Function>>> = OnceLock::new();
    RECORDS.get_or_init(|| {
        [
            ray_cone::records(),
            ray_diff::records(),
            ray_diff_f64::records(),
            wireframe::records(),
        ]
        .into_iter()
        .flatten()
        .collect()
    })
}

/// The records of `module`, in the module's order.
pub fn module_records(module: Module) -> impl Iterator<Item = &'static dyn Function> {
    records()
        .iter()
        .filter(move |record| record.module() == module)
        .map(AsRef::as_ref)
}
