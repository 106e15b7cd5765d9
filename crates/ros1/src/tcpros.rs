//! TCPROS framing: connection headers and length-prefixed messages.
//!
//! ```text
//! header:   u32 LE total | { u32 LE len | "key=value" }*
//! message:  u32 LE len | len bytes of ROS 1 serialization
//! service response: u8 ok | u32 LE len | body (the response, or an error text if ok = 0)
//! ```
//!
//! Messages are read into one buffer each and handed on as [`Bytes`] without a copy; the
//! payload is never decoded here.

use bytes::{Bytes, BytesMut};
use tokio::io::{AsyncRead, AsyncReadExt, AsyncWrite, AsyncWriteExt};

/// Largest connection header accepted (a full definition of a big type is ~20 KB).
pub const MAX_HEADER: usize = 1024 * 1024;
/// Largest message accepted (a 4K depth image is ~32 MB).
pub const MAX_MESSAGE: usize = 256 * 1024 * 1024;

/// A connection header's fields, in the order they came.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Header(pub Vec<(String, String)>);

impl Header {
    pub fn new() -> Header {
        Header(Vec::new())
    }

    pub fn with(mut self, key: &str, value: impl Into<String>) -> Header {
        self.0.push((key.to_owned(), value.into()));
        self
    }

    pub fn get(&self, key: &str) -> Option<&str> {
        self.0
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }

    /// The field's value or an empty string.
    pub fn text(&self, key: &str) -> &str {
        self.get(key).unwrap_or("")
    }

    /// `key=1`.
    pub fn flag(&self, key: &str) -> bool {
        self.get(key) == Some("1")
    }

    pub fn encode(&self) -> Vec<u8> {
        let body: usize = self.0.iter().map(|(k, v)| 4 + k.len() + 1 + v.len()).sum();
        let mut out = Vec::with_capacity(4 + body);
        out.extend_from_slice(&(body as u32).to_le_bytes());
        for (k, v) in &self.0 {
            out.extend_from_slice(&((k.len() + 1 + v.len()) as u32).to_le_bytes());
            out.extend_from_slice(k.as_bytes());
            out.push(b'=');
            out.extend_from_slice(v.as_bytes());
        }
        out
    }

    /// Decodes a header body (without its leading total length).
    pub fn decode(body: &[u8]) -> Result<Header, FrameError> {
        let mut fields = Vec::new();
        let mut rest = body;
        while !rest.is_empty() {
            let Some((len, after)) = rest.split_first_chunk::<4>() else {
                return Err(FrameError::Invalid("header field length cut short".into()));
            };
            let len = u32::from_le_bytes(*len) as usize;
            if len > after.len() {
                return Err(FrameError::Invalid(format!(
                    "header field of {len} bytes with {} left",
                    after.len()
                )));
            }
            let field = &after[..len];
            let Some(eq) = field.iter().position(|b| *b == b'=') else {
                return Err(FrameError::Invalid("header field without '='".into()));
            };
            let text = |b: &[u8]| {
                String::from_utf8(b.to_vec())
                    .map_err(|_| FrameError::Invalid("header field is not UTF-8".into()))
            };
            fields.push((text(&field[..eq])?, text(&field[eq + 1..])?));
            rest = &after[len..];
        }
        Ok(Header(fields))
    }
}

