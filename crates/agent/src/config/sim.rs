//! The `sim:` section: which simulated sensors run, on which topics, how fast.
//!
//! A sensor that is omitted (or `null`) does not run; a sensor given as `{}` runs with the
//! defaults below. `sim: {}` (no sensor named at all) is shorthand for "all five sensors with
//! their defaults" (the optional `markers` layer is not among them), which is what
//! [`SimConfig::default`] returns too; as soon as one sensor is named, only the named ones
//! run.

use std::time::Duration;

use serde::Deserialize;

/// Simulated robot: a seed, up to five sensors and the optional markers. See `docs/config.md`.
#[derive(Debug, Clone, PartialEq, Deserialize, serde::Serialize)]
#[serde(from = "SimConfigYaml")]
pub struct SimConfig {
    /// Seeds the sensor noise and the robot's start position on its path. Default 1.
    pub seed: u64,
    /// Prepended to every `frame_id` (`odom`, `base_link`, `laser`, `lidar`, `camera`).
    /// Default `""`.
    pub frame_prefix: String,
    pub laser_scan: Option<LaserScanSim>,
    pub odometry: Option<OdometrySim>,
    pub pose: Option<PoseSim>,
    pub point_cloud: Option<PointCloudSim>,
    pub image: Option<ImageSim>,
    /// The room as `visualization_msgs` markers. Not among the default sensors: runs only
    /// when named.
    pub markers: Option<MarkersSim>,
}

impl Default for SimConfig {
    /// All five sensors with their defaults, seed 1.
    fn default() -> Self {
        Self {
            seed: 1,
            frame_prefix: String::new(),
            laser_scan: Some(LaserScanSim::default()),
            odometry: Some(OdometrySim::default()),
            pose: Some(PoseSim::default()),
            point_cloud: Some(PointCloudSim::default()),
            image: Some(ImageSim::default()),
            markers: None,
        }
    }
}

impl SimConfig {
    /// `(yaml key, topic, rate_hz)` of every enabled sensor, in a fixed order.
    pub fn enabled_topics(&self) -> Vec<(&'static str, &str, f64)> {
        let mut out = Vec::new();
        if let Some(s) = &self.laser_scan {
            out.push(("laser_scan", s.topic.as_str(), s.rate_hz));
        }
        if let Some(s) = &self.odometry {
            out.push(("odometry", s.topic.as_str(), s.rate_hz));
        }
        if let Some(s) = &self.pose {
            out.push(("pose", s.topic.as_str(), s.rate_hz));
        }
        if let Some(s) = &self.point_cloud {
            out.push(("point_cloud", s.topic.as_str(), s.rate_hz));
        }
        if let Some(s) = &self.image {
            out.push(("image", s.topic.as_str(), s.rate_hz));
        }
        if let Some(s) = &self.markers {
            out.push(("markers", s.topic.as_str(), s.rate_hz));
        }
        out
    }
}

/// Publish period for a rate in Hz, rounded to whole nanoseconds. `rate_hz` must be > 0
/// (validation guarantees it for loaded configs; non-positive rates give one hour).
pub fn period_of(rate_hz: f64) -> Duration {
    if rate_hz > 0.0 && rate_hz.is_finite() {
        Duration::from_nanos((1e9 / rate_hz).round().max(1.0) as u64)
    } else {
        Duration::from_secs(3600)
    }
}

