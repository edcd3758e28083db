//! The renderer's seeded test generator: Marsaglia's xorshift64 (13, 7,
//! 17; "Xorshift RNGs", J. Stat. Software 8(14), 2003). One generator, so
//! a randomised test states only its seed and how it maps the numbers.

/// A xorshift64 state (never zero).
pub struct XorShift(u64);

impl XorShift {
    pub fn new(seed: u64) -> XorShift {
        XorShift(seed.max(1))
    }

    pub fn next_u64(&mut self) -> u64 {
        let mut s = self.0;
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        self.0 = s;
        s
    }

    /// Uniform in [0, 1), from the top 53 bits (exact in f64; `as f32`
    /// rounds once, as dividing an `f32` of those bits by 2^53 would).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}
