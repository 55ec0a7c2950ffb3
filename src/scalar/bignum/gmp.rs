//! The big numbers from GMP and MPFR, through rug (feature `gmp`).

use super::Round;
use rug::ops::{AssignRound, DivRounding, Pow};
use std::cmp::Ordering;
use std::fmt;

/// An integer of any size (an exact rational's numerator or denominator).
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Integer(rug::Integer);

/// An exact rational number, always in lowest terms.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Rational(rug::Rational);

/// A binary floating-point number of any precision, or an infinity, or NaN.
#[derive(Clone, Debug)]
pub(crate) struct Float(rug::Float);

impl From<i64> for Integer {
    fn from(i: i64) -> Integer {
        Integer(rug::Integer::from(i))
    }
}

impl fmt::Display for Integer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.fmt(f)
    }
}

impl Integer {
    pub(crate) fn power(&self, exp: u32) -> Integer {
        Integer(rug::Integer::from((&self.0).pow(exp)))
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.0.is_zero()
    }

    pub(crate) fn is_one(&self) -> bool {
        self.0 == 1
    }

    pub(crate) fn cmp0(&self) -> Ordering {
        self.0.cmp0()
    }

    /// `floor(self / d)`, for `d` non-zero.
    pub(crate) fn div_floor(&self, d: &Integer) -> Integer {
        Integer(rug::Integer::from(DivRounding::div_floor(&self.0, &d.0)))
    }

    pub(crate) fn is_perfect_square(&self) -> bool {
        self.0.is_perfect_square()
    }

    /// The integer square root (rounded down) of a non-negative integer.
    pub(crate) fn sqrt(&self) -> Integer {
        Integer(self.0.clone().sqrt())
    }

    pub(crate) fn is_divisible(&self, d: &Integer) -> bool {
        self.0.is_divisible(&d.0)
    }

    /// `self mod d` in `0..d`, for `d > 0`.
    pub(crate) fn rem_small(&self, d: u32) -> u32 {
        self.0.mod_u(d)
    }

    /// `self / d`, for `d` a divisor of `self`.
    pub(crate) fn div_exact(&self, d: &Integer) -> Integer {
        Integer(rug::Integer::from(self.0.div_exact_ref(&d.0)))
    }

    /// The greatest common divisor, non-negative.
    pub(crate) fn gcd(&self, o: &Integer) -> Integer {
        Integer(rug::Integer::from(self.0.gcd_ref(&o.0)))
    }

    /// `self 2^bits`.
    pub(crate) fn shifted_left(&self, bits: u64) -> Integer {
        let bits = u32::try_from(bits).expect("shifts stay below 2^32 bits");
        Integer(rug::Integer::from(&self.0 << bits))
    }

    pub(crate) fn plus(&self, o: &Integer) -> Integer {
        Integer(rug::Integer::from(&self.0 + &o.0))
    }

    pub(crate) fn minus(&self, o: &Integer) -> Integer {
        Integer(rug::Integer::from(&self.0 - &o.0))
    }

    pub(crate) fn times(&self, o: &Integer) -> Integer {
        Integer(rug::Integer::from(&self.0 * &o.0))
    }

    pub(crate) fn negated(&self) -> Integer {
        Integer(rug::Integer::from(-&self.0))
    }
}

impl Rational {
    /// `n / d` in lowest terms, for `d` non-zero.
    pub(crate) fn ratio(n: Integer, d: Integer) -> Rational {
        Rational(rug::Rational::from((n.0, d.0)))
    }

    pub(crate) fn of_finite_f64(x: f64) -> Rational {
        Rational(rug::Rational::from_f64(x).expect("a finite f64"))
    }

    pub(crate) fn numer(&self) -> Integer {
        Integer(self.0.numer().clone())
    }

    pub(crate) fn denom(&self) -> Integer {
        Integer(self.0.denom().clone())
    }

    pub(crate) fn numer_bits(&self) -> u64 {
        u64::from(self.0.numer().significant_bits())
    }

    pub(crate) fn denom_bits(&self) -> u64 {
        u64::from(self.0.denom().significant_bits())
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.0.is_zero()
    }

    pub(crate) fn cmp0(&self) -> Ordering {
        self.0.cmp0()
    }

