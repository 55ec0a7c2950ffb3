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

use super::bisector::Eq2Terms;
use super::{BisectorRoots, Eq2Coefficients, Field, Ring, Sign, SourceDistance};
use std::cell::OnceCell;

/// A number type that may know the exact sign of a value: `None` means "cannot tell" (a filter
/// too coarse for it); an exact type always answers.
pub(crate) trait CertifiedSign: Ring {
    fn certified_sign(&self) -> Option<Sign>;

    /// The sign where it is clear without a proof of zero (a filter, or refinement that moves
    /// the value away from zero), else `None`; a type that always answers may still say `None`
    /// here, so that a sign near zero can be avoided where the answer does not need it.
    fn clear_sign(&self) -> Option<Sign> {
        self.certified_sign()
    }

    /// Whether [`CertifiedSign::certified_sign`] always answers (an exact type, which may
    /// answer without a certificate). For such a type, a sign that [`CertifiedSign::proved_sign`]
    /// cannot certify is left to an argument that does not need it; for the others, `None` is a
    /// question for a finer type.
    const ALWAYS_ANSWERS: bool = false;

    /// The sign where it is certified, else `None`, and no decision.
    fn proved_sign(&self) -> Option<Sign> {
        self.certified_sign()
    }
}

/// Which solutions of eq. (1) lie strictly inside a shared range.
pub(crate) enum Crossings<T> {
    None,
    Infinite,
    /// One solution where the distance functions cross, with its position from the range's
    /// start, exact in `T`.
    At(T),
    /// One solution where they touch without crossing (a double root of eq. (2)).
    Touch(T),
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
            Crossings::Touch(u) => Crossings::Touch(f(&u)),
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

/// The gap of two pseudo-sources, `|s2 - s1|^2 - (sigma2 - sigma1)^2`, with `s2` mirrored
/// across the edge's line if `mirror`: how far the triangle inequality
/// `|sigma2 - sigma1| <= |s1 s2|` is from equality. Eq. (2)'s discriminant factors as
/// `B^2 - 4AC = beta^2 G G'` (`G` the gap, `G'` the mirrored one), so a double root, where one
/// distance function touches the other without crossing it, is a zero gap: a pseudo-source seen
/// straight from the other one. Built from differences of the inputs, so that a backend whose
/// inputs are `f64` can decide its sign exactly at little cost.
pub(crate) fn source_gap<T: Ring>(a: &SourceDistance<T>, b: &SourceDistance<T>, mirror: bool) -> T {
    let dx = b.x.clone() - &a.x;
    let dy = if mirror {
        b.y.clone() + &a.y
    } else {
        b.y.clone() - &a.y
    };
    let ds = b.sigma.clone() - &a.sigma;
    dx.clone() * &dx + dy.clone() * &dy - ds.clone() * &ds
}

/// Eq. (2)'s `P` at `origin`: its constant term `C` with positions measured from there.
pub(crate) fn eq2_at<T: Ring>(a: &SourceDistance<T>, b: &SourceDistance<T>, origin: &T) -> T {
    Eq2Terms::new(a, b, origin).constant()
}

/// The linear form `m u + c` that equals `A (q2(u) - beta^2)` at the roots of eq. (2)'s `P`
/// (`q2` the squared distance from the second pseudo-source), as `(m, c)`: `q2 - beta^2`
/// reduced by `P / A` has slope `-2 x2 - B / A = -alpha (2 alpha x2 + gamma) / A`, written so
/// that it is zero with alpha (pseudo-sources level along the edge, as on a wall below a
/// polygonal rim) by its factor, not by the cancellation of two deep terms.
fn reduced_excess<T: Ring>(
    [alpha, x2, gamma, excess]: [&T; 4],
    eq2: &Eq2Coefficients<T>,
) -> (T, T) {
    let m = -(alpha.clone() * &(T::from_f64(2.0) * alpha * x2 + gamma));
    (m, eq2.a.clone() * excess - &eq2.c)
}

/// The factor of `P(p) m^2` whose sign is not known beforehand, `p = -c / m` the zero of the
/// [`reduced_excess`] `m u + c`: `P(p) m^2 = A c^2 - B c m + C m^2 = A F1 F2 / 16` with
/// `F1 = G G' + 4 beta^2 y1^2` (`G`, `G'` the [`source_gap`]s) and this `F2 = (alpha^2 -
/// 9 beta^2)(alpha^2 - beta^2) + 2 alpha^2 (y1^2 + y2^2) - 6 beta^2 (y1^2 - y2^2) + (y1^2 -
/// y2^2)^2`. Where eq. (2) has two roots, its discriminant `beta^2 G G'` is positive, so `F1` is
/// too, and `P(p) m^2` has the sign of `A F2`. The product itself is of degree 10 and, for a
/// vertex's wedge along its edge against the wedge that lit the vertex (`y1 = 0`, `G` near
/// zero), as small as `G^2`: beyond double-double, so that exact rationals had to decide it
/// (9,548 times on stanford_bunny); `F2` is of degree 4 and not small there.
pub(crate) fn excess_factor<T: Ring>(a: &SourceDistance<T>, b: &SourceDistance<T>) -> T {
    let alpha = b.x.clone() - &a.x;
    let beta = b.sigma.clone() - &a.sigma;
    let (alpha2, beta2) = (alpha.clone() * &alpha, beta.clone() * &beta);
    let (y1, y2) = (a.y.clone() * &a.y, b.y.clone() * &b.y);
    let dy = y1.clone() - &y2;
    (alpha2.clone() - &(T::from_f64(9.0) * &beta2)) * &(alpha2.clone() - &beta2)
        + &(T::from_f64(2.0) * &alpha2 * &(y1 + &y2))
        - &(T::from_f64(6.0) * &beta2 * &dy)
        + &(dy.clone() * &dy)
}

/// Signs that depend on the two wedges and the ends of their shared range only, which a
/// backend may decide apart from the rest of [`crossings`] when the filter's number type cannot:
/// they are the ones near-degenerate meetings make hard, and deciding them alone is far cheaper
/// than deciding the whole meeting again at a finer stage. `None`: not decided apart.
pub(crate) trait InputSigns {
    /// The sign of [`source_gap`].
    fn gap(&self, mirror: bool) -> Option<Sign>;

