//! The expression DAG of exact reals: rational leaves, `+ - * /`, negation and square roots.
//!
//! Each node carries, computed once when it is built:
//! - an `f64` [`Interval`] enclosing its value (the filter);
//! - the BFMSS quantities `log2 u(E)` and `log2 l(E)` of its separation bound \[BFMSS01\];
//! - whether a square root occurs below it (if not, it can be evaluated as a rational);
//! - whether a division below it has a divisor that the filter does not show non-zero (such
//!   divisors are decided before any sign of the node is, see [`Node::divisors_unchecked`]);
//! - a hash of its expression, so that `a - b` of two copies of one expression (the engine
//!   builds the same construction from the same inputs more than once) is known to be zero by
//!   structure ([`same_expression`]). Sums and products hash alike in either order.
//!
//! Operations on two rational leaves fold into a rational leaf (while it stays small), and the
//! square root of a perfect-square rational is rational, so meshes with rational lengths build
//! no DAG at all. A few identities are applied as nodes are built, where an operand is a copy
//! of another's: `a - (a - b) = b`, `(a + b) - b = a`, `(a - b) - (a - c) = c - b` and
//! `-(-a) = a`. They are what a position measured from the other end of an edge, `L - x`,
//! turns into when it is measured back: on a mesh with a mirror symmetry, the mirror images of
//! a wedge then build one and the same expression, and their ties are zeros by structure.

use super::super::bignum::{Float, Rational};
use super::super::{Interval, Sign};
use super::form::Memo;
use std::collections::HashSet;
use std::hash::{Hash, Hasher};
use std::sync::{Arc, Mutex, OnceLock};

/// Rational leaves larger than this (numerator plus denominator bits) are not folded further:
/// the DAG and its interval evaluation are cheaper than ever-growing rationals.
const FOLD_BITS: u64 = 2048;

/// An operation of the DAG.
pub(crate) enum Op {
    Leaf(Rational),
    Add(Arc<Node>, Arc<Node>),
    Sub(Arc<Node>, Arc<Node>),
    Mul(Arc<Node>, Arc<Node>),
    Div(Arc<Node>, Arc<Node>),
    Neg(Arc<Node>),
    Sqrt(Arc<Node>),
    /// A node whose children were moved out while it was dropped.
    Dropped,
}

/// An enclosure of a node's value at some precision, cached for refinement.
pub(crate) struct Enclosure {
    pub(crate) precision: u32,
    pub(crate) lo: Float,
    pub(crate) hi: Float,
}

/// A node of the DAG.
pub(crate) struct Node {
    pub(crate) op: Op,
    pub(crate) filter: Interval,
    /// `log2 u(E)`, an upper bound (`-inf` for the value zero).
    pub(crate) log_u: f64,
    /// `log2 l(E)`, an upper bound.
    pub(crate) log_l: f64,
    pub(crate) has_sqrt: bool,
    /// Whether a division at or below this node has a divisor whose filter contains zero, so
    /// that the divisor may be zero. Such a node has no certified sign until every such divisor
    /// is certified non-zero: a division by zero has no value, and the stages below would
    /// otherwise read one into it (an infinite enclosure clipped by a square root, a rational
    /// evaluation, a normal form, or a rewriting such as `0 * x = 0`).
    pub(crate) divisors_unchecked: bool,
    /// The outcome of checking those divisors, once known.
    pub(crate) divisors_checked: OnceLock<DivisorCheck>,
    pub(crate) cache: Mutex<Option<Enclosure>>,
    /// The normal form, with the tower it is written in and the budget it had (see
    /// `normal_form.rs`).
    pub(crate) normal_form: Mutex<Option<Memo>>,
    /// A hash of the expression: equal for equal expressions, whichever nodes hold them.
    hash: u64,
    /// Whether the node is zero by its structure (`x - x` or `0 * x` of an expression `x`),
    /// once its divisors are non-zero.
    pub(crate) structural_zero: bool,
}

/// The outcome of checking a node's divisors (see [`Node::divisors_unchecked`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum DivisorCheck {
    /// Every divisor is certified non-zero.
    NonZero,
    /// A divisor is certified zero.
    Zero,
    /// A divisor is shown neither zero nor non-zero within the precision cap `cap` (bits),
    /// refined to `precision`; valid while the cap stays `cap`.
    Uncertain {
        /// The precision cap of the check.
        cap: u32,
        /// The precision reached.
        precision: u32,
    },
}

/// `log2(2^a + 2^b)`, rounded up to the next whole bit.
fn log_add(a: f64, b: f64) -> f64 {
    if a == f64::NEG_INFINITY {
        b
    } else if b == f64::NEG_INFINITY {
        a
    } else {
        a.max(b) + 1.0
    }
}

