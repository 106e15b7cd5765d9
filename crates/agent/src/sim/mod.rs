//! A simulated robot: plausible sensor data in rosbridge JSON at configured rates.
//!
//! The robot drives a figure-eight through a 20 m room with five round pillars
//! ([`world`]); it publishes a 360° laser scan and a 3D point cloud ray-cast against that
//! room, odometry, a pose, and JPEG-sized compressed images ([`messages`]).
//!
//! Design: sans-IO, in the quinn style. The driver owns the clock: it calls
//! [`Sim::poll`] with the time since start and sleeps until [`Sim::next_due`]. Each topic
//! has slots at `k × period`; a message is a pure function of (config, robot name, topic,
//! slot), so output is deterministic for a seed whatever the polling pattern. A driver that
//! falls behind gets the newest slot per topic, not a burst of stale ones; the skipped
//! slots are counted ([`Sim::skipped`]).

mod driver;
mod messages;
mod world;

pub use driver::drive;

use std::time::Duration;

use bytes::Bytes;

use crate::config::SimConfig;
use messages::{Header, Scratch};
use world::Noise;

/// One simulated topic.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SimTopic {
    /// Local topic name, e.g. `/scan`.
    pub name: String,
    /// ROS 2 type name, e.g. `sensor_msgs/msg/LaserScan`.
    pub type_name: &'static str,
    /// Time between two messages.
    pub period: Duration,
}

/// One generated message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SimMessage {
    /// Index into [`Sim::topics`].
    pub topic_index: usize,
    /// Header stamp: construction epoch + slot time, nanoseconds since the Unix epoch.
    pub stamp_ns: u64,
    /// The message object as rosbridge JSON text (what goes in a `publish` op's `msg`).
    pub json: Bytes,
}

#[derive(Debug, Clone, Copy)]
enum Sensor {
    LaserScan { beams: u32 },
    Odometry,
    Pose,
    PointCloud { points: u32 },
    Image { bytes: u32 },
}

impl Sensor {
    fn type_name(self) -> &'static str {
        match self {
            Self::LaserScan { .. } => "sensor_msgs/msg/LaserScan",
            Self::Odometry => "nav_msgs/msg/Odometry",
            Self::Pose => "geometry_msgs/msg/PoseStamped",
            Self::PointCloud { .. } => "sensor_msgs/msg/PointCloud2",
            Self::Image { .. } => "sensor_msgs/msg/CompressedImage",
        }
    }
}

/// `frame_id`s, with the configured prefix applied once.
#[derive(Debug)]
struct Frames {
    map: String,
    odom: String,
    base_link: String,
    laser: String,
    lidar: String,
    camera: String,
}

impl Frames {
    fn new(prefix: &str) -> Self {
        let f = |name: &str| format!("{prefix}{name}");
        Self {
            map: f("map"),
            odom: f("odom"),
            base_link: f("base_link"),
            laser: f("laser"),
            lidar: f("lidar"),
            camera: f("camera"),
        }
    }
}

/// The simulated robot. See the module docs.
#[derive(Debug)]
pub struct Sim {
    topics: Vec<SimTopic>,
    sensors: Vec<Sensor>,
    /// Per topic: period in nanoseconds (≥ 1) and the next slot not yet emitted.
    period_ns: Vec<u64>,
    next_slot: Vec<u64>,
    skipped: u64,
    epoch_ns: u64,
    /// Seed and name mixed: robots sharing a seed still drive and see differently.
    robot_seed: u64,
    start_phase: f64,
    frames: Frames,
    scratch: Scratch,
}

impl Sim {
    /// A simulator for the enabled sensors of `cfg`. `epoch_ns` (nanoseconds since the Unix
    /// epoch) is the stamp of time zero; message stamps are `epoch_ns + slot time`.
    pub fn new(cfg: &SimConfig, robot_name: &str, epoch_ns: u64) -> Self {
        let mut topics = Vec::new();
        let mut sensors = Vec::new();
        let mut add = |name: &str, rate_hz: f64, sensor: Sensor| {
            topics.push(SimTopic {
                name: name.to_owned(),
                type_name: sensor.type_name(),
                period: crate::config::period_of(rate_hz),
            });
            sensors.push(sensor);
        };
        if let Some(s) = &cfg.laser_scan {
            add(
                &s.topic,
                s.rate_hz,
                Sensor::LaserScan {
                    beams: s.ranges.max(1),
                },
            );
        }
        if let Some(s) = &cfg.odometry {
            add(&s.topic, s.rate_hz, Sensor::Odometry);
        }
        if let Some(s) = &cfg.pose {
            add(&s.topic, s.rate_hz, Sensor::Pose);
        }
        if let Some(s) = &cfg.point_cloud {
            add(
                &s.topic,
                s.rate_hz,
                Sensor::PointCloud {
                    points: s.points.max(1),
                },
            );
        }
        if let Some(s) = &cfg.image {
            add(&s.topic, s.rate_hz, Sensor::Image { bytes: s.bytes });
        }
        let period_ns = topics
            .iter()
            .map(|t| {
                u64::try_from(t.period.as_nanos())
                    .unwrap_or(u64::MAX)
                    .max(1)
            })
            .collect();
        let robot_seed = world::mix64(cfg.seed ^ world::name_hash(robot_name));
        Self {
            next_slot: vec![0; topics.len()],
            topics,
            sensors,
            period_ns,
            skipped: 0,
            epoch_ns,
            robot_seed,
            start_phase: world::start_phase(robot_seed),
            frames: Frames::new(&cfg.frame_prefix),
            scratch: Scratch::default(),
        }
    }

