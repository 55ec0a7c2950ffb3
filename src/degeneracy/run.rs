//! Running the corpus: many seeded cases, round-robin over the kinds, each checked by
//! [`check_invariants`] in one backend against a reference backend, with panics caught and
//! counted, and a serializable summary.

use super::generate::{degenerate_case, DegenerateKind, MeshSize};
use super::invariants::{check_invariants, Tolerances, Violation, ViolationKind};
use crate::mesh::shapes::SplitMix64;
use crate::mesh::{ValidationReport, VertexId};
pub use crate::scalar::Backend;
use crate::scalar::{Adaptive, Real};
use serde::Serialize;
use std::any::Any;
use std::collections::BTreeMap;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::Instant;

/// What the corpus does in each backend: `f64` is checked against [`Adaptive`], the others
/// against `f64`; [`Real`] (exact) runs on [`MeshSize::Small`] meshes.
impl Backend {
    /// The backend whose vertex distances this one's are compared with.
    pub fn reference(self) -> Backend {
        match self {
            Backend::F64 => Backend::Adaptive,
            Backend::Adaptive | Backend::Exact => Backend::F64,
        }
    }

    /// The size of the meshes this backend is run on.
    pub fn mesh_size(self) -> MeshSize {
        match self {
            Backend::F64 | Backend::Adaptive => MeshSize::Full,
            Backend::Exact => MeshSize::Small,
        }
    }

    /// The tolerances of its checks.
    pub fn tolerances(self) -> Tolerances {
        match self {
            Backend::F64 | Backend::Adaptive => Tolerances::FLOAT,
            Backend::Exact => Tolerances::EXACT,
        }
    }
}

/// The outcome of one case.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CaseReport {
    /// The kind of mesh.
    pub mesh_kind: DegenerateKind,
    /// The mesh's seed: `degenerate_case(mesh_kind, seed, backend.mesh_size())` rebuilds it.
    pub seed: u64,
    /// The first source.
    pub source: VertexId,
    /// The second source (the target of the symmetry check).
    pub other: VertexId,
    /// What was broken (a panic anywhere in the case is one [`ViolationKind::Panic`]).
    pub violations: Vec<Violation>,
    /// Decisions the backend could not certify (exact backend only).
    pub uncertified_decisions: u64,
    /// Whether the mesh's edge lengths span more than [`ValidationReport::WIDE_SPAN`] (slivers,
    /// mixed magnitudes), which the mesh report warns of; counted to show that the corpus
    /// covers such meshes, which are held to every invariant as any other.
    pub beyond_float_range: bool,
}

/// Generates the mesh of `(mesh_kind, seed)` at the backend's size, picks two sources (the
/// first at the degeneracy half of the time) and checks every invariant, catching panics.
///
/// # Example
/// ```
/// use exact_geodesics::degeneracy::{run_case, Backend, DegenerateKind};
/// let report = run_case(Backend::F64, DegenerateKind::Components, 11);
/// assert_eq!(report.mesh_kind, DegenerateKind::Components);
/// ```
pub fn run_case(backend: Backend, mesh_kind: DegenerateKind, seed: u64) -> CaseReport {
    run_case_of_size(backend, mesh_kind, seed, backend.mesh_size())
}

