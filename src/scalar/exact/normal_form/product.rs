//! The product of two normal forms, each of its terms summed over integers.
//!
//! A product of rationals, and a sum, each reduce their result by a gcd, and on large forms
//! those gcds were most of the cost of a normal form (more than half of the exact degeneracy
//! corpus's time went to GMP's gcd): squaring a form of `n` terms adds `n^2` products into far
//! fewer terms. So the products that fall on one monomial are summed as integers over their
//! common denominator and reduced once; a monomial reached by one product alone is that
//! product of rationals. Pairs of monomials that share a square root whose square is not an
//! integer (a nested radical) are multiplied out through that square, as before.

use super::{budget, is_atom, square_of, Monomial, NormalForm, WORK_LEFT};
use crate::scalar::bignum::{Integer, Rational};
use std::collections::{BTreeMap, BTreeSet};

/// One product of a term of each factor: their coefficients and the integer squares of the
/// roots they share.
type Product<'a> = (&'a Rational, &'a Rational, Vec<&'a Integer>);

impl NormalForm {
    pub(super) fn mul(&self, other: &NormalForm) -> Option<NormalForm> {
        let work = self.0.len() * other.0.len();
        if work > budget().product_work()
            || WORK_LEFT.with(|w| w.replace(w.get().saturating_sub(work))) < work
        {
            return None;
        }
        let squares = shared_integer_squares(self, other);
        let mut by_monomial: BTreeMap<Monomial, Vec<Product>> = BTreeMap::new();
        let mut rest = NormalForm::default();
        for (m1, c1) in &self.0 {
            for (m2, c2) in &other.0 {
                let (product, common) = merged(m1, m2);
                let integer_squares: Option<Vec<&Integer>> =
                    common.iter().map(|s| squares[s].as_ref()).collect();
                match integer_squares {
                    Some(q) => by_monomial.entry(product).or_default().push((c1, c2, q)),
                    None => {
                        let mut term = NormalForm::monomial(c1.clone() * c2, product);
                        for s in common {
                            term = term.mul(&square_of(s)?)?;
                        }
                        rest.accumulate(&term, 1);
                    }
                }
            }
        }
        for (m, products) in by_monomial {
            rest.accumulate(&NormalForm::monomial(sum(&products), m), 1);
        }
        rest.checked()
    }
}

/// The sum of the products: one product in rationals, several over their common
/// denominator, reduced once.
fn sum(products: &[Product]) -> Rational {
    let times_squares = |c: Integer, q: &[&Integer]| q.iter().fold(c, |c, q| c.times(q));
    if let [(c1, c2, q)] = products {
        let product = (*c1).clone() * *c2;
        return if q.is_empty() {
            product
        } else {
            product * Rational::from(times_squares(Integer::from(1), q))
        };
    }
    let (mut numerator, mut denominator) = (Integer::from(0), Integer::from(1));
    for (c1, c2, q) in products {
        let n = times_squares(c1.numer().times(&c2.numer()), q);
        let d = c1.denom().times(&c2.denom());
        if d == denominator {
            numerator = numerator.plus(&n);
        } else if denominator.is_divisible(&d) {
            numerator = numerator.plus(&n.times(&denominator.div_exact(&d)));
        } else {
            let g = denominator.gcd(&d);
            let (widen, scale) = (d.div_exact(&g), denominator.div_exact(&g));
            numerator = numerator.times(&widen).plus(&n.times(&scale));
            denominator = denominator.times(&widen);
        }
    }
    Rational::ratio(numerator, denominator)
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
