//! A camera's pixels as the encoder takes them: 4:2:0 planes (I420), kept and refilled frame
//! after frame so a stream allocates nothing once it runs.
//!
//! RGB, BGR and grey pixels and JPEGs become full-range BT.601 (the range JPEG itself uses,
//! so a JPEG camera's YCbCr passes through without a colour conversion either way); a
//! camera's YUV 4:2:2 stays in the limited range cameras send it in. The encoder signals
//! which in the stream ([`Range`]). Odd widths and heights lose their last column or row:
//! 4:2:0 needs both even.

use openh264::formats::YUVSource;
use zune_core::bytestream::ZCursor;
use zune_core::colorspace::ColorSpace;
use zune_core::options::DecoderOptions;
use zune_jpeg::JpegDecoder;

use crate::VideoError;
use crate::source::Pixels;

/// The largest picture taken: what OpenH264 encodes (level 5.2).
const MAX_WIDTH: u32 = 3840;
const MAX_HEIGHT: u32 = 2160;

/// The value range of the samples, told to decoders in the stream's VUI.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Range {
    /// 0–255 (JPEG's, and what RGB converts to here).
    Full,
    /// 16–235 luma, 16–240 chroma (video cameras' YUV).
    Limited,
}

/// One picture in I420: a luma plane and two quarter-size chroma planes.
#[derive(Debug, Default)]
pub struct Picture {
    width: usize,
    height: usize,
    y: Vec<u8>,
    u: Vec<u8>,
    v: Vec<u8>,
    /// The JPEG decoder's output, kept between frames.
    scratch: Vec<u8>,
    range: Option<Range>,
}

impl Picture {
    pub fn width(&self) -> usize {
        self.width
    }

    pub fn height(&self) -> usize {
        self.height
    }

    /// The range of the last picture filled in.
    pub fn range(&self) -> Range {
        self.range.unwrap_or(Range::Full)
    }

    /// The luma plane (`width` × `height`), for tests and measurements.
    pub fn luma(&self) -> &[u8] {
        &self.y
    }

    /// Fills the picture from a camera message's pixels.
    pub fn fill(&mut self, pixels: &Pixels<'_>) -> Result<(), VideoError> {
        match *pixels {
            Pixels::Raw {
                width,
                height,
                step,
                encoding,
                data,
            } => self.fill_raw(width, height, step, encoding, data),
            Pixels::Jpeg(jpeg) => self.fill_jpeg(jpeg),
        }
    }

    fn resize(&mut self, width: u32, height: u32) -> Result<(), VideoError> {
        let bad = |why| VideoError::BadSize { width, height, why };
        if width < 2 || height < 2 {
            return Err(bad("too small (at least 2x2)"));
        }
        if width.max(height) > MAX_WIDTH || width.min(height) > MAX_HEIGHT {
            return Err(bad("larger than H.264 level 5.2 takes (3840x2160)"));
        }
        self.width = (width & !1) as usize;
        self.height = (height & !1) as usize;
        let (w, h) = (self.width, self.height);
        self.y.resize(w * h, 0);
        self.u.resize(w / 2 * h / 2, 0);
        self.v.resize(w / 2 * h / 2, 0);
        Ok(())
    }

    fn fill_raw(
        &mut self,
        width: u32,
        height: u32,
        step: u32,
        encoding: &str,
        data: &[u8],
    ) -> Result<(), VideoError> {
        let layout = match encoding {
            "rgb8" => Layout::Rgb { px: 3, r: 0, b: 2 },
            "bgr8" => Layout::Rgb { px: 3, r: 2, b: 0 },
            "rgba8" => Layout::Rgb { px: 4, r: 0, b: 2 },
            "bgra8" => Layout::Rgb { px: 4, r: 2, b: 0 },
            "mono8" | "8UC1" => Layout::Grey,
            "yuv422" | "uyvy" => Layout::Yuv422 { y0: 1, u: 0, v: 2 },
            "yuv422_yuy2" | "yuyv" => Layout::Yuv422 { y0: 0, u: 1, v: 3 },
            other => return Err(VideoError::UnsupportedEncoding(other.to_owned())),
        };
        let bad = |why| VideoError::BadSize { width, height, why };
        let row = width as usize * layout.bytes_per_pixel();
        if (step as usize) < row {
            return Err(bad("wider than its row step says"));
        }
        let need = (step as usize)
            .checked_mul(height as usize - 1)
            .and_then(|n| n.checked_add(row));
        if height == 0 || need.is_none_or(|n| data.len() < n) {
            return Err(bad("larger than its data"));
        }
        self.resize(width, height)?;
        let step = step as usize;
        match layout {
            Layout::Rgb { px, r, b } => self.load_rgb(data, step, px, r, b),
            Layout::Grey => self.load_grey(data, step),
            Layout::Yuv422 { y0, u, v } => self.load_yuv422(data, step, y0, u, v),
        }
        Ok(())
    }

