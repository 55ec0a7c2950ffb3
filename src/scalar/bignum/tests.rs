//! The contract of the big numbers, checked on whichever implementation is built: expected
//! values come from hand computation or from IEEE `f64` arithmetic (correctly rounded to
//! nearest at 53 bits), never from the implementation itself.

use super::*;

fn q(n: i64, d: i64) -> Rational {
    Rational::new(Integer::from(n), Integer::from(d)).expect("non-zero denominator")
}

fn exact(x: &Float) -> Rational {
    x.to_rational().expect("a finite float")
}

fn pow2(e: i64) -> Rational {
    Rational::from(1).times_pow2(e)
}

#[test]
fn rationals_reduce_and_compute_exactly() {
    assert_eq!(q(6, -4), q(-3, 2));
    assert_eq!(q(1, 3) + q(1, 6), q(1, 2));
    assert_eq!(q(1, 3) - q(1, 2), q(-1, 6));
    assert_eq!(q(2, 3) * q(9, 4), q(3, 2));
    assert_eq!(q(2, 3) / q(4, 9), q(3, 2));
    assert_eq!(-q(2, 3), q(-2, 3));
    assert_eq!(q(-5, 7).cmp0(), Ordering::Less);
    assert!((q(1, 3) - q(1, 3)).is_zero());
    assert_eq!(
        (q(12, 35).numer(), q(12, 35).denom()),
        (12.into(), 35.into())
    );
    assert_eq!((q(12, 35).numer_bits(), q(12, 35).denom_bits()), (4, 6));
    assert_eq!(Rational::from_f64(0.375), Some(q(3, 8)));
    assert_eq!(Rational::from_f64(-5e-324), Some(-pow2(-1074)));
    assert_eq!(Rational::from_f64(f64::NAN), None);
    assert_eq!(q(3, 4).times_pow2(-3), q(3, 32));
}

#[test]
fn rationals_convert_to_f64_by_truncation() {
    // 0.1 as an f64 is above 1/10 (by 1/180143985094819840): truncation takes the one below.
    assert_eq!(q(1, 10).to_f64(), 0.1f64.next_down());
    assert_eq!(q(-1, 10).to_f64(), -0.1f64.next_down());
    assert_eq!(q(1, 3).to_f64(), 1.0 / 3.0);
    assert_eq!(pow2(-1074).to_f64(), 5e-324);
    assert_eq!(pow2(1100).to_f64(), f64::INFINITY);
}

#[test]
fn integers_give_roots_powers_and_divisibility() {
    let i = Integer::from;
    assert_eq!(i(10).pow(20) * i(10).pow(20), i(10).pow(40));
    assert!(i(10).pow(40).is_perfect_square());
    assert_eq!(i(10).pow(40).sqrt(), i(10).pow(20));
    assert!(!(i(10).pow(40) + i(1)).is_perfect_square());
    assert_eq!(i(99).sqrt(), i(9));
    assert!(i(98).is_divisible(&i(49)) && !i(98).is_divisible(&i(4)));
    assert_eq!(i(98).div_exact(&i(49)), i(2));
    assert_eq!(i(-3).shifted_left(70), -i(3) * i(2).pow(70));
    assert_eq!(i(-3).cmp0(), Ordering::Less);
}

#[test]
fn floats_round_in_the_direction_asked_for() {
    let third = q(1, 3);
    // 1/3 = 0.0101010101|0101... in binary: ten significant bits end at 2^-11.
    let down = Float::from_rational(&third, 10, Round::Down);
    let up = Float::from_rational(&third, 10, Round::Up);
    assert_eq!(exact(&down), q(682, 2048));
    assert_eq!(exact(&up), q(683, 2048));
    assert_eq!(
        exact(&Float::from_rational(&-third, 10, Round::Up)),
        q(-682, 2048)
    );
    // sqrt 2 = 741455.2... / 2^19.
    let two = Float::from_rational(&q(2, 1), 20, Round::Down);
    assert_eq!(exact(&two.sqrt(20, Round::Down)), q(741_455, 1 << 19));
    assert_eq!(exact(&two.sqrt(20, Round::Up)), q(741_456, 1 << 19));
    // Ties go to the even neighbour: 1 + 2^-11 and 1 + 3 2^-11 at 11 bits.
    let nearest = |r: Rational| exact(&Float::from_rational(&r, 11, Round::Nearest));
    assert_eq!(nearest(q(2049, 2048)), q(1, 1));
    assert_eq!(nearest(q(2051, 2048)), q(513, 512));
}

