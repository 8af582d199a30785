//! Error bounds derived from Vulkan's precision rules (Vulkan spec, "Precision and Operation of
//! SPIR-V Instructions"), plus the mirror's own rounding.
//!
//! - `+ - *` are correctly rounded, but an implementation may fuse `a * b + c`, so a short sum of
//!   products may differ from the mirror by a few units in the last place of its largest term.
//! - Division: 2.5 ULP. `inversesqrt`: 2 ULP; `sqrt` and `length` inherit `1 / inversesqrt`.
//! - `log2`: 3 ULP outside `[0.5, 2]`, absolute `2^-21` inside.
//! - `sin`, `cos`: absolute `2^-11` in `[-pi, pi]`; `tan` inherits `sin / cos`.
//! - `atan`: inherits `atan2`, 4096 ULP.
//! - Denormals may be flushed to zero, so every bound has an absolute floor of the smallest normal.

/// One unit in the last place at 1.0 (2^-23); `n` of them times a magnitude bounds `n` roundings.
pub const ULP: f32 = f32::EPSILON;
/// Absolute error of `sin` and `cos` (2^-11).
pub const SIN_COS_ERROR: f32 = 1.0 / 2048.0;
/// Relative error of `atan` (4096 ULP).
pub const ATAN_ULPS: f32 = 4096.0;

/// `n` roundings of a value of size `scale`, with the denormal floor.
pub fn ulps(n: f32, scale: f32) -> f32 {
    n * ULP * scale.abs() + f32::MIN_POSITIVE
}

/// Error of `log2` returning `result` on the device (3 ULP, or 2^-21 near 0), plus the mirror's ULP.
pub fn log2_error(result: f32) -> f32 {
    (4.0 * ULP * result.abs()).max(1.0 / 2_097_152.0 + ULP * result.abs())
}

/// Error of `atan(x)` when `x` itself is off by `x_error`: the propagated error `x_error / (1 + x^2)`
/// plus 4096 ULP of the result and the mirror's ULP.
pub fn atan_error(x: f32, x_error: f32) -> f32 {
    let x = f64::from(x);
    (f64::from(x_error) / (1.0 + x * x)) as f32 + ulps(ATAN_ULPS + 1.0, x.atan() as f32)
}

/// Error of `tan(angle)` computed as `sin / cos` with absolute errors of 2^-11 each:
/// `(2^-11 / |cos|) * (1 + |tan|)`, plus the division's 2.5 ULP and the mirror's ULP.
pub fn tan_error(angle: f32) -> f32 {
    let (sin, cos) = f64::from(angle).sin_cos();
    let tan = (sin / cos).abs();
    (f64::from(SIN_COS_ERROR) / cos.abs() * (1.0 + tan)) as f32 + ulps(3.5, tan as f32)
}

/// Rounding error of a dot product `sum(a_i * b_i)`: 3 roundings of the sum of term magnitudes.
pub fn dot_error(a: glam::Vec3, b: glam::Vec3) -> f32 {
    ulps(3.0, (a * b).abs().element_sum())
}
