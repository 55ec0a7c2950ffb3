//! proptest strategies shared by the test binaries.

use exact_geodesics::degeneracy::DegenerateKind;
use proptest::prelude::*;

/// A case of the degenerate-mesh corpus: any kind, any seed.
pub fn degenerate_case() -> impl Strategy<Value = (DegenerateKind, u64)> {
    (
        proptest::sample::select(&DegenerateKind::ALL[..]),
        any::<u64>(),
    )
}