/// `log2` bound of an integer of `bits` bits.
fn log2_bound(bits: u64) -> f64 {
    if bits == 0 {
        f64::NEG_INFINITY
    } else {
        bits as f64
    }
}

/// The `f64` interval enclosing a rational.
pub(crate) fn enclose(r: &Rational) -> Interval {
    let x = r.to_f64();
    if !x.is_finite() {
        return Interval::ENTIRE;
    }
    match Rational::from_f64(x) {
        Some(exact) if exact == *r => Interval::point(x),
        _ => Interval {
            lo: x.next_down(),
            hi: x.next_up(),
        },
    }
}

impl Node {
    pub(crate) fn leaf(r: Rational) -> Arc<Node> {
        Arc::new(Node::leaf_node(r))
    }

    fn leaf_node(r: Rational) -> Node {
        let mut hasher = std::hash::DefaultHasher::new();
        r.hash(&mut hasher);
        Node {
            hash: hasher.finish(),
            structural_zero: false,
            filter: enclose(&r),
            log_u: log2_bound(r.numer_bits()),
            log_l: log2_bound(r.denom_bits()),
            has_sqrt: false,
            divisors_unchecked: false,
            divisors_checked: OnceLock::new(),
            op: Op::Leaf(r),
            cache: Mutex::new(None),
            normal_form: Mutex::new(None),
        }
    }

    pub(crate) fn rational(&self) -> Option<&Rational> {
        match &self.op {
            Op::Leaf(r) => Some(r),
            _ => None,
        }
    }

    fn build(op: Op, filter: Interval, log_u: f64, log_l: f64, has_sqrt: bool) -> Arc<Node> {
        Arc::new(Node::operation(op, filter, log_u, log_l, has_sqrt))
    }

    fn operation(op: Op, filter: Interval, log_u: f64, log_l: f64, has_sqrt: bool) -> Node {
        let divisors_unchecked = match &op {
            Op::Div(a, b) => {
                a.divisors_unchecked
                    || b.divisors_unchecked
                    || !matches!(b.filter.sign(), Some(Sign::Positive | Sign::Negative))
            }
            _ => {
                let mut children = op_children(&op);
                children.any(|c| c.divisors_unchecked)
            }
        };
        Node {
            hash: op_hash(&op),
            structural_zero: false,
            op,
            filter,
            log_u,
            log_l,
            has_sqrt,
            divisors_unchecked,
            divisors_checked: OnceLock::new(),
            cache: Mutex::new(None),
            normal_form: Mutex::new(None),
        }
    }

    /// `x - x` or `0 * x`: zero wherever `x` has a value. Without divisors to check that is the
    /// rational zero (marked as a zero by structure when `x` is an expression); otherwise the
    /// operation is kept, for its divisors to be checked before its sign is given, but its
    /// filter is the point zero, so that the sign is certified zero once they are shown
    /// non-zero (a zero times a division by zero stays undefined).
    fn zero_of(op: Op) -> Arc<Node> {
        let mut zero = if op_children(&op).any(|c| c.divisors_unchecked) {
            let has_sqrt = op_children(&op).any(|c| c.has_sqrt);
            Node::operation(op, Interval::point(0.0), f64::NEG_INFINITY, 0.0, has_sqrt)
        } else if op_children(&op).all(|c| c.rational().is_some()) {
            return Node::leaf(Rational::default());
        } else {
            Node::leaf_node(Rational::default())
        };
        zero.structural_zero = true;
        Arc::new(zero)
    }

    /// Folds a binary operation of two small rational leaves.
    fn fold(
        a: &Arc<Node>,
        b: &Arc<Node>,
        f: impl FnOnce(&Rational, &Rational) -> Option<Rational>,
    ) -> Option<Arc<Node>> {
        let (x, y) = (a.rational()?, b.rational()?);
        if x.size_bits() + y.size_bits() > FOLD_BITS {
            return None;
        }
        f(x, y).map(Node::leaf)
    }

    fn is_zero(&self) -> bool {
        self.rational().is_some_and(|r| r.is_zero())
    }

    fn is_one(&self) -> bool {
        self.rational().is_some_and(Rational::is_one)
    }

    pub(crate) fn add(a: Arc<Node>, b: Arc<Node>) -> Arc<Node> {
        if let Some(n) = Node::fold(&a, &b, |x, y| Some(x.clone() + y)) {
            return n;
        }
        if b.is_zero() {
            return a;
        }
        if a.is_zero() {
            return b;
        }
        let (log_u, log_l) = (
            log_add(a.log_u + b.log_l, a.log_l + b.log_u),
            a.log_l + b.log_l,
        );
        let (filter, has_sqrt) = (a.filter + b.filter, a.has_sqrt || b.has_sqrt);
        Node::build(Op::Add(a, b), filter, log_u, log_l, has_sqrt)
    }

