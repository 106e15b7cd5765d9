//! One video stream: an encoder thread behind a queue of two frames.
//!
//! The caller pushes camera messages as they come ([`Stream::push`]); a frame that arrives
//! sooner than the stream's frame rate allows is left out there, and a full queue lets its
//! oldest frame go, so a camera faster than the encoder costs a counter, never a backlog.
//! The thread reads, converts and encodes each frame and hands the `CompressedVideo`
//! message to the caller's sink. Dropping the [`Stream`] stops and joins the thread.

use std::collections::VecDeque;
use std::path::PathBuf;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Condvar, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use bytes::Bytes;

use crate::encoder::{H264Encoder, Settings};
use crate::picture::Picture;
use crate::source::{self, SourceKind};
use crate::{VideoError, message};

/// Frames waiting for the encoder at most: one being encoded and the next; a third means
/// the encoder is behind, and the oldest goes.
const QUEUE: usize = 2;

/// What the encoder thread hands over for each frame it encoded.
#[derive(Debug)]
pub struct Output {
    /// The `foxglove_msgs/msg/CompressedVideo` message, CDR.
    pub cdr: Bytes,
    pub keyframe: bool,
    /// The source image's stamp (its arrival when it had none), Unix nanoseconds.
    pub stamp_ns: u64,
    /// When its source message arrived.
    pub arrived: Instant,
}

/// A stream's counters, for status and tests.
#[derive(Debug, Default)]
pub struct StreamStats {
    /// Camera messages pushed.
    pub offered: AtomicU64,
    /// Left out because they came sooner than the frame rate allows.
    pub over_rate: AtomicU64,
    /// Let go from a full queue (the encoder was behind), or waiting when the stream
    /// stopped.
    pub dropped: AtomicU64,
    /// Left out by the encoder's rate control.
    pub skipped: AtomicU64,
    pub encoded: AtomicU64,
    pub keyframes: AtomicU64,
    /// Frames that could not be read or encoded.
    pub failed: AtomicU64,
    /// Bytes of bitstream made.
    pub bytes: AtomicU64,
    /// Time spent converting and encoding, nanoseconds.
    pub busy_ns: AtomicU64,
}

struct Pending {
    frames: VecDeque<(SourceKind, Bytes, Instant)>,
    /// When the last frame let in arrived (for the frame rate).
    last_in: Option<Instant>,
    keyframe: bool,
    /// A new target bitrate, for the encoder before its next frame.
    bitrate: Option<u32>,
    stop: bool,
}

struct Shared {
    pending: Mutex<Pending>,
    wake: Condvar,
    stats: Arc<StreamStats>,
    /// The shortest gap between two frames let in (a little under the frame interval, so
    /// a camera at exactly the stream's rate is not thinned by its jitter).
    min_gap: Duration,
}

/// A running stream (see the module docs).
pub struct Stream {
    shared: Arc<Shared>,
    thread: Option<JoinHandle<()>>,
}

impl Stream {
    /// Starts the encoder thread of a stream. `sink` gets every encoded frame, on the
    /// encoder thread.
    pub fn spawn(
        name: &str,
        settings: Settings,
        library: Option<PathBuf>,
        sink: Box<dyn FnMut(Output) + Send>,
    ) -> std::io::Result<Stream> {
        let interval = Duration::from_secs_f32(1.0 / settings.fps.max(0.1));
        let shared = Arc::new(Shared {
            pending: Mutex::new(Pending {
                frames: VecDeque::with_capacity(QUEUE + 1),
                last_in: None,
                keyframe: false,
                bitrate: None,
                stop: false,
            }),
            wake: Condvar::new(),
            stats: Arc::default(),
            min_gap: interval.mul_f32(0.8),
        });
        let worker = Worker {
            shared: shared.clone(),
            encoder: H264Encoder::new(settings, library),
            sink,
            name: name.to_owned(),
            last_error: None,
        };
        let thread = std::thread::Builder::new()
            .name(format!("video {name}"))
            .spawn(move || worker.run())?;
        Ok(Stream {
            shared,
            thread: Some(thread),
        })
    }

