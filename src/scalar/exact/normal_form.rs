//! A cheap exact zero test: values in a tower of quadratic extensions of the rationals,
//! `Q(sqrt r1, ..., sqrt rk)`, in normal form.
//!
//! An element is a sum of rational multiples of square-free products of *symbols*; each symbol
//! `s` stands for the square root of a value already in the tower (its *square*), and `s * s`
//! is rewritten into that square. A symbol with a rational square is a radical of an integer
//! with its small square factors taken out, so equal radicals are one symbol; any other radical
//! is keyed by the normal form of its radicand. Edge lengths and unfolded positions of a mesh
//! with rational coordinates are in such a field, so the identities between them (Example 1's
//! symmetric wedges, [LZT §3]) reduce to a normal form of zero.
//!
//! The normal form is unique only when the symbols are independent, which is not checked: a
//! zero normal form proves the value zero; a non-zero one proves nothing, and the refinement
//! with the separation bound takes over. Normal forms that grow past their [`Budget`] give up.
//!
//! The square root of a form that is a square in the tower is that square's root, not a new
//! symbol ([`NormalForm::root_in_tower`], checked by squaring): a length along a straight line
//! through a chain of edges, `sqrt((c1 sqrt(r1) + ... + ck sqrt(rk))^2)` once its square is
//! expanded, is then the sum of the edges' lengths, and its identities stay visible.
//!
//! A last resort ([`zero_over_atoms`]) writes every subexpression too large to expand as an
//! *atom*, an indeterminate: the identities MMP creates are mostly local (a pseudo-source's
//! tangency with the image that lit it, across the faces between them), and they hold whatever
//! value the deep unfoldings below give the image. Subexpressions whose forms over atoms are
//! proportional share one atom, so that `(p - x)^2` and `(x - p)^2` built on two sides of a
//! mirror are one atom squared. A form that is not zero as it stands may still be proved zero
//! by eliminating its square roots one at a time ([`zero_by_elimination`]): sums of distances
//! of several radicals whose radicands hold other radicals, where the symbols are not
//! independent.

use super::super::bignum::{Integer, Rational, Round};
use super::super::{Field, Interval, Sign};
use super::form::{Budget, Memo, Monomial, NormalForm};
use super::node::{enclose, Node, Op};
use std::cell::RefCell;
use std::collections::{BTreeMap, HashMap};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

mod coprime;
mod product;

/// Normal forms with a coefficient larger than this (numerator plus denominator bits) are
/// abandoned: rational arithmetic on them costs more than the separation bound would.
const MAX_COEFFICIENT_BITS: u64 = 16384;

/// Term-by-term multiplications the last resorts of one run (one tower, [`new_tower`]) may
/// spend together: a mesh with many zeros that no budget proves pays for twenty of them at
/// most, then keeps to the cheap budget.
const LAST_RESORT_WORK_PER_RUN: usize = 100_000_000;

thread_local! {
    static WORK_LEFT: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
    static LAST_RESORT_WORK_LEFT: std::cell::Cell<usize> =
        const { std::cell::Cell::new(LAST_RESORT_WORK_PER_RUN) };
    static BUDGET: std::cell::Cell<Budget> = const { std::cell::Cell::new(Budget::Cheap) };
    /// This thread's tower: a propagation starts a new one ([`new_tower`]), so that its symbols
    /// neither pile up from run to run nor are shared (and locked) between threads.
    static TOWER: RefCell<Tower> = RefCell::new(Tower::new());
}

/// Ids of towers, unique in the process: a normal form memoized on a node is valid only in the
/// tower it was computed in.
static NEXT_TOWER: AtomicU64 = AtomicU64::new(0);

struct Tower {
    id: u64,
    /// The square of each symbol; `None` for an atom.
    squares: Vec<Option<NormalForm>>,
    /// An enclosure of each symbol's value, for the sign of a square root found in the tower
    /// ([`NormalForm::root_in_tower`]).
    enclosures: Vec<Interval>,
    /// The atoms, by the address of the node each stands for (held, so that the address is
    /// not reused while the tower lives).
    atoms: HashMap<usize, (u32, Arc<Node>)>,
    /// Normal forms over atoms, by the address of their node (held likewise), with the budget
    /// they had: asked only of would-be uncertified decisions, so kept here rather than on
    /// every node.
    atom_forms: HashMap<usize, (Arc<Node>, NormalForm, Budget)>,
    /// Atoms standing for values known by their forms over atoms, by [`AtomKey`].
    keyed_atoms: HashMap<AtomKey, u32>,
    /// The symbols of integer radicals, by square class ([`square_class`]): radicals whose
    /// product is a square are one symbol, up to a rational factor.
    integer_radicals: HashMap<u64, Vec<(Integer, u32)>>,
    radicals: HashMap<NormalForm, u32>,
}

impl Tower {
    /// A new symbol with this square (`None` for an atom) and an enclosure of its value.
    fn push(&mut self, square: Option<NormalForm>, enclosure: Interval) -> u32 {
        let id = self.squares.len() as u32;
        self.squares.push(square);
        self.enclosures.push(enclosure);
        id
    }

    fn new() -> Tower {
        Tower {
            id: NEXT_TOWER.fetch_add(1, Ordering::Relaxed),
            squares: Vec::new(),
            enclosures: Vec::new(),
            atoms: HashMap::new(),
            atom_forms: HashMap::new(),
            keyed_atoms: HashMap::new(),
            integer_radicals: HashMap::new(),
            radicals: HashMap::new(),
        }
    }
}

