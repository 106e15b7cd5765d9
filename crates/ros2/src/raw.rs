//! One DDS sample as the bridge carries it: the CDR bytes with their 4-byte
//! encapsulation header, never decoded on the robot.
//!
//! rustdds hands a reader's adapter the representation identifier and the bytes after
//! the header; [`RawAdapter`] puts the header back (one copy, out of rustdds' receive
//! buffer) so the payload is exactly what a ROS 2 node serialized. On the way out it
//! hands rustdds the body as a slice of the same buffer (no copy); rustdds writes the
//! little-endian header itself.

use bytes::Bytes;
use rustdds::RepresentationIdentifier;
use rustdds::no_key::{Decode, DefaultDecoder, DeserializerAdapter, SerializerAdapter};

/// A CDR sample: `[0x00, 0x01 | 0x00, options(2)]` then the body.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RawCdr(pub Bytes);

/// The little-endian CDR header ROS 2 nodes write.
pub const CDR_LE_HEADER: [u8; 4] = [0x00, 0x01, 0x00, 0x00];

impl RawCdr {
    /// True when the sample is little-endian plain CDR (what DDS writers here send).
    pub fn is_le(bytes: &[u8]) -> bool {
        bytes.len() >= 4 && bytes[..2] == CDR_LE_HEADER[..2]
    }
}

#[derive(Debug, thiserror::Error)]
pub enum RawError {
    #[error("a CDR sample to write must start with the little-endian CDR header")]
    NotLittleEndian,
}

/// Reads and writes [`RawCdr`] samples (plain CDR, either byte order in, little out).
pub struct RawAdapter;

impl DeserializerAdapter<RawCdr> for RawAdapter {
    type Error = RawError;
    type Decoded = RawCdr;

    fn supported_encodings() -> &'static [RepresentationIdentifier] {
        &[
            RepresentationIdentifier::CDR_LE,
            RepresentationIdentifier::CDR_BE,
        ]
    }

    fn transform_decoded(decoded: RawCdr) -> RawCdr {
        decoded
    }
}

impl DefaultDecoder<RawCdr> for RawAdapter {
    type Decoder = RawDecoder;
    const DECODER: RawDecoder = RawDecoder;
}

/// Puts the encapsulation header back in front of a received body.
#[derive(Debug, Clone, Copy)]
pub struct RawDecoder;

impl<'de> Decode<'de, RawCdr> for RawDecoder {
    type Error = RawError;

    fn decode_bytes(
        self,
        input: &'de [u8],
        encoding: RepresentationIdentifier,
    ) -> Result<RawCdr, RawError> {
        let mut v = Vec::with_capacity(4 + input.len());
        v.extend_from_slice(&encoding.to_bytes());
        v.extend_from_slice(&[0, 0]);
        v.extend_from_slice(input);
        Ok(RawCdr(Bytes::from(v)))
    }
}

impl SerializerAdapter<RawCdr> for RawAdapter {
    type Error = RawError;

    fn output_encoding() -> RepresentationIdentifier {
        RepresentationIdentifier::CDR_LE
    }

    fn to_bytes(value: &RawCdr) -> Result<Bytes, RawError> {
        if !RawCdr::is_le(&value.0) {
            return Err(RawError::NotLittleEndian);
        }
        Ok(value.0.slice(4..))
    }
}

/// The 16-byte request header rmw_cyclonedds puts before a request's or reply's fields:
/// the client's id and the request's sequence number, both little-endian here.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct RequestHeader {
    pub client: u64,
    pub seq: i64,
}

impl RequestHeader {
    pub const LEN: usize = 16;

    /// Reads the header of a sample (after its encapsulation); `None` when too short or
    /// not little-endian... big-endian headers are read too.
    pub fn read(sample: &[u8]) -> Option<RequestHeader> {
        let h = sample.get(4..4 + Self::LEN)?;
        let (a, b): ([u8; 8], [u8; 8]) = (h[..8].try_into().ok()?, h[8..].try_into().ok()?);
        Some(if RawCdr::is_le(sample) {
            RequestHeader {
                client: u64::from_le_bytes(a),
                seq: i64::from_le_bytes(b),
            }
        } else {
            RequestHeader {
                client: u64::from_be_bytes(a),
                seq: i64::from_be_bytes(b),
            }
        })
    }

    /// A sample of this header followed by `body` (a little-endian CDR message with its
    /// header; the 16 bytes keep the body's 8-byte alignment).
    pub fn prepend(&self, body: &[u8]) -> Bytes {
        let mut v = Vec::with_capacity(body.len() + Self::LEN);
        v.extend_from_slice(&CDR_LE_HEADER);
        v.extend_from_slice(&self.client.to_le_bytes());
        v.extend_from_slice(&self.seq.to_le_bytes());
        v.extend_from_slice(body.get(4..).unwrap_or_default());
        Bytes::from(v)
    }

    /// The message after the header, as a CDR sample of its own (same byte order).
    pub fn strip(sample: &Bytes) -> Option<Bytes> {
        if sample.len() < 4 + Self::LEN {
            return None;
        }
        let mut v = Vec::with_capacity(sample.len() - Self::LEN);
        v.extend_from_slice(&sample[..4]);
        v.extend_from_slice(&sample[4 + Self::LEN..]);
        Some(Bytes::from(v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decoding_restores_the_header_and_encoding_slices_it_off() {
        let body = [1u8, 0, 0, 0, 7, 0, 0, 0];
        let raw = RawDecoder
            .decode_bytes(&body, RepresentationIdentifier::CDR_LE)
            .unwrap();
        assert_eq!(&raw.0[..4], &CDR_LE_HEADER);
        assert_eq!(&raw.0[4..], &body);
        assert_eq!(&RawAdapter::to_bytes(&raw).unwrap()[..], &body);
        let be = RawDecoder
            .decode_bytes(&body, RepresentationIdentifier::CDR_BE)
            .unwrap();
        assert_eq!(&be.0[..2], &[0, 0]);
        assert!(RawAdapter::to_bytes(&be).is_err());
    }

    #[test]
    fn request_headers_wrap_and_unwrap_a_message() {
        let msg = Bytes::from_static(&[0, 1, 0, 0, 5, 0, 0, 0, 0, 0, 0, 0]);
        let h = RequestHeader {
            client: 0x1122_3344_5566_7788,
            seq: 42,
        };
        let sample = h.prepend(&msg);
        assert_eq!(sample.len(), msg.len() + 16);
        assert_eq!(RequestHeader::read(&sample), Some(h));
        assert_eq!(RequestHeader::strip(&sample).unwrap(), msg);
        assert_eq!(RequestHeader::read(&sample[..10]), None);
    }
}