    /// The `f64` next to the value towards zero (infinite beyond the `f64` range).
    pub(crate) fn to_f64(&self) -> f64 {
        self.0.to_f64()
    }

    pub(crate) fn plus(&self, o: &Rational) -> Rational {
        Rational(rug::Rational::from(&self.0 + &o.0))
    }

    pub(crate) fn minus(&self, o: &Rational) -> Rational {
        Rational(rug::Rational::from(&self.0 - &o.0))
    }

    pub(crate) fn times(&self, o: &Rational) -> Rational {
        Rational(rug::Rational::from(&self.0 * &o.0))
    }

    /// `self / o`; zero if `o` is zero.
    pub(crate) fn over(&self, o: &Rational) -> Rational {
        if o.is_zero() {
            return Rational::default();
        }
        Rational(rug::Rational::from(&self.0 / &o.0))
    }

    pub(crate) fn negated(&self) -> Rational {
        Rational(rug::Rational::from(-&self.0))
    }
}

fn round(r: Round) -> rug::float::Round {
    match r {
        Round::Down => rug::float::Round::Down,
        Round::Up => rug::float::Round::Up,
        Round::Nearest => rug::float::Round::Nearest,
    }
}

impl Float {
    /// `v` rounded to `prec` bits in the direction `r`.
    fn rounded<T>(prec: u32, v: T, r: Round) -> Float
    where
        rug::Float: AssignRound<T, Round = rug::float::Round, Ordering = Ordering>,
    {
        Float(rug::Float::with_val_round(prec, v, round(r)).0)
    }

    pub(crate) fn zero(prec: u32) -> Float {
        Float(rug::Float::new(prec))
    }

    pub(crate) fn infinite(negative: bool) -> Float {
        let special = if negative {
            rug::float::Special::NegInfinity
        } else {
            rug::float::Special::Infinity
        };
        Float(rug::Float::with_val(64, special))
    }

    pub(crate) fn from_rational(q: &Rational, prec: u32, r: Round) -> Float {
        Float::rounded(prec, &q.0, r)
    }

    pub(crate) fn add(a: &Float, b: &Float, prec: u32, r: Round) -> Float {
        Float::rounded(prec, &a.0 + &b.0, r)
    }

    pub(crate) fn sub(a: &Float, b: &Float, prec: u32, r: Round) -> Float {
        Float::rounded(prec, &a.0 - &b.0, r)
    }

    pub(crate) fn mul(a: &Float, b: &Float, prec: u32, r: Round) -> Float {
        Float::rounded(prec, &a.0 * &b.0, r)
    }

    pub(crate) fn div(a: &Float, b: &Float, prec: u32, r: Round) -> Float {
        Float::rounded(prec, &a.0 / &b.0, r)
    }

    /// The square root; NaN below zero.
    pub(crate) fn sqrt(&self, prec: u32, r: Round) -> Float {
        Float::rounded(prec, self.0.sqrt_ref(), r)
    }

    pub(crate) fn negated(&self) -> Float {
        Float(-self.0.clone())
    }

    pub(crate) fn compare(&self, o: &Float) -> Option<Ordering> {
        self.0.partial_cmp(&o.0)
    }

    /// The sign as an ordering against zero; `None` for NaN.
    pub(crate) fn cmp0(&self) -> Option<Ordering> {
        self.0.cmp0()
    }

    pub(crate) fn is_nan(&self) -> bool {
        self.0.is_nan()
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.0.is_zero()
    }

    /// `e` with `2^(e-1) <= |x| < 2^e`; `None` for zero, infinities and NaN.
    pub(crate) fn top_exponent(&self) -> Option<i64> {
        self.0.get_exp().map(i64::from)
    }

    /// The `f64` rounded in the direction `r` (beyond the `f64` range: the largest finite
    /// value where the direction allows it, otherwise an infinity).
    pub(crate) fn to_f64(&self, r: Round) -> f64 {
        self.0.to_f64_round(round(r))
    }

    /// The exact value; `None` for infinities and NaN.
    pub(crate) fn to_rational(&self) -> Option<Rational> {
        self.0.to_rational().map(Rational)
    }
}
