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

    pub(crate) fn coefficients(&self) -> Eq2Coefficients<S> {
        let two = S::from_f64(2.0);
        Eq2Coefficients {
            a: self.alpha.clone() * &self.alpha - &self.beta2,
            b: two * &self.x2 * &self.beta2 + self.alpha.clone() * &self.gamma,
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
