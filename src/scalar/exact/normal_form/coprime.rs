//! A unique normal form for sums of products of integer radicals, over a coprime basis.
//!
//! The tower keeps one symbol per square class of integer radicands, so `sqrt 6` and
//! `sqrt 2 sqrt 3` are two monomials of one value: the symbols are not independent, and a
//! form that is zero may not look it. Mirror twins built through other faces are such zeros:
//! their squared lengths share large factors, which no small prime shows. Written over a
//! *coprime basis* of the radicands (pairwise coprime integers, none a square, of which every
//! radicand is a product of powers), the products of distinct basis roots are linearly
//! independent over the rationals: two such products differ in the square-free part of their
//! squares, since a product of coprime non-squares is never a square. The form there is
//! zero exactly when every coefficient is, in both directions.

use super::{square_of, NormalForm};
use crate::scalar::bignum::{Integer, Rational};
use std::collections::btree_map::Entry;
use std::collections::{BTreeMap, BTreeSet};

impl NormalForm {
    /// Whether the form is zero, decided exactly where each of its symbols is the square root
    /// of a positive integer; `None` where one is not (an atom, or a root of a radical).
    pub(super) fn is_zero_over_coprime_radicals(&self) -> Option<bool> {
        let mut radicands = BTreeMap::new();
        for &symbol in self.0.keys().flatten() {
            if let Entry::Vacant(entry) = radicands.entry(symbol) {
                let square = square_of(symbol)?.as_rational()?;
                if !square.denom().is_one() || square.cmp0().is_le() {
                    return None;
                }
                entry.insert(square.numer());
            }
        }
        let basis = coprime_basis(radicands.values().cloned().collect());
        let mut roots = BTreeMap::new();
        for (symbol, radicand) in radicands {
            roots.insert(symbol, over_basis(radicand, &basis)?);
        }
        let mut canonical: BTreeMap<Vec<usize>, Rational> = BTreeMap::new();
        for (monomial, coefficient) in &self.0 {
            let mut factor = Integer::from(1);
            let mut odd = BTreeSet::new();
            for symbol in monomial {
                let (outside, inside) = &roots[symbol];
                factor = factor * outside.clone();
                for &i in inside {
                    // sqrt(c) sqrt(c) = c.
                    if !odd.insert(i) {
                        odd.remove(&i);
                        factor = factor * basis[i].clone();
                    }
                }
            }
            let term = coefficient.clone() * Rational::from(factor);
            let sum = canonical.entry(odd.into_iter().collect()).or_default();
            *sum += &term;
        }
        Some(canonical.values().all(Rational::is_zero))
    }
}

/// Pairwise coprime integers above 1, none a square, of which every one of `numbers`
/// (positive) is a product of powers: two numbers with a common factor `g` are replaced by
/// `g` and their quotients by it, which lowers the product of all, until none has one.
fn coprime_basis(mut todo: Vec<Integer>) -> Vec<Integer> {
    let mut basis: Vec<Integer> = Vec::new();
    while let Some(n) = todo.pop() {
        if n.is_one() {
            continue;
        }
        let common = basis.iter().enumerate().find_map(|(i, b)| {
            let g = b.gcd(&n);
            (!g.is_one()).then_some((i, g))
        });
        match common {
            Some((i, g)) => {
                let b = basis.swap_remove(i);
                todo.extend([b.div_exact(&g), n.div_exact(&g), g]);
            }
            None => {
                let mut root = n;
                while root.is_perfect_square() {
                    root = root.sqrt();
                }
                if !root.is_one() {
                    basis.push(root);
                }
            }
        }
    }
    basis
}

/// `sqrt(m) = outside * prod sqrt(basis[i])` over the indices `inside`; `None` if `m` is not a
/// product of powers of the basis.
fn over_basis(mut m: Integer, basis: &[Integer]) -> Option<(Integer, Vec<usize>)> {
    let mut outside = Integer::from(1);
    let mut inside = Vec::new();
    for (i, c) in basis.iter().enumerate() {
        let mut power = 0u32;
        while m.is_divisible(c) {
            m = m.div_exact(c);
            power += 1;
        }
        outside = outside * c.pow(power / 2);
        if power % 2 == 1 {
            inside.push(i);
        }
    }
    m.is_one().then_some((outside, inside))
}

#[cfg(test)]
mod tests {
    use super::super::super::{Field, Real};
    use super::super::{new_tower, normal_form};
    use super::*;

    fn int(i: i64) -> Integer {
        Integer::from(i)
    }

    /// `sqrt(p q) - sqrt(p) sqrt(q) + tiny` for primes `p`, `q` beyond the tower's small ones:
    /// three symbols, of three square classes.
    fn product_of_roots(tiny: Rational) -> NormalForm {
        new_tower();
        let root = |i: i64| Real::from_integer(i).sqrt();
        let (p, q) = (1_000_003, 999_983);
        let value = root(p * q) - &(root(p) * &root(q)) + &Real::from_rational(tiny);
        let form = normal_form(&value.0).expect("a normal form");
        assert!(!form.is_zero());
        form
    }

    #[test]
    fn a_root_of_a_product_is_the_product_of_the_roots() {
        let zero = product_of_roots(Rational::from(0));
        assert_eq!(zero.is_zero_over_coprime_radicals(), Some(true));
        let tiny = Rational::new(int(1), int(2).pow(200)).expect("a rational");
        assert_eq!(
            product_of_roots(tiny).is_zero_over_coprime_radicals(),
            Some(false)
        );
    }

    #[test]
    fn the_basis_is_coprime_and_generates_every_number() {
        // 2^2 * 3 * 7^3, 3 * 5 * 7, 49 * 11^2 * 13 and a square: 36.
        let numbers = [1372, 105, 76_153, 36].map(int);
        let basis = coprime_basis(numbers.to_vec());
        for (i, a) in basis.iter().enumerate() {
            assert!(!a.is_one() && !a.is_perfect_square(), "{a}");
            for b in &basis[i + 1..] {
                assert!(a.gcd(b).is_one(), "{a} and {b}");
            }
        }
        for n in numbers {
            let (outside, inside) = over_basis(n.clone(), &basis).expect("a product of the basis");
            let mut square = outside.clone() * outside;
            for i in inside {
                square = square * basis[i].clone();
            }
            assert_eq!(square, n);
        }
    }
}
