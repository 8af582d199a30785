//! Registries with one item per shader function, in module order, and the check that keeps them
//! so.
//!
//! The workspace keeps several per-function lists: the agreement checks, the degenerate-input
//! tables, the fuzz entries. Each is a list of [`Registered`] items, built one module at a time in
//! the module's function order ([`Module::functions`]); [`check_registry`] finds the first item out
//! of place, and, for a list meant to cover every function, the first function missing.
//!
//! ```
//! use ray_footprint::registry::{check_registry, Coverage, Registered};
//! use ray_footprint::shaders::Module;
//!
//! let registry = vec![
//!     Registered::new(Module::RayCone, "width_at", 1),
//!     Registered::new(Module::RayCone, "propagate", 2),
//!     Registered::new(Module::Wireframe, "stipple", 3),
//! ];
//! assert!(check_registry(&registry, Coverage::Subset).is_ok());
//! assert!(check_registry(&registry, Coverage::Complete).is_err());
//! ```

use crate::shaders::Module;

/// An item that belongs to one function of a shader module.
#[derive(Clone, Debug, PartialEq)]
pub struct Registered<T> {
    /// The module declaring the function.
    pub module: Module,
    /// The function's Rust name (the shader name without `rf_`).
    pub function: &'static str,
    /// What the registry holds for the function.
    pub item: T,
}

impl<T> Registered<T> {
    /// `item`, registered for `function` of `module`.
    pub fn new(module: Module, function: &'static str, item: T) -> Self {
        Registered {
            module,
            function,
            item,
        }
    }

    /// The same registration holding `f(item)`.
    pub fn map<U>(self, f: impl FnOnce(T) -> U) -> Registered<U> {
        Registered::new(self.module, self.function, f(self.item))
    }
}

/// The registry of every module, from the registry of each one, in the order of [`Module::ALL`].
pub fn registry<T>(per_module: impl FnMut(Module) -> Vec<Registered<T>>) -> Vec<Registered<T>> {
    Module::ALL.iter().copied().flat_map(per_module).collect()
}

/// Which functions a registry must hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Coverage {
    /// Every function of every module.
    Complete,
    /// Any of them.
    Subset,
}

/// Why a registry is not in module order, or not complete.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RegistryError {
    /// The registered name is no function of its module.
    Unknown {
        /// The module it was registered in.
        module: Module,
        /// The name.
        function: &'static str,
    },
    /// The function comes after a function or module that follows it, or a second time.
    OutOfOrder {
        /// The function's module.
        module: Module,
        /// The function.
        function: &'static str,
    },
    /// A complete registry lacks the function.
    Missing {
        /// The function's module.
        module: Module,
        /// The first function missing.
        function: &'static str,
    },
}

impl std::fmt::Display for RegistryError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RegistryError::Unknown { module, function } => {
                write!(f, "{}: `{function}` is no function of the module", module.stem())
            }
            RegistryError::OutOfOrder { module, function } => write!(
                f,
                "{}: `{function}` is registered twice or after a function that follows it",
                module.stem()
            ),
            RegistryError::Missing { module, function } => {
                write!(f, "{}: `{function}` is missing", module.stem())
            }
        }
    }
}

impl std::error::Error for RegistryError {}

