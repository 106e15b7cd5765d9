//! Time and size bounds on one HTTP connection that hyper does not enforce itself: an
//! exchange that stops moving ([`IdleIo`]) and request bodies that are too large or never
//! finish arriving ([`GuardedBody`]).
//!
//! Design choice: both are thin wrappers around what hyper already reads — the socket and
//! the request body — so no handler has to remember a limit. A body that breaks a bound
//! fails with an error the handler sees as a broken body, and records a [`BodyVerdict`]
//! the connection layer turns into the answer the client gets (413 or 408, then close),
//! whatever the handler made of the error.

use std::io;
use std::pin::Pin;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU8, Ordering};
use std::task::{Context, Poll};
use std::time::Duration;

use bytes::Bytes;
use http_body::{Body, Frame, SizeHint};
use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};
use tokio::time::{Instant, Sleep};

/// A socket that fails with `TimedOut` when neither a read nor a write makes progress
/// for `idle`, while `http_phase` is set. The upgrade to WebSocket clears the flag: a
/// quiet WebSocket is normal, and agents and sessions watch their own liveness.
pub struct IdleIo<I> {
    inner: I,
    idle: Duration,
    timer: Pin<Box<Sleep>>,
    http_phase: Arc<AtomicBool>,
}

impl<I> IdleIo<I> {
    pub fn new(inner: I, idle: Duration, http_phase: Arc<AtomicBool>) -> IdleIo<I> {
        IdleIo {
            inner,
            idle,
            timer: Box::pin(tokio::time::sleep(idle)),
            http_phase,
        }
    }

    /// The socket itself, once nothing is to be guarded any more (after an upgrade).
    pub fn into_inner(self) -> I {
        self.inner
    }

    fn armed(&self) -> bool {
        self.http_phase.load(Ordering::Relaxed)
    }

    fn progressed(&mut self) {
        if self.armed() {
            let at = Instant::now() + self.idle;
            self.timer.as_mut().reset(at);
        }
    }

    /// On a pending read or write: whether the connection has been still too long.
    fn expired(&mut self, cx: &mut Context<'_>) -> bool {
        self.armed() && self.timer.as_mut().poll(cx).is_ready()
    }

    fn timed_out(&self) -> io::Error {
        io::Error::new(
            io::ErrorKind::TimedOut,
            format!(
                "nothing read or written for {:?} (--idle-timeout-secs)",
                self.idle
            ),
        )
    }
}

impl<I: AsyncRead + Unpin> AsyncRead for IdleIo<I> {
    fn poll_read(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &mut ReadBuf<'_>,
    ) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        match Pin::new(&mut this.inner).poll_read(cx, buf) {
            Poll::Ready(r) => {
                this.progressed();
                Poll::Ready(r)
            }
            Poll::Pending if this.expired(cx) => Poll::Ready(Err(this.timed_out())),
            Poll::Pending => Poll::Pending,
        }
    }
}

impl<I: AsyncWrite + Unpin> AsyncWrite for IdleIo<I> {
    fn poll_write(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &[u8],
    ) -> Poll<io::Result<usize>> {
        let this = self.get_mut();
        match Pin::new(&mut this.inner).poll_write(cx, buf) {
            Poll::Ready(r) => {
                this.progressed();
                Poll::Ready(r)
            }
            Poll::Pending if this.expired(cx) => Poll::Ready(Err(this.timed_out())),
            Poll::Pending => Poll::Pending,
        }
    }

    fn poll_flush(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        match Pin::new(&mut this.inner).poll_flush(cx) {
            Poll::Pending if this.expired(cx) => Poll::Ready(Err(this.timed_out())),
            other => other,
        }
    }

    fn poll_shutdown(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.get_mut().inner).poll_shutdown(cx)
    }
}

/// Why a request body was cut off.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum BodyError {
    #[error("request body over the {max}-byte limit (--max-body-bytes)")]
    TooLarge { max: u64 },
    #[error("request body not complete within {after:?} (--body-timeout-secs)")]
    TimedOut { after: Duration },
    /// The connection failed while the body was arriving.
    #[error("request body broken off: {cause}")]
    Broken { cause: String },
}

/// What became of a request body, shared between [`GuardedBody`] and the connection
/// layer: 0 fine so far, then the [`BodyError`] that cut it.
#[derive(Default)]
pub struct BodyVerdict(AtomicU8);