#[test]
fn floats_agree_with_ieee_arithmetic_at_53_bits() {
    let xs = [1.0, 3.0, 0.1, -7.25e-3, 1e300, 2.5e-300, 12345.678, -0.3];
    let f = |x: f64| Float::from_rational(&Rational::from_f64(x).expect("finite"), 53, Round::Down);
    for &x in &xs {
        for &y in &xs {
            let (a, b) = (f(x), f(y));
            let cases = [
                (Float::add(&a, &b, 53, Round::Nearest), x + y),
                (Float::sub(&a, &b, 53, Round::Nearest), x - y),
                (Float::mul(&a, &b, 53, Round::Nearest), x * y),
                (Float::div(&a, &b, 53, Round::Nearest), x / y),
            ];
            for (got, want) in cases {
                if want.is_finite() && (want == 0.0 || want.abs() > 1e-290) {
                    assert_eq!(got.to_f64(Round::Nearest), want, "{x} {y}");
                }
            }
            let ra = exact(&a);
            let rb = exact(&b);
            let sum = ra.clone() + &rb;
            let product = ra.clone() * &rb;
            let quotient = ra.clone() / &rb;
            for prec in [2, 53, 200] {
                let bracket = |lo: Float, hi: Float, value: &Rational| {
                    assert!(exact(&lo).minus(value).cmp0().is_le(), "{x} {y} {prec}");
                    assert!(exact(&hi).minus(value).cmp0().is_ge(), "{x} {y} {prec}");
                };
                bracket(
                    Float::add(&a, &b, prec, Round::Down),
                    Float::add(&a, &b, prec, Round::Up),
                    &sum,
                );
                bracket(
                    Float::mul(&a, &b, prec, Round::Down),
                    Float::mul(&a, &b, prec, Round::Up),
                    &product,
                );
                bracket(
                    Float::div(&a, &b, prec, Round::Down),
                    Float::div(&a, &b, prec, Round::Up),
                    &quotient,
                );
            }
        }
        if x > 0.0 {
            assert_eq!(
                f(x).sqrt(53, Round::Nearest).to_f64(Round::Nearest),
                x.sqrt()
            );
            let (lo, hi) = (f(x).sqrt(70, Round::Down), f(x).sqrt(70, Round::Up));
            let square = |r: Rational| r.clone() * &r;
            assert!(square(exact(&lo)).minus(&exact(&f(x))).cmp0().is_le());
            assert!(square(exact(&hi)).minus(&exact(&f(x))).cmp0().is_ge());
        }
    }
}

#[test]
fn sums_of_far_apart_values_round_by_the_small_one() {
    let one = Float::from_rational(&q(1, 1), 64, Round::Down);
    let tiny = Float::from_rational(&pow2(-5000), 64, Round::Down);
    let above = Float::add(&one, &tiny, 64, Round::Up);
    assert_eq!(exact(&above), q(1, 1) + pow2(-63));
    assert_eq!(exact(&Float::add(&one, &tiny, 64, Round::Down)), q(1, 1));
    assert_eq!(
        exact(&Float::sub(&one, &tiny, 64, Round::Down)),
        q(1, 1) - pow2(-64)
    );
    assert_eq!(exact(&Float::sub(&one, &tiny, 64, Round::Nearest)), q(1, 1));
}

#[test]
fn floats_convert_to_f64_in_the_direction_asked_for() {
    let third = Float::from_rational(&q(1, 3), 200, Round::Down);
    assert_eq!(third.to_f64(Round::Nearest), 1.0 / 3.0);
    assert_eq!(third.to_f64(Round::Down), 1.0 / 3.0);
    assert_eq!(third.to_f64(Round::Up), (1.0f64 / 3.0).next_up());
    let huge = Float::from_rational(&pow2(2000), 64, Round::Down);
    assert_eq!(huge.to_f64(Round::Down), f64::MAX);
    assert_eq!(huge.to_f64(Round::Up), f64::INFINITY);
    assert_eq!(huge.negated().to_f64(Round::Up), f64::MIN);
    // 1.5 2^-1074 lies halfway between the two smallest subnormals.
    let half_way = Float::from_rational(&(pow2(-1074) * q(3, 2)), 64, Round::Down);
    assert_eq!(half_way.to_f64(Round::Down), 5e-324);
    assert_eq!(half_way.to_f64(Round::Nearest), 1e-323);
    assert_eq!(half_way.to_f64(Round::Up), 1e-323);
    let below_all = Float::from_rational(&pow2(-3000), 64, Round::Down);
    assert_eq!(below_all.to_f64(Round::Down), 0.0);
    assert_eq!(below_all.to_f64(Round::Up), 5e-324);
}

#[test]
fn floats_have_signs_exponents_and_infinities() {
    let f = |r: Rational| Float::from_rational(&r, 64, Round::Down);
    assert_eq!(f(q(1, 1)).top_exponent(), Some(1));
    assert_eq!(f(q(3, 4)).top_exponent(), Some(0));
    assert_eq!(f(-pow2(-100)).top_exponent(), Some(-99));
    assert_eq!(Float::zero(64).top_exponent(), None);
    assert!(Float::zero(64).is_zero() && Float::zero(64).cmp0() == Some(Ordering::Equal));
    assert_eq!(f(q(-1, 3)).cmp0(), Some(Ordering::Less));
    let (inf, minus_inf) = (Float::infinite(false), Float::infinite(true));
    assert!(minus_inf < f(q(-1, 1)) && f(q(1, 1)) < inf);
    assert_eq!(Float::add(&inf, &f(q(1, 1)), 64, Round::Down), inf);
    assert!(Float::add(&inf, &minus_inf, 64, Round::Down).is_nan());
    assert!(Float::mul(&inf, &Float::zero(64), 64, Round::Down).is_nan());
    assert_eq!(Float::mul(&minus_inf, &f(q(-2, 1)), 64, Round::Up), inf);
    assert!(Float::div(&f(q(1, 1)), &inf, 64, Round::Up).is_zero());
    assert_eq!(inf.sqrt(64, Round::Down), inf);
    assert_eq!(minus_inf.negated(), inf);
    assert!(Float::add(&inf, &minus_inf, 64, Round::Down)
        .cmp0()
        .is_none());
    assert_eq!(inf.to_rational(), None);
}
