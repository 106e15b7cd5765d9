//! The server side of a WebSocket connection, as two halves that share nothing: a
//! [`Reader`] (a `Stream` of client messages) and a [`Writer`] (a `Sink` of server
//! messages), used by rosbridge sessions.
//!
//! Why not tokio-tungstenite's `WebSocketStream` here: the hub's rosbridge traffic is
//! mostly small messages, and there the stream's shape costs more than the messages.
//! Split for a reader and a writer task, every frame in and out takes the split's lock
//! and re-registers the task's waker, and each frame is read by its own poll of the
//! socket layer. A bare relay of 64-byte rosbridge publishes measured 0.32–0.38 µs of
//! CPU per delivery on tokio-tungstenite, 0.30 on fastwebsockets, and 0.16 with frames
//! taken straight out of the read buffer as below (docs/benchmarks/log.md, "The hub's
//! own WebSocket layer, envelope shapes"). tungstenite still does the handshake (the hub
//! through hyper, the agent's listener with `accept_async`) and gives the message, close
//! and error types.
//!
//! - The reader reads up to [`READ_CHUNK`] bytes per system call and returns every whole
//!   message already in its buffer without touching the socket; payloads are slices of
//!   that buffer, unmasked in place ([`frames::Decoder`]). Its reads grow from
//!   [`FIRST_READ`] while they fill the room given and shrink back while they come small,
//!   so a busy connection reads in large chunks and an idle one (a robot's heartbeats)
//!   holds a kilobyte or two instead of 64 kB.
//! - The writer gathers frames in one buffer and writes them with one (vectored) call per
//!   flush. Payloads over [`COPY_UP_TO`] bytes are not copied but queued as they are.
//! - Control frames are not answered here: a `Ping` comes out of the reader for the
//!   session to answer, and so does a `Close`. After a `Close` or an error the reader
//!   ends; after sending a `Close` the writer refuses further messages.
//! - The writer counts the bytes the socket took ([`Writer::written`]): progress of a
//!   client's connection where the kernel's own count cannot be read ([`liveness`]).
//! - permessage-deflate, when the handshake agreed it ([`deflate`]): the reader inflates
//!   compressed client messages ([`Reader::inflating`]); the writer marks the messages it
//!   is given compressed ([`PartsSink::start_send_deflated`]) and never compresses on its
//!   own, as the bytes are made once per message for every subscriber.
//! - Text comes out unchecked ([`ClientMessage::Text`]): its reader checks the UTF-8, most
//!   often while reading the text anyway, instead of in a pass of its own.

pub mod deflate;
pub mod frames;
pub mod liveness;
pub mod replies;
pub mod tcp_progress;
pub mod timer;

use std::collections::VecDeque;
use std::io::IoSlice;
use std::pin::Pin;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::task::{Context, Poll, ready};

use bytes::{Buf, BufMut, Bytes, BytesMut};
use futures_util::{Sink, Stream};
use tokio::io::{AsyncRead, AsyncWrite};
use tokio_tungstenite::tungstenite::error::ProtocolError;
use tokio_tungstenite::tungstenite::protocol::CloseFrame;
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};

use frames::Decoder;

/// Bytes the reader asks the socket for at most per read, and the writer's fill level at
/// which it writes before taking more.
pub const READ_CHUNK: usize = 64 << 10;
/// Room a new reader's first read is given, and the least it comes down to.
pub const FIRST_READ: usize = 1 << 10;
/// Payloads up to this size are copied into the writer's buffer; larger ones are queued
/// as they are and written from where they lie.
pub const COPY_UP_TO: usize = 16 << 10;
/// Write-buffer capacity a writer keeps once everything is written; a larger one (left
/// by a burst) is let go, so an idle connection holds little.
const KEEP_CAPACITY: usize = 64 << 10;
/// Slices handed to one vectored write.
const MAX_SLICES: usize = 64;

/// A message from the client as the [`Reader`] gives it.
#[derive(Debug, Clone, PartialEq)]
pub enum ClientMessage {
    /// A text message's bytes, not yet checked as UTF-8. Its reader must check them and
    /// close the connection with 1007 (RFC 6455, 8.1) when they are not; a rosbridge
    /// session does it while reading a publish (its envelope's shape, its message's
    /// check against the type) and in one pass for anything else.
    Text(Bytes),
    Binary(Bytes),
    Ping(Bytes),
    Pong(Bytes),
    Close(Option<CloseFrame>),
}

