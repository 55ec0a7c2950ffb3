//! Lehmer's greatest common divisor of big integers (Knuth, TAOCP vol. 2, §4.5.2, Algorithm
//! L): most Euclidean steps are taken on the leading 64 bits and applied to the full numbers
//! at once. num-integer's binary algorithm shifts and subtracts the full numbers once per bit,
//! which made reducing fractions most of the pure build's time.

use num_bigint::{BigInt, BigUint};
use num_integer::Integer as _;
use num_traits::{ToPrimitive, Zero};

/// `gcd(a, b)`; `gcd(0, 0) = 0`.
pub(super) fn gcd(a: &BigUint, b: &BigUint) -> BigUint {
    let (mut u, mut v) = if a >= b {
        (a.clone(), b.clone())
    } else {
        (b.clone(), a.clone())
    };
    // u >= v throughout.
    while !v.is_zero() {
        if let Some(small) = v.to_u64() {
            let rest = (&u % small).to_u64().expect("below a u64");
            return BigUint::from(rest.gcd(&small));
        }
        let shift = u.bits() - 64;
        let mut x = i128::from((&u >> shift).to_u64().expect("64 leading bits"));
        let mut y = i128::from((&v >> shift).to_u64().expect("at most 64 bits"));
        let (mut p, mut q, mut r, mut s) = (1i128, 0i128, 0i128, 1i128);
        // Steps on the leading bits, while both bounds on the quotient agree (step L2).
        // (Knuth shows these sums stay in [0, 2^64]; the test keeps `/` a floor division.)
        while x + p >= 0 && x + q >= 0 && y + r > 0 && y + s > 0 {
            let quotient = (x + p) / (y + r);
            if quotient != (x + q) / (y + s) {
                break;
            }
            (p, r) = (r, p - quotient * r);
            (q, s) = (s, q - quotient * s);
            (x, y) = (y, x - quotient * y);
        }
        if q == 0 {
            // No step agreed: one full division (step L4).
            let rest = &u % &v;
            u = v;
            v = rest;
        } else {
            let (ui, vi) = (BigInt::from(u), BigInt::from(v));
            let next_u = &ui * p + &vi * q;
            let next_v = ui * r + vi * s;
            u = next_u
                .to_biguint()
                .expect("Lehmer's combinations stay non-negative");
            v = next_v
                .to_biguint()
                .expect("Lehmer's combinations stay non-negative");
        }
    }
    u
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gcds_of_products_of_known_factors() {
        let big = |hex: &str| BigUint::parse_bytes(hex.as_bytes(), 16).expect("hex");
        // Two 250-bit-ish numbers sharing the factor 2^61 - 1 (a prime) times 3^40.
        let common = big("1fffffffffffffff") * BigUint::from(3u32).pow(40);
        let a = &common * big("f00dfacecafebeef0123456789abcdef0fedcba987654321");
        let b = &common * big("1ffffffffffffffffffffff");
        let (a_rest, b_rest) = (&a / &common, &b / &common);
        // The cofactors share no factor (2^89 - 1 is prime; checked by num-integer's binary
        // algorithm).
        assert_eq!(a_rest.gcd(&b_rest), BigUint::from(1u32));
        assert_eq!(gcd(&a, &b), common);
        assert_eq!(gcd(&b, &a), common);
        assert_eq!(gcd(&a, &BigUint::zero()), a);
        assert_eq!(gcd(&BigUint::zero(), &BigUint::zero()), BigUint::zero());
        // Consecutive Fibonacci numbers: the longest Euclidean chains, gcd 1.
        let (mut f, mut g) = (BigUint::from(1u32), BigUint::from(1u32));
        for _ in 0..3000 {
            (f, g) = (g.clone(), f + g);
        }
        assert_eq!(gcd(&f, &g), BigUint::from(1u32));
        let scale = BigUint::from(10u32).pow(300);
        assert_eq!(gcd(&(&f * &scale), &(&g * &scale)), scale);
    }
}
