//! The exact backend: real numbers built from rationals with `+ - * /` and square roots, with
//! certified signs, in the manner of CORE's `Expr` and LEDA's `real`.
//!
//! A [`Real`] is a node of an expression DAG over rational leaves (an `f64` input converts
//! exactly). Its sign is decided in stages, each counted ([`DecisionCounts`]):
//! 1. the `f64` interval computed when the node was built (the filter);
//! 2. without square roots below it, exact rational evaluation; with them, intervals of
//!    binary floats rounded outwards (MPFR, or pure Rust without the feature `gmp`: see
//!    `scalar::bignum`) at doubling precision until the enclosure excludes zero;
//! 3. a zero is certified by structure (`x - x` of two copies of one expression), by exact
//!    rational evaluation, by a zero normal form in a tower of quadratic extensions, or when
//!    the enclosure is smaller than the BFMSS separation bound \[BFMSS01\] (a non-zero value
//!    cannot be that small); last, by a zero normal form in which the subexpressions too
//!    large to expand are indeterminates (an identity whatever their values), or by
//!    eliminating the square roots of a normal form one at a time (`A + B s = 0` where `A`
//!    and `B` have opposite signs and `A^2 - B^2 s^2 = 0`);
//! 4. a decision that reaches the precision cap (this thread's: [`set_precision_cap`], or the
//!    run's: [`PropagateOptions::precision_cap`](crate::PropagateOptions)) without either is
//!    *uncertified*: the value is then within `2^-cap` of zero, it is treated as zero (a tie),
//!    and it is recorded with its place, never passed off as exact.
//!
//! Division by zero: `x / y` builds a node whatever `y` is, and a value with a division whose
//! divisor the filter cannot show non-zero has its divisors decided first (stages 1 to 4). If
//! one is zero, or not certified within the cap, the value is undefined or may be, and its sign
//! is *uncertified* ([`Uncertainty::DivisionByZero`] or [`Uncertainty::PrecisionCap`]): zero
//! is returned, counted and located like any uncertified decision, and never certified (not
//! even when the rest of the expression would settle it, as in `sqrt(1 / 0) + 1`).
//! [`Field::to_f64`] of a value with a divisor certified zero is NaN.
//!
//! \[BFMSS01\] Burnikel, Funke, Mehlhorn, Schirra, Schmitt, *A separation bound for real
//! algebraic expressions*, ESA 2001.

mod decimal;
mod form;
mod node;
mod normal_form;
mod refine;

pub use super::audit::{Certificate, Uncertainty, ZeroProof};
pub use super::bignum::{Integer, Rational};

/// The exact squared distance between two points with finite float coordinates: equal values
/// prove equal lengths.
pub(crate) fn squared_distance(a: [f64; 3], b: [f64; 3]) -> Option<Rational> {
    let mut sum = Rational::from(0);
    for (x, y) in a.into_iter().zip(b) {
        let d = Rational::from_f64(x)? - Rational::from_f64(y)?;
        sum = sum + d.clone() * d;
    }
    Some(sum)
}

use super::audit::{self, DecisionCounts, Site};
use super::bignum::{Float, Round};
use super::roots::{self, CertifiedSign};
use super::{Bisector, BisectorRoots, Field, Interval, Lower, Ring, Scalar, Sign, SourceDistance};
use node::{DivisorCheck, Node, Op};
use std::cell::Cell;
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};
use std::sync::Arc;
use thiserror::Error;

/// The precision cap, in bits, used unless [`set_precision_cap`] says otherwise.
pub const DEFAULT_PRECISION_CAP: u32 = 8192;

/// The first precision of the exact stage, in bits.
const FIRST_PRECISION: u32 = 128;

/// The margin by which the front must be beyond an enclosure of a wedge's distances before its
/// edge is given up ([`Scalar::front_passed`]): half of [`FRONT_MARGIN`](super::FRONT_MARGIN),
/// `2^-21`. The later wedges' distances lie above the front to the rounding of its `f64` key
/// (ulps), far below this; the other half covers the width of the enclosure and the rounding
/// of the `f64` value at which the engine asks, so that the edge is given up when the engine
/// first asks, as in the float backends.
const FRONT_CERTIFIED_MARGIN: f64 = 1.0 + 1.0 / (1u64 << 21) as f64;

/// The precision, in bits, up to which a sign is sought without a proof of zero where the
/// engine can do without it ([`CertifiedSign::clear_sign`]) and before a square root's radicand
/// is taken as positive by the normal form.
const CLEAR_PRECISION: u32 = 1024;

/// The smallest precision cap, in bits: the exact stage starts at this precision.
pub const MIN_PRECISION_CAP: u32 = FIRST_PRECISION;

/// The largest precision cap, in bits. Refinement doubles the precision up to the cap and keeps
/// an enclosure of two big floats on every node of the expression, so at `2^20` bits a hard
/// decision already costs 256 KiB per node; a larger cap would exhaust memory before it helped.
pub const MAX_PRECISION_CAP: u32 = 1 << 20;

thread_local! {
    /// This thread's precision cap: each thread (each propagation) has its own.
    static PRECISION_CAP: Cell<u32> = const { Cell::new(DEFAULT_PRECISION_CAP) };
}

/// A precision cap outside [`MIN_PRECISION_CAP`]`..=`[`MAX_PRECISION_CAP`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Error)]
#[error("precision cap {bits} is out of range: it must be from {MIN_PRECISION_CAP} to {MAX_PRECISION_CAP} bits")]
pub struct PrecisionCapError {
    /// The cap asked for, in bits.
    pub bits: u32,
}

