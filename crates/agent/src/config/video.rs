//! `video:` — camera topics offered as H.264 video (crates/video, docs/video.md): for each
//! camera topic, the video topic beside it and how it is encoded. Reference in
//! docs/config.md.

use serde::Deserialize;

/// One camera topic's video stream (the key of the `video:` mapping is the camera topic).
#[derive(Debug, Clone, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct VideoStreamConfig {
    /// The video topic (`foxglove_msgs/msg/CompressedVideo`), a local name like the
    /// camera's.
    pub topic: String,
    /// Frames a second at most (1–60). Default 15; a faster camera is thinned.
    #[serde(default = "default_fps")]
    pub fps: f32,
    /// Target kilobits a second on a link that carries it (50–50000). Default 1000.
    #[serde(default = "default_bitrate_kbps")]
    pub bitrate_kbps: u32,
    /// The least the target comes down to when the link carries less (50 to
    /// `bitrate_kbps`). Default a quarter of `bitrate_kbps`, at least 50.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub min_bitrate_kbps: Option<u32>,
    /// A keyframe at least this often, seconds (0.2–60). Default 2: the longest a viewer
    /// that missed a frame waits for a whole picture.
    #[serde(default = "default_keyframe_s")]
    pub keyframe_s: f32,
}

fn default_fps() -> f32 {
    15.0
}

fn default_bitrate_kbps() -> u32 {
    1000
}

fn default_keyframe_s() -> f32 {
    2.0
}

impl VideoStreamConfig {
    /// The encoder's settings.
    pub fn settings(&self) -> fleetlink_video::Settings {
        fleetlink_video::Settings {
            fps: self.fps,
            bitrate_bps: self.bitrate_kbps.saturating_mul(1000),
            keyframe_every: (self.keyframe_s * self.fps).round().max(1.0) as u32,
        }
    }

    /// The floor of the bitrate, bits a second.
    pub fn min_bitrate_bps(&self) -> u32 {
        self.min_bitrate_kbps
            .unwrap_or((self.bitrate_kbps / 4).max(50))
            .min(self.bitrate_kbps)
            .saturating_mul(1000)
    }

    /// What is wrong with it, as (field, message).
    pub(crate) fn problem(&self) -> Option<(&'static str, String)> {
        if !(self.fps.is_finite() && (1.0..=60.0).contains(&self.fps)) {
            return Some((
                "fps",
                format!("must be 1 to 60 (frames a second), got {}", self.fps),
            ));
        }
        if !(50..=50_000).contains(&self.bitrate_kbps) {
            return Some((
                "bitrate_kbps",
                format!(
                    "must be 50 to 50000 (kilobits a second; 640x480 at 15 fps looks good \
                     from about 500), got {}",
                    self.bitrate_kbps
                ),
            ));
        }
        if let Some(min) = self.min_bitrate_kbps
            && !(50..=self.bitrate_kbps).contains(&min)
        {
            return Some((
                "min_bitrate_kbps",
                format!(
                    "must be 50 to bitrate_kbps ({}), got {min}",
                    self.bitrate_kbps
                ),
            ));
        }
        if !(self.keyframe_s.is_finite() && (0.2..=60.0).contains(&self.keyframe_s)) {
            return Some((
                "keyframe_s",
                format!(
                    "must be 0.2 to 60 (seconds between keyframes), got {}",
                    self.keyframe_s
                ),
            ));
        }
        None
    }
}
