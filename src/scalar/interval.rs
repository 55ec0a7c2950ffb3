//! Intervals of `f64` with outward rounding: the floating-point filter of the certifying
//! backends. Every operation encloses the exact result of the exact operands; an exact
//! operation (e.g. `0 - 0`) stays a point, so exact zeros pass the filter.
//!
//! Rust has no rounding modes, so each bound is rounded to nearest and then moved outwards
//! only when the error-free transformation of the operation (TwoSum, or a fused multiply-add
//! for `*`, `/` and `sqrt`) shows that rounding went the wrong way.

use super::{Field, Ring, Sign};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A closed interval `[lo, hi]` of reals, with `f64` bounds (possibly infinite).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// Lower bound.
    pub lo: f64,
    /// Upper bound.
    pub hi: f64,
}

/// The rounding error of `a + b`: `a + b = s + e` exactly (Knuth's TwoSum).
#[inline(always)]
fn sum_error(a: f64, b: f64, s: f64) -> f64 {
    let bb = s - a;
    (a - (s - bb)) + (b - bb)
}

#[inline(always)]
fn add_down(a: f64, b: f64) -> f64 {
    let s = a + b;
    if s.is_finite() && sum_error(a, b, s) < 0.0 {
        s.next_down()
    } else {
        s
    }
}

#[inline(always)]
fn add_up(a: f64, b: f64) -> f64 {
    let s = a + b;
    if s.is_finite() && sum_error(a, b, s) > 0.0 {
        s.next_up()
    } else {
        s
    }
}

/// `a * b` rounded down and up: `a * b = p + e` exactly with `e = fma(a, b, -p)`.
#[inline(always)]
fn mul_bounds(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    if !p.is_finite() {
        return (p, p);
    }
    let e = a.mul_add(b, -p);
    // Near underflow the fma residual is not exact: widen unconditionally there.
    let tiny = (p.abs() < 1e-290 && p != 0.0) || (p == 0.0 && a != 0.0 && b != 0.0);
    if tiny {
        (p.next_down(), p.next_up())
    } else if e < 0.0 {
        (p.next_down(), p)
    } else if e > 0.0 {
        (p, p.next_up())
    } else {
        (p, p)
    }
}

/// `a / b` (with `b != 0`) rounded down and up: `a = q b + r` exactly with `r = fma(-q, b, a)`.
#[inline(always)]
fn div_bounds(a: f64, b: f64) -> (f64, f64) {
    let q = a / b;
    if !q.is_finite() || q.abs() < 1e-290 {
        return (q.next_down(), q.next_up());
    }
    let r = (-q).mul_add(b, a);
    let low = (r < 0.0) != (b < 0.0) && r != 0.0;
    if r == 0.0 {
        (q, q)
    } else if low {
        (q.next_down(), q)
    } else {
        (q, q.next_up())
    }
}

/// `sqrt(x)` (with `x >= 0`) rounded down and up: `x = s^2 + r` exactly with `r = fma(-s, s, x)`.
#[inline(always)]
fn sqrt_bounds(x: f64) -> (f64, f64) {
    let s = x.sqrt();
    if !s.is_finite() || s < 1e-150 {
        return ((s.next_down()).max(0.0), s.next_up());
    }
    let r = (-s).mul_add(s, x);
    if r < 0.0 {
        (s.next_down(), s)
    } else if r > 0.0 {
        (s, s.next_up())
    } else {
        (s, s)
    }
}