/// Sets the largest precision, in bits, at which this thread seeks a sign before the decision
/// is recorded as uncertified (other threads keep theirs). A propagation sets it from its
/// options ([`PropagateOptions::precision_cap`](crate::PropagateOptions)) when they give one.
///
/// # Errors
/// [`PrecisionCapError`] if `bits` is below [`MIN_PRECISION_CAP`] or above
/// [`MAX_PRECISION_CAP`]; the cap is then left as it was.
///
/// # Example
/// ```
/// use exact_geodesics::scalar::exact::{precision_cap, set_precision_cap};
/// set_precision_cap(4096)?;
/// assert_eq!(precision_cap(), 4096);
/// assert!(set_precision_cap(0).is_err());
/// assert_eq!(precision_cap(), 4096);
/// # Ok::<(), exact_geodesics::scalar::exact::PrecisionCapError>(())
/// ```
pub fn set_precision_cap(bits: u32) -> Result<(), PrecisionCapError> {
    if !(MIN_PRECISION_CAP..=MAX_PRECISION_CAP).contains(&bits) {
        return Err(PrecisionCapError { bits });
    }
    PRECISION_CAP.set(bits);
    Ok(())
}

/// This thread's precision cap, in bits.
pub fn precision_cap() -> u32 {
    PRECISION_CAP.get()
}

/// An exact real number: an expression DAG over rationals with `+ - * /` and `sqrt`.
#[derive(Clone)]
pub struct Real(Arc<Node>);

/// Why [`Real::certified_decimal`] gives no digits.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "{digits} certified digits are out of reach (an uncertified decision, or beyond the \
     precision cap)"
)]
pub struct DigitsOutOfReach {
    /// The digits asked for.
    pub digits: u32,
}

impl Real {
    /// [`Scalar::bisector`] with the signs the engine knows apart (`signs`).
    fn meeting(
        a: &SourceDistance<Real>,
        b: &SourceDistance<Real>,
        [lo, hi]: [&Real; 2],
        known: &[Option<[Real; 2]>; 2],
        signs: &impl roots::InputSigns,
    ) -> Bisector<Real> {
        let known = known
            .each_ref()
            .map(|v| v.as_ref().map(|[t, m]| (t.clone() - m).decide()));
        let ties = known.map(|s| s == Some(Sign::Zero));
        let crossings = roots::crossings(a, b, lo, hi, signs, ties)
            .expect("the exact backend decides every sign");
        let changes = crossings.changes();
        let first = roots::first_stretch_sign(
            (a, b),
            [lo, hi],
            changes,
            &roots::InT,
            known,
            <Real as CertifiedSign>::clear_sign,
        );
        let roots = roots::into_roots(crossings, lo);
        let first = first.unwrap_or_else(|| {
            let end = match &roots {
                BisectorRoots::One(r) | BisectorRoots::Touch(r) | BisectorRoots::Two(r, _) => r,
                _ => hi,
            };
            let mid = (lo.clone() + end) * &Real::from_f64(0.5);
            (a.at(&mid) - &b.at(&mid)).decide()
        });
        Bisector::alternating(roots, Lower::of_difference(first))
    }

    /// The exact value of a rational.
    pub fn from_rational(r: Rational) -> Real {
        Real(Node::leaf(r))
    }

    /// The exact value of an integer.
    pub fn from_integer(i: i64) -> Real {
        Real::from_rational(Rational::from(i))
    }

    /// The sign and how it was established, without counting the decision.
    ///
    /// A value that divides by zero, or whose divisors cannot all be certified non-zero within
    /// the precision cap, is [`Certificate::Uncertified`] with sign zero.
    pub fn certified_sign(&self) -> (Sign, Certificate) {
        self.certified_sign_with(true)
    }

    /// [`Real::certified_sign`]; `thorough` allows a zero's last resort its larger budget (see
    /// [`normal_form::zero_by_elimination`]), which a sign the engine can do without (asked
    /// by [`CertifiedSign::proved_sign`]) is not worth: on cad_featuretype two such signs
    /// took 5.4 s of 14.
    fn certified_sign_with(&self, thorough: bool) -> (Sign, Certificate) {
        let node = &self.0;
        if let Err(cause) = check_divisors(node) {
            return (Sign::Zero, Certificate::Uncertified(cause));
        }
        if let Some(settled) = self.settled_without_refinement() {
            return settled;
        }
        if let Some(settled) = self.sign_of_factors() {
            return settled;
        }
        let (lo, hi) = refine::enclosure(node, FIRST_PRECISION);
        if lo.cmp0() == Some(Ordering::Greater) {
            return (Sign::Positive, Certificate::Refinement);
        }
        if hi.cmp0() == Some(Ordering::Less) {
            return (Sign::Negative, Certificate::Refinement);
        }
        if normal_form::zero_by_squares(node) {
            return (
                Sign::Zero,
                Certificate::CertifiedZero(ZeroProof::NormalForm),
            );
        }
        let cap = precision_cap();
        let zero_bits = refine::zero_bound_bits(node, cap);
        let mut precision = (2 * FIRST_PRECISION).min(cap);
        loop {
            let (lo, hi) = refine::enclosure(node, precision);
            if lo.cmp0() == Some(Ordering::Greater) {
                return (Sign::Positive, Certificate::Refinement);
            }
            if hi.cmp0() == Some(Ordering::Less) {
                return (Sign::Negative, Certificate::Refinement);
            }
            if let Some(bits) = zero_bits {
                if below(&lo, bits) && below(&hi, bits) {
                    return (
                        Sign::Zero,
                        Certificate::CertifiedZero(ZeroProof::SeparationBound),
                    );
                }
            }
            if precision >= cap {
                if normal_form::zero_over_atoms(node)
                    || normal_form::zero_by_elimination(node, thorough)
                {
                    return (
                        Sign::Zero,
                        Certificate::CertifiedZero(ZeroProof::NormalForm),
                    );
                }
                return (
                    Sign::Zero,
                    Certificate::Uncertified(Uncertainty::PrecisionCap(precision)),
                );
            }
            precision = precision.saturating_mul(2).min(cap);
        }
    }