    /// Offers a camera message of `kind` (CDR) that arrived at `arrived`.
    pub fn push(&self, kind: SourceKind, cdr: Bytes, arrived: Instant) {
        let s = &self.shared;
        s.stats.offered.fetch_add(1, Relaxed);
        let mut p = s.pending.lock().unwrap_or_else(|e| e.into_inner());
        if p.last_in
            .is_some_and(|last| arrived.saturating_duration_since(last) < s.min_gap)
        {
            s.stats.over_rate.fetch_add(1, Relaxed);
            return;
        }
        p.last_in = Some(arrived);
        if p.frames.len() >= QUEUE {
            p.frames.pop_front();
            s.stats.dropped.fetch_add(1, Relaxed);
        }
        p.frames.push_back((kind, cdr, arrived));
        drop(p);
        s.wake.notify_one();
    }

    /// The next frame encoded is a keyframe.
    pub fn request_keyframe(&self) {
        let mut p = self
            .shared
            .pending
            .lock()
            .unwrap_or_else(|e| e.into_inner());
        p.keyframe = true;
    }

    /// The encoder's target bitrate from its next frame on.
    pub fn set_bitrate(&self, bps: u32) {
        let mut p = self
            .shared
            .pending
            .lock()
            .unwrap_or_else(|e| e.into_inner());
        p.bitrate = Some(bps);
    }

    pub fn stats(&self) -> Arc<StreamStats> {
        self.shared.stats.clone()
    }
}

