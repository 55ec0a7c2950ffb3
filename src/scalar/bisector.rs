//! The bisector of two wedges on an edge: eq. (1) and its quadratic form eq. (2) [LZT §2].

use super::{Field, Ring};

/// The distance function of a wedge along its edge: `D(t) = sigma + sqrt((t - x)^2 + y^2)`,
/// where `(x, y)` is the unfolded pseudo-source in the edge's frame and `sigma` its distance to
/// the source [LZT Definition 1]. The side of the edge (tau) does not enter: `y` appears squared.
#[derive(Clone, Debug, PartialEq)]
pub struct SourceDistance<S> {
    /// Pseudo-source position along the edge.
    pub x: S,
    /// Pseudo-source distance from the edge's line.
    pub y: S,
    /// Geodesic distance from the pseudo-source back to the source.
    pub sigma: S,
}

impl<S: Field> SourceDistance<S> {
    /// `D(t)`: the geodesic distance through this pseudo-source to the point `t` of the edge.
    #[inline]
    pub fn at(&self, t: &S) -> S {
        let dx = t.clone() - &self.x;
        (dx.clone() * dx + self.y.clone() * &self.y).sqrt() + &self.sigma
    }
}

/// The coefficients of eq. (2), `A t^2 + B t + C = 0`, for wedges `w1`, `w2` with
/// `alpha = x2 - x1`, `beta = sigma2 - sigma1`, `gamma = |s1|^2 - |s2|^2 - beta^2` [LZT §2].
/// Example 1's symmetric wedges give `A = B = C = 0`; Example 2 gives `A = B = 0 != C`.
#[derive(Clone, Debug, PartialEq)]
pub struct Eq2Coefficients<S> {
    /// Coefficient of `t^2`: `alpha^2 - beta^2`.
    pub a: S,
    /// Coefficient of `t`: `2 x2 beta^2 + alpha gamma`.
    pub b: S,
    /// Constant term: `gamma^2 / 4 - |s2|^2 beta^2`.
    pub c: S,
}

impl<S: Ring> Eq2Coefficients<S> {
    /// Eq. (2) for two wedges, with positions measured from `origin` on the edge (the engine
    /// passes the left end of the shared range, which keeps the f64 coefficients small).
    pub fn new(w1: &SourceDistance<S>, w2: &SourceDistance<S>, origin: &S) -> Self {
        Eq2Terms::new(w1, w2, origin).coefficients()
    }
}

/// The terms eq. (2) is built from, with positions measured from an origin on the edge.
pub(crate) struct Eq2Terms<S> {
    /// `x2` from the origin.
    pub(crate) x2: S,
    /// `alpha = x2 - x1`.
    pub(crate) alpha: S,
    /// `beta = sigma2 - sigma1`.
    pub(crate) beta: S,
    /// `beta^2`.
    pub(crate) beta2: S,
    /// `|s2|^2` from the origin.
    pub(crate) n2: S,
    /// `gamma = |s1|^2 - |s2|^2 - beta^2`.
    pub(crate) gamma: S,
}

impl<S: Ring> Eq2Terms<S> {
    pub(crate) fn new(w1: &SourceDistance<S>, w2: &SourceDistance<S>, origin: &S) -> Self {
        let x1 = w1.x.clone() - origin;
        let x2 = w2.x.clone() - origin;
        // From the inputs rather than from x1, x2: one rounding fewer for f64 filters.
        let alpha = w2.x.clone() - &w1.x;
        let beta = w2.sigma.clone() - &w1.sigma;
        let beta2 = beta.clone() * &beta;
        let n1 = x1.clone() * &x1 + w1.y.clone() * &w1.y;
        let n2 = x2.clone() * &x2 + w2.y.clone() * &w2.y;
        let gamma = n1 - &n2 - &beta2;
        Eq2Terms {
            x2,
            alpha,
            beta,
            beta2,
            n2,
            gamma,
        }
    }

    /// `C`, the value of eq. (2)'s `P` at the origin.
    pub(crate) fn constant(&self) -> S {
        S::from_f64(0.25) * &self.gamma * &self.gamma - self.n2.clone() * &self.beta2
    }

    /// `A = alpha^2 - beta^2`.
    pub(crate) fn quadratic(&self) -> S {
        self.alpha.clone() * &self.alpha - &self.beta2
    }

    /// `B = 2 x2 beta^2 + alpha gamma`.
    pub(crate) fn linear(&self) -> S {
        S::from_f64(2.0) * &self.x2 * &self.beta2 + self.alpha.clone() * &self.gamma
    }

    pub(crate) fn coefficients(&self) -> Eq2Coefficients<S> {
        Eq2Coefficients {
            a: self.quadratic(),
            b: self.linear(),
            c: self.constant(),
        }
    }
}

