//! Exact rationals as a [`Ring`] with exact signs: the adaptive backend's exact stage, where
//! every predicate is a polynomial in `f64` inputs (so no square root is needed).

use super::roots::CertifiedSign;
use super::{Ring, Sign};
use rug::Rational;
use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// An exact rational.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Q(pub(crate) Rational);

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
        Q(self.0 + &o.0)
    }
}

impl<'a> Sub<&'a Q> for Q {
    type Output = Q;
    fn sub(self, o: &'a Q) -> Q {
        Q(self.0 - &o.0)
    }
}

impl<'a> Mul<&'a Q> for Q {
    type Output = Q;
    fn mul(self, o: &'a Q) -> Q {
        Q(self.0 * &o.0)
    }
}

impl<'a> Div<&'a Q> for Q {
    type Output = Q;
    /// Division by zero, which the predicates never ask for (they test the divisor's sign
    /// first), gives zero rather than a panic.
    fn div(self, o: &'a Q) -> Q {
        if o.0.is_zero() {
            Q(Rational::new())
        } else {
            Q(self.0 / &o.0)
        }
    }
}

impl Neg for Q {
    type Output = Q;
    fn neg(self) -> Q {
        Q(-self.0)
    }
}

impl Ring for Q {
    fn from_f64(x: f64) -> Self {
        Q(Rational::from_f64(x).unwrap_or_default())
    }
}

impl CertifiedSign for Q {
    fn certified_sign(&self) -> Option<Sign> {
        Some(match self.0.cmp0() {
            Ordering::Less => Sign::Negative,
            Ordering::Equal => Sign::Zero,
            Ordering::Greater => Sign::Positive,
        })
    }
}
