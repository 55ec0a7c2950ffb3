//! Double-double numbers (an unevaluated sum of two `f64`, about 106 bits) with a running bound
//! on their absolute error: the adaptive backend's second filter. The near-ties that the `f64`
//! filter cannot tell apart are, almost always, apart by more than 1e-30 relative; this settles
//! them at a small fraction of the cost of exact rationals.
//!
//! The products and sums are Dekker's and Knuth's error-free transformations; each operation's
//! own error is bounded by `2^-96` times the size of its operands, about a thousand times the
//! published bounds of these algorithms (Joldes, Muller, Popescu 2017), so that the bound stays
//! safe without a finer analysis.

use super::roots::CertifiedSign;
use super::{Ring, Sign};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// The relative error charged to each operation.
const ROUNDING: f64 = 1.0 / (1u128 << 96) as f64;

/// The absolute error charged to a product or quotient for what underflow may lose.
const UNDERFLOW: f64 = f64::MIN_POSITIVE;

/// Covers the roundings made while computing a bound.
const SLACK: f64 = 1.0 + 8.0 * f64::EPSILON;

/// `hi + lo` with `|lo| <= ulp(hi) / 2`, and a bound on the distance to the exact value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct DoubleDouble {
    hi: f64,
    lo: f64,
    error: f64,
}

#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

#[inline(always)]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let ((ah, al), (bh, bl)) = (split(a), split(b));
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

impl DoubleDouble {
    /// No check for overflow here: an overflow leaves an infinite or NaN part or bound, which
    /// every later operation keeps (an infinite part makes the next error-free sum NaN) and
    /// which [`DoubleDouble::is_finite`] turns into "cannot tell" where a value is read.
    #[inline(always)]
    fn new(hi: f64, lo: f64, error: f64) -> DoubleDouble {
        let (hi, lo) = two_sum(hi, lo);
        DoubleDouble {
            hi,
            lo,
            error: error * SLACK,
        }
    }

    /// Whether the parts and the bound are finite and the value below `1e150`: beyond that, the
    /// product of two such values would overflow in Dekker's splitting (`2^27 |x|` near
    /// `f64::MAX`), so such a value is not read.
    #[inline(always)]
    fn is_finite(&self) -> bool {
        self.hi.abs() < 1e150 && self.lo.is_finite() && self.error.is_finite()
    }

    /// The nearest `f64`.
    #[inline(always)]
    pub(crate) fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    /// The nearest `f64` if the value is known to within `2^-60` of itself or, for values
    /// below 1, to within `2^-60` (for values of unit size, as the adaptive backend's root
    /// positions are computed), else `None`.
    #[inline(always)]
    pub(crate) fn accurate_f64(self) -> Option<f64> {
        let value = self.hi + self.lo;
        (self.is_finite() && self.error <= value.abs().max(1.0) * (1.0 / (1u64 << 60) as f64))
            .then_some(value)
    }

    #[inline(always)]
    fn magnitude(&self) -> f64 {
        self.hi.abs() + self.lo.abs()
    }
}

impl Add for DoubleDouble {
    type Output = DoubleDouble;
    #[inline(always)]
    fn add(self, o: DoubleDouble) -> DoubleDouble {
        let (s, e) = two_sum(self.hi, o.hi);
        // Sums of plain doubles are exact as a double-double: no charge, so exact zeros stay.
        let exact = self.lo == 0.0 && o.lo == 0.0;
        let e = e + self.lo + o.lo;
        let own = if exact {
            0.0
        } else {
            ROUNDING * (self.magnitude() + o.magnitude())
        };
        DoubleDouble::new(s, e, self.error + o.error + own)
    }
}

impl Neg for DoubleDouble {
    type Output = DoubleDouble;
    #[inline(always)]
    fn neg(self) -> DoubleDouble {
        DoubleDouble {
            hi: -self.hi,
            lo: -self.lo,
            error: self.error,
        }
    }
}

impl Sub for DoubleDouble {
    type Output = DoubleDouble;
    #[inline(always)]
    fn sub(self, o: DoubleDouble) -> DoubleDouble {
        self + (-o)
    }
}

