//! Property 1 [LZT §3] decided by exact signs: the solutions of eq. (1) on a shared range, for
//! number types whose signs are exact when they are given ([`CertifiedSign`]).
//!
//! Eq. (2) comes from eq. (1), `sqrt(q1) = sqrt(q2) + beta`, by squaring twice, which may add
//! roots. Writing `L(t) = 2 alpha t + gamma`, the first squaring gives `L(t) = 2 beta sqrt(q2)`,
//! the second eq. (2). A root of eq. (2) therefore solves eq. (1) exactly when `L(t)` has the
//! sign of `beta` (or is zero) and `q2(t) >= beta^2` when `beta < 0`.
//!
//! Every decision is a sign of a polynomial in the inputs, never of an expression with the
//! root's square root: where a root `r` of `P = A u^2 + B u + C` is compared with a point `p`,
//! the signs of `A P(p)` and of `2 A p + B` tell whether `p` lies between the roots, left of
//! both or right of both. So an exact rational type suffices, and the adaptive backend's exact
//! stage needs no square roots.

use super::{BisectorRoots, Eq2Coefficients, Field, Ring, Sign, SourceDistance};

/// A number type that may know the exact sign of a value: `None` means "cannot tell" (a filter
/// too coarse for it); an exact type always answers.
pub(crate) trait CertifiedSign: Ring {
    fn certified_sign(&self) -> Option<Sign>;
}

/// Which solutions of eq. (1) lie strictly inside a shared range.
pub(crate) enum Crossings<T> {
    None,
    Infinite,
    /// One solution, with its position from the range's start, exact in `T`.
    At(T),
    /// Eq. (2) has two distinct roots; which of them (smaller, larger) are solutions, with the
    /// sign of `A`, which orders them.
    Quadratic {
        eq2: Eq2Coefficients<T>,
        sign_a: Sign,
        smaller: bool,
        larger: bool,
    },
}

impl<T> Crossings<T> {
    /// The same crossings with every value mapped by `f` (e.g. exact values rounded to `f64`).
    pub(crate) fn map<U>(self, f: impl Fn(&T) -> U) -> Crossings<U> {
        match self {
            Crossings::None => Crossings::None,
            Crossings::Infinite => Crossings::Infinite,
            Crossings::At(u) => Crossings::At(f(&u)),
            Crossings::Quadratic {
                eq2,
                sign_a,
                smaller,
                larger,
            } => Crossings::Quadratic {
                eq2: Eq2Coefficients {
                    a: f(&eq2.a),
                    b: f(&eq2.b),
                    c: f(&eq2.c),
                },
                sign_a,
                smaller,
                larger,
            },
        }
    }
}

/// Whether two wedges have the same distance function: `A = B = C = 0` in eq. (2).
pub(crate) fn same_distance_function<T: CertifiedSign>(
    a: &SourceDistance<T>,
    b: &SourceDistance<T>,
) -> Option<bool> {
    let eq2 = Eq2Coefficients::new(a, b, &a.x);
    for c in [&eq2.a, &eq2.b, &eq2.c] {
        if c.certified_sign()? != Sign::Zero {
            return Some(false);
        }
    }
    Some(true)
}

fn negate(s: Sign) -> Sign {
    match s {
        Sign::Negative => Sign::Positive,
        Sign::Zero => Sign::Zero,
        Sign::Positive => Sign::Negative,
    }
}

/// The quadratic `P` of eq. (2) with two distinct real roots, and `A`'s sign.
struct TwoRoots<'a, T> {
    eq2: &'a Eq2Coefficients<T>,
    sa: Sign,
}

