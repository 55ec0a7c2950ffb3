//! Binary floats of any precision in pure Rust: `(-1)^neg mag 2^exp` over a big-integer
//! magnitude, each operation computed exactly (or with a flag for a non-zero remainder) and
//! then rounded once, as MPFR does.

use super::super::Round;
use super::Rational;
use num_bigint::{BigInt, BigUint, Sign};
use num_integer::Integer as _;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cmp::Ordering;

/// A finite value `(-1)^neg mag 2^exp`; zero when `mag` is zero (then `neg` is false).
#[derive(Clone, Debug)]
pub(crate) struct Dyadic {
    neg: bool,
    mag: BigUint,
    exp: i64,
}

impl Dyadic {
    /// `e` with `2^(e-1) <= |x| < 2^e`, for `x` non-zero.
    fn top(&self) -> i64 {
        self.exp + self.mag.bits() as i64
    }
}

/// A binary floating-point number of any precision, or an infinity, or NaN.
#[derive(Clone, Debug)]
pub(crate) enum Float {
    Finite(Dyadic),
    Infinite { neg: bool },
    Nan,
}

/// `mag >> drop`, rounded as `r` asks for a value of sign `neg`, where `sticky` says the exact
/// magnitude exceeds `mag` by less than one unit of `mag` (callers then keep at least two bits
/// below the rounding position, so that the flag cannot reach the half-way bit).
fn round_shift(neg: bool, mag: &BigUint, drop: u64, sticky: bool, r: Round) -> BigUint {
    if drop == 0 {
        debug_assert!(!sticky, "an inexact magnitude is longer than its precision");
        return mag.clone();
    }
    let kept = mag >> drop;
    let zeros = mag.trailing_zeros().unwrap_or(u64::MAX);
    let inexact = sticky || zeros < drop;
    let away = match r {
        Round::Down => neg && inexact,
        Round::Up => !neg && inexact,
        Round::Nearest => {
            let half = mag.bit(drop - 1);
            let beyond_half = sticky || zeros < drop - 1;
            half && (beyond_half || kept.bit(0))
        }
    };
    if away {
        kept + 1u32
    } else {
        kept
    }
}

/// `(-1)^neg (mag + sticky) 2^exp` rounded to `prec` bits (see [`round_shift`]).
fn rounded(neg: bool, mag: BigUint, exp: i64, sticky: bool, prec: u32, r: Round) -> Float {
    let drop = mag.bits().saturating_sub(u64::from(prec));
    let mut kept = round_shift(neg, &mag, drop, sticky, r);
    let mut exp = exp + drop as i64;
    // A carry into a new bit leaves a power of two: one bit fewer, exactly.
    if kept.bits() > u64::from(prec) {
        kept >>= 1u32;
        exp += 1;
    }
    finite(neg, kept, exp)
}

fn finite(neg: bool, mag: BigUint, exp: i64) -> Float {
    let neg = neg && !mag.is_zero();
    Float::Finite(Dyadic { neg, mag, exp })
}

/// `a + b` rounded to `prec` bits.
fn sum(a: &Dyadic, b: &Dyadic, prec: u32, r: Round) -> Float {
    if b.mag.is_zero() {
        return rounded(a.neg, a.mag.clone(), a.exp, false, prec, r);
    }
    if a.mag.is_zero() {
        return rounded(b.neg, b.mag.clone(), b.exp, false, prec, r);
    }
    let (x, y) = if a.top() >= b.top() { (a, b) } else { (b, a) };
    // A summand below both the larger one's last bit and the rounding grid's quarter unit
    // (`x` and the grid's points and midpoints are multiples of 2^floor) moves the sum inside
    // an interval free of them, as does a token 2^(floor - 1) of its sign: the token rounds
    // the same way and keeps the exact sum short.
    let floor = x.exp.min(x.top() - i64::from(prec) - 2);
    let token = BigUint::one();
    let (y_mag, y_exp) = if y.top() <= floor {
        (&token, floor - 1)
    } else {
        (&y.mag, y.exp)
    };
    let e = x.exp.min(y_exp);
    let signed = |neg: bool, mag: &BigUint, exp: i64| {
        let sign = if neg { Sign::Minus } else { Sign::Plus };
        BigInt::from_biguint(sign, mag << (exp - e) as u64)
    };
    let total = signed(x.neg, &x.mag, x.exp) + signed(y.neg, y_mag, y_exp);
    rounded(
        total.is_negative(),
        total.magnitude().clone(),
        e,
        false,
        prec,
        r,
    )
}

