//! When an interval enclosure says something: a quantity known to [`WELL_CONDITIONED`], the
//! relative width its enclosure may have. The records keep their agreement checks to such inputs
//! ([`crate::Record::conditioned`]); the others are checked for the documented clamps only.

use shader_proptest::interval::Interval;

/// Bits to which a divisor must be known for its quotient to be well-conditioned: a relative
/// width of the divisor's enclosure of at most 2^-10. Beyond that (a ray parallel to the triangle
/// within rounding, a sliver, an object-space direction lost to the cancellation of a far origin)
/// the clamped quotient's enclosure is as wide as the outputs themselves, so those inputs are
/// checked separately, for finite outputs within the documented clamp (the edge-case suite).
pub const WELL_CONDITIONED: f64 = 1.0 / 1024.0;

/// Whether a quotient by `k` is well-conditioned ([`WELL_CONDITIONED`]); an exact 0 is, since both
/// sides then take the clamp.
pub fn well_conditioned(k: Interval) -> bool {
    k.relative_width() <= WELL_CONDITIONED
}