    /// The value in decimal with `digits` significant digits (`digits >= 1`), differing from
    /// the exact value by less than one unit in its last digit (a rounded midpoint of a
    /// certified enclosure at least ten times narrower than that unit); `"0"` for a value
    /// certified zero. `None` if the sign is not certified (within the
    /// precision cap, or because the value divides by zero) or if the cap does not allow an
    /// enclosure that narrow. Written `d.ddd` with an exponent `e-x` / `ex` unless it is zero.
    ///
    /// # Example
    /// ```
    /// use exact_geodesics::scalar::{Field, Real};
    /// let root2 = Real::from_integer(2).sqrt();
    /// assert_eq!(root2.to_decimal(12).as_deref(), Some("1.41421356237"));
    /// let tiny = Real::from_integer(1) / Real::from_integer(3_000_000);
    /// assert_eq!(tiny.to_decimal(4).as_deref(), Some("3.333e-7"));
    /// assert_eq!((root2.clone() * &root2 - Real::from_integer(2)).to_decimal(5).as_deref(), Some("0"));
    /// ```
    pub fn to_decimal(&self, digits: u32) -> Option<String> {
        let digits = digits.max(1);
        match self.certified_sign() {
            (_, Certificate::Uncertified(_)) => return None,
            (Sign::Zero, _) => return Some("0".to_owned()),
            _ => {}
        }
        // log2(10) < 3.33 bits per digit, and a margin for the factor of ten.
        let mut precision = (digits.saturating_mul(4) + 64).max(FIRST_PRECISION);
        let cap = precision_cap().max(precision);
        loop {
            let (lo, hi) = refine::enclosure(&self.0, precision);
            if let (Some(lo), Some(hi)) = (lo.to_rational(), hi.to_rational()) {
                if let Some(text) = decimal::rounded_midpoint(&lo, &hi, digits) {
                    return Some(text);
                }
            }
            if precision >= cap {
                return None;
            }
            precision = precision.saturating_mul(2).min(cap);
        }
    }

    /// [`Real::to_decimal`], with the reason when the digits are out of reach.
    ///
    /// # Errors
    /// [`DigitsOutOfReach`] where `to_decimal` gives `None`.
    pub fn certified_decimal(&self, digits: u32) -> Result<String, DigitsOutOfReach> {
        self.to_decimal(digits).ok_or(DigitsOutOfReach { digits })
    }

    /// Whether the value is shown positive by refinement alone (no zero certificate), within
    /// [`CLEAR_PRECISION`] bits.
    fn positive_without_zero_test(&self) -> bool {
        self.refined_away_from_zero() == Some(Sign::Positive)
    }

    /// The sign if refinement within [`CLEAR_PRECISION`] bits moves the enclosure off zero.
    fn refined_away_from_zero(&self) -> Option<Sign> {
        let mut precision = FIRST_PRECISION;
        while precision <= CLEAR_PRECISION {
            let (lo, hi) = refine::enclosure(&self.0, precision);
            if lo.cmp0() == Some(Ordering::Greater) {
                return Some(Sign::Positive);
            }
            if hi.cmp0() == Some(Ordering::Less) {
                return Some(Sign::Negative);
            }
            precision *= 2;
        }
        None
    }

    /// The sign and its certificate from the first stages, which need no refinement (a value
    /// whose divisors are certified non-zero): a structural zero, a filter away from zero, or
    /// the exact rational value of a DAG without square roots. `None` if they cannot tell.
    fn settled_without_refinement(&self) -> Option<(Sign, Certificate)> {
        let node = &self.0;
        if node.structural_zero {
            return Some((Sign::Zero, Certificate::CertifiedZero(ZeroProof::Structure)));
        }
        // A filter of exactly zero is left to the stages that name a proof of zero.
        if let Some(s) = node.filter.sign().filter(|&s| s != Sign::Zero) {
            return Some((s, Certificate::Filter));
        }
        if node.has_sqrt {
            return None;
        }
        Some(match refine::rational_value(node).cmp0() {
            Ordering::Less => (Sign::Negative, Certificate::Refinement),
            Ordering::Equal => (
                Sign::Zero,
                Certificate::CertifiedZero(ZeroProof::RationalValue),
            ),
            Ordering::Greater => (Sign::Positive, Certificate::Refinement),
        })
    }

    /// The sign of a negation, product or quotient from its operands' certified signs (the
    /// divisors are known non-zero here): a zero of the numerator alone may be proved where
    /// that of the whole quotient, which also carries the denominator, is beyond the proofs.
    /// `None` where an operand's sign is not certified, or the value is no such operation.
    fn sign_of_factors(&self) -> Option<(Sign, Certificate)> {
        let sign = |n: &Arc<Node>| match Real(n.clone()).certified_sign() {
            (_, Certificate::Uncertified(_)) => None,
            settled => Some(settled),
        };
        match &self.0.op {
            Op::Neg(a) => sign(a).map(|(s, c)| (s.times(Sign::Negative), c)),
            Op::Mul(a, b) | Op::Div(a, b) => {
                let (sa, ca) = sign(a)?;
                if sa == Sign::Zero {
                    return Some((sa, ca));
                }
                let (sb, cb) = sign(b)?;
                let certificate = if sb == Sign::Zero {
                    cb
                } else {
                    Certificate::Refinement
                };
                Some((sa.times(sb), certificate))
            }
            _ => None,
        }
    }

    /// The sign and its certificate where it is clear without a search for a proof of zero:
    /// divisors checked, then the first stages ([`Self::settled_without_refinement`]), or
    /// refinement within [`CLEAR_PRECISION`] bits. `None` otherwise (the value may be zero).
    fn clear_certified_sign(&self) -> Option<(Sign, Certificate)> {
        check_divisors(&self.0).ok()?;
        self.settled_without_refinement().or_else(|| {
            self.refined_away_from_zero()
                .map(|s| (s, Certificate::Refinement))
        })
    }