/// Checks that `registry` lists the functions of each module in the module's order, the modules in
/// the order of [`Module::ALL`], each function at most once, and with [`Coverage::Complete`]
/// every function. The error names the first item out of place or the first function missing.
pub fn check_registry<T>(registry: &[Registered<T>], coverage: Coverage) -> Result<(), RegistryError> {
    let mut items = registry.iter().peekable();
    for &module in Module::ALL {
        let functions = module.functions();
        let mut next = 0;
        while let Some(item) = items.next_if(|item| item.module == module) {
            let missing = |index: usize| RegistryError::Missing {
                module,
                function: functions[index],
            };
            let found = functions[next..]
                .iter()
                .position(|&function| function == item.function)
                .map(|offset| next + offset);
            match found {
                Some(index) if coverage == Coverage::Complete && index > next => return Err(missing(next)),
                Some(index) => next = index + 1,
                None if functions.contains(&item.function) => {
                    return Err(RegistryError::OutOfOrder {
                        module,
                        function: item.function,
                    })
                }
                None => {
                    return Err(RegistryError::Unknown {
                        module,
                        function: item.function,
                    })
                }
            }
        }
        if coverage == Coverage::Complete && next < functions.len() {
            return Err(RegistryError::Missing {
                module,
                function: functions[next],
            });
        }
    }
    match items.next() {
        Some(item) if item.module.functions().contains(&item.function) => Err(RegistryError::OutOfOrder {
            module: item.module,
            function: item.function,
        }),
        Some(item) => Err(RegistryError::Unknown {
            module: item.module,
            function: item.function,
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(module: Module, functions: &[&'static str]) -> Vec<Registered<()>> {
        functions
            .iter()
            .map(|&function| Registered::new(module, function, ()))
            .collect()
    }

    fn complete() -> Vec<Registered<()>> {
        registry(|module| names(module, &module.functions()))
    }

    #[test]
    fn every_module_has_functions() {
        for &module in Module::ALL {
            let functions = module.functions();
            assert!(!functions.is_empty(), "{}", module.stem());
            println!("{}: {} functions", module.stem(), functions.len());
        }
        assert_eq!(
            Module::RayCone.functions()[..2],
            ["pack_ray_cone", "unpack_ray_cone"]
        );
    }

    #[test]
    fn the_module_order_is_complete() {
        assert_eq!(check_registry(&complete(), Coverage::Complete), Ok(()));
        assert_eq!(check_registry(&complete(), Coverage::Subset), Ok(()));
        assert_eq!(check_registry::<()>(&[], Coverage::Subset), Ok(()));
    }

    #[test]
    fn a_gap_is_missing_only_from_a_complete_registry() {
        let mut registry = complete();
        registry.remove(1);
        let missing = RegistryError::Missing {
            module: Module::RayCone,
            function: "unpack_ray_cone",
        };
        assert_eq!(check_registry(&registry, Coverage::Complete), Err(missing));
        assert_eq!(check_registry(&registry, Coverage::Subset), Ok(()));
    }

    #[test]
    fn a_missing_last_function_is_missing() {
        let mut registry = complete();
        let last = registry.pop().expect("a function");
        let missing = RegistryError::Missing {
            module: last.module,
            function: last.function,
        };
        assert_eq!(check_registry(&registry, Coverage::Complete), Err(missing));
    }

    #[test]
    fn swapped_functions_are_out_of_order() {
        let mut registry = complete();
        registry.swap(0, 1);
        let error = RegistryError::OutOfOrder {
            module: Module::RayCone,
            function: "pack_ray_cone",
        };
        assert_eq!(check_registry(&registry, Coverage::Subset), Err(error.clone()));
        assert_eq!(
            check_registry(&registry, Coverage::Complete),
            Err(RegistryError::Missing {
                module: Module::RayCone,
                function: "pack_ray_cone",
            })
        );
        assert_eq!(
            error.to_string(),
            "ray_cone: `pack_ray_cone` is registered twice or after a function that follows it"
        );
    }

    #[test]
    fn a_function_registered_twice_is_out_of_order() {
        let registry = names(Module::Wireframe, &["edge_position", "edge_position"]);
        assert_eq!(
            check_registry(&registry, Coverage::Subset),
            Err(RegistryError::OutOfOrder {
                module: Module::Wireframe,
                function: "edge_position",
            })
        );
    }

    #[test]
    fn modules_out_of_order_are_out_of_order() {
        let mut registry = names(Module::Wireframe, &["stipple"]);
        registry.extend(names(Module::RayCone, &["width_at"]));
        assert_eq!(
            check_registry(&registry, Coverage::Subset),
            Err(RegistryError::OutOfOrder {
                module: Module::RayCone,
                function: "width_at",
            })
        );
    }

    #[test]
    fn a_name_of_another_module_is_unknown() {
        let registry = names(Module::RayDiff, &["width_at"]);
        let error = RegistryError::Unknown {
            module: Module::RayDiff,
            function: "width_at",
        };
        assert_eq!(check_registry(&registry, Coverage::Subset), Err(error.clone()));
        assert_eq!(
            error.to_string(),
            "ray_diff: `width_at` is no function of the module"
        );
    }
}
