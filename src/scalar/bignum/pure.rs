//! The big numbers in pure Rust (without the feature `gmp`): integers and rationals from
//! num-bigint and num-rational, and binary floats `(-1)^s m 2^e` over a big-integer
//! magnitude, each operation computed exactly (or with a remainder flag) and rounded once.
//!
//! Fractions are reduced here with Lehmer's gcd ([`lehmer`]) rather than by num-rational's
//! arithmetic, and compared and hashed by their reduced parts rather than by num-rational's
//! continued fractions: those three were nine tenths of the pure build's time.

use super::lehmer;
use super::Round;
use num_bigint::{BigInt, BigUint, Sign};
use num_integer::Integer as _;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
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

    /// `self / d`, for `d` a divisor of `self`.
    pub(crate) fn div_exact(&self, d: &Integer) -> Integer {
        Integer(&self.0 / &d.0)
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
        let (neg, mag, exp) = decompose(x);
        let n = BigInt::from_biguint(if neg { Sign::Minus } else { Sign::Plus }, mag);
        Rational(BigRational::from_integer(n)).times_pow2(exp)
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

/// `x = (-1)^neg mag 2^exp` for a finite `x`.
fn decompose(x: f64) -> (bool, BigUint, i64) {
    let bits = x.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as i64;
    let fraction = bits & ((1u64 << 52) - 1);
    let (mantissa, exp) = if exponent == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1u64 << 52), exponent - 1075)
    };
    (x.is_sign_negative(), BigUint::from(mantissa), exp)
}

/// A binary floating-point number of any precision, or an infinity, or NaN.
#[derive(Clone, Debug)]
pub(crate) enum Float {
    /// `(-1)^neg mag 2^exp`; zero when `mag` is zero (then `neg` is false).
    Finite {
        neg: bool,
        mag: BigUint,
        exp: i64,
    },
    Infinite {
        neg: bool,
    },
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

impl Float {
    fn finite(neg: bool, mag: BigUint, exp: i64) -> Float {
        let neg = neg && !mag.is_zero();
        Float::Finite { neg, mag, exp }
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
        Float::finite(neg, kept, exp)
    }

    pub(crate) fn zero(_prec: u32) -> Float {
        Float::finite(false, BigUint::zero(), 0)
    }

    pub(crate) fn infinite(neg: bool) -> Float {
        Float::Infinite { neg }
    }

    pub(crate) fn from_rational(q: &Rational, prec: u32, r: Round) -> Float {
        let (n, d) = (q.0.numer(), q.0.denom());
        quotient(n.is_negative(), n.magnitude(), 0, d.magnitude(), 0, prec, r)
    }

    pub(crate) fn add(a: &Float, b: &Float, prec: u32, r: Round) -> Float {
        match (a, b) {
            (Float::Nan, _) | (_, Float::Nan) => Float::Nan,
            (Float::Infinite { neg: p }, Float::Infinite { neg: q }) if p != q => Float::Nan,
            (Float::Infinite { neg }, _) | (_, Float::Infinite { neg }) => Float::infinite(*neg),
            (
                Float::Finite {
                    neg: na,
                    mag: ma,
                    exp: ea,
                },
                Float::Finite {
                    neg: nb,
                    mag: mb,
                    exp: eb,
                },
            ) => sum(*na, ma, *ea, *nb, mb, *eb, prec, r),
        }
    }

    pub(crate) fn sub(a: &Float, b: &Float, prec: u32, r: Round) -> Float {
        Float::add(a, &b.negated(), prec, r)
    }

    pub(crate) fn mul(a: &Float, b: &Float, prec: u32, r: Round) -> Float {
        match (a, b) {
            (Float::Nan, _) | (_, Float::Nan) => Float::Nan,
            (Float::Infinite { .. }, _) | (_, Float::Infinite { .. }) => {
                if a.is_zero() || b.is_zero() {
                    Float::Nan
                } else {
                    Float::infinite(a.is_negative() != b.is_negative())
                }
            }
            (
                Float::Finite {
                    neg: na,
                    mag: ma,
                    exp: ea,
                },
                Float::Finite {
                    neg: nb,
                    mag: mb,
                    exp: eb,
                },
            ) => Float::rounded(na != nb, ma * mb, ea + eb, false, prec, r),
        }
    }

