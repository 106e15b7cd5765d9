//! `fleetlink bench video`: camera video against JPEG on the same frames
//! (docs/benchmarks.md, "Camera video"). For each clip: every frame as a JPEG of
//! `--jpeg-quality`, its bytes and luma PSNR; then the lowest H.264 bitrate whose stream
//! reaches that PSNR, its bytes, and the encoder's time per frame. The clips are raw RGB
//! frames (`scripts/bench-video.sh` makes them from public camera footage with PyAV); the
//! demo's camera is rendered here (`--demo-frames`).

use std::time::Duration;

use anyhow::{Context, bail};
use fleetlink_video::Settings;
use fleetlink_video::quality::{self, Clip, Figures, H264Figures};
use serde_json::json;

#[derive(clap::Args)]
pub struct Args {
    /// A clip of raw frames, `NAME=PATH` (WIDTH x HEIGHT rgb24 frames back to back); may
    /// be given several times.
    #[arg(long = "clip")]
    clips: Vec<String>,
    /// Frames of the demo robots' camera to render and measure as one more clip (0: none).
    #[arg(long, default_value_t = 150)]
    demo_frames: usize,
    /// The frames' width in pixels (the clips' and the demo camera's).
    #[arg(long, default_value_t = 640)]
    width: u32,
    /// The frames' height in pixels.
    #[arg(long, default_value_t = 480)]
    height: u32,
    /// The stream's frame rate (the clips' frames are taken as this rate's).
    #[arg(long, default_value_t = 15.0)]
    fps: f32,
    /// Seconds between keyframes.
    #[arg(long, default_value_t = 2.0)]
    keyframe_s: f32,
    /// The JPEG quality H.264 is compared with.
    #[arg(long, default_value_t = 80)]
    jpeg_quality: u8,
    /// One JSON object instead of the text lines.
    #[arg(long)]
    json: bool,
}

pub fn run(args: Args) -> anyhow::Result<()> {
    let mut clips = Vec::new();
    for spec in &args.clips {
        let (name, path) = spec
            .split_once('=')
            .with_context(|| format!("--clip {spec:?}: give NAME=PATH"))?;
        let bytes = std::fs::read(path).with_context(|| format!("reading clip {path}"))?;
        let frame = (args.width * args.height * 3) as usize;
        if bytes.is_empty() || bytes.len() % frame != 0 {
            bail!(
                "clip {path} is {} bytes, not a whole number of {}x{} rgb24 frames",
                bytes.len(),
                args.width,
                args.height
            );
        }
        let rgb = bytes.chunks_exact(frame).map(<[u8]>::to_vec).collect();
        clips.push((
            name.to_owned(),
            Clip {
                width: args.width,
                height: args.height,
                rgb,
            },
        ));
    }
    if args.demo_frames > 0 {
        clips.push(("demo camera".to_owned(), demo_clip(&args)?));
    }
    if clips.is_empty() {
        bail!("nothing to measure: give --clip NAME=PATH or --demo-frames N");
    }
    let base = Settings {
        fps: args.fps,
        bitrate_bps: 0,
        keyframe_every: (args.keyframe_s * args.fps).round().max(1.0) as u32,
    };
    let mut rows = Vec::new();
    for (name, clip) in &clips {
        let jpeg = quality::jpeg(clip, args.jpeg_quality)?;
        let video = quality::matching(clip, jpeg.psnr_db, base)?;
        let row = Row::new(name, clip.rgb.len(), args.fps, jpeg, video);
        if !args.json {
            println!("{}", row.text());
        }
        rows.push(row);
    }
    // A clip where H.264 did not reach JPEG's PSNR at any bitrate tried counts as 0.
    let mut ratios: Vec<f64> = rows
        .iter()
        .map(|r| if r.reached { r.ratio } else { 0.0 })
        .collect();
    ratios.sort_by(f64::total_cmp);
    let n = ratios.len();
    let median = (ratios[(n - 1) / 2] + ratios[n / 2]) / 2.0;
    let mut encode: Vec<f64> = rows
        .iter()
        .flat_map(|r| r.video.encode_ms.clone())
        .collect();
    encode.sort_by(f64::total_cmp);
    let (p50, p95) = (
        quality::quantile(&encode, 0.5),
        quality::quantile(&encode, 0.95),
    );
    if args.json {
        println!(
            "{}",
            json!({ "clips": rows, "median_ratio": median, "encode_ms_p50": p50, "encode_ms_p95": p95 })
        );
    } else {
        println!(
            "median: JPEG q{} / H.264 bytes at equal or better luma PSNR {median:.2}x over {} \
             clips; encode {}x{} p50 {p50:.2} ms, p95 {p95:.2} ms a frame",
            args.jpeg_quality,
            rows.len(),
            args.width,
            args.height
        );
    }
    Ok(())
}

