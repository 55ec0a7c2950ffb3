//! The `f64` backend: hardware floating point with one documented tolerance policy.
//!
//! Every tolerance the f64 engine uses is a constant of [`FloatTolerance`]; the engine itself
//! contains no epsilon. All tolerances are relative to a length of the edge at hand, so results
//! do not depend on the scale of the model (compare Observation 3 [LZT §6]).

use super::{
    Bisector, BisectorRoots, Eq2Coefficients, Field, Lower, Ring, Scalar, Sign, SourceDistance,
    FRONT_MARGIN,
};
use std::cmp::Ordering;

/// The f64 backend's tolerance policy, one constant per kind of decision.
pub struct FloatTolerance;

impl FloatTolerance {
    /// Two distances closer than this (relative) are a tie, and a tie keeps the wedge already on
    /// the edge. Above the rounding error of `sigma + sqrt(..)` chains of a few hundred faces
    /// (~1e-15), and small: a tie decides who owns a whole piece of an edge, so on slivers whose
    /// edges are 1e8 times the distances at hand, a tie of 1e-12 gave away pieces worth 20 %.
    pub const DISTANCE: f64 = 1e-14;
    /// Wedges shorter than this fraction of their edge (`2^-40`, about 9.1e-13, as the
    /// adaptive backend's [`Resolution::EXTENT`](super::Resolution::EXTENT)) are
    /// dropped: their rays are numerically parallel and they cannot carry a distance their
    /// neighbours do not. Positions are computed from the end of the edge nearer the sources
    /// ([`Scalar::frames_from_nearer_end`]), to ulps of the distances at hand; on an edge 1e8
    /// times longer than those, 1e-11 of it dropped ranges that carried 7e-5 of a distance.
    pub const EXTENT: f64 = 4096.0 * f64::EPSILON;
    /// Slack, as a fraction of the edge length (`2^-46`, about 1.4e-14), when asking whether a
    /// point lies in a wedge's range; covers the rounding of unfolded coordinates. Larger slack
    /// lets a wedge claim vertices beyond its range: on slivers a thousand times longer than
    /// the distances at hand, 1e-9 gave distances 2 % short, and on edges 1e8 times longer,
    /// 1e-12 gave 3e-7.
    pub const WITHIN: f64 = 64.0 * f64::EPSILON;
    /// A point lies on an edge's line ([`Scalar::on_line`]) if its height is at most this
    /// fraction (`2^-46`, as [`FloatTolerance::WITHIN`]) of the edge's length and its square
    /// at most this fraction of the square of the point's offset from the nearer end: then
    /// the distances through it move by this fraction at most when it is taken onto the line.
    /// Heights of a few ulps of a unit edge, from a vertex moved onto the edge, made windows as
    /// narrow, lost beside their neighbours, and the geodesics through the corner went round
    /// it (1e-9 of a distance long). With the first condition alone, a vertex 1e-16 from a
    /// unit edge's end was taken onto the edge and the distances of 3e-16 through it came out
    /// 30 % short.
    pub const ON_LINE: f64 = 64.0 * f64::EPSILON;
    /// Two wedges whose pseudo-sources and sigmas agree to this fraction of their size have
    /// the same distance function: eq. (2) has infinitely many solutions. Two images of one
    /// pseudo-source that agree to this fraction of their range's scale are one image.
    pub const SAME_SOURCE: f64 = 1e-12;
    /// A root of eq. (2) solves eq. (1) if the two distances there agree to this fraction.
    pub const ROOT_RESIDUAL: f64 = 1e-9;
}

impl Ring for f64 {
    #[inline(always)]
    fn from_f64(x: f64) -> Self {
        x
    }
}

impl Field for f64 {
    #[inline(always)]
    fn to_f64(&self) -> f64 {
        *self
    }

    #[inline(always)]
    fn sqrt(&self) -> Self {
        self.max(0.0).sqrt()
    }
}

impl Scalar for f64 {
    super::keeps_no_values!();

    #[inline]
    fn near_tie(a: &SourceDistance<f64>, b: &SourceDistance<f64>, t: &f64) -> bool {
        a.at(t).compare_distance(&b.at(t)) == Ordering::Equal
    }

