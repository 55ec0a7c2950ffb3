//! The decision counters of certifying backends, kept per thread: the engine runs one
//! propagation on one thread, and reads them through [`Scalar::take_counts`](super::Scalar).

use serde::Serialize;
use std::cell::{Cell, RefCell};

/// Where the engine takes a decision: the edge (by index, when there is one) and what it is
/// deciding.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub struct Site {
    /// The edge whose wedges are being decided, if any.
    pub edge: Option<u32>,
    /// What is being decided, in the paper's words (e.g. "eq. (2) on a shared range").
    pub what: &'static str,
}

impl Site {
    /// No particular place (queries after the propagation).
    pub const ANYWHERE: Site = Site {
        edge: None,
        what: "query",
    };
}

/// A decision a backend could not certify: within its precision cap, or at all.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DecisionSite {
    /// Where the engine took it.
    pub site: Site,
    /// Why it is uncertified.
    pub cause: Uncertainty,
    /// An enclosure of the value whose sign was asked, as `f64` bounds (infinite when the value
    /// divides by zero).
    pub enclosure: [f64; 2],
}

/// Why a sign is not certified.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Uncertainty {
    /// Refinement reached the precision cap (the bits reached) without excluding zero or
    /// proving it: the value is within `2^-cap` of zero.
    PrecisionCap(u32),
    /// The value divides by zero: a divisor in its expression is zero (the value is undefined
    /// and has no sign). No precision settles it.
    DivisionByZero,
}

/// How a backend settled the decisions of one run.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
#[non_exhaustive]
pub struct DecisionCounts {
    /// Decisions asked of the backend.
    pub decisions: u64,
    /// Settled by the floating-point filter (an `f64` interval or error bound).
    pub by_filter: u64,
    /// Settled by the exact stage: exact rationals, or multiple-precision intervals refined
    /// until they exclude zero.
    pub by_refinement: u64,
    /// Values proved to be exactly zero by the exact stage (a separation bound or a symbolic
    /// identity); a zero the filter sees as the point interval `[0, 0]` counts as filtered.
    pub certified_zeros: u64,
    /// Of those, proved by structure: the difference of two copies of one expression, or a
    /// product with zero.
    pub zeros_by_structure: u64,
    /// Of those, proved by exact rational evaluation (no square root below them).
    pub zeros_by_rational_value: u64,
    /// Of those, proved by a zero normal form in a tower of quadratic extensions.
    pub zeros_by_normal_form: u64,
    /// Of those, proved by an enclosure below the BFMSS separation bound.
    pub zeros_by_separation_bound: u64,
    /// Decisions not certified: not within the precision cap, or of a value that divides by zero
    /// (reported, never passed off as exact).
    pub uncertified: u64,
    /// The first uncertified decisions, with their places.
    pub uncertified_sites: Vec<DecisionSite>,
}

/// How many uncertified decisions keep their place in [`DecisionCounts::uncertified_sites`].
const KEPT_SITES: usize = 64;

/// How the sign of a value was established.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Certificate {
    /// A floating-point filter excluded zero (or was the point zero).
    Filter,
    /// The exact stage: exact rationals, or a refined interval that excluded zero.
    Refinement,
    /// Proved zero, by the proof given.
    CertifiedZero(ZeroProof),
    /// Not established, for the reason given; the sign given is zero.
    Uncertified(Uncertainty),
}

/// How a zero was proved.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ZeroProof {
    /// The value is `x - x` for two copies of one expression `x` (or a product with zero):
    /// an identity the algorithm built, proved without evaluating it.
    Structure,
    /// Exact rational evaluation: no square root occurs in the value.
    RationalValue,
    /// The value's normal form in a tower of quadratic extensions is zero.
    NormalForm,
    /// An enclosure of the value lies below the BFMSS separation bound \[BFMSS01\], which no
    /// non-zero value of its expression can.
    SeparationBound,
}

impl DecisionCounts {
    /// Adds the counts of another run (one that went on beside this one on another thread);
    /// its sites join this one's as far as there is room.
    pub(crate) fn absorb(&mut self, other: DecisionCounts) {
        self.decisions += other.decisions;
        self.by_filter += other.by_filter;
        self.by_refinement += other.by_refinement;
        self.certified_zeros += other.certified_zeros;
        self.zeros_by_structure += other.zeros_by_structure;
        self.zeros_by_rational_value += other.zeros_by_rational_value;
        self.zeros_by_normal_form += other.zeros_by_normal_form;
        self.zeros_by_separation_bound += other.zeros_by_separation_bound;
        self.uncertified += other.uncertified;
        let room = KEPT_SITES.saturating_sub(self.uncertified_sites.len());
        self.uncertified_sites
            .extend(other.uncertified_sites.into_iter().take(room));
    }
}

impl Certificate {
    /// Whether the sign is proved.
    pub fn is_certified(self) -> bool {
        !matches!(self, Certificate::Uncertified(_))
    }
}

thread_local! {
    static COUNTS: RefCell<DecisionCounts> = RefCell::new(DecisionCounts::default());
    static SITE: Cell<Site> = const { Cell::new(Site::ANYWHERE) };
}

pub(crate) fn locate(site: Site) {
    SITE.with(|s| s.set(site));
}

/// Counts one decision; `enclosure` is only read for uncertified ones.
pub(crate) fn record(settled: Certificate, enclosure: impl FnOnce() -> [f64; 2]) {
    COUNTS.with(|c| {
        let mut c = c.borrow_mut();
        c.decisions += 1;
        match settled {
            Certificate::Filter => c.by_filter += 1,
            Certificate::Refinement => c.by_refinement += 1,
            Certificate::CertifiedZero(proof) => {
                c.certified_zeros += 1;
                match proof {
                    ZeroProof::Structure => c.zeros_by_structure += 1,
                    ZeroProof::RationalValue => c.zeros_by_rational_value += 1,
                    ZeroProof::NormalForm => c.zeros_by_normal_form += 1,
                    ZeroProof::SeparationBound => c.zeros_by_separation_bound += 1,
                }
            }
            Certificate::Uncertified(cause) => {
                c.uncertified += 1;
                if c.uncertified_sites.len() < KEPT_SITES {
                    let site = SITE.with(Cell::get);
                    c.uncertified_sites.push(DecisionSite {
                        site,
                        cause,
                        enclosure: enclosure(),
                    });
                }
            }
        }
    });
}

pub(crate) fn take() -> DecisionCounts {
    COUNTS.with(|c| std::mem::take(&mut *c.borrow_mut()))
}
