//! What an H.264 access unit (Annex B: NAL units behind `00 00 01` or `00 00 00 01` start
//! codes) says about itself: whether a decoder can start at it, and the codec string a
//! browser's `VideoDecoder` wants, read from its sequence parameter set. Also where the
//! access unit sits in a `foxglove_msgs/msg/CompressedVideo` message's CDR, so the router
//! can tell a keyframe without decoding the message.
//!
//! Only the units in front of the first slice are looked at: the parameter sets and the
//! slice's header byte. A frame's picture data is never scanned.

use memchr::memmem;

/// NAL unit types this module looks for (H.264 Table 7-1).
const NAL_SLICE: u8 = 1;
const NAL_IDR: u8 = 5;
const NAL_SPS: u8 = 7;
const NAL_PPS: u8 = 8;

/// The NAL units of an Annex B access unit, each without its start code.
pub fn nal_units(data: &[u8]) -> impl Iterator<Item = &[u8]> {
    let mut rest = data;
    std::iter::from_fn(move || {
        let start = memmem::find(rest, &[0, 0, 1])? + 3;
        let body = &rest[start..];
        let end = memmem::find(body, &[0, 0, 1]).unwrap_or(body.len());
        rest = &body[end..];
        // A four-byte start code leaves a zero at the end of the unit before it.
        let unit = &body[..end];
        Some(unit.strip_suffix(&[0]).unwrap_or(unit))
    })
}

/// The types of the units up to and including the first slice, without scanning the
/// slice itself.
fn leading_types(data: &[u8]) -> impl Iterator<Item = u8> {
    let mut rest = data;
    let mut done = false;
    std::iter::from_fn(move || {
        if done {
            return None;
        }
        let start = memmem::find(rest, &[0, 0, 1])? + 3;
        let ty = rest.get(start)? & 0x1F;
        done = (NAL_SLICE..=NAL_IDR).contains(&ty);
        rest = &rest[start..];
        Some(ty)
    })
}

/// The type of a NAL unit (its low five bits).
pub fn nal_type(unit: &[u8]) -> Option<u8> {
    unit.first().map(|b| b & 0x1F)
}

/// Whether a decoder can start at this access unit: its first slice is an IDR slice and
/// the parameter sets come before it.
pub fn is_keyframe(data: &[u8]) -> bool {
    let (mut sps, mut pps) = (false, false);
    for ty in leading_types(data) {
        match ty {
            NAL_SPS => sps = true,
            NAL_PPS => pps = true,
            NAL_IDR => return sps && pps,
            NAL_SLICE..NAL_IDR => return false,
            _ => {}
        }
    }
    false
}

/// The WebCodecs / RFC 6381 codec string of the stream, `avc1.PPCCLL` (profile,
/// constraint flags and level from the SPS), when the access unit carries an SPS.
pub fn codec_string(data: &[u8]) -> Option<String> {
    let sps = nal_units(data).find(|u| nal_type(u) == Some(NAL_SPS))?;
    let [_, profile, constraints, level, ..] = *sps else {
        return None;
    };
    Some(format!("avc1.{profile:02X}{constraints:02X}{level:02X}"))
}

/// The `data` field of a `foxglove_msgs/msg/CompressedVideo` message in CDR (`timestamp`,
/// `frame_id`, `data`, `format`), borrowed; `None` if the message is cut short.
pub fn compressed_video_data(cdr: &[u8]) -> Option<&[u8]> {
    let little = match cdr.get(1)? {
        0 | 2 => false,
        1 | 3 => true,
        _ => return None,
    };
    let body = cdr.get(4..)?;
    let u32_at = |at: usize| -> Option<u32> {
        let b: [u8; 4] = body.get(at..at + 4)?.try_into().ok()?;
        Some(if little {
            u32::from_le_bytes(b)
        } else {
            u32::from_be_bytes(b)
        })
    };
    // timestamp: sec, nanosec; then frame_id's length and bytes.
    let frame_id_len = u32_at(8)? as usize;
    let at = (12usize.checked_add(frame_id_len)?).next_multiple_of(4);
    let data_len = u32_at(at)? as usize;
    body.get(at + 4..(at + 4).checked_add(data_len)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    const UNIT: &[u8] = &[
        0, 0, 0, 1, 0x67, 0x42, 0xC0, 0x16, 0x8C, // SPS
        0, 0, 0, 1, 0x68, 0xCE, 0x3C, 0x80, // PPS
        0, 0, 1, 0x65, 0xB8, 0x00, 0x04, // IDR slice, three-byte start code
    ];

    #[test]
    fn units_are_split_at_both_start_code_lengths() {
        let units: Vec<&[u8]> = nal_units(UNIT).collect();
        assert_eq!(units.len(), 3);
        assert_eq!(units[0], [0x67, 0x42, 0xC0, 0x16, 0x8C]);
        assert_eq!(units[1], [0x68, 0xCE, 0x3C, 0x80]);
        assert_eq!(units[2], [0x65, 0xB8, 0x00, 0x04]);
        assert_eq!(nal_units(&[1, 2, 3]).count(), 0);
    }

    #[test]
    fn a_keyframe_needs_an_idr_slice_and_its_parameter_sets() {
        assert!(is_keyframe(UNIT));
        assert!(!is_keyframe(&UNIT[17..]), "an IDR slice alone");
        assert!(!is_keyframe(&[0, 0, 0, 1, 0x61, 0xE0]), "a P slice");
        // A P slice whose data happens to hold an IDR header is still a P slice.
        assert!(!is_keyframe(&[
            0, 0, 1, 0x61, 0, 0, 1, 0x67, 0, 0, 1, 0x68, 0, 0, 1, 0x65
        ]));
        assert!(!is_keyframe(&[]));
    }

    #[test]
    fn the_codec_string_comes_from_the_sps() {
        assert_eq!(codec_string(UNIT).as_deref(), Some("avc1.42C016"));
        assert_eq!(codec_string(&UNIT[17..]), None);
    }

    #[test]
    fn the_access_unit_is_found_in_a_compressed_video_message() {
        #[rustfmt::skip]
        let cdr: &[u8] = &[
            0, 1, 0, 0,
            3, 0, 0, 0, 7, 0, 0, 0,
            4, 0, 0, 0, b'c', b'a', b'm', 0,
            5, 0, 0, 0, 0, 0, 0, 1, 0x65, 0, 0, 0,
            5, 0, 0, 0, b'h', b'2', b'6', b'4', 0,
        ];
        assert_eq!(compressed_video_data(cdr), Some(&[0, 0, 0, 1, 0x65][..]));
        for cut in [0, 3, 15, 25] {
            assert_eq!(compressed_video_data(&cdr[..cut]), None, "cut at {cut}");
        }
    }
}
