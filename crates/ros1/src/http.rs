//! Just enough HTTP/1.1 to carry XML-RPC: `POST` one document, get one back.
//!
//! Design choice: the ROS master and nodes are Python `xmlrpc` peers that send a
//! `Content-Length` on every request and response and never use chunked encoding,
//! continuations or pipelining; a small reader/writer over a `TcpStream` covers them
//! with bounded sizes and timeouts, without an HTTP stack in the agent's dependencies.
//! The client opens one connection per call (`Connection: close`); calls are rare
//! (registration, discovery once a second), and a fresh connection is what makes a
//! restarted master visible at once.

use std::time::Duration;

use tokio::io::{AsyncRead, AsyncReadExt, AsyncWrite, AsyncWriteExt};
use tokio::net::TcpStream;

/// Largest header block accepted.
const MAX_HEAD: usize = 64 * 1024;
/// Largest XML-RPC body accepted (a getSystemState of a big graph is well under this).
const MAX_BODY: usize = 16 * 1024 * 1024;

#[derive(Debug, thiserror::Error)]
pub enum HttpError {
    #[error("{uri} is not an http://host:port URI")]
    BadUri { uri: String },
    #[error("cannot reach {uri}: {source}")]
    Connect { uri: String, source: std::io::Error },
    #[error("{uri} did not answer within {timeout:?}")]
    Timeout { uri: String, timeout: Duration },
    #[error("I/O with {uri}: {source}")]
    Io { uri: String, source: std::io::Error },
    #[error("bad HTTP from {uri}: {reason}")]
    Protocol { uri: String, reason: String },
}

/// `host:port` and path of an `http://` URI (ROS masters and node APIs).
pub fn split_uri(uri: &str) -> Option<(String, String)> {
    let rest = uri.strip_prefix("http://")?;
    let (authority, path) = match rest.find('/') {
        Some(i) => (&rest[..i], &rest[i..]),
        None => (rest, "/"),
    };
    if authority.is_empty() || !authority.contains(':') {
        return None;
    }
    Some((authority.to_owned(), path.to_owned()))
}

/// POSTs `body` to `uri` and returns the response body (any 2xx status).
pub async fn post(uri: &str, body: &str, timeout: Duration) -> Result<String, HttpError> {
    let (authority, path) = split_uri(uri).ok_or_else(|| HttpError::BadUri { uri: uri.into() })?;
    let work = async {
        let mut stream =
            TcpStream::connect(&authority)
                .await
                .map_err(|source| HttpError::Connect {
                    uri: uri.into(),
                    source,
                })?;
        let _ = stream.set_nodelay(true);
        let request = format!(
            "POST {path} HTTP/1.1\r\nHost: {authority}\r\nUser-Agent: fleetlink-ros1\r\n\
             Content-Type: text/xml\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{body}",
            body.len()
        );
        let io = |source| HttpError::Io {
            uri: uri.into(),
            source,
        };
        stream.write_all(request.as_bytes()).await.map_err(io)?;
        let mut reader = Reader::new(stream);
        let head = reader
            .head()
            .await
            .map_err(io)?
            .ok_or_else(|| HttpError::Protocol {
                uri: uri.into(),
                reason: "connection closed before a response".into(),
            })?;
        let status = head
            .first_line
            .split_whitespace()
            .nth(1)
            .and_then(|s| s.parse::<u16>().ok())
            .unwrap_or(0);
        if !(200..300).contains(&status) {
            return Err(HttpError::Protocol {
                uri: uri.into(),
                reason: format!("status line {:?}", head.first_line),
            });
        }
        let body = match head.content_length {
            Some(n) => reader.body(n).await.map_err(io)?,
            None => reader.rest().await.map_err(io)?,
        };
        String::from_utf8(body).map_err(|_| HttpError::Protocol {
            uri: uri.into(),
            reason: "body is not UTF-8".into(),
        })
    };
    tokio::time::timeout(timeout, work)
        .await
        .map_err(|_| HttpError::Timeout {
            uri: uri.into(),
            timeout,
        })?
}

/// A request or response head.
#[derive(Debug)]
pub struct Head {
    pub first_line: String,
    pub content_length: Option<usize>,
    pub close: bool,
}

/// Reads heads and bodies from one connection, keeping what was read past a head.
pub struct Reader<S> {
    stream: S,
    buf: Vec<u8>,
}

fn invalid(reason: String) -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::InvalidData, reason)
}

impl<S: AsyncRead + Unpin> Reader<S> {
    pub fn new(stream: S) -> Self {
        Reader {
            stream,
            buf: Vec::new(),
        }
    }

    pub fn get_mut(&mut self) -> &mut S {
        &mut self.stream
    }