/// Replaces this thread's tower by an empty one; normal forms memoized in the old one are
/// computed again when asked for.
pub(crate) fn new_tower() {
    TOWER.with(|t| *t.borrow_mut() = Tower::new());
    LAST_RESORT_WORK_LEFT.with(|w| w.set(LAST_RESORT_WORK_PER_RUN));
}

fn tower_id() -> u64 {
    TOWER.with(|t| t.borrow().id)
}

/// The square of a symbol; `None` for an atom, which has no relation.
fn square_of(symbol: u32) -> Option<NormalForm> {
    TOWER.with(|t| t.borrow().squares[symbol as usize].clone())
}

fn is_atom(symbol: u32) -> bool {
    TOWER.with(|t| t.borrow().squares[symbol as usize].is_none())
}

impl NormalForm {
    fn rational(r: Rational) -> NormalForm {
        let mut m = BTreeMap::new();
        if !r.is_zero() {
            m.insert(Vec::new(), r);
        }
        NormalForm(m)
    }

    fn monomial(c: Rational, m: Monomial) -> NormalForm {
        let mut map = BTreeMap::new();
        if !c.is_zero() {
            map.insert(m, c);
        }
        NormalForm(map)
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    /// The first coefficient, and the form divided by it (`1` and zero for zero).
    fn normalized(&self) -> (Rational, NormalForm) {
        match self.0.values().next() {
            Some(lead) => (
                lead.clone(),
                NormalForm(
                    self.0
                        .iter()
                        .map(|(m, c)| (m.clone(), c.clone() / lead))
                        .collect(),
                ),
            ),
            None => (Rational::from(1), NormalForm::default()),
        }
    }

    fn scaled(self, c: &Rational) -> NormalForm {
        if c.is_zero() {
            return NormalForm::default();
        }
        NormalForm(self.0.into_iter().map(|(m, x)| (m, x * c)).collect())
    }

    /// The value, if it is rational.
    pub(crate) fn as_rational(&self) -> Option<Rational> {
        match self.0.len() {
            0 => Some(Rational::default()),
            1 => self.0.get(&Vec::new()).cloned(),
            _ => None,
        }
    }

    fn checked(self) -> Option<NormalForm> {
        let small = |c: &Rational| c.size_bits() <= MAX_COEFFICIENT_BITS;
        (self.0.len() <= budget().terms() && self.0.values().all(small)).then_some(self)
    }

    fn add(&self, other: &NormalForm, sign: i32) -> Option<NormalForm> {
        let mut sum = self.clone();
        sum.accumulate(other, sign);
        sum.checked()
    }

    /// `self += sign * other`, in place.
    fn accumulate(&mut self, other: &NormalForm, sign: i32) {
        for (m, c) in &other.0 {
            let entry = self.0.entry(m.clone()).or_default();
            if sign > 0 {
                *entry += c;
            } else {
                *entry -= c;
            }
            if entry.is_zero() {
                self.0.remove(m);
            }
        }
    }

    fn neg(&self) -> NormalForm {
        NormalForm(
            self.0
                .iter()
                .map(|(m, c)| (m.clone(), -c.clone()))
                .collect(),
        )
    }

    fn div(&self, other: &NormalForm) -> Option<NormalForm> {
        let (mut num, mut den) = (self.clone(), other.clone());
        // Multiply by conjugates until the denominator is rational: with `den = p + q s` for
        // its largest symbol `s`, `(p + q s)(p - q s) = p^2 - q^2 square(s)` is free of `s`.
        // An atom has no conjugate: a quotient by it is not a polynomial.
        while den.as_rational().is_none() {
            let s = *den.0.keys().filter_map(|m| m.last()).max()?;
            if is_atom(s) {
                return None;
            }
            let conjugate = NormalForm(
                den.0
                    .iter()
                    .map(|(m, c)| {
                        let c = if m.contains(&s) {
                            -c.clone()
                        } else {
                            c.clone()
                        };
                        (m.clone(), c)
                    })
                    .collect(),
            );
            num = num.mul(&conjugate)?;
            den = den.mul(&conjugate)?;
        }
        let d = den.as_rational()?;
        if d.is_zero() {
            return None;
        }
        Some(NormalForm(
            num.0.into_iter().map(|(m, c)| (m, c / &d)).collect(),
        ))
    }

    /// The square root of a value known to be positive, `root` giving an enclosure of it: a
    /// new symbol's enclosure is the better of that and the root of the form's own, which
    /// cancellation among large terms may leave wide (a sign that the elimination of square
    /// roots reads off it). Asked only for a new symbol.
    fn sqrt(&self, root: impl FnOnce() -> Interval) -> Option<NormalForm> {
        if let Some(r) = self.as_rational() {
            return Some(sqrt_of_rational(&r));
        }
        if let Some(root) = self.denested() {
            return Some(root);
        }
        if let Some(root) = self.root_in_tower(ROOT_DEPTH) {
            return Some(root);
        }
        let known = TOWER.with(|t| t.borrow().radicals.get(self).copied());
        let id = known.unwrap_or_else(|| {
            let enclosure = self.enclosure().sqrt().meet(root());
            TOWER.with(|t| {
                let mut t = t.borrow_mut();
                let id = t.push(Some(self.clone()), enclosure);
                t.radicals.insert(self.clone(), id);
                id
            })
        });
        Some(NormalForm::monomial(Rational::from(1), vec![id]))
    }
}

/// How many symbols deep [`NormalForm::root_in_tower`] looks: each level may ask three roots of
/// the level below.
const ROOT_DEPTH: u32 = 4;

/// Radicands with more terms than this are not searched for a root in the tower. The square of
/// a sum of `k` radicals of distinct classes has `1 + k (k - 1) / 2` terms: a straight line
/// along 23 strips of distinct widths (a cylinder's columns) still has its root found.
const ROOT_TERMS: usize = 256;

impl NormalForm {
    /// An enclosure of the value, from the enclosures of the symbols.
    fn enclosure(&self) -> Interval {
        TOWER.with(|t| {
            let t = t.borrow();
            self.0.iter().fold(Interval::point(0.0), |sum, (m, c)| {
                let term = m
                    .iter()
                    .fold(enclose(c), |x, &s| x * t.enclosures[s as usize]);
                sum + term
            })
        })
    }