impl BodyVerdict {
    fn set(&self, e: &BodyError) {
        let code = match e {
            BodyError::TooLarge { .. } => 1,
            BodyError::TimedOut { .. } => 2,
            BodyError::Broken { .. } => return,
        };
        self.0.store(code, Ordering::Relaxed);
    }

    /// `Some(true)` too large, `Some(false)` too slow, `None` not cut.
    pub fn too_large(&self) -> Option<bool> {
        match self.0.load(Ordering::Relaxed) {
            1 => Some(true),
            2 => Some(false),
            _ => None,
        }
    }
}

/// A request body bounded in size and in time (the clock starts with the request head).
pub struct GuardedBody<B> {
    inner: B,
    left: u64,
    max: u64,
    after: Duration,
    deadline: Pin<Box<Sleep>>,
    verdict: Arc<BodyVerdict>,
}

impl<B> GuardedBody<B> {
    pub fn new(inner: B, max: u64, after: Duration, verdict: Arc<BodyVerdict>) -> GuardedBody<B> {
        GuardedBody {
            inner,
            left: max,
            max,
            after,
            deadline: Box::pin(tokio::time::sleep(after)),
            verdict,
        }
    }

    fn cut(&self, e: BodyError) -> Poll<Option<Result<Frame<Bytes>, BodyError>>> {
        self.verdict.set(&e);
        Poll::Ready(Some(Err(e)))
    }
}

impl<B> Body for GuardedBody<B>
where
    B: Body<Data = Bytes> + Unpin,
    B::Error: Into<Box<dyn std::error::Error + Send + Sync>>,
{
    type Data = Bytes;
    type Error = BodyError;

    fn poll_frame(
        self: Pin<&mut Self>,
        cx: &mut Context<'_>,
    ) -> Poll<Option<Result<Frame<Bytes>, BodyError>>> {
        let this = self.get_mut();
        match Pin::new(&mut this.inner).poll_frame(cx) {
            Poll::Ready(Some(Ok(frame))) => {
                let len = frame.data_ref().map_or(0, |d| d.len() as u64);
                if len > this.left {
                    return this.cut(BodyError::TooLarge { max: this.max });
                }
                this.left -= len;
                Poll::Ready(Some(Ok(frame)))
            }
            Poll::Ready(Some(Err(e))) => this.cut(BodyError::Broken {
                cause: e.into().to_string(),
            }),
            Poll::Ready(None) => Poll::Ready(None),
            Poll::Pending if this.deadline.as_mut().poll(cx).is_ready() => {
                this.cut(BodyError::TimedOut { after: this.after })
            }
            Poll::Pending => Poll::Pending,
        }
    }

    fn is_end_stream(&self) -> bool {
        self.inner.is_end_stream()
    }

    fn size_hint(&self) -> SizeHint {
        self.inner.size_hint()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use http_body_util::BodyExt;

    fn guarded<B>(inner: B, max: u64) -> (GuardedBody<B>, Arc<BodyVerdict>) {
        let verdict = Arc::new(BodyVerdict::default());
        let after = Duration::from_secs(5);
        (
            GuardedBody::new(inner, max, after, verdict.clone()),
            verdict,
        )
    }

    #[tokio::test(start_paused = true)]
    async fn body_over_the_limit_is_cut_whatever_its_framing() {
        let (body, verdict) = guarded(http_body_util::Full::new(Bytes::from(vec![7; 2000])), 1000);
        let err = body.collect().await.expect_err("over the limit");
        assert_eq!(err, BodyError::TooLarge { max: 1000 });
        assert_eq!(verdict.too_large(), Some(true));

        let (body, verdict) = guarded(http_body_util::Full::new(Bytes::from(vec![7; 1000])), 1000);
        assert_eq!(
            body.collect().await.expect("at the limit").to_bytes().len(),
            1000
        );
        assert_eq!(verdict.too_large(), None);
    }

    #[tokio::test(start_paused = true)]
    async fn body_that_never_arrives_times_out() {
        let never = http_body_util::StreamBody::new(futures_util::stream::pending::<
            Result<Frame<Bytes>, std::convert::Infallible>,
        >());
        let (body, verdict) = guarded(never, 1000);
        let err = body.collect().await.expect_err("never completes");
        assert_eq!(
            err,
            BodyError::TimedOut {
                after: Duration::from_secs(5)
            }
        );
        assert_eq!(verdict.too_large(), Some(false));
    }
}