impl<T: CertifiedSign> TwoRoots<'_, T> {
    /// The sign of `root - p` for the smaller (`larger = false`) or larger root.
    fn root_minus(&self, larger: bool, p: &T) -> Option<Sign> {
        let e = self.eq2;
        let at_p = e.a.clone() * p * p + &(e.b.clone() * p) + &e.c;
        let between = at_p.certified_sign()?.times(self.sa);
        let two = T::from_f64(2.0);
        // The sign of p minus the vertex -B / (2A).
        let side = (two * &e.a * p + &e.b).certified_sign()?.times(self.sa);
        Some(match (between, side) {
            (Sign::Negative, _) => {
                if larger {
                    Sign::Positive
                } else {
                    Sign::Negative
                }
            }
            (Sign::Positive, s) => negate(s),
            // p is a root: the smaller one if it is left of the vertex.
            (Sign::Zero, s) => match (s == Sign::Negative, larger) {
                (true, false) | (false, true) => Sign::Zero,
                (true, true) => Sign::Positive,
                (false, false) => Sign::Negative,
            },
        })
    }

    /// The sign of `m r + c` at a root `r`.
    fn linear_at(&self, larger: bool, m: &T, c: &T) -> Option<Sign> {
        match m.certified_sign()? {
            Sign::Zero => c.certified_sign(),
            sm => {
                let p = -(c.clone() / m);
                Some(self.root_minus(larger, &p)?.times(sm))
            }
        }
    }
}

/// The solutions of eq. (1) strictly inside `(lo, hi)`, every decision an exact sign of a
/// polynomial in the inputs; `None` when `T` cannot tell one of them.
pub(crate) fn crossings<T: CertifiedSign>(
    a: &SourceDistance<T>,
    b: &SourceDistance<T>,
    lo: &T,
    hi: &T,
) -> Option<Crossings<T>> {
    let eq2 = Eq2Coefficients::new(a, b, lo);
    let (sa, sb) = (eq2.a.certified_sign()?, eq2.b.certified_sign()?);
    // C is often nearly zero (the range starts where the wedges are nearly equal), so its sign
    // is asked only where it decides.
    if (sa, sb) == (Sign::Zero, Sign::Zero) && eq2.c.certified_sign()? == Sign::Zero {
        return Some(Crossings::Infinite);
    }
    let (x1, x2) = (a.x.clone() - lo, b.x.clone() - lo);
    let alpha = x2.clone() - &x1;
    let beta = b.sigma.clone() - &a.sigma;
    let sbeta = beta.certified_sign()?;
    let beta2 = beta.clone() * &beta;
    let n1 = x1.clone() * &x1 + a.y.clone() * &a.y;
    let n2 = x2.clone() * &x2 + b.y.clone() * &b.y;
    let gamma = n1 - &n2 - &beta2;
    let two = T::from_f64(2.0);
    let width = hi.clone() - lo;
    // q2(u) - beta^2 = u^2 - 2 x2 u + (n2 - beta^2).
    let q2_excess = n2.clone() - &beta2;
    // A single root, known exactly: inside the range, and a solution of eq. (1)?
    let single = |u: T| -> Option<Crossings<T>> {
        let inside = u.certified_sign()? == Sign::Positive
            && (width.clone() - &u).certified_sign()? == Sign::Positive;
        if !inside {
            return Some(Crossings::None);
        }
        if sbeta != Sign::Zero {
            let sl = (two.clone() * &alpha * &u + &gamma).certified_sign()?;
            if sl != Sign::Zero && sl != sbeta {
                return Some(Crossings::None);
            }
            if sbeta == Sign::Negative {
                let q = u.clone() * &u - &(two.clone() * &x2 * &u) + &q2_excess;
                if q.certified_sign()? == Sign::Negative {
                    return Some(Crossings::None);
                }
            }
        }
        Some(Crossings::At(u))
    };
    if sbeta == Sign::Zero {
        // Equal sigmas: eq. (1) is linear, L(t) = 0 (eq. (2) is its square, a double root).
        return match alpha.certified_sign()? {
            Sign::Zero => Some(Crossings::None),
            _ => single(-(gamma.clone() / &(two.clone() * &alpha))),
        };
    }
    if sa == Sign::Zero {
        return match sb {
            Sign::Zero => Some(Crossings::None),
            _ => single(-(eq2.c.clone() / &eq2.b)),
        };
    }
    let disc = eq2.b.clone() * &eq2.b - two.clone() * &two * &eq2.a * &eq2.c;
    match disc.certified_sign()? {
        Sign::Negative => return Some(Crossings::None),
        Sign::Zero => return single(-(eq2.b.clone() / &(two.clone() * &eq2.a))),
        Sign::Positive => {}
    }
    let roots = TwoRoots { eq2: &eq2, sa };
    let zero = T::from_f64(0.0);
    // At a root, L(u) = 2 alpha u + gamma; q2(u) - beta^2 reduced by P / A is linear too.
    let m_q = -(two.clone() * &x2) - &(eq2.b.clone() / &eq2.a);
    let c_q = q2_excess.clone() - &(eq2.c.clone() / &eq2.a);
    let two_alpha = two.clone() * &alpha;
    let solves = |larger: bool| -> Option<bool> {
        if roots.root_minus(larger, &zero)? != Sign::Positive
            || roots.root_minus(larger, &width)? != Sign::Negative
        {
            return Some(false);
        }
        let sl = roots.linear_at(larger, &two_alpha, &gamma)?;
        if sl != Sign::Zero && sl != sbeta {
            return Some(false);
        }
        if sbeta == Sign::Negative && roots.linear_at(larger, &m_q, &c_q)? == Sign::Negative {
            return Some(false);
        }
        Some(true)
    };
    let (smaller, larger) = (solves(false)?, solves(true)?);
    Some(Crossings::Quadratic {
        eq2,
        sign_a: sa,
        smaller,
        larger,
    })
}

