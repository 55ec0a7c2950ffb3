//! A monotone priority queue on `f64` keys (a radix heap [AMOT90] with digits of several
//! bits): continuous Dijkstra takes its events out in the order of their distances, and every
//! event it queues lies at or beyond the front, so an event is filed by the highest digit in
//! which its key differs from the last key taken out and that digit's value, and moved only
//! towards that key, each time to a lower level. The first version, with digits of one bit,
//! did more work than a binary heap (4 % more instructions on stanford_bunny) but in few
//! places in memory: 6 % less time, where the heap's 1.8M pops each went down 14 levels of 12k
//! events and were 23 % of the run's first-level cache misses.
//!
//! Digits of one bit (the classic radix heap) moved each event down about one bucket at a time:
//! an event's key differs from the front's in bits 33 to 47 when queued, and the bunny's 1.8M
//! events made 12M moves. With digits of six bits the levels are ten, and a bucket per value of
//! the digit leaves the rest of its level in place when its nearest key becomes the front:
//! stanford_bunny 2.6 % fewer instructions (5.48G -> 5.34G) and 5 % fewer misses of a 2 MiB
//! cache (cachegrind), for 0.04-0.7 MiB more peak memory (eight bits: 4 % fewer instructions
//! but 4 % more first-level misses and 1.2 MiB more on the bunny).
//!
//! Keys are ordered to [`KEY_RESOLUTION`]: each positive normal one is rounded down to its
//! twelve leading bits, and taken out with that value. Continuous Dijkstra needs no finer
//! order: every event queued later lies beyond the rounded key taken out, since it lies beyond
//! the true one, and that is all that final vertices and given-up edges rest on (the order
//! among events within one step is as free as among events of equal keys). The rounding
//! spares the moves of the lowest levels: from v0, 6.9 % fewer instructions on
//! stanford_bunny, 7.7 % on fandisk, 5.6 % on rocker_arm, 3.4 % on icosphere5, the same
//! wedges propagated to within 1.3 % (fewer on fandisk, 0.5 % more created on the bunny),
//! and the vertices' distances changed in their last bits (1e-14 at most on these).
//!
//! Events of equal rounded keys leave in the queue's own order. Keys queued behind the front
//! (a child wedge's smallest distance, rounded, can fall an ulp short of its parent's) are
//! queued at the front's key: due at once, as they are by their own key.
//!
//! [AMOT90]: R. K. Ahuja, K. Mehlhorn, J. Orlin, R. E. Tarjan, Faster algorithms for the
//! shortest path problem, J. ACM 37(2), 1990.

/// The integer of a key's bits that orders as [`f64::total_cmp`] orders keys, unsigned: the
/// sign bit flipped for positive keys, every bit for negative ones.
#[inline(always)]
fn radix_key(key: f64) -> u64 {
    let bits = key.to_bits();
    bits ^ (((bits as i64 >> 63) as u64) | (1 << 63))
}

/// The key of [`radix_key`]'s integer.
#[inline(always)]
fn key_of(radix: u64) -> f64 {
    let flip = if radix >> 63 == 1 { 1 << 63 } else { u64::MAX };
    f64::from_bits(radix ^ flip)
}

/// The bits of a key's [`radix_key`] integer below its twelve leading bits of mantissa.
const ROUNDED_BITS: u32 = 40;

/// The relative step to which keys are ordered: keys within it of each other may leave in
/// either order ([`RadixQueue::push`]).
pub(crate) const KEY_RESOLUTION: f64 =
    1.0 / (1u64 << (f64::MANTISSA_DIGITS - 1 - ROUNDED_BITS)) as f64;

/// The most items an emptied bucket keeps room for: few, since the buckets are many (705; 256
/// items each, as the one-bit queue's 65 kept, could hold 4 MiB of 24-byte events).
const KEPT_CAPACITY: usize = 32;

/// Bits of a key per level of buckets.
const DIGIT_BITS: u32 = 6;
/// Buckets per level: one per value of a digit.
const DIGITS: usize = 1 << DIGIT_BITS;
/// Buckets: the front's own key, then a level per digit of a 64-bit key.
const SLOTS: usize = 1 + u64::BITS.div_ceil(DIGIT_BITS) as usize * DIGITS;
/// Words of the bitmap of filled buckets (at most 64: one `u64` marks those not zero).
const WORDS: usize = SLOTS.div_ceil(64);
const _: () = assert!(WORDS <= 64);

