//! What the fleet's catalog tells the topic loop, waiting to be read: the latest state of
//! each liveliness token and the definitions asked of other hubs ([`Inbox`]), and the
//! tokens of hubs not admitted yet ([`Parked`]).
//!
//! Design choice: both are plain data behind the loop, with no Zenoh in them, so their
//! bounds are tested without a session.

use std::collections::HashMap;
use std::sync::Mutex;

use fleetlink_proto::Schema;
use fleetlink_relay::TopicName;
use tokio::sync::Notify;

use crate::keys::Offer;

/// Tokens kept of all the hubs not admitted yet (their links' certificates not seen yet):
/// a hub joining offers its whole catalog at once, and is admitted as soon as a link of
/// its own shows a certificate; beyond this many, what they offer is not kept.
const PARKED_TOKENS: usize = 100_000;
/// Hubs not admitted yet whose tokens are kept at once. Only hubs joining right now, or
/// reached only through another hub, wait here; the tokens of a hub past this many are
/// not kept.
const PARKED_HUBS: usize = 1024;

/// What the catalog's tokens and the definitions asked of other hubs tell the topic loop.
pub(super) enum News {
    Token {
        hub: String,
        offer: Offer,
        put: bool,
    },
    Schema {
        name: TopicName,
        schema: Schema,
    },
}

/// The topic loop's news, coalesced. Zenoh hands the catalog's tokens to a callback on its
/// own threads, which must not wait; rather than queueing every change there, a token's
/// latest state replaces the one not read yet (a hub offering and withdrawing a topic a
/// thousand times leaves one entry). So what waits is at most one entry per token that
/// changed since the loop last read, and one per definition asked for. They are read in
/// the order each was first heard; one token's state never depends on another's, so the
/// end state is the one a queue gives.
#[derive(Default)]
pub(super) struct Inbox {
    pending: Mutex<Pending>,
    pub(super) ready: Notify,
}

#[derive(Default)]
struct Pending {
    order: Vec<NewsKey>,
    latest: HashMap<NewsKey, News>,
}

/// What a piece of news replaces: a token by its key expression, a definition by topic.
#[derive(Clone, PartialEq, Eq, Hash)]
pub(super) enum NewsKey {
    Token(String),
    Schema(TopicName),
}

impl Inbox {
    pub(super) fn post(&self, key: NewsKey, news: News) {
        let mut p = self.pending.lock().unwrap_or_else(|p| p.into_inner());
        if p.latest.insert(key.clone(), news).is_none() {
            p.order.push(key);
        }
        drop(p);
        self.ready.notify_one();
    }

    /// Everything posted since the last call, oldest first.
    pub(super) fn take(&self) -> Vec<News> {
        let Pending { order, mut latest } =
            std::mem::take(&mut *self.pending.lock().unwrap_or_else(|p| p.into_inner()));
        order.iter().filter_map(|k| latest.remove(k)).collect()
    }
}

/// The live tokens of hubs not admitted (yet), by hub, taken when the hub is admitted.
/// Bounded: at most [`PARKED_HUBS`] hubs and [`PARKED_TOKENS`] tokens in all, further
/// tokens not kept; a hub whose tokens are all withdrawn (it left) is let go, and so is a
/// hub refused. A token is found by hashing, so withdrawing one costs the same however
/// many are parked.
#[derive(Default)]
pub(super) struct Parked {
    /// Each hub's tokens, with the order they came in.
    by_hub: HashMap<String, HashMap<Offer, u64>>,
    next: u64,
    total: usize,
}

impl Parked {
    /// Hub `hub`, not admitted, offered (`put`) or withdrew `offer`.
    pub(super) fn note(&mut self, hub: &str, offer: &Offer, put: bool) {
        if put {
            if self.total >= PARKED_TOKENS
                || (!self.by_hub.contains_key(hub) && self.by_hub.len() >= PARKED_HUBS)
            {
                return;
            }
            let tokens = self.by_hub.entry(hub.to_owned()).or_default();
            if !tokens.contains_key(offer) {
                tokens.insert(offer.clone(), self.next);
                self.next += 1;
                self.total += 1;
            }
        } else if let Some(tokens) = self.by_hub.get_mut(hub) {
            if tokens.remove(offer).is_some() {
                self.total -= 1;
            }
            if tokens.is_empty() {
                self.by_hub.remove(hub);
            }
        }
    }