#[derive(Debug, thiserror::Error)]
pub enum FrameError {
    #[error("connection closed")]
    Closed,
    #[error("invalid TCPROS data: {0}")]
    Invalid(String),
    #[error("{what} of {len} bytes is over the limit of {limit}")]
    TooLarge {
        what: &'static str,
        len: usize,
        limit: usize,
    },
    #[error("TCPROS I/O: {0}")]
    Io(#[from] std::io::Error),
}

async fn read_len<R: AsyncRead + Unpin>(r: &mut R) -> Result<usize, FrameError> {
    let mut len = [0u8; 4];
    match r.read_exact(&mut len).await {
        Ok(_) => Ok(u32::from_le_bytes(len) as usize),
        Err(e) if e.kind() == std::io::ErrorKind::UnexpectedEof => Err(FrameError::Closed),
        Err(e) => Err(e.into()),
    }
}

async fn read_body<R: AsyncRead + Unpin>(
    r: &mut R,
    len: usize,
    what: &'static str,
    limit: usize,
) -> Result<Bytes, FrameError> {
    if len > limit {
        return Err(FrameError::TooLarge { what, len, limit });
    }
    // Read into spare capacity: zero-filling a megabyte point cloud's buffer first would
    // cost as much as the copy out of the socket.
    let mut buf = BytesMut::with_capacity(len);
    while buf.len() < len {
        let want = (len - buf.len()) as u64;
        if (&mut *r).take(want).read_buf(&mut buf).await? == 0 {
            return Err(FrameError::Invalid(format!(
                "connection closed inside a {what}"
            )));
        }
    }
    Ok(buf.freeze())
}

pub async fn read_header<R: AsyncRead + Unpin>(r: &mut R) -> Result<Header, FrameError> {
    let len = read_len(r).await?;
    let body = read_body(r, len, "connection header", MAX_HEADER).await?;
    Header::decode(&body)
}

pub async fn write_header<W: AsyncWrite + Unpin>(w: &mut W, h: &Header) -> Result<(), FrameError> {
    w.write_all(&h.encode()).await?;
    w.flush().await?;
    Ok(())
}

/// One message's body.
pub async fn read_message<R: AsyncRead + Unpin>(r: &mut R) -> Result<Bytes, FrameError> {
    let len = read_len(r).await?;
    read_body(r, len, "message", MAX_MESSAGE).await
}

/// A message with its length prefix, ready to write to any number of connections.
pub fn frame(body: &[u8]) -> Bytes {
    let mut out = BytesMut::with_capacity(4 + body.len());
    out.extend_from_slice(&(body.len() as u32).to_le_bytes());
    out.extend_from_slice(body);
    out.freeze()
}

/// A service response: the ok byte, then the body (or the error text).
pub async fn read_service_response<R: AsyncRead + Unpin>(
    r: &mut R,
) -> Result<Result<Bytes, String>, FrameError> {
    let mut ok = [0u8; 1];
    match r.read_exact(&mut ok).await {
        Ok(_) => {}
        Err(e) if e.kind() == std::io::ErrorKind::UnexpectedEof => return Err(FrameError::Closed),
        Err(e) => return Err(e.into()),
    }
    let body = read_message(r).await?;
    Ok(if ok[0] == 1 {
        Ok(body)
    } else {
        Err(String::from_utf8_lossy(&body).into_owned())
    })
}

pub async fn write_service_response<W: AsyncWrite + Unpin>(
    w: &mut W,
    answer: Result<&[u8], &str>,
) -> Result<(), FrameError> {
    let (ok, body) = match answer {
        Ok(b) => (1u8, b),
        Err(text) => (0u8, text.as_bytes()),
    };
    let mut out = Vec::with_capacity(5 + body.len());
    out.push(ok);
    out.extend_from_slice(&(body.len() as u32).to_le_bytes());
    out.extend_from_slice(body);
    w.write_all(&out).await?;
    w.flush().await?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_round_trips() {
        let h = Header::new()
            .with("callerid", "/talker")
            .with("message_definition", "string data\n# a=b\n")
            .with("latching", "1");
        let bytes = h.encode();
        assert_eq!(
            u32::from_le_bytes(bytes[..4].try_into().unwrap()) as usize,
            bytes.len() - 4
        );
        let back = Header::decode(&bytes[4..]).unwrap();
        assert_eq!(back, h);
        assert_eq!(back.text("message_definition"), "string data\n# a=b\n");
        assert!(back.flag("latching"));
        assert_eq!(back.get("nothing"), None);
    }

    /// The header rospy's talker sends for std_msgs/String (fields as on the wire).
    #[test]
    fn decodes_a_rospy_header() {
        let mut body = Vec::new();
        for f in [
            "md5sum=992ce8a1687cec8c8bd883ec73ca41d1",
            "type=std_msgs/String",
        ] {
            body.extend_from_slice(&(f.len() as u32).to_le_bytes());
            body.extend_from_slice(f.as_bytes());
        }
        let h = Header::decode(&body).unwrap();
        assert_eq!(h.text("type"), "std_msgs/String");
    }

    #[test]
    fn malformed_headers_are_invalid() {
        for bad in [
            &[5u8, 0, 0][..],
            &[10, 0, 0, 0, b'a', b'=', b'b'][..],
            &[3, 0, 0, 0, b'a', b'b', b'c'][..],
            &[2, 0, 0, 0, b'=', 0xff][..],
        ] {
            assert!(
                matches!(Header::decode(bad), Err(FrameError::Invalid(_))),
                "{bad:?}"
            );
        }
    }

    #[tokio::test]
    async fn messages_frame_and_read_back() {
        let (mut a, mut b) = tokio::io::duplex(1 << 16);
        a.write_all(&frame(b"hello")).await.unwrap();
        a.write_all(&frame(b"")).await.unwrap();
        write_service_response(&mut a, Err("no")).await.unwrap();
        drop(a);
        assert_eq!(&read_message(&mut b).await.unwrap()[..], b"hello");
        assert_eq!(read_message(&mut b).await.unwrap().len(), 0);
        assert_eq!(
            read_service_response(&mut b).await.unwrap(),
            Err("no".to_owned())
        );
        assert!(matches!(
            read_message(&mut b).await,
            Err(FrameError::Closed)
        ));
    }

    #[tokio::test]
    async fn oversized_and_cut_messages_are_refused() {
        let (mut a, mut b) = tokio::io::duplex(1 << 16);
        a.write_all(&u32::MAX.to_le_bytes()).await.unwrap();
        assert!(matches!(
            read_message(&mut b).await,
            Err(FrameError::TooLarge { .. })
        ));
        let (mut a, mut b) = tokio::io::duplex(1 << 16);
        a.write_all(&[10, 0, 0, 0, 1, 2]).await.unwrap();
        drop(a);
        assert!(matches!(
            read_message(&mut b).await,
            Err(FrameError::Invalid(_))
        ));
    }
}
