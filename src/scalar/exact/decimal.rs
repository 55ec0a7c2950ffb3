//! Decimal digits of an exact real from a certified enclosure, computed in exact rationals so
//! that every build prints the same digits.

use super::super::bignum::{Integer, Rational};
use std::cmp::Ordering;

/// `10^k` for any integer `k`.
fn power_of_ten(k: i64) -> Rational {
    let p = Rational::from(Integer::from(10).pow(k.unsigned_abs() as u32));
    if k >= 0 {
        p
    } else {
        Rational::from(1) / p
    }
}

fn compare(a: &Rational, b: &Rational) -> Ordering {
    a.clone().minus(b).cmp0()
}

/// The nearest integer to a non-negative rational, ties to even.
fn round_half_even(x: &Rational) -> Integer {
    let (n, d) = (x.numer(), x.denom());
    let q = n.div_floor(&d);
    let twice_rest = (n - q.clone() * &d).shifted_left(1);
    match twice_rest.minus(&d).cmp0() {
        Ordering::Greater => q + Integer::from(1),
        Ordering::Equal if !q.is_divisible(&Integer::from(2)) => q + Integer::from(1),
        _ => q,
    }
}

/// The midpoint of `[lo, hi]` rounded to `digits` significant decimal digits, if the interval
/// is at most a tenth of a unit in the last of those digits wide (so that the digits differ
/// from any value in it by less than one unit); `None` otherwise.
///
/// Written as MPFR writes a float: `d.ddd` followed by `eX` unless `X`, the decimal exponent,
/// is zero, or with the point moved right when the value is at least one and has no more
/// integer digits than `digits`.
pub(super) fn rounded_midpoint(lo: &Rational, hi: &Rational, digits: u32) -> Option<String> {
    let mid = (lo.clone() + hi) / Rational::from(2);
    if mid.is_zero() {
        return None;
    }
    let negative = mid.cmp0() == Ordering::Less;
    let magnitude = if negative { -mid } else { mid };
    // 10^(e - 1) <= |mid| < 10^e, from an estimate by bits (log10 2 < 0.30103).
    let bits = magnitude.numer_bits() as i64 - magnitude.denom_bits() as i64;
    let mut e = (bits as f64 * std::f64::consts::LOG10_2).floor() as i64;
    while compare(&magnitude, &power_of_ten(e)) != Ordering::Less {
        e += 1;
    }
    while compare(&magnitude, &power_of_ten(e - 1)) == Ordering::Less {
        e -= 1;
    }
    let digits_i = i64::from(digits);
    let unit = power_of_ten(e - digits_i);
    if compare(&((hi.clone() - lo) * Rational::from(10)), &unit) == Ordering::Greater {
        return None;
    }
    let mut n = round_half_even(&(magnitude / &unit));
    if n == Integer::from(10).pow(digits) {
        n = Integer::from(10).pow(digits - 1);
        e += 1;
    }
    let text = n.to_string();
    let (before, exponent) = if e <= 0 || e > digits_i {
        (1, e - 1)
    } else {
        (e as usize, 0)
    };
    let mut out = String::from(if negative { "-" } else { "" });
    out.push_str(&text[..before]);
    if before < text.len() {
        out.push('.');
        out.push_str(&text[before..]);
    }
    if exponent != 0 {
        out.push_str(&format!("e{exponent}"));
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(Integer::from(n), Integer::from(d)).expect("a denominator")
    }

    fn point(n: i64, d: i64, digits: u32) -> Option<String> {
        rounded_midpoint(&q(n, d), &q(n, d), digits)
    }

    #[test]
    fn digits_are_written_as_mpfr_writes_them() {
        assert_eq!(point(1, 3, 4).as_deref(), Some("3.333e-1"));
        assert_eq!(point(-2, 3, 3).as_deref(), Some("-6.67e-1"));
        assert_eq!(point(12346, 100, 4).as_deref(), Some("123.5"));
        assert_eq!(point(12345, 1, 3).as_deref(), Some("1.23e4"));
        assert_eq!(point(120, 1, 3).as_deref(), Some("120"));
        assert_eq!(point(7, 1, 1).as_deref(), Some("7"));
        assert_eq!(point(9996, 1000, 3).as_deref(), Some("10.0"));
        assert_eq!(point(1, 1, 5).as_deref(), Some("1.0000"));
        // Ties go to the even digit: 0.125 and 0.375 to two digits.
        assert_eq!(point(1, 8, 2).as_deref(), Some("1.2e-1"));
        assert_eq!(point(3, 8, 2).as_deref(), Some("3.8e-1"));
    }

    #[test]
    fn a_wide_enclosure_gives_no_digits() {
        // [0.2, 0.3] is 0.1 wide: not a tenth of a unit at any digit.
        assert_eq!(rounded_midpoint(&q(2, 10), &q(3, 10), 1), None);
        // 1/1000 wide around 0.25: enough for one digit (a unit of 0.1), not for two.
        let (lo, hi) = (q(249, 1000), q(251, 1000));
        assert_eq!(rounded_midpoint(&lo, &hi, 1).as_deref(), Some("2e-1"));
        assert_eq!(rounded_midpoint(&lo, &hi, 2), None);
    }
}