    /// Takes the tokens of the hubs `admitted` says are admitted now, each hub's in the
    /// order they came, and lets go of those of the hubs `refused` says were refused.
    pub(super) fn take(
        &mut self,
        admitted: impl Fn(&str) -> bool,
        refused: impl Fn(&str) -> bool,
    ) -> Vec<(String, Vec<Offer>)> {
        let now: Vec<String> = self
            .by_hub
            .keys()
            .filter(|h| admitted(h))
            .cloned()
            .collect();
        let mut taken = Vec::with_capacity(now.len());
        for hub in now {
            let tokens = self.by_hub.remove(&hub).unwrap_or_default();
            self.total -= tokens.len();
            let mut tokens: Vec<(Offer, u64)> = tokens.into_iter().collect();
            tokens.sort_unstable_by_key(|(_, n)| *n);
            taken.push((hub, tokens.into_iter().map(|(o, _)| o).collect()));
        }
        let total = &mut self.total;
        self.by_hub.retain(|hub, tokens| {
            let keep = !refused(hub);
            if !keep {
                *total -= tokens.len();
            }
            keep
        });
        taken
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn token(inbox: &Inbox, key: &str, name: &str, put: bool) {
        let offer = Offer::Want { name: name.into() };
        let news = News::Token {
            hub: "h1".into(),
            offer,
            put,
        };
        inbox.post(NewsKey::Token(key.into()), news);
    }

    /// (name, put) of each token read.
    fn read(inbox: &Inbox) -> Vec<(String, bool)> {
        inbox
            .take()
            .into_iter()
            .map(|n| match n {
                News::Token {
                    offer: Offer::Want { name },
                    put,
                    ..
                } => (name, put),
                _ => panic!("only wants were posted"),
            })
            .collect()
    }

    #[test]
    fn news_of_one_token_coalesce_to_its_latest_state_in_first_heard_order() {
        let inbox = Inbox::default();
        for i in 0..1000 {
            token(&inbox, "k/a", "/a", i % 2 == 0);
        }
        token(&inbox, "k/b", "/b", true);
        token(&inbox, "k/a", "/a", true);
        token(&inbox, "k/b", "/b", false);
        assert_eq!(
            read(&inbox),
            [("/a".to_owned(), true), ("/b".to_owned(), false)]
        );
        assert!(read(&inbox).is_empty(), "what was read is gone");
        token(&inbox, "k/a", "/a", false);
        assert_eq!(read(&inbox), [("/a".to_owned(), false)]);
    }

    fn want(name: &str) -> Offer {
        Offer::Want { name: name.into() }
    }

    #[test]
    fn tokens_of_hubs_not_admitted_are_bounded_by_hub_and_in_all() {
        let mut parked = Parked::default();
        // Hubs that are not (yet) admitted, each under a name of its own choosing.
        for h in 0..PARKED_HUBS + 500 {
            parked.note(&format!("hub{h}"), &want("/a"), true);
        }
        assert_eq!(
            parked.by_hub.len(),
            PARKED_HUBS,
            "no more hubs than the bound"
        );
        for i in 0..PARKED_TOKENS + 10 {
            parked.note("hub0", &want(&format!("/t{i}")), true);
        }
        assert_eq!(parked.total, PARKED_TOKENS, "no more tokens than the bound");
        assert_eq!(
            parked.by_hub.values().map(HashMap::len).sum::<usize>(),
            PARKED_TOKENS
        );

        // A hub that withdraws all it offered (it left) is let go, making room.
        parked.note("hub1", &want("/a"), false);
        assert!(!parked.by_hub.contains_key("hub1"));
        assert_eq!(parked.total, PARKED_TOKENS - 1);
        parked.note("late", &want("/a"), true);
        assert!(parked.by_hub.contains_key("late"));
        assert_eq!(parked.total, PARKED_TOKENS);
        // A withdrawal from a hub with nothing parked keeps nothing.
        parked.note("unknown", &want("/a"), false);
        assert!(!parked.by_hub.contains_key("unknown"));
        assert_eq!(parked.by_hub.len(), PARKED_HUBS);
    }

    #[test]
    fn parked_tokens_go_to_the_loop_once_admitted_and_are_dropped_once_refused() {
        let mut parked = Parked::default();
        parked.note("good", &want("/a"), true);
        parked.note("good", &want("/b"), true);
        parked.note("good", &want("/a"), false);
        parked.note("bad", &want("/a"), true);
        parked.note("waiting", &want("/a"), true);
        parked.note("good", &want("/c"), true);
        parked.note("good", &want("/a"), true);
        let taken = parked.take(|h| h == "good", |h| h == "bad");
        assert_eq!(
            taken,
            [("good".to_owned(), vec![want("/b"), want("/c"), want("/a")])],
            "in the order they came"
        );
        let left: Vec<&String> = parked.by_hub.keys().collect();
        assert_eq!(left, ["waiting"]);
        assert_eq!(parked.total, 1, "only the waiting hub's token is counted");
    }
}
