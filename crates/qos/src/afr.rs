//! AFR buffering (Wang et al., "AFR: An Efficient Buffering Algorithm for Cloud Robotic
//! Systems", IROS 2022, Algorithm 1): a bounded queue that, while the link is down, keeps
//! evenly spaced messages instead of only the newest or oldest ones.
//!
//! The algorithm keeps three numbers: the dropping rate `r` (accept one message in `r`),
//! the message counter `c` (messages seen since the last accepted one) and the dropping
//! position `p`. On each arriving message: if `r > 1` and the queue is at most R = 2/3
//! full, `r` is halved (and `c` reduced by the new `r` if it reached it); then `c` is
//! incremented and the message is discarded unless `c` reached `r`. An accepted message
//! that meets a full queue first evicts the message at position `p` and moves `p` one
//! step on; when `p` runs past the end, every other message has gone, so `r` doubles and
//! `p` restarts at the head. Sending a message from the head moves `p` back by one.
//!
//! Design choice: evicting "the message at position `p`" from a plain ring buffer costs
//! O(L) moves. Here the queue is two rings — `thinned` holds positions `0..p` (already
//! thinned in this pass), `rest` holds positions `p..` — so position `p` is always
//! `rest.front()` and every step is O(1): one pop, one move, or an O(1) swap when a pass
//! ends. Items are moved, never cloned; the rings grow as messages wait and let a large
//! buffer go once drained (as [`crate::TopicQueue`] does).

use std::collections::VecDeque;

use crate::ring::release_if_drained;

/// What happened to a message offered to [`Afr::push`].
#[derive(Debug, PartialEq, Eq)]
pub enum AfrPush<T> {
    /// Queued, nothing dropped.
    Queued,
    /// The offered message itself was discarded by the rate `r` (returned unchanged).
    Decimated(T),
    /// The offered message was queued and this older message was evicted from position `p`.
    Evicted(T),
}

/// AFR queue of capacity L.
#[derive(Debug, Clone)]
pub struct Afr<T> {
    thinned: VecDeque<T>,
    rest: VecDeque<T>,
    capacity: usize,
    rate: u64,
    counter: u64,
}

impl<T> Afr<T> {
    /// An empty queue holding at most `capacity` (>= 1) messages.
    pub fn new(capacity: usize) -> Self {
        let capacity = capacity.max(1);
        Afr {
            thinned: VecDeque::new(),
            rest: VecDeque::new(),
            capacity,
            rate: 1,
            counter: 0,
        }
    }