impl Interval {
    /// Every real.
    pub const ENTIRE: Interval = Interval {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// The point interval of an `f64`.
    #[inline(always)]
    pub fn point(x: f64) -> Interval {
        Interval { lo: x, hi: x }
    }

    /// The sign of every point of the interval, if they all share one.
    #[inline(always)]
    pub fn sign(&self) -> Option<Sign> {
        if self.lo > 0.0 {
            Some(Sign::Positive)
        } else if self.hi < 0.0 {
            Some(Sign::Negative)
        } else if self.lo == 0.0 && self.hi == 0.0 {
            Some(Sign::Zero)
        } else {
            None
        }
    }

    /// The common part of two enclosures of one value: an enclosure of it too.
    #[inline(always)]
    pub fn meet(self, o: Interval) -> Interval {
        Interval {
            lo: self.lo.max(o.lo),
            hi: self.hi.min(o.hi),
        }
    }

    /// Whether the interval is `[-inf, inf]` or has lost its bounds to a NaN.
    fn checked(self) -> Interval {
        if self.lo.is_nan() || self.hi.is_nan() {
            Interval::ENTIRE
        } else {
            self
        }
    }
}

impl Add for Interval {
    type Output = Interval;
    #[inline(always)]
    fn add(self, o: Interval) -> Interval {
        Interval {
            lo: add_down(self.lo, o.lo),
            hi: add_up(self.hi, o.hi),
        }
        .checked()
    }
}

impl Sub for Interval {
    type Output = Interval;
    #[inline(always)]
    fn sub(self, o: Interval) -> Interval {
        self + (-o)
    }
}

impl Neg for Interval {
    type Output = Interval;
    #[inline(always)]
    fn neg(self) -> Interval {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl Mul for Interval {
    type Output = Interval;
    #[inline(always)]
    fn mul(self, o: Interval) -> Interval {
        let products = [
            mul_bounds(self.lo, o.lo),
            mul_bounds(self.lo, o.hi),
            mul_bounds(self.hi, o.lo),
            mul_bounds(self.hi, o.hi),
        ];
        let lo = products.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
        let hi = products
            .iter()
            .map(|p| p.1)
            .fold(f64::NEG_INFINITY, f64::max);
        if products.iter().any(|p| p.0.is_nan()) {
            return Interval::ENTIRE;
        }
        Interval { lo, hi }
    }
}

impl Div for Interval {
    type Output = Interval;
    #[inline(always)]
    fn div(self, o: Interval) -> Interval {
        if o.lo <= 0.0 && o.hi >= 0.0 {
            return Interval::ENTIRE;
        }
        let quotients = [
            div_bounds(self.lo, o.lo),
            div_bounds(self.lo, o.hi),
            div_bounds(self.hi, o.lo),
            div_bounds(self.hi, o.hi),
        ];
        if quotients.iter().any(|q| q.0.is_nan()) {
            return Interval::ENTIRE;
        }
        Interval {
            lo: quotients.iter().map(|q| q.0).fold(f64::INFINITY, f64::min),
            hi: quotients
                .iter()
                .map(|q| q.1)
                .fold(f64::NEG_INFINITY, f64::max),
        }
    }
}

ops_by_reference_for_copy!(Interval);

impl Ring for Interval {
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        Interval::point(x)
    }
}

impl Field for Interval {
    fn to_f64(&self) -> f64 {
        if self.lo.is_finite() && self.hi.is_finite() {
            self.lo + 0.5 * (self.hi - self.lo)
        } else if self.lo.is_finite() {
            self.lo
        } else {
            self.hi
        }
    }

    #[inline(always)]
    fn sqrt(&self) -> Self {
        if self.hi <= 0.0 {
            return Interval::point(0.0);
        }
        Interval {
            lo: sqrt_bounds(self.lo.max(0.0)).0,
            hi: sqrt_bounds(self.hi).1,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn contains(i: Interval, x: f64) -> bool {
        i.lo <= x && x <= i.hi
    }

    #[test]
    fn exact_operations_stay_points() {
        let z = Interval::point(0.5) - Interval::point(0.5);
        assert_eq!(z.sign(), Some(Sign::Zero));
        let p = Interval::point(3.0) * Interval::point(0.25);
        assert_eq!(p, Interval::point(0.75));
        assert_eq!(Interval::point(9.0).sqrt(), Interval::point(3.0));
    }

    #[test]
    fn rounded_operations_enclose_the_exact_result() {
        // 0.1 + 0.2 rounds up to 0.30000000000000004; the exact sum of the two binary
        // numbers lies below it, and the interval must reach down.
        let s = Interval::point(0.1) + Interval::point(0.2);
        assert!(s.lo < s.hi);
        let third = Interval::point(1.0) / Interval::point(3.0);
        assert!(third.lo < third.hi && contains(third, 1.0 / 3.0));
        let r2 = Interval::point(2.0).sqrt();
        assert!((r2 * r2).lo <= 2.0 && (r2 * r2).hi >= 2.0);
        assert_eq!(
            (Interval::point(1.0) / Interval { lo: -1.0, hi: 1.0 }).sign(),
            None
        );
    }

    #[test]
    fn division_by_an_interval_containing_zero_is_entire() {
        let point = Interval::point;
        for divisor in [
            point(0.0),
            point(-0.0),
            Interval { lo: -0.0, hi: 0.0 },
            Interval { lo: 0.0, hi: 1.0 },
            Interval { lo: -1.0, hi: 0.0 },
            Interval::ENTIRE,
        ] {
            for dividend in [point(0.0), point(1.0), Interval { lo: -2.0, hi: 3.0 }] {
                assert_eq!(
                    dividend / divisor,
                    Interval::ENTIRE,
                    "{dividend:?} / {divisor:?}"
                );
            }
        }
        // What an infinite enclosure turns into downstream: never a sign.
        let undefined = point(1.0) / point(0.0);
        assert_eq!((undefined * point(0.0)).sign(), None);
        assert_eq!((undefined - undefined).sign(), None);
    }
}
