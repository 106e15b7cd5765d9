//! What an H.264 access unit (Annex B: NAL units behind `00 00 01` or `00 00 00 01` start
//! codes) says about itself: whether a decoder can start at it, and the codec string a
//! browser's `VideoDecoder` wants, read from its sequence parameter set.

/// NAL unit types this module looks for (H.264 Table 7-1).
const NAL_IDR: u8 = 5;
const NAL_SPS: u8 = 7;
const NAL_PPS: u8 = 8;

/// The NAL units of an Annex B access unit, each without its start code.
pub fn nal_units(data: &[u8]) -> impl Iterator<Item = &[u8]> {
    let mut rest = data;
    std::iter::from_fn(move || {
        let start = find_start(rest)?;
        let body = &rest[start..];
        let end = find_code(body).unwrap_or(body.len());
        rest = &body[end..];
        // A four-byte start code leaves a zero at the end of the unit before it.
        let unit = &body[..end];
        Some(unit.strip_suffix(&[0]).unwrap_or(unit))
    })
}

/// Where the first unit's bytes begin (just after a start code).
fn find_start(data: &[u8]) -> Option<usize> {
    find_code(data).map(|at| at + 3)
}

/// Where the next `00 00 01` begins.
fn find_code(data: &[u8]) -> Option<usize> {
    data.windows(3).position(|w| w == [0, 0, 1])
}

/// The type of a NAL unit (its low five bits).
pub fn nal_type(unit: &[u8]) -> Option<u8> {
    unit.first().map(|b| b & 0x1F)
}

/// Whether a decoder can start at this access unit: it holds an IDR slice and the
/// parameter sets it needs.
pub fn is_keyframe(data: &[u8]) -> bool {
    let (mut idr, mut sps, mut pps) = (false, false, false);
    for unit in nal_units(data) {
        match nal_type(unit) {
            Some(NAL_IDR) => idr = true,
            Some(NAL_SPS) => sps = true,
            Some(NAL_PPS) => pps = true,
            _ => {}
        }
    }
    idr && sps && pps
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
    }

    #[test]
    fn the_codec_string_comes_from_the_sps() {
        assert_eq!(codec_string(UNIT).as_deref(), Some("avc1.42C016"));
        assert_eq!(codec_string(&UNIT[17..]), None);
    }
}