    /// The order of two values where their filters tell it, counted as a decision; `None`
    /// otherwise. Values with divisors that may be zero are left to the sign of their
    /// difference, which checks the divisors first.
    fn filtered_order(&self, other: &Self) -> Option<Ordering> {
        if self.0.divisors_unchecked || other.0.divisors_unchecked {
            return None;
        }
        let (a, b) = (self.filter(), other.filter());
        let order = if a.hi < b.lo {
            Ordering::Less
        } else if a.lo > b.hi {
            Ordering::Greater
        } else {
            return None;
        };
        audit::record(Certificate::Filter, || [0.0; 2]);
        Some(order)
    }

    /// An `f64` enclosure of the value (from the filter, or refined when the filter is wide).
    pub fn enclosure(&self) -> [f64; 2] {
        let f = self.0.filter;
        if f.lo.is_finite() && f.hi.is_finite() {
            return [f.lo, f.hi];
        }
        let (lo, hi) = refine::enclosure(&self.0, FIRST_PRECISION);
        [lo.to_f64(Round::Down), hi.to_f64(Round::Up)]
    }

    /// An `f64` enclosure from the [`FIRST_PRECISION`]-bit one that [`Field::to_f64`] computes
    /// and keeps (a few ulps wide), unbounded for a value that may divide by zero.
    fn narrow_enclosure(&self) -> [f64; 2] {
        if check_divisors(&self.0).is_err() {
            return [f64::NEG_INFINITY, f64::INFINITY];
        }
        let f = self.filter();
        if f.lo == f.hi {
            return [f.lo, f.hi];
        }
        let (lo, hi) = refine::enclosure(&self.0, FIRST_PRECISION);
        [lo.to_f64(Round::Down), hi.to_f64(Round::Up)]
    }

    /// The sign, counted as a decision of the current run.
    fn decide(&self) -> Sign {
        let (sign, certificate) = self.certified_sign();
        audit::record(certificate, || self.enclosure());
        sign
    }

    fn filter(&self) -> Interval {
        self.0.filter
    }
}

/// Certifies every divisor at or below `node` that its filter does not show non-zero (see
/// [`Node::divisors_unchecked`]); the error says why one is not certified non-zero.
fn check_divisors(node: &Arc<Node>) -> Result<(), Uncertainty> {
    if !node.divisors_unchecked {
        return Ok(());
    }
    let cap = precision_cap();
    match node.divisors_checked.get() {
        Some(DivisorCheck::NonZero) => return Ok(()),
        Some(DivisorCheck::Zero) => return Err(Uncertainty::DivisionByZero),
        Some(&DivisorCheck::Uncertain {
            cap: then,
            precision,
        }) if then == cap => {
            return Err(Uncertainty::PrecisionCap(precision));
        }
        // Not checked yet, or at another cap (then checked again, and not kept).
        Some(DivisorCheck::Uncertain { .. }) | None => {}
    }
    let outcome = node.children().try_for_each(check_divisors).and_then(|()| {
        let Op::Div(_, divisor) = &node.op else {
            return Ok(());
        };
        match Real(divisor.clone()).certified_sign() {
            (_, Certificate::Uncertified(cause)) => Err(cause),
            (Sign::Zero, _) => Err(Uncertainty::DivisionByZero),
            (Sign::Positive | Sign::Negative, _) => Ok(()),
        }
    });
    let checked = match outcome {
        Ok(()) => DivisorCheck::NonZero,
        Err(Uncertainty::DivisionByZero) => DivisorCheck::Zero,
        Err(Uncertainty::PrecisionCap(precision)) => DivisorCheck::Uncertain { cap, precision },
    };
    // Kept by the first check only: another thread, or an earlier cap, may have been first.
    let _ = node.divisors_checked.set(checked);
    outcome
}

/// Whether `|x| <= 2^-bits`.
fn below(x: &Float, bits: u32) -> bool {
    x.is_zero() || x.top_exponent().is_some_and(|e| e <= -i64::from(bits))
}

impl fmt::Debug for Real {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Real(~{})", self.to_f64())
    }
}

macro_rules! real_ops {
    ($($tr:ident $f:ident $node:ident),*) => {$(
        impl $tr for Real {
            type Output = Real;
            #[inline]
            fn $f(self, o: Real) -> Real {
                Real(Node::$node(self.0, o.0))
            }
        }
        impl<'a> $tr<&'a Real> for Real {
            type Output = Real;
            #[inline]
            fn $f(self, o: &'a Real) -> Real {
                Real(Node::$node(self.0, o.0.clone()))
            }
        }
    )*};
}
real_ops!(Add add add, Sub sub sub, Mul mul mul, Div div div);

impl Neg for Real {
    type Output = Real;
    fn neg(self) -> Real {
        Real(Node::neg(self.0))
    }
}

impl Ring for Real {
    /// The exact value of a finite `f64`.
    ///
    /// # Panics
    /// If `x` is NaN or infinite: it has no exact value, and no value would be honest. The
    /// engine passes mesh coordinates (finite, see [`TriMesh::new`](crate::TriMesh::new)),
    /// validated parameters and constants only.
    fn from_f64(x: f64) -> Self {
        let exact = Rational::from_f64(x);
        Real::from_rational(
            exact.unwrap_or_else(|| {
                panic!("Real::from_f64({x}): a non-finite f64 has no exact value")
            }),
        )
    }
}