/// tungstenite's messages, for sessions run over other streams (tests, benches).
impl From<WsMessage> for ClientMessage {
    fn from(m: WsMessage) -> ClientMessage {
        match m {
            WsMessage::Text(t) => ClientMessage::Text(t.into()),
            WsMessage::Binary(b) => ClientMessage::Binary(b),
            WsMessage::Ping(b) => ClientMessage::Ping(b),
            WsMessage::Pong(b) => ClientMessage::Pong(b),
            WsMessage::Close(c) => ClientMessage::Close(c),
            WsMessage::Frame(f) => ClientMessage::Binary(f.into_payload()),
        }
    }
}

/// The two halves of an accepted (handshake done) server connection over `io`.
pub fn server<S>(
    io: S,
    max_message: usize,
) -> (
    Writer<tokio::io::WriteHalf<S>>,
    Reader<tokio::io::ReadHalf<S>>,
)
where
    S: AsyncRead + AsyncWrite,
{
    // tokio's split takes a lock per read or write call, not per frame: one per socket
    // read of many messages, one per flush.
    let (r, w) = tokio::io::split(io);
    (Writer::new(w), Reader::new(r, max_message))
}

/// The two halves of an accepted server connection whose socket was split already;
/// `read` are bytes read from it past the handshake, the start of the client's frames.
pub fn server_halves<R, W>(r: R, w: W, read: Bytes, max_message: usize) -> (Writer<W>, Reader<R>)
where
    R: AsyncRead,
    W: AsyncWrite,
{
    let mut reader = Reader::new(r, max_message);
    reader.buf.extend_from_slice(&read);
    (Writer::new(w), reader)
}

/// Client messages read from `R`.
pub struct Reader<R> {
    io: R,
    buf: BytesMut,
    /// Room given to the next read: doubled (up to [`READ_CHUNK`]) when a read filled it,
    /// halved (down to [`FIRST_READ`]) when one used under an eighth of it.
    chunk: usize,
    decoder: Decoder,
    /// A `Close`, an error or the end of the stream was returned: nothing more comes.
    done: bool,
}

impl<R> Reader<R> {
    /// A reader of client frames from `io`, refusing messages over `max_message` bytes.
    pub fn new(io: R, max_message: usize) -> Reader<R> {
        Reader {
            io,
            buf: BytesMut::new(),
            chunk: FIRST_READ,
            decoder: Decoder::new(max_message),
            done: false,
        }
    }

    /// The same reader on a connection that negotiated permessage-deflate.
    pub fn inflating(mut self) -> Reader<R> {
        self.decoder = self.decoder.inflating();
        self
    }
}

impl<R: AsyncRead + Unpin> Stream for Reader<R> {
    type Item = Result<ClientMessage, WsError>;

