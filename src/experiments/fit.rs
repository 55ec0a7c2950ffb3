//! A least-squares line with a confidence interval for its slope: how Observation 3 [LZT §6]
//! is tested, as the exponent of a power law `w/l ~ l^slope` fitted on log-log axes.

use serde::Serialize;

/// The confidence level of [`LineFit::slope_ci95`].
pub const CONFIDENCE: f64 = 0.95;

/// The ordinary least-squares line `y = intercept + slope x` through `n` points, with the
/// standard error of the slope and its 95 % confidence interval.
///
/// With `Sxx = sum (x - mean x)^2`, `Sxy = sum (x - mean x)(y - mean y)`: `slope = Sxy / Sxx`,
/// `intercept = mean y - slope mean x`, the residual variance `s^2 = SSE / (n - 2)`, the
/// standard error `se = sqrt(s^2 / Sxx)`, and the interval `slope ± t se` with `t` the
/// two-sided 95 % critical value of Student's t with `n - 2` degrees of freedom
/// ([`student_t_critical`]), as the textbook interval under independent normal errors.
///
/// # Example
/// ```
/// use exact_geodesics::experiments::LineFit;
/// // y = 1 + 2x exactly: the slope is 2 with no error.
/// let fit = LineFit::of(&[0.0, 1.0, 2.0, 3.0], &[1.0, 3.0, 5.0, 7.0]).expect("3+ points");
/// assert_eq!((fit.slope, fit.intercept, fit.slope_std_error), (2.0, 1.0, 0.0));
/// assert_eq!(fit.slope_ci95, [2.0, 2.0]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct LineFit {
    /// Number of points.
    pub points: usize,
    /// Fitted slope.
    pub slope: f64,
    /// Fitted intercept (the value at `x = 0`).
    pub intercept: f64,
    /// Standard error of the slope.
    pub slope_std_error: f64,
    /// The 95 % confidence interval of the slope, `[low, high]`.
    pub slope_ci95: [f64; 2],
}

impl LineFit {
    /// The fit of the points `(x[i], y[i])`, or `None` if there are fewer than three (no
    /// residual degree of freedom), the slices differ in length, a value is not finite, or all
    /// `x` are equal.
    pub fn of(x: &[f64], y: &[f64]) -> Option<LineFit> {
        let n = x.len();
        if n < 3 || y.len() != n || x.iter().chain(y).any(|v| !v.is_finite()) {
            return None;
        }
        let mean = |v: &[f64]| v.iter().sum::<f64>() / n as f64;
        let (mx, my) = (mean(x), mean(y));
        let sxx: f64 = x.iter().map(|a| (a - mx).powi(2)).sum();
        if sxx == 0.0 {
            return None;
        }
        let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
        let slope = sxy / sxx;
        let intercept = my - slope * mx;
        let sse: f64 = x
            .iter()
            .zip(y)
            .map(|(a, b)| (b - intercept - slope * a).powi(2))
            .sum();
        let df = (n - 2) as u32;
        let slope_std_error = (sse / f64::from(df) / sxx).sqrt();
        let half = student_t_critical(CONFIDENCE, df).expect("0 < CONFIDENCE < 1, df >= 1")
            * slope_std_error;
        Some(LineFit {
            points: n,
            slope,
            intercept,
            slope_std_error,
            slope_ci95: [slope - half, slope + half],
        })
    }
}