    /// The square root of a positive value that is a square in the tower: `T` with `T * T`
    /// equal to the form (checked in normal form, so a proof whether or not the symbols are
    /// independent) and `T > 0` (by its enclosure). A distance whose square was expanded, as
    /// `sqrt((a + b sqrt(p) + c sqrt(q))^2)` for a point reached along a line through a chain
    /// of edges, is then that sum, and not a new symbol whose relation to it is lost.
    ///
    /// The root is sought as `X + Y s` for the form's last symbol `s` (of square `D`), with the
    /// form `A + B s`: `X^2 + Y^2 D = A` and `2 X Y = B`; first with `Y` of one term, which
    /// needs no further root, else from `X^2 = (A ± C) / 2` with `C^2 = A^2 - B^2 D`, roots
    /// sought in turn, `depth` symbols deep.
    fn root_in_tower(&self, depth: u32) -> Option<NormalForm> {
        if self.0.len() > ROOT_TERMS {
            return None;
        }
        let monomials: Vec<&Monomial> = self.0.keys().collect();
        let root = self.signed_root(depth, &monomials)?;
        match root.enclosure().sign()? {
            Sign::Positive => Some(root),
            Sign::Negative => Some(root.neg()),
            Sign::Zero => None,
        }
    }

    /// A form whose square is this one, of either sign: a rational's root as a rational
    /// multiple of one of `monomials` (those of the radicand the search began with: their
    /// radicands need not be of one square class, as `sqrt 6 = sqrt 2 sqrt 3`), else a new
    /// radical; a form's as `X + Y s` ([`Self::root_with_monomial_part`], else `depth` levels
    /// of [`Self::root_by_halves`]).
    fn signed_root(&self, depth: u32, monomials: &[&Monomial]) -> Option<NormalForm> {
        if let Some(r) = self.as_rational() {
            if r.cmp0().is_lt() {
                return None;
            }
            let multiple = monomials.iter().find_map(|&m| {
                let q = rational_root(&(r.clone() / &monomial_square(m)?))?;
                Some(NormalForm::monomial(q, m.clone()))
            });
            return Some(multiple.unwrap_or_else(|| sqrt_of_rational(&r)));
        }
        let s = *self.0.keys().filter_map(|m| m.last()).max()?;
        let d = square_of(s)?;
        let (mut a, mut b) = (NormalForm::default(), NormalForm::default());
        for (m, c) in &self.0 {
            match m.split_last() {
                Some((&last, rest)) if last == s => b.0.insert(rest.to_vec(), c.clone()),
                _ => a.0.insert(m.clone(), c.clone()),
            };
        }
        let split = Split { a, b, s, d };
        let with_monomial = split.root_with_monomial_part(self, monomials);
        if with_monomial.is_some() || depth == 0 {
            return with_monomial;
        }
        split.root_by_halves(self, depth, monomials)
    }
}

/// A form `A + B s` split at its last symbol `s`, of square `D`, whose root is sought as
/// `X + Y s`: `X^2 + Y^2 D = A` and `2 X Y = B`.
struct Split {
    a: NormalForm,
    b: NormalForm,
    s: u32,
    d: NormalForm,
}

impl Split {
    /// `X + Y s` if its square is `form`.
    fn checked_root(
        &self,
        x: &NormalForm,
        y: &NormalForm,
        form: &NormalForm,
    ) -> Option<NormalForm> {
        let root = x.add(
            &y.mul(&NormalForm::monomial(Rational::from(1), vec![self.s]))?,
            1,
        )?;
        (root.mul(&root)? == *form).then_some(root)
    }

