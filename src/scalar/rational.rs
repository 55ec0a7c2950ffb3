//! Exact rationals as a [`Ring`] with exact signs: the adaptive backend's exact stage, where
//! every predicate is a polynomial (or a ratio of polynomials) in `f64` inputs, so no square
//! root is needed.
//!
//! The inputs are binary fractions, so a value is kept as `n 2^e / d` and never reduced:
//! sums of binary fractions only shift, and a predicate is a few dozen operations, too few for
//! the numbers to grow much. Reducing by gcds, as a canonical rational does after every
//! operation, would cost more than the rest of the arithmetic.

use super::bignum::{f64_parts, Float, Integer, Rational, Round};
use super::roots::CertifiedSign;
use super::{Ring, Sign};
use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// An exact rational `n 2^e / d`, with `d > 0`; `d` stays 1 until a division.
#[derive(Clone, Debug)]
pub(crate) struct Q {
    n: Integer,
    e: i64,
    d: Integer,
}

impl Q {
    fn zero() -> Q {
        Q {
            n: Integer::default(),
            e: 0,
            d: Integer::from(1),
        }
    }

    fn normalized(n: Integer, e: i64, d: Integer) -> Q {
        if n.is_zero() {
            Q::zero()
        } else {
            Q { n, e, d }
        }
    }

    /// The nearest `f64` (for reports and positions; exactness is in the sign), through an
    /// exact rational, so that no scaling overflows or underflows on the way.
    pub(crate) fn to_f64(&self) -> f64 {
        let r = Rational::new(self.n.clone(), self.d.clone())
            .expect("a positive denominator")
            .times_pow2(self.e);
        // Rounded to nearest (a rational's own conversion truncates).
        Float::from_rational(&r, 53, Round::Nearest).to_f64(Round::Nearest)
    }

    /// `self + o`, or `self - o` if `negate`.
    fn add_signed(self, o: &Q, negate: bool) -> Q {
        if o.n.is_zero() {
            return self;
        }
        if self.n.is_zero() {
            return if negate { -o.clone() } else { o.clone() };
        }
        // Over the common denominator, and with the smaller exponent: only the operand with
        // the larger exponent is shifted, into one allocation of the right size.
        let (mut n, right, d) = if self.d.is_one() && o.d.is_one() {
            (self.n, Integer::default(), self.d)
        } else {
            let right = o.n.times(&self.d);
            (self.n * &o.d, right, self.d * &o.d)
        };
        let right = if o.d.is_one() && d.is_one() {
            &o.n
        } else {
            &right
        };
        let e = self.e.min(o.e);
        if self.e > e {
            n = n.shifted_left((self.e - e) as u64);
        }
        if o.e > e {
            let shifted = right.shifted_left((o.e - e) as u64);
            if negate {
                n -= &shifted;
            } else {
                n += &shifted;
            }
        } else if negate {
            n -= right;
        } else {
            n += right;
        }
        Q::normalized(n, e, d)
    }
}

impl PartialEq for Q {
    fn eq(&self, other: &Q) -> bool {
        (self.clone() - other).n.is_zero()
    }
}

macro_rules! rational_ops {
    ($($tr:ident $f:ident),*) => {$(
        impl $tr for Q {
            type Output = Q;
            fn $f(self, o: Q) -> Q {
                $tr::$f(self, &o)
            }
        }
    )*};
}
rational_ops!(Add add, Sub sub, Mul mul, Div div);

impl<'a> Add<&'a Q> for Q {
    type Output = Q;
    fn add(self, o: &'a Q) -> Q {
        self.add_signed(o, false)
    }
}

impl<'a> Sub<&'a Q> for Q {
    type Output = Q;
    fn sub(self, o: &'a Q) -> Q {
        self.add_signed(o, true)
    }
}

impl<'a> Mul<&'a Q> for Q {
    type Output = Q;
    fn mul(self, o: &'a Q) -> Q {
        let d = if o.d.is_one() { self.d } else { self.d * &o.d };
        Q::normalized(self.n * &o.n, self.e + o.e, d)
    }
}