impl Field for Real {
    /// The nearest `f64` (from a 128-bit enclosure unless the filter is already a point); NaN
    /// for a value that divides by zero.
    fn to_f64(&self) -> f64 {
        if check_divisors(&self.0) == Err(Uncertainty::DivisionByZero) {
            return f64::NAN;
        }
        let f = self.filter();
        if f.lo == f.hi {
            return f.lo;
        }
        let (lo, hi) = refine::enclosure(&self.0, FIRST_PRECISION);
        let straddles = lo.cmp0() != Some(Ordering::Greater) && hi.cmp0() != Some(Ordering::Less);
        if straddles && normal_form::normal_form(&self.0).is_some_and(|nf| nf.is_zero()) {
            return 0.0;
        }
        let sum = Float::add(&lo, &hi, FIRST_PRECISION, Round::Nearest);
        let two = Float::from_rational(&Rational::from(2), FIRST_PRECISION, Round::Nearest);
        Float::div(&sum, &two, FIRST_PRECISION, Round::Nearest).to_f64(Round::Nearest)
    }

    fn sqrt(&self) -> Self {
        Real(Node::sqrt(self.0.clone()))
    }
}

impl CertifiedSign for Real {
    fn certified_sign(&self) -> Option<Sign> {
        Some(self.decide())
    }

    /// Counted as a decision when it answers; a value it cannot move away from zero (within
    /// [`CLEAR_PRECISION`] bits) is left undecided and uncounted.
    fn clear_sign(&self) -> Option<Sign> {
        let (sign, certificate) = self.clear_certified_sign()?;
        audit::record(certificate, || self.enclosure());
        Some(sign)
    }

    const ALWAYS_ANSWERS: bool = true;

    /// The sign where it is certified, counted as a decision; `None`, and no decision, where it
    /// is not. For questions about structure, where `no` only leaves the values to compare: a
    /// tie of two images built along different chains of faces is often proved here by a normal
    /// form or a separation bound, beyond what the first stages settle.
    fn proved_sign(&self) -> Option<Sign> {
        let (sign, certificate) = self
            .clear_certified_sign()
            .unwrap_or_else(|| self.certified_sign_with(false));
        if matches!(certificate, Certificate::Uncertified(_)) {
            return None;
        }
        audit::record(certificate, || self.enclosure());
        Some(sign)
    }
}

impl Scalar for Real {
    type Kept<T: Clone + std::fmt::Debug + Send + Sync> = Option<T>;

    fn keep<T: Clone + std::fmt::Debug + Send + Sync>(make: impl FnOnce() -> T) -> Self::Kept<T> {
        Some(make())
    }

    fn kept<T: Clone + std::fmt::Debug + Send + Sync>(kept: &Self::Kept<T>) -> Option<T> {
        kept.clone()
    }

    fn sign(&self) -> Sign {
        self.decide()
    }

    /// Exact rationals measure every length.
    fn measures_below_float_resolution() -> bool {
        true
    }

    /// Certified on enclosures: the upper end of an interval enclosure of `D` at the range's
    /// ends (from the operands' `Real::narrow_enclosure`s, which the engine's `f64` values
    /// of them already computed), times `FRONT_CERTIFIED_MARGIN`, at most `front`. Not a
    /// decision of the run's counts: `false` keeps the wedges, which is always right.
    fn front_passed(d: &SourceDistance<Self>, lo: &Self, hi: &Self, front: f64) -> bool {
        let enclose = |v: &Real| {
            let [lo, hi] = v.narrow_enclosure();
            Interval { lo, hi }
        };
        let d = SourceDistance {
            x: enclose(&d.x),
            y: enclose(&d.y),
            sigma: enclose(&d.sigma),
        };
        let farthest = d.at(&enclose(lo)).hi.max(d.at(&enclose(hi)).hi);
        (Interval::point(farthest) * Interval::point(FRONT_CERTIFIED_MARGIN)).hi <= front
    }

    fn compare(&self, other: &Self) -> Ordering {
        self.filtered_order(other)
            .unwrap_or_else(|| (self.clone() - other).decide().as_ordering())
    }

    fn compare_distance(&self, other: &Self) -> Ordering {
        self.compare(other)
    }

    fn has_extent(lo: &Self, hi: &Self, _scale: &Self) -> bool {
        hi.compare(lo) == Ordering::Greater
    }

    fn within(x: &Self, lo: &Self, hi: &Self, _scale: impl FnOnce() -> Self) -> bool {
        x.compare(lo) != Ordering::Less && x.compare(hi) != Ordering::Greater
    }

    /// `false` only where the foot is clearly outside (`CertifiedSign::clear_sign`): a foot
    /// at a range end is no decision.
    fn foot_within(x: &Self, lo: &Self, hi: &Self, _closed: bool) -> bool {
        let clearly = |end: &Self, side| {
            let order = x
                .filtered_order(end)
                .or_else(|| CertifiedSign::clear_sign(&(x.clone() - end)).map(Sign::as_ordering));
            order == Some(side)
        };
        !clearly(lo, Ordering::Less) && !clearly(hi, Ordering::Greater)
    }

    fn on_line(height: &Self, _x: &Self, _length: &Self) -> bool {
        height.sign() == Sign::Zero
    }

    fn same_distance_function(
        a: &SourceDistance<Self>,
        b: &SourceDistance<Self>,
        _scale: &Self,
    ) -> bool {
        roots::same_distance_function(a, b) == Some(true)
    }

    /// By certified signs (`CertifiedSign::proved_sign`).
    fn proved_same_distance_function(a: &SourceDistance<Self>, b: &SourceDistance<Self>) -> bool {
        roots::same_distance_function_by(a, b, <Real as CertifiedSign>::proved_sign) == Some(true)
    }

    /// By certified signs, as `proved_same_distance_function`.
    fn proved_same_point(p: [&Self; 2], q: [&Self; 2]) -> bool {
        (0..2).all(|i| CertifiedSign::proved_sign(&(p[i].clone() - q[i])) == Some(Sign::Zero))
    }

