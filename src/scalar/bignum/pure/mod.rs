//! The big numbers in pure Rust (without the feature `gmp`): integers and rationals from
//! num-bigint and num-rational, and binary floats of our own ([`float`]).
//!
//! Fractions are reduced here with Lehmer's gcd ([`lehmer`]) rather than by num-rational's
//! arithmetic, and compared and hashed by their reduced parts rather than by num-rational's
//! continued fractions: those three were nine tenths of the pure build's time.

mod float;
mod lehmer;

pub(crate) use float::Float;

use super::{f64_parts, Round};
use num_bigint::{BigInt, Sign};
use num_integer::Integer as _;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::fmt;
use std::hash::{Hash, Hasher};

/// An integer of any size (an exact rational's numerator or denominator).
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Integer(BigInt);

/// An exact rational number, always in lowest terms with a positive denominator.
#[derive(Clone, Debug)]
pub struct Rational(BigRational);

impl PartialEq for Rational {
    fn eq(&self, o: &Rational) -> bool {
        self.0.numer() == o.0.numer() && self.0.denom() == o.0.denom()
    }
}

impl Eq for Rational {}

impl Hash for Rational {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.0.numer().hash(state);
        self.0.denom().hash(state);
    }
}

impl Default for Rational {
    fn default() -> Rational {
        Rational(BigRational::zero())
    }
}

impl From<i64> for Integer {
    fn from(i: i64) -> Integer {
        Integer(BigInt::from(i))
    }
}

impl fmt::Display for Integer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.fmt(f)
    }
}

impl Integer {
    pub(crate) fn power(&self, exp: u32) -> Integer {
        Integer(self.0.pow(exp))
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.0.is_zero()
    }

    pub(crate) fn is_one(&self) -> bool {
        self.0.is_one()
    }

    pub(crate) fn cmp0(&self) -> Ordering {
        sign_order(self.0.sign())
    }

    /// `floor(self / d)`, for `d` non-zero.
    pub(crate) fn div_floor(&self, d: &Integer) -> Integer {
        Integer(self.0.div_floor(&d.0))
    }

    pub(crate) fn is_perfect_square(&self) -> bool {
        !self.0.is_negative() && {
            let root = self.0.sqrt();
            &root * &root == self.0
        }
    }

    /// The integer square root (rounded down) of a non-negative integer.
    pub(crate) fn sqrt(&self) -> Integer {
        Integer(self.0.sqrt())
    }

    pub(crate) fn is_divisible(&self, d: &Integer) -> bool {
        self.0.is_multiple_of(&d.0)
    }

    /// `self mod d` in `0..d`, for `d > 0`.
    pub(crate) fn rem_small(&self, d: u32) -> u32 {
        let r = self.0.mod_floor(&BigInt::from(d));
        r.iter_u32_digits().next().unwrap_or(0)
    }

    /// `self / d`, for `d` a divisor of `self`.
    pub(crate) fn div_exact(&self, d: &Integer) -> Integer {
        Integer(&self.0 / &d.0)
    }

    /// The greatest common divisor, non-negative.
    pub(crate) fn gcd(&self, o: &Integer) -> Integer {
        Integer(self.0.gcd(&o.0))
    }

    /// `self 2^bits`.
    pub(crate) fn shifted_left(&self, bits: u64) -> Integer {
        Integer(&self.0 << bits)
    }

    pub(crate) fn plus(&self, o: &Integer) -> Integer {
        Integer(&self.0 + &o.0)
    }

    pub(crate) fn minus(&self, o: &Integer) -> Integer {
        Integer(&self.0 - &o.0)
    }

    pub(crate) fn times(&self, o: &Integer) -> Integer {
        Integer(&self.0 * &o.0)
    }

    pub(crate) fn negated(&self) -> Integer {
        Integer(-&self.0)
    }
}

fn sign_order(s: Sign) -> Ordering {
    match s {
        Sign::Minus => Ordering::Less,
        Sign::NoSign => Ordering::Equal,
        Sign::Plus => Ordering::Greater,
    }
}

impl Rational {
    /// `n / d` in lowest terms, for `d` non-zero.
    pub(crate) fn ratio(n: Integer, d: Integer) -> Rational {
        Rational::reduced(n.0, d.0)
    }

    /// `n / d` in lowest terms with a positive denominator, for `d` non-zero.
    fn reduced(n: BigInt, d: BigInt) -> Rational {
        let g = BigInt::from(lehmer::gcd(n.magnitude(), d.magnitude()));
        let (n, d) = if g.is_one() { (n, d) } else { (n / &g, d / &g) };
        let (n, d) = if d.is_negative() { (-n, -d) } else { (n, d) };
        Rational(BigRational::new_raw(n, d))
    }

    pub(crate) fn of_finite_f64(x: f64) -> Rational {
        let (neg, mantissa, exp) = f64_parts(x);
        let n = BigInt::from(mantissa);
        Rational::from_big(if neg { -n } else { n }).times_pow2(exp)
    }

    fn from_big(n: BigInt) -> Rational {
        Rational(BigRational::from_integer(n))
    }

    pub(crate) fn numer(&self) -> Integer {
        Integer(self.0.numer().clone())
    }

    pub(crate) fn denom(&self) -> Integer {
        Integer(self.0.denom().clone())
    }

    pub(crate) fn numer_bits(&self) -> u64 {
        self.0.numer().bits()
    }

    pub(crate) fn denom_bits(&self) -> u64 {
        self.0.denom().bits()
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.0.is_zero()
    }

    pub(crate) fn cmp0(&self) -> Ordering {
        sign_order(self.0.numer().sign())
    }

    /// The `f64` next to the value towards zero (infinite beyond the `f64` range), as GMP's
    /// `mpq_get_d` gives it.
    pub(crate) fn to_f64(&self) -> f64 {
        let toward_zero = if self.cmp0().is_lt() {
            Round::Up
        } else {
            Round::Down
        };
        let x = Float::from_rational(self, 64, toward_zero);
        match x.top_exponent() {
            Some(e) if e > 1024 => x.to_f64(Round::Nearest),
            _ => x.to_f64(toward_zero),
        }
    }

    pub(crate) fn plus(&self, o: &Rational) -> Rational {
        let ((a, b), (c, d)) = (self.parts(), o.parts());
        if b == d {
            return Rational::reduced(a + c, b.clone());
        }
        Rational::reduced(a * d + c * b, b * d)
    }

    pub(crate) fn minus(&self, o: &Rational) -> Rational {
        self.plus(&o.negated())
    }

    pub(crate) fn times(&self, o: &Rational) -> Rational {
        let ((a, b), (c, d)) = (self.parts(), o.parts());
        Rational::reduced(a * c, b * d)
    }

    /// `self / o`; zero if `o` is zero.
    pub(crate) fn over(&self, o: &Rational) -> Rational {
        if o.is_zero() {
            return Rational::default();
        }
        let ((a, b), (c, d)) = (self.parts(), o.parts());
        Rational::reduced(a * d, b * c)
    }

    pub(crate) fn negated(&self) -> Rational {
        Rational(BigRational::new_raw(
            -self.0.numer(),
            self.0.denom().clone(),
        ))
    }

    fn parts(&self) -> (&BigInt, &BigInt) {
        (self.0.numer(), self.0.denom())
    }
}