/// `a / b` rounded to `prec` bits, for `b` non-zero.
fn quotient(a: &Dyadic, b: &Dyadic, prec: u32, r: Round) -> Float {
    if a.mag.is_zero() {
        return Float::zero(prec);
    }
    // Enough bits in the dividend for a quotient of prec + 3 bits.
    let want = u64::from(prec) + 3 + b.mag.bits();
    let shift = want.saturating_sub(a.mag.bits());
    let (q, rem) = (&a.mag << shift).div_rem(&b.mag);
    let exp = a.exp - b.exp - shift as i64;
    rounded(a.neg != b.neg, q, exp, !rem.is_zero(), prec, r)
}

/// `2^e` for `-1022 <= e <= 1023`.
fn pow2(e: i64) -> f64 {
    f64::from_bits(((e + 1023) as u64) << 52)
}

impl Float {
    pub(crate) fn zero(_prec: u32) -> Float {
        finite(false, BigUint::zero(), 0)
    }

    pub(crate) fn infinite(neg: bool) -> Float {
        Float::Infinite { neg }
    }

    pub(crate) fn from_rational(q: &Rational, prec: u32, r: Round) -> Float {
        let (n, d) = q.parts();
        let numerator = Dyadic {
            neg: n.is_negative(),
            mag: n.magnitude().clone(),
            exp: 0,
        };
        let denominator = Dyadic {
            neg: false,
            mag: d.magnitude().clone(),
            exp: 0,
        };
        quotient(&numerator, &denominator, prec, r)
    }

    pub(crate) fn add(a: &Float, b: &Float, prec: u32, r: Round) -> Float {
        match (a, b) {
            (Float::Nan, _) | (_, Float::Nan) => Float::Nan,
            (Float::Infinite { neg: p }, Float::Infinite { neg: q }) if p != q => Float::Nan,
            (Float::Infinite { neg }, _) | (_, Float::Infinite { neg }) => Float::infinite(*neg),
            (Float::Finite(x), Float::Finite(y)) => sum(x, y, prec, r),
        }
    }

    pub(crate) fn sub(a: &Float, b: &Float, prec: u32, r: Round) -> Float {
        Float::add(a, &b.negated(), prec, r)
    }

    pub(crate) fn mul(a: &Float, b: &Float, prec: u32, r: Round) -> Float {
        match (a, b) {
            (Float::Nan, _) | (_, Float::Nan) => Float::Nan,
            (Float::Finite(x), Float::Finite(y)) => rounded(
                x.neg != y.neg,
                &x.mag * &y.mag,
                x.exp + y.exp,
                false,
                prec,
                r,
            ),
            _ if a.is_zero() || b.is_zero() => Float::Nan,
            _ => Float::infinite(a.is_negative() != b.is_negative()),
        }
    }

    pub(crate) fn div(a: &Float, b: &Float, prec: u32, r: Round) -> Float {
        match (a, b) {
            (Float::Nan, _) | (_, Float::Nan) => Float::Nan,
            (Float::Infinite { .. }, Float::Infinite { .. }) => Float::Nan,
            (Float::Infinite { neg }, _) => Float::infinite(*neg != b.is_negative()),
            (_, Float::Infinite { .. }) => Float::zero(prec),
            (Float::Finite(x), Float::Finite(y)) if !y.mag.is_zero() => quotient(x, y, prec, r),
            _ => Float::Nan,
        }
    }

    /// The square root; NaN below zero.
    pub(crate) fn sqrt(&self, prec: u32, r: Round) -> Float {
        let x = match self {
            Float::Infinite { neg: false } => return self.clone(),
            Float::Finite(x) if !x.neg => x,
            _ => return Float::Nan,
        };
        if x.mag.is_zero() {
            return self.clone();
        }
        // An even exponent, and at least 2 (prec + 3) bits, so that the root has prec + 3.
        let want = 2 * (u64::from(prec) + 3);
        let mut shift = want.saturating_sub(x.mag.bits());
        if (x.exp - shift as i64) % 2 != 0 {
            shift += 1;
        }
        let radicand = &x.mag << shift;
        let root = radicand.sqrt();
        let sticky = &root * &root != radicand;
        rounded(false, root, (x.exp - shift as i64) / 2, sticky, prec, r)
    }