impl Drop for Stream {
    fn drop(&mut self) {
        self.shared
            .pending
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .stop = true;
        self.shared.wake.notify_one();
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

struct Worker {
    shared: Arc<Shared>,
    encoder: H264Encoder,
    sink: Box<dyn FnMut(Output) + Send>,
    name: String,
    /// The last failure logged, so that a stream of bad frames logs once.
    last_error: Option<String>,
}

impl Worker {
    fn run(mut self) {
        let mut picture = Picture::default();
        let start = Instant::now();
        loop {
            let (kind, cdr, arrived, keyframe, bitrate) = {
                let mut p = self
                    .shared
                    .pending
                    .lock()
                    .unwrap_or_else(|e| e.into_inner());
                loop {
                    if p.stop {
                        let left = p.frames.len() as u64;
                        self.shared.stats.dropped.fetch_add(left, Relaxed);
                        return;
                    }
                    if let Some((kind, cdr, arrived)) = p.frames.pop_front() {
                        break (
                            kind,
                            cdr,
                            arrived,
                            std::mem::take(&mut p.keyframe),
                            p.bitrate.take(),
                        );
                    }
                    p = self.shared.wake.wait(p).unwrap_or_else(|e| e.into_inner());
                }
            };
            if keyframe {
                self.encoder.request_keyframe();
            }
            if let Some(bps) = bitrate
                && let Err(e) = self.encoder.set_bitrate(bps)
            {
                tracing::warn!("video {}: {e}", self.name);
            }
            let began = Instant::now();
            let stamp_ms = arrived.saturating_duration_since(start).as_millis() as u64;
            let result = self.encode(kind, &cdr, &mut picture, stamp_ms, arrived);
            let stats = &self.shared.stats;
            stats
                .busy_ns
                .fetch_add(began.elapsed().as_nanos() as u64, Relaxed);
            match result {
                Ok(Some(out)) => {
                    stats.encoded.fetch_add(1, Relaxed);
                    stats.keyframes.fetch_add(u64::from(out.keyframe), Relaxed);
                    stats.bytes.fetch_add(out.cdr.len() as u64, Relaxed);
                    (self.sink)(out);
                }
                Ok(None) => {
                    stats.skipped.fetch_add(1, Relaxed);
                }
                Err(e) => {
                    stats.failed.fetch_add(1, Relaxed);
                    let text = e.to_string();
                    if self.last_error.as_deref() != Some(text.as_str()) {
                        tracing::warn!("video {}: a frame was not encoded: {text}", self.name);
                        self.last_error = Some(text);
                    }
                }
            }
        }
    }

    fn encode(
        &mut self,
        kind: SourceKind,
        cdr: &[u8],
        picture: &mut Picture,
        stamp_ms: u64,
        arrived: Instant,
    ) -> Result<Option<Output>, VideoError> {
        let frame = source::read(kind, cdr)?;
        picture.fill(&frame.pixels)?;
        let stamp_ns = match frame.stamp_ns {
            0 => unix_ns(arrived),
            ns => ns,
        };
        let mut encoded = None;
        let mut failed = None;
        let hint = picture.width() * picture.height() / 8;
        let cdr =
            message::compressed_video(stamp_ns, frame.frame_id, "h264", hint, |buf| {
                match self.encoder.encode(picture, stamp_ms, buf) {
                    Ok(f) => encoded = f,
                    Err(e) => failed = Some(e),
                }
            });
        if let Some(e) = failed {
            return Err(e);
        }
        Ok(encoded.map(|f| Output {
            cdr: Bytes::from(cdr),
            keyframe: f.keyframe,
            stamp_ns,
            arrived,
        }))
    }
}

/// `at` as Unix nanoseconds (by the wall clock's offset from the monotonic one now).
fn unix_ns(at: Instant) -> u64 {
    let now = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .unwrap_or_default();
    let ago = Instant::now().saturating_duration_since(at);
    now.saturating_sub(ago).as_nanos() as u64
}

#[cfg(test)]
mod tests {
    use std::sync::mpsc;

    use super::*;
    use crate::h264;
    use crate::source::tests::image_cdr;

    fn settings() -> Settings {
        Settings {
            fps: 15.0,
            bitrate_bps: 1_000_000,
            keyframe_every: 30,
        }
    }

    #[test]
    fn a_stream_encodes_what_it_is_given_starting_with_a_keyframe() {
        let (tx, rx) = mpsc::channel();
        let stream = Stream::spawn(
            "test",
            settings(),
            None,
            Box::new(move |o| tx.send(o).unwrap()),
        )
        .unwrap();
        let t0 = Instant::now();
        for f in 0..5u32 {
            let rgb = vec![(f * 40) as u8; 64 * 32 * 3];
            let cdr = image_cdr(64, 32, "rgb8", 64 * 3, &rgb);
            stream.push(
                SourceKind::Image,
                Bytes::from(cdr),
                t0 + Duration::from_millis(70 * u64::from(f)),
            );
            // One at a time, so that none is let go from the queue.
            if f == 0 {
                let first = rx.recv_timeout(Duration::from_secs(10)).unwrap();
                assert!(first.keyframe);
                let data_at = 4 + 8 + 8; // stamp, "cam" string
                let len = u32::from_le_bytes(first.cdr[data_at..data_at + 4].try_into().unwrap());
                let au = &first.cdr[data_at + 4..][..len as usize];
                assert!(h264::is_keyframe(au));
                assert_eq!(first.stamp_ns, 7_000_000_500, "the source's stamp");
            }
        }
        let stats = stream.stats();
        let settled = || {
            stats.encoded.load(Relaxed)
                + stats.skipped.load(Relaxed)
                + stats.dropped.load(Relaxed)
                + stats.failed.load(Relaxed)
        };
        let deadline = Instant::now() + Duration::from_secs(10);
        while settled() < 5 && Instant::now() < deadline {
            std::thread::sleep(Duration::from_millis(5));
        }
        drop(stream);
        assert_eq!(
            settled(),
            5,
            "each frame was encoded, skipped by rate control or let go"
        );
        assert_eq!(stats.failed.load(Relaxed), 0);
        let got = 1 + rx.try_iter().count() as u64;
        assert_eq!(
            stats.encoded.load(Relaxed),
            got,
            "every frame out was counted"
        );
        assert!(got >= 2, "more than the first frame came out: {got}");
    }

    #[test]
    fn frames_sooner_than_the_rate_are_left_out_and_bad_ones_counted() {
        let stream = Stream::spawn("test", settings(), None, Box::new(|_| {})).unwrap();
        let t0 = Instant::now();
        for ms in [0, 10, 20, 70] {
            stream.push(
                SourceKind::Image,
                Bytes::from_static(&[0, 1, 0, 0, 1]),
                t0 + Duration::from_millis(ms),
            );
        }
        let stats = stream.stats();
        drop(stream);
        assert_eq!(stats.offered.load(Relaxed), 4);
        assert_eq!(
            stats.over_rate.load(Relaxed),
            2,
            "10 and 20 ms came too soon"
        );
        assert_eq!(
            stats.failed.load(Relaxed) + stats.dropped.load(Relaxed),
            2,
            "the malformed frames were counted, not encoded"
        );
        assert_eq!(stats.encoded.load(Relaxed), 0);
    }
}
