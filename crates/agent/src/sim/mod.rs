//! A simulated robot: plausible sensor data in rosbridge JSON at configured rates.
//!
//! The robot drives a figure-eight through a 20 m room with five round pillars
//! ([`world`]); it publishes a 360° laser scan and a 3D point cloud ray-cast against that
//! room, odometry, a pose, and JPEG pictures of the room from the robot's camera
//! ([`camera`]), all as rosbridge JSON ([`messages`]); optionally the room itself (pillars,
//! walls, the navigation goal) as `visualization_msgs` markers.
//!
//! Design: sans-IO, in the quinn style. The driver owns the clock: it calls
//! [`Sim::poll`] with the time since start and sleeps until [`Sim::next_due`]. Each topic
//! has slots at `k × period`; a message is a pure function of (config, robot name, topic,
//! slot), so output is deterministic for a seed whatever the polling pattern. A driver that
//! falls behind gets the newest slot per topic, not a burst of stale ones; the skipped
//! slots are counted ([`Sim::skipped`]).

mod camera;
mod driver;
mod messages;
pub mod services;
mod world;

pub use driver::drive;

use std::time::Duration;

use bytes::Bytes;

use crate::config::SimConfig;
use camera::CameraSpec;
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
    Image(CameraSpec),
    Markers,
}

impl Sensor {
    fn type_name(self) -> &'static str {
        match self {
            Self::LaserScan { .. } => "sensor_msgs/msg/LaserScan",
            Self::Odometry => "nav_msgs/msg/Odometry",
            Self::Pose => "geometry_msgs/msg/PoseStamped",
            Self::PointCloud { .. } => "sensor_msgs/msg/PointCloud2",
            Self::Image(_) => "sensor_msgs/msg/CompressedImage",
            Self::Markers => "visualization_msgs/msg/MarkerArray",
        }
    }
}

/// How the robot moves: its figure-eight patrol, standing still, or driving straight to a
/// navigation goal (times in seconds since start).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Motion {
    Patrol,
    Hold {
        x: f64,
        y: f64,
        yaw: f64,
    },
    Drive {
        from: (f64, f64),
        to: (f64, f64),
        t0: f64,
        speed: f64,
    },
}

/// Goals must lie this far inside the room's walls.
pub const ROOM_HALF: f64 = 9.5;

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
    motion: Motion,
    /// The navigation goal the markers show (set by the driver, which knows the goal).
    goal_marker: Option<(f64, f64)>,
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
            add(
                &s.topic,
                s.rate_hz,
                Sensor::Image(CameraSpec::new(s.width, s.height, s.quality)),
            );
        }
        if let Some(s) = &cfg.markers {
            add(&s.topic, s.rate_hz, Sensor::Markers);
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
            motion: Motion::Patrol,
            goal_marker: None,
        }
    }

    /// Where the robot is `t` seconds after start, under its current motion.
    fn state_at(&self, t: f64) -> world::RobotState {
        match self.motion {
            Motion::Patrol => world::robot_state(t, self.start_phase),
            Motion::Hold { x, y, yaw } => world::RobotState {
                x,
                y,
                yaw,
                speed: 0.0,
                yaw_rate: 0.0,
            },
            Motion::Drive {
                from,
                to,
                t0,
                speed,
            } => {
                let (dx, dy) = (to.0 - from.0, to.1 - from.1);
                let d = dx.hypot(dy);
                let s = ((t - t0) * speed).clamp(0.0, d);
                let f = if d > 0.0 { s / d } else { 1.0 };
                world::RobotState {
                    x: from.0 + dx * f,
                    y: from.1 + dy * f,
                    yaw: if d > 0.0 { dy.atan2(dx) } else { 0.0 },
                    speed: if s < d { speed } else { 0.0 },
                    yaw_rate: 0.0,
                }
            }
        }
    }

    /// The robot's pose `(x, y, yaw)` at `now` (time since start).
    pub fn pose_at(&self, now: Duration) -> (f64, f64, f64) {
        let s = self.state_at(now.as_secs_f64());
        (s.x, s.y, s.yaw)
    }

    pub fn motion(&self) -> Motion {
        self.motion
    }

    /// Starts driving from where the robot is at `now` to `(x, y)` at `speed` m/s.
    /// Returns the distance to go.
    pub fn navigate(&mut self, now: Duration, x: f64, y: f64, speed: f64) -> f64 {
        let (fx, fy, _) = self.pose_at(now);
        self.motion = Motion::Drive {
            from: (fx, fy),
            to: (x, y),
            t0: now.as_secs_f64(),
            speed: speed.max(0.01),
        };
        (x - fx).hypot(y - fy)
    }

    /// Distance left to the navigation goal at `now`, if driving to one.
    pub fn distance_remaining(&self, now: Duration) -> Option<f64> {
        match self.motion {
            Motion::Drive { to, .. } => {
                let (x, y, _) = self.pose_at(now);
                Some((to.0 - x).hypot(to.1 - y))
            }
            _ => None,
        }
    }

    /// Stops where the robot is at `now`.
    pub fn hold(&mut self, now: Duration) {
        let (x, y, yaw) = self.pose_at(now);
        self.motion = Motion::Hold { x, y, yaw };
    }

    /// Back to the figure-eight patrol.
    pub fn patrol(&mut self) {
        self.motion = Motion::Patrol;
    }

    /// The navigation goal shown on the markers topic from now on (`None`: no goal, the
    /// goal marker is deleted). Messages stay a pure function of their slot and this.
    pub fn set_goal_marker(&mut self, goal: Option<(f64, f64)>) {
        self.goal_marker = goal;
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
        self.poll_wanted_into(now, out, |_| true);
    }

    /// Like [`Sim::poll_into`], but the due slots of topics `wanted` says nobody wants
    /// are passed over without being made: a camera nobody watches costs nothing to render.
    pub fn poll_wanted_into(
        &mut self,
        now: Duration,
        out: &mut Vec<SimMessage>,
        wanted: impl Fn(usize) -> bool,
    ) {
        let now_ns = u64::try_from(now.as_nanos()).unwrap_or(u64::MAX);
        for i in 0..self.topics.len() {
            let period = self.period_ns[i];
            if self.next_slot[i].saturating_mul(period) > now_ns {
                continue;
            }
            let slot = now_ns / period;
            let skipped = slot - self.next_slot[i];
            self.next_slot[i] = slot + 1;
            if wanted(i) {
                self.skipped += skipped;
                out.push(self.generate_slot(i, slot));
            }
        }
    }

    /// Whether topic `i` is costly to make (the camera's rendered pictures), so that a
    /// driver makes it only while it is wanted ([`Sim::poll_wanted_into`]).
    pub fn is_costly(&self, i: usize) -> bool {
        matches!(self.sensors.get(i), Some(Sensor::Image(_)))
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
        let state = self.state_at(t_ns as f64 * 1e-9);
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
            Sensor::Image(spec) => messages::compressed_image(
                scratch,
                &state,
                spec,
                Header::new(stamp_ns, &frames.camera),
            ),
            // Same frame as the pose, so the markers line up with the robot on a map.
            Sensor::Markers => messages::markers(stamp_ns, &frames.map, self.goal_marker),
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
