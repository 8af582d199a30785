//! What the tests share (the lab's tests include this file too). Each test binary compiles this
//! module and uses part of it.
#![allow(dead_code)]

use glam::DVec3;
use std::path::Path;

/// Asserts that the text between the markers `start` and `end` in the file at `path` is `block`
/// (white space at either end aside); with `RAY_FOOTPRINT_BLESS` set, writes `block` there instead.
/// `what` names the generated table in the failure message.
pub fn assert_generated_block(path: &Path, start: &str, end: &str, block: &str, what: &str) {
    let doc = std::fs::read_to_string(path).unwrap_or_else(|error| panic!("{}: {error}", path.display()));
    let (head, rest) = doc.split_once(start).expect("the start marker");
    let (current, tail) = rest.split_once(end).expect("the end marker");
    if std::env::var_os("RAY_FOOTPRINT_BLESS").is_some() {
        std::fs::write(path, format!("{head}{start}{block}{end}{tail}")).expect("writing");
        return;
    }
    assert_eq!(
        current.trim(),
        block.trim(),
        "{what} is out of date; rerun with RAY_FOOTPRINT_BLESS=1"
    );
}

/// The largest error over `cases` random cases: `error` checks one case drawn from a generator
/// seeded with `seed` (one generator for all cases) and returns the error it measured.
pub fn worst_case(seed: u64, cases: usize, mut error: impl FnMut(&mut Rng) -> f64) -> f64 {
    let mut rng = Rng(seed);
    (0..cases).map(|_| error(&mut rng)).fold(0.0, f64::max)
}

/// Asserts that the struct `$ty` is `$size` bytes long with each listed field at the offset given
/// (`assert_layout!(Type, 32, { a: 0, b: 16 })`), naming the field that is elsewhere; prints the
/// size.
#[macro_export]
macro_rules! assert_layout {
    ($ty:ty, $size:expr, { $($field:ident: $offset:expr),+ $(,)? }) => {{
        let size = std::mem::size_of::<$ty>();
        println!("{}: size {size}", stringify!($ty));
        assert_eq!(size, $size, "size of {}", stringify!($ty));
        $(
            assert_eq!(
                std::mem::offset_of!($ty, $field),
                $offset,
                "offset of {}.{}",
                stringify!($ty),
                stringify!($field)
            );
        )+
    }};
}

/// A small deterministic generator (xorshift64*), so the tests need no extra crate and always see
/// the same cases.
pub struct Rng(pub u64);

impl Rng {
    /// Uniform in `[0, 1)`.
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in `[lo, hi)`.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }

    /// -1 or 1.
    pub fn sign(&mut self) -> f64 {
        if self.next() < 0.5 {
            -1.0
        } else {
            1.0
        }
    }

    /// `10^e` for `e` uniform in `[lo, hi]`.
    pub fn log_range(&mut self, lo: f64, hi: f64) -> f64 {
        10f64.powf(self.range(lo, hi))
    }

    /// A unit vector uniform on the sphere.
    pub fn unit(&mut self) -> DVec3 {
        let z = self.range(-1.0, 1.0);
        let phi = self.range(0.0, std::f64::consts::TAU);
        let r = (1.0 - z * z).sqrt();
        DVec3::new(r * phi.cos(), r * phi.sin(), z)
    }
}
