//! Options that change while a part runs (a runtime configuration change, docs/
//! runtime-config.md): the part holds a `watch` receiver of its options, if it was given
//! one, and waits for the next change beside its other work.

use tokio::sync::watch;

/// The next value `changes` holds; never, if there is no source of changes or once it is
/// gone (so a `select!` branch on it simply never fires).
pub async fn next_change<T: Clone>(changes: &mut Option<watch::Receiver<T>>) -> T {
    if let Some(rx) = changes {
        if rx.changed().await.is_ok() {
            return rx.borrow_and_update().clone();
        }
        *changes = None;
    }
    std::future::pending().await
}

#[cfg(test)]
mod tests {
    use super::*;

    #[tokio::test]
    async fn a_change_is_seen_once_and_a_gone_source_never_fires() {
        let (tx, rx) = watch::channel(1);
        let mut changes = Some(rx);
        tx.send_replace(2);
        assert_eq!(next_change(&mut changes).await, 2);
        let again = tokio::time::timeout(
            std::time::Duration::from_millis(20),
            next_change(&mut changes),
        );
        assert!(again.await.is_err(), "the same value is not seen twice");
        drop(tx);
        let gone = tokio::time::timeout(
            std::time::Duration::from_millis(20),
            next_change(&mut changes),
        );
        assert!(gone.await.is_err());
        assert!(changes.is_none(), "a gone source is let go of");
        let mut none: Option<watch::Receiver<u8>> = None;
        let never =
            tokio::time::timeout(std::time::Duration::from_millis(20), next_change(&mut none));
        assert!(never.await.is_err());
    }
}
