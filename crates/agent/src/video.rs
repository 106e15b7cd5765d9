//! The agent's video streams: each camera topic of the `video:` section offered as an H.264
//! video topic, encoded only while someone wants the video (crates/video, docs/video.md).
//!
//! Each stream is an in-process participant of the agent's router. It advertises its video
//! topic at once, so the hub lists it, and asks the uplink's read interest whether anyone
//! wants it: a viewer at the hub, a local subscriber. While someone does, it subscribes to
//! the camera topic (which makes the ROS bridges read the camera) and runs an encoder
//! thread ([`fleetlink_video::Stream`]); once nobody has wanted the video for
//! [`UNWANTED_BEFORE_PAUSE`](fleetlink_relay::read_interest::UNWANTED_BEFORE_PAUSE), it
//! stops the thread and lets the camera go. The camera topic itself is sent to the hub only
//! if someone there wants it too. While it runs, its target bitrate follows the link
//! ([`fleetlink_video::rate`]): down when its frames wait in the uplink's queue, up again
//! when they do not, capped by the hub's share and the data budget.
//!
//! The streams follow the `video:` section as it changes while the agent runs
//! ([`supervise`]): a stream whose settings change restarts its encoder with them (its
//! next frame a keyframe), one whose camera or video topic changes, or that goes, ends, and
//! a new one starts.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::{Duration, Instant};

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::read_interest::{Look, ReadInterest};
use fleetlink_relay::router::{Publication, SubOptions, SubscriptionId, Target};
use fleetlink_relay::{ClientId, ClientKind, Router, Topic, TopicName};
use fleetlink_video::rate::{LinkFollower, LinkState};
use fleetlink_video::source::SourceKind;
use fleetlink_video::{Settings, Stream, VIDEO_TYPE};
use tokio::sync::watch;
use tokio_util::sync::CancellationToken;

/// How often a stream looks again at who wants it when nothing told it (local subscribers
/// coming and going are not signalled), and at its link (its bitrate follows it).
const LOOK_EVERY: Duration = Duration::from_secs(1);

/// One configured stream.
#[derive(Debug, Clone, PartialEq)]
pub struct VideoOptions {
    /// The camera topic (`sensor_msgs/msg/Image` or `CompressedImage`).
    pub camera: TopicName,
    /// The video topic it is offered as.
    pub topic: TopicName,
    pub settings: Settings,
    /// The least the bitrate comes down to when the link carries less than
    /// `settings.bitrate_bps` ([`fleetlink_video::rate`]).
    pub min_bitrate_bps: u32,
    /// Cisco's OpenH264 to load instead of the built-in one.
    pub library: Option<PathBuf>,
}

/// A stream [`supervise`] runs: where its settings go, and how to end it.
struct Served {
    video: TopicName,
    settings: watch::Sender<VideoOptions>,
    stop: CancellationToken,
    task: tokio::task::JoinHandle<()>,
}

/// Runs the streams `wanted` lists, following its changes, until `shutdown`.
pub async fn supervise(
    mut wanted: watch::Receiver<Vec<VideoOptions>>,
    router: Arc<Router>,
    interest: Option<Arc<ReadInterest>>,
    shutdown: CancellationToken,
) {
    let mut served: BTreeMap<TopicName, Served> = BTreeMap::new();
    loop {
        let want = wanted.borrow_and_update().clone();
        // Streams that go, or whose camera is offered under another video topic, end
        // first (a video topic may pass from one camera to another).
        let ending: Vec<TopicName> = served
            .iter()
            .filter(|(camera, s)| {
                !want
                    .iter()
                    .any(|o| o.camera == **camera && o.topic == s.video)
            })
            .map(|(camera, _)| camera.clone())
            .collect();
        for camera in ending {
            if let Some(s) = served.remove(&camera) {
                s.stop.cancel();
                let _ = s.task.await;
                tracing::info!(
                    "video {}: no longer offered (configuration changed)",
                    s.video
                );
            }
        }
        for opts in want {
            match served.get(&opts.camera) {
                Some(s) => {
                    s.settings.send_if_modified(|now| {
                        let changed = *now != opts;
                        *now = opts;
                        changed
                    });
                }
                None => {
                    let (settings, changes) = watch::channel(opts.clone());
                    let stop = shutdown.child_token();
                    let task = tokio::spawn(serve(
                        changes,
                        router.clone(),
                        interest.clone(),
                        stop.clone(),
                    ));
                    let video = opts.topic.clone();
                    let s = Served {
                        video,
                        settings,
                        stop,
                        task,
                    };
                    served.insert(opts.camera, s);
                }
            }
        }
        tokio::select! {
            _ = shutdown.cancelled() => break,
            changed = wanted.changed() => {
                if changed.is_err() {
                    // Nobody changes the streams any more: they run as they are.
                    shutdown.cancelled().await;
                    break;
                }
            }
        }
    }
    for s in served.into_values() {
        let _ = s.task.await;
    }
}

