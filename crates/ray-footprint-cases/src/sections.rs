//! The sections of each shader module, and the folders their case files live in.
//!
//! A module's Rust mirror (`src/<module>.rs` of the root crate) and its shader files divide its
//! functions into sections with banners `// ---- Title ----`, the same in every language
//! (`tests/module_parity.rs`). Each section has a folder `src/<module>/<folder>/` in this crate,
//! named by a word of its title ([`folders`], in banner order), and each function's case file
//! `<function>.rs` lies in the folder of the section whose banner precedes the function.
//! [`check_sections`] holds a module's folders and files to its banners and names the first
//! offender.
//!
//! ```
//! use ray_footprint::shaders::Module;
//! use ray_footprint_cases::sections::{check_sections, SectionError};
//!
//! let mirror = "// ---- Settings from the host ----\npub fn unpack_wireframe_settings() {}\n\
//!               // ---- Coverage ----\npub fn edge_position() {}\n";
//! let files = [("settings", "unpack_wireframe_settings"), ("settings", "edge_position")];
//! assert_eq!(
//!     check_sections(Module::Wireframe, mirror, &files),
//!     Err(SectionError::Misplaced {
//!         module: Module::Wireframe,
//!         function: "edge_position".to_string(),
//!         folder: "settings".to_string(),
//!         section: "coverage",
//!     })
//! );
//! ```

use ray_footprint::shaders::Module;

/// The section folders of `module`, one per section banner, in banner order: each a word of its
/// banner's title.
pub fn folders(module: Module) -> &'static [&'static str] {
    match module {
        Module::RayCone => &[
            "packing",
            "cameras",
            "propagation",
            "surface",
            "curvature",
            "footprint",
            "refraction",
            "scattering",
        ],
        Module::RayDiff => &[
            "camera",
            "transfer",
            "derivatives",
            "reflection",
            "gbuffer",
            "mapping",
            "reintersection",
            "cones",
        ],
        Module::RayDiffF64 => &["reintersection"],
        Module::Wireframe => &["settings", "coverage"],
    }
}

/// Why a module's section folders or case files do not follow its banners.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SectionError {
    /// A banner has no folder in [`folders`].
    NoFolder {
        /// The module.
        module: Module,
        /// The banner's title.
        banner: String,
    },
    /// A folder of [`folders`] has no banner.
    NoBanner {
        /// The module.
        module: Module,
        /// The folder.
        folder: &'static str,
    },
    /// A folder of [`folders`] is no word of the title of the banner in its place.
    NotItsTitle {
        /// The module.
        module: Module,
        /// The folder.
        folder: &'static str,
        /// The title of the banner in its place.
        banner: String,
    },
    /// A folder of the crate is none of the module's section folders.
    UnknownFolder {
        /// The module.
        module: Module,
        /// The folder.
        folder: String,
    },
    /// A function's case file lies in another section's folder.
    Misplaced {
        /// The module.
        module: Module,
        /// The function.
        function: String,
        /// The folder its case file lies in.
        folder: String,
        /// The folder of the section whose banner precedes the function.
        section: &'static str,
    },
}

impl std::fmt::Display for SectionError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SectionError::NoFolder { module, banner } => write!(
                f,
                "{}: the banner `{banner}` has no section folder in `sections::folders`",
                module.stem()
            ),
            SectionError::NoBanner { module, folder } => write!(
                f,
                "{}: the section folder `{folder}` has no banner in src/{}.rs",
                module.stem(),
                module.stem()
            ),
            SectionError::NotItsTitle {
                module,
                folder,
                banner,
            } => write!(
                f,
                "{}: the section folder `{folder}` is no word of the banner in its place, `{banner}`",
                module.stem()
            ),
            SectionError::UnknownFolder { module, folder } => write!(
                f,
                "src/{}/{folder}/: no section of {} has this folder (its sections: {})",
                module.stem(),
                module.stem(),
                folders(*module).join(", ")
            ),
            SectionError::Misplaced {
                module,
                function,
                folder,
                section,
            } => write!(
                f,
                "src/{}/{folder}/{function}.rs: `{function}` follows the banner of the section whose \
                 folder is `{section}`: the file belongs in src/{}/{section}/",
                module.stem(),
                module.stem()
            ),
        }
    }
}

impl std::error::Error for SectionError {}

/// The titles of the section banners of `mirror` (a Rust mirror module's source), in order, each
/// with those of `functions` declared under it.
fn banners<'a>(mirror: &'a str, functions: &[&'static str]) -> Vec<(&'a str, Vec<&'static str>)> {
    let mut banners: Vec<(&str, Vec<&str>)> = Vec::new();
    for line in mirror.lines() {
        let title = line
            .strip_prefix("// ---- ")
            .and_then(|rest| rest.strip_suffix(" ----"));
        if let Some(title) = title {
            banners.push((title, Vec::new()));
        } else if let Some(rest) = line.strip_prefix("pub fn ") {
            let declared = functions.iter().find(|function| {
                rest.strip_prefix(**function)
                    .is_some_and(|after| after.starts_with('('))
            });
            if let (Some(&function), Some((_, under))) = (declared, banners.last_mut()) {
                under.push(function);
            }
        }
    }
    banners
}