/// The two-sided critical value of Student's t distribution with `df` degrees of freedom: the
/// `t >= 0` with `P(|T| <= t) = confidence`. `None` unless `0 < confidence < 1` and `df >= 1`.
///
/// `P(|T| <= t)` is computed in closed form (Abramowitz and Stegun 26.7.3-4): with
/// `theta = atan(t / sqrt(df))`, for odd `df`
/// `(2/pi) (theta + sin theta (cos theta + (2/3) cos^3 theta + ... + (2·4···(df-3))/(1·3···(df-2)) cos^(df-2) theta))`
/// and for even `df`
/// `sin theta (1 + (1/2) cos^2 theta + ... + (1·3···(df-3))/(2·4···(df-2)) cos^(df-2) theta)`;
/// it increases with `theta`, which is found by bisection on `[0, pi/2]` to the last bit.
///
/// # Example
/// ```
/// use exact_geodesics::experiments::student_t_critical;
/// // df = 2: P(|T| <= t) = sin theta, so t = sqrt(2) tan(asin 0.95) = 4.3027.
/// let t = student_t_critical(0.95, 2).expect("in range");
/// assert!((t - 2f64.sqrt() * 0.95 / (1.0f64 - 0.95 * 0.95).sqrt()).abs() < 1e-12);
/// assert_eq!(student_t_critical(1.0, 2), None);
/// ```
pub fn student_t_critical(confidence: f64, df: u32) -> Option<f64> {
    if !(confidence > 0.0 && confidence < 1.0) || df == 0 {
        return None;
    }
    let (mut lo, mut hi) = (0.0f64, std::f64::consts::FRAC_PI_2);
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if t_within(mid, df) < confidence {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(f64::from(df).sqrt() * (0.5 * (lo + hi)).tan())
}

/// `P(|T| <= sqrt(df) tan theta)` for Student's t with `df` degrees of freedom (see
/// [`student_t_critical`]).
fn t_within(theta: f64, df: u32) -> f64 {
    let (sin, cos) = theta.sin_cos();
    let cos2 = cos * cos;
    if df % 2 == 0 {
        // 1 + (1/2) c^2 + (1·3)/(2·4) c^4 + ..., (df - 2) / 2 terms after the first.
        let mut term = 1.0;
        let mut sum = 1.0;
        for j in 1..df / 2 {
            term *= f64::from(2 * j - 1) / f64::from(2 * j) * cos2;
            sum += term;
        }
        sin * sum
    } else {
        // c + (2/3) c^3 + (2·4)/(3·5) c^5 + ..., (df - 1) / 2 terms in all (none for df = 1).
        let mut term = cos;
        let mut sum = 0.0;
        for j in 0..(df - 1) / 2 {
            if j > 0 {
                term *= f64::from(2 * j) / f64::from(2 * j + 1) * cos2;
            }
            sum += term;
        }
        std::f64::consts::FRAC_2_PI * (theta + sin * sum)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn t_critical_values_by_hand() {
        // df = 1 (Cauchy): P(|T| <= t) = 2 theta / pi, so t = tan(0.95 pi / 2) = 12.7062.
        let t1 = student_t_critical(0.95, 1).expect("in range");
        assert!((t1 - (0.95 * std::f64::consts::FRAC_PI_2).tan()).abs() < 1e-10);
        // df = 3: (2/pi)(theta + sin theta cos theta) = 0.95 at t = 3.182446 (printed tables).
        let t3 = student_t_critical(0.95, 3).expect("in range");
        assert!((t3 - 3.182_446_305).abs() < 1e-8, "{t3}");
        // df = 4: sin theta (1 + cos^2 theta / 2) = 0.95 at t = 2.776445 (printed tables).
        let t4 = student_t_critical(0.95, 4).expect("in range");
        assert!((t4 - 2.776_445_105).abs() < 1e-8, "{t4}");
        // Tables: df = 10: 2.228139; df = 30: 2.042272; large df tends to 1.959964.
        let t10 = student_t_critical(0.95, 10).expect("in range");
        assert!((t10 - 2.228_138_852).abs() < 1e-8, "{t10}");
        let t30 = student_t_critical(0.95, 30).expect("in range");
        assert!((t30 - 2.042_272_456).abs() < 1e-8, "{t30}");
        let t_big = student_t_critical(0.95, 100_000).expect("in range");
        assert!((t_big - 1.959_963_985).abs() < 1e-4, "{t_big}");
        // 99 %, df = 5: 4.032143.
        let t99 = student_t_critical(0.99, 5).expect("in range");
        assert!((t99 - 4.032_142_984).abs() < 1e-8, "{t99}");
    }

    #[test]
    fn t_critical_refuses_what_has_no_quantile() {
        assert_eq!(student_t_critical(0.0, 3), None);
        assert_eq!(student_t_critical(f64::NAN, 3), None);
        assert_eq!(student_t_critical(0.95, 0), None);
    }

    #[test]
    fn line_fit_of_four_points_by_hand() {
        // x = 0..3, y = 0, 1, 1, 2: mean x 3/2, mean y 1, Sxx = 5, Sxy = 3, slope 3/5,
        // intercept 1 - 9/10 = 1/10; residuals -0.1, 0.3, -0.3, 0.1, SSE = 0.2, s^2 = 0.1,
        // se = sqrt(0.1 / 5) = sqrt(0.02); t(2) = sqrt(2) 0.95 / sqrt(0.0975).
        let fit = LineFit::of(&[0.0, 1.0, 2.0, 3.0], &[0.0, 1.0, 1.0, 2.0]).expect("4 points");
        assert_eq!(fit.points, 4);
        assert!((fit.slope - 0.6).abs() < 1e-15);
        assert!((fit.intercept - 0.1).abs() < 1e-15);
        let se = 0.02f64.sqrt();
        assert!((fit.slope_std_error - se).abs() < 1e-15);
        let half = 2f64.sqrt() * 0.95 / 0.0975f64.sqrt() * se;
        assert!((fit.slope_ci95[0] - (0.6 - half)).abs() < 1e-12);
        assert!((fit.slope_ci95[1] - (0.6 + half)).abs() < 1e-12);
    }

    #[test]
    fn line_fit_recovers_the_exponent_of_a_power_law() {
        // y = 3 x^(-1/2) on log-log axes: slope -1/2, intercept ln 3, no scatter.
        let x: Vec<f64> = [0.5f64, 0.25, 0.125, 0.0625, 0.03125]
            .iter()
            .map(|v| v.ln())
            .collect();
        let y: Vec<f64> = x.iter().map(|lx| (3.0 * (-0.5 * lx).exp()).ln()).collect();
        let fit = LineFit::of(&x, &y).expect("5 points");
        assert!((fit.slope + 0.5).abs() < 1e-12);
        assert!((fit.intercept - 3f64.ln()).abs() < 1e-12);
        assert!(fit.slope_std_error < 1e-12);
        assert!(fit.slope_ci95[0] <= fit.slope && fit.slope <= fit.slope_ci95[1]);
    }

    #[test]
    fn line_fit_needs_three_points_with_spread_in_x() {
        assert_eq!(LineFit::of(&[0.0, 1.0], &[0.0, 1.0]), None);
        assert_eq!(LineFit::of(&[2.0; 3], &[0.0, 1.0, 2.0]), None);
        assert_eq!(LineFit::of(&[0.0, 1.0, 2.0], &[0.0, 1.0]), None);
        assert_eq!(LineFit::of(&[0.0, 1.0, f64::NAN], &[0.0, 1.0, 2.0]), None);
    }
}
