//! Every record, gathered once from the modules in the order of [`Module::ALL`], and the files of
//! each module's section folders.

use crate::record::Function;
use crate::{ray_cone, ray_diff, ray_diff_f64, wireframe};
use ray_footprint::shaders::Module;
use std::sync::OnceLock;

/// Every record, in module order (built once): each module's records, in the module's order.
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

/// Every file of `module`'s section folders, as `(folder, file stem)`, as the build script found
/// them: what [`crate::sections::check_sections`] holds to the module's banners.
pub fn section_files(module: Module) -> &'static [(&'static str, &'static str)] {
    match module {
        Module::RayCone => ray_cone::SECTION_FILES,
        Module::RayDiff => ray_diff::SECTION_FILES,
        Module::RayDiffF64 => ray_diff_f64::SECTION_FILES,
        Module::Wireframe => wireframe::SECTION_FILES,
    }
}
