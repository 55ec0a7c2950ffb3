//! `f64` vector helpers for the mesh's own geometry (lengths, angles, degeneracy) on
//! `glam::DVec3`, computed without overflow or underflow whatever the model's units.

use glam::DVec3;

/// The power of two `p` with `m p` in `[1, 2)` for a positive finite `m`, kept within
/// `2^-1022 ..= 2^1022` (so that it and its inverse are normal numbers).
pub(crate) fn normalizing_power(m: f64) -> f64 {
    // The binary exponent, read off the bits (subnormals first brought into the normal range).
    let (m, shift) = if m < f64::MIN_POSITIVE {
        (m * TWO_TO_64, 64)
    } else {
        (m, 0)
    };
    let exponent = ((m.to_bits() >> 52) & 0x7ff) as i32 - 1023 - shift;
    power_of_two((-exponent).clamp(-1022, 1022))
}

/// `2^k`, exactly, for `-1022 <= k <= 1023` (clamped to that range).
pub(crate) fn power_of_two(k: i32) -> f64 {
    let k = k.clamp(-1022, 1023);
    f64::from_bits(((k + 1023) as u64) << 52)
}

pub(crate) const TWO_TO_64: f64 = 18446744073709551616.0;

/// Whether squares and products of numbers up to `m` in magnitude stay normal `f64`s, so that
/// no scaling is needed.
fn squares_safely(m: f64) -> bool {
    (1e-150..=1e150).contains(&m)
}

/// `v` scaled to unit length, computed without overflow or underflow; `None` for the zero
/// vector.
pub(crate) fn unit(v: DVec3) -> Option<DVec3> {
    let largest = v.abs().max_element();
    if largest == 0.0 {
        return None;
    }
    let v = if squares_safely(largest) {
        v
    } else {
        v * normalizing_power(largest)
    };
    Some(v / v.length())
}

/// The length of `v`, without overflow or underflow in its square.
pub(crate) fn length(v: DVec3) -> f64 {
    let largest = v.abs().max_element();
    if largest == 0.0 {
        return 0.0;
    }
    if squares_safely(largest) {
        return v.length();
    }
    let power = normalizing_power(largest);
    (v * power).length() / power
}

/// The angle between two vectors (0 if either is zero), computed on unit vectors so that it
/// does not depend on their magnitudes.
pub(crate) fn angle(u: DVec3, w: DVec3) -> f64 {
    match (unit(u), unit(w)) {
        (Some(u), Some(w)) => angle_of_units(u, w),
        _ => 0.0,
    }
}

/// The angle between two unit vectors.
pub(crate) fn angle_of_units(u: DVec3, w: DVec3) -> f64 {
    length(u.cross(w)).atan2(u.dot(w))
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

    #[test]
    fn normalizing_power_brings_magnitudes_into_one_to_two_within_its_clamp() {
        for m in [3.0, 0.75, 1e-300, 1e300] {
            let scaled = m * normalizing_power(m);
            assert!((1.0..2.0).contains(&scaled), "{m}: {scaled}");
        }
        // Beyond 2^+-1022 the power stays a normal number.
        assert_eq!(normalizing_power(5e-320), power_of_two(1022));
        assert_eq!(normalizing_power(f64::MAX), power_of_two(-1022));
    }
}