    pub(crate) fn negated(&self) -> Float {
        match self {
            Float::Finite(x) => finite(!x.neg, x.mag.clone(), x.exp),
            Float::Infinite { neg } => Float::infinite(!neg),
            Float::Nan => Float::Nan,
        }
    }

    fn is_negative(&self) -> bool {
        match self {
            Float::Finite(x) => x.neg,
            Float::Infinite { neg } => *neg,
            Float::Nan => false,
        }
    }

    pub(crate) fn compare(&self, o: &Float) -> Option<Ordering> {
        let rank = |x: &Float| match x {
            Float::Infinite { neg: true } => Some(-1),
            Float::Finite(_) => Some(0),
            Float::Infinite { neg: false } => Some(1),
            Float::Nan => None,
        };
        let by_rank = rank(self)?.cmp(&rank(o)?);
        if by_rank != Ordering::Equal || !matches!(self, Float::Finite(_)) {
            return Some(by_rank);
        }
        // The sign of a difference survives any rounding.
        Float::sub(self, o, 2, Round::Nearest).cmp0()
    }

    /// The sign as an ordering against zero; `None` for NaN.
    pub(crate) fn cmp0(&self) -> Option<Ordering> {
        match self {
            Float::Nan => None,
            _ if self.is_zero() => Some(Ordering::Equal),
            _ if self.is_negative() => Some(Ordering::Less),
            _ => Some(Ordering::Greater),
        }
    }

    pub(crate) fn is_nan(&self) -> bool {
        matches!(self, Float::Nan)
    }

    pub(crate) fn is_zero(&self) -> bool {
        matches!(self, Float::Finite(x) if x.mag.is_zero())
    }

    /// `e` with `2^(e-1) <= |x| < 2^e`; `None` for zero, infinities and NaN.
    pub(crate) fn top_exponent(&self) -> Option<i64> {
        match self {
            Float::Finite(x) if !x.mag.is_zero() => Some(x.top()),
            _ => None,
        }
    }

    /// The `f64` rounded in the direction `r` (beyond the `f64` range: the largest finite
    /// value where the direction allows it, otherwise an infinity).
    pub(crate) fn to_f64(&self, r: Round) -> f64 {
        let x = match self {
            Float::Nan => return f64::NAN,
            Float::Infinite { neg: true } => return f64::NEG_INFINITY,
            Float::Infinite { neg: false } => return f64::INFINITY,
            Float::Finite(x) if x.mag.is_zero() => return 0.0,
            Float::Finite(x) => x,
        };
        // The unit of the last place: 53 bits below the top, but no finer than subnormals.
        let lsb = (x.top() - 53).max(-1074);
        let m = if x.exp >= lsb {
            &x.mag << (x.exp - lsb) as u64
        } else {
            round_shift(x.neg, &x.mag, (lsb - x.exp) as u64, false, r)
        };
        let magnitude = if lsb + m.bits() as i64 > 1024 {
            let to_infinity = match r {
                Round::Nearest => true,
                Round::Down => x.neg,
                Round::Up => !x.neg,
            };
            if to_infinity {
                f64::INFINITY
            } else {
                f64::MAX
            }
        } else {
            // Exact: m < 2^54, and each factor of two keeps the value representable.
            let m = m.to_f64().expect("at most 54 bits");
            m * pow2(lsb.max(-1022)) * pow2(lsb.min(-1022) + 1022)
        };
        if x.neg {
            -magnitude
        } else {
            magnitude
        }
    }

    /// The exact value; `None` for infinities and NaN.
    pub(crate) fn to_rational(&self) -> Option<Rational> {
        let Float::Finite(x) = self else {
            return None;
        };
        let sign = if x.neg { Sign::Minus } else { Sign::Plus };
        Some(Rational::from_big(BigInt::from_biguint(sign, x.mag.clone())).times_pow2(x.exp))
    }
}
