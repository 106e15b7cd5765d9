//! OpenH264 set up for live camera video: Constrained Baseline (no B-frames, so every frame
//! can be shown as it arrives), one slice, the parameter sets before every keyframe, rate
//! control by bitrate with frame skipping (over budget, the encoder leaves a frame out
//! rather than the link queueing it), and the samples' range told in the VUI.
//!
//! The encoder is made at the first picture, when its range is known, and made again when
//! the range changes (the next frame is a keyframe either way).

use std::path::PathBuf;

use openh264::encoder::{
    BitRate, Complexity, Encoder, EncoderConfig, FrameRate, FrameType, IntraFramePeriod, Profile,
    RateControlMode, SpsPpsStrategy, UsageType, VuiConfig,
};
use openh264::{OpenH264API, Timestamp};

use crate::VideoError;
use crate::picture::{Picture, Range};

/// How a stream is encoded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Frames a second at most.
    pub fps: f32,
    /// Target bits a second.
    pub bitrate_bps: u32,
    /// A keyframe at least this often, in frames.
    pub keyframe_every: u32,
}

/// One encoded frame: an Annex B access unit.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EncodedFrame {
    pub keyframe: bool,
}

/// An H.264 encoder for one stream.
pub struct H264Encoder {
    settings: Settings,
    /// Cisco's prebuilt OpenH264 library to load instead of the one built in.
    library: Option<PathBuf>,
    encoder: Option<(Encoder, Range)>,
    force_keyframe: bool,
}

impl H264Encoder {
    /// An encoder of the OpenH264 compiled into this binary, or of the library at
    /// `library` (Cisco's prebuilt `libopenh264.so`, loaded at the first frame).
    pub fn new(settings: Settings, library: Option<PathBuf>) -> H264Encoder {
        H264Encoder {
            settings,
            library,
            encoder: None,
            force_keyframe: false,
        }
    }

    pub fn settings(&self) -> Settings {
        self.settings
    }

    /// The next frame is a keyframe.
    pub fn request_keyframe(&mut self) {
        self.force_keyframe = true;
    }

    /// Changes the target bitrate from the next frame on, without a keyframe (the stream
    /// follows its link: [`crate::rate`]). The `openh264` crate sets the bitrate only when
    /// it makes an encoder, and making one starts with a keyframe, the frame a slow link
    /// can least afford: so the option is set through its raw API, the crate's one use of
    /// `unsafe`.
    #[allow(unsafe_code)]
    pub fn set_bitrate(&mut self, bps: u32) -> Result<(), VideoError> {
        self.settings.bitrate_bps = bps;
        let Some((encoder, _)) = &mut self.encoder else {
            return Ok(()); // made with it at the first picture
        };
        let mut info = openh264_sys2::SBitrateInfo {
            iLayer: openh264_sys2::SPATIAL_LAYER_ALL,
            iBitrate: i32::try_from(bps).unwrap_or(i32::MAX),
        };
        // The maximum first: the encoder refuses a target above it.
        for option in [
            openh264_sys2::ENCODER_OPTION_MAX_BITRATE,
            openh264_sys2::ENCODER_OPTION_BITRATE,
        ] {
            // SAFETY: the encoder is initialised (it was made with a configuration), and
            // both options take a pointer to an `SBitrateInfo` that lives through the
            // call; neither changes anything the bindings rely on (sizes, formats).
            let rc = unsafe { encoder.raw_api().set_option(option, (&raw mut info).cast()) };
            if rc != 0 {
                return Err(VideoError::Encoder(format!(
                    "OpenH264 refused the bitrate {bps} b/s (option {option}: error {rc})"
                )));
            }
        }
        Ok(())
    }

    /// Encodes `picture` captured at `stamp_ms`, appending its access unit to `out`.
    /// `None` when the encoder skipped the frame to keep to its bitrate.
    pub fn encode(
        &mut self,
        picture: &Picture,
        stamp_ms: u64,
        out: &mut Vec<u8>,
    ) -> Result<Option<EncodedFrame>, VideoError> {
        let range = picture.range();
        if self.encoder.as_ref().is_none_or(|(_, r)| *r != range) {
            let config = config(self.settings, range);
            let api = match &self.library {
                None => OpenH264API::from_source(),
                Some(path) => OpenH264API::from_blob_path(path).map_err(|e| {
                    VideoError::Encoder(format!("cannot load {}: {e}", path.display()))
                })?,
            };
            let encoder = Encoder::with_api_config(api, config)
                .map_err(|e| VideoError::Encoder(e.to_string()))?;
            self.encoder = Some((encoder, range));
        }
        let (encoder, _) = self.encoder.as_mut().expect("made above");
        if std::mem::take(&mut self.force_keyframe) {
            encoder.force_intra_frame();
        }
        let stream = encoder
            .encode_at(picture, Timestamp::from_millis(stamp_ms))
            .map_err(|e| VideoError::Encoder(e.to_string()))?;
        let keyframe = match stream.frame_type() {
            FrameType::Skip | FrameType::Invalid => return Ok(None),
            FrameType::IDR => true,
            _ => false,
        };
        let before = out.len();
        stream.write_vec(out);
        if out.len() == before {
            return Ok(None);
        }
        Ok(Some(EncodedFrame { keyframe }))
    }
}

