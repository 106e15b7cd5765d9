//! Measuring the video encoder against JPEG on the same frames: bytes and luma PSNR (each
//! decoded picture's luma against the source's), for `fleetlink bench video`
//! (docs/benchmarks.md, "Camera video").
//!
//! The source's luma is what the encoder is given (full-range BT.601 of its RGB); a JPEG's
//! is its decoded Y plane, an H.264 frame's is OpenH264's decoded Y plane. A frame the
//! encoder leaves out (rate control) is scored as what a viewer goes on showing: the last
//! decoded picture.

use std::time::Instant;

use openh264::decoder::Decoder;
use openh264::formats::YUVSource;

use crate::VideoError;
use crate::encoder::{H264Encoder, Settings};
use crate::picture::Picture;
use crate::source::Pixels;

/// Frames of one clip, RGB, all the same size.
pub struct Clip {
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<Vec<u8>>,
}

/// One way of sending the clip: its bytes and quality.
#[derive(Debug, Clone, Default, serde::Serialize)]
pub struct Figures {
    /// Payload bytes of all frames.
    pub bytes: u64,
    /// Mean luma PSNR over the frames, dB.
    pub psnr_db: f64,
    /// The lowest frame's PSNR, dB.
    pub psnr_min_db: f64,
}

/// H.264's figures, with what it cost.
#[derive(Debug, Clone, Default, serde::Serialize)]
pub struct H264Figures {
    pub figures: Figures,
    pub bitrate_bps: u32,
    pub keyframes: u32,
    /// Frames the encoder left out.
    pub skipped: u32,
    /// Milliseconds per frame in the encoder, sorted.
    pub encode_ms: Vec<f64>,
    /// Milliseconds per frame turning RGB into the encoder's planes, sorted.
    pub convert_ms: Vec<f64>,
}

fn luma_of(picture: &mut Picture, clip: &Clip, rgb: &[u8]) -> Result<Vec<u8>, VideoError> {
    picture.fill(&raw(clip, rgb))?;
    Ok(picture.luma().to_vec())
}

fn raw<'a>(clip: &Clip, rgb: &'a [u8]) -> Pixels<'a> {
    Pixels::Raw {
        width: clip.width,
        height: clip.height,
        step: clip.width * 3,
        encoding: "rgb8",
        data: rgb,
    }
}

fn psnr(a: &[u8], b: &[u8]) -> f64 {
    let sum: u64 = a
        .iter()
        .zip(b)
        .map(|(&x, &y)| u64::from(x.abs_diff(y)).pow(2))
        .sum();
    let mse = sum as f64 / a.len().max(1) as f64;
    10.0 * (255.0f64 * 255.0 / mse.max(1e-6)).log10()
}

fn summarize(bytes: u64, scores: &[f64]) -> Figures {
    Figures {
        bytes,
        psnr_db: scores.iter().sum::<f64>() / scores.len().max(1) as f64,
        psnr_min_db: scores.iter().copied().fold(f64::INFINITY, f64::min),
    }
}

/// Every frame as a JPEG of `quality` (colour at half resolution below 90, as cameras do).
pub fn jpeg(clip: &Clip, quality: u8) -> Result<Figures, VideoError> {
    let (mut source, mut decoded) = (Picture::default(), Picture::default());
    let (mut bytes, mut scores) = (0, Vec::new());
    let mut buf = Vec::new();
    for rgb in &clip.rgb {
        buf.clear();
        jpeg_encoder::Encoder::new(&mut buf, quality)
            .encode(
                rgb,
                clip.width as u16,
                clip.height as u16,
                jpeg_encoder::ColorType::Rgb,
            )
            .map_err(|e| VideoError::Jpeg(e.to_string()))?;
        bytes += buf.len() as u64;
        let want = luma_of(&mut source, clip, rgb)?;
        decoded.fill(&Pixels::Jpeg(&buf))?;
        scores.push(psnr(&want, decoded.luma()));
    }
    Ok(summarize(bytes, &scores))
}