    /// The root where `Y = y M` is one term, `M` a product of symbols of rational square: a
    /// sum of lengths along one line, `sqrt((c1 sqrt(r1) + ... + ck sqrt(rk))^2)`, has such a
    /// root at every symbol. Then `X = B / (2 Y)`, and `v = Y^2` is rational: with the
    /// rational parts `a0`, `d0`, `e0` of `A`, `D` and `B^2` (the symbols taken as
    /// independent, for a guess that is checked), `d0 v^2 - a0 v + e0 / 4 = 0`.
    fn root_with_monomial_part(
        &self,
        form: &NormalForm,
        monomials: &[&Monomial],
    ) -> Option<NormalForm> {
        let b2 = self.b.mul(&self.b)?;
        let [a0, d0, e0] = [&self.a, &self.d, &b2].map(NormalForm::rational_part);
        let quarter = Rational::new(Integer::from(1), Integer::from(4))?;
        let candidates: Vec<Rational> = if d0.is_zero() {
            if a0.is_zero() {
                return None;
            }
            vec![e0 * &quarter / &a0]
        } else {
            // v = (a0 ± sqrt(a0^2 - d0 e0)) / (2 d0)
            let root = rational_root(&(a0.clone() * &a0 - &(d0.clone() * &e0)))?;
            let twice = d0.clone() * &Rational::from(2);
            vec![(a0.clone() + &root) / &twice, (a0 - &root) / &twice]
        };
        let empty = Vec::new();
        let terms: Vec<&Monomial> = std::iter::once(&empty)
            .chain(self.b.0.keys())
            .chain(monomials.iter().copied())
            .collect();
        for v in candidates.into_iter().filter(|v| v.cmp0().is_gt()) {
            for &m in &terms {
                let Some(m2) = monomial_square(m) else {
                    continue;
                };
                let Some(y) = rational_root(&(v.clone() / &m2)) else {
                    continue;
                };
                // X = B / (2 y M) = B M / (2 y M^2).
                let Some(x) = self
                    .b
                    .mul(&NormalForm::monomial(Rational::from(1), m.clone()))
                    .map(|bm| {
                        bm.scaled(&(Rational::from(1) / &(y.clone() * &m2 * &Rational::from(2))))
                    })
                else {
                    continue;
                };
                let root = self.checked_root(&x, &NormalForm::monomial(y, m.clone()), form);
                if root.is_some() {
                    return root;
                }
            }
        }
        None
    }