    #[inline(always)]
    fn orientation(p: [&f64; 2], q: [&f64; 2], r: [&f64; 2]) -> Sign {
        ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])).sign()
    }

    #[inline(always)]
    fn at_least(value: f64, bound: impl FnOnce() -> f64) -> f64 {
        value.max(bound())
    }

    #[inline(always)]
    fn frames_from_nearer_end() -> bool {
        true
    }

    #[inline(always)]
    fn measures_below_float_resolution() -> bool {
        false
    }

    /// In `f64` arithmetic on the constructed values, with the margin `FRONT_MARGIN`.
    #[inline(always)]
    fn front_passed(d: &SourceDistance<f64>, lo: &f64, hi: &f64, front: f64) -> bool {
        farthest(d, *lo, *hi) * FRONT_MARGIN <= front
    }

    #[inline(always)]
    fn sign(&self) -> Sign {
        if *self > 0.0 {
            Sign::Positive
        } else if *self < 0.0 {
            Sign::Negative
        } else {
            Sign::Zero
        }
    }

    #[inline(always)]
    fn compare(&self, other: &Self) -> Ordering {
        self.total_cmp(other)
    }

    #[inline(always)]
    fn compare_distance(&self, other: &Self) -> Ordering {
        compare_with_tie(*self, *other, FloatTolerance::DISTANCE)
    }

    #[inline(always)]
    fn has_extent(lo: &Self, hi: &Self, scale: &Self) -> bool {
        hi - lo > FloatTolerance::EXTENT * scale
    }

    #[inline(always)]
    fn fans_out(lo: &Self, hi: &Self, x: &Self, y: &Self) -> bool {
        fans_out(*lo, *hi, *x, *y)
    }

    #[inline(always)]
    fn within(x: &Self, lo: &Self, hi: &Self, scale: impl FnOnce() -> Self) -> bool {
        let slack = FloatTolerance::WITHIN * scale();
        *x >= lo - slack && *x <= hi + slack
    }

    #[inline(always)]
    fn on_line(height: &Self, x: &Self, length: &Self) -> bool {
        let offset = x.min(length - x);
        *height <= FloatTolerance::ON_LINE * length
            && height * height <= FloatTolerance::ON_LINE * offset * offset
    }

    /// Within [`FloatTolerance::SAME_SOURCE`] of the size of the values compared (the
    /// pseudo-sources' coordinates and sigmas), which is what their constructions are known
    /// to; not of the range's length: on a range 2e8 long, pseudo-sources 1e-6 apart, the
    /// nearer lower by 1e-6 all along, were taken for one and the higher kept the range.
    fn same_distance_function(
        a: &SourceDistance<f64>,
        b: &SourceDistance<f64>,
        _scale: &f64,
    ) -> bool {
        let size = [a.x, b.x, a.y, b.y, a.sigma, b.sigma]
            .iter()
            .fold(0.0f64, |m, c| m.max(c.abs()));
        agree(a, b, FloatTolerance::SAME_SOURCE * size)
    }

    /// Within [`FloatTolerance::SAME_SOURCE`] of the range's scale (or of the images'
    /// distance from the edge): two chains of constructions of one pseudo-source's image.
    #[inline]
    fn same_image(a: &SourceDistance<f64>, b: &SourceDistance<f64>, scale: &f64) -> bool {
        agree(
            a,
            b,
            FloatTolerance::SAME_SOURCE * scale.max(a.y.abs()).max(b.y.abs()),
        )
    }

    /// The roots by `roots_in`; on each stretch between them, the lower function where the
    /// difference is clearest (`lower_on`): the roots' positions are rounded, and near a
    /// near-double root they move far, so owners are not inferred by alternation.
    fn bisector(
        a: &SourceDistance<f64>,
        b: &SourceDistance<f64>,
        lo: &f64,
        hi: &f64,
        _known: &[Option<[f64; 2]>; 2],
    ) -> Bisector<f64> {
        let roots = roots_in(a, b, *lo, *hi);
        let mut lower = [Lower::Neither; 3];
        if roots != BisectorRoots::Infinite {
            let cuts = match roots {
                BisectorRoots::One(r) | BisectorRoots::Touch(r) => [Some(r), None],
                BisectorRoots::Two(r, s) => [Some(r), Some(s)],
                _ => [None, None],
            };
            let mut start = *lo;
            for (i, end) in cuts.into_iter().flatten().chain([*hi]).enumerate() {
                lower[i] = lower_on(a, b, [start, end], [*lo, *hi], FloatTolerance::DISTANCE);
                start = end;
            }
        }
        Bisector { roots, lower }
    }
}

