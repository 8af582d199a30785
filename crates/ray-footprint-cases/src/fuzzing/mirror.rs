//! `cpu_mirror`: every public function of the Rust mirror modules on arbitrary `f32` inputs.
//!
//! Each input is evaluated twice by every function, with the arguments its record draws
//! ([`crate::Record::fuzz`]) from the input's words as they are and mapped into the documented
//! domain ([`super::draw`]). With raw words nothing must panic (and the wireframe module, whose
//! documentation promises it for every finite input, gives a finite coverage in `[0, 1]` whenever
//! every argument is finite); in the domain every output is finite and the record's promises hold.

use super::draw::Mode;
use crate::records::records;

/// The `cpu_mirror` target.
pub fn cpu_mirror(data: &[u8]) -> Result<(), String> {
    for record in records() {
        for mode in [Mode::Raw, Mode::Domain] {
            record.fuzz(data, mode)?;
        }
    }
    Ok(())
}