impl<'a> Div<&'a Q> for Q {
    type Output = Q;
    /// Division by zero, which the predicates never ask for (they test the divisor's sign
    /// first), gives zero rather than a panic.
    fn div(self, o: &'a Q) -> Q {
        if o.n.is_zero() {
            return Q::zero();
        }
        let mut n = if o.d.is_one() { self.n } else { self.n * &o.d };
        let mut d = self.d * &o.n;
        if d.cmp0().is_lt() {
            n = -n;
            d = -d;
        }
        Q::normalized(n, self.e - o.e, d)
    }
}

impl Neg for Q {
    type Output = Q;
    fn neg(self) -> Q {
        Q { n: -self.n, ..self }
    }
}

impl Ring for Q {
    /// Non-finite values, which the engine never passes, become zero.
    fn from_f64(x: f64) -> Self {
        if !x.is_finite() || x == 0.0 {
            return Q::zero();
        }
        let (negative, mantissa, e) = f64_parts(x);
        let n = Integer::from(mantissa as i64);
        Q {
            n: if negative { -n } else { n },
            e,
            d: Integer::from(1),
        }
    }
}

impl CertifiedSign for Q {
    fn certified_sign(&self) -> Option<Sign> {
        Some(match self.n.cmp0() {
            Ordering::Less => Sign::Negative,
            Ordering::Equal => Sign::Zero,
            Ordering::Greater => Sign::Positive,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exact(q: &Q) -> Rational {
        Rational::new(q.n.clone(), q.d.clone())
            .expect("a positive denominator")
            .times_pow2(q.e)
    }

    #[test]
    fn values_are_exact_rationals() {
        let xs = [0.1, -3.0, 1e-300, 5e-324, 7.25e10, -0.0];
        for &x in &xs {
            assert_eq!(exact(&Q::from_f64(x)), Rational::from_f64(x).unwrap());
            for &y in &xs {
                let (p, q) = (
                    Rational::from_f64(x).unwrap(),
                    Rational::from_f64(y).unwrap(),
                );
                let (a, b) = (Q::from_f64(x), Q::from_f64(y));
                assert_eq!(exact(&(a.clone() + &b)), p.clone() + &q);
                assert_eq!(exact(&(a.clone() - &b)), p.clone() - &q);
                assert_eq!(exact(&(a.clone() * &b)), p.clone() * &q);
                if y != 0.0 {
                    let quotient = a.clone() / &b;
                    assert_eq!(exact(&quotient), p.clone() / &q);
                    // Through a division and back: (x / y) * y - x = 0 exactly.
                    let back = quotient * &b - &a;
                    assert_eq!(back.certified_sign(), Some(Sign::Zero));
                    let seven = Q::from_f64(7.0);
                    let mixed = a.clone() / &b + &(b.clone() / &seven);
                    let expected = p.clone() / &q + q.clone() / Rational::from(7);
                    assert_eq!(exact(&mixed), expected);
                }
            }
        }
    }

    #[test]
    fn values_far_from_one_convert_to_f64() {
        let tiny = Q::from_f64(1e-160);
        let one = Q::from_f64(1.0);
        assert_eq!((tiny.clone() * &tiny + &one).to_f64(), 1.0);
        assert_eq!(Q::from_f64(2.5e-308).to_f64(), 2.5e-308);
        assert_eq!((tiny.clone() / &Q::from_f64(3.0)).to_f64(), 1e-160 / 3.0);
        assert_eq!(Q::from_f64(-1e300).to_f64(), -1e300);
    }

    #[test]
    fn signs_of_tiny_differences_are_exact() {
        let one = Q::from_f64(1.0);
        let tiny = Q::from_f64(f64::EPSILON) * &Q::from_f64(f64::EPSILON);
        assert_eq!(
            (one.clone() + &tiny - &one).certified_sign(),
            Some(Sign::Positive)
        );
        assert_eq!(
            (one.clone() - &tiny - &one).certified_sign(),
            Some(Sign::Negative)
        );
        let third = Q::from_f64(1.0) / &Q::from_f64(3.0);
        let sum = third.clone() + &third + &third - &one;
        assert_eq!(sum.certified_sign(), Some(Sign::Zero));
    }
}
