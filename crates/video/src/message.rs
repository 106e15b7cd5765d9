//! `foxglove_msgs/msg/CompressedVideo` written straight as CDR: the encoder appends its
//! bitstream into the message's own buffer, so a frame is copied once, from the encoder.

/// The CDR of a `CompressedVideo` message around a bitstream that `write` appends to the
/// buffer it is given (little-endian CDR). `format` is the codec, `h264`.
pub fn compressed_video(
    stamp_ns: u64,
    frame_id: &str,
    format: &str,
    size_hint: usize,
    write: impl FnOnce(&mut Vec<u8>),
) -> Vec<u8> {
    let mut b = Vec::with_capacity(32 + frame_id.len() + size_hint + format.len());
    b.extend_from_slice(&[0, 1, 0, 0]);
    let sec = u32::try_from(stamp_ns / 1_000_000_000).unwrap_or(u32::MAX);
    b.extend_from_slice(&sec.to_le_bytes());
    b.extend_from_slice(&((stamp_ns % 1_000_000_000) as u32).to_le_bytes());
    string(&mut b, frame_id);
    align4(&mut b);
    let len_at = b.len();
    b.extend_from_slice(&[0; 4]);
    write(&mut b);
    let len = (b.len() - len_at - 4) as u32;
    b[len_at..len_at + 4].copy_from_slice(&len.to_le_bytes());
    align4(&mut b);
    string(&mut b, format);
    b
}

fn align4(b: &mut Vec<u8>) {
    // Alignment counts from the end of the four-byte encapsulation header.
    while !(b.len() - 4).is_multiple_of(4) {
        b.push(0);
    }
}

fn string(b: &mut Vec<u8>, s: &str) {
    align4(b);
    b.extend_from_slice(&(s.len() as u32 + 1).to_le_bytes());
    b.extend_from_slice(s.as_bytes());
    b.push(0);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_are_laid_out_with_cdr_alignment() {
        let au = [0, 0, 0, 1, 0x65];
        let b = compressed_video(3_000_000_007, "cam", "h264", 5, |v| {
            v.extend_from_slice(&au)
        });
        // Header, stamp (3 s, 7 ns), "cam" with its NUL and length.
        assert_eq!(
            b[..20],
            [
                0, 1, 0, 0, 3, 0, 0, 0, 7, 0, 0, 0, 4, 0, 0, 0, b'c', b'a', b'm', 0
            ]
        );
        assert_eq!(
            fleetlink_msg::h264::compressed_video_data(&b),
            Some(&au[..])
        );
        // The bitstream padded to four, then "h264" with its NUL and length.
        assert_eq!(b[29..], [0, 0, 0, 5, 0, 0, 0, b'h', b'2', b'6', b'4', 0]);
    }
}
