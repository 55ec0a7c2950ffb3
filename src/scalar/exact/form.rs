//! The values of the tower of quadratic extensions (`normal_form.rs`): an element in normal
//! form and its monomials, what computing one may cost, and the memo a node keeps of its form.
//! Apart from the arithmetic, so that a node (`node.rs`) holds its memo without importing what
//! computes it from nodes.

use super::super::bignum::Rational;
use std::collections::BTreeMap;

/// A product of symbols, in increasing order: square roots at most once each (their squares
/// are rewritten), atoms as often as their power.
pub(super) type Monomial = Vec<u32>;

/// An element of the tower in normal form.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub(crate) struct NormalForm(pub(super) BTreeMap<Monomial, Rational>);

/// What a normal form may cost before it is abandoned (and the zero left to the separation
/// bound): the forms asked of every sign that a filter leaves open are cheap; the last resort
/// of a zero that nothing else could prove may cost more.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Budget {
    Cheap,
    LastResort,
}

impl Budget {
    /// Normal forms with more terms than this are abandoned.
    pub(super) fn terms(self) -> usize {
        match self {
            Budget::Cheap => 256,
            Budget::LastResort => 4096,
        }
    }

    /// Products needing more term-by-term multiplications than this are abandoned.
    pub(super) fn product_work(self) -> usize {
        match self {
            Budget::Cheap => 2048,
            Budget::LastResort => 65_536,
        }
    }

    /// Term-by-term multiplications one zero test may spend, over all the nodes it
    /// normalises.
    pub(super) fn work_per_test(self) -> usize {
        match self {
            Budget::Cheap => 50_000,
            Budget::LastResort => 5_000_000,
        }
    }
}

/// A node's normal form in the tower of id `tower`, `None` where it could not be had within
/// `budget` (asked again under a larger one).
pub(crate) struct Memo {
    pub(super) tower: u64,
    pub(super) form: Option<NormalForm>,
    pub(super) budget: Budget,
}