    pub(crate) fn div(a: &Float, b: &Float, prec: u32, r: Round) -> Float {
        match (a, b) {
            (Float::Nan, _) | (_, Float::Nan) => Float::Nan,
            (Float::Infinite { .. }, Float::Infinite { .. }) => Float::Nan,
            (Float::Infinite { neg }, _) => Float::infinite(*neg != b.is_negative()),
            (_, Float::Infinite { .. }) => Float::zero(prec),
            (_, _) if b.is_zero() => Float::Nan,
            (
                Float::Finite {
                    neg: na,
                    mag: ma,
                    exp: ea,
                },
                Float::Finite {
                    neg: nb,
                    mag: mb,
                    exp: eb,
                },
            ) => quotient(na != nb, ma, *ea, mb, *eb, prec, r),
        }
    }

    /// The square root; NaN below zero.
    pub(crate) fn sqrt(&self, prec: u32, r: Round) -> Float {
        match self {
            Float::Nan | Float::Infinite { neg: true } | Float::Finite { neg: true, .. } => {
                Float::Nan
            }
            Float::Infinite { neg: false } => self.clone(),
            Float::Finite { mag, exp, .. } => {
                if mag.is_zero() {
                    return self.clone();
                }
                // An even exponent, and at least 2 (prec + 3) bits, so that the root has
                // prec + 3.
                let want = 2 * (u64::from(prec) + 3);
                let mut shift = want.saturating_sub(mag.bits());
                if (exp - shift as i64) % 2 != 0 {
                    shift += 1;
                }
                let radicand = mag << shift;
                let root = radicand.sqrt();
                let sticky = &root * &root != radicand;
                Float::rounded(false, root, (exp - shift as i64) / 2, sticky, prec, r)
            }
        }
    }

    pub(crate) fn negated(&self) -> Float {
        match self {
            Float::Finite { neg, mag, exp } => Float::finite(!neg, mag.clone(), *exp),
            Float::Infinite { neg } => Float::infinite(!neg),
            Float::Nan => Float::Nan,
        }
    }

    fn is_negative(&self) -> bool {
        matches!(
            self,
            Float::Finite { neg: true, .. } | Float::Infinite { neg: true }
        )
    }

    pub(crate) fn compare(&self, o: &Float) -> Option<Ordering> {
        let rank = |x: &Float| match x {
            Float::Infinite { neg: true } => Some(-1),
            Float::Finite { .. } => Some(0),
            Float::Infinite { neg: false } => Some(1),
            Float::Nan => None,
        };
        let by_rank = rank(self)?.cmp(&rank(o)?);
        if by_rank != Ordering::Equal {
            return Some(by_rank);
        }
        let (Float::Finite { .. }, Float::Finite { .. }) = (self, o) else {
            return Some(Ordering::Equal);
        };
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
        matches!(self, Float::Finite { mag, .. } if mag.is_zero())
    }

    /// `e` with `2^(e-1) <= |x| < 2^e`; `None` for zero, infinities and NaN.
    pub(crate) fn top_exponent(&self) -> Option<i64> {
        match self {
            Float::Finite { mag, exp, .. } if !mag.is_zero() => Some(exp + mag.bits() as i64),
            _ => None,
        }
    }

