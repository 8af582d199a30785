//! Fuzz target `cpu_mirror`: see `ray_footprint::fuzzing` for the properties it checks.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| ray_footprint::fuzzing::fuzz_one("cpu_mirror", data));
