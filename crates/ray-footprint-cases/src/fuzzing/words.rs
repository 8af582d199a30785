//! [`Words`]: fuzz input bytes read as little-endian 32-bit words.

/// Little-endian 32-bit words of a byte string, cycling: word `i` is made of the bytes
/// `4i .. 4i + 4` modulo the length. An empty string gives zeros.
#[derive(Clone, Debug)]
pub struct Words<'a> {
    data: &'a [u8],
    next: usize,
}

impl<'a> Words<'a> {
    /// Words of `data`, from the first.
    pub fn new(data: &'a [u8]) -> Self {
        Words { data, next: 0 }
    }

    /// The next word.
    pub fn u32(&mut self) -> u32 {
        if self.data.is_empty() {
            return 0;
        }
        let start = self.next * 4;
        self.next += 1;
        let byte = |k: usize| self.data[(start + k) % self.data.len()];
        u32::from_le_bytes([byte(0), byte(1), byte(2), byte(3)])
    }

    /// The next word as the bits of an `f32`.
    pub fn f32(&mut self) -> f32 {
        f32::from_bits(self.u32())
    }

    /// The next `n` bytes (cycling), for structs read byte by byte.
    pub fn bytes(&mut self, n: usize) -> Vec<u8> {
        let words: Vec<u8> = (0..n.div_ceil(4))
            .flat_map(|_| self.u32().to_le_bytes())
            .collect();
        words[..n].to_vec()
    }
}