    /// The sign of eq. (2)'s `P` at the start (`false`) or end (`true`) of the range
    /// ([`eq2_at`]): near zero when the range starts where the two wedges already cross.
    fn at_end(&self, end: bool) -> Option<Sign>;

    /// The sign of [`excess_factor`].
    fn excess_factor(&self) -> Option<Sign> {
        None
    }

    /// Where the engine knows by structure that one pseudo-source is seen straight from the
    /// other (see [`SeenStraight`]): whether the two lie on opposite sides of the edge's line
    /// in the surface. Their gap, taken as the surface places them, is then zero, asked of no
    /// arithmetic.
    fn seen_straight(&self) -> Option<bool> {
        None
    }
}

/// No sign decided apart, and one pseudo-source seen straight from the other: a vertex lit
/// across a face by a wedge, and the vertex's own wedge on an edge that wedge, its parent or
/// a descendant around the vertex reached (see `mmp/paths.rs`, `Path::seen_straight_from`).
/// The vertex's distance is the lit wedge's distance function there, so the two distance
/// functions touch. `opposite`: whether the two images lie on opposite sides of the edge's
/// line in the surface.
pub(crate) struct SeenStraight {
    pub(crate) opposite: bool,
}

impl InputSigns for SeenStraight {
    fn gap(&self, _mirror: bool) -> Option<Sign> {
        None
    }

    fn at_end(&self, _end: bool) -> Option<Sign> {
        None
    }

    fn seen_straight(&self) -> Option<bool> {
        Some(self.opposite)
    }
}

/// No sign decided apart: the number type decides every sign itself.
pub(crate) struct InT;

impl InputSigns for InT {
    fn gap(&self, _mirror: bool) -> Option<Sign> {
        None
    }