    fn poll_next(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<Option<Self::Item>> {
        let this = self.get_mut();
        loop {
            if this.done {
                return Poll::Ready(None);
            }
            match this.decoder.decode(&mut this.buf) {
                Ok(Some(m)) => {
                    this.done = matches!(m, ClientMessage::Close(_));
                    return Poll::Ready(Some(Ok(m)));
                }
                Ok(None) => {}
                Err(e) => {
                    this.done = true;
                    return Poll::Ready(Some(Err(e)));
                }
            }
            // Room for the rest of the next frame, and for a good read. A large buffer
            // left by a burst is let go once everything in it was taken.
            if this.buf.is_empty() && this.buf.capacity() > 2 * this.chunk {
                this.buf = BytesMut::new();
            }
            let rest = this
                .decoder
                .wanted(&this.buf)
                .map_or(0, |w| w.saturating_sub(this.buf.len()));
            if this.buf.capacity() - this.buf.len() < rest.max(this.chunk / 4) {
                this.buf.reserve(rest.max(this.chunk));
            }
            let room = this.buf.capacity() - this.buf.len();
            let read = ready!(tokio_util::io::poll_read_buf(
                Pin::new(&mut this.io),
                cx,
                &mut this.buf
            ));
            if let Ok(n) = read {
                if n >= room {
                    this.chunk = (this.chunk * 2).min(READ_CHUNK);
                } else if n < this.chunk / 8 {
                    this.chunk = (this.chunk / 2).max(FIRST_READ);
                }
            }
            match read {
                Ok(0) => {
                    this.done = true;
                    if this.buf.is_empty() && !this.decoder.in_message() {
                        return Poll::Ready(None);
                    }
                    let cut = ProtocolError::ResetWithoutClosingHandshake;
                    return Poll::Ready(Some(Err(WsError::Protocol(cut))));
                }
                Ok(_) => {}
                Err(e) => {
                    this.done = true;
                    return Poll::Ready(Some(Err(WsError::Io(e))));
                }
            }
        }
    }
}

/// Server messages written to `W`.
pub struct Writer<W> {
    io: W,
    /// Frames waiting to be written, in order, before those in `tail`.
    queue: VecDeque<Bytes>,
    /// The newest frames, gathered.
    tail: BytesMut,
    /// Bytes in `queue` and `tail`.
    pending: usize,
    close_sent: bool,
    /// Bytes the socket took so far, shared with whoever watches the connection's
    /// progress.
    written: Arc<AtomicU64>,
    /// permessage-deflate was negotiated: what the writer's users compress.
    deflate: Option<deflate::DeflateConfig>,
}

impl<W> Writer<W> {
    pub fn new(io: W) -> Writer<W> {
        Writer {
            io,
            queue: VecDeque::new(),
            tail: BytesMut::new(),
            pending: 0,
            close_sent: false,
            written: Arc::default(),
            deflate: None,
        }
    }

    /// The same writer on a connection that negotiated permessage-deflate: its users may
    /// send messages compressed as `cfg` says.
    pub fn deflating(mut self, cfg: deflate::DeflateConfig) -> Writer<W> {
        self.deflate = Some(cfg);
        self
    }

    /// The count of bytes the socket took, as the writer keeps it.
    pub fn written(&self) -> Arc<AtomicU64> {
        self.written.clone()
    }

    /// Queues one frame. The payload is copied behind the frames before it, unless it is
    /// large: then it is queued as it is (no reference to it is taken otherwise, as a
    /// new reference to bytes made in one piece costs an allocation).
    fn push(&mut self, opcode: u8, payload: Bytes) {
        let before = self.tail.len();
        frames::encode_header(&mut self.tail, opcode, payload.len());
        self.pending += self.tail.len() - before + payload.len();
        if payload.len() > COPY_UP_TO {
            self.queue.push_back(self.tail.split().freeze());
            self.queue.push_back(payload);
        } else {
            self.tail.extend_from_slice(&payload);
        }
    }
}

impl<W: AsyncWrite + Unpin> Writer<W> {
    /// Writes until nothing is pending.
    fn poll_write_out(&mut self, cx: &mut Context<'_>) -> Poll<Result<(), WsError>> {
        while self.pending > 0 {
            let n = if self.queue.is_empty() {
                ready!(Pin::new(&mut self.io).poll_write(cx, &self.tail))?
            } else {
                let mut slices = [IoSlice::new(&[]); MAX_SLICES];
                let mut k = 0;
                for (slot, seg) in slices.iter_mut().zip(&self.queue) {
                    *slot = IoSlice::new(seg);
                    k += 1;
                }
                if k < MAX_SLICES && !self.tail.is_empty() {
                    slices[k] = IoSlice::new(&self.tail);
                    k += 1;
                }
                ready!(Pin::new(&mut self.io).poll_write_vectored(cx, &slices[..k]))?
            };
            if n == 0 {
                return Poll::Ready(Err(WsError::Io(std::io::ErrorKind::WriteZero.into())));
            }
            self.pending -= n;
            self.written.fetch_add(n as u64, Ordering::Relaxed);
            let mut left = n;
            while left > 0 {
                match self.queue.front_mut() {
                    Some(seg) if seg.len() <= left => {
                        left -= seg.len();
                        self.queue.pop_front();
                    }
                    Some(seg) => {
                        seg.advance(left);
                        left = 0;
                    }
                    None => {
                        self.tail.advance(left);
                        left = 0;
                    }
                }
            }
        }
        if self.tail.capacity() > KEEP_CAPACITY {
            self.tail = BytesMut::new();
        }
        Poll::Ready(Ok(()))
    }
}

impl<W: AsyncWrite + Unpin> Sink<WsMessage> for Writer<W> {
    type Error = WsError;

