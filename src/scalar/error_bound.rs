//! `f64` values with a running bound on their absolute error: the adaptive backend's filter.
//!
//! Cheaper than [`Interval`](super::Interval) (no fused multiply-adds, one bound instead of
//! two): each operation adds the propagated error of its operands and one rounding, `2^-52`
//! times the result, and scales the sum up slightly to cover the rounding of the bound itself.
//! A sign is certain when the value is farther from zero than its bound; a value computed
//! without rounding from exact inputs has bound zero, so exact zeros are recognised.

use super::roots::CertifiedSign;
use super::{Field, Ring, Sign};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Twice the unit roundoff: covers `|x - fl(x)| <= u |x| <= u |fl(x)| / (1 - u)`.
const ROUNDING: f64 = f64::EPSILON;

/// Covers the roundings made while computing a bound (a few, each at most `1 + 2^-53`).
const SLACK: f64 = 1.0 + 4.0 * f64::EPSILON;

/// The absolute error a product or quotient of non-zero operands may have lost to underflow,
/// which the relative rounding term does not cover (a result of zero would pass for exact).
#[inline(always)]
fn underflow(result: f64, a: f64, b: f64) -> f64 {
    if result.abs() < f64::MIN_POSITIVE && a != 0.0 && b != 0.0 {
        f64::MIN_POSITIVE
    } else {
        0.0
    }
}

/// An `f64` value and a bound on its distance to the exact value it stands for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ErrorBound {
    value: f64,
    error: f64,
}

impl ErrorBound {
    /// No check for overflow here: an infinite or NaN value or bound makes every comparison in
    /// [`CertifiedSign::certified_sign`] fail, so it can only answer "cannot tell".
    #[inline(always)]
    fn new(value: f64, propagated: f64) -> ErrorBound {
        ErrorBound {
            value,
            error: (propagated + ROUNDING * value.abs()) * SLACK,
        }
    }
}

impl Add for ErrorBound {
    type Output = ErrorBound;
    #[inline(always)]
    fn add(self, o: ErrorBound) -> ErrorBound {
        ErrorBound::new(self.value + o.value, self.error + o.error)
    }
}

impl Sub for ErrorBound {
    type Output = ErrorBound;
    #[inline(always)]
    fn sub(self, o: ErrorBound) -> ErrorBound {
        ErrorBound::new(self.value - o.value, self.error + o.error)
    }
}

impl Mul for ErrorBound {
    type Output = ErrorBound;
    #[inline(always)]
    fn mul(self, o: ErrorBound) -> ErrorBound {
        let value = self.value * o.value;
        let propagated =
            self.value.abs() * o.error + o.value.abs() * self.error + self.error * o.error;
        ErrorBound::new(value, propagated + underflow(value, self.value, o.value))
    }
}

impl Div for ErrorBound {
    type Output = ErrorBound;
    #[inline(always)]
    fn div(self, o: ErrorBound) -> ErrorBound {
        let margin = o.value.abs() - o.error;
        if margin <= 0.0 {
            return ErrorBound {
                value: 0.0,
                error: f64::INFINITY,
            };
        }
        // |a'/b' - a/b| <= (|a| e_b + |b| e_a) / (|b| (|b| - e_b)).
        let propagated = (self.value.abs() * o.error + o.value.abs() * self.error)
            / (o.value.abs() * margin * (1.0 - 4.0 * f64::EPSILON));
        let value = self.value / o.value;
        ErrorBound::new(value, propagated + underflow(value, self.value, o.value))
    }
}

impl Neg for ErrorBound {
    type Output = ErrorBound;
    #[inline(always)]
    fn neg(self) -> ErrorBound {
        ErrorBound {
            value: -self.value,
            error: self.error,
        }
    }
}

ops_by_reference_for_copy!(ErrorBound);

impl Ring for ErrorBound {
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        ErrorBound {
            value: x,
            error: 0.0,
        }
    }
}

impl Field for ErrorBound {
    #[inline(always)]
    fn to_f64(&self) -> f64 {
        self.value
    }

    /// `sqrt(max(x, 0))`: `|sqrt(x') - sqrt(x)| = |x' - x| / (sqrt(x') + sqrt(x))`.
    #[inline(always)]
    fn sqrt(&self) -> Self {
        let v = self.value.max(0.0).sqrt();
        let low = self.value - self.error;
        if low <= 0.0 {
            let reach = (self.value.max(0.0) + self.error).sqrt() * SLACK;
            return ErrorBound::new(v, reach);
        }
        ErrorBound::new(
            v,
            self.error / (low.sqrt() * (1.0 - 4.0 * f64::EPSILON) + v),
        )
    }
}

impl CertifiedSign for ErrorBound {
    #[inline(always)]
    fn certified_sign(&self) -> Option<Sign> {
        // An overflowed value has an infinite bound (or is NaN): no comparison holds.
        if self.value > self.error {
            Some(Sign::Positive)
        } else if -self.value > self.error {
            Some(Sign::Negative)
        } else if self.value == 0.0 && self.error == 0.0 {
            Some(Sign::Zero)
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_zeros_are_recognised_and_rounding_is_bounded() {
        let x = ErrorBound::from_f64(0.1);
        assert_eq!((x - x).certified_sign(), Some(Sign::Zero));
        let third = ErrorBound::from_f64(1.0) / ErrorBound::from_f64(3.0);
        let back = third * ErrorBound::from_f64(3.0) - ErrorBound::from_f64(1.0);
        assert_eq!(back.certified_sign(), None);
        let tiny = ErrorBound::from_f64(1e-170);
        assert_eq!((tiny * tiny).certified_sign(), None);
        assert_eq!((tiny / ErrorBound::from_f64(1e170)).certified_sign(), None);
        let huge = ErrorBound::from_f64(1e300);
        assert_eq!((huge * huge).certified_sign(), None);
        assert_eq!((huge * huge - huge * huge).certified_sign(), None);
        let r = ErrorBound::from_f64(2.0).sqrt();
        assert!((r.value - std::f64::consts::SQRT_2).abs() <= r.error.max(f64::EPSILON));
        assert_eq!(
            (r - ErrorBound::from_f64(1.4)).certified_sign(),
            Some(Sign::Positive)
        );
    }
}
