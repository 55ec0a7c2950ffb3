//! Property 1 [LZT §3] decided by exact signs: the solutions of eq. (1) on a shared range, for
//! number types whose signs are exact when they are given ([`CertifiedSign`]).
//!
//! Eq. (2) comes from eq. (1), `sqrt(q1) = sqrt(q2) + beta`, by squaring twice, which may add
//! roots. Writing `L(t) = 2 alpha t + gamma`, the first squaring gives `L(t) = 2 beta sqrt(q2)`,
//! the second eq. (2). A root of eq. (2) therefore solves eq. (1) exactly when `L(t)` has the
//! sign of `beta` (or is zero) and `sqrt(q2) + beta >= 0`. These are signs of values that are
//! not zero except in degenerate positions, so deciding them is cheap, unlike testing
//! `D1(t) - D2(t) = 0` at a root, which would need a zero certificate every time.

use super::{BisectorRoots, Eq2Coefficients, Field, Sign, SourceDistance};

/// A number type that may know the exact sign of a value: `None` means "cannot tell" (an
/// interval straddling zero); an exact type always answers.
pub(crate) trait CertifiedSign: Field {
    fn certified_sign(&self) -> Option<Sign>;
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

/// The solutions of eq. (1) strictly inside `(lo, hi)`, every decision taken by exact signs.
pub(crate) fn bisector_roots<T: CertifiedSign>(
    a: &SourceDistance<T>,
    b: &SourceDistance<T>,
    lo: &T,
    hi: &T,
) -> Option<BisectorRoots<T>> {
    let eq2 = Eq2Coefficients::new(a, b, lo);
    let (sa, sb) = (eq2.a.certified_sign()?, eq2.b.certified_sign()?);
    // C is often nearly zero (the range starts where the wedges are nearly equal), so its sign
    // is asked only when A = B = 0 makes it decide the case.
    if (sa, sb) == (Sign::Zero, Sign::Zero) && eq2.c.certified_sign()? == Sign::Zero {
        return Some(BisectorRoots::Infinite);
    }
    let (x1, x2) = (a.x.clone() - lo, b.x.clone() - lo);
    let alpha = x2.clone() - &x1;
    let beta = b.sigma.clone() - &a.sigma;
    let sbeta = beta.certified_sign()?;
    let n1 = x1.clone() * &x1 + a.y.clone() * &a.y;
    let n2 = x2.clone() * &x2 + b.y.clone() * &b.y;
    let gamma = n1 - &n2 - &(beta.clone() * &beta);
    let two = T::from_f64(2.0);
    // Candidates, in increasing order, in coordinates from `lo`.
    let candidates: Vec<T> = if sbeta == Sign::Zero {
        // Equal sigmas: eq. (1) is linear, `L(t) = 0` (eq. (2) is its square, a double root).
        match alpha.certified_sign()? {
            Sign::Zero => Vec::new(),
            _ => vec![-gamma.clone() / &(two.clone() * &alpha)],
        }
    } else if sa == Sign::Zero {
        match sb {
            Sign::Zero => Vec::new(),
            _ => vec![-eq2.c.clone() / &eq2.b],
        }
    } else {
        let disc = eq2.b.clone() * &eq2.b - two.clone() * &two * &eq2.a * &eq2.c;
        let twice_a = two.clone() * &eq2.a;
        match disc.certified_sign()? {
            Sign::Negative => Vec::new(),
            Sign::Zero => vec![-eq2.b.clone() / &twice_a],
            Sign::Positive => {
                let root = disc.sqrt();
                let minus = (-eq2.b.clone() - &root) / &twice_a;
                let plus = (-eq2.b.clone() + &root) / &twice_a;
                if sa == Sign::Positive {
                    vec![minus, plus]
                } else {
                    vec![plus, minus]
                }
            }
        }
    };
    let width = hi.clone() - lo;
    let mut roots = Vec::with_capacity(2);
    for u in candidates {
        if u.certified_sign()? != Sign::Positive
            || (width.clone() - &u).certified_sign()? != Sign::Positive
        {
            continue;
        }
        if sbeta != Sign::Zero {
            let l = two.clone() * &alpha * &u + &gamma;
            let sl = l.certified_sign()?;
            if sl != Sign::Zero && sl != sbeta {
                continue;
            }
            if sbeta == Sign::Negative {
                let dx = u.clone() - &x2;
                let q2 = dx.clone() * &dx + b.y.clone() * &b.y;
                if (q2 - &(beta.clone() * &beta)).certified_sign()? == Sign::Negative {
                    continue;
                }
            }
        }
        roots.push(u + lo);
    }
    let mut roots = roots.into_iter();
    Some(match (roots.next(), roots.next()) {
        (None, _) => BisectorRoots::None,
        (Some(r), None) => BisectorRoots::One(r),
        (Some(r), Some(s)) => BisectorRoots::Two(r, s),
    })
}