macro_rules! sensor {
    ($(#[$doc:meta])* $name:ident { topic: $topic:literal, rate_hz: $rate:literal $(, $(#[$fdoc:meta])* $field:ident: $ty:ty = $default:literal)* }) => {
        $(#[$doc])*
        #[derive(Debug, Clone, PartialEq, Deserialize, serde::Serialize)]
        #[serde(default, deny_unknown_fields)]
        pub struct $name {
            #[doc = concat!("Local topic name. Default `", $topic, "`.")]
            pub topic: String,
            #[doc = concat!("Publish rate in Hz (> 0, fractions allowed). Default ", stringify!($rate), ".")]
            pub rate_hz: f64,
            $($(#[$fdoc])* pub $field: $ty,)*
        }

        impl Default for $name {
            fn default() -> Self {
                Self { topic: $topic.to_owned(), rate_hz: $rate as f64, $($field: $default,)* }
            }
        }

        impl $name {
            /// Time between two messages.
            pub fn period(&self) -> Duration {
                period_of(self.rate_hz)
            }
        }
    };
}

sensor!(
    /// `sensor_msgs/msg/LaserScan`: a 360° planar scan of the room.
    LaserScanSim { topic: "/scan", rate_hz: 10,
        /// Number of beams. Default 720.
        ranges: u32 = 720 }
);
sensor!(
    /// `nav_msgs/msg/Odometry` in the `odom` frame.
    OdometrySim { topic: "/odom", rate_hz: 20 }
);
sensor!(
    /// `geometry_msgs/msg/PoseStamped` in the `odom` frame.
    PoseSim { topic: "/pose", rate_hz: 10 }
);
sensor!(
    /// `sensor_msgs/msg/PointCloud2` (x, y, z, intensity as float32) from a 3D lidar.
    PointCloudSim { topic: "/points", rate_hz: 5,
        /// Points per cloud. Default 10000.
        points: u32 = 10_000 }
);
/// `sensor_msgs/msg/CompressedImage` with `format: jpeg`: a picture of the room from the
/// robot's pose (see `sim::camera`).
///
/// Written out rather than made by `sensor!`: it keeps the removed `bytes` key only so that
/// a config still setting it is refused with a pointer to `width` and `height`, instead of
/// the generic "unknown field" error.
#[derive(Debug, Clone, PartialEq, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct ImageSim {
    /// Local topic name. Default `/camera/image/compressed`.
    pub topic: String,
    /// Publish rate in Hz (> 0, fractions allowed). Default 10.
    pub rate_hz: f64,
    /// Picture width in pixels (16–4096). Default 320.
    pub width: u32,
    /// Picture height in pixels (16–4096). Default 240.
    pub height: u32,
    /// JPEG quality, 1–100 (below 90 the colour is stored at half resolution, as most
    /// cameras do). Default 75.
    pub quality: u32,
    /// The old size in bytes of the noise the camera sent before it rendered pictures.
    /// Never used: validation refuses a config that sets it, naming the keys to use.
    #[serde(rename = "bytes", skip_serializing)]
    pub removed_bytes: Option<serde::de::IgnoredAny>,
}

impl Default for ImageSim {
    fn default() -> Self {
        Self {
            topic: "/camera/image/compressed".to_owned(),
            rate_hz: 10.0,
            width: 320,
            height: 240,
            quality: 75,
            removed_bytes: None,
        }
    }
}

impl ImageSim {
    /// Time between two messages.
    pub fn period(&self) -> Duration {
        period_of(self.rate_hz)
    }
}
sensor!(
    /// `visualization_msgs/msg/MarkerArray` in the pose's frame: the pillars (`CYLINDER`),
    /// the walls (`LINE_STRIP`) and the navigation goal, if any (`SPHERE`, else `DELETE`).
    MarkersSim { topic: "/markers", rate_hz: 1 }
);

/// The YAML shape, before "no sensor named means all sensors" is applied.
#[derive(Deserialize)]
#[serde(default, deny_unknown_fields)]
struct SimConfigYaml {
    seed: u64,
    frame_prefix: String,
    laser_scan: Option<LaserScanSim>,
    odometry: Option<OdometrySim>,
    pose: Option<PoseSim>,
    point_cloud: Option<PointCloudSim>,
    image: Option<ImageSim>,
    markers: Option<MarkersSim>,
}

impl Default for SimConfigYaml {
    fn default() -> Self {
        Self {
            seed: 1,
            frame_prefix: String::new(),
            laser_scan: None,
            odometry: None,
            pose: None,
            point_cloud: None,
            image: None,
            markers: None,
        }
    }
}

impl From<SimConfigYaml> for SimConfig {
    fn from(y: SimConfigYaml) -> Self {
        let none_named = y.laser_scan.is_none()
            && y.odometry.is_none()
            && y.pose.is_none()
            && y.point_cloud.is_none()
            && y.image.is_none()
            && y.markers.is_none();
        if none_named {
            return Self {
                seed: y.seed,
                frame_prefix: y.frame_prefix,
                ..Self::default()
            };
        }
        Self {
            seed: y.seed,
            frame_prefix: y.frame_prefix,
            laser_scan: y.laser_scan,
            odometry: y.odometry,
            pose: y.pose,
            point_cloud: y.point_cloud,
            image: y.image,
            markers: y.markers,
        }
    }
}