    /// The next head; `None` if the peer closed the connection between messages.
    pub async fn head(&mut self) -> std::io::Result<Option<Head>> {
        let end = loop {
            if let Some(i) = self.buf.windows(4).position(|w| w == b"\r\n\r\n") {
                break i;
            }
            if self.buf.len() > MAX_HEAD {
                return Err(invalid(format!("head longer than {MAX_HEAD} bytes")));
            }
            let mut chunk = [0u8; 4096];
            let n = self.stream.read(&mut chunk).await?;
            if n == 0 {
                if self.buf.iter().all(|b| b.is_ascii_whitespace()) {
                    return Ok(None);
                }
                return Err(invalid("connection closed inside a head".into()));
            }
            self.buf.extend_from_slice(&chunk[..n]);
        };
        let text = String::from_utf8_lossy(&self.buf[..end]).into_owned();
        self.buf.drain(..end + 4);
        let mut lines = text.split("\r\n");
        let first_line = lines.next().unwrap_or("").trim().to_owned();
        let mut content_length = None;
        let mut close = first_line.ends_with("HTTP/1.0");
        for line in lines {
            let Some((k, v)) = line.split_once(':') else {
                continue;
            };
            let (k, v) = (k.trim().to_ascii_lowercase(), v.trim());
            match k.as_str() {
                "content-length" => {
                    let n: usize = v
                        .parse()
                        .map_err(|_| invalid(format!("Content-Length {v:?}")))?;
                    if n > MAX_BODY {
                        return Err(invalid(format!("body of {n} bytes is over {MAX_BODY}")));
                    }
                    content_length = Some(n);
                }
                "connection" => close = v.eq_ignore_ascii_case("close"),
                "transfer-encoding" if !v.eq_ignore_ascii_case("identity") => {
                    return Err(invalid(format!("transfer encoding {v:?} not supported")));
                }
                _ => {}
            }
        }
        Ok(Some(Head {
            first_line,
            content_length,
            close,
        }))
    }

    /// Exactly `n` body bytes.
    pub async fn body(&mut self, n: usize) -> std::io::Result<Vec<u8>> {
        while self.buf.len() < n {
            let mut chunk = vec![0u8; (n - self.buf.len()).min(64 * 1024)];
            let got = self.stream.read(&mut chunk).await?;
            if got == 0 {
                return Err(invalid("connection closed inside a body".into()));
            }
            self.buf.extend_from_slice(&chunk[..got]);
        }
        Ok(self.buf.drain(..n).collect())
    }

    /// Everything until the peer closes (a response without `Content-Length`).
    pub async fn rest(&mut self) -> std::io::Result<Vec<u8>> {
        let mut out = std::mem::take(&mut self.buf);
        (&mut self.stream)
            .take(MAX_BODY as u64)
            .read_to_end(&mut out)
            .await?;
        Ok(out)
    }
}

/// Writes a `200 OK` response with an XML body.
pub async fn write_response<W: AsyncWrite + Unpin>(
    w: &mut W,
    body: &str,
    close: bool,
) -> std::io::Result<()> {
    let head = format!(
        "HTTP/1.1 200 OK\r\nServer: fleetlink-ros1\r\nContent-Type: text/xml\r\n\
         Content-Length: {}\r\nConnection: {}\r\n\r\n",
        body.len(),
        if close { "close" } else { "keep-alive" }
    );
    w.write_all(head.as_bytes()).await?;
    w.write_all(body.as_bytes()).await?;
    w.flush().await
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uris_split_into_authority_and_path() {
        assert_eq!(
            split_uri("http://localhost:11311/"),
            Some(("localhost:11311".into(), "/".into()))
        );
        assert_eq!(
            split_uri("http://10.0.0.2:4000"),
            Some(("10.0.0.2:4000".into(), "/".into()))
        );
        assert_eq!(split_uri("rosrpc://h:1"), None);
        assert_eq!(split_uri("http://nohost/"), None);
    }

    #[tokio::test]
    async fn reads_keep_alive_requests_in_sequence() {
        let (mut a, b) = tokio::io::duplex(1024);
        a.write_all(
            b"POST / HTTP/1.1\r\nContent-Length: 3\r\n\r\nabcPOST / HTTP/1.1\r\ncontent-length: 2\r\nConnection: close\r\n\r\nxy",
        )
        .await
        .unwrap();
        drop(a);
        let mut r = Reader::new(b);
        let h = r.head().await.unwrap().unwrap();
        assert_eq!(h.content_length, Some(3));
        assert!(!h.close);
        assert_eq!(r.body(3).await.unwrap(), b"abc");
        let h = r.head().await.unwrap().unwrap();
        assert!(h.close);
        assert_eq!(r.body(2).await.unwrap(), b"xy");
        assert!(r.head().await.unwrap().is_none());
    }

    #[tokio::test]
    async fn oversized_and_truncated_input_is_refused() {
        let (mut a, b) = tokio::io::duplex(1024);
        a.write_all(b"POST / HTTP/1.1\r\nContent-Length: 999999999\r\n\r\n")
            .await
            .unwrap();
        assert!(Reader::new(b).head().await.is_err());
        let (mut a, b) = tokio::io::duplex(1024);
        a.write_all(b"POST / HTTP/1.1\r\nContent-Le").await.unwrap();
        drop(a);
        assert!(Reader::new(b).head().await.is_err());
    }
}
