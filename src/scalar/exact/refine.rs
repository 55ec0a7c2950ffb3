//! The exact stage: multiple-precision interval evaluation of the DAG (binary floats with
//! directed rounding, from `scalar::bignum`), exact rational evaluation of DAGs without square
//! roots, and the BFMSS separation bound that turns a small enough enclosure into a proof of
//! zero.

use super::super::bignum::{Float, Rational, Round};
use super::node::{Enclosure, Node, Op};
use std::cmp::Ordering;
use std::collections::{HashMap, HashSet};
use std::sync::Arc;

fn entire() -> (Float, Float) {
    (Float::infinite(true), Float::infinite(false))
}

/// The smallest and the largest of four bounds (each computed in both directions); the whole
/// line if one is NaN (`0 * inf`).
fn min_max(candidates: [(Float, Float); 4]) -> (Float, Float) {
    if candidates.iter().any(|(l, h)| l.is_nan() || h.is_nan()) {
        return entire();
    }
    let mut lo = candidates[0].0.clone();
    let mut hi = candidates[0].1.clone();
    for (l, h) in candidates.into_iter().skip(1) {
        if l < lo {
            lo = l;
        }
        if h > hi {
            hi = h;
        }
    }
    (lo, hi)
}

/// The four products (or quotients) of two intervals' bounds by `op`, each rounded down and up.
fn corners(
    op: fn(&Float, &Float, u32, Round) -> Float,
    prec: u32,
    (al, ah): &(Float, Float),
    (bl, bh): &(Float, Float),
) -> [(Float, Float); 4] {
    let both = |x: &Float, y: &Float| (op(x, y, prec, Round::Down), op(x, y, prec, Round::Up));
    [both(al, bl), both(al, bh), both(ah, bl), both(ah, bh)]
}

/// An enclosure `[lo, hi]` of the node's value, evaluated with `prec`-bit floats rounded
/// outwards at every operation, and cached on the node.
pub(crate) fn enclosure(node: &Node, prec: u32) -> (Float, Float) {
    if let Some(e) = node.cache.lock().expect("cache lock").as_ref() {
        if e.precision >= prec {
            return (e.lo.clone(), e.hi.clone());
        }
    }
    let (lo, hi) = match &node.op {
        Op::Leaf(r) => (
            Float::from_rational(r, prec, Round::Down),
            Float::from_rational(r, prec, Round::Up),
        ),
        Op::Add(a, b) => {
            let ((al, ah), (bl, bh)) = (enclosure(a, prec), enclosure(b, prec));
            (
                Float::add(&al, &bl, prec, Round::Down),
                Float::add(&ah, &bh, prec, Round::Up),
            )
        }
        Op::Sub(a, b) => {
            let ((al, ah), (bl, bh)) = (enclosure(a, prec), enclosure(b, prec));
            (
                Float::sub(&al, &bh, prec, Round::Down),
                Float::sub(&ah, &bl, prec, Round::Up),
            )
        }
        Op::Mul(a, b) => min_max(corners(
            Float::mul,
            prec,
            &enclosure(a, prec),
            &enclosure(b, prec),
        )),
        Op::Div(a, b) => {
            let (x, y) = (enclosure(a, prec), enclosure(b, prec));
            if y.0.cmp0() != Some(Ordering::Greater) && y.1.cmp0() != Some(Ordering::Less) {
                entire()
            } else {
                min_max(corners(Float::div, prec, &x, &y))
            }
        }
        Op::Neg(a) => {
            let (al, ah) = enclosure(a, prec);
            (ah.negated(), al.negated())
        }
        Op::Sqrt(a) => {
            let (mut al, mut ah) = enclosure(a, prec);
            if al.cmp0() != Some(Ordering::Greater) {
                al = Float::zero(prec);
            }
            if ah.cmp0() != Some(Ordering::Greater) {
                ah = Float::zero(prec);
            }
            (al.sqrt(prec, Round::Down), ah.sqrt(prec, Round::Up))
        }
        Op::Dropped => unreachable!("a live node keeps its children"),
    };
    *node.cache.lock().expect("cache lock") = Some(Enclosure {
        precision: prec,
        lo: lo.clone(),
        hi: hi.clone(),
    });
    (lo, hi)
}

/// The exact value of a DAG without square roots.
///
/// # Panics
/// If a divisor is zero; [`Real::certified_sign`](super::Real::certified_sign) certifies every
/// divisor non-zero first.
pub(crate) fn rational_value(root: &Arc<Node>) -> Rational {
    fn eval(node: &Arc<Node>, memo: &mut HashMap<*const Node, Rational>) -> Rational {
        if let Some(r) = memo.get(&Arc::as_ptr(node)) {
            return r.clone();
        }
        let value = match &node.op {
            Op::Leaf(r) => r.clone(),
            Op::Add(a, b) => eval(a, memo) + eval(b, memo),
            Op::Sub(a, b) => eval(a, memo) - eval(b, memo),
            Op::Mul(a, b) => eval(a, memo) * eval(b, memo),
            Op::Div(a, b) => {
                let d = eval(b, memo);
                assert!(
                    !d.is_zero(),
                    "divisors are certified non-zero before evaluation"
                );
                eval(a, memo) / &d
            }
            Op::Neg(a) => -eval(a, memo),
            Op::Sqrt(_) | Op::Dropped => unreachable!("only called on DAGs without square roots"),
        };
        memo.insert(Arc::as_ptr(node), value.clone());
        value
    }
    eval(root, &mut HashMap::new())
}

/// The number of distinct square-root nodes in the DAG, counting up to `limit`.
fn sqrt_count(root: &Arc<Node>, limit: usize) -> usize {
    let mut seen: HashSet<*const Node> = HashSet::new();
    let mut stack = vec![root];
    let mut count = 0;
    while let Some(node) = stack.pop() {
        if !seen.insert(Arc::as_ptr(node)) || !node.has_sqrt {
            continue;
        }
        if matches!(node.op, Op::Sqrt(_)) {
            count += 1;
            if count >= limit {
                return count;
            }
        }
        stack.extend(node.children());
    }
    count
}

/// The BFMSS separation bound \[BFMSS01\] in bits: if the value `E` of the DAG is not zero then
/// `|E| >= 2^-bits`, with `bits = (D - 1) log2 u(E) + log2 l(E)` and `D = 2^k` for `k`
/// distinct square roots. `None` when the bound exceeds `cap` (it could not be reached).
pub(crate) fn zero_bound_bits(root: &Arc<Node>, cap: u32) -> Option<u32> {
    let k = sqrt_count(root, 40);
    let degree = 2f64.powi(k as i32);
    let bits = (degree - 1.0) * root.log_u.max(0.0) + root.log_l.max(0.0) + 2.0;
    (bits.is_finite() && bits < f64::from(cap)).then(|| bits.ceil() as u32)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn leaf(i: i64) -> Arc<Node> {
        Node::leaf(Rational::from(i))
    }

    #[test]
    fn a_quotient_by_an_enclosure_of_zero_is_entire() {
        let by_zero = Node::div(leaf(1), leaf(0));
        let root2 = Node::sqrt(leaf(2));
        let hidden_zero = Node::sub(Node::mul(root2.clone(), root2), leaf(2));
        let by_hidden_zero = Node::div(leaf(1), hidden_zero);
        for node in [by_zero, by_hidden_zero] {
            for precision in [128, 1024] {
                assert_eq!(enclosure(&node, precision), entire());
            }
        }
    }
}