    pub(crate) fn sub(a: Arc<Node>, b: Arc<Node>) -> Arc<Node> {
        if let Some(n) = Node::fold(&a, &b, |x, y| Some(x.clone() - y)) {
            return n;
        }
        if same_expression(&a, &b) {
            return Node::zero_of(Op::Sub(a, b));
        }
        if b.is_zero() {
            return a;
        }
        if let Some(n) = Node::cancel(&a, &b) {
            return n;
        }
        let (log_u, log_l) = (
            log_add(a.log_u + b.log_l, a.log_l + b.log_u),
            a.log_l + b.log_l,
        );
        let (filter, has_sqrt) = (a.filter - b.filter, a.has_sqrt || b.has_sqrt);
        Node::build(Op::Sub(a, b), filter, log_u, log_l, has_sqrt)
    }

    /// `a - b` where a copy of an operand cancels: `a - (a - c) = c`, `(c + b) - b = c`,
    /// `(b + c) - b = c`, `(p - c) - (p - d) = d - c`. Only where the cancelled copy's
    /// divisors are known non-zero: the result would have a value where `a - b` has none.
    fn cancel(a: &Arc<Node>, b: &Arc<Node>) -> Option<Arc<Node>> {
        let gone = |x: &Arc<Node>, y: &Arc<Node>| {
            (!x.divisors_unchecked || x.divisors_checked.get() == Some(&DivisorCheck::NonZero))
                && same_expression(x, y)
        };
        match (&a.op, &b.op) {
            (_, Op::Sub(p, c)) if gone(a, p) => Some(c.clone()),
            (Op::Add(c, q), _) if gone(q, b) => Some(c.clone()),
            (Op::Add(q, c), _) if gone(q, b) => Some(c.clone()),
            (Op::Sub(p, c), Op::Sub(q, d)) if gone(p, q) => Some(Node::sub(d.clone(), c.clone())),
            _ => None,
        }
    }

    pub(crate) fn mul(a: Arc<Node>, b: Arc<Node>) -> Arc<Node> {
        if let Some(n) = Node::fold(&a, &b, |x, y| Some(x.clone() * y)) {
            return n;
        }
        if a.is_zero() || b.is_zero() {
            return Node::zero_of(Op::Mul(a, b));
        }
        // The same node, not a copy of it: identities the engine builds (an edge's length
        // reached as one times it) stay visible to `x - x`.
        if a.is_one() {
            return b;
        }
        if b.is_one() {
            return a;
        }
        let (log_u, log_l) = (a.log_u + b.log_u, a.log_l + b.log_l);
        let (filter, has_sqrt) = (a.filter * b.filter, a.has_sqrt || b.has_sqrt);
        Node::build(Op::Mul(a, b), filter, log_u, log_l, has_sqrt)
    }

    pub(crate) fn div(a: Arc<Node>, b: Arc<Node>) -> Arc<Node> {
        let quotient = |x: &Rational, y: &Rational| (!y.is_zero()).then(|| x.clone() / y);
        if let Some(n) = Node::fold(&a, &b, quotient) {
            return n;
        }
        if b.is_one() {
            return a;
        }
        let (log_u, log_l) = (a.log_u + b.log_l, a.log_l + b.log_u);
        let (filter, has_sqrt) = (a.filter / b.filter, a.has_sqrt || b.has_sqrt);
        Node::build(Op::Div(a, b), filter, log_u, log_l, has_sqrt)
    }

    pub(crate) fn neg(a: Arc<Node>) -> Arc<Node> {
        if let Some(r) = a.rational() {
            return Node::leaf(-r.clone());
        }
        if let Op::Neg(p) = &a.op {
            return p.clone();
        }
        let (log_u, log_l, filter, has_sqrt) = (a.log_u, a.log_l, -a.filter, a.has_sqrt);
        Node::build(Op::Neg(a), filter, log_u, log_l, has_sqrt)
    }

    /// The square root of `max(a, 0)`: a negative rational gives zero, a perfect square its
    /// rational root.
    pub(crate) fn sqrt(a: Arc<Node>) -> Arc<Node> {
        if let Some(r) = a.rational() {
            if r.cmp0().is_le() {
                return Node::leaf(Rational::default());
            }
            let (n, d) = (r.numer(), r.denom());
            if n.is_perfect_square() && d.is_perfect_square() {
                let root = Rational::new(n.sqrt(), d.sqrt()).expect("a positive denominator");
                return Node::leaf(root);
            }
        }
        let (log_u, log_l) = (0.5 * a.log_u, 0.5 * a.log_l);
        let filter = super::super::Field::sqrt(&a.filter);
        Node::build(Op::Sqrt(a), filter, log_u, log_l, true)
    }