/// The bucket of a key (as [`radix_key`]'s integer) no nearer than the front `front`: `0` if
/// they are equal, else, after it, one per value of the highest digit in which they differ,
/// the lower digits first. Buckets thus order as their keys do.
#[inline(always)]
fn bucket(radix: u64, front: u64) -> usize {
    let differ = radix ^ front;
    if differ == 0 {
        return 0;
    }
    let level = (u64::BITS - 1 - differ.leading_zeros()) / DIGIT_BITS;
    let digit = (radix >> (level * DIGIT_BITS)) as usize & (DIGITS - 1);
    1 + level as usize * DIGITS + digit
}

/// Marks bucket `b` as filled in the bitmap of the buckets after the first (`filled`, and
/// `words`, which of its words are not zero).
#[inline(always)]
fn mark(filled: &mut [u64; WORDS], words: &mut u64, b: usize) {
    if b > 0 {
        filled[b / 64] |= 1 << (b % 64);
        *words |= 1 << (b / 64);
    }
}

/// Items due at `f64` keys, taken out nearest first to [`KEY_RESOLUTION`] (among items of one
/// rounded key, in the queue's own order).
pub(crate) struct RadixQueue<T> {
    /// The key of the last item taken out (the front), as [`radix_key`]'s integer.
    front: u64,
    /// Bucket `0` holds items at the front's key, the others those whose highest digit that
    /// differs from the front's is of a level and a value ([`bucket`]).
    buckets: Vec<Vec<(u64, T)>>,
    /// Which buckets after the first hold an item (bit `b % 64` of word `b / 64`).
    filled: [u64; WORDS],
    /// Which words of `filled` are not zero.
    words: u64,
    len: usize,
}

impl<T> RadixQueue<T> {
    /// An empty queue, its front at the smallest key.
    pub(crate) fn new() -> Self {
        RadixQueue {
            front: 0,
            buckets: std::iter::repeat_with(Vec::new).take(SLOTS).collect(),
            filled: [0; WORDS],
            words: 0,
            len: 0,
        }
    }

    /// Items waiting.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    #[inline(always)]
    fn file(&mut self, radix: u64, item: T) {
        let b = bucket(radix, self.front);
        self.buckets[b].push((radix, item));
        mark(&mut self.filled, &mut self.words, b);
    }

    /// Queues `item` at `key`, rounded down to [`KEY_RESOLUTION`] if positive and normal, or at
    /// the front's key if that lies behind it.
    pub(crate) fn push(&mut self, key: f64, item: T) {
        let radix = radix_key(key);
        // A negative key's integer has its bits flipped: clearing them would set the key's own
        // (and make -inf a NaN); distances are not negative. A subnormal key has fewer leading
        // bits than the resolution counts on: rounded, 5e-324 became 0, and a wedge there, due
        // only beyond its key, came up at 0 again for ever.
        let rounded = match (radix >> 63, (radix >> 52) & 0x7ff) {
            (1, 1..) => radix & !((1 << ROUNDED_BITS) - 1),
            _ => radix,
        };
        self.file(rounded.max(self.front), item);
        self.len += 1;
    }