    /// The `f64` rounded in the direction `r` (beyond the `f64` range: the largest finite
    /// value where the direction allows it, otherwise an infinity).
    pub(crate) fn to_f64(&self, r: Round) -> f64 {
        let (neg, mag, exp) = match self {
            Float::Nan => return f64::NAN,
            Float::Infinite { neg } => {
                return if *neg {
                    f64::NEG_INFINITY
                } else {
                    f64::INFINITY
                }
            }
            Float::Finite { neg, mag, exp } => (*neg, mag, *exp),
        };
        if mag.is_zero() {
            return 0.0;
        }
        // The unit of the last place: 53 bits below the top, but no finer than subnormals.
        let lsb = (exp + mag.bits() as i64 - 53).max(-1074);
        let m = if exp >= lsb {
            mag << (exp - lsb) as u64
        } else {
            round_shift(neg, mag, (lsb - exp) as u64, false, r)
        };
        let magnitude = if lsb + m.bits() as i64 > 1024 {
            let to_infinity = match r {
                Round::Nearest => true,
                Round::Down => neg,
                Round::Up => !neg,
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
        if neg {
            -magnitude
        } else {
            magnitude
        }
    }

    /// The exact value; `None` for infinities and NaN.
    pub(crate) fn to_rational(&self) -> Option<Rational> {
        let Float::Finite { neg, mag, exp } = self else {
            return None;
        };
        let sign = if *neg { Sign::Minus } else { Sign::Plus };
        let n = BigRational::from_integer(BigInt::from_biguint(sign, mag.clone()));
        Some(Rational(n).times_pow2(*exp))
    }
}

/// `2^e` for `-1022 <= e <= 1023`.
fn pow2(e: i64) -> f64 {
    f64::from_bits(((e + 1023) as u64) << 52)
}

/// `(-1)^neg (ma 2^ea) / (mb 2^eb)` rounded to `prec` bits, for `mb` non-zero.
fn quotient(neg: bool, ma: &BigUint, ea: i64, mb: &BigUint, eb: i64, prec: u32, r: Round) -> Float {
    if ma.is_zero() {
        return Float::zero(prec);
    }
    // Enough bits in the dividend for a quotient of prec + 3 bits.
    let want = u64::from(prec) + 3 + mb.bits();
    let shift = want.saturating_sub(ma.bits());
    let (q, rem) = (ma << shift).div_rem(mb);
    Float::rounded(neg, q, ea - eb - shift as i64, !rem.is_zero(), prec, r)
}

/// `(-1)^na ma 2^ea + (-1)^nb mb 2^eb`, rounded to `prec` bits.
#[allow(clippy::too_many_arguments)]
fn sum(
    na: bool,
    ma: &BigUint,
    ea: i64,
    nb: bool,
    mb: &BigUint,
    eb: i64,
    prec: u32,
    r: Round,
) -> Float {
    if mb.is_zero() {
        return Float::rounded(na, ma.clone(), ea, false, prec, r);
    }
    if ma.is_zero() {
        return Float::rounded(nb, mb.clone(), eb, false, prec, r);
    }
    let (top_a, top_b) = (ea + ma.bits() as i64, eb + mb.bits() as i64);
    let ((nx, mx, ex), (ny, my, ey)) = if top_a >= top_b {
        ((na, ma, ea), (nb, mb, eb))
    } else {
        ((nb, mb, eb), (na, ma, ea))
    };
    // A summand below both the larger one's last bit and the rounding grid's quarter unit
    // (`x` and the grid's points and midpoints are multiples of 2^floor) moves the sum inside
    // an interval free of them, as does a token 2^(floor - 1) of its sign: the token rounds
    // the same way and keeps the exact sum short.
    let floor = ex.min(ex + mx.bits() as i64 - i64::from(prec) - 2);
    let token = BigUint::one();
    let (my, ey) = if ey + my.bits() as i64 <= floor {
        (&token, floor - 1)
    } else {
        (my, ey)
    };
    let e = ex.min(ey);
    let x = BigInt::from_biguint(sign_of(nx), mx << (ex - e) as u64);
    let y = BigInt::from_biguint(sign_of(ny), my << (ey - e) as u64);
    let total = x + y;
    Float::rounded(
        total.is_negative(),
        total.magnitude().clone(),
        e,
        false,
        prec,
        r,
    )
}

fn sign_of(neg: bool) -> Sign {
    if neg {
        Sign::Minus
    } else {
        Sign::Plus
    }
}
