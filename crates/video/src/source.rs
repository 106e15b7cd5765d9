//! A camera message read in place: `sensor_msgs/msg/Image` or `sensor_msgs/msg/CompressedImage`
//! as CDR (what a ROS 2 robot publishes, and what the agent converts any other encoding
//! to once). The pixels are borrowed, never copied; only the fields the encoder needs are
//! read, in their fixed order.

use crate::VideoError;

/// Which camera type a source topic carries.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SourceKind {
    /// `sensor_msgs/msg/Image`: raw pixels.
    Image,
    /// `sensor_msgs/msg/CompressedImage`: a JPEG.
    Compressed,
}

impl SourceKind {
    /// The kind of a ROS type name (either spelling), or `None` for a type that is not a
    /// camera image.
    pub fn of_type(type_name: &str) -> Option<SourceKind> {
        match type_name {
            "sensor_msgs/msg/Image" | "sensor_msgs/Image" => Some(SourceKind::Image),
            "sensor_msgs/msg/CompressedImage" | "sensor_msgs/CompressedImage" => {
                Some(SourceKind::Compressed)
            }
            _ => None,
        }
    }
}

/// The pixels of a camera message.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pixels<'a> {
    Raw {
        width: u32,
        height: u32,
        /// Bytes per row (at least `width` × bytes per pixel).
        step: u32,
        encoding: &'a str,
        data: &'a [u8],
    },
    Jpeg(&'a [u8]),
}

/// One camera message, read in place.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CameraFrame<'a> {
    /// The header's stamp, nanoseconds since the Unix epoch (0 when the sender left it
    /// empty).
    pub stamp_ns: u64,
    pub frame_id: &'a str,
    pub pixels: Pixels<'a>,
}

/// Reads a CDR camera message of `kind`.
pub fn read(kind: SourceKind, cdr: &[u8]) -> Result<CameraFrame<'_>, VideoError> {
    let mut r = Cdr::new(cdr)?;
    let sec = r.u32()?;
    let nanosec = r.u32()?;
    let frame_id = r.string()?;
    let stamp_ns = u64::from(sec) * 1_000_000_000 + u64::from(nanosec);
    let pixels = match kind {
        SourceKind::Image => {
            let height = r.u32()?;
            let width = r.u32()?;
            let encoding = r.string()?;
            let _big_endian = r.u8()?;
            let step = r.u32()?;
            let data = r.bytes()?;
            Pixels::Raw {
                width,
                height,
                step,
                encoding,
                data,
            }
        }
        SourceKind::Compressed => {
            let format = r.string()?;
            let data = r.bytes()?;
            let jpeg = data.starts_with(&[0xFF, 0xD8]);
            let named = format.to_ascii_lowercase();
            if !(jpeg || named.contains("jpeg") || named.contains("jpg")) {
                return Err(VideoError::UnsupportedFormat(format.to_owned()));
            }
            Pixels::Jpeg(data)
        }
    };
    Ok(CameraFrame {
        stamp_ns,
        frame_id,
        pixels,
    })
}

/// A CDR reader over one message: alignment counts from the end of the 4-byte
/// encapsulation header, as the format says.
struct Cdr<'a> {
    body: &'a [u8],
    at: usize,
    little: bool,
}

impl<'a> Cdr<'a> {
    fn new(bytes: &'a [u8]) -> Result<Self, VideoError> {
        let (head, body) = bytes
            .split_at_checked(4)
            .ok_or(VideoError::Malformed("no encapsulation header"))?;
        let little = match head[1] {
            0 | 2 => false,
            1 | 3 => true,
            _ => return Err(VideoError::Malformed("unknown CDR encapsulation")),
        };
        Ok(Cdr {
            body,
            at: 0,
            little,
        })
    }

