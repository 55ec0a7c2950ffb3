//! The checker of Property 2 [LZT §3]: final wedges on an edge do not overlap, and together they
//! cover every reached edge.

use super::field::GeodesicField;
use crate::mesh::EdgeId;
use crate::scalar::Scalar;
use serde::Serialize;

/// One place where the final wedges of an edge fail to tile it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum CoverageIssue {
    /// Two consecutive wedges overlap on `[from, to]`.
    Overlap {
        /// The edge.
        edge: EdgeId,
        /// Start of the overlap, from the edge's `vertices[0]`.
        from: f64,
        /// End of the overlap.
        to: f64,
    },
    /// No wedge covers `[from, to]` of an edge that some wedge reached.
    Gap {
        /// The edge.
        edge: EdgeId,
        /// Start of the gap.
        from: f64,
        /// End of the gap.
        to: f64,
    },
}

/// The result of checking Property 2 on every edge.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct CoverageReport {
    /// Edges that carry at least one wedge.
    pub edges_reached: usize,
    /// Every overlap and gap found.
    pub issues: Vec<CoverageIssue>,
}

impl CoverageReport {
    /// The longest gap as a fraction of its edge's length (0 if there is none).
    pub fn largest_gap_fraction<S: Scalar>(&self, field: &GeodesicField<'_, S>) -> f64 {
        self.issues
            .iter()
            .filter_map(|issue| match issue {
                CoverageIssue::Gap { edge, from, to } => {
                    Some((to - from) / field.edge_length(*edge).to_f64())
                }
                CoverageIssue::Overlap { .. } => None,
            })
            .fold(0.0, f64::max)
    }

    /// Whether any two wedges overlap.
    pub fn has_overlaps(&self) -> bool {
        self.issues
            .iter()
            .any(|i| matches!(i, CoverageIssue::Overlap { .. }))
    }
}

impl<S: Scalar> GeodesicField<'_, S> {
    /// Checks Property 2: on every edge that some wedge reached, the final wedges are sorted,
    /// pairwise disjoint and cover the edge from end to end. A gap or overlap counts if the
    /// backend would keep a wedge that long ([`Scalar::has_extent`]).
    pub fn check_coverage(&self) -> CoverageReport {
        let mut report = CoverageReport::default();
        for (i, wedges) in self.wedges.per_edge().enumerate() {
            if wedges.is_empty() {
                continue;
            }
            report.edges_reached += 1;
            let edge = EdgeId(i as u32);
            let length = self.unfolding.length(edge);
            let model = |x: &S| self.unfolding.to_model(x.to_f64());
            let mut reached = S::zero();
            for w in wedges {
                if S::has_extent(&reached, &w.b0, length) {
                    report.issues.push(CoverageIssue::Gap {
                        edge,
                        from: model(&reached),
                        to: model(&w.b0),
                    });
                } else if S::has_extent(&w.b0, &reached, length) {
                    report.issues.push(CoverageIssue::Overlap {
                        edge,
                        from: model(&w.b0),
                        to: model(&S::min_of(&reached, &w.b1)),
                    });
                }
                reached = S::max_of(&reached, &w.b1);
            }
            if S::has_extent(&reached, length, length) {
                report.issues.push(CoverageIssue::Gap {
                    edge,
                    from: model(&reached),
                    to: model(length),
                });
            }
        }
        report
    }
}
