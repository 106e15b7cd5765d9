//! Camera video: a robot's camera images turned into H.264, one access unit per message, as
//! `foxglove_msgs/msg/CompressedVideo` (docs/video.md).
//!
//! What it owns, from the inside out:
//! - [`source`]: reading a camera message (`sensor_msgs/msg/Image` or `CompressedImage`, CDR)
//!   without copying its pixels;
//! - [`picture`]: those pixels as the encoder's 4:2:0 planes (raw formats and JPEG);
//! - [`encoder`]: OpenH264 set up for live camera video (Constrained Baseline, no B-frames,
//!   parameter sets before every keyframe, frames skipped rather than queued);
//! - [`h264`] (from `fleetlink-msg`, which the router shares): what a frame's bitstream
//!   says (keyframe or not, the codec string);
//! - [`message`]: the `CompressedVideo` message written straight as CDR;
//! - [`quality`]: the encoder measured against JPEG on the same frames (the benchmark);
//! - [`stream`]: one encoder thread per stream behind a queue of two frames that drops the
//!   oldest;
//! - [`rate`]: the stream's target bitrate following its link.
//!
//! No sockets and no async runtime: the agent decides when a stream runs (someone watches
//! it) and publishes what it makes.

pub mod encoder;
pub use fleetlink_msg::h264;
pub mod message;
pub mod picture;
pub mod quality;
pub mod rate;
pub mod source;
pub mod stream;

pub use encoder::{EncodedFrame, H264Encoder, Settings};
pub use stream::{Output, Stream, StreamStats};

/// The ROS 2 type of a video topic.
pub const VIDEO_TYPE: &str = "foxglove_msgs/msg/CompressedVideo";

/// What went wrong with one frame. The stream goes on with the next.
#[derive(Debug, thiserror::Error)]
pub enum VideoError {
    #[error("the camera message is cut short or malformed ({0}); is the topic's type right?")]
    Malformed(&'static str),
    #[error(
        "image encoding '{0}' is not one the video encoder takes: use rgb8, bgr8, rgba8, \
         bgra8, mono8, yuv422 (UYVY), yuv422_yuy2 (YUYV), or a JPEG CompressedImage"
    )]
    UnsupportedEncoding(String),
    #[error(
        "compressed image format '{0}' is not JPEG; only JPEG CompressedImage topics can be \
         offered as video"
    )]
    UnsupportedFormat(String),
    #[error("image {width}x{height} is {why}")]
    BadSize {
        width: u32,
        height: u32,
        why: &'static str,
    },
    #[error("the JPEG does not decode: {0}")]
    Jpeg(String),
    #[error("the H.264 encoder failed: {0}")]
    Encoder(String),
}
