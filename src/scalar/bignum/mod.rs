//! Big numbers for the exact stages: integers, rationals, and binary floats of any precision
//! with directed rounding, from GMP and MPFR (rug, the default feature `gmp`) or in pure Rust
//! (num-bigint and num-rational, without it).
//!
//! Both implementations offer the same types with the same meaning, so the exact backend runs
//! one algorithm and gives the same answers in both builds. A [`Float`] operation is the exact
//! result rounded once, in the direction asked for, to the precision asked for (MPFR's
//! contract): rounded [`Round::Down`] it is a lower bound, [`Round::Up`] an upper bound, so an
//! interval built from them is a proof. [`Round::Nearest`] breaks ties to even. A float may
//! also be infinite or NaN (an interval divided by one containing zero is the whole line).

use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub, SubAssign};

#[cfg(feature = "gmp")]
mod gmp;
#[cfg(feature = "gmp")]
use gmp as imp;
#[cfg(not(feature = "gmp"))]
mod pure;
#[cfg(not(feature = "gmp"))]
use pure as imp;

pub(crate) use imp::Float;
pub use imp::{Integer, Rational};

/// `x = (-1)^neg mantissa 2^exp` exactly, the mantissa below `2^53`, for a finite `x`.
pub(crate) fn f64_parts(x: f64) -> (bool, u64, i64) {
    let bits = x.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as i64;
    let fraction = bits & ((1u64 << 52) - 1);
    let (mantissa, exp) = if exponent == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1u64 << 52), exponent - 1075)
    };
    (x.is_sign_negative(), mantissa, exp)
}

/// The direction in which a [`Float`] operation rounds its exact result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Round {
    /// Towards minus infinity.
    Down,
    /// Towards plus infinity.
    Up,
    /// To the nearest, ties to even.
    Nearest,
}

impl Integer {
    /// `self^exp`.
    ///
    /// # Example
    /// ```
    /// use exact_geodesics::scalar::exact::Integer;
    /// assert_eq!(Integer::from(10).pow(3), Integer::from(1000));
    /// ```
    pub fn pow(&self, exp: u32) -> Integer {
        self.power(exp)
    }
}

impl Rational {
    /// `numer / denom`, reduced; `None` if `denom` is zero.
    ///
    /// # Example
    /// ```
    /// use exact_geodesics::scalar::exact::{Integer, Rational};
    /// let half = Rational::new(Integer::from(2), Integer::from(4));
    /// assert_eq!(half, Rational::new(Integer::from(-1), Integer::from(-2)));
    /// assert!(Rational::new(Integer::from(1), Integer::from(0)).is_none());
    /// ```
    pub fn new(numer: Integer, denom: Integer) -> Option<Rational> {
        (!denom.is_zero()).then(|| Rational::ratio(numer, denom))
    }

    /// The exact value of a finite `f64`; `None` for NaN and infinities.
    pub fn from_f64(x: f64) -> Option<Rational> {
        x.is_finite().then(|| Rational::of_finite_f64(x))
    }

    /// Whether the value is one.
    pub(crate) fn is_one(&self) -> bool {
        *self == Rational::from(1)
    }

    /// Numerator bits plus denominator bits.
    pub(crate) fn size_bits(&self) -> u64 {
        self.numer_bits() + self.denom_bits()
    }

    /// `self 2^e`.
    pub(crate) fn times_pow2(&self, e: i64) -> Rational {
        let power = Rational::from(Integer::from(1).shifted_left(e.unsigned_abs()));
        if e >= 0 {
            self.clone() * power
        } else {
            self.clone() / power
        }
    }
}

impl From<Integer> for Rational {
    fn from(i: Integer) -> Rational {
        Rational::ratio(i, Integer::from(1))
    }
}

impl From<i64> for Rational {
    fn from(i: i64) -> Rational {
        Rational::from(Integer::from(i))
    }
}

impl PartialEq for Float {
    fn eq(&self, o: &Float) -> bool {
        self.compare(o) == Some(Ordering::Equal)
    }
}

impl PartialOrd for Float {
    fn partial_cmp(&self, o: &Float) -> Option<Ordering> {
        self.compare(o)
    }
}

/// The ring operators of a big-number type, from its methods `plus`, `minus`, `times` (on
/// borrowed operands) and `negated`.
macro_rules! ring_operators {
    ($($t:ty),*) => {$(
        impl Add<&$t> for $t {
            type Output = $t;
            fn add(self, o: &$t) -> $t { self.plus(o) }
        }
        impl Sub<&$t> for $t {
            type Output = $t;
            fn sub(self, o: &$t) -> $t { self.minus(o) }
        }
        impl Mul<&$t> for $t {
            type Output = $t;
            fn mul(self, o: &$t) -> $t { self.times(o) }
        }
        impl Add for $t {
            type Output = $t;
            fn add(self, o: $t) -> $t { self.plus(&o) }
        }
        impl Sub for $t {
            type Output = $t;
            fn sub(self, o: $t) -> $t { self.minus(&o) }
        }
        impl Mul for $t {
            type Output = $t;
            fn mul(self, o: $t) -> $t { self.times(&o) }
        }
        impl AddAssign<&$t> for $t {
            fn add_assign(&mut self, o: &$t) { *self = self.plus(o); }
        }
        impl SubAssign<&$t> for $t {
            fn sub_assign(&mut self, o: &$t) { *self = self.minus(o); }
        }
        impl Neg for $t {
            type Output = $t;
            fn neg(self) -> $t { self.negated() }
        }
    )*};
}
ring_operators!(Integer, Rational);

/// Division by zero gives zero rather than a panic; the exact stages certify every divisor
/// non-zero before they divide.
impl Div<&Rational> for Rational {
    type Output = Rational;
    fn div(self, o: &Rational) -> Rational {
        self.over(o)
    }
}

impl Div for Rational {
    type Output = Rational;
    fn div(self, o: Rational) -> Rational {
        self.over(&o)
    }
}

#[cfg(test)]
mod tests;