#[derive(serde::Serialize)]
struct Row {
    name: String,
    frames: usize,
    jpeg: Figures,
    jpeg_kbytes_per_s: f64,
    video: H264Figures,
    video_kbytes_per_s: f64,
    /// JPEG bytes over H.264 bytes.
    ratio: f64,
    /// H.264 reached JPEG's PSNR (else `video` is the highest bitrate tried).
    reached: bool,
}

impl Row {
    fn new(name: &str, frames: usize, fps: f32, jpeg: Figures, video: H264Figures) -> Row {
        let seconds = frames as f64 / f64::from(fps);
        Row {
            name: name.to_owned(),
            frames,
            jpeg_kbytes_per_s: jpeg.bytes as f64 / seconds / 1e3,
            video_kbytes_per_s: video.figures.bytes as f64 / seconds / 1e3,
            ratio: jpeg.bytes as f64 / video.figures.bytes.max(1) as f64,
            reached: video.figures.psnr_db >= jpeg.psnr_db,
            jpeg,
            video,
        }
    }

    fn text(&self) -> String {
        format!(
            "{:<28} {:>4} frames  JPEG {:>7.1} kB/s {:>5.2} dB  H.264 {:>7.1} kB/s {:>5.2} dB \
             ({} kbit/s set, {} keyframes, {} skipped)  {:>5.2}x fewer bytes{}  encode p50 \
             {:.2} p95 {:.2} ms, convert p50 {:.2} ms",
            self.name,
            self.frames,
            self.jpeg_kbytes_per_s,
            self.jpeg.psnr_db,
            self.video_kbytes_per_s,
            self.video.figures.psnr_db,
            self.video.bitrate_bps / 1000,
            self.video.keyframes,
            self.video.skipped,
            self.ratio,
            if self.reached {
                ""
            } else {
                " (JPEG's PSNR not reached: counted as 0 in the median)"
            },
            quality::quantile(&self.video.encode_ms, 0.5),
            quality::quantile(&self.video.encode_ms, 0.95),
            quality::quantile(&self.video.convert_ms, 0.5),
        )
    }
}

/// The demo robots' camera at the clip size, one frame every 1/fps s along the robot's
/// patrol: rendered at JPEG quality 100 and decoded, as the source frames.
fn demo_clip(args: &Args) -> anyhow::Result<Clip> {
    use fleetlink_agent::config::{ImageSim, SimConfig};
    let cfg = SimConfig {
        laser_scan: None,
        odometry: None,
        pose: None,
        point_cloud: None,
        markers: None,
        image: Some(ImageSim {
            width: args.width,
            height: args.height,
            quality: 100,
            rate_hz: f64::from(args.fps),
            ..ImageSim::default()
        }),
        ..SimConfig::default()
    };
    let mut sim = fleetlink_agent::sim::Sim::new(&cfg, "robot1", 0);
    let mut rgb = Vec::new();
    for i in 0..args.demo_frames {
        let at = Duration::from_secs_f64(i as f64 / f64::from(args.fps));
        let msg = sim.generate(0, at);
        let v: serde_json::Value = serde_json::from_slice(&msg.json)?;
        let b64 = v["data"]
            .as_str()
            .context("the camera message has its data")?;
        let jpeg = base64::Engine::decode(&base64::engine::general_purpose::STANDARD, b64)?;
        let mut dec = zune_jpeg::JpegDecoder::new(zune_core::bytestream::ZCursor::new(&jpeg));
        rgb.push(dec.decode().context("decoding the demo camera's JPEG")?);
    }
    Ok(Clip {
        width: args.width,
        height: args.height,
        rgb,
    })
}
