//! The three number types by name, for code that picks one at run time (the corpus, the
//! experiments of [LZT §6]); the engine itself only ever sees a type parameter `S: Scalar`.

use serde::Serialize;

/// A backend by name: `f64`, [`Adaptive`](super::Adaptive) or [`Real`](super::Real) (exact).
///
/// # Example
/// ```
/// use exact_geodesics::scalar::Backend;
/// assert_eq!(Backend::Adaptive.name(), "adaptive");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Backend {
    /// Hardware floating point with its one tolerance policy.
    F64,
    /// f64 values, every predicate decided exactly for them.
    Adaptive,
    /// Exact reals with certified signs.
    Exact,
}

impl Backend {
    /// The backend's name as it appears in reports and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Backend::F64 => "f64",
            Backend::Adaptive => "adaptive",
            Backend::Exact => "exact",
        }
    }
}