    /// The nearest item and its key as queued (rounded).
    pub(crate) fn pop(&mut self) -> Option<(f64, T)> {
        if self.buckets[0].is_empty() {
            if self.words == 0 {
                return None;
            }
            let w = self.words.trailing_zeros() as usize;
            let b = w * 64 + self.filled[w].trailing_zeros() as usize;
            self.filled[w] &= !(1 << (b % 64));
            if self.filled[w] == 0 {
                self.words &= !(1 << w);
            }
            // The bucket's nearest key becomes the front; every item of the bucket then
            // differs from it in a lower digit than before, so moves to a lower bucket, and
            // the other buckets of the level still differ from it in that digit.
            let (lower, upper) = self.buckets.split_at_mut(b);
            let items = &mut upper[0];
            let front = items.iter().map(|x| x.0).min().expect("a filled bucket");
            self.front = front;
            for (radix, item) in items.drain(..) {
                let to = bucket(radix, front);
                lower[to].push((radix, item));
                mark(&mut self.filled, &mut self.words, to);
            }
            // The emptied bucket keeps a small allocation for the items filed there later: a
            // large one kept by every bucket held ten times the queue's peak.
            if items.capacity() > KEPT_CAPACITY {
                items.shrink_to(KEPT_CAPACITY);
            }
        }
        let (radix, item) = self.buckets[0].pop().expect("items at the front's key");
        self.len -= 1;
        Some((key_of(radix), item))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn keys_map_to_integers_in_their_order_and_back() {
        let keys = [
            f64::NEG_INFINITY,
            -1e300,
            -1.0,
            -f64::MIN_POSITIVE,
            -0.0,
            0.0,
            f64::MIN_POSITIVE,
            1.0,
            1.0 + f64::EPSILON,
            1e300,
            f64::INFINITY,
        ];
        for pair in keys.windows(2) {
            assert!(radix_key(pair[0]) < radix_key(pair[1]), "{pair:?}");
        }
        for k in keys {
            assert_eq!(key_of(radix_key(k)).to_bits(), k.to_bits());
        }
    }

    proptest! {
        /// Keys come out in the order of their values rounded down to the resolution, each
        /// with that value, pushes interleaved at or beyond the front; a key behind the front
        /// comes out at the front's key. Keys are few multiples of powers of two beyond the
        /// front, from 2^-40 to 2^20, so that many are equal and the others differ from the
        /// front in digits of every level, and their rounding matters.
        #[test]
        fn pops_come_out_nearest_first_to_the_resolution(
            steps in prop::collection::vec((0u32..6, -40i32..20, 0usize..4), 1..300),
        ) {
            // Rounded down to 12 significant bits: the binary exponent, then the step.
            let rounded = |k: f64| {
                let exponent = ((k.to_bits() >> 52) & 0x7ff) as i32 - 1023;
                let step = 2f64.powi(exponent) * KEY_RESOLUTION;
                if k.is_normal() && k > 0.0 { (k / step).floor() * step } else { k }
            };
            let mut queue = RadixQueue::new();
            let mut reference: Vec<f64> = Vec::new();
            let mut front = f64::NEG_INFINITY;
            for (i, &(offset, scale, pops)) in steps.iter().enumerate() {
                let beyond = f64::from(offset) * 2f64.powi(scale);
                let key = match i % 7 {
                    3 => front - 1.0,
                    _ => front.max(0.0) + beyond + beyond / 3.0,
                };
                queue.push(key, i);
                reference.push(rounded(key).max(front));
                for _ in 0..pops {
                    reference.sort_by(|a, b| b.total_cmp(a));
                    let expected = reference.pop();
                    let got = queue.pop().map(|(k, _)| k);
                    prop_assert_eq!(got, expected);
                    if let Some(k) = got {
                        front = k;
                    }
                }
                prop_assert_eq!(queue.len(), reference.len());
            }
        }
    }

    /// Subnormal keys keep their bits: rounded, they would fall to 0.
    #[test]
    fn subnormal_keys_are_not_rounded() {
        let mut queue = RadixQueue::new();
        let tiny = 5e-324;
        queue.push(tiny, 0);
        queue.push(0.0, 1);
        assert_eq!(queue.pop(), Some((0.0, 1)));
        assert_eq!(queue.pop(), Some((tiny, 0)));
    }

    #[test]
    fn keys_within_the_resolution_leave_in_either_order_and_those_apart_in_theirs() {
        let mut queue = RadixQueue::new();
        let one = 1.0 + KEY_RESOLUTION;
        for (key, item) in [
            (one + KEY_RESOLUTION / 2.0, 0),
            (one, 1),
            (one + KEY_RESOLUTION, 2),
        ] {
            queue.push(key, item);
        }
        // The first two round to one key and leave together, before the third.
        let mut first = [queue.pop().unwrap(), queue.pop().unwrap()];
        first.sort_by_key(|x| x.1);
        assert_eq!(first, [(one, 0), (one, 1)]);
        assert_eq!(queue.pop(), Some((one + KEY_RESOLUTION, 2)));
        assert_eq!(queue.pop(), None);
    }
}