/// The roots of eq. (2) in increasing order, for two distinct real roots, in a [`Field`]:
/// `(-B -+ sqrt(D)) / 2A`, ordered by the sign of `A`. The exact backend wants this shape (one
/// square root over the coefficients, which its normal form handles); `f64` wants the
/// cancellation-free one of [`stable_roots`].
pub(crate) fn quadratic_roots<S: Field>(eq2: &Eq2Coefficients<S>, sign_a: Sign) -> [S; 2] {
    let two = S::from_f64(2.0);
    let disc = eq2.b.clone() * &eq2.b - two.clone() * &two * &eq2.a * &eq2.c;
    let root = disc.sqrt();
    let twice_a = two * &eq2.a;
    let minus = (-eq2.b.clone() - &root) / &twice_a;
    let plus = (-eq2.b.clone() + &root) / &twice_a;
    if sign_a == Sign::Positive {
        [minus, plus]
    } else {
        [plus, minus]
    }
}

/// The roots of eq. (2) in increasing order in `f64`, without cancellation:
/// `q = -(B + sign(B) sqrt(D)) / 2`, and the roots `q / A` and `C / q`.
pub(crate) fn stable_roots(eq2: &Eq2Coefficients<f64>) -> [f64; 2] {
    let (a, b, c) = (eq2.a, eq2.b, eq2.c);
    let q = -0.5 * (b + b.signum() * (b * b - 4.0 * a * c).max(0.0).sqrt());
    let (r, s) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
    [r.min(s), r.max(s)]
}

/// Which of the two roots are solutions, as [`BisectorRoots`] back on the edge.
fn chosen<S: Field>([r, s]: [S; 2], smaller: bool, larger: bool, lo: &S) -> BisectorRoots<S> {
    match (smaller, larger) {
        (true, true) => BisectorRoots::Two(r + lo, s + lo),
        (true, false) => BisectorRoots::One(r + lo),
        (false, true) => BisectorRoots::One(s + lo),
        (false, false) => BisectorRoots::None,
    }
}

/// [`into_roots`] for `f64`, with the roots of [`stable_roots`].
pub(crate) fn into_f64_roots(c: Crossings<f64>, lo: f64) -> BisectorRoots<f64> {
    match c {
        Crossings::Quadratic {
            eq2,
            smaller,
            larger,
            ..
        } => chosen(stable_roots(&eq2), smaller, larger, &lo),
        other => into_roots(other, &lo),
    }
}

/// The crossings as [`BisectorRoots`] in a [`Field`], positions back on the edge.
pub(crate) fn into_roots<S: Field>(c: Crossings<S>, lo: &S) -> BisectorRoots<S> {
    match c {
        Crossings::None => BisectorRoots::None,
        Crossings::Infinite => BisectorRoots::Infinite,
        Crossings::At(u) => BisectorRoots::One(u + lo),
        Crossings::Quadratic {
            eq2,
            sign_a,
            smaller,
            larger,
        } => chosen(quadratic_roots(&eq2, sign_a), smaller, larger, lo),
    }
}