    /// The simulated topics; [`SimMessage::topic_index`] indexes this.
    pub fn topics(&self) -> &[SimTopic] {
        &self.topics
    }

    /// Messages due at `now` (time since start), at most one per topic.
    pub fn poll(&mut self, now: Duration) -> Vec<SimMessage> {
        let mut out = Vec::new();
        self.poll_into(now, &mut out);
        out
    }

    /// Like [`Sim::poll`], appending to `out` so a driver can reuse one `Vec`.
    pub fn poll_into(&mut self, now: Duration, out: &mut Vec<SimMessage>) {
        let now_ns = u64::try_from(now.as_nanos()).unwrap_or(u64::MAX);
        for i in 0..self.topics.len() {
            let period = self.period_ns[i];
            if self.next_slot[i].saturating_mul(period) > now_ns {
                continue;
            }
            let slot = now_ns / period;
            self.skipped += slot - self.next_slot[i];
            self.next_slot[i] = slot + 1;
            out.push(self.generate_slot(i, slot));
        }
    }

    /// Time since start at which the next message is due (`Duration::MAX` with no topics).
    pub fn next_due(&self) -> Duration {
        self.next_slot
            .iter()
            .zip(&self.period_ns)
            .map(|(slot, period)| slot.saturating_mul(*period))
            .min()
            .map_or(Duration::MAX, Duration::from_nanos)
    }

    /// Slots passed over because the driver polled late, over all topics.
    pub fn skipped(&self) -> u64 {
        self.skipped
    }

    /// The message topic `topic_index` publishes at its slot at or before `at`, without
    /// touching the schedule (for benchmarks, tests and on-demand sampling).
    ///
    /// # Panics
    /// If `topic_index` is out of range of [`Sim::topics`].
    pub fn generate(&mut self, topic_index: usize, at: Duration) -> SimMessage {
        let at_ns = u64::try_from(at.as_nanos()).unwrap_or(u64::MAX);
        let slot = at_ns / self.period_ns[topic_index];
        self.generate_slot(topic_index, slot)
    }

    fn generate_slot(&mut self, i: usize, slot: u64) -> SimMessage {
        let t_ns = slot.saturating_mul(self.period_ns[i]);
        let stamp_ns = self.epoch_ns.saturating_add(t_ns);
        let state = world::robot_state(t_ns as f64 * 1e-9, self.start_phase);
        let mut noise = Noise::new(world::mix64(
            self.robot_seed ^ world::mix64((i as u64) << 48 ^ slot),
        ));
        let frames = &self.frames;
        let scratch = &mut self.scratch;
        let json = match self.sensors[i] {
            Sensor::LaserScan { beams } => messages::laser_scan(
                scratch,
                &state,
                beams,
                self.topics[i].period.as_secs_f32(),
                &mut noise,
                Header::new(stamp_ns, &frames.laser),
            ),
            Sensor::Odometry => messages::odometry(
                &state,
                Header::new(stamp_ns, &frames.odom),
                &frames.base_link,
            ),
            Sensor::Pose => messages::pose_stamped(&state, Header::new(stamp_ns, &frames.map)),
            Sensor::PointCloud { points } => messages::point_cloud(
                scratch,
                &state,
                points,
                &mut noise,
                Header::new(stamp_ns, &frames.lidar),
            ),
            Sensor::Image { bytes } => messages::compressed_image(
                scratch,
                bytes,
                &mut noise,
                Header::new(stamp_ns, &frames.camera),
            ),
        };
        SimMessage {
            topic_index: i,
            stamp_ns,
            json: Bytes::from(json),
        }
    }
}

#[cfg(test)]
mod tests;