/// The larger of `d`'s distances at `lo` and `hi`, `max(d.at(lo), d.at(hi))` to the last bit
/// with one square root: rounded sums, roots and sums are monotone, so the end farther from
/// the foot of the pseudo-source gives the larger distance as computed too.
#[inline(always)]
pub(crate) fn farthest(d: &SourceDistance<f64>, lo: f64, hi: f64) -> f64 {
    let (a, b) = (lo - d.x, hi - d.x);
    ((a * a).max(b * b) + d.y * d.y).sqrt() + d.sigma
}

/// Whether the range `[lo, hi]` is wider than its farther end's distance from the
/// pseudo-source at `(x, y)`: its rays then spread by more than half a right angle, however
/// short the range is beside its edge ([`FloatTolerance::EXTENT`] drops ranges as
/// numerically parallel rays by the edge's length alone). Through 4e-6 of an edge 5e6 long,
/// a vertex 1e-7 from it (the middle corner of a nearly degenerate face) fans out the
/// geodesics into the faces beyond that nothing else reaches; dropped, they left distances
/// there 0.27 long (mixed magnitudes). A range seen from afar keeps the edge's resolution:
/// where near-ties cut it, its ends are known no better. Compared squared (no root; squares
/// that overflow or underflow only keep the edge's resolution).
#[inline(always)]
pub(crate) fn fans_out(lo: f64, hi: f64, x: f64, y: f64) -> bool {
    let (width, far) = (hi - lo, (x - lo).abs().max((x - hi).abs()));
    width > 0.0 && width * width > far * far + y * y
}

/// Which of `a`, `b` is lower on the stretch `[start, end]` of the range `[lo, hi]`: at its
/// middle, as [`Scalar::compare_distance`] decides (a tie: closer than `relative_tie`, for f64
/// [`FloatTolerance::DISTANCE`]);
/// if that is a tie, at whichever of its ends that are the range's ends (not rounded roots,
/// where the two are equal) the difference is clearest. The middle of a long stretch lies
/// where both distances are large and their tie wide: on a range 5e8 long whose distances
/// differ by 3e-6 throughout, the middle saw a tie and kept the worse wedge, and the wedges it
/// sent on lost 1.0 of a distance of 7e6 (mixed magnitudes, issue 10). `Neither` if every
/// point asked is a tie.
pub(crate) fn lower_on(
    a: &SourceDistance<f64>,
    b: &SourceDistance<f64>,
    [start, end]: [f64; 2],
    [lo, hi]: [f64; 2],
    relative_tie: f64,
) -> Lower {
    let clearness = |t: f64| {
        let (da, db) = (a.at(&t), b.at(&t));
        let tie = relative_tie * da.abs().max(db.abs());
        let lower = if da < db { Lower::First } else { Lower::Second };
        ((da - db).abs() / tie, lower)
    };
    let mid = clearness(0.5 * (start + end));
    if mid.0 > 1.0 {
        return mid.1;
    }
    let ends = [(start == lo).then_some(lo), (end == hi).then_some(hi)];
    let (clearest, lower) =
        ends.into_iter()
            .flatten()
            .map(clearness)
            .fold(
                (1.0, Lower::Neither),
                |best, c| if c.0 > best.0 { c } else { best },
            );
    if clearest > 1.0 {
        lower
    } else {
        Lower::Neither
    }
}

