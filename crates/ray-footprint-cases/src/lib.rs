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
//! - [`degenerate`]: the degenerate rows, run on the CPU and the GPU; [`pages`] renders their
//!   table into the root crate's `src/degenerate.md`;
//! - [`fuzzing`]: the cargo-fuzz targets and the replay of their corpora;
//! - [`reference`](mod@reference): each function against independent references (exact geometry, f64 finite
//!   differences, closed forms computed another way, identities, peer originals), once as drawn and
//!   once more at scales from 2^-40 to 2^40 through each exact scale symmetry; [`pages`]
//!   renders the table of the root crate's `src/proven.md`;
//! - [`symmetry`]: the transformations each function's math respects (a scale with the function's
//!   degree, a rotation, a translation, an order or a sign exchanged), declared in its record or
//!   refused with a reason, run on the mirror (`tests/symmetries.rs`, 100,000 cases each) and on
//!   the device as metamorphic checks (the lab's GPU tests).
//!
//! # One file per function
//!
//! Each public function's proof is one file, its case file
//! `src/<module>/<section>/<function>.rs`: its record (`pub fn record()`), the interval enclosure its
//! tolerance uses, its case strategy, its degenerate rows, its references and whatever else only it
//! uses. `<section>` is the folder of the section whose banner (`// ---- Title ----`) precedes the
//! function in the root crate's `src/<module>.rs`, named by a word of the title
//! ([`sections::folders`]). What several functions of a section share lies in a file of the
//! section's folder (`shared.rs`); what several sections share, in a file of `src/<module>/`
//! (`bound.rs`, `strategy.rs`, ...); what several modules share, in this crate's own modules
//! ([`exact`], [`strategy`], [`conditioning`], ...).
//!
//! No list names the case files. The build script reads the folders and writes, for each module, the
//! module declarations of every file in them and the module's records in the module's order (a file
//! named after a public function of the module is that function's case file); `src/<module>.rs`
//! includes what it wrote. So adding a function adds its case file and edits nothing else here.
//! `tests/records.rs` names a function without a case file ([`order::check_order`]) and a case
//! file in another section's folder ([`sections::check_sections`]). `cargo fmt` does not see the case
//! files (only the build script declares them): format them with `rustfmt`, as CI does.
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
pub mod symmetry;
pub mod wireframe;

pub use record::{Function, IllConditioned, Promises, Record};
pub use records::{module_records, records, section_files};