    fn poll_ready(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<Result<(), WsError>> {
        let this = self.get_mut();
        if this.pending >= READ_CHUNK {
            ready!(this.poll_write_out(cx))?;
        }
        Poll::Ready(Ok(()))
    }

    fn start_send(self: Pin<&mut Self>, m: WsMessage) -> Result<(), WsError> {
        let this = self.get_mut();
        if this.close_sent {
            return Err(WsError::Protocol(ProtocolError::SendAfterClosing));
        }
        match m {
            WsMessage::Text(t) => this.push(0x1, Bytes::from(t)),
            WsMessage::Binary(b) => this.push(0x2, b),
            WsMessage::Ping(b) => this.push(0x9, b),
            WsMessage::Pong(b) => this.push(0xA, b),
            WsMessage::Close(c) => {
                let mut body = BytesMut::new();
                if let Some(c) = c {
                    body.put_u16(c.code.into());
                    // A control frame carries at most 125 bytes: the reason is cut at a
                    // character boundary to fit.
                    let mut end = c.reason.len().min(123);
                    while !c.reason.is_char_boundary(end) {
                        end -= 1;
                    }
                    body.put_slice(&c.reason.as_bytes()[..end]);
                }
                this.close_sent = true;
                this.push(0x8, body.freeze());
            }
            WsMessage::Frame(_) => {
                return Err(WsError::Io(std::io::Error::new(
                    std::io::ErrorKind::Unsupported,
                    "a server session does not write raw frames",
                )));
            }
        }
        Ok(())
    }

    fn poll_flush(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<Result<(), WsError>> {
        let this = self.get_mut();
        ready!(this.poll_write_out(cx))?;
        Pin::new(&mut this.io).poll_flush(cx).map_err(WsError::Io)
    }

    fn poll_close(mut self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<Result<(), WsError>> {
        if !self.close_sent {
            self.as_mut().start_send(WsMessage::Close(None))?;
        }
        ready!(self.as_mut().poll_flush(cx))?;
        Pin::new(&mut self.get_mut().io)
            .poll_shutdown(cx)
            .map_err(WsError::Io)
    }
}

/// A sink of server messages that also takes a text message in pieces, for a writer to
/// put straight into its buffer: a rosbridge `publish` is the topic's head, the message
/// as its publisher sent it, and a brace ([`crate::Message::json_parts`]).
pub trait PartsSink: Sink<WsMessage, Error = WsError> + Unpin {
    /// Queues one text message made of `parts`, which together must be UTF-8; like
    /// `start_send`, only after `poll_ready` said so. This default puts the pieces
    /// together and sends them as one message.
    fn start_send_parts(&mut self, parts: &[&[u8]]) -> Result<(), WsError> {
        let text = String::from_utf8(parts.concat())
            .map_err(|e| WsError::Utf8(format!("a text message is not UTF-8: {e}")))?;
        Pin::new(self).start_send(WsMessage::text(text))
    }

    /// Queues one binary message: `head` (a few bytes made for this receiver) followed by
    /// `body` (bytes shared by many receivers); like `start_send`, only after
    /// `poll_ready` said so. A Foxglove `MessageData` is a per-subscription header in
    /// front of a payload every subscriber shares. This default puts the two together.
    fn start_send_binary_parts(&mut self, head: &[u8], body: &Bytes) -> Result<(), WsError> {
        let mut whole = BytesMut::with_capacity(head.len() + body.len());
        whole.extend_from_slice(head);
        whole.extend_from_slice(body);
        Pin::new(self).start_send(WsMessage::Binary(whole.freeze()))
    }

    /// The compression the client negotiated (permessage-deflate), if any. Sinks that
    /// cannot send compressed messages say `None`.
    fn deflate(&self) -> Option<deflate::DeflateConfig> {
        None
    }

    /// Queues one compressed message (RSV1 set): `text` or binary, its payload `head`
    /// followed by `body`, both compressed bytes ([`deflate::compress`],
    /// [`deflate::stored_block`]); only when [`PartsSink::deflate`] says so and after
    /// `poll_ready`.
    fn start_send_deflated(
        &mut self,
        text: bool,
        head: &[u8],
        body: &Bytes,
    ) -> Result<(), WsError> {
        let _ = (text, head, body);
        Err(WsError::Io(std::io::Error::new(
            std::io::ErrorKind::Unsupported,
            "this sink did not negotiate permessage-deflate",
        )))
    }
}

impl<W: AsyncWrite + Unpin> PartsSink for Writer<W> {
    fn start_send_parts(&mut self, parts: &[&[u8]]) -> Result<(), WsError> {
        if self.close_sent {
            return Err(WsError::Protocol(ProtocolError::SendAfterClosing));
        }
        let len = parts.iter().map(|p| p.len()).sum();
        let before = self.tail.len();
        frames::encode_header(&mut self.tail, 0x1, len);
        self.tail.reserve(len);
        for p in parts {
            self.tail.extend_from_slice(p);
        }
        self.pending += self.tail.len() - before;
        Ok(())
    }

    fn start_send_binary_parts(&mut self, head: &[u8], body: &Bytes) -> Result<(), WsError> {
        if self.close_sent {
            return Err(WsError::Protocol(ProtocolError::SendAfterClosing));
        }
        let before = self.tail.len();
        frames::encode_header(&mut self.tail, 0x2, head.len() + body.len());
        self.tail.extend_from_slice(head);
        self.pending += self.tail.len() - before + body.len();
        // As `push`: a large body is written from where it lies, not copied.
        if body.len() > COPY_UP_TO {
            self.queue.push_back(self.tail.split().freeze());
            self.queue.push_back(body.clone());
        } else {
            self.tail.extend_from_slice(body);
        }
        Ok(())
    }

    fn deflate(&self) -> Option<deflate::DeflateConfig> {
        self.deflate
    }

    fn start_send_deflated(
        &mut self,
        text: bool,
        head: &[u8],
        body: &Bytes,
    ) -> Result<(), WsError> {
        if self.close_sent {
            return Err(WsError::Protocol(ProtocolError::SendAfterClosing));
        }
        let before = self.tail.len();
        let opcode = if text { 0x1 } else { 0x2 };
        frames::encode_compressed_header(&mut self.tail, opcode, head.len() + body.len());
        self.tail.extend_from_slice(head);
        self.pending += self.tail.len() - before + body.len();
        // As `push`: a large body, shared by every subscriber, is written from where it
        // lies.
        if body.len() > COPY_UP_TO {
            self.queue.push_back(self.tail.split().freeze());
            self.queue.push_back(body.clone());
        } else {
            self.tail.extend_from_slice(body);
        }
        Ok(())
    }
}

/// Sinks over channels and tungstenite (tests, benches) take the pieces put together.
impl<S> PartsSink for futures_util::stream::SplitSink<S, WsMessage> where
    S: Sink<WsMessage, Error = WsError>
{
}

/// Waits until `sink` takes a message, then queues the text made of `parts` (see
/// [`PartsSink::start_send_parts`]).
pub async fn feed_parts<K: PartsSink>(sink: &mut K, parts: &[&[u8]]) -> Result<(), WsError> {
    std::future::poll_fn(|cx| Pin::new(&mut *sink).poll_ready(cx)).await?;
    sink.start_send_parts(parts)
}

/// Waits until `sink` takes a message, then queues the compressed message `head` + `body`
/// (see [`PartsSink::start_send_deflated`]).
pub async fn feed_deflated<K: PartsSink>(
    sink: &mut K,
    text: bool,
    head: &[u8],
    body: &Bytes,
) -> Result<(), WsError> {
    std::future::poll_fn(|cx| Pin::new(&mut *sink).poll_ready(cx)).await?;
    sink.start_send_deflated(text, head, body)
}

/// Waits until `sink` takes a message, then queues the binary message `head` + `body`
/// (see [`PartsSink::start_send_binary_parts`]).
pub async fn feed_binary_parts<K: PartsSink>(
    sink: &mut K,
    head: &[u8],
    body: &Bytes,
) -> Result<(), WsError> {
    std::future::poll_fn(|cx| Pin::new(&mut *sink).poll_ready(cx)).await?;
    sink.start_send_binary_parts(head, body)
}

#[cfg(test)]
mod deflate_tests;
#[cfg(test)]
mod tests;
