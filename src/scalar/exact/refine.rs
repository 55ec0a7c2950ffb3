//! The exact stage: multiple-precision interval evaluation of the DAG (MPFR with directed
//! rounding), exact rational evaluation of DAGs without square roots, and the BFMSS separation
//! bound that turns a small enough enclosure into a proof of zero.

use super::node::{Enclosure, Node, Op};
use rug::float::Round;
use rug::ops::AssignRound;
use rug::{Float, Rational};
use std::cmp::Ordering;
use std::collections::{HashMap, HashSet};
use std::sync::Arc;

fn down<T>(prec: u32, v: T) -> Float
where
    Float: AssignRound<T, Round = Round, Ordering = Ordering>,
{
    Float::with_val_round(prec, v, Round::Down).0
}

fn up<T>(prec: u32, v: T) -> Float
where
    Float: AssignRound<T, Round = Round, Ordering = Ordering>,
{
    Float::with_val_round(prec, v, Round::Up).0
}

fn entire(prec: u32) -> (Float, Float) {
    (
        Float::with_val(prec, rug::float::Special::NegInfinity),
        Float::with_val(prec, rug::float::Special::Infinity),
    )
}

fn min_max(prec: u32, candidates: [(Float, Float); 4]) -> (Float, Float) {
    if candidates.iter().any(|(l, h)| l.is_nan() || h.is_nan()) {
        return entire(prec);
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

/// An enclosure `[lo, hi]` of the node's value, evaluated with `prec`-bit MPFR floats rounded
/// outwards at every operation, and cached on the node.
pub(crate) fn enclosure(node: &Node, prec: u32) -> (Float, Float) {
    if let Some(e) = node.cache.lock().expect("cache lock").as_ref() {
        if e.precision >= prec {
            return (e.lo.clone(), e.hi.clone());
        }
    }
    let (lo, hi) = match &node.op {
        Op::Leaf(r) => (
            Float::with_val_round(prec, r, Round::Down).0,
            Float::with_val_round(prec, r, Round::Up).0,
        ),
        Op::Add(a, b) => {
            let ((al, ah), (bl, bh)) = (enclosure(a, prec), enclosure(b, prec));
            (down(prec, &al + &bl), up(prec, &ah + &bh))
        }
        Op::Sub(a, b) => {
            let ((al, ah), (bl, bh)) = (enclosure(a, prec), enclosure(b, prec));
            (down(prec, &al - &bh), up(prec, &ah - &bl))
        }
        Op::Mul(a, b) => {
            let ((al, ah), (bl, bh)) = (enclosure(a, prec), enclosure(b, prec));
            min_max(
                prec,
                [
                    (down(prec, &al * &bl), up(prec, &al * &bl)),
                    (down(prec, &al * &bh), up(prec, &al * &bh)),
                    (down(prec, &ah * &bl), up(prec, &ah * &bl)),
                    (down(prec, &ah * &bh), up(prec, &ah * &bh)),
                ],
            )
        }
        Op::Div(a, b) => {
            let ((al, ah), (bl, bh)) = (enclosure(a, prec), enclosure(b, prec));
            if bl.cmp0() != Some(Ordering::Greater) && bh.cmp0() != Some(Ordering::Less) {
                entire(prec)
            } else {
                min_max(
                    prec,
                    [
                        (down(prec, &al / &bl), up(prec, &al / &bl)),
                        (down(prec, &al / &bh), up(prec, &al / &bh)),
                        (down(prec, &ah / &bl), up(prec, &ah / &bl)),
                        (down(prec, &ah / &bh), up(prec, &ah / &bh)),
                    ],
                )
            }
        }
        Op::Neg(a) => {
            let (al, ah) = enclosure(a, prec);
            (-ah, -al)
        }
        Op::Sqrt(a) => {
            let (mut al, mut ah) = enclosure(a, prec);
            if al.cmp0() != Some(Ordering::Greater) {
                al = Float::new(prec);
            }
            if ah.cmp0() != Some(Ordering::Greater) {
                ah = Float::new(prec);
            }
            (down(prec, al.sqrt_ref()), up(prec, ah.sqrt_ref()))
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
                eval(a, memo) / d
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
    use rug::Rational;

    fn leaf(i: i32) -> Arc<Node> {
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
                let (lo, hi) = enclosure(&node, precision);
                assert!(lo.is_infinite() && lo.is_sign_negative(), "{lo}");
                assert!(hi.is_infinite() && hi.is_sign_positive(), "{hi}");
            }
        }
    }
}