    fn load_rgb(&mut self, data: &[u8], step: usize, px: usize, r: usize, b: usize) {
        let (w, h) = (self.width, self.height);
        for row in 0..h {
            let src = &data[row * step..][..w * px];
            let out = &mut self.y[row * w..][..w];
            for (o, p) in out.iter_mut().zip(src.chunks_exact(px)) {
                *o = luma(p[r], p[1], p[b]);
            }
        }
        // Chroma from each 2x2 block's mean colour.
        let cw = w / 2;
        for cy in 0..h / 2 {
            let top = &data[2 * cy * step..];
            let bottom = &data[(2 * cy + 1) * step..];
            for cx in 0..cw {
                let at = 2 * cx * px;
                let sum = |c: usize| {
                    u32::from(top[at + c])
                        + u32::from(top[at + px + c])
                        + u32::from(bottom[at + c])
                        + u32::from(bottom[at + px + c])
                };
                let (u, v) = chroma(sum(r), sum(1), sum(b));
                self.u[cy * cw + cx] = u;
                self.v[cy * cw + cx] = v;
            }
        }
        self.range = Some(Range::Full);
    }

    fn load_grey(&mut self, data: &[u8], step: usize) {
        let w = self.width;
        for row in 0..self.height {
            self.y[row * w..][..w].copy_from_slice(&data[row * step..][..w]);
        }
        self.u.fill(128);
        self.v.fill(128);
        self.range = Some(Range::Full);
    }

    fn load_yuv422(&mut self, data: &[u8], step: usize, y0: usize, u: usize, v: usize) {
        let (w, h) = (self.width, self.height);
        let cw = w / 2;
        for row in 0..h {
            let src = &data[row * step..][..w * 2];
            let out = &mut self.y[row * w..][..w];
            for (pair, quad) in out.chunks_exact_mut(2).zip(src.chunks_exact(4)) {
                pair[0] = quad[y0];
                pair[1] = quad[y0 + 2];
            }
        }
        // 4:2:2 has chroma on every row; 4:2:0 keeps the mean of each two.
        for cy in 0..h / 2 {
            let top = &data[2 * cy * step..][..w * 2];
            let bottom = &data[(2 * cy + 1) * step..][..w * 2];
            for cx in 0..cw {
                let (t, b) = (&top[cx * 4..], &bottom[cx * 4..]);
                self.u[cy * cw + cx] = mean2(t[u], b[u]);
                self.v[cy * cw + cx] = mean2(t[v], b[v]);
            }
        }
        self.range = Some(Range::Limited);
    }

    fn fill_jpeg(&mut self, jpeg: &[u8]) -> Result<(), VideoError> {
        let jpeg_err = |e: zune_jpeg::errors::DecodeErrors| VideoError::Jpeg(e.to_string());
        let options = DecoderOptions::default().jpeg_set_out_colorspace(ColorSpace::YCbCr);
        let mut dec = JpegDecoder::new_with_options(ZCursor::new(jpeg), options);
        dec.decode_headers().map_err(jpeg_err)?;
        let (width, height) = dec
            .dimensions()
            .ok_or(VideoError::Jpeg("no size in its header".into()))?;
        let space = dec
            .output_colorspace()
            .ok_or(VideoError::Jpeg("no colour space in its header".into()))?;
        let size = dec
            .output_buffer_size()
            .ok_or(VideoError::Jpeg("no size in its header".into()))?;
        let mut scratch = std::mem::take(&mut self.scratch);
        scratch.resize(size, 0);
        let decoded = dec.decode_into(&mut scratch).map_err(jpeg_err);
        let (w, h) = (width as u32, height as u32);
        let filled = decoded.and_then(|()| match space {
            ColorSpace::YCbCr => {
                self.resize(w, h)?;
                self.load_ycbcr444(&scratch, width);
                Ok(())
            }
            ColorSpace::Luma => {
                self.resize(w, h)?;
                self.load_grey(&scratch, width);
                Ok(())
            }
            ColorSpace::RGB => {
                self.resize(w, h)?;
                self.load_rgb(&scratch, width * 3, 3, 0, 2);
                Ok(())
            }
            other => Err(VideoError::Jpeg(format!(
                "it decodes to {other:?}, not YCbCr, RGB or grey"
            ))),
        });
        self.scratch = scratch;
        filled
    }

