//! Lengths in space free of overflow and underflow for coordinates from `2^-600` to `2^600`.

/// `2^k`, exactly, for `-1022 <= k <= 1023` (clamped to that range).
pub(crate) fn power_of_two(k: i32) -> f64 {
    let k = k.clamp(-1022, 1023);
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// The length of `q - p` in `f64`, without overflow or underflow.
pub(crate) fn distance_f64(p: [f64; 3], q: [f64; 3]) -> f64 {
    (q[0] - p[0]).hypot(q[1] - p[1]).hypot(q[2] - p[2])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_of_two_is_exact_at_both_ends_of_the_range() {
        assert_eq!(power_of_two(600), 2f64.powi(600));
        assert_eq!(power_of_two(-600), 2f64.powi(-600));
        assert_eq!(power_of_two(0), 1.0);
    }
}
