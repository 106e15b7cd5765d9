//! The one step every JSON scanner here repeats: finding where a string's plain run ends.
//!
//! The hub reads every rosbridge publish twice without building anything: its envelope
//! (fleetlink-proto's `rosbridge::scan`) and its message against the type
//! (`json_text`). Both spend most of their time stepping over strings — keys, the `op`,
//! the topic, string fields — and most of those strings are a few bytes long.

/// Bytes looked at a word at a time before a vector search takes over.
const SHORT: usize = 64;

const ONES: u64 = 0x0101_0101_0101_0101;
const HIGHS: u64 = 0x8080_8080_8080_8080;

/// The high bit of each byte of `v` (eight bytes of text, little-endian) that is a quote,
/// a backslash or below 0x20. Bytes above the lowest such byte may be marked wrongly
/// (a borrow runs upwards); the lowest mark is always right, and it is the one used.
#[inline]
fn stops(v: u64) -> u64 {
    let quote = v ^ (ONES * u64::from(b'"'));
    let backslash = v ^ (ONES * u64::from(b'\\'));
    let zero = |x: u64| x.wrapping_sub(ONES) & !x;
    (zero(quote) | zero(backslash) | (v.wrapping_sub(ONES * 0x20) & !v)) & HIGHS
}

/// The index of the first quote, backslash or control character in `b` at or after
/// `from`, or `b.len()` when there is none. Called just inside a string, it is where the
/// string ends when `b[index]` is a quote.
#[inline(always)]
pub fn string_stop(b: &[u8], from: usize) -> usize {
    let Some(rest) = b.get(from..) else {
        return b.len();
    };
    // Most strings end within a few bytes: eight at a time, they are passed before a
    // vector search would have been set up.
    let head = &rest[..rest.len().min(SHORT)];
    let mut words = head.chunks_exact(8);
    let mut i = from;
    for w in words.by_ref() {
        let m = stops(u64::from_le_bytes(w.try_into().expect("eight bytes")));
        if m != 0 {
            return i + (m.trailing_zeros() / 8) as usize;
        }
        i += 8;
    }
    if head.len() < rest.len() {
        return long_stop(b, i);
    }
    // The last few bytes of the text.
    for &c in words.remainder() {
        if c == b'"' || c == b'\\' || c < 0x20 {
            return i;
        }
        i += 1;
    }
    b.len()
}

/// [`string_stop`] past the first `SHORT` bytes of a string.
#[inline(never)]
fn long_stop(b: &[u8], from: usize) -> usize {
    let end = from + memchr::memchr2(b'"', b'\\', &b[from..]).unwrap_or(b.len() - from);
    let run = &b[from..end];
    // A whole-run test the compiler vectorises; the position only when one is there.
    if run.iter().fold(true, |ok, &c| ok & (c >= 0x20)) {
        end
    } else {
        from + run.iter().position(|&c| c < 0x20).unwrap_or(run.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first stop byte the slow way.
    fn oracle(b: &[u8], from: usize) -> usize {
        (from..b.len())
            .find(|&i| b[i] == b'"' || b[i] == b'\\' || b[i] < 0x20)
            .unwrap_or(b.len())
    }

    #[test]
    fn finds_the_first_quote_backslash_or_control_at_every_position() {
        // Stops before, inside and after the byte loop's reach, and none at all.
        for len in [
            0usize, 1, 5, 7, 8, 9, 15, 16, 17, 31, 32, 33, 39, 40, 41, 100,
        ] {
            for at in 0..=len {
                for stop in [b'"', b'\\', 0x00, 0x1f, b'\n'] {
                    let mut b = vec![b'a'; len];
                    if at < len {
                        b[at] = stop;
                    }
                    for from in [0, 1.min(len), at.min(len)] {
                        assert_eq!(string_stop(&b, from), oracle(&b, from), "{b:?} from {from}");
                    }
                }
            }
        }
    }

    #[test]
    fn a_control_character_before_the_quote_is_found_first() {
        let mut b = vec![b'x'; 40];
        b[30] = b'"';
        b[25] = 0x07;
        assert_eq!(string_stop(&b, 0), 25);
        assert_eq!(string_stop(&b, 26), 30);
        // Multi-byte UTF-8 is plain text.
        let s = "é€😀\"".repeat(5);
        assert_eq!(string_stop(s.as_bytes(), 0), "é€😀".len());
    }

    #[test]
    fn agrees_with_the_slow_way_on_every_byte_value() {
        // Each byte value at each place of a word, among bytes that never stop a run
        // (high bytes of UTF-8 included), and runs of random bytes.
        let plain: Vec<u8> = (0x20..=0xffu8)
            .filter(|c| *c != b'"' && *c != b'\\')
            .collect();
        for c in 0..=255u8 {
            for at in 0..12 {
                let mut b: Vec<u8> = (0..48).map(|i| plain[(i * 7 + at) % plain.len()]).collect();
                b[at] = c;
                b[at + 20] = c;
                for from in [0, 1, at] {
                    assert_eq!(
                        string_stop(&b, from),
                        oracle(&b, from),
                        "byte {c:#x} at {at}"
                    );
                }
            }
        }
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        for _ in 0..2000 {
            let b: Vec<u8> = (0..64)
                .map(|_| {
                    x ^= x << 13;
                    x ^= x >> 7;
                    x ^= x << 17;
                    // Mostly plain text, now and then a byte that stops.
                    if x.is_multiple_of(23) {
                        (x >> 8) as u8 & 0x3f
                    } else {
                        plain[(x >> 16) as usize % plain.len()]
                    }
                })
                .collect();
            for from in [0, 3, 9, 33] {
                assert_eq!(string_stop(&b, from), oracle(&b, from), "{b:?} from {from}");
            }
        }
    }

    #[test]
    fn from_past_the_end_is_the_end() {
        assert_eq!(string_stop(b"ab", 2), 2);
        assert_eq!(string_stop(b"ab", 5), 2);
    }
}