    /// By the filters, else by a certified sign of the difference (no decision without one).
    fn proved_order(a: &Self, b: &Self) -> Option<Ordering> {
        a.filtered_order(b)
            .or_else(|| CertifiedSign::proved_sign(&(a.clone() - b)).map(Sign::as_ordering))
    }

    /// Certified, as [`Scalar::same_distance_function`]: in a flat region the image is one
    /// expression however it crossed the region (see `mmp/flat_region.rs`).
    fn same_image(a: &SourceDistance<Self>, b: &SourceDistance<Self>, scale: &Self) -> bool {
        Self::same_distance_function(a, b, scale)
    }

    /// The crossings by exact signs (`roots::crossings`), with the ends' kept values where the
    /// engine has them (a tie there is then known by structure, not decided again); the lower
    /// wedge on the first stretch by the sign of `a - b` at an end where it is clear
    /// (`roots::first_stretch_sign`), else at the first stretch's middle; the owners then
    /// alternate at the crossings.
    fn bisector(
        a: &SourceDistance<Self>,
        b: &SourceDistance<Self>,
        lo: &Self,
        hi: &Self,
        known: &[Option<[Self; 2]>; 2],
    ) -> Bisector<Self> {
        Self::meeting(a, b, [lo, hi], known, &roots::InT)
    }

    /// As [`Scalar::bisector`], the zero gap taken from the structure
    /// (`roots::SeenStraight`).
    fn bisector_seen_straight(
        a: &SourceDistance<Self>,
        b: &SourceDistance<Self>,
        lo: &Self,
        hi: &Self,
        known: &[Option<[Self; 2]>; 2],
        opposite: bool,
    ) -> Bisector<Self> {
        Self::meeting(a, b, [lo, hi], known, &roots::SeenStraight { opposite })
    }

    fn orientation(p: [&Self; 2], q: [&Self; 2], r: [&Self; 2]) -> Sign {
        let cross = (q[0].clone() - p[0]) * &(r[1].clone() - p[1])
            - (q[1].clone() - p[1]) * &(r[0].clone() - p[0]);
        cross.decide()
    }

    /// The run's cap (clamped into `MIN_PRECISION_CAP..=MAX_PRECISION_CAP`) becomes this
    /// thread's, and the run starts a tower of radicals of its own.
    fn begin_run(precision_cap: Option<u32>) {
        if let Some(bits) = precision_cap {
            PRECISION_CAP.set(bits.clamp(MIN_PRECISION_CAP, MAX_PRECISION_CAP));
        }
        normal_form::new_tower();
    }

    fn locate(site: Site) {
        audit::locate(site);
    }