    fn at_end(&self, _end: bool) -> Option<Sign> {
        None
    }
}

/// Whether two wedges have the same distance function: `A = B = C = 0` in eq. (2).
pub(crate) fn same_distance_function<T: CertifiedSign>(
    a: &SourceDistance<T>,
    b: &SourceDistance<T>,
) -> Option<bool> {
    same_distance_function_by(a, b, T::certified_sign)
}

/// [`same_distance_function`] with the coefficients' signs told by `sign`.
pub(crate) fn same_distance_function_by<T: CertifiedSign>(
    a: &SourceDistance<T>,
    b: &SourceDistance<T>,
    sign: impl Fn(&T) -> Option<Sign>,
) -> Option<bool> {
    let eq2 = Eq2Coefficients::new(a, b, &a.x);
    let coefficients = [&eq2.a, &eq2.b, &eq2.c];
    // One coefficient clearly non-zero answers, before a zero of another is sought: two
    // images on one line through a pseudo-source (on a band of strips, along its rim) have
    // `B = 0` only by that line, which no normal form of theirs shows.
    if coefficients
        .iter()
        .any(|c| matches!(c.clear_sign(), Some(Sign::Positive | Sign::Negative)))
    {
        return Some(false);
    }
    for c in coefficients {
        if sign(c)? != Sign::Zero {
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

/// Where the roots of eq. (2)'s `P` lie, told by the range's ends alone: `P`'s signs there and
/// its slopes there. A quadratic monotone on the range (its slope of one sign at both ends) has
/// no root inside if its signs at the ends agree, and exactly one if they differ (then two
/// distinct real roots). This needs no discriminant, which is zero (and so beyond a filter)
/// wherever one distance function touches the other, even far outside the range.
enum RootsByEnds {
    NoneInside,
    OneInside,
}

impl RootsByEnds {
    /// Placed from signs that are clear ([`CertifiedSign::clear_sign`]) at the ends of
    /// `[0, width]`; `None` if one is not, if `P` is known to vanish at an end (`ties`), or if
    /// `P` is not monotone on the range.
    fn of<T: CertifiedSign>(eq2: &Eq2Coefficients<T>, width: &T, ties: [bool; 2]) -> Option<Self> {
        if ties[0] || ties[1] {
            return None;
        }
        let two = T::from_f64(2.0);
        let slope_lo = eq2.b.clear_sign()?;
        let slope_hi = (two * &eq2.a * width + &eq2.b).clear_sign()?;
        if slope_lo == Sign::Zero || slope_lo != slope_hi {
            return None;
        }
        let at_lo = eq2.c.clear_sign()?;
        let at_hi =
            (eq2.a.clone() * width * width + &(eq2.b.clone() * width) + &eq2.c).clear_sign()?;
        match (at_lo, at_hi) {
            (Sign::Zero, _) | (_, Sign::Zero) => None,
            (lo, hi) if lo == hi => Some(RootsByEnds::NoneInside),
            _ => Some(RootsByEnds::OneInside),
        }
    }
}

/// The quadratic `P` of eq. (2) with two distinct real roots, and `A`'s sign.
struct TwoRoots<'a, T> {
    eq2: &'a Eq2Coefficients<T>,
    sa: Sign,
}

impl<T: CertifiedSign> TwoRoots<'_, T> {
    /// The sign of `root - p` for the smaller (`larger = false`) or larger root, from the signs
    /// of `P(p)` and of the slope `P'(p)`, the slope asked only if needed.
    fn root_minus_given(
        &self,
        larger: bool,
        at_p: Sign,
        slope: impl FnOnce() -> Option<Sign>,
    ) -> Option<Sign> {
        // p between the roots, or else left or right of both by its side of the vertex
        // -B / (2A) (the slope's sign, times A's).
        Some(match at_p.times(self.sa) {
            Sign::Negative => {
                if larger {
                    Sign::Positive
                } else {
                    Sign::Negative
                }
            }
            Sign::Positive => negate(slope()?.times(self.sa)),
            // p is a root: the smaller one if it is left of the vertex.
            Sign::Zero => match (slope()?.times(self.sa) == Sign::Negative, larger) {
                (true, false) | (false, true) => Sign::Zero,
                (true, true) => Sign::Positive,
                (false, false) => Sign::Negative,
            },
        })
    }

    /// The sign of `(m r + c) / A` at a root `r`, without a division: `m r + c = m (r - p)` at
    /// `p = -c / m`, and the signs of `P(p) m^2` (`at_p`, see [`excess_factor`]) and of
    /// `P'(p) m = B m - 2 A c` tell where `p` lies.
    fn linear_over_a_at(
        &self,
        larger: bool,
        m: &T,
        c: &T,
        at_p: impl FnOnce() -> Option<Sign>,
    ) -> Option<Sign> {
        let e = self.eq2;
        let sign = match m.certified_sign()? {
            Sign::Zero => c.certified_sign()?,
            sm => {
                let slope = || {
                    let scaled = e.b.clone() * m - &(T::from_f64(2.0) * &e.a * c);
                    Some(scaled.certified_sign()?.times(sm))
                };
                self.root_minus_given(larger, at_p()?, slope)?.times(sm)
            }
        };
        Some(sign.times(self.sa))
    }
}

/// The solutions of eq. (1) strictly inside `(lo, hi)`, every decision an exact sign of a
/// polynomial in the inputs; `None` when `T` cannot tell one of them.
///
/// `signs` decides the signs that depend on the inputs only where `T` cannot ([`InT`]: `T`
/// decides every sign). `ties[0]` (`ties[1]`) says that the distance functions are known to be
/// equal at `lo` (`hi`): eq. (2)'s `P` is zero there, and is not evaluated.
pub(crate) fn crossings<T: CertifiedSign>(
    a: &SourceDistance<T>,
    b: &SourceDistance<T>,
    lo: &T,
    hi: &T,
    signs: &impl InputSigns,
    ties: [bool; 2],
) -> Option<Crossings<T>> {
    // One pseudo-source seen straight from the other by structure: their gap as the surface
    // places them is zero (mirrored where the frames put on one side of the line images that
    // lie on opposite sides, or the other way round).
    let straight = |mirror: bool| {
        let opposite = signs.seen_straight()?;
        let same_in_frame = a.y.certified_sign()?.times(b.y.certified_sign()?) != Sign::Negative;
        (mirror == (opposite == same_in_frame)).then_some(Sign::Zero)
    };
    let gap = |mirror| {
        straight(mirror)
            .or_else(|| source_gap(a, b, mirror).certified_sign())
            .or_else(|| signs.gap(mirror))
    };
    let terms = Eq2Terms::new(a, b, lo);
    let eq2 = terms.coefficients();
    let Eq2Terms {
        x2,
        alpha,
        beta,
        beta2,
        n2,
        gamma,
    } = terms;
    // A = (alpha - beta)(alpha + beta): each factor is a sum of the inputs, so its sign is
    // certain unless it nearly vanishes (Example 2's configuration).
    let sa = (alpha.clone() - &beta)
        .certified_sign()?
        .times((alpha.clone() + &beta).certified_sign()?);
    let width = hi.clone() - lo;
    // B is asked only when A = 0, C only for A = B = 0: C is often nearly zero (the range
    // starts where the wedges are nearly equal). With A = 0, eq. (2) is `B u + C`: clearly of
    // one sign at both ends of the range, it has no root inside whatever B is (two images on
    // one line through a pseudo-source have B = 0 only by that line, which no normal form
    // shows).
    let sb = match sa {
        Sign::Zero => {
            let at_end = eq2.c.clone() + &(eq2.b.clone() * &width);
            match (eq2.c.clear_sign(), at_end.clear_sign()) {
                (Some(s0), Some(s1)) if s0 != Sign::Zero && s0 == s1 => {
                    return Some(Crossings::None)
                }
                _ => Some(eq2.b.certified_sign()?),
            }
        }
        _ => None,
    };
    if sb == Some(Sign::Zero) && eq2.c.certified_sign()? == Sign::Zero {
        return Some(Crossings::Infinite);
    }
    let sbeta = beta.certified_sign()?;
    let alpha_sign = alpha.certified_sign()?;
    let two = T::from_f64(2.0);
    // q2(u) - beta^2 = u^2 - 2 x2 u + (n2 - beta^2).
    let q2_excess = n2.clone() - &beta2;
    // A single root, known exactly: inside the range, and a solution of eq. (1)? Not inside
    // where the functions are known to tie at an end: the root is that end.
    let single = |u: T| -> Option<Crossings<T>> {
        if ties[0] || ties[1] {
            return Some(Crossings::None);
        }
        // A root of eq. (2) where L has the wrong sign solves no eq. (1), wherever it lies: told
        // first where that sign is clear, so that such a root at an end of the range (a
        // tangency with the mirror image: a pseudo-source lit across this very edge, whose
        // straight way crossed it at the range's end) need not be placed against the end.
        let wrong_side = |sl: Sign| sl != Sign::Zero && sl != sbeta;
        if sbeta != Sign::Zero
            && (two.clone() * &alpha * &u + &gamma)
                .clear_sign()
                .is_some_and(wrong_side)
        {
            return Some(Crossings::None);
        }
        let inside = u.certified_sign()? == Sign::Positive
            && (width.clone() - &u).certified_sign()? == Sign::Positive;
        if !inside {
            return Some(Crossings::None);
        }
        if sbeta != Sign::Zero {
            let sl = (two.clone() * &alpha * &u + &gamma).certified_sign()?;
            if wrong_side(sl) {
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
        return match alpha_sign {
            Sign::Zero => Some(Crossings::None),
            _ => single(-(gamma.clone() / &(two.clone() * &alpha))),
        };
    }
    // Pseudo-sources level along the edge (alpha = 0, beta != 0): the difference of the
    // distances is a strictly monotone function of (t - x2)^2, so it vanishes at most once on
    // either side of their common foot. A tie known at an end with the foot beyond it (a rim
    // vertex lit straight along the rim by another, both giving the edge's vertex one
    // distance) is then the only solution on the range, and no gap need be proved zero.
    if alpha_sign == Sign::Zero {
        if ties[0] && x2.certified_sign()? != Sign::Positive {
            return Some(Crossings::None);
        }
        if ties[1] && (x2.clone() - &width).certified_sign()? != Sign::Negative {
            return Some(Crossings::None);
        }
    }
    match sb {
        Some(Sign::Zero) => return Some(Crossings::None),
        Some(_) => return single(-(eq2.c.clone() / &eq2.b)),
        None => {}
    }
    // B^2 - 4AC = beta^2 G G' (the source gaps), beta != 0 here. The gap with s2 on s1's side
    // of the line is the smaller (they differ by 4 |y1 y2|): if it is positive, so is the other.
    let opposite = a.y.certified_sign()?.times(b.y.certified_sign()?) == Sign::Negative;
    let discriminant = |gap: &dyn Fn(bool) -> Option<Sign>| {
        Some(match gap(opposite)? {
            Sign::Negative => negate(gap(!opposite)?),
            near => near,
        })
    };
    let clear_gap = |mirror| source_gap(a, b, mirror).clear_sign();
    // A zero gap is a tangency the algorithm itself makes: a vertex's wedges touch, along its
    // shadow line, the wedges of the image that lit it. Where the gap is not clear, the ends of
    // the range may still place the roots without it (`RootsByEnds`).
    let disc = match discriminant(&clear_gap) {
        Some(disc) => disc,
        None => match RootsByEnds::of(&eq2, &width, ties) {
            Some(RootsByEnds::NoneInside) => return Some(Crossings::None),
            Some(RootsByEnds::OneInside) => Sign::Positive,
            None => discriminant(&gap)?,
        },
    };
    match disc {
        Sign::Negative => return Some(Crossings::None),
        // A double root: the distance functions touch there (a zero gap: one pseudo-source
        // lies on a straight way from the other) and do not cross.
        Sign::Zero => {
            return single(-(eq2.b.clone() / &(two.clone() * &eq2.a))).map(|c| match c {
                Crossings::At(u) => Crossings::Touch(u),
                other => other,
            })
        }
        Sign::Positive => {}
    }
    let roots = TwoRoots { eq2: &eq2, sa };
    let zero = T::from_f64(0.0);
    // At a root, L(u) = 2 alpha u + gamma; q2(u) - beta^2 is linear there too.
    let (m_q, c_q) = reduced_excess([&alpha, &x2, &gamma, &q2_excess], &eq2);
    let two_alpha = two.clone() * &alpha;
    // At the foot of a pseudo-source on the edge's line (a vertex's wedge along its edge), P is
    // (G / 2)^2 and its slope -+alpha G, G the gap (either one: they agree when a y is zero).
    // G != 0 here, since the discriminant beta^2 G^2 is positive. A range that starts or ends
    // at such a vertex, where the other wedge gives the vertex its distance, has a near-double
    // root of P there, which no filter can place; the gap's sign can.
    // P at each end where it is proved (asked once): `Some(None)` where it is not.
    let p_at_end: [OnceCell<Option<Sign>>; 2] = Default::default();
    let p_value =
        |from_lo: &T| eq2.a.clone() * from_lo * from_lo + &(eq2.b.clone() * from_lo) + &eq2.c;
    // The sign of a root minus an end; `assumed[i]` stands for P's sign at end `i` where it is
    // not proved.
    let at_end = |larger: bool, end: &T, from_lo: &T, is_hi: bool, assumed: [Sign; 2]| {
        for (s, slope) in [(a, negate(alpha_sign)), (b, alpha_sign)] {
            if s.y.certified_sign()? == Sign::Zero
                && (s.x.clone() - end).certified_sign()? == Sign::Zero
            {
                let g = gap(false)?;
                return roots.root_minus_given(larger, Sign::Positive, || Some(slope.times(g)));
            }
        }
        let slope = || (two.clone() * &eq2.a * from_lo + &eq2.b).certified_sign();
        let i = usize::from(is_hi);
        let at_p = if ties[i] {
            Sign::Zero
        } else {
            let proved = p_at_end[i].get_or_init(|| {
                p_value(from_lo)
                    .proved_sign()
                    .or_else(|| signs.at_end(is_hi))
            });
            match proved {
                Some(sign) => *sign,
                None if T::ALWAYS_ANSWERS => assumed[i],
                None => return None,
            }
        };
        roots.root_minus_given(larger, at_p, slope)
    };
    // The sign of P(p) m^2 at the zero p of the reduced excess: A's times that of its factor F2
    // (the other one is positive here, with the discriminant).
    let excess_at_p = || {
        let factor = excess_factor(a, b)
            .certified_sign()
            .or_else(|| signs.excess_factor())?;
        Some(sa.times(factor))
    };
    let solves_assuming = |larger: bool, assumed: [Sign; 2]| -> Option<bool> {
        if at_end(larger, lo, &zero, false, assumed)? != Sign::Positive
            || at_end(larger, hi, &width, true, assumed)? != Sign::Negative
        {
            return Some(false);
        }
        let sl = match alpha_sign {
            Sign::Zero => gamma.certified_sign()?,
            sm => {
                // At L's zero p, P(p) = -beta^2 q2(p) < 0: q2(p) = 0 only at the foot of a
                // pseudo-source on the line with a zero gap, where the discriminant is zero.
                // Known without P(p), which a near-tangency puts beyond any filter.
                let p = -(gamma.clone() / &two_alpha);
                let slope = || (two.clone() * &eq2.a * &p + &eq2.b).certified_sign();
                roots
                    .root_minus_given(larger, Sign::Negative, slope)?
                    .times(sm)
            }
        };
        if sl != Sign::Zero && sl != sbeta {
            return Some(false);
        }
        if sbeta == Sign::Negative
            && roots.linear_over_a_at(larger, &m_q, &c_q, excess_at_p)? == Sign::Negative
        {
            return Some(false);
        }
        Some(true)
    };
    // A root of P exactly at an end, where nothing proves P zero there, is most often one the
    // algorithm made: a mirror root (the pseudo-source was reached back through that end's
    // vertex from the other's image) or a tangency. Where every sign P may have there gives
    // the same answer, that answer is proved without the sign; else the sign is decided (and
    // counted uncertified).
    let solves = |larger: bool| -> Option<bool> {
        let first = solves_assuming(larger, [Sign::Zero; 2])?;
        let unproved = || [0, 1].map(|i| matches!(p_at_end[i].get(), Some(None)));
        if !unproved().contains(&true) {
            return Some(first);
        }
        // Every pair of signs, since another sign at one end may lead to asking the other end.
        let signs = [Sign::Negative, Sign::Zero, Sign::Positive];
        let agree = signs.iter().all(|&s0| {
            signs
                .iter()
                .all(|&s1| solves_assuming(larger, [s0, s1]) == Some(first))
        });
        if agree {
            return Some(first);
        }
        let unproved = unproved();
        let decided = [(&zero, 0), (&width, 1)].map(|(from_lo, i)| {
            if unproved[i] {
                p_value(from_lo).certified_sign().unwrap_or(Sign::Zero)
            } else {
                Sign::Zero
            }
        });
        solves_assuming(larger, decided)
    };
    let (smaller, larger) = (solves(false)?, solves(true)?);
    Some(Crossings::Quadratic {
        eq2,
        sign_a: sa,
        smaller,
        larger,
    })
}

impl<T> Crossings<T> {
    /// How many times the lower function changes inside the range.
    pub(crate) fn changes(&self) -> usize {
        match self {
            Crossings::None | Crossings::Infinite | Crossings::Touch(_) => 0,
            Crossings::At(_) => 1,
            Crossings::Quadratic {
                smaller, larger, ..
            } => usize::from(*smaller) + usize::from(*larger),
        }
    }
}

/// The sign of `D_a(p) - D_b(p)` (eq. (1)'s two sides at `p`) as signs of polynomials in the
/// inputs, with positions from `p`: with `beta = sigma_b - sigma_a` and `n_a`, `n_b` the squared
/// distances from the pseudo-sources, `D_a - D_b = sqrt(n_a) - (sqrt(n_b) + beta)`; squaring
/// gives `L = n_a - n_b - beta^2` (eq. (2)'s `gamma` from `p`) against `2 beta sqrt(n_b)`, and
/// squaring again eq. (2)'s `P(p)` (`at_p`: its sign decided apart, asked if `sign` cannot
/// tell). `sign` is the number
/// type's sign ([`CertifiedSign::certified_sign`] or [`CertifiedSign::clear_sign`]).
fn difference_sign<T: CertifiedSign>(
    a: &SourceDistance<T>,
    b: &SourceDistance<T>,
    p: &T,
    at_p: impl FnOnce() -> Option<Sign>,
    sign: impl Fn(&T) -> Option<Sign>,
) -> Option<Sign> {
    let terms = Eq2Terms::new(a, b, p);
    let xa = a.x.clone() - p;
    let n_a = xa.clone() * &xa + &(a.y.clone() * &a.y);
    let s_beta = sign(&terms.beta)?;
    let s_nb = sign(&terms.n2)?;
    // The sign of sqrt(n_b) + beta.
    let s_right = match s_beta {
        Sign::Negative => sign(&(terms.n2.clone() - &terms.beta2))?,
        Sign::Zero if s_nb == Sign::Zero => Sign::Zero,
        _ => Sign::Positive,
    };
    match s_right {
        Sign::Negative => return Some(Sign::Positive),
        Sign::Zero => return sign(&n_a),
        Sign::Positive => {}
    }
    // sign(L - 2 beta sqrt(n_b)), both sides' signs first.
    let s_l = sign(&terms.gamma)?;
    if s_beta == Sign::Zero || s_nb == Sign::Zero {
        return Some(s_l);
    }
    Some(match s_l {
        Sign::Zero => negate(s_beta),
        s if s != s_beta => s,
        s => {
            let s_p = match sign(&terms.constant()) {
                Some(s_p) => s_p,
                None => at_p()?,
            };
            s_p.times(s)
        }
    })
}

/// The sign of `D_a - D_b` on the first stretch of `(lo, hi)` (from `lo` to the first
/// solution of eq. (1), or the whole range), given how many times it `changes` inside:
/// the sign at `lo`, else at `hi` (times `(-1)^changes`), else, with no solution inside and
/// the functions equal at both ends, at the middle. By Property 1 [LZT §3] the functions meet
/// at most twice unless they coincide, so an end where they are equal leaves the other end
/// nonzero when they cross inside. `known[i]`: the sign at that end, if known apart (the
/// engine's kept values); `signs` decides eq. (2)'s `P` at the ends apart. `None` when the
/// number type cannot tell.
pub(crate) fn first_stretch_sign<T: CertifiedSign>(
    (a, b): (&SourceDistance<T>, &SourceDistance<T>),
    [lo, hi]: [&T; 2],
    changes: usize,
    signs: &impl InputSigns,
    known: [Option<Sign>; 2],
    sign: impl Fn(&T) -> Option<Sign>,
) -> Option<Sign> {
    // Both ends by the number type's own signs first, then with eq. (2)'s `P` there decided
    // apart: a range often starts where the two functions tie, and `P` is then near zero.
    let mut undecided = false;
    for apart in [false, true] {
        undecided = false;
        for (i, end) in [lo, hi].into_iter().enumerate() {
            let at_end = known[i].or_else(|| {
                let at_p = || if apart { signs.at_end(i == 1) } else { None };
                difference_sign(a, b, end, at_p, &sign)
            });
            match at_end {
                None => undecided = true,
                Some(Sign::Zero) => {}
                Some(s) if i == 1 && changes % 2 == 1 => return Some(negate(s)),
                Some(s) => return Some(s),
            }
        }
        if !undecided {
            break;
        }
    }
    if undecided {
        return None;
    }
    if changes > 0 {
        // Equal at both ends and crossing inside: not possible by Property 1.
        return Some(Sign::Zero);
    }
    let mid = (lo.clone() + hi) * &T::from_f64(0.5);
    difference_sign(a, b, &mid, || None, &sign)
}

/// The roots of eq. (2) in increasing order, for two distinct real roots, in a [`Field`]:
/// `(-B -+ sqrt(D)) / 2A`, ordered by the sign of `A`. The exact backend wants this shape (one
/// square root over the coefficients, which its normal form handles); `f64` wants the
/// cancellation-free one from exact coefficients (the adaptive backend's `root_positions`).
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

/// Which of the two roots are solutions, as [`BisectorRoots`] back on the edge.
fn chosen<S: Field>([r, s]: [S; 2], smaller: bool, larger: bool, lo: &S) -> BisectorRoots<S> {
    match (smaller, larger) {
        (true, true) => BisectorRoots::Two(r + lo, s + lo),
        (true, false) => BisectorRoots::One(r + lo),
        (false, true) => BisectorRoots::One(s + lo),
        (false, false) => BisectorRoots::None,
    }
}

/// The crossings as [`BisectorRoots`] in a [`Field`], positions back on the edge.
pub(crate) fn into_roots<S: Field>(c: Crossings<S>, lo: &S) -> BisectorRoots<S> {
    match c {
        Crossings::None => BisectorRoots::None,
        Crossings::Infinite => BisectorRoots::Infinite,
        Crossings::At(u) => BisectorRoots::One(u + lo),
        Crossings::Touch(u) => BisectorRoots::Touch(u + lo),
        Crossings::Quadratic {
            eq2,
            sign_a,
            smaller,
            larger,
        } => chosen(quadratic_roots(&eq2, sign_a), smaller, larger, lo),
    }
}

#[cfg(test)]
mod tests {
    use super::super::rational::Q;
    use super::*;
    use proptest::prelude::*;

    fn source(x: f64, y: f64, sigma: f64) -> SourceDistance<Q> {
        SourceDistance {
            x: Q::from_f64(x),
            y: Q::from_f64(y),
            sigma: Q::from_f64(sigma),
        }
    }

    /// Exact rationals that always answer but prove no sign of a value within 1/8 of zero
    /// ([`CertifiedSign::proved_sign`] is `None` there), as an exact backend that cannot prove
    /// a zero, or a sign near one: the arguments that go around an unproved sign must give what
    /// the exact signs give.
    #[derive(Clone, Debug)]
    struct NearZeroUnproved(Q);

    /// The arithmetic of a wrapper of [`Q`], done on the rationals.
    macro_rules! delegate {
        ($t:ident: $($tr:ident $f:ident),*) => {
            $(
                impl std::ops::$tr for $t {
                    type Output = $t;
                    fn $f(self, other: $t) -> $t {
                        $t(std::ops::$tr::$f(self.0, &other.0))
                    }
                }
                impl<'a> std::ops::$tr<&'a $t> for $t {
                    type Output = $t;
                    fn $f(self, other: &'a $t) -> $t {
                        $t(std::ops::$tr::$f(self.0, &other.0))
                    }
                }
            )*
            impl std::ops::Neg for $t {
                type Output = $t;
                fn neg(self) -> $t {
                    $t(-self.0)
                }
            }
        };
    }
    delegate!(NearZeroUnproved: Add add, Sub sub, Mul mul, Div div);

    impl Ring for NearZeroUnproved {
        fn from_f64(x: f64) -> Self {
            NearZeroUnproved(Q::from_f64(x))
        }
    }

    impl CertifiedSign for NearZeroUnproved {
        const ALWAYS_ANSWERS: bool = true;

        fn certified_sign(&self) -> Option<Sign> {
            self.0.certified_sign()
        }

        fn proved_sign(&self) -> Option<Sign> {
            let eighth = Q::from_f64(0.125);
            let near = (self.0.clone() - &eighth).certified_sign() == Some(Sign::Negative)
                && (self.0.clone() + &eighth).certified_sign() == Some(Sign::Positive);
            (!near).then(|| self.0.certified_sign()).flatten()
        }
    }

    /// Exact rationals that decide every sign but zero's, as an exact backend that cannot prove
    /// a zero: [`CertifiedSign::certified_sign`] is `None` there.
    #[derive(Clone, Debug)]
    struct ZeroUndecided(Q);

    delegate!(ZeroUndecided: Add add, Sub sub, Mul mul, Div div);

    impl Ring for ZeroUndecided {
        fn from_f64(x: f64) -> Self {
            ZeroUndecided(Q::from_f64(x))
        }
    }

    impl CertifiedSign for ZeroUndecided {
        fn certified_sign(&self) -> Option<Sign> {
            self.0.certified_sign().filter(|&s| s != Sign::Zero)
        }
    }

    /// What the engine reads of the crossings: which roots solve eq. (1) inside the range.
    #[derive(Debug, PartialEq)]
    enum Reading {
        Undecided,
        None,
        Infinite,
        At(Q),
        Touch(Q),
        Two { smaller: bool, larger: bool },
    }

    fn reading<T>(c: Option<Crossings<T>>, to_q: impl Fn(&T) -> Q) -> Reading {
        match c {
            None => Reading::Undecided,
            Some(Crossings::None) => Reading::None,
            Some(Crossings::Infinite) => Reading::Infinite,
            Some(Crossings::At(u)) => Reading::At(to_q(&u)),
            Some(Crossings::Touch(u)) => Reading::Touch(to_q(&u)),
            Some(Crossings::Quadratic {
                smaller, larger, ..
            }) => Reading::Two { smaller, larger },
        }
    }

    /// Points at integer distances from the origin (Pythagorean triples, either sign).
    const AT_WHOLE_DISTANCES: [(f64, f64, f64); 8] = [
        (3.0, 4.0, 5.0),
        (-4.0, 3.0, 5.0),
        (5.0, 12.0, 13.0),
        (-12.0, 5.0, 13.0),
        (8.0, 15.0, 17.0),
        (-15.0, 8.0, 17.0),
        (0.0, 7.0, 7.0),
        (6.0, 8.0, 10.0),
    ];

    proptest! {
        /// A vertex seen straight from the image that lit it, `sigma2 = sigma1 + |s1 s2|` in
        /// the surface: on opposite sides of the edge's line or on one side, both frames
        /// giving `y >= 0` or the second `y <= 0`. With no zero decided by arithmetic, the
        /// crossings are read only where the structure is told, and then as exact signs read
        /// them.
        #[test]
        fn a_vertex_seen_straight_touches_the_image_that_lit_it(
            i in 0..8usize, x1 in -8..9i32, t in 1..8i32, s1 in 0..40i32, lo in -8..9i32,
            width in 1..40i32, opposite in any::<bool>(), flip in any::<bool>(),
        ) {
            let (dx, dy, d) = AT_WHOLE_DISTANCES[i];
            // Images apart along the edge (`alpha != 0`), so that the gap is the only zero.
            prop_assume!(dy > 0.0 && dx != 0.0);
            let (x1, t) = (f64::from(x1) / 4.0, f64::from(t) / 8.0);
            // In the surface: `y1 > 0`, and `y2 = y1 - dy` (opposite sides) or `y1 + dy`.
            let y1 = dy * t;
            let y2 = if opposite { y1 - dy } else { y1 + dy };
            // The frame keeps `y2`'s sign, or gives it as a distance from the line.
            let y2 = if flip { y2.abs() } else { y2 };
            let s1 = f64::from(s1) / 4.0;
            let (a, b) = (source(x1, y1, s1), source(x1 + dx, y2, s1 + d));
            let mirrored = flip && opposite;
            prop_assert_eq!(source_gap(&a, &b, mirrored), Q::from_f64(0.0));
            let lo = f64::from(lo) / 2.0;
            let hi = lo + f64::from(width) / 4.0;
            let exact = crossings(&a, &b, &Q::from_f64(lo), &Q::from_f64(hi), &InT, [false; 2]);
            let hide = |d: &SourceDistance<Q>| SourceDistance {
                x: ZeroUndecided(d.x.clone()),
                y: ZeroUndecided(d.y.clone()),
                sigma: ZeroUndecided(d.sigma.clone()),
            };
            let (ha, hb) = (hide(&a), hide(&b));
            let (hlo, hhi) = (ZeroUndecided::from_f64(lo), ZeroUndecided::from_f64(hi));
            let told = crossings(&ha, &hb, &hlo, &hhi, &SeenStraight { opposite }, [false; 2]);
            let exact = reading(exact, Q::clone);
            prop_assert_ne!(&exact, &Reading::Undecided);
            prop_assert_eq!(reading(told, |v| v.0.clone()), exact);
        }

        /// Two pseudo-sources whose distances tie at the range's start, `lo = 0`, or whose sigmas
        /// differ by the sum of their distances from it (a mirror root there), or nearly: `P(0)`
        /// is zero or small. With its sign unproved, the roots the engine reads are those of
        /// exact signs.
        #[test]
        fn an_unproved_root_of_p_at_an_end_changes_nothing(
            i in 0..8usize, j in 0..8usize, mirror in any::<bool>(), scale in 1..4i32,
            s1 in 0..40i32, hi in 1..60i32, flip in any::<bool>(), off in -2..3i32,
        ) {
            let (x1, y1, d1) = AT_WHOLE_DISTANCES[i];
            let (x2, y2, d2) = AT_WHOLE_DISTANCES[j];
            let k = f64::from(scale);
            let y2 = if flip { -y2 } else { y2 };
            let s1 = f64::from(s1);
            let tie = if mirror { s1 + d1 + k * d2 } else { s1 + d1 - k * d2 };
            let s2 = tie + f64::from(off) / 65536.0;
            prop_assume!(s2 >= 0.0);
            let (a, b) = (source(x1, y1, s1), source(k * x2, k * y2, s2));
            let (lo, hi) = (Q::from_f64(0.0), Q::from_f64(f64::from(hi) / 4.0));
            let exact = crossings(&a, &b, &lo, &hi, &InT, [false, false]);
            let hide = |d: &SourceDistance<Q>| SourceDistance {
                x: NearZeroUnproved(d.x.clone()),
                y: NearZeroUnproved(d.y.clone()),
                sigma: NearZeroUnproved(d.sigma.clone()),
            };
            let (ha, hb) = (hide(&a), hide(&b));
            let (hlo, hhi) = (NearZeroUnproved(lo.clone()), NearZeroUnproved(hi.clone()));
            let argued = crossings(&ha, &hb, &hlo, &hhi, &InT, [false, false]);
            prop_assert_eq!(reading(argued, |v| v.0.clone()), reading(exact, Q::clone));
        }

        /// `B^2 - 4AC = beta^2 G G'`, exactly, whatever the sides of the pseudo-sources.
        #[test]
        fn the_discriminant_is_beta_squared_times_the_gaps(
            x1 in -2.0..2.0f64, y1 in -2.0..2.0f64, s1 in 0.0..3.0f64,
            x2 in -2.0..2.0f64, y2 in -2.0..2.0f64, s2 in 0.0..3.0f64, lo in -1.0..1.0f64,
        ) {
            let (a, b) = (source(x1, y1, s1), source(x2, y2, s2));
            let e = Eq2Coefficients::new(&a, &b, &Q::from_f64(lo));
            let disc = e.b.clone() * &e.b - Q::from_f64(4.0) * &e.a * &e.c;
            let beta = b.sigma.clone() - &a.sigma;
            let factored =
                beta.clone() * &beta * &source_gap(&a, &b, false) * &source_gap(&a, &b, true);
            prop_assert_eq!((disc - &factored).certified_sign(), Some(Sign::Zero));
        }

        /// Where `L(t) = 2 alpha t + gamma` vanishes, `P = -beta^2 q2`.
        #[test]
        fn at_the_zero_of_l_p_is_minus_beta_squared_q2(
            x1 in -2.0..2.0f64, y1 in -2.0..2.0f64, s1 in 0.0..3.0f64,
            x2 in -2.0..2.0f64, y2 in -2.0..2.0f64, s2 in 0.0..3.0f64, lo in -1.0..1.0f64,
        ) {
            let (a, b) = (source(x1, y1, s1), source(x2, y2, s2));
            let terms = Eq2Terms::new(&a, &b, &Q::from_f64(lo));
            prop_assume!(terms.alpha.certified_sign() != Some(Sign::Zero));
            let e = terms.coefficients();
            let p = -(terms.gamma.clone() / &(Q::from_f64(2.0) * &terms.alpha));
            let at_p = e.a.clone() * &p * &p + &(e.b.clone() * &p) + &e.c;
            let dx = p - &terms.x2;
            let q2 = dx.clone() * &dx + &(b.y.clone() * &b.y);
            let expected = -(terms.beta2.clone() * &q2);
            prop_assert_eq!((at_p - &expected).certified_sign(), Some(Sign::Zero));
        }

        /// The reduced excess is `A (q2(u) - beta^2) - P(u)` at every `u` (so it is
        /// `A (q2 - beta^2)` at the roots of `P`), and `P` at its zero `p = -c / m`, times `m^2`,
        /// is `A (G G' + 4 beta^2 y1^2) F2 / 16` with `F2` the [`excess_factor`].
        #[test]
        fn the_reduced_excess_at_its_zero_factors(
            x1 in -2.0..2.0f64, y1 in -2.0..2.0f64, s1 in 0.0..3.0f64,
            x2 in -2.0..2.0f64, y2 in -2.0..2.0f64, s2 in 0.0..3.0f64,
            lo in -1.0..1.0f64, u in -3.0..3.0f64,
        ) {
            let (a, b) = (source(x1, y1, s1), source(x2, y2, s2));
            let terms = Eq2Terms::new(&a, &b, &Q::from_f64(lo));
            let e = terms.coefficients();
            let excess = terms.n2.clone() - &terms.beta2;
            let (m, c) = reduced_excess([&terms.alpha, &terms.x2, &terms.gamma, &excess], &e);
            let u = Q::from_f64(u);
            let p_at = |t: &Q| e.a.clone() * t * t + &(e.b.clone() * t) + &e.c;
            let dx = u.clone() - &terms.x2;
            let q2 = dx.clone() * &dx + &(b.y.clone() * &b.y);
            let expected = e.a.clone() * &(q2 - &terms.beta2) - &p_at(&u);
            let linear = m.clone() * &u + &c;
            prop_assert_eq!((linear - &expected).certified_sign(), Some(Sign::Zero));
            prop_assume!(m.certified_sign() != Some(Sign::Zero));
            let p = -(c.clone() / &m);
            let at_p = p_at(&p) * &m * &m;
            let f1 = source_gap(&a, &b, false) * &source_gap(&a, &b, true)
                + &(Q::from_f64(4.0) * &terms.beta2 * &a.y * &a.y);
            let factored = e.a.clone() * &f1 * &excess_factor(&a, &b) / &Q::from_f64(16.0);
            prop_assert_eq!((at_p - &factored).certified_sign(), Some(Sign::Zero));
        }

        /// At the foot of a pseudo-source on the edge's line, `P = (G / 2)^2` and
        /// `P' = -+alpha G` (minus for the first wedge's foot, plus for the second's).
        #[test]
        fn at_a_foot_p_is_the_squared_gap(
            x1 in -2.0..2.0f64, y1 in -2.0..2.0f64, s1 in 0.0..3.0f64,
            x2 in -2.0..2.0f64, s2 in 0.0..3.0f64, lo in -1.0..1.0f64, first in any::<bool>(),
        ) {
            let (a, b) = if first {
                (source(x2, 0.0, s2), source(x1, y1, s1))
            } else {
                (source(x1, y1, s1), source(x2, 0.0, s2))
            };
            let e = Eq2Coefficients::new(&a, &b, &Q::from_f64(lo));
            let foot = Q::from_f64(x2) - &Q::from_f64(lo);
            let p = e.a.clone() * &foot * &foot + &(e.b.clone() * &foot) + &e.c;
            let slope = Q::from_f64(2.0) * &e.a * &foot + &e.b;
            let g = source_gap(&a, &b, false);
            let alpha_g = (b.x.clone() - &a.x) * &g;
            let expected_slope = if first { -alpha_g } else { alpha_g };
            let quarter = Q::from_f64(0.25);
            prop_assert_eq!((p - &(quarter * &g * &g)).certified_sign(), Some(Sign::Zero));
            prop_assert_eq!((slope - &expected_slope).certified_sign(), Some(Sign::Zero));
        }
    }
}
