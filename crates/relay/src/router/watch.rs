//! How participants hear of changes without polling: a publisher of the demand for its
//! topics ([`DemandWatch`]), a participant that mirrors the router elsewhere of every
//! topic that changes ([`TopicsWatch`]).

use super::*;

/// Where a publisher hears that the demand for its topics may have changed: the topics
/// whose subscribers changed since it last looked, coalesced (a set of ids, bounded by
/// the topics there are), and a wake-up. What the demand now is, it asks
/// [`Router::wanted`]; a burst of subscription churn costs it one look per topic.
#[derive(Default)]
pub struct DemandWatch {
    pub(super) changed: Mutex<HashSet<TopicId>>,
    /// Pull requests since the last look, coalesced per topic.
    pub(super) pulls: Mutex<HashSet<TopicId>>,
    pub(super) notify: tokio::sync::Notify,
}

impl DemandWatch {
    pub(super) fn mark(&self, topic: TopicId) {
        let fresh = self
            .changed
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .insert(topic);
        if fresh {
            self.notify.notify_one();
        }
    }

    pub(super) fn pull(&self, topic: TopicId) {
        self.pulls
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .insert(topic);
        self.notify.notify_one();
    }

    /// The topics someone asked to pull since the last call.
    pub fn take_pulls(&self) -> Vec<TopicId> {
        self.pulls
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .drain()
            .collect()
    }

    /// The topics whose subscribers changed since the last call.
    pub fn take(&self) -> Vec<TopicId> {
        self.changed
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .drain()
            .collect()
    }

    /// Resolves once something was marked since the last `take` (at once if something
    /// is waiting).
    pub async fn changed(&self) {
        self.notify.notified().await;
    }
}

/// Where a participant that mirrors the router hears which topics changed: their names
/// since it last looked, coalesced, and a wake-up ([`Router::watch_topics`]).
#[derive(Default)]
pub struct TopicsWatch {
    pub(super) changed: Mutex<HashSet<TopicName>>,
    pub(super) notify: tokio::sync::Notify,
}

impl TopicsWatch {
    pub(super) fn mark(&self, name: &TopicName) {
        let mut set = self.changed.lock().unwrap_or_else(|p| p.into_inner());
        if set.is_empty() {
            self.notify.notify_one();
        }
        set.insert(name.clone());
    }

    /// The topics that changed since the last call.
    pub fn take(&self) -> Vec<TopicName> {
        self.changed
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .drain()
            .collect()
    }

    /// Resolves once something was marked since the last `take` (at once if something
    /// is waiting).
    pub async fn changed(&self) {
        self.notify.notified().await;
    }
}

#[cfg(test)]
mod watch_tests {
    use super::*;

    #[test]
    fn a_topics_watch_nobody_holds_is_let_go() {
        // Viewers that come and go (each Foxglove session holds one watch) leave nothing
        // behind in the router.
        let router = Router::default();
        for _ in 0..10 {
            drop(router.watch_topics());
        }
        let kept = router.watch_topics();
        assert_eq!(router.lock().watchers.len(), 1);
        let (c, _) = router.connect(ClientKind::Foxglove, None);
        let name = TopicName::parse("/a").unwrap();
        router
            .advertise(c, &name, Schema::named("std_msgs/msg/Empty"), false)
            .unwrap();
        assert_eq!(kept.take(), vec![name]);
    }
}