    /// The root from `X^2 = (A ± C) / 2` with `C^2 = A^2 - B^2 D`, both roots sought in
    /// turn ([`NormalForm::signed_root`], `depth - 1` levels), then `Y = B / (2 X)`.
    fn root_by_halves(
        &self,
        form: &NormalForm,
        depth: u32,
        monomials: &[&Monomial],
    ) -> Option<NormalForm> {
        let n = self
            .a
            .mul(&self.a)?
            .add(&self.b.mul(&self.b)?.mul(&self.d)?, -1)?;
        let c = n.signed_root(depth - 1, monomials)?;
        let half = Rational::new(Integer::from(1), Integer::from(2))?;
        for sign in [1, -1] {
            let root = self
                .a
                .add(&c, sign)
                .and_then(|x2| x2.scaled(&half).signed_root(depth - 1, monomials))
                .filter(|x| !x.is_zero())
                .and_then(|x| {
                    let y = self.b.div(&x.clone().scaled(&Rational::from(2)))?;
                    self.checked_root(&x, &y, form)
                });
            if root.is_some() {
                return root;
            }
        }
        None
    }
}

impl NormalForm {
    /// The rational part (the coefficient of the empty monomial).
    fn rational_part(&self) -> Rational {
        self.0.get(&Vec::new()).cloned().unwrap_or_default()
    }
}

/// The square of a monomial, if it is rational.
fn monomial_square(m: &Monomial) -> Option<Rational> {
    let one = NormalForm::monomial(Rational::from(1), m.clone());
    one.mul(&one)?.as_rational()
}

/// The rational square root of a rational, if it has one.
fn rational_root(r: &Rational) -> Option<Rational> {
    if r.cmp0().is_lt() {
        return None;
    }
    let (n, d) = (r.numer(), r.denom());
    (n.is_perfect_square() && d.is_perfect_square())
        .then(|| Rational::new(n.sqrt(), d.sqrt()))
        .flatten()
}

impl NormalForm {
    /// Whether the form is zero, also where its symbols are not independent, for a form of two
    /// terms `c1 M1 + c2 M2` over square roots: they are positive, so the form is zero exactly
    /// when the coefficients have opposite signs and `c1^2 M1^2 = c2^2 M2^2`, asked in turn of
    /// that difference (a form over the radicands, `depth` times at most). A zero is a proof;
    /// `false` proves nothing.
    fn is_zero_by_squares(&self, depth: u32) -> bool {
        if self.is_zero() {
            return true;
        }
        let mut terms = self.0.iter();
        let (Some((m1, c1)), Some((m2, c2)), None) = (terms.next(), terms.next(), terms.next())
        else {
            return false;
        };
        if depth == 0 || c1.cmp0() == c2.cmp0() {
            return false;
        }
        let square = |m: &Monomial, c: &Rational| -> Option<NormalForm> {
            let mut form = NormalForm::rational(c.clone() * c);
            for &symbol in m {
                form = form.mul(&square_of(symbol)?)?;
            }
            Some(form)
        };
        let (Some(a), Some(b)) = (square(m1, c1), square(m2, c2)) else {
            return false;
        };
        a.add(&b, -1)
            .is_some_and(|difference| difference.is_zero_by_squares(depth - 1))
    }
}

/// How many times [`NormalForm::is_zero_by_elimination`] may split a form into the two parts
/// it asks in turn: each split may double the work.
const SPLIT_DEPTH: u32 = 6;

impl NormalForm {
    /// Whether the form is zero, by eliminating its square roots one at a time: with `s` its
    /// last square-root symbol (of square `D`, positive) and the form `A + B s`, the form is
    /// zero when `A` and `B` have opposite signs (by their enclosures) and `A^2 - B^2 D`, free
    /// of `s`, is zero in turn; then `|A| = |B| s`. Where neither `A`'s sign nor `B`'s is clear,
    /// the form is zero when `A` and `B` are each zero: the symbols are not independent, and a
    /// mirror image built through other faces is `s` times a combination of radicals that is
    /// zero by identities of its own. A zero is a proof, whether or not the symbols are
    /// independent (sums of distances `d1 + d2 = d3 + d4` of several radicals, their radicands
    /// in turn of other radicals); `false` proves nothing.
    fn is_zero_by_elimination(&self, splits: u32) -> bool {
        let mut form = self.clone();
        loop {
            if form.is_zero() {
                return true;
            }
            if let Some(zero) = form.is_zero_over_coprime_radicals() {
                return zero;
            }
            let Some(s) = form
                .0
                .keys()
                .flatten()
                .copied()
                .filter(|&s| !is_atom(s))
                .max()
            else {
                return false;
            };
            let Some(d) = square_of(s) else {
                return false;
            };
            let (mut a, mut b) = (NormalForm::default(), NormalForm::default());
            for (m, c) in &form.0 {
                match m.iter().position(|&x| x == s) {
                    Some(i) => {
                        let mut rest = m.clone();
                        rest.remove(i);
                        b.0.insert(rest, c.clone());
                    }
                    None => {
                        a.0.insert(m.clone(), c.clone());
                    }
                }
            }
            let clear =
                |form: &NormalForm| form.enclosure().sign().filter(|&sign| sign != Sign::Zero);
            let next = match (clear(&a), clear(&b)) {
                (Some(x), Some(y)) if x != y => {
                    a.mul(&a).and_then(|a2| a2.add(&b.mul(&b)?.mul(&d)?, -1))
                }
                (None, None) if splits > 0 => {
                    return a.is_zero_by_elimination(splits - 1)
                        && b.is_zero_by_elimination(splits - 1);
                }
                _ => None,
            };
            let Some(next) = next else {
                return false;
            };
            form = next;
        }
    }
}

/// Whether the node's normal form is zero by the elimination of its square roots
/// ([`NormalForm::is_zero_by_elimination`]), over atoms where it has no normal form (see
/// [`zero_over_atoms`]). Costly: asked only of a zero that nothing else could prove. First
/// within the cheap budget; failing that, if `thorough`, with the budget of a last resort: the
/// normal form under it, else the form over atoms of the cheap budget, else the form over atoms
/// under it, where larger forms keep as expressions what were atoms.
pub(crate) fn zero_by_elimination(node: &Arc<Node>, thorough: bool) -> bool {
    let eliminated = |form: &NormalForm| form.is_zero_by_elimination(SPLIT_DEPTH);
    WORK_LEFT.with(|w| w.set(Budget::Cheap.work_per_test()));
    let cheap = memoized(node).unwrap_or_else(|| over_atoms(node));
    if eliminated(&cheap) {
        return true;
    }
    if !thorough {
        return false;
    }
    if let Some(form) = last_resort(|| memoized(node)) {
        return last_resort(|| eliminated(&form));
    }
    last_resort(|| eliminated(&cheap)) || last_resort(|| eliminated(&over_atoms(node)))
}

/// `work` with the budget of a last resort ([`Budget::LastResort`]), its multiplications
/// taken from what the run's last resorts have left ([`LAST_RESORT_WORK_PER_RUN`]).
fn last_resort<T>(work: impl FnOnce() -> T) -> T {
    let run_left = LAST_RESORT_WORK_LEFT.with(|w| w.get());
    let allowed = Budget::LastResort.work_per_test().min(run_left);
    BUDGET.with(|b| b.set(Budget::LastResort));
    WORK_LEFT.with(|w| w.set(allowed));
    let done = work();
    // Saturating: a zero test nested in the work (a radicand's sign) resets `WORK_LEFT`.
    let spent = allowed.saturating_sub(WORK_LEFT.with(|w| w.get()));
    LAST_RESORT_WORK_LEFT.with(|w| w.set(run_left - spent));
    BUDGET.with(|b| b.set(Budget::Cheap));
    done
}

/// Whether the node's normal form is zero, by [`NormalForm::is_zero_by_squares`] where its
/// symbols may not be independent.
pub(crate) fn zero_by_squares(node: &Arc<Node>) -> bool {
    WORK_LEFT.with(|w| w.set(Budget::Cheap.work_per_test()));
    memoized(node).is_some_and(|nf| nf.is_zero_by_squares(4))
}

/// The primes whose squares are taken out of an integer radicand and whose quadratic
/// characters make its square class ([`square_class`]).
const CLASS_PRIMES: [u32; 54] = [
    2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97,
    101, 103, 107, 109, 113, 127, 131, 137, 139, 149, 151, 157, 163, 167, 173, 179, 181, 191, 193,
    197, 199, 211, 223, 227, 229, 233, 239, 241, 251,
];

/// A key of the square class of a positive integer `m` without square factors of
/// [`CLASS_PRIMES`]: if `m m'` is a square, `m` and `m'` have the same key. For each of those
/// primes `p`, whether `p` divides `m` (then once: the same must hold of `m'`) or else whether
/// `m` is a square modulo `p` (Euler's criterion; the product of two residues or of two
/// non-residues is a residue), and `m mod 8` for 2 (odd squares are 1 mod 8). Different classes
/// share a key only by chance; a shared key is checked exactly.
fn square_class(m: &Integer) -> u64 {
    let mut key: u64 = u64::from(m.rem_small(8));
    for &p in &CLASS_PRIMES[1..] {
        let r = u64::from(m.rem_small(p));
        let bit = if r == 0 {
            2
        } else {
            // r^((p - 1) / 2) mod p is 1 for a residue, p - 1 otherwise.
            let (mut base, mut exp, mut acc) = (r, (p - 1) / 2, 1u64);
            while exp > 0 {
                if exp & 1 == 1 {
                    acc = acc * base % u64::from(p);
                }
                base = base * base % u64::from(p);
                exp >>= 1;
            }
            u64::from(acc == 1)
        };
        key = key.rotate_left(2) ^ bit;
    }
    key
}

impl NormalForm {
    /// The square root of `p + q M` (`p`, `q` rational, `M` a product of symbols whose square
    /// `D` is rational) when it denests: if `c = sqrt(p^2 - q^2 D)` is rational and `p > 0`,
    /// then `sqrt(p + q sqrt(D)) = sqrt((p + c) / 2) + sign(q) sqrt((p - c) / 2)`. Distances
    /// between points whose coordinates share radicals are often of this form (a point on a
    /// line through two others, a right angle), and their identities need the denested root.
    fn denested(&self) -> Option<NormalForm> {
        if self.0.len() != 2 {
            return None;
        }
        let p = self.0.get(&Vec::new())?;
        let (m, q) = self.0.iter().find(|(m, _)| !m.is_empty())?;
        let mut d = Rational::from(1);
        for &s in m {
            d = d * &square_of(s)?.as_rational()?;
        }
        if p.cmp0().is_le() {
            return None;
        }
        let c = rational_root(&(p.clone() * p - &(q.clone() * q * &d)))?;
        let half = Rational::new(Integer::from(1), Integer::from(2))?;
        let larger = sqrt_of_rational(&((p.clone() + &c) * &half));
        let smaller = sqrt_of_rational(&((p.clone() - &c) * &half));
        let sign = if q.cmp0().is_lt() { -1 } else { 1 };
        larger.add(&smaller, sign)
    }
}

/// `sqrt(p / q) = (f / q) sqrt(m)` with `p q = f^2 m` and the square factors of
/// [`CLASS_PRIMES`] taken out of `m`; radicals whose product is a square (equal up to a rational
/// factor: on a straight line, `|ac| = |ab| + |bc|` with three radicands of one class) share
/// one symbol, so that the normal form sees their identities.
fn sqrt_of_rational(r: &Rational) -> NormalForm {
    if r.cmp0().is_le() {
        return NormalForm::default();
    }
    let mut m = r.numer() * r.denom();
    let mut f = Integer::from(1);
    for p in CLASS_PRIMES {
        let p2 = Integer::from(i64::from(p * p));
        while m.is_divisible(&p2) {
            m = m.div_exact(&p2);
            f = f * Integer::from(i64::from(p));
        }
    }
    let over_denominator = |f: Integer| Rational::new(f, r.denom()).expect("a denominator");
    if m.is_perfect_square() {
        return NormalForm::rational(over_denominator(f * m.sqrt()));
    }
    let class = square_class(&m);
    let (id, factor) = TOWER.with(|t| {
        let mut t = t.borrow_mut();
        let same = t.integer_radicals.get(&class).and_then(|radicals| {
            radicals.iter().find_map(|(other, id)| {
                // sqrt(m) = sqrt(m m') / m' * sqrt(m'), with sqrt(m m') an integer.
                let product = m.clone() * other.clone();
                product
                    .is_perfect_square()
                    .then(|| (*id, Rational::new(product.sqrt(), other.clone())))
            })
        });
        match same {
            Some((id, factor)) => (id, factor.expect("a positive radicand")),
            None => {
                let enclosure = enclose(&Rational::from(m.clone())).sqrt();
                let id = t.push(
                    Some(NormalForm::rational(Rational::from(m.clone()))),
                    enclosure,
                );
                t.integer_radicals.entry(class).or_default().push((m, id));
                (id, Rational::from(1))
            }
        }
    });
    NormalForm::monomial(over_denominator(f) * &factor, vec![id])
}

/// The normal form of a node's value, memoized on the node; `None` if it grew too large or
/// a square root's radicand could not be shown positive.
pub(crate) fn normal_form(node: &Arc<Node>) -> Option<NormalForm> {
    WORK_LEFT.with(|w| w.set(Budget::Cheap.work_per_test()));
    memoized(node)
}

/// Whether the node's normal form over atoms is zero: every subexpression whose normal form
/// cannot be had (too large, or a square root of a radicand not shown positive) or has more
/// than [`ATOM_TERMS`] terms is an atom, an indeterminate. A zero there is zero for every value
/// of the atoms, so it proves the value zero (an atom is never divided by, and a square root
/// over atoms is a symbol only where its radicand is shown positive). Costly on deep
/// expressions: asked only of a zero that nothing else could prove.
pub(crate) fn zero_over_atoms(node: &Arc<Node>) -> bool {
    WORK_LEFT.with(|w| w.set(Budget::Cheap.work_per_test()));
    over_atoms(node).is_zero()
}

/// Normal forms over atoms larger than this make their node an atom: the local identities
/// need only a few terms above the atoms, and a smaller atom keeps the work per test small.
const ATOM_TERMS: usize = 64;

/// The node's normal form over atoms, memoized in this thread's tower; asked again under a
/// larger budget, which may expand what was an atom.
fn over_atoms(node: &Arc<Node>) -> NormalForm {
    let key = Arc::as_ptr(node) as usize;
    let budget = budget();
    let known = TOWER.with(|t| {
        let t = t.borrow();
        let (_, nf, had) = t.atom_forms.get(&key)?;
        (*had >= budget).then(|| nf.clone())
    });
    if let Some(nf) = known {
        return nf;
    }
    let pair =
        |a: &Arc<Node>, b: &Arc<Node>| [over_atoms(a), over_atoms(b)].map(|f| f.normalized());
    let nf = match compute_with(node, |child| Some(over_atoms(child))) {
        Some(nf) if nf.0.len() <= ATOM_TERMS => nf,
        Some(nf) => {
            let (lead, form) = nf.normalized();
            keyed_atom(AtomKey::Form(form)).scaled(&lead)
        }
        None => match &node.op {
            Op::Mul(a, b) => {
                let [(la, fa), (lb, fb)] = pair(a, b);
                let factors = if form_hash(&fa) <= form_hash(&fb) {
                    [fa, fb]
                } else {
                    [fb, fa]
                };
                keyed_atom(AtomKey::Product(factors)).scaled(&(la * &lb))
            }
            Op::Div(a, b) => {
                let [(la, fa), (lb, fb)] = pair(a, b);
                keyed_atom(AtomKey::Quotient([fa, fb])).scaled(&(la / &lb))
            }
            _ => atom(node),
        },
    };
    TOWER.with(|t| {
        t.borrow_mut()
            .atom_forms
            .insert(key, (node.clone(), nf.clone(), budget))
    });
    nf
}

/// What an atom stands for when it is known by forms over atoms: a value of that form, or the
/// product or quotient of two values of those forms, each form divided by its first
/// coefficient (the atom is then multiplied by it). Values with one key are equal, a zero
/// normal form being a proof, so they are one atom whichever nodes hold them.
#[derive(Clone, PartialEq, Eq, Hash)]
enum AtomKey {
    Form(NormalForm),
    Product([NormalForm; 2]),
    Quotient([NormalForm; 2]),
}

/// The atom of a key.
fn keyed_atom(key: AtomKey) -> NormalForm {
    let known = TOWER.with(|t| t.borrow().keyed_atoms.get(&key).copied());
    let id = known.unwrap_or_else(|| {
        let enclosure = match &key {
            AtomKey::Form(f) => f.enclosure(),
            AtomKey::Product([f, g]) => f.enclosure() * g.enclosure(),
            AtomKey::Quotient([f, g]) => f.enclosure() / g.enclosure(),
        };
        TOWER.with(|t| {
            let mut t = t.borrow_mut();
            let id = t.push(None, enclosure);
            t.keyed_atoms.insert(key, id);
            id
        })
    });
    NormalForm::monomial(Rational::from(1), vec![id])
}

/// A hash of a form: the order of a product's factors in its key.
fn form_hash(f: &NormalForm) -> u64 {
    use std::hash::{Hash, Hasher};
    let mut h = std::collections::hash_map::DefaultHasher::new();
    f.hash(&mut h);
    h.finish()
}

/// The atom standing for the node's value.
fn atom(node: &Arc<Node>) -> NormalForm {
    let key = Arc::as_ptr(node) as usize;
    let id = TOWER.with(|t| {
        let mut t = t.borrow_mut();
        if let Some((id, _)) = t.atoms.get(&key) {
            return *id;
        }
        let id = t.push(None, node.filter);
        t.atoms.insert(key, (id, node.clone()));
        id
    });
    NormalForm::monomial(Rational::from(1), vec![id])
}

/// The node's normal form in this thread's tower, memoized on the node with the tower's id
/// and the budget it had: a form abandoned under a smaller budget is asked again.
fn memoized(node: &Arc<Node>) -> Option<NormalForm> {
    let (tower, budget) = (tower_id(), budget());
    if let Some(memo) = node.normal_form.lock().expect("memo lock").as_ref() {
        if memo.tower == tower && (memo.form.is_some() || memo.budget >= budget) {
            return memo.form.clone();
        }
    }
    let form = compute(node);
    *node.normal_form.lock().expect("memo lock") = Some(Memo {
        tower,
        form: form.clone(),
        budget,
    });
    form
}

fn budget() -> Budget {
    BUDGET.with(|b| b.get())
}

fn compute(node: &Arc<Node>) -> Option<NormalForm> {
    compute_with(node, memoized)
}

/// The node's normal form from its children's, as `form` gives them.
fn compute_with(
    node: &Arc<Node>,
    form: impl Fn(&Arc<Node>) -> Option<NormalForm>,
) -> Option<NormalForm> {
    match &node.op {
        Op::Leaf(r) => Some(NormalForm::rational(r.clone())),
        Op::Add(a, b) => form(a)?.add(&form(b)?, 1),
        Op::Sub(a, b) => form(a)?.add(&form(b)?, -1),
        Op::Mul(a, b) => form(a)?.mul(&form(b)?),
        Op::Div(a, b) => form(a)?.div(&form(b)?),
        Op::Neg(a) => Some(form(a)?.neg()),
        Op::Sqrt(a) => {
            let radicand = form(a)?;
            // The node is sqrt(max(a, 0)): the symbol stands for it only if a > 0 (or a = 0).
            if radicand.is_zero() {
                return Some(NormalForm::default());
            }
            if a.filter.lo > 0.0 || super::Real(a.clone()).positive_without_zero_test() {
                // The node's refined enclosure (cached on it once a sign asked for it).
                radicand.sqrt(|| {
                    let (lo, hi) = super::refine::enclosure(node, super::FIRST_PRECISION);
                    let root = Interval {
                        lo: lo.to_f64(Round::Down),
                        hi: hi.to_f64(Round::Up),
                    };
                    root.meet(node.filter)
                })
            } else {
                None
            }
        }
        Op::Dropped => None,
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Field, Real};
    use super::*;

    fn root(i: i64) -> Real {
        Real::from_integer(i).sqrt()
    }

    /// `sqrt 7 (sqrt 3 sqrt(1 + sqrt 2) - sqrt(3 + 3 sqrt 2))` with `sqrt 7` the last symbol:
    /// zero, as `sqrt 7` times a zero of nested radicals (so not decided over a coprime basis of
    /// integer radicals) whose symbols are not independent. Its part free of `sqrt 7` is zero as
    /// it stands, so no sign tells it apart from the other part.
    fn zero_times_a_root(tiny: Real) -> Real {
        new_tower();
        let nested = |c: i64| (Real::from_integer(c) + &(Real::from_integer(c) * &root(2))).sqrt();
        let inner = root(3) * &nested(1) - &nested(3) + &tiny;
        let form = normal_form(&inner.0).expect("a normal form");
        assert!(!form.is_zero() && form.is_zero_over_coprime_radicals().is_none());
        root(7) * &inner
    }

    #[test]
    fn a_root_times_a_hidden_zero_is_proved_zero_by_elimination() {
        let zero = zero_times_a_root(Real::from_integer(0));
        assert!(normal_form(&zero.0).is_some_and(|form| !form.is_zero()));
        assert!(zero_by_elimination(&zero.0, true));
    }

    #[test]
    fn a_root_times_a_tiny_non_zero_is_not_proved_zero() {
        let tiny =
            Real::from_integer(1) / Real::from_rational(Rational::from(Integer::from(2).pow(200)));
        assert!(!zero_by_elimination(&zero_times_a_root(tiny).0, true));
    }

    /// `(1 + sqrt 2)(1 + sqrt 3) ... (1 + sqrt 23)` over the first nine primes, multiplied in
    /// one order and in the other, less one another: zero, with a normal form of 512 terms
    /// (past the cheap budget's 256), in a new tower.
    fn binomials_multiplied_two_ways() -> Real {
        new_tower();
        let primes = [2, 3, 5, 7, 11, 13, 17, 19, 23];
        let factor = |p: &i64| Real::from_integer(1) + &root(*p);
        let product = |x: Real, p: &i64| x * &factor(p);
        let forwards = primes.iter().fold(Real::from_integer(1), product);
        let backwards = primes.iter().rev().fold(Real::from_integer(1), product);
        forwards - &backwards
    }

    /// The last resorts of one run share a reserve: spent, a zero that only a last resort
    /// proves is left unproved; a new run (a new tower) has the whole reserve again.
    #[test]
    fn the_last_resorts_of_a_run_stop_when_its_reserve_is_spent() {
        let zero = binomials_multiplied_two_ways();
        assert!(normal_form(&zero.0).is_none());
        LAST_RESORT_WORK_LEFT.with(|w| w.set(0));
        assert!(!zero_by_elimination(&zero.0, true));
        let zero = binomials_multiplied_two_ways();
        assert!(zero_by_elimination(&zero.0, true));
        let left = LAST_RESORT_WORK_LEFT.with(|w| w.get());
        assert!(left < LAST_RESORT_WORK_PER_RUN && left > 0);
    }

    /// `sqrt(2 + 10^-900 sqrt(10^200 + 1) sqrt(10^200 + 3) sqrt(10^200 + 7) sqrt(10^200 + 9))`:
    /// the radicand's form is two terms, one of a coefficient below `f64`'s range times radicals
    /// above it, so its `f64` enclosure is the whole line; the root's symbol takes the node's
    /// refined enclosure, and its sign (which the elimination of square roots reads) is clear.
    #[test]
    fn a_root_whose_radicand_overflows_f64_has_a_clear_sign() {
        new_tower();
        let big = |k: i64| {
            let n = Integer::from(10).pow(200) + Integer::from(k);
            Real::from_rational(Rational::from(n)).sqrt()
        };
        let tiny =
            Real::from_integer(1) / Real::from_rational(Rational::from(Integer::from(10).pow(900)));
        let radicand = Real::from_integer(2) + &(tiny * &big(1) * &big(3) * &big(7) * &big(9));
        let form = normal_form(&radicand.0).expect("a normal form");
        assert_eq!(form.enclosure().sign(), None);
        let root = normal_form(&radicand.sqrt().0).expect("a normal form");
        assert_eq!(root.enclosure().sign(), Some(Sign::Positive));
    }

    /// `(sqrt 2 / 2 + sqrt 3 / 3 + 1 / 5)^2`, expanded by hand: products of unequal
    /// denominators fall on the rational term (`1/2 + 1/3 + 1/25 = 131/150`), one product
    /// on each other monomial.
    #[test]
    fn a_square_sums_the_products_that_fall_on_one_monomial() {
        new_tower();
        let q = |n: i64, d: i64| {
            Real::from_rational(Rational::new(Integer::from(n), Integer::from(d)).expect("d > 0"))
        };
        let x = q(1, 2) * &root(2) + &(q(1, 3) * &root(3)) + &q(1, 5);
        let expanded = q(131, 150)
            + &(q(1, 3) * &root(2) * &root(3))
            + &(q(1, 5) * &root(2))
            + &(q(2, 15) * &root(3));
        let square = normal_form(&(x.clone() * &x).0).expect("a normal form");
        assert_eq!(Some(square), normal_form(&expanded.0));
    }
}