fn config(s: Settings, range: Range) -> EncoderConfig {
    let vui = VuiConfig::bt601().full_range(range == Range::Full);
    EncoderConfig::new()
        .usage_type(UsageType::CameraVideoRealTime)
        .profile(Profile::Baseline)
        .complexity(Complexity::Low)
        .rate_control_mode(RateControlMode::Bitrate)
        .bitrate(BitRate::from_bps(s.bitrate_bps))
        .max_frame_rate(FrameRate::from_hz(s.fps))
        .skip_frames(true)
        .intra_frame_period(IntraFramePeriod::from_num_frames(s.keyframe_every.max(1)))
        .sps_pps_strategy(SpsPpsStrategy::ConstantId)
        .num_threads(1)
        .vui(vui)
}

#[cfg(test)]
pub(crate) mod tests {
    use openh264::decoder::Decoder;
    use openh264::formats::YUVSource;

    use super::*;
    use crate::h264;
    use crate::source::Pixels;

    /// A moving test card: gradients and a bright square that moves 4 px a frame.
    pub(crate) fn card(w: usize, h: usize, frame: usize) -> Vec<u8> {
        let mut rgb = vec![0u8; w * h * 3];
        for y in 0..h {
            for x in 0..w {
                let i = (y * w + x) * 3;
                let inside = (x + 400 - 4 * frame % 400) % 400 < 64 && (y / 64) % 2 == 0;
                rgb[i] = if inside { 250 } else { (x * 255 / w) as u8 };
                rgb[i + 1] = if inside { 240 } else { (y * 255 / h) as u8 };
                rgb[i + 2] = 128;
            }
        }
        rgb
    }

    fn psnr(a: &[u8], b: &[u8]) -> f64 {
        let mse: f64 = a
            .iter()
            .zip(b)
            .map(|(&x, &y)| (f64::from(x) - f64::from(y)).powi(2))
            .sum::<f64>()
            / a.len() as f64;
        10.0 * (255.0f64 * 255.0 / mse.max(1e-9)).log10()
    }

    /// `pic` holds the `w`×`h` rgb8 picture `rgb`.
    fn fill_rgb(pic: &mut Picture, w: usize, h: usize, rgb: &[u8]) {
        let pixels = Pixels::Raw {
            width: w as u32,
            height: h as u32,
            step: (w * 3) as u32,
            encoding: "rgb8",
            data: rgb,
        };
        pic.fill(&pixels).unwrap();
    }

    #[test]
    fn frames_decode_from_the_first_and_keyframes_come_when_asked() {
        let (w, h) = (160, 96);
        let settings = Settings {
            fps: 15.0,
            bitrate_bps: 2_000_000,
            keyframe_every: 10,
        };
        let mut enc = H264Encoder::new(settings, None);
        let mut dec = Decoder::new().unwrap();
        let mut pic = Picture::default();
        let mut keyframes = Vec::new();
        for f in 0..25 {
            fill_rgb(&mut pic, w, h, &card(w, h, f));
            if f == 13 {
                enc.request_keyframe();
            }
            let mut out = Vec::new();
            let Some(frame) = enc.encode(&pic, f as u64 * 66, &mut out).unwrap() else {
                continue;
            };
            assert_eq!(frame.keyframe, h264::is_keyframe(&out), "frame {f}");
            if frame.keyframe {
                keyframes.push(f);
                assert_eq!(
                    h264::codec_string(&out).as_deref().map(|c| &c[..7]),
                    Some("avc1.42")
                );
            }
            let yuv = dec
                .decode(&out)
                .unwrap()
                .expect("a picture per access unit");
            assert_eq!(yuv.dimensions(), (w, h));
            let y_plane: Vec<u8> = (0..h)
                .flat_map(|row| yuv.y()[row * yuv.strides().0..][..w].to_vec())
                .collect();
            let p = psnr(&y_plane, pic.luma());
            assert!(p > 30.0, "frame {f}: luma PSNR {p:.1} dB");
        }
        assert_eq!(keyframes.first(), Some(&0), "the first frame is a keyframe");
        assert!(
            keyframes.contains(&13),
            "the asked-for keyframe: {keyframes:?}"
        );
        assert!(
            keyframes.contains(&10),
            "the periodic keyframe: {keyframes:?}"
        );
    }

    #[test]
    fn a_lower_bitrate_takes_effect_without_a_keyframe() {
        let (w, h) = (320, 240);
        let settings = Settings {
            fps: 15.0,
            bitrate_bps: 2_000_000,
            keyframe_every: 1000,
        };
        let mut enc = H264Encoder::new(settings, None);
        let mut pic = Picture::default();
        // Bytes of frames 15..45 (after the rate control settled) at one bitrate, then
        // the next 30 after the change.
        let (mut before, mut after) = (0usize, 0usize);
        let mut keyframes_after_change = 0;
        // Noise: more detail than either bitrate carries, so both are used in full.
        let mut x = 0x2545_f491_4f6c_dd1du64;
        let mut noise = move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x as u8
        };
        for f in 0..90 {
            let rgb: Vec<u8> = (0..w * h * 3).map(|_| noise()).collect();
            fill_rgb(&mut pic, w, h, &rgb);
            if f == 45 {
                enc.set_bitrate(200_000).unwrap();
                assert_eq!(enc.settings().bitrate_bps, 200_000);
            }
            let mut out = Vec::new();
            let frame = enc.encode(&pic, f as u64 * 66, &mut out).unwrap();
            match f {
                15..45 => before += out.len(),
                60..90 => after += out.len(),
                _ => {}
            }
            if f >= 45 && frame.is_some_and(|fr| fr.keyframe) {
                keyframes_after_change += 1;
            }
        }
        assert_eq!(keyframes_after_change, 0, "no keyframe for a new bitrate");
        assert!(
            after * 4 < before,
            "30 frames: {before} bytes at 2 Mbit/s, {after} bytes at 200 kbit/s"
        );
    }
}