/// [`run_case`] on a mesh of the given size instead of the backend's.
pub fn run_case_of_size(
    backend: Backend,
    mesh_kind: DegenerateKind,
    seed: u64,
    size: MeshSize,
) -> CaseReport {
    let mut rng = SplitMix64::new(seed.rotate_left(17) ^ 0x5eed);
    let mut report = CaseReport {
        mesh_kind,
        seed,
        source: VertexId(0),
        other: VertexId(0),
        violations: Vec::new(),
        uncertified_decisions: 0,
        beyond_float_range: false,
    };
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        let case = degenerate_case(mesh_kind, seed, size);
        let n = case.mesh.vertex_count() as u64;
        let mut vertex = |focus_chance: f64| {
            if !case.focus.is_empty() && rng.next_f64() < focus_chance {
                case.focus[(rng.next_u64() % case.focus.len() as u64) as usize]
            } else {
                VertexId((rng.next_u64() % n) as u32)
            }
        };
        let (a, b) = (vertex(0.5), vertex(0.3));
        report.source = a;
        report.other = b;
        let probe_seed = rng.next_u64();
        let tolerances = backend.tolerances();
        let mesh = &case.mesh;
        let beyond = mesh.validation().edge_length_span > ValidationReport::WIDE_SPAN;
        let found = match backend {
            Backend::F64 => check_invariants::<f64, Adaptive>(mesh, a, b, probe_seed, &tolerances),
            Backend::Adaptive => {
                check_invariants::<Adaptive, f64>(mesh, a, b, probe_seed, &tolerances)
            }
            Backend::Exact => check_invariants::<Real, f64>(mesh, a, b, probe_seed, &tolerances),
        };
        (found, beyond)
    }));
    match outcome {
        Ok((found, beyond)) => {
            report.violations = found.violations;
            report.uncertified_decisions = found.uncertified_decisions;
            report.beyond_float_range = beyond;
        }
        Err(payload) => report.violations.push(Violation {
            kind: ViolationKind::Panic,
            detail: format!(
                "from {} and {}: {}",
                report.source,
                report.other,
                panic_message(payload.as_ref())
            ),
            occurrences: 1,
        }),
    }
    report
}

/// The message a panic was raised with.
fn panic_message(payload: &(dyn Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic without a message".to_string())
}

/// How far [`run_corpus`] got, for a progress bar.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CorpusProgress {
    /// Cases run.
    pub done: u64,
    /// Cases in all.
    pub total: u64,
    /// Cases with at least one violation so far.
    pub failing: u64,
}

/// The cases of one mesh kind.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct MeshKindTally {
    /// Cases run.
    pub cases: u64,
    /// Cases with at least one violation.
    pub cases_with_violations: u64,
    /// Cases breaking each invariant.
    pub violations_by_kind: BTreeMap<ViolationKind, u64>,
}

/// One violation with the case that shows it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CaseViolation {
    /// The kind of mesh.
    pub mesh_kind: DegenerateKind,
    /// The mesh's seed.
    pub seed: u64,
    /// The first source.
    pub source: VertexId,
    /// The second source.
    pub other: VertexId,
    /// The invariant.
    pub kind: ViolationKind,
    /// The first failure.
    pub detail: String,
    /// How many times it failed in the case.
    pub occurrences: usize,
}

/// The most examples a [`CorpusSummary`] keeps.
const KEPT_EXAMPLES: usize = 50;

/// The result of [`run_corpus`].
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CorpusSummary {
    /// The backend under test.
    pub backend: Backend,
    /// The backend its vertex distances were compared with.
    pub reference: Backend,
    /// The size of the meshes.
    pub mesh_size: MeshSize,
    /// Cases run.
    pub cases: u64,
    /// The corpus seed.
    pub seed: u64,
    /// Wall-clock seconds.
    pub seconds: f64,
    /// Cases with at least one violation.
    pub cases_with_violations: u64,
    /// Cases breaking each invariant.
    pub violations_by_kind: BTreeMap<ViolationKind, u64>,
    /// The same, per kind of mesh.
    pub cases_by_mesh_kind: BTreeMap<DegenerateKind, MeshKindTally>,
    /// Decisions the backend could not certify, over all cases (exact backend only).
    pub uncertified_decisions: u64,
    /// Cases whose mesh's edge lengths span more than
    /// [`ValidationReport::WIDE_SPAN`](crate::mesh::ValidationReport::WIDE_SPAN)
    /// ([`CaseReport::beyond_float_range`]).
    pub cases_beyond_float_range: u64,
    /// The first case of each pair (mesh kind, invariant) that failed, in order, at most 50.
    pub first_violations: Vec<CaseViolation>,
}

