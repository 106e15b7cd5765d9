//! A deadline a loop waits on many times without making a timer entry each time.

use std::time::{Duration, Instant};

/// A deadline for a loop that waits many times: one timer entry for the session's life,
/// moved only when the deadline does (the heartbeat's, most of the time), instead of a
/// new one for every message read.
pub struct Timer {
    sleep: std::pin::Pin<Box<tokio::time::Sleep>>,
    at: Option<Instant>,
}

impl Default for Timer {
    fn default() -> Timer {
        Timer {
            sleep: Box::pin(tokio::time::sleep(Duration::from_secs(3600))),
            at: None,
        }
    }
}

impl Timer {
    /// Sleeps until `at` (forever for `None`).
    pub async fn wait(&mut self, at: Option<Instant>) {
        let Some(at) = at else {
            return std::future::pending().await;
        };
        if self.at != Some(at) {
            self.sleep.as_mut().reset(at.into());
            self.at = Some(at);
        }
        self.sleep.as_mut().await
    }
}