/// Whether `folder` is a word of `title`, hyphens dropped and case ignored ("gbuffer" of
/// "G-buffer differentials").
fn is_word_of(folder: &str, title: &str) -> bool {
    title
        .replace('-', "")
        .to_lowercase()
        .split(|c: char| !c.is_alphanumeric())
        .any(|word| word == folder)
}

/// Checks `module`'s section folders against the banners of its mirror source `mirror`: each
/// folder of [`folders`] is a word of the banner in its place, in banner order; each folder of
/// `files` (`(folder, file stem)`, every file of the crate's section folders) is one of them; and
/// each case file (a file named after a function of the module) lies in the folder of the section
/// whose banner precedes its function. The error names the first offender.
pub fn check_sections(module: Module, mirror: &str, files: &[(&str, &str)]) -> Result<(), SectionError> {
    let functions = module.functions();
    let banners = banners(mirror, &functions);
    let expected = folders(module);
    for index in 0..banners.len().max(expected.len()) {
        match (expected.get(index), banners.get(index)) {
            (Some(&folder), Some(&(title, _))) if !is_word_of(folder, title) => {
                return Err(SectionError::NotItsTitle {
                    module,
                    folder,
                    banner: title.to_string(),
                })
            }
            (None, Some(&(title, _))) => {
                return Err(SectionError::NoFolder {
                    module,
                    banner: title.to_string(),
                })
            }
            (Some(&folder), None) => return Err(SectionError::NoBanner { module, folder }),
            _ => {}
        }
    }
    for &(folder, _) in files {
        if !expected.contains(&folder) {
            return Err(SectionError::UnknownFolder {
                module,
                folder: folder.to_string(),
            });
        }
    }
    for &(folder, file) in files {
        let section = expected
            .iter()
            .zip(&banners)
            .find(|(_, (_, under))| under.contains(&file))
            .map(|(&section, _)| section);
        match section {
            Some(section) if section != folder => {
                return Err(SectionError::Misplaced {
                    module,
                    function: file.to_string(),
                    folder: folder.to_string(),
                    section,
                })
            }
            _ => {}
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A wireframe mirror with its two banners, one function under each.
    const MIRROR: &str =
        "// ---- Settings from the host ----\npub fn unpack_wireframe_settings(io: u32) {}\n\
                          // ---- Coverage (wireframe tutorial) ----\npub fn edge_position(b: f32) {}\n";

    #[test]
    fn files_in_their_sections_pass() {
        let files = [
            ("settings", "unpack_wireframe_settings"),
            ("coverage", "edge_position"),
            ("coverage", "shared"),
        ];
        assert_eq!(check_sections(Module::Wireframe, MIRROR, &files), Ok(()));
    }

    #[test]
    fn a_file_in_another_section_is_misplaced() {
        let files = [("coverage", "unpack_wireframe_settings")];
        let error = SectionError::Misplaced {
            module: Module::Wireframe,
            function: "unpack_wireframe_settings".to_string(),
            folder: "coverage".to_string(),
            section: "settings",
        };
        assert_eq!(
            check_sections(Module::Wireframe, MIRROR, &files),
            Err(error.clone())
        );
        assert_eq!(
            error.to_string(),
            "src/wireframe/coverage/unpack_wireframe_settings.rs: `unpack_wireframe_settings` follows \
             the banner of the section whose folder is `settings`: the file belongs in \
             src/wireframe/settings/"
        );
    }

    #[test]
    fn an_unknown_folder_is_named() {
        let files = [("lines", "edge_position")];
        let error = SectionError::UnknownFolder {
            module: Module::Wireframe,
            folder: "lines".to_string(),
        };
        assert_eq!(
            check_sections(Module::Wireframe, MIRROR, &files),
            Err(error.clone())
        );
        assert_eq!(
            error.to_string(),
            "src/wireframe/lines/: no section of wireframe has this folder (its sections: settings, coverage)"
        );
    }

    #[test]
    fn banners_in_another_order_are_not_their_folders() {
        let swapped = "// ---- Coverage ----\npub fn edge_position(b: f32) {}\n\
                       // ---- Settings from the host ----\npub fn unpack_wireframe_settings(io: u32) {}\n";
        assert_eq!(
            check_sections(Module::Wireframe, swapped, &[]),
            Err(SectionError::NotItsTitle {
                module: Module::Wireframe,
                folder: "settings",
                banner: "Coverage".to_string(),
            })
        );
    }

    #[test]
    fn a_banner_more_or_less_is_named() {
        let more = format!("{MIRROR}// ---- Stipple ----\n");
        assert_eq!(
            check_sections(Module::Wireframe, &more, &[]),
            Err(SectionError::NoFolder {
                module: Module::Wireframe,
                banner: "Stipple".to_string(),
            })
        );
        let less = "// ---- Settings from the host ----\npub fn unpack_wireframe_settings(io: u32) {}\n";
        assert_eq!(
            check_sections(Module::Wireframe, less, &[]),
            Err(SectionError::NoBanner {
                module: Module::Wireframe,
                folder: "coverage",
            })
        );
    }

    #[test]
    fn hyphens_and_case_are_dropped_from_titles() {
        assert!(is_word_of(
            "gbuffer",
            "Surface spread from G-buffer derivatives (RTG Eq. 31-33)"
        ));
        assert!(is_word_of(
            "reintersection",
            "Re-intersection of the neighbour rays (RTG Eq. 13)"
        ));
        assert!(!is_word_of("packing", "Primary cones from cameras (RTG Eq. 30)"));
    }
}
