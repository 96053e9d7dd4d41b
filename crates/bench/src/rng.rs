//! The benchmarks' deterministic inputs: one xorshift64 generator (Marsaglia, 2003, "Xorshift
//! RNGs", Journal of Statistical Software 8(14), the shift triple 13, 7, 17), seeded per
//! section so that every run measures the same rows.

/// Uniform numbers in [0, 1) (the top 53 bits of each xorshift64 state) from `seed` (nonzero):
/// the same sequence for the same seed on every run and machine.
pub fn uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut s = seed;
    move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[cfg(test)]
mod tests {
    /// xorshift64 at Marsaglia's example seed 88172645463325252: its first three states as
    /// public xorshift implementations pin them in their tests (8748534153485358512,
    /// 3040900993826735515, 3453997556048239312), each as its top 53 bits over 2^53.
    #[test]
    fn the_published_xorshift64_states_in_order() {
        let mut u = super::uniform(88_172_645_463_325_252);
        for state in [8_748_534_153_485_358_512u64, 3_040_900_993_826_735_515, 3_453_997_556_048_239_312] {
            assert_eq!(u(), (state >> 11) as f64 / (1u64 << 53) as f64);
        }
    }
}