    fn take(&mut self, n: usize) -> Result<&'a [u8], VideoError> {
        let end = self.at.checked_add(n).filter(|&e| e <= self.body.len());
        let end = end.ok_or(VideoError::Malformed("a field runs past the end"))?;
        let s = &self.body[self.at..end];
        self.at = end;
        Ok(s)
    }

    fn u8(&mut self) -> Result<u8, VideoError> {
        Ok(self.take(1)?[0])
    }

    fn u32(&mut self) -> Result<u32, VideoError> {
        self.at = self.at.next_multiple_of(4);
        let b: [u8; 4] = self.take(4)?.try_into().expect("four bytes taken");
        Ok(if self.little {
            u32::from_le_bytes(b)
        } else {
            u32::from_be_bytes(b)
        })
    }

    fn bytes(&mut self) -> Result<&'a [u8], VideoError> {
        let n = self.u32()? as usize;
        self.take(n)
    }

    fn string(&mut self) -> Result<&'a str, VideoError> {
        let b = self.bytes()?;
        let b = b.strip_suffix(&[0]).unwrap_or(b);
        std::str::from_utf8(b).map_err(|_| VideoError::Malformed("a string is not UTF-8"))
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A CDR `sensor_msgs/msg/Image` (little-endian), laid out field by field.
    pub(crate) fn image_cdr(
        width: u32,
        height: u32,
        encoding: &str,
        step: u32,
        data: &[u8],
    ) -> Vec<u8> {
        let mut b = vec![0, 1, 0, 0];
        let w = |b: &mut Vec<u8>, bytes: &[u8], align: usize| {
            while !(b.len() - 4).is_multiple_of(align) {
                b.push(0);
            }
            b.extend_from_slice(bytes);
        };
        w(&mut b, &7u32.to_le_bytes(), 4);
        w(&mut b, &500u32.to_le_bytes(), 4);
        let frame_id = b"cam\0";
        w(&mut b, &(frame_id.len() as u32).to_le_bytes(), 4);
        w(&mut b, frame_id, 1);
        w(&mut b, &height.to_le_bytes(), 4);
        w(&mut b, &width.to_le_bytes(), 4);
        let enc = [encoding.as_bytes(), b"\0"].concat();
        w(&mut b, &(enc.len() as u32).to_le_bytes(), 4);
        w(&mut b, &enc, 1);
        w(&mut b, &[0], 1);
        w(&mut b, &step.to_le_bytes(), 4);
        w(&mut b, &(data.len() as u32).to_le_bytes(), 4);
        w(&mut b, data, 1);
        b
    }

    #[test]
    fn an_image_is_read_field_by_field_without_copying_its_pixels() {
        let data = vec![9u8; 4 * 2 * 3];
        let cdr = image_cdr(4, 2, "rgb8", 12, &data);
        let f = read(SourceKind::Image, &cdr).unwrap();
        assert_eq!(f.stamp_ns, 7_000_000_500);
        assert_eq!(f.frame_id, "cam");
        let Pixels::Raw {
            width,
            height,
            step,
            encoding,
            data: px,
        } = f.pixels
        else {
            panic!("raw pixels expected");
        };
        assert_eq!((width, height, step, encoding), (4, 2, 12, "rgb8"));
        assert_eq!(px.as_ptr(), cdr[cdr.len() - 24..].as_ptr());
    }

    #[test]
    fn a_message_cut_short_is_refused_with_the_reason() {
        let cdr = image_cdr(4, 2, "rgb8", 12, &[1; 24]);
        for cut in [0, 3, 10, cdr.len() - 1] {
            let e = read(SourceKind::Image, &cdr[..cut]).unwrap_err();
            assert!(matches!(e, VideoError::Malformed(_)), "{cut}: {e}");
        }
    }

    #[test]
    fn a_png_compressed_image_is_refused_by_name() {
        let mut b = vec![0, 1, 0, 0];
        b.extend_from_slice(&[0; 8]); // stamp
        b.extend_from_slice(&1u32.to_le_bytes());
        b.extend_from_slice(&[0, 0, 0, 0]); // "" and padding
        b.extend_from_slice(&4u32.to_le_bytes());
        b.extend_from_slice(b"png\0");
        b.extend_from_slice(&4u32.to_le_bytes());
        b.extend_from_slice(&[0x89, b'P', b'N', b'G']);
        let e = read(SourceKind::Compressed, &b).unwrap_err();
        assert!(e.to_string().contains("'png'"), "{e}");
    }
}
