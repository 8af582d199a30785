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

pub mod agreement;
pub mod conditioning;
pub mod degenerate;
pub mod exact;
pub mod fuzzing;
pub mod order;
pub mod pages;
pub mod ray_cone;
pub mod ray_diff;
pub mod ray_diff_f64;
mod record;
mod records;
pub mod reference;
pub mod sections;
pub mod special;
pub mod strategy;
pub mod wireframe;

pub use record::{Function, IllConditioned, Promises, Record};
pub use records::{module_records, records, section_files};