impl Mul for DoubleDouble {
    type Output = DoubleDouble;
    #[inline(always)]
    fn mul(self, o: DoubleDouble) -> DoubleDouble {
        let (p, e) = two_prod(self.hi, o.hi);
        let e = e + (self.hi * o.lo + self.lo * o.hi);
        let (ma, mb) = (self.magnitude(), o.magnitude());
        let propagated = ma * o.error + mb * self.error + self.error * o.error;
        // Dekker's product is exact for plain doubles unless it underflows.
        let no_underflow = p.abs() > 1e-280 || self.hi == 0.0 || o.hi == 0.0;
        let own = if self.lo == 0.0 && o.lo == 0.0 && no_underflow {
            0.0
        } else {
            // Near underflow the parts lose absolute bits the relative charge does not cover.
            ROUNDING * ma * mb + UNDERFLOW
        };
        DoubleDouble::new(p, e, propagated + own)
    }
}

impl Div for DoubleDouble {
    type Output = DoubleDouble;
    #[inline(always)]
    fn div(self, o: DoubleDouble) -> DoubleDouble {
        let (ma, mb) = (self.magnitude(), o.magnitude());
        let margin = mb - o.error;
        if margin <= 0.0 || o.hi == 0.0 {
            return DoubleDouble::new(0.0, 0.0, f64::INFINITY);
        }
        // Long division: q1 + q2, each remainder computed with error-free products.
        let q1 = self.hi / o.hi;
        let (p, pe) = two_prod(q1, o.hi);
        let r = (self.hi - p) - pe + self.lo - q1 * o.lo;
        let q2 = r / o.hi;
        let propagated =
            (ma * o.error + mb * self.error) / (mb * margin * (1.0 - 8.0 * f64::EPSILON));
        DoubleDouble::new(
            q1,
            q2,
            propagated + ROUNDING * 4.0 * (ma / margin) + UNDERFLOW,
        )
    }
}

ops_by_reference_for_copy!(DoubleDouble);

impl Ring for DoubleDouble {
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        DoubleDouble {
            hi: x,
            lo: 0.0,
            error: 0.0,
        }
    }
}

impl CertifiedSign for DoubleDouble {
    #[inline(always)]
    fn certified_sign(&self) -> Option<Sign> {
        // |hi + lo| >= |hi| - |lo|, and |lo| is at most half an ulp of hi.
        let size = self.hi.abs() - self.lo.abs();
        if !self.is_finite() {
            None
        } else if self.hi == 0.0 && self.lo == 0.0 && self.error == 0.0 {
            Some(Sign::Zero)
        } else if size > self.error && self.hi > 0.0 {
            Some(Sign::Positive)
        } else if size > self.error && self.hi < 0.0 {
            Some(Sign::Negative)
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn separates_what_f64_cannot_and_keeps_exact_zeros() {
        let one = DoubleDouble::from_f64(1.0);
        let tiny = DoubleDouble::from_f64(1e-20);
        // (1 + 1e-20) - 1 is 1e-20 in double-double, 0 in f64.
        assert_eq!(((one + tiny) - one).certified_sign(), Some(Sign::Positive));
        let x = DoubleDouble::from_f64(0.1);
        assert_eq!((x - x).certified_sign(), Some(Sign::Zero));
        // 1/3 * 3 - 1 is within the bound of zero: no sign.
        let third = one / DoubleDouble::from_f64(3.0);
        assert_eq!(
            (third * DoubleDouble::from_f64(3.0) - one).certified_sign(),
            None
        );
    }

    #[test]
    fn an_overflow_anywhere_in_a_computation_cannot_tell() {
        let huge = DoubleDouble::from_f64(1e200);
        let third = DoubleDouble::from_f64(1.0) / DoubleDouble::from_f64(3.0);
        let square = huge * huge;
        assert_eq!(square.certified_sign(), None);
        assert_eq!(square.accurate_f64(), None);
        assert_eq!((square - square).certified_sign(), None);
        assert_eq!(
            (square * DoubleDouble::from_f64(0.0)).certified_sign(),
            None
        );
        // Back in range after an overflow on the way.
        assert_eq!(((huge * third) * huge / huge).certified_sign(), None);
        assert_eq!(((huge * third) * huge / huge).accurate_f64(), None);
        // Beyond 1e150 when read: products of such values could overflow in the splitting.
        assert_eq!((huge * third).certified_sign(), None);
        let fine = (DoubleDouble::from_f64(1e100) * third) / DoubleDouble::from_f64(1e100);
        assert_eq!(fine.certified_sign(), Some(Sign::Positive));
    }
}