/// The roots of eq. (2) that solve eq. (1) strictly inside `(lo, hi)`, as
/// [`Scalar::bisector_roots`].
fn roots_in(
    a: &SourceDistance<f64>,
    b: &SourceDistance<f64>,
    lo: f64,
    hi: f64,
) -> BisectorRoots<f64> {
    if f64::same_distance_function(a, b, &(hi - lo)) {
        return BisectorRoots::Infinite;
    }
    let scale = (hi - lo)
        .max(a.y.abs())
        .max(b.y.abs())
        .max((a.x - lo).abs())
        .max((b.x - lo).abs());
    let f = |t: f64| a.at(&t) - b.at(&t);
    let solves_eq1 = |t: f64| f(t).abs() <= FloatTolerance::ROOT_RESIDUAL * a.at(&t).max(b.at(&t));
    let eq2 = Eq2Coefficients::new(a, b, &lo);
    let (candidates, count, double) = quadratic_roots(eq2.a, eq2.b, eq2.c, hi - lo);
    let mut roots = [0.0; 2];
    let mut found = 0;
    let mut touching = double;
    for &t in &candidates[..count] {
        let t = t + lo;
        if t <= lo || t >= hi || !solves_eq1(t) {
            continue;
        }
        if found > 0 && t - roots[found - 1] <= FloatTolerance::EXTENT * scale {
            // Two roots closer than the resolution: a touching point, or a crossing beside
            // a root of eq. (2) that eq. (1) only nearly solves; the ends tell below.
            touching = true;
            continue;
        }
        roots[found] = t;
        found += 1;
    }
    // Eq. (2) is ill-conditioned when the pseudo-sources nearly coincide; a sign change of
    // eq. (1) across the range proves a crossing, so find it directly if eq. (2) missed it.
    let (f_lo, f_hi) = (f(lo), f(hi));
    if found % 2 == 0 && f_lo * f_hi < 0.0 {
        roots[0] = bisect(f, lo, hi, f_lo);
        found = 1;
    }
    // A single root is a touching point only if eq. (1) keeps its sign across the range
    // (with equal sigmas, eq. (2) is the square of a line's equation: a double root that
    // crosses). Which wedge is lower on each piece is the engine's to ask.
    touching = touching && f_lo * f_hi > 0.0;
    match roots[..found] {
        [] => BisectorRoots::None,
        [r] if touching => BisectorRoots::Touch(r),
        [r] => BisectorRoots::One(r),
        [r, s] => BisectorRoots::Two(r, s),
        _ => unreachable!("a quadratic has at most two roots"),
    }
}

/// Whether two distance functions' pseudo-sources (`x`, `|y|`) and sigmas agree within `same`.
fn agree(a: &SourceDistance<f64>, b: &SourceDistance<f64>, same: f64) -> bool {
    (a.x - b.x).abs() <= same
        && (a.sigma - b.sigma).abs() <= same
        && (a.y.abs() - b.y.abs()).abs() <= same
}

/// Compares `a` and `b`, calling them equal when they differ by at most `relative` times the
/// larger magnitude.
#[inline(always)]
pub(crate) fn compare_with_tie(a: f64, b: f64, relative: f64) -> Ordering {
    let tie = relative * a.abs().max(b.abs());
    if a < b - tie {
        Ordering::Less
    } else if a > b + tie {
        Ordering::Greater
    } else {
        Ordering::Equal
    }
}