    /// From the JPEG decoder's interleaved full-resolution YCbCr.
    fn load_ycbcr444(&mut self, data: &[u8], width: usize) {
        let (w, h) = (self.width, self.height);
        let step = width * 3;
        for row in 0..h {
            let src = &data[row * step..][..w * 3];
            for (o, p) in self.y[row * w..][..w].iter_mut().zip(src.chunks_exact(3)) {
                *o = p[0];
            }
        }
        let cw = w / 2;
        for cy in 0..h / 2 {
            let top = &data[2 * cy * step..];
            let bottom = &data[(2 * cy + 1) * step..];
            for cx in 0..cw {
                let at = 6 * cx;
                let mean = |c: usize| {
                    let s = u32::from(top[at + c])
                        + u32::from(top[at + 3 + c])
                        + u32::from(bottom[at + c])
                        + u32::from(bottom[at + 3 + c]);
                    ((s + 2) / 4) as u8
                };
                self.u[cy * cw + cx] = mean(1);
                self.v[cy * cw + cx] = mean(2);
            }
        }
        self.range = Some(Range::Full);
    }
}

impl YUVSource for Picture {
    fn dimensions(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    fn strides(&self) -> (usize, usize, usize) {
        (self.width, self.width / 2, self.width / 2)
    }

    fn y(&self) -> &[u8] {
        &self.y
    }

    fn u(&self) -> &[u8] {
        &self.u
    }

    fn v(&self) -> &[u8] {
        &self.v
    }
}

#[derive(Debug, Clone, Copy)]
enum Layout {
    /// `px` bytes a pixel, red at `r`, green at 1, blue at `b`.
    Rgb {
        px: usize,
        r: usize,
        b: usize,
    },
    Grey,
    /// Two pixels in four bytes: luma at `y0` and `y0 + 2`.
    Yuv422 {
        y0: usize,
        u: usize,
        v: usize,
    },
}

impl Layout {
    fn bytes_per_pixel(self) -> usize {
        match self {
            Layout::Rgb { px, .. } => px,
            Layout::Grey => 1,
            Layout::Yuv422 { .. } => 2,
        }
    }
}

/// Full-range BT.601 luma, in 16-bit fixed point.
fn luma(r: u8, g: u8, b: u8) -> u8 {
    let y = 19_595 * u32::from(r) + 38_470 * u32::from(g) + 7_471 * u32::from(b);
    ((y + 32_768) >> 16) as u8
}

/// Full-range BT.601 chroma of a 2x2 block, from the sums of its four samples.
fn chroma(r4: u32, g4: u32, b4: u32) -> (u8, u8) {
    let (r, g, b) = (r4 as i64, g4 as i64, b4 as i64);
    // Coefficients × 2^16, and the block's sums are 4× the mean: shift by 18.
    let u = (-11_059 * r - 21_709 * g + 32_768 * b + (1 << 17)) >> 18;
    let v = (32_768 * r - 27_439 * g - 5_329 * b + (1 << 17)) >> 18;
    ((u + 128).clamp(0, 255) as u8, (v + 128).clamp(0, 255) as u8)
}

fn mean2(a: u8, b: u8) -> u8 {
    ((u16::from(a) + u16::from(b)).div_ceil(2)) as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    fn raw<'a>(w: u32, h: u32, encoding: &'a str, data: &'a [u8]) -> Pixels<'a> {
        let bpp = data.len() as u32 / (w * h);
        Pixels::Raw {
            width: w,
            height: h,
            step: w * bpp,
            encoding,
            data,
        }
    }

    #[test]
    fn primary_colours_land_where_bt601_puts_them() {
        let mut p = Picture::default();
        for (rgb, y, u, v) in [
            ([255, 255, 255], 255, 128, 128),
            ([0, 0, 0], 0, 128, 128),
            ([255, 0, 0], 76, 85, 255),
            ([0, 255, 0], 150, 44, 21),
            ([0, 0, 255], 29, 255, 107),
        ] {
            let data: Vec<u8> = rgb.iter().copied().cycle().take(4 * 3).collect();
            p.fill(&raw(2, 2, "rgb8", &data)).unwrap();
            assert_eq!((p.y[0], p.u[0], p.v[0]), (y, u, v), "{rgb:?}");
            let bgr: Vec<u8> = [rgb[2], rgb[1], rgb[0]]
                .iter()
                .copied()
                .cycle()
                .take(12)
                .collect();
            p.fill(&raw(2, 2, "bgr8", &bgr)).unwrap();
            assert_eq!((p.y[0], p.u[0], p.v[0]), (y, u, v), "bgr {rgb:?}");
        }
    }

    #[test]
    fn yuv422_keeps_its_samples_and_range() {
        // UYVY: U Y0 V Y1 on two rows.
        let uyvy = [10, 20, 30, 40, 50, 60, 70, 80];
        let mut p = Picture::default();
        p.fill(&raw(2, 2, "yuv422", &uyvy)).unwrap();
        assert_eq!(p.y, [20, 40, 60, 80]);
        assert_eq!((p.u[0], p.v[0]), (30, 50));
        assert_eq!(p.range(), Range::Limited);
        let yuyv = [20, 10, 40, 30, 60, 50, 80, 70];
        p.fill(&raw(2, 2, "yuv422_yuy2", &yuyv)).unwrap();
        assert_eq!(p.y, [20, 40, 60, 80]);
        assert_eq!((p.u[0], p.v[0]), (30, 50));
    }

    #[test]
    fn odd_sizes_drop_a_column_and_a_row_and_strides_are_honoured() {
        // 3x3 grey with a row step of 5 (two bytes of padding a row).
        let data = [1, 2, 3, 0, 0, 4, 5, 6, 0, 0, 7, 8, 9];
        let mut p = Picture::default();
        p.fill(&Pixels::Raw {
            width: 3,
            height: 3,
            step: 5,
            encoding: "mono8",
            data: &data,
        })
        .unwrap();
        assert_eq!((p.width(), p.height()), (2, 2));
        assert_eq!(p.y, [1, 2, 4, 5]);
    }

    #[test]
    fn bad_pictures_are_refused_with_what_is_wrong() {
        let mut p = Picture::default();
        let e = p.fill(&raw(2, 2, "16UC1", &[0; 8])).unwrap_err();
        assert!(e.to_string().contains("'16UC1'"), "{e}");
        let short = Pixels::Raw {
            width: 4,
            height: 4,
            step: 12,
            encoding: "rgb8",
            data: &[0; 40],
        };
        let e = p.fill(&short).unwrap_err();
        assert!(e.to_string().contains("larger than its data"), "{e}");
        let narrow = Pixels::Raw {
            width: 4,
            height: 1,
            step: 4,
            encoding: "rgb8",
            data: &[0; 12],
        };
        assert!(p.fill(&narrow).is_err());
        let e = p.fill(&Pixels::Jpeg(&[0xFF, 0xD8, 1, 2])).unwrap_err();
        assert!(matches!(e, VideoError::Jpeg(_)), "{e}");
    }

    #[test]
    fn a_jpeg_passes_its_luma_through() {
        // A flat grey-blue picture: JPEG keeps flat colour nearly exactly.
        let (w, h) = (32u16, 16u16);
        let rgb: Vec<u8> = [90u8, 120, 200]
            .iter()
            .copied()
            .cycle()
            .take(32 * 16 * 3)
            .collect();
        let mut jpeg = Vec::new();
        jpeg_encoder::Encoder::new(&mut jpeg, 95)
            .encode(&rgb, w, h, jpeg_encoder::ColorType::Rgb)
            .unwrap();
        let mut p = Picture::default();
        p.fill(&Pixels::Jpeg(&jpeg)).unwrap();
        assert_eq!((p.width(), p.height()), (32, 16));
        let want = luma(90, 120, 200);
        assert!(
            p.y.iter().all(|&y| y.abs_diff(want) <= 2),
            "{want} vs {:?}",
            &p.y[..4]
        );
        let (u, v) = chroma(4 * 90, 4 * 120, 4 * 200);
        assert!(p.u[0].abs_diff(u) <= 2 && p.v[0].abs_diff(v) <= 2);
    }
}
