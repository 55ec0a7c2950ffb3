//! The product of two normal forms, summed over integers.
//!
//! A product of rationals, and a sum, each reduce their result by a gcd, and on large forms
//! those gcds were most of the cost of a normal form (more than half of the exact degeneracy
//! corpus's time went to GMP's gcd). So both factors are put over a common denominator, the
//! products of their coefficients are summed as integers, and each term of the result is
//! reduced once. Pairs of monomials that share a square root whose square is not an integer
//! (a nested radical) are multiplied out in rationals, as before.

use super::{is_atom, square_of, Monomial, NormalForm, MAX_PRODUCT_WORK, MAX_TERMS, WORK_LEFT};
use crate::scalar::bignum::{Integer, Rational};
use std::collections::btree_map::Entry;
use std::collections::{BTreeMap, BTreeSet};

impl NormalForm {
    pub(super) fn mul(&self, other: &NormalForm) -> Option<NormalForm> {
        let work = self.0.len() * other.0.len();
        if work > MAX_PRODUCT_WORK
            || WORK_LEFT.with(|w| w.replace(w.get().saturating_sub(work))) < work
        {
            return None;
        }
        let (left, l) = self.over_common_denominator();
        let (right, r) = other.over_common_denominator();
        let denominator = l.times(&r);
        let squares = shared_integer_squares(self, other);
        let mut integral: BTreeMap<Monomial, Integer> = BTreeMap::new();
        let mut rest = NormalForm::default();
        for (m1, a) in &left {
            for (m2, b) in &right {
                let (product, common) = merged(m1, m2);
                let integral_squares: Option<Vec<&Integer>> =
                    common.iter().map(|s| squares[s].as_ref()).collect();
                match integral_squares {
                    Some(squares) => {
                        let c = squares.into_iter().fold(a.times(b), |c, q| c.times(q));
                        match integral.entry(product) {
                            Entry::Vacant(entry) => {
                                entry.insert(c);
                            }
                            Entry::Occupied(mut entry) => {
                                let sum = entry.get().plus(&c);
                                if sum.is_zero() {
                                    entry.remove();
                                } else {
                                    *entry.get_mut() = sum;
                                }
                            }
                        }
                    }
                    None => {
                        let c = Rational::ratio(a.times(b), denominator.clone());
                        let mut term = NormalForm::monomial(c, product);
                        for s in common {
                            term = term.mul(&square_of(s)?)?;
                        }
                        rest.accumulate(&term, 1);
                    }
                }
                if integral.len() + rest.0.len() > MAX_TERMS {
                    return None;
                }
            }
        }
        for (m, n) in integral {
            let term = NormalForm::monomial(Rational::ratio(n, denominator.clone()), m);
            rest.accumulate(&term, 1);
        }
        rest.checked()
    }

    /// The coefficients as integers over one common denominator, with that denominator.
    fn over_common_denominator(&self) -> (Vec<(&Monomial, Integer)>, Integer) {
        let mut common = Integer::from(1);
        for c in self.0.values() {
            let d = c.denom();
            if !common.is_divisible(&d) {
                common = common.times(&d.div_exact(&common.gcd(&d)));
            }
        }
        let scaled = self
            .0
            .iter()
            .map(|(m, c)| (m, c.numer().times(&common.div_exact(&c.denom()))))
            .collect();
        (scaled, common)
    }
}

/// The product of two monomials, without the square roots they share, and those roots (whose
/// squares multiply the product). Atoms have no square: they stay, twice.
fn merged(m1: &Monomial, m2: &Monomial) -> (Monomial, Vec<u32>) {
    let (mut product, mut common) = (Vec::new(), Vec::new());
    let (mut i, mut j) = (0, 0);
    while i < m1.len() || j < m2.len() {
        match (m1.get(i), m2.get(j)) {
            (Some(a), Some(b)) if a == b => {
                if is_atom(*a) {
                    product.extend([*a, *b]);
                } else {
                    common.push(*a);
                }
                i += 1;
                j += 1;
            }
            (Some(a), Some(b)) if a < b => {
                product.push(*a);
                i += 1;
            }
            (Some(a), None) => {
                product.push(*a);
                i += 1;
            }
            (_, Some(b)) => {
                product.push(*b);
                j += 1;
            }
            (None, None) => unreachable!("loop condition"),
        }
    }
    (product, common)
}

/// The square roots in both forms, each with its square if that is an integer.
fn shared_integer_squares(f: &NormalForm, g: &NormalForm) -> BTreeMap<u32, Option<Integer>> {
    let symbols =
        |form: &NormalForm| -> BTreeSet<u32> { form.0.keys().flatten().copied().collect() };
    let integer_square = |s: u32| {
        let square = square_of(s)?.as_rational()?;
        square.denom().is_one().then(|| square.numer())
    };
    symbols(f)
        .intersection(&symbols(g))
        .filter(|&&s| !is_atom(s))
        .map(|&s| (s, integer_square(s)))
        .collect()
}
