//! Whether, and how, the agent's writer compresses each message of a topic on its link
//! (`compression:` in the topic's QoS; the envelope is [`fleetlink_proto::compress`]).
//!
//! `lz4` and `zstd` compress every message but the smallest, and send one as it is when
//! compressing did not make it smaller. `auto` compresses with a fast zstd level only
//! where that pays: every message it compresses also measures the saving, and a topic
//! whose messages shrink by less than [`AUTO_MIN_SAVING`] (JPEG or PNG images, clouds
//! compressed at the source) is sent as it is until [`AUTO_RECHECK`] has passed or
//! [`AUTO_RECHECK_MESSAGES`] messages have gone by, then sampled again.

use std::time::{Duration, Instant};

use bytes::Bytes;
use fleetlink_proto::compress::{self, Codec, ZSTD_AUTO_LEVEL, ZSTD_LEVEL};
use fleetlink_qos::Compression;

/// Messages smaller than this are never compressed (the frame header outweighs the gain).
const MIN_SIZE: usize = 128;
/// ... and under `auto`, not below this.
const AUTO_MIN_SIZE: usize = 512;
/// `auto` keeps compressing a topic while its messages shrink by at least this share.
const AUTO_MIN_SAVING: f64 = 0.10;
/// How long `auto` sends a topic that did not shrink as it is before it samples again ...
const AUTO_RECHECK: Duration = Duration::from_secs(5);
/// ... or after how many of its messages, whichever comes first.
const AUTO_RECHECK_MESSAGES: u32 = 100;

/// One topic's compression on one link.
#[derive(Debug)]
pub(super) struct Compressor {
    mode: Compression,
    /// `auto` found the topic incompressible at this time, and has skipped this many
    /// messages since.
    skipping: Option<(Instant, u32)>,
}

impl Compressor {
    /// `None` for `compression: none`.
    pub(super) fn new(mode: Compression) -> Option<Compressor> {
        (mode != Compression::None).then_some(Compressor {
            mode,
            skipping: None,
        })
    }

    /// The compression envelope to send instead of `raw`, or `None` to send `raw` as it is.
    pub(super) fn apply(&mut self, raw: &[u8], now: Instant) -> Option<Bytes> {
        match self.mode {
            Compression::None => None,
            _ if raw.len() < MIN_SIZE => None,
            Compression::Lz4 => compress::compress(Codec::Lz4, raw, 0),
            Compression::Zstd => compress::compress(Codec::Zstd, raw, ZSTD_LEVEL),
            Compression::Auto => {
                if raw.len() < AUTO_MIN_SIZE {
                    return None;
                }
                if let Some((since, skipped)) = &mut self.skipping {
                    *skipped += 1;
                    if now.saturating_duration_since(*since) < AUTO_RECHECK
                        && *skipped < AUTO_RECHECK_MESSAGES
                    {
                        return None;
                    }
                }
                let out = compress::compress(Codec::Zstd, raw, ZSTD_AUTO_LEVEL);
                let saving = out
                    .as_ref()
                    .map_or(0.0, |o| 1.0 - o.len() as f64 / raw.len() as f64);
                self.skipping = (saving < AUTO_MIN_SAVING).then_some((now, 0));
                // Compressed already: sent so if it is smaller at all.
                out
            }
        }
    }

    /// Whether `auto` is sending this topic as it is for now.
    #[cfg(test)]
    fn is_skipping(&self) -> bool {
        self.skipping.is_some()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn noise(n: usize, seed: u64) -> Vec<u8> {
        let mut x = seed | 1;
        (0..n)
            .map(|_| {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                x as u8
            })
            .collect()
    }

    fn cloud(n: usize) -> Vec<u8> {
        // Points on a plane: x, y step slowly, z and intensity repeat.
        (0..n / 16)
            .flat_map(|i| {
                let (x, y) = ((i % 100) as f32 * 0.05, (i / 100) as f32 * 0.05);
                [x, y, 0.0f32, 100.0].into_iter().flat_map(f32::to_le_bytes)
            })
            .collect()
    }

    #[test]
    fn auto_compresses_what_shrinks_and_leaves_noise_alone() {
        let t0 = Instant::now();
        let mut c = Compressor::new(Compression::Auto).unwrap();
        let raw = cloud(64_000);
        let env = c.apply(&raw, t0).expect("a cloud shrinks");
        assert!(env.len() * 3 < raw.len(), "{} of {}", env.len(), raw.len());
        assert!(!c.is_skipping());

        let mut j = Compressor::new(Compression::Auto).unwrap();
        assert!(j.apply(&noise(50_000, 1), t0).is_none());
        assert!(j.is_skipping());
        // Skipped without trying, until the recheck is due ...
        for i in 1..AUTO_RECHECK_MESSAGES {
            assert!(
                j.apply(&raw, t0 + Duration::from_millis(i as u64))
                    .is_none()
            );
        }
        // ... then sampled again: the topic now shrinks, and is compressed from here on.
        assert!(j.apply(&raw, t0 + Duration::from_millis(200)).is_some());
        assert!(!j.is_skipping());
        assert!(j.apply(&noise(50_000, 2), t0).is_none());
        assert!(
            j.apply(&raw, t0 + AUTO_RECHECK).is_some(),
            "recheck after 5 s"
        );
    }

    #[test]
    fn small_messages_are_never_compressed() {
        let now = Instant::now();
        for mode in [Compression::Auto, Compression::Zstd, Compression::Lz4] {
            let mut c = Compressor::new(mode).unwrap();
            assert!(c.apply(&[0u8; MIN_SIZE - 1], now).is_none(), "{mode:?}");
        }
        let mut z = Compressor::new(Compression::Zstd).unwrap();
        assert!(z.apply(&[0u8; MIN_SIZE], now).is_some());
        assert!(Compressor::new(Compression::None).is_none());
    }

    #[test]
    fn each_mode_uses_its_codec() {
        let now = Instant::now();
        let raw = cloud(20_000);
        for (mode, codec) in [
            (Compression::Lz4, Codec::Lz4),
            (Compression::Zstd, Codec::Zstd),
            (Compression::Auto, Codec::Zstd),
        ] {
            let env = Compressor::new(mode).unwrap().apply(&raw, now).unwrap();
            assert_eq!(compress::codec_of(&env), Some(codec), "{mode:?}");
            assert_eq!(compress::open(&env, 1 << 20).unwrap(), raw);
        }
    }
}
