//! Fuzz target `compose`: see `ray_footprint_cases::fuzzing` for the properties it checks.
#![no_main]

use ray_footprint_cases::fuzzing;

libfuzzer_sys::fuzz_target!(|data: &[u8]| fuzzing::fuzz_one(fuzzing::compose::compose, data));
