//! The one order check: the records name every public function of every module once, in the
//! module's order ([`Module::functions`]), the modules in the order of [`Module::ALL`].
//!
//! ```
//! use ray_footprint::shaders::Module;
//! use ray_footprint_cases::order::{check_order, OrderError};
//!
//! let mut names: Vec<(Module, &str)> = Module::ALL
//!     .iter()
//!     .flat_map(|&module| module.functions().into_iter().map(move |name| (module, name)))
//!     .collect();
//! assert_eq!(check_order(&names), Ok(()));
//! names.swap(0, 1);
//! assert_eq!(
//!     check_order(&names),
//!     Err(OrderError::Missing { module: Module::RayCone, function: "pack_ray_cone" })
//! );
//! ```

use ray_footprint::shaders::Module;

/// Why a list of functions is not in module order, or not complete.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum OrderError {
    /// The name is no function of its module.
    Unknown {
        /// The module it was named in.
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
    /// The list lacks the function.
    Missing {
        /// The function's module.
        module: Module,
        /// The first function missing.
        function: &'static str,
    },
}

impl std::fmt::Display for OrderError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OrderError::Unknown { module, function } => {
                write!(f, "{}: `{function}` is no function of the module", module.stem())
            }
            OrderError::OutOfOrder { module, function } => write!(
                f,
                "{}: `{function}` comes twice or after a function that follows it",
                module.stem()
            ),
            OrderError::Missing { module, function } => {
                write!(f, "{}: `{function}` is missing", module.stem())
            }
        }
    }
}

impl std::error::Error for OrderError {}

/// Every public function of every module, in module order.
pub fn all_functions() -> Vec<(Module, &'static str)> {
    Module::ALL
        .iter()
        .flat_map(|&module| {
            module
                .functions()
                .into_iter()
                .map(move |function| (module, function))
        })
        .collect()
}

/// Checks that `names` lists every function of every module once, each module's in the module's
/// order, the modules in the order of [`Module::ALL`]. The error names the first name out of place:
/// one that is no function of its module, one that comes again or after a function that follows
/// it, or the function that should have come where another stands.
pub fn check_order(names: &[(Module, &'static str)]) -> Result<(), OrderError> {
    let expected = all_functions();
    for (index, &(module, function)) in expected.iter().enumerate() {
        let Some(&(found_module, found)) = names.get(index) else {
            return Err(OrderError::Missing { module, function });
        };
        if (found_module, found) == (module, function) {
            continue;
        }
        return Err(
            match expected.iter().position(|&item| item == (found_module, found)) {
                None => OrderError::Unknown {
                    module: found_module,
                    function: found,
                },
                Some(earlier) if earlier < index => OrderError::OutOfOrder {
                    module: found_module,
                    function: found,
                },
                Some(_) => OrderError::Missing { module, function },
            },
        );
    }
    match names.get(expected.len()) {
        None => Ok(()),
        Some(&(module, function)) if module.functions().contains(&function) => {
            Err(OrderError::OutOfOrder { module, function })
        }
        Some(&(module, function)) => Err(OrderError::Unknown { module, function }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        assert_eq!(check_order(&all_functions()), Ok(()));
    }

    #[test]
    fn a_gap_is_missing() {
        let mut names = all_functions();
        names.remove(1);
        let missing = OrderError::Missing {
            module: Module::RayCone,
            function: "unpack_ray_cone",
        };
        assert_eq!(check_order(&names), Err(missing));
    }

    #[test]
    fn a_missing_last_function_is_missing() {
        let mut names = all_functions();
        let (module, function) = names.pop().expect("a function");
        assert_eq!(check_order(&names), Err(OrderError::Missing { module, function }));
    }

    #[test]
    fn a_function_named_twice_is_out_of_order() {
        let mut names = all_functions();
        names.insert(1, names[0]);
        let error = OrderError::OutOfOrder {
            module: Module::RayCone,
            function: "pack_ray_cone",
        };
        assert_eq!(check_order(&names), Err(error.clone()));
        assert_eq!(
            error.to_string(),
            "ray_cone: `pack_ray_cone` comes twice or after a function that follows it"
        );
    }

    #[test]
    fn swapped_functions_miss_the_first() {
        let mut names = all_functions();
        names.swap(0, 1);
        assert_eq!(
            check_order(&names),
            Err(OrderError::Missing {
                module: Module::RayCone,
                function: "pack_ray_cone",
            })
        );
    }

    #[test]
    fn a_name_of_another_module_is_unknown() {
        let mut names = all_functions();
        let first_ray_diff = names
            .iter()
            .position(|&(module, _)| module == Module::RayDiff)
            .expect("ray_diff functions");
        names[first_ray_diff].1 = "width_at";
        let error = OrderError::Unknown {
            module: Module::RayDiff,
            function: "width_at",
        };
        assert_eq!(check_order(&names), Err(error.clone()));
        assert_eq!(
            error.to_string(),
            "ray_diff: `width_at` is no function of the module"
        );
    }
}