/// Real roots of `a t^2 + b t + c` in increasing order (the first `count` entries), computed
/// without cancellation, and whether the one root is a double root (a tangency); `width` is
/// the length of the range of interest, which tells when `a` (or `b`) is negligible.
fn quadratic_roots(a: f64, b: f64, c: f64, width: f64) -> ([f64; 2], usize, bool) {
    let linear_size = b.abs() * width + c.abs();
    if a.abs() * width * width <= f64::EPSILON * linear_size {
        if b == 0.0 || b.abs() * width <= f64::EPSILON * c.abs() {
            return ([0.0; 2], 0, false);
        }
        return ([-c / b, 0.0], 1, false);
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        // A tangency rounded to a negative discriminant still touches zero at the vertex.
        if disc >= -8.0 * f64::EPSILON * (b * b).max((4.0 * a * c).abs()) {
            return ([-b / (2.0 * a), 0.0], 1, true);
        }
        return ([0.0; 2], 0, false);
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    if q == 0.0 {
        return ([0.0; 2], 1, true);
    }
    let (r, s) = (q / a, c / q);
    ([r.min(s), r.max(s)], 2, false)
}

/// A root of `f` in `(lo, hi)`, given `f(lo) * f(hi) < 0`.
fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64, f_lo: f64) -> f64 {
    let lo_negative = f_lo < 0.0;
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if (f(mid) < 0.0) == lo_negative {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn src(x: f64, y: f64, sigma: f64) -> SourceDistance<f64> {
        SourceDistance { x, y, sigma }
    }

    proptest::proptest! {
        /// One square root gives the larger of the two ends' distances bit for bit.
        #[test]
        fn farthest_is_the_larger_end_distance_to_the_last_bit(
            x in -1e3f64..1e3, y in -1e3f64..1e3, sigma in 0f64..1e3,
            lo in -1e3f64..1e3, width in 0f64..1e3,
        ) {
            let d = src(x, y, sigma);
            let hi = lo + width;
            proptest::prop_assert_eq!(
                farthest(&d, lo, hi).to_bits(),
                d.at(&lo).max(d.at(&hi)).to_bits()
            );
        }
    }

    #[test]
    fn property1_symmetric_sources_have_infinitely_many_roots() {
        let r = f64::bisector_roots(&src(0.5, 1.0, 0.3), &src(0.5, -1.0, 0.3), &0.0, &1.0);
        assert_eq!(r, BisectorRoots::Infinite);
    }

    #[test]
    fn property1_one_root_is_the_perpendicular_bisector() {
        match f64::bisector_roots(&src(0.0, 1.0, 0.0), &src(1.0, 1.0, 0.0), &0.0, &1.0) {
            BisectorRoots::One(r) => assert!((r - 0.5).abs() < 1e-14),
            other => panic!("expected one root, got {other:?}"),
        }
    }

    #[test]
    fn property1_hyperbolic_bisector_root_solves_eq1() {
        let (a, b) = (src(0.1, 0.7, 0.4), src(0.9, 0.3, 0.2));
        match f64::bisector_roots(&a, &b, &0.0, &1.0) {
            BisectorRoots::One(r) => assert!((a.at(&r) - b.at(&r)).abs() < 1e-12),
            other => panic!("expected one root, got {other:?}"),
        }
    }

    #[test]
    fn property1_two_roots_from_opposite_sides() {
        // A near pseudo-source with a large sigma beats a far one only near its foot.
        let (a, b) = (src(0.5, 0.05, 1.5), src(0.5, -2.0, 0.0));
        match f64::bisector_roots(&a, &b, &-1.0, &2.0) {
            BisectorRoots::Two(r, s) => {
                assert!(r < 0.5 && s > 0.5);
                assert!((a.at(&r) - b.at(&r)).abs() < 1e-12);
                assert!((a.at(&s) - b.at(&s)).abs() < 1e-12);
            }
            other => panic!("expected two roots, got {other:?}"),
        }
    }

    #[test]
    fn property1_parallel_offset_has_no_root() {
        // Example 2's configuration: P - P' parallel to the edge and sigma = |P - P'|.
        let (a, b) = (src(0.2, 0.5, 0.0), src(-0.3, 0.5, 0.5));
        let eq2 = Eq2Coefficients::new(&a, &b, &0.0);
        assert!(eq2.a.abs() < 1e-15 && eq2.b.abs() < 1e-15 && eq2.c.abs() > 1e-3);
        assert_eq!(f64::bisector_roots(&a, &b, &0.5, &1.0), BisectorRoots::None);
    }

    #[test]
    fn a_range_fans_out_only_when_wider_than_its_distance_from_the_source() {
        // 4e-6 wide, the source 1e-7 off its middle: rays spread over most of a half-turn.
        assert!(fans_out(0.499994, 0.499998, 0.499996, 1e-7));
        // The same width 4000 away: numerically parallel at an edge's resolution.
        assert!(!fans_out(0.499994, 0.499998, 0.499996, 4000.0));
        assert!(!fans_out(0.499994, 0.499998, -4000.0, 0.0));
        // Empty or reversed ranges never, wherever the source.
        assert!(!fans_out(1.0, 1.0, 1.0, 0.0));
        assert!(!fans_out(1.0, 0.5, 0.75, 0.0));
    }

    #[test]
    fn distance_ties_are_relative() {
        assert_eq!(1.0f64.compare_distance(&(1.0 + 1e-15)), Ordering::Equal);
        assert_eq!(1.0f64.compare_distance(&1.001), Ordering::Less);
        assert_eq!(1e6f64.compare_distance(&(1e6 + 1e-9)), Ordering::Equal);
    }
}