/// Runs one stream until `shutdown`, taking new settings (same camera and video topic)
/// from `changes`.
async fn serve(
    mut changes: watch::Receiver<VideoOptions>,
    router: Arc<Router>,
    interest: Option<Arc<ReadInterest>>,
    shutdown: CancellationToken,
) {
    let mut opts = changes.borrow_and_update().clone();
    let (client, outbox) = router.connect(
        ClientKind::Internal {
            role: "video".into(),
        },
        None,
    );
    // CDR from the start, so the link announces the topic before its first frame (the hub
    // lists it, and a viewer can ask for it) also when the stream starts after the link.
    let how = Publication {
        encoding: Some(Encoding::Cdr),
        ..Publication::default()
    };
    let topic = match router.advertise_as(client, &opts.topic, Schema::named(VIDEO_TYPE), how) {
        Ok(t) => t,
        Err(e) => {
            tracing::warn!("video: cannot offer {}: {e}", opts.topic);
            router.disconnect(client);
            return;
        }
    };
    // The hub's requests for a keyframe arrive as pulls of the video topic.
    let asks = router.watch_demand(client);
    let mut running: Option<Running> = None;
    let mut unwanted_since = None;
    let mut look = tokio::time::interval(LOOK_EVERY);
    look.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    let mut unreadable: Option<String> = None;
    loop {
        tokio::select! {
            _ = shutdown.cancelled() => break,
            Ok(()) = changes.changed() => {
                let new = changes.borrow_and_update().clone();
                tracing::info!(
                    "video {}: settings changed: {} fps, {} kbit/s ({} at least), a keyframe \
                     every {} frames",
                    opts.topic,
                    new.settings.fps,
                    new.settings.bitrate_bps / 1000,
                    new.min_bitrate_bps / 1000,
                    new.settings.keyframe_every
                );
                opts = new;
                // The encoder restarts with them; its first frame is a keyframe.
                if let Some(r) = running.take() {
                    r.stop(&router, client, "settings changed");
                    running = Running::start(&opts, &router, client, &topic);
                }
                continue;
            }
            _ = ReadInterest::changed(&interest) => {}
            _ = look.tick() => {
                if let (Some(r), Some(i)) = (&mut running, &interest) {
                    r.follow_link(i, &topic);
                }
            }
            _ = asks.changed() => {
                asks.take();
                if !asks.take_pulls().is_empty()
                    && let Some(r) = &mut running
                {
                    r.keyframe_asked(Instant::now());
                }
                continue;
            }
            _ = outbox.ready() => {
                loop {
                    let batch = outbox.take(16, 64 << 20, Instant::now());
                    if batch.items.is_empty() {
                        break;
                    }
                    for (_, _, msg) in batch.items {
                        let Some(r) = &running else { continue };
                        let Some(kind) = SourceKind::of_type(&msg.topic.schema.type_name) else {
                            note_once(&mut unreadable, format!(
                                "{} is a {}, not a sensor_msgs/Image or CompressedImage; \
                                 it cannot be offered as video",
                                opts.camera, msg.topic.schema.type_name));
                            continue;
                        };
                        match msg.payload_in(Encoding::Cdr, router.transcoder()) {
                            Ok(cdr) => r.stream.push(kind, cdr, msg.received()),
                            Err(e) => note_once(&mut unreadable, format!(
                                "a message of {} does not convert to CDR: {e}", opts.camera)),
                        }
                    }
                }
                continue;
            }
        }
        let wanted = match &interest {
            Some(i) => i.look_asked(&opts.topic, client, &mut unwanted_since, Instant::now()),
            // Without an uplink only local subscribers count.
            None if topic.has_subscriber_besides(&[client]) => Look::Read,
            None => Look::Stop,
        };
        match (wanted, running.is_some()) {
            (Look::Read, false) => {
                running = Running::start(&opts, &router, client, &topic);
                unreadable = None;
            }
            (Look::Stop, true) => {
                if let Some(r) = running.take() {
                    r.stop(&router, client, "nobody watches");
                }
                // The last frame kept for the hub would start a later viewer's picture
                // on a frame that needs the ones before it.
                if let Some(i) = &interest {
                    i.stopped_reading(&opts.topic);
                }
            }
            _ => {}
        }
    }
    if let Some(r) = running.take() {
        r.stop(&router, client, "the stream ends");
    }
    router.disconnect(client);
}

