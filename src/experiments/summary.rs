//! Moments and extremes of a sample: how Tables 1-2 [LZT §6] summarize w(e) and l(e), each
//! regarded as a random variable over the edges of a model.

use serde::Serialize;

/// Mean, standard deviation, skewness, minimum and maximum of a sample of `count` values.
///
/// The moments are the *population* ones (divided by `count`, not `count - 1`): the sample is
/// every edge (or face) of the model, not a draw from a larger set. With
/// `m_k = (1/n) sum (x_i - mean)^k`: `std = sqrt(m_2)` and `skewness = m_3 / m_2^(3/2)`
/// (Fisher's g1, without the small-sample correction). A constant sample has skewness 0.
///
/// # Example
/// ```
/// use exact_geodesics::experiments::Summary;
/// let s = Summary::of(&[1.0, 2.0, 3.0, 4.0]).expect("not empty");
/// assert_eq!(s.mean, 2.5);
/// assert_eq!(s.std, 1.25f64.sqrt());
/// assert_eq!((s.min, s.max, s.skewness), (1.0, 4.0, 0.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Summary {
    /// Number of values.
    pub count: usize,
    /// Arithmetic mean.
    pub mean: f64,
    /// Population standard deviation `sqrt(m_2)`.
    pub std: f64,
    /// Population skewness `m_3 / m_2^(3/2)`; 0 when every value is the same.
    pub skewness: f64,
    /// Smallest value.
    pub min: f64,
    /// Largest value.
    pub max: f64,
}

impl Summary {
    /// The summary of `values`, or `None` if there are none. Values are expected to be finite
    /// (edge lengths, angles, wedge counts); a NaN or infinity makes the moments NaN or infinite.
    pub fn of(values: &[f64]) -> Option<Summary> {
        if values.is_empty() {
            return None;
        }
        let n = values.len() as f64;
        let mean = values.iter().sum::<f64>() / n;
        let central = |k: i32| values.iter().map(|x| (x - mean).powi(k)).sum::<f64>() / n;
        let (m2, m3) = (central(2), central(3));
        let skewness = if m2 > 0.0 { m3 / m2.powf(1.5) } else { 0.0 };
        Some(Summary {
            count: values.len(),
            mean,
            std: m2.sqrt(),
            skewness,
            min: values.iter().copied().fold(f64::INFINITY, f64::min),
            max: values.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn empty_sample_has_no_summary() {
        assert_eq!(Summary::of(&[]), None);
    }

    #[test]
    fn skewness_of_one_outlier_is_two_over_root_three() {
        // mean 1/4, m2 = 3/16, m3 = 3/32: g1 = (3/32) / (3/16)^(3/2) = 2/sqrt(3).
        let s = Summary::of(&[0.0, 0.0, 0.0, 1.0]).expect("not empty");
        assert!((s.skewness - 2.0 / 3f64.sqrt()).abs() < 1e-12);
        assert!((s.std - (3.0f64 / 16.0).sqrt()).abs() < 1e-15);
    }

    #[test]
    fn constant_sample_has_zero_spread_and_skewness() {
        let s = Summary::of(&[7.0; 5]).expect("not empty");
        assert_eq!((s.mean, s.std, s.skewness, s.count), (7.0, 0.0, 0.0, 5));
    }
}