/// The clip as one H.264 stream with `settings`, decoded back frame by frame.
pub fn h264(clip: &Clip, settings: Settings) -> Result<H264Figures, VideoError> {
    let mut encoder = H264Encoder::new(settings, None);
    let mut decoder = Decoder::new().map_err(|e| VideoError::Encoder(e.to_string()))?;
    let mut picture = Picture::default();
    let mut out = H264Figures {
        bitrate_bps: settings.bitrate_bps,
        ..H264Figures::default()
    };
    let (mut bytes, mut scores) = (0, Vec::new());
    let mut shown: Option<Vec<u8>> = None;
    let mut au = Vec::new();
    for (i, rgb) in clip.rgb.iter().enumerate() {
        let t = Instant::now();
        picture.fill(&raw(clip, rgb))?;
        out.convert_ms.push(t.elapsed().as_secs_f64() * 1e3);
        au.clear();
        let stamp_ms = (i as f64 * 1000.0 / f64::from(settings.fps)) as u64;
        let t = Instant::now();
        let frame = encoder.encode(&picture, stamp_ms, &mut au)?;
        out.encode_ms.push(t.elapsed().as_secs_f64() * 1e3);
        match frame {
            Some(f) => {
                bytes += au.len() as u64;
                out.keyframes += u32::from(f.keyframe);
                let yuv = decoder
                    .decode(&au)
                    .map_err(|e| VideoError::Encoder(format!("decoding back: {e}")))?
                    .ok_or(VideoError::Encoder("no picture decoded".into()))?;
                let (w, h) = (picture.width(), picture.height());
                let stride = yuv.strides().0;
                let y: Vec<u8> = (0..h)
                    .flat_map(|r| &yuv.y()[r * stride..][..w])
                    .copied()
                    .collect();
                shown = Some(y);
            }
            None => out.skipped += 1,
        }
        let Some(y) = &shown else {
            return Err(VideoError::Encoder("the first frame was left out".into()));
        };
        scores.push(psnr(picture.luma(), y));
    }
    out.figures = summarize(bytes, &scores);
    out.encode_ms.sort_by(f64::total_cmp);
    out.convert_ms.sort_by(f64::total_cmp);
    Ok(out)
}

/// The lowest bitrate (to within a few per cent, between 50 kbit/s and 20 Mbit/s) at which
/// the stream's mean luma PSNR is at least `psnr_db`, and its figures; the highest tried
/// if none reaches it.
pub fn matching(clip: &Clip, psnr_db: f64, base: Settings) -> Result<H264Figures, VideoError> {
    let (mut lo, mut hi) = (50_000f64.ln(), 20_000_000f64.ln());
    let at = |ln: f64| Settings {
        bitrate_bps: ln.exp() as u32,
        ..base
    };
    let mut best = h264(clip, at(hi))?;
    for _ in 0..9 {
        let mid = (lo + hi) / 2.0;
        let f = h264(clip, at(mid))?;
        if f.figures.psnr_db >= psnr_db {
            hi = mid;
            best = f;
        } else {
            lo = mid;
        }
    }
    Ok(best)
}

/// The value at quantile `q` (0–1) of sorted figures.
pub fn quantile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return 0.0;
    }
    sorted[((sorted.len() - 1) as f64 * q).round() as usize]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn h264_is_found_at_jpegs_quality_for_fewer_bytes() {
        let (w, h) = (96usize, 64usize);
        let rgb = (0..20)
            .map(|f| crate::encoder::tests::card(w, h, f))
            .collect();
        let clip = Clip {
            width: w as u32,
            height: h as u32,
            rgb,
        };
        let j = jpeg(&clip, 80).unwrap();
        assert!(j.psnr_db > 30.0, "{j:?}");
        let base = Settings {
            fps: 15.0,
            bitrate_bps: 0,
            keyframe_every: 30,
        };
        let v = matching(&clip, j.psnr_db, base).unwrap();
        assert!(v.figures.psnr_db >= j.psnr_db, "{v:?} vs {j:?}");
        assert!(v.figures.bytes < j.bytes, "{v:?} vs {j:?}");
        assert_eq!(v.encode_ms.len(), 20);
        assert!(v.keyframes >= 1);
    }
}