/// A stream while someone wants it.
struct Running {
    topic: TopicName,
    sub: SubscriptionId,
    stream: Stream,
    /// When the last keyframe asked for was forced.
    forced: Option<Instant>,
    /// The target bitrate, following the link.
    rate: LinkFollower,
    /// The lowest and highest targets it had.
    rate_span: (u32, u32),
}

/// The most often a stream forces a keyframe when asked (the hub asks at most once a
/// second per link; several hubs or viewers could ask more).
const FORCE_EVERY: Duration = Duration::from_secs(1);

impl Running {
    fn start(
        opts: &VideoOptions,
        router: &Arc<Router>,
        client: ClientId,
        topic: &Arc<Topic>,
    ) -> Option<Running> {
        let seq = AtomicU64::new(0);
        let publish_to = topic.clone();
        let sink = Box::new(move |out: fleetlink_video::Output| {
            let n = seq.fetch_add(1, Relaxed) + 1;
            let payload = Payload::new(Encoding::Cdr, out.cdr);
            publish_to.publish_at(
                publish_to.meta(),
                client,
                n,
                out.stamp_ns,
                payload,
                out.arrived,
            );
        });
        let stream = match Stream::spawn(
            opts.topic.as_str(),
            opts.settings,
            opts.library.clone(),
            sink,
        ) {
            Ok(s) => s,
            Err(e) => {
                tracing::warn!("video {}: cannot start its encoder thread: {e}", opts.topic);
                return None;
            }
        };
        let sub = match router.subscribe(
            client,
            Target::Exact(opts.camera.clone()),
            SubOptions::default(),
        ) {
            Ok(sub) => sub,
            Err(e) => {
                tracing::warn!("video {}: cannot read {}: {e}", opts.topic, opts.camera);
                return None;
            }
        };
        tracing::info!(
            "video {}: someone watches; encoding {}",
            opts.topic,
            opts.camera
        );
        Some(Running {
            topic: opts.topic.clone(),
            sub,
            stream,
            // Its first frame is a keyframe.
            forced: Some(Instant::now()),
            rate: LinkFollower::new(
                opts.min_bitrate_bps,
                opts.settings.bitrate_bps,
                opts.settings.fps,
            ),
            rate_span: (opts.settings.bitrate_bps, opts.settings.bitrate_bps),
        })
    }

    /// Looks at the link (about once a second) and moves the encoder's target bitrate
    /// with it.
    fn follow_link(&mut self, interest: &ReadInterest, topic: &Topic) {
        let (backlog_frames, limit_bytes_per_sec) = interest.link_load(topic);
        let link = LinkState {
            backlog_frames,
            limit_bytes_per_sec,
        };
        if let Some(bps) = self.rate.update(link) {
            self.stream.set_bitrate(bps);
            self.rate_span = (self.rate_span.0.min(bps), self.rate_span.1.max(bps));
            tracing::debug!(
                "video {}: bitrate {} kbit/s ({} frames waiting on the link)",
                self.topic,
                bps / 1000,
                backlog_frames
            );
        }
    }

    /// The hub asked for a keyframe: the next frame is one, unless one was forced less
    /// than [`FORCE_EVERY`] ago.
    fn keyframe_asked(&mut self, now: Instant) {
        if self
            .forced
            .is_some_and(|at| now.saturating_duration_since(at) < FORCE_EVERY)
        {
            return;
        }
        self.forced = Some(now);
        self.stream.request_keyframe();
        tracing::debug!("video {}: a keyframe was asked for", self.topic);
    }

    /// Ends the encoder and lets the camera go; `why` opens the log line.
    fn stop(self, router: &Router, client: ClientId, why: &str) {
        router.unsubscribe(client, self.sub);
        let s = self.stream.stats();
        let stream = self.stream;
        // Dropping the stream joins its thread (after the frame it is encoding): off the
        // agent's runtime.
        tokio::task::spawn_blocking(move || drop(stream));
        tracing::info!(
            "video {}: {why}; stopped after {} frames ({} keyframes, {} left out \
             over the frame rate, {} skipped by rate control, {} behind, {} failed; \
             bitrate {} to {} kbit/s, following the link)",
            self.topic,
            s.encoded.load(Relaxed),
            s.keyframes.load(Relaxed),
            s.over_rate.load(Relaxed),
            s.skipped.load(Relaxed),
            s.dropped.load(Relaxed),
            s.failed.load(Relaxed),
            self.rate_span.0 / 1000,
            self.rate_span.1 / 1000,
        );
    }
}

/// Logs a problem with the camera's messages once until it changes.
fn note_once(last: &mut Option<String>, text: String) {
    if last.as_deref() != Some(text.as_str()) {
        tracing::warn!("video: {text}");
        *last = Some(text);
    }
}