/// Runs `cases` cases in `backend`, the `i`-th on kind `DegenerateKind::ALL[i % 10]` with a
/// seed drawn from `seed`; calls `progress` after each case.
///
/// # Example
/// ```
/// use exact_geodesics::degeneracy::{run_corpus, Backend};
/// let summary = run_corpus(Backend::F64, 3, 0, |_| {});
/// assert_eq!(summary.cases, 3);
/// assert_eq!(summary.cases_by_mesh_kind.len(), 3);
/// ```
pub fn run_corpus(
    backend: Backend,
    cases: u64,
    seed: u64,
    mut progress: impl FnMut(&CorpusProgress),
) -> CorpusSummary {
    let started = Instant::now();
    let mut seeds = SplitMix64::new(seed);
    let mut summary = CorpusSummary {
        backend,
        reference: backend.reference(),
        mesh_size: backend.mesh_size(),
        cases,
        seed,
        seconds: 0.0,
        cases_with_violations: 0,
        violations_by_kind: BTreeMap::new(),
        cases_by_mesh_kind: BTreeMap::new(),
        uncertified_decisions: 0,
        cases_beyond_float_range: 0,
        first_violations: Vec::new(),
    };
    let kinds = DegenerateKind::ALL;
    for i in 0..cases {
        let kind = kinds[(i % kinds.len() as u64) as usize];
        let report = run_case(backend, kind, seeds.next_u64());
        summary.add(&report);
        progress(&CorpusProgress {
            done: i + 1,
            total: cases,
            failing: summary.cases_with_violations,
        });
    }
    summary.seconds = started.elapsed().as_secs_f64();
    summary
}

impl CorpusSummary {
    fn add(&mut self, report: &CaseReport) {
        self.uncertified_decisions += report.uncertified_decisions;
        self.cases_beyond_float_range += u64::from(report.beyond_float_range);
        let tally = self.cases_by_mesh_kind.entry(report.mesh_kind).or_default();
        tally.cases += 1;
        if report.violations.is_empty() {
            return;
        }
        tally.cases_with_violations += 1;
        self.cases_with_violations += 1;
        for v in &report.violations {
            *tally.violations_by_kind.entry(v.kind).or_default() += 1;
            *self.violations_by_kind.entry(v.kind).or_default() += 1;
            let seen = self
                .first_violations
                .iter()
                .any(|e| e.mesh_kind == report.mesh_kind && e.kind == v.kind);
            if !seen && self.first_violations.len() < KEPT_EXAMPLES {
                self.first_violations.push(CaseViolation {
                    mesh_kind: report.mesh_kind,
                    seed: report.seed,
                    source: report.source,
                    other: report.other,
                    kind: v.kind,
                    detail: v.detail.clone(),
                    occurrences: v.occurrences,
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn report(mesh_kind: DegenerateKind, kinds: &[ViolationKind]) -> CaseReport {
        CaseReport {
            mesh_kind,
            seed: 1,
            source: VertexId(0),
            other: VertexId(1),
            violations: kinds
                .iter()
                .map(|&kind| Violation {
                    kind,
                    detail: String::new(),
                    occurrences: 1,
                })
                .collect(),
            uncertified_decisions: 2,
            beyond_float_range: false,
        }
    }

    #[test]
    fn a_caught_panic_keeps_its_message() {
        let payload = catch_unwind(|| panic!("lost at {}", 7)).expect_err("panics");
        assert_eq!(panic_message(payload.as_ref()), "lost at 7");
        let payload = catch_unwind(|| panic!("static")).expect_err("panics");
        assert_eq!(panic_message(payload.as_ref()), "static");
    }

    #[test]
    fn summary_counts_cases_per_invariant_and_keeps_one_example_per_pair() {
        let mut summary = run_corpus(Backend::F64, 0, 0, |_| {});
        let flat = DegenerateKind::FlatGrid;
        summary.add(&report(
            flat,
            &[ViolationKind::Asymmetric, ViolationKind::TraceLength],
        ));
        summary.add(&report(flat, &[ViolationKind::Asymmetric]));
        summary.add(&report(DegenerateKind::Bowtie, &[]));
        assert_eq!(summary.cases_with_violations, 2);
        assert_eq!(summary.violations_by_kind[&ViolationKind::Asymmetric], 2);
        assert_eq!(summary.cases_by_mesh_kind[&flat].cases_with_violations, 2);
        assert_eq!(summary.cases_by_mesh_kind[&DegenerateKind::Bowtie].cases, 1);
        assert_eq!(summary.first_violations.len(), 2);
        assert_eq!(summary.uncertified_decisions, 6);
    }
}