/// The solutions of eq. (1) strictly inside a shared range, classified as in Property 1 [LZT §3].
#[derive(Clone, Debug, PartialEq)]
pub enum BisectorRoots<S> {
    /// The wedges do not meet inside the range (Example 2, or one wedge better throughout).
    None,
    /// One crossing point: the lower wedge changes there.
    One(S),
    /// One point where the distance functions touch without crossing (a double root of
    /// eq. (2): one pseudo-source seen straight from the other, at the distance the other
    /// gives it); the same wedge is lower on both sides.
    Touch(S),
    /// Two crossing points, in increasing order; the pseudo-sources then lie on different
    /// sides of the edge (Property 1).
    Two(S, S),
    /// The distance functions coincide on the range (Example 1: `A = B = C = 0`).
    Infinite,
}

impl<S> BisectorRoots<S> {
    /// The same case with every root mapped by `f`.
    pub fn map<T>(self, f: impl Fn(S) -> T) -> BisectorRoots<T> {
        match self {
            BisectorRoots::None => BisectorRoots::None,
            BisectorRoots::One(r) => BisectorRoots::One(f(r)),
            BisectorRoots::Touch(r) => BisectorRoots::Touch(f(r)),
            BisectorRoots::Two(r, s) => BisectorRoots::Two(f(r), f(s)),
            BisectorRoots::Infinite => BisectorRoots::Infinite,
        }
    }

    /// Which of the four cases of Property 1 this is.
    pub fn case(&self) -> Eq2Case {
        match self {
            BisectorRoots::None => Eq2Case::None,
            BisectorRoots::One(_) | BisectorRoots::Touch(_) => Eq2Case::One,
            BisectorRoots::Two(..) => Eq2Case::Two,
            BisectorRoots::Infinite => Eq2Case::Infinite,
        }
    }
}

/// Which of two distance functions is lower on a stretch of their shared range.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Lower {
    /// The first function (the wedge already on the edge, in the engine).
    First,
    /// The second function (the arriving wedge).
    Second,
    /// Neither: they are equal there, or the backend cannot tell them apart.
    Neither,
}

impl Lower {
    /// Which function is lower where `first - second` has sign `sign`.
    pub fn of_difference(sign: super::Sign) -> Lower {
        match sign {
            super::Sign::Negative => Lower::First,
            super::Sign::Zero => Lower::Neither,
            super::Sign::Positive => Lower::Second,
        }
    }

    /// The other function: the lower one beyond a crossing.
    pub fn flipped(self) -> Lower {
        match self {
            Lower::First => Lower::Second,
            Lower::Second => Lower::First,
            Lower::Neither => Lower::Neither,
        }
    }
}

/// The meeting of two wedges on their shared range [LZT §2-§4]: the solutions of eq. (1)
/// inside it ([`BisectorRoots`]) and which wedge is lower on each stretch between them, both
/// from one decision of the backend.
#[derive(Clone, Debug, PartialEq)]
pub struct Bisector<S> {
    /// The solutions of eq. (1) strictly inside the range.
    pub roots: BisectorRoots<S>,
    /// Which function is lower on each stretch the roots cut the range into, from its start:
    /// one entry per stretch (one for `None` and `Infinite`, two for `One` and `Touch`, three
    /// for `Two`), the others `Neither`.
    pub lower: [Lower; 3],
}

impl<S> Bisector<S> {
    /// Roots and owners from the lower function on the first stretch: it changes at every
    /// crossing and not at a touching root (the certified backends, whose roots are exact in
    /// their sign structure).
    pub fn alternating(roots: BisectorRoots<S>, first: Lower) -> Self {
        let lower = match roots {
            BisectorRoots::One(_) => [first, first.flipped(), Lower::Neither],
            BisectorRoots::Touch(_) => [first, first, Lower::Neither],
            BisectorRoots::Two(..) => [first, first.flipped(), first],
            BisectorRoots::Infinite => [Lower::Neither; 3],
            BisectorRoots::None => [first, Lower::Neither, Lower::Neither],
        };
        Bisector { roots, lower }
    }

    /// The stretches: each one's end (a root, or `None` for the range's end) and which function
    /// is lower on it.
    pub fn stretches(self) -> impl Iterator<Item = (Option<S>, Lower)> {
        let lower = self.lower;
        let ends: [Option<S>; 2] = match self.roots {
            BisectorRoots::One(r) | BisectorRoots::Touch(r) => [Some(r), None],
            BisectorRoots::Two(r, s) => [Some(r), Some(s)],
            BisectorRoots::None | BisectorRoots::Infinite => [None, None],
        };
        let count = ends.iter().flatten().count();
        ends.into_iter()
            .flatten()
            .map(Some)
            .chain(std::iter::once(None))
            .zip(lower)
            .take(count + 1)
    }
}

/// The number of solutions of eq. (2) in a shared range, without the solutions themselves.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Eq2Case {
    /// No solution.
    None,
    /// One solution.
    One,
    /// Two solutions.
    Two,
    /// Infinitely many solutions.
    Infinite,
}