    fn take_counts() -> DecisionCounts {
        audit::take()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn int(i: i64) -> Real {
        Real::from_integer(i)
    }

    fn by_zero() -> (Sign, Certificate) {
        (
            Sign::Zero,
            Certificate::Uncertified(Uncertainty::DivisionByZero),
        )
    }

    /// `sqrt(2)^2 - 2`: zero, but not a rational leaf, and its filter straddles zero.
    fn hidden_zero() -> Real {
        let r2 = int(2).sqrt();
        r2.clone() * &r2 - int(2)
    }

    /// A pseudo-source at 1e16 in its edge's frame, a range 0.5 to 1 beyond it: the distances
    /// there are 0.5 to 1, but their `f64` values, `1e16 + 1` less `1e16` in `f64`, are 0.
    /// With the front at 0.5, the `f64` comparison the engine used gave the edge up although a
    /// wedge arriving later could win its far end; the enclosures do not.
    #[test]
    fn the_front_passes_a_wedge_by_its_enclosure_not_by_its_f64_values() {
        let far = Real::from_f64(1e16);
        let d = SourceDistance {
            x: far.clone(),
            y: int(0),
            sigma: int(0),
        };
        let (lo, hi) = (far.clone() + Real::from_f64(0.5), far + int(1));
        let rounded = SourceDistance {
            x: d.x.to_f64(),
            y: 0.0,
            sigma: 0.0,
        };
        assert!(f64::front_passed(&rounded, &lo.to_f64(), &hi.to_f64(), 0.5));
        assert!(!Real::front_passed(&d, &lo, &hi, 0.5));
        assert!(!Real::front_passed(&d, &lo, &hi, 1.0));
        assert!(Real::front_passed(&d, &lo, &hi, 2.5));
    }

    #[test]
    fn division_by_an_exact_zero_is_never_certified() {
        let undefined = int(1) / int(0);
        assert_eq!(undefined.certified_sign(), by_zero());
        // Without square roots the rational evaluation read 1 / 0 as 0: certified positive.
        assert_eq!((undefined.clone() + int(1)).certified_sign(), by_zero());
        // The square root clips the infinite enclosure to [0, inf]: the filter said positive.
        assert_eq!((undefined.sqrt() + int(1)).certified_sign(), by_zero());
        let hidden = int(1) / hidden_zero();
        assert_eq!(hidden.certified_sign(), by_zero());
        assert_eq!((hidden.sqrt() + int(1)).certified_sign(), by_zero());
    }

    #[test]
    fn rewriting_does_not_remove_a_division_by_zero() {
        let undefined = int(1) / int(0);
        // 0 * x = 0 and x - x = 0 hold only where x has a value.
        assert_eq!((int(0) * undefined.clone()).certified_sign(), by_zero());
        assert_eq!((undefined.clone() * int(0)).certified_sign(), by_zero());
        assert_eq!(
            (undefined.clone() - undefined.clone()).certified_sign(),
            by_zero()
        );
        let hidden = int(0) * (int(3) / hidden_zero());
        assert_eq!(hidden.certified_sign(), by_zero());
    }

    #[test]
    fn a_division_by_zero_is_counted_uncertified_and_located() {
        let _ = Real::take_counts();
        let undefined = (int(1) / int(0)).sqrt() + int(1);
        Real::locate(Site {
            edge: Some(7),
            what: "a test",
        });
        // The filter alone would have said undefined > 0.
        assert_eq!(undefined.compare(&int(0)), Ordering::Equal);
        assert_eq!(undefined.sign(), Sign::Zero);
        let counts = Real::take_counts();
        assert_eq!((counts.decisions, counts.uncertified), (2, 2));
        let site = &counts.uncertified_sites[0];
        assert_eq!(site.cause, Uncertainty::DivisionByZero);
        assert_eq!(site.site.edge, Some(7));
        assert!(undefined.to_f64().is_nan());
        assert!((int(1) / int(0)).to_f64().is_nan());
    }

    /// `sqrt(10^70 + 1) - 10^35`, about 5e-36: non-zero, but its `f64` filter contains zero.
    fn tiny() -> Real {
        let e35 = Real::from_rational(Rational::from(Integer::from(10).pow(35)));
        (e35.clone() * &e35 + int(1)).sqrt() - &e35
    }

    #[test]
    fn a_divisor_the_filter_cannot_separate_from_zero_is_certified_first() {
        let tiny = tiny();
        assert_eq!(tiny.filter().sign(), None);
        let huge = int(1) / tiny;
        assert_eq!(
            huge.certified_sign(),
            (Sign::Positive, Certificate::Refinement)
        );
        assert!(huge.to_f64() > 1.9e35 && huge.to_f64() < 2.1e35);
    }

    #[test]
    fn rewriting_keeps_its_zeros_once_the_divisors_are_non_zero() {
        let huge = int(1) / tiny();
        let zero = (Sign::Zero, Certificate::CertifiedZero(ZeroProof::Structure));
        assert_eq!((huge.clone() - huge.clone()).certified_sign(), zero);
        assert_eq!((int(0) * huge.clone()).certified_sign(), zero);
        assert_eq!(huge.compare(&huge), Ordering::Equal);
        assert_eq!(Real::take_counts().uncertified, 0);
    }

    /// `sqrt(2) * sqrt(3) + 1/3`, built anew on each call.
    fn copy_of_an_expression() -> Real {
        int(2).sqrt() * &int(3).sqrt() + &(int(1) / int(3))
    }

    #[test]
    fn two_copies_of_one_expression_differ_by_a_structural_zero() {
        let (a, b) = (copy_of_an_expression(), copy_of_an_expression());
        assert!(!Arc::ptr_eq(&a.0, &b.0));
        assert_eq!(
            (a.clone() - b.clone()).certified_sign(),
            (Sign::Zero, Certificate::CertifiedZero(ZeroProof::Structure))
        );
        // The same expression with its operands in the other order is a copy.
        let swapped = int(1) / int(3) + &(int(3).sqrt() * &int(2).sqrt());
        assert_eq!(
            (a.clone() - swapped).certified_sign(),
            (Sign::Zero, Certificate::CertifiedZero(ZeroProof::Structure))
        );
        // A different expression of the same value is no copy: another proof settles it.
        let other = int(6).sqrt() + &(int(1) / int(3));
        let proof = (a - other).certified_sign();
        assert!(
            matches!(proof, (Sign::Zero, Certificate::CertifiedZero(p)) if p != ZeroProof::Structure),
            "{proof:?}"
        );
        // Nor is an expression that differs in one leaf, however close.
        let near = int(2).sqrt() * &int(3).sqrt() + &(Real::from_f64(1.0 / 3.0));
        assert_eq!((b - near).certified_sign().1, Certificate::Refinement);
    }

    /// An identity off by 2^-9000, below what refinement within the cap can see, is not called
    /// zero.
    fn assert_not_zero_when_off_by_2_pow_minus_9000(identity: Real) {
        let tiny = Real::from_rational(
            Rational::new(Integer::from(1), Integer::from(2).pow(9000)).unwrap(),
        );
        let (_, certificate) = (identity + &tiny).certified_sign();
        assert!(
            matches!(certificate, Certificate::Uncertified(_)),
            "{certificate:?}"
        );
    }

    fn normal_form_zero() -> (Sign, Certificate) {
        (
            Sign::Zero,
            Certificate::CertifiedZero(ZeroProof::NormalForm),
        )
    }

    /// A big integer with no square factor below 256 (a prime above it).
    const BIG_PRIME: i64 = 1_000_003;

    #[test]
    fn radicals_equal_up_to_a_large_square_share_a_symbol() {
        // Three points on a line in space: |ac| = |ab| + |bc|, radicands 3 p^2, 3 q^2 and
        // 3 (p + q)^2 with no small square factor in common but 3.
        let (p, q) = (BIG_PRIME, 999_983);
        let length = |k: i64| int(3 * k * k).sqrt();
        let straight = length(p + q) - length(p) - length(q);
        assert_eq!(straight.certified_sign(), normal_form_zero());
        // Off the line by one part in 10^24, non-zero: refinement says so.
        let off = Real::from_rational(
            Rational::new(Integer::from(1), Integer::from(10).pow(24)).unwrap(),
        );
        let bent = (int(3 * (p + q) * (p + q)) + &off).sqrt() - length(p) - length(q);
        assert_eq!(
            bent.certified_sign(),
            (Sign::Positive, Certificate::Refinement)
        );
    }

    #[test]
    fn a_nested_radical_that_denests_is_seen_as_its_denested_form() {
        // sqrt(3 + 2 sqrt 2) = 1 + sqrt 2, and sqrt(p^2 (5 - 2 sqrt 6)) = p (sqrt 3 - sqrt 2).
        let r2 = int(2).sqrt();
        let root = (int(3) + &(int(2) * &r2)).sqrt();
        assert_eq!((root - &int(1) - &r2).certified_sign(), normal_form_zero());
        let p = int(BIG_PRIME);
        let p2 = p.clone() * &p;
        let nested = (p2.clone() * &int(5) - &(p2 * &int(2) * &int(6).sqrt())).sqrt();
        let denested = p * &(int(3).sqrt() - &int(2).sqrt());
        assert_eq!((nested - &denested).certified_sign(), normal_form_zero());
        // Not a square in Q(sqrt 2): no false denesting.
        let other = (int(3) + &int(2).sqrt()).sqrt() - &int(1) - &int(2).sqrt();
        assert_ne!(other.certified_sign().0, Sign::Zero);
    }

    #[test]
    fn an_identity_over_an_expression_too_large_to_expand_is_proved_over_atoms() {
        // X = (1 + sqrt 3)(1 + sqrt 5)...(1 + sqrt 31): 1,024 terms, past the normal form's
        // size, and 11 square roots put the separation bound past the cap. The identity
        // (X + sqrt 2)^2 - X^2 - 2 sqrt(2) X - 2 = 0 holds whatever X is.
        let deep = [3, 5, 7, 11, 13, 17, 19, 23, 29, 31]
            .into_iter()
            .fold(int(1), |x, p| x * &(int(1) + &int(p).sqrt()));
        let r2 = int(2).sqrt();
        let sum = deep.clone() + &r2;
        let identity =
            sum.clone() * &sum - &(deep.clone() * &deep) - &(int(2) * &r2 * &deep) - &int(2);
        assert_eq!(identity.certified_sign(), normal_form_zero());
        assert_not_zero_when_off_by_2_pow_minus_9000(identity);
    }

    #[test]
    fn a_length_along_a_chain_of_edges_is_the_root_of_its_expanded_square() {
        // The length of a straight line across k edges of radical lengths, sqrt(T^2) with
        // T = c1 sqrt(r1) + ... + ck sqrt(rk) expanded, is T: the square root of a square of
        // the tower, not a new radical. Radicands of about 100 bits, coprime, as edge lengths
        // of a float mesh are; coefficients dyadic.
        let radicand = |a: i64, b: i64| {
            Real::from_rational(Rational::from(Integer::from(a) * Integer::from(b)))
        };
        let dyadic =
            |c: i64, k: u32| int(c) / Real::from_rational(Rational::from(Integer::from(2).pow(k)));
        let terms = [
            (radicand(4_311_131_297, 4_311_131_299), dyadic(1, 54)),
            (radicand(4_311_131_291, 4_311_131_333), dyadic(-3, 55)),
            (radicand(34_489_050_391, 34_489_050_407), dyadic(1, 57)),
            (radicand(34_489_050_403, 34_489_050_389), dyadic(5, 57)),
            (radicand(4_311_131_311, 4_311_131_323), dyadic(1, 54)),
            (radicand(1_326_500_107, 1_326_500_113), dyadic(13, 56)),
        ];
        for k in 1..=terms.len() {
            let t = terms[..k]
                .iter()
                .fold(int(0), |t, (r, c)| t + &(r.sqrt() * c));
            let square = t.clone() * &t;
            let length = square.sqrt();
            let expected = if t.to_f64() > 0.0 {
                t.clone()
            } else {
                -t.clone()
            };
            assert_eq!(
                (length.clone() - &expected).certified_sign(),
                normal_form_zero(),
                "{k} terms"
            );
            // Not the root of a square: off by one part in 10^30.
            let off = Real::from_rational(
                Rational::new(Integer::from(1), Integer::from(10).pow(30)).unwrap(),
            );
            let near = (square + &off).sqrt() - &expected;
            assert_eq!(
                near.certified_sign(),
                (Sign::Positive, Certificate::Refinement)
            );
        }
        // sqrt 2 + sqrt 3 + sqrt 5: a square in the tower whose search meets sqrt 24 = 2 sqrt 2
        // sqrt 3, of a square class of its own.
        let t = int(2).sqrt() + &int(3).sqrt() + &int(5).sqrt();
        let length = (t.clone() * &t).sqrt();
        assert_eq!((length - &t).certified_sign(), normal_form_zero());
    }

    #[test]
    fn a_sum_of_nested_radicals_is_proved_zero_by_eliminating_them() {
        // sqrt(A) + sqrt(B) = sqrt(A + B + 2 sqrt(A B)) with A and B themselves sums of
        // radicals of large integers: four radicals of radicals, related only through their
        // radicands, so that the normal form is not zero; nine square roots put the separation
        // bound past the cap.
        let big = |a: i64, b: i64| {
            Real::from_rational(Rational::from(Integer::from(a) * Integer::from(b)))
        };
        let a = big(4_311_131_297, 4_311_131_299).sqrt()
            + &big(34_489_050_391, 34_489_050_407).sqrt()
            + &big(1_326_500_107, 1_326_500_113).sqrt()
            + &int(7);
        let b = big(4_311_131_291, 4_311_131_333).sqrt() * &int(3)
            + &big(4_311_131_311, 4_311_131_323).sqrt()
            + &int(11);
        let joint = (a.clone() + &b + &(int(2) * &(a.clone() * &b).sqrt())).sqrt();
        let identity = a.sqrt() + &b.sqrt() - &joint;
        assert_eq!(identity.certified_sign(), normal_form_zero());
        assert_not_zero_when_off_by_2_pow_minus_9000(identity);
    }

    #[test]
    #[should_panic(expected = "non-finite f64 has no exact value")]
    fn from_f64_of_nan_panics() {
        let _ = Real::from_f64(f64::NAN);
    }

    #[test]
    #[should_panic(expected = "non-finite f64 has no exact value")]
    fn from_f64_of_infinity_panics() {
        let _ = Real::from_f64(f64::INFINITY);
    }
}
