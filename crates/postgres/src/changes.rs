//! Change notifications between hubs: `NOTIFY fleetlink_changes, '<what>'` in the
//! transaction that changes something, `LISTEN fleetlink_changes` on one dedicated
//! connection per process.
//!
//! Design choice: a notification only says *what kind* of state changed (rules, tokens,
//! users, parameters), never the change itself; the receiver reloads that kind from the
//! tables. So a lost or repeated notification costs a reload, never a wrong state, and
//! after the listening connection was lost (notifications sent meanwhile are gone) the
//! listener reports [`Change::Everything`]. PostgreSQL sends a notification only when its
//! transaction commits, so a receiver never reloads before the change is visible.
//!
//! The listener is a task on the database's own runtime. It reconnects with exponential
//! backoff (0.1 s doubling to 5 s) whenever its connection ends, and logs the loss once
//! and the recovery once.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use futures_util::StreamExt;
use tokio_postgres::AsyncMessage;

use crate::{Database, DbError, Transaction};

/// The channel every fleetlink process notifies and listens on.
pub const CHANNEL: &str = "fleetlink_changes";

const RETRY_MIN: Duration = Duration::from_millis(100);
const RETRY_MAX: Duration = Duration::from_secs(5);

/// What kind of shared state changed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Change {
    /// Access rules (the rule revision moved).
    Rules,
    /// A token was revoked.
    Tokens,
    /// A user was added, removed, or given a new password.
    Users,
    /// A parameter was set or deleted.
    Params,
    /// Anything may have changed: the listener (re)started and may have missed
    /// notifications.
    Everything,
}

impl Change {
    pub fn as_str(self) -> &'static str {
        match self {
            Change::Rules => "rules",
            Change::Tokens => "tokens",
            Change::Users => "users",
            Change::Params => "params",
            Change::Everything => "everything",
        }
    }

    pub fn parse(s: &str) -> Option<Change> {
        [
            Change::Rules,
            Change::Tokens,
            Change::Users,
            Change::Params,
            Change::Everything,
        ]
        .into_iter()
        .find(|c| c.as_str() == s)
    }
}

type Callback = Arc<dyn Fn(Change) -> bool + Send + Sync>;

/// Who wants to hear about changes, and whether the listener runs.
#[derive(Default)]
pub(crate) struct Subscribers {
    // std Mutex: pushed to when a store starts, copied out per notification; never held
    // while a callback runs.
    list: Mutex<Vec<Callback>>,
    listening: AtomicBool,
}

impl Subscribers {
    fn deliver(&self, change: Change) {
        let list = self.list.lock().unwrap_or_else(|p| p.into_inner()).clone();
        let gone: Vec<Callback> = list.into_iter().filter(|f| !f(change)).collect();
        if !gone.is_empty() {
            self.list
                .lock()
                .unwrap_or_else(|p| p.into_inner())
                .retain(|f| !gone.iter().any(|g| Arc::ptr_eq(f, g)));
        }
    }
}

/// Sends `change` to every listening process when `tx` commits.
pub async fn notify(tx: &Transaction<'_>, change: Change) -> Result<(), DbError> {
    let st = tx.prepare_cached("SELECT pg_notify($1, $2)").await?;
    tx.query(&st, &[&CHANNEL, &change.as_str()]).await?;
    Ok(())
}

impl Database {
    /// Calls `f` for every change notified by any process on this database (this one
    /// included), and with [`Change::Everything`] each time listening (re)starts. The
    /// first call starts the listener.
    ///
    /// `f` runs on the database's runtime thread: it must return at once, handing any
    /// work (which may use the database) to a thread of its own. Returning `false`
    /// unsubscribes it.
    pub fn on_change(&self, f: impl Fn(Change) -> bool + Send + Sync + 'static) {
        let subs = &self.inner.changes;
        subs.list
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .push(Arc::new(f));
        if !subs.listening.swap(true, Ordering::AcqRel) {
            self.inner.handle.spawn(listen(
                self.inner.config.clone(),
                subs.clone(),
                self.inner.shown.clone(),
            ));
        }
    }
}

/// Keeps one connection listening on [`CHANNEL`], for as long as the database lives.
async fn listen(config: tokio_postgres::Config, subs: Arc<Subscribers>, shown: String) {
    let mut backoff = RETRY_MIN;
    let mut lost = false;
    loop {
        match config.connect(tokio_postgres::NoTls).await {
            Ok((client, mut conn)) => {
                let s = subs.clone();
                // The connection must be polled for the LISTEN to complete and for
                // notifications to arrive; this task does both until it ends.
                let mut driver = tokio::spawn(async move {
                    let mut messages = futures_util::stream::poll_fn(|cx| conn.poll_message(cx));
                    while let Some(m) = messages.next().await {
                        match m {
                            Ok(AsyncMessage::Notification(n)) => match Change::parse(n.payload()) {
                                Some(c) => s.deliver(c),
                                None => tracing::debug!("unknown change {:?}", n.payload()),
                            },
                            Ok(_) => {}
                            Err(e) => return e.to_string(),
                        }
                    }
                    "the server closed the connection".to_owned()
                });
                match client.batch_execute(&format!("LISTEN {CHANNEL}")).await {
                    Ok(()) => {
                        if std::mem::take(&mut lost) {
                            tracing::info!(
                                "listening for changes at {shown} again; reloading shared state"
                            );
                        }
                        backoff = RETRY_MIN;
                        subs.deliver(Change::Everything);
                        let why = (&mut driver).await.unwrap_or_else(|e| e.to_string());
                        tracing::warn!(
                            "stopped listening for changes at {shown}: {why}; reconnecting"
                        );
                        lost = true;
                    }
                    Err(e) => {
                        driver.abort();
                        if !std::mem::replace(&mut lost, true) {
                            tracing::warn!("cannot listen for changes at {shown}: {e}; retrying");
                        }
                    }
                }
            }
            Err(e) => {
                if !std::mem::replace(&mut lost, true) {
                    tracing::warn!(
                        "cannot connect to {shown} to listen for changes: {e}; retrying"
                    );
                }
            }
        }
        tokio::time::sleep(backoff).await;
        backoff = (backoff * 2).min(RETRY_MAX);
    }
}