    pub fn len(&self) -> usize {
        self.thinned.len() + self.rest.len()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// Current dropping rate r (1 = accept every message).
    pub fn rate(&self) -> u64 {
        self.rate
    }

    /// Current dropping position p.
    pub fn position(&self) -> usize {
        self.thinned.len()
    }

    /// Current message counter c.
    pub fn counter(&self) -> u64 {
        self.counter
    }

    pub fn push(&mut self, item: T) -> AfrPush<T> {
        let size = self.len();
        // Occupancy at or below R = 2/3: the link keeps up again, accept twice as many.
        if self.rate > 1 && size * 3 <= self.capacity * 2 {
            self.rate /= 2;
            if self.counter >= self.rate {
                self.counter -= self.rate;
            }
        }
        self.counter += 1;
        if self.counter < self.rate {
            return AfrPush::Decimated(item);
        }
        self.counter = 0;
        let evicted = if size >= self.capacity {
            // `rest` is never empty here: positions p..L exist while p < L.
            let evicted = self.rest.pop_front();
            if self.thinned.len() + 1 >= self.capacity {
                // The pass is over: every other message is gone; start again at the head
                // with half the rate. (`rest` is empty, so the swap moves all to `rest`.)
                std::mem::swap(&mut self.thinned, &mut self.rest);
                self.rate = self.rate.saturating_mul(2);
            } else if let Some(next) = self.rest.pop_front() {
                self.thinned.push_back(next);
            }
            evicted
        } else {
            None
        };
        self.rest.push_back(item);
        match evicted {
            Some(old) => AfrPush::Evicted(old),
            None => AfrPush::Queued,
        }
    }

    /// Takes the head (oldest) message; moves `p` back by one as the queue shifts.
    pub fn pop(&mut self) -> Option<T> {
        let item = self.thinned.pop_front().or_else(|| self.rest.pop_front());
        release_if_drained(&mut self.thinned);
        release_if_drained(&mut self.rest);
        item
    }

    /// Room held for items now (both rings), not the bound.
    pub fn reserved(&self) -> usize {
        self.thinned.capacity() + self.rest.capacity()
    }

    /// Queued messages, head first.
    pub fn iter(&self) -> impl Iterator<Item = &T> {
        self.thinned.iter().chain(self.rest.iter())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn contents(afr: &Afr<u32>) -> Vec<u32> {
        afr.iter().copied().collect()
    }

    /// The worked example of the paper's Figure 4 (L = 8, messages numbered from 1, the
    /// link down throughout): the first 8 fill the queue; messages 9..16 each evict the
    /// message at p = 0, 1, …, 7, which leaves every second message; then r = 2, so only
    /// even-numbered messages are accepted, and the thinning pass repeats over 18..32.
    #[test]
    fn afr_matches_the_hand_worked_figure_4_trace() {
        let mut afr = Afr::new(8);
        let mut log = Vec::new();
        for m in 1..=32u32 {
            let out = afr.push(m);
            log.push((m, out, contents(&afr), afr.rate(), afr.position()));
        }
        let at = |m: u32| &log[m as usize - 1];
        assert_eq!(at(8).2, vec![1, 2, 3, 4, 5, 6, 7, 8]);
        assert_eq!(at(9).1, AfrPush::Evicted(1));
        assert_eq!(at(9).2, vec![2, 3, 4, 5, 6, 7, 8, 9]);
        assert_eq!(at(10).1, AfrPush::Evicted(3));
        assert_eq!(at(10).2, vec![2, 4, 5, 6, 7, 8, 9, 10]);
        assert_eq!(at(12).2, vec![2, 4, 6, 8, 9, 10, 11, 12]);
        assert_eq!(
            (at(15).2.clone(), at(15).4),
            (vec![2, 4, 6, 8, 10, 12, 14, 15], 7)
        );
        // Message 16 evicts 15 at p = 7, the pass ends: r doubles, p returns to 0.
        assert_eq!(at(16).1, AfrPush::Evicted(15));
        assert_eq!(
            (at(16).2.clone(), at(16).3, at(16).4),
            (vec![2, 4, 6, 8, 10, 12, 14, 16], 2, 0)
        );
        // r = 2: odd messages are decimated, even ones thin the queue again from p = 0.
        assert_eq!(at(17).1, AfrPush::Decimated(17));
        assert_eq!(at(18).1, AfrPush::Evicted(2));
        assert_eq!(at(18).2, vec![4, 6, 8, 10, 12, 14, 16, 18]);
        assert_eq!(at(20).2, vec![4, 8, 10, 12, 14, 16, 18, 20]);
        assert_eq!(
            (at(32).2.clone(), at(32).3),
            (vec![4, 8, 12, 16, 20, 24, 28, 32], 4)
        );
    }

    #[test]
    fn draining_below_two_thirds_halves_the_rate() {
        let mut afr = Afr::new(6);
        for m in 1..=12u32 {
            afr.push(m);
        }
        assert_eq!(afr.rate(), 2);
        assert_eq!(contents(&afr), vec![2, 4, 6, 8, 10, 12]);
        // Send three: 3 left <= 2/3 * 6, so the next arrival lowers r back to 1 first.
        for _ in 0..3 {
            afr.pop();
        }
        assert_eq!(afr.push(13), AfrPush::Queued);
        assert_eq!(afr.rate(), 1);
        assert_eq!(afr.push(14), AfrPush::Queued);
        assert_eq!(contents(&afr), vec![8, 10, 12, 13, 14]);
    }

    #[test]
    fn popping_moves_the_drop_position_back() {
        let mut afr = Afr::new(4);
        for m in 1..=6u32 {
            afr.push(m);
        }
        // 5 evicted 1 (p: 0 -> 1), 6 evicted 3 (p: 1 -> 2).
        assert_eq!((contents(&afr), afr.position()), (vec![2, 4, 5, 6], 2));
        assert_eq!(afr.pop(), Some(2));
        assert_eq!(afr.position(), 1);
        afr.push(7);
        // Queue 3/4 full > 2/3: r stays 1, 7 enters without eviction.
        assert_eq!(contents(&afr), vec![4, 5, 6, 7]);
        assert_eq!(afr.push(8), AfrPush::Evicted(5));
    }
}