    /// The children of this node.
    pub(crate) fn children(&self) -> impl Iterator<Item = &Arc<Node>> {
        op_children(&self.op)
    }
}

/// The hash of an operation's expression, from its kind and its operands' hashes, in either
/// order for a sum or a product.
fn op_hash(op: &Op) -> u64 {
    let tag: u64 = match op {
        Op::Leaf(_) => 1,
        Op::Add(..) => 2,
        Op::Sub(..) => 3,
        Op::Mul(..) => 4,
        Op::Div(..) => 5,
        Op::Neg(_) => 6,
        Op::Sqrt(_) => 7,
        Op::Dropped => 8,
    };
    let mix = |h: u64, c: u64| (h.rotate_left(23) ^ c).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    match op {
        Op::Add(a, b) | Op::Mul(a, b) => mix(mix(tag, a.hash.min(b.hash)), a.hash.max(b.hash)),
        _ => op_children(op).fold(tag, |h, c| mix(h, c.hash)),
    }
}

/// Node pairs [`same_expression`] may compare before it gives up (and answers `false`): two
/// copies of a long construction are compared in time linear in their size, but no more.
const SAME_EXPRESSION_BUDGET: usize = 4096;

/// Whether two nodes hold the same expression: the same node, or the same operation on
/// operands that hold the same expressions (a sum's or a product's in either order), down to
/// equal rational leaves. `false` may also mean "too large to tell"; `true` is a proof that
/// the values are equal.
pub(crate) fn same_expression(a: &Arc<Node>, b: &Arc<Node>) -> bool {
    if Arc::ptr_eq(a, b) {
        return true;
    }
    if a.hash != b.hash {
        return false;
    }
    let mut seen = HashSet::new();
    let mut stack = vec![(a, b)];
    while let Some((x, y)) = stack.pop() {
        if Arc::ptr_eq(x, y) || !seen.insert((Arc::as_ptr(x), Arc::as_ptr(y))) {
            continue;
        }
        if x.hash != y.hash || seen.len() > SAME_EXPRESSION_BUDGET {
            return false;
        }
        let same_kind = match (&x.op, &y.op) {
            (Op::Leaf(p), Op::Leaf(q)) => p == q,
            (Op::Add(..), Op::Add(..))
            | (Op::Sub(..), Op::Sub(..))
            | (Op::Mul(..), Op::Mul(..))
            | (Op::Div(..), Op::Div(..))
            | (Op::Neg(_), Op::Neg(_))
            | (Op::Sqrt(_), Op::Sqrt(_)) => true,
            _ => false,
        };
        if !same_kind {
            return false;
        }
        match (&x.op, &y.op) {
            // Operands in the other order: paired by their hashes.
            (Op::Add(x0, x1), Op::Add(y0, y1)) | (Op::Mul(x0, x1), Op::Mul(y0, y1))
                if x0.hash != y0.hash =>
            {
                stack.extend([(x0, y1), (x1, y0)]);
            }
            _ => stack.extend(x.children().zip(y.children())),
        }
    }
    true
}

/// The operands of an operation.
fn op_children(op: &Op) -> impl Iterator<Item = &Arc<Node>> {
    let (a, b) = match op {
        Op::Add(a, b) | Op::Sub(a, b) | Op::Mul(a, b) | Op::Div(a, b) => (Some(a), Some(b)),
        Op::Neg(a) | Op::Sqrt(a) => (Some(a), None),
        Op::Leaf(_) | Op::Dropped => (None, None),
    };
    a.into_iter().chain(b)
}

impl Drop for Node {
    /// Drops long chains without recursing once per level (a DAG built along hundreds of faces
    /// would otherwise overflow a thread's stack).
    fn drop(&mut self) {
        let mut stack: Vec<Arc<Node>> = Vec::new();
        let take =
            |op: &mut Op, stack: &mut Vec<Arc<Node>>| match std::mem::replace(op, Op::Dropped) {
                Op::Add(a, b) | Op::Sub(a, b) | Op::Mul(a, b) | Op::Div(a, b) => {
                    stack.push(a);
                    stack.push(b);
                }
                Op::Neg(a) | Op::Sqrt(a) => stack.push(a),
                Op::Leaf(_) | Op::Dropped => {}
            };
        take(&mut self.op, &mut stack);
        while let Some(node) = stack.pop() {
            if let Ok(mut node) = Arc::try_unwrap(node) {
                take(&mut node.op, &mut stack);
            }
        }
    }
}
