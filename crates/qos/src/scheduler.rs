//! The uplink scheduler (Robofleet, Algorithms 1–2): decides which queued message goes on
//! the link next, and when sending must pause.
//!
//! Order of service: messages of `no_drop` topics wait in one FIFO shared by all of them,
//! always served first, in arrival order. Every other topic has its own bounded
//! [`TopicQueue`] (rate limit + drop policy); among topics with something queued, the one
//! with the largest `priority × (now − last time it got a message through)` goes next —
//! *descending*, as the paper intends (the published client sorts ascending and so serves
//! the least-waited topic first; `scheduler_serves_longest_weighted_wait_first` guards
//! against that). Sending pauses while `max_in_flight` frames (nT) are unacknowledged, and
//! while the byte budget (the robot's capacity share) is spent.
//!
//! Design choice: the weighted wait `p·(now − s)` of two topics can swap order as time
//! passes, so no single heap orders all topics. But topics of *equal* priority never swap:
//! the one that was served longest ago wins. Topics are therefore grouped by priority,
//! each group a min-heap on `s`; picking scans one head per group. The cost is
//! O(distinct priorities + log topics) per message, without allocation — a fleet uses a
//! handful of priority levels, however many topics it has.

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap, VecDeque};
use std::sync::Arc;

use crate::budget::DataBudget;
use crate::config::TopicQos;
use crate::error::QosError;
use crate::queue::{DropReason, Push, TopicQueue};
use crate::time::Nanos;
pub use crate::topic::TopicId;

/// Size of an item on the wire, in bytes, for the byte budget.
pub trait WireLen {
    fn wire_len(&self) -> usize;
}

impl WireLen for [u8] {
    fn wire_len(&self) -> usize {
        self.len()
    }
}

impl WireLen for Vec<u8> {
    fn wire_len(&self) -> usize {
        self.len()
    }
}

impl<T: WireLen + ?Sized> WireLen for Arc<T> {
    fn wire_len(&self) -> usize {
        (**self).wire_len()
    }
}

impl<T: WireLen + ?Sized> WireLen for Box<T> {
    fn wire_len(&self) -> usize {
        (**self).wire_len()
    }
}

impl<T: WireLen + ?Sized> WireLen for &T {
    fn wire_len(&self) -> usize {
        (**self).wire_len()
    }
}

/// Outcome of [`Scheduler::offer`]; the same cases as a queue push.
pub type Offer<T> = Push<T>;

#[derive(Debug, Clone)]
pub struct SchedulerConfig {
    /// nT: frames sent but not yet acknowledged at which sending pauses.
    pub max_in_flight: usize,
    /// Depth of the byte budget's bucket, as seconds of the budget rate: how much may
    /// leave back-to-back after an idle spell.
    pub budget_burst_secs: f64,
}

impl Default for SchedulerConfig {
    fn default() -> Self {
        SchedulerConfig {
            max_in_flight: 32,
            budget_burst_secs: 0.02,
        }
    }
}

#[derive(Debug)]
enum Lane<T> {
    /// Items live in the shared no-drop FIFO; this counts this topic's share of it.
    NoDrop {
        queued: usize,
        capacity: usize,
    },
    Queue(TopicQueue<T>),
}

#[derive(Debug)]
struct Topic<T> {
    id: TopicId,
    lane: Lane<T>,
    group: usize,
    last_sent: Option<Nanos>,
    /// In its group's heap (has something queued).
    ready: bool,
    /// Not eligible for now ([`Scheduler::set_held`]): its messages wait in its queue.
    held: bool,
    /// When it last had to wait because the data budget was closed.
    thinned_at: Option<Nanos>,
}

#[derive(Debug)]
struct Group {
    priority: f32,
    /// (last time served, topic index), earliest first.
    ready: BinaryHeap<Reverse<(Nanos, u32)>>,
}

/// Byte budget: a token bucket refilled at the capacity share.
#[derive(Debug, Clone)]
struct Budget {
    bytes_per_sec: f64,
    burst: f64,
    tokens: f64,
    at: Nanos,
}

impl Budget {
    fn refill(&mut self, now: Nanos) {
        let dt = now.saturating_sub(self.at).as_secs_f64();
        self.tokens = (self.tokens + dt * self.bytes_per_sec).min(self.burst);
        self.at = self.at.max(now);
    }
}

/// Robofleet-style scheduler over items of type `T` (see the module docs).
#[derive(Debug)]
pub struct Scheduler<T> {
    config: SchedulerConfig,
    topics: Vec<Topic<T>>,
    index: HashMap<TopicId, u32>,
    groups: Vec<Group>,
    /// Per group, parallel to `groups`: its priority and the wait start of its
    /// longest-waiting ready topic (`+inf` when none is ready). Picking the next topic
    /// scans these two flat arrays only, so the cost stays well under a microsecond with
    /// a thousand distinct priorities instead of chasing one heap per group.
    group_priority: Vec<f64>,
    group_head: Vec<f64>,
    no_drop: VecDeque<(u32, T)>,
    in_flight: usize,
    /// Sizes of the unacknowledged items, oldest first (acks arrive in send order), and
    /// their sum: the byte window keeps what sits in the link's queue short.
    in_flight_sizes: VecDeque<usize>,
    in_flight_bytes: usize,
    window_bytes: Option<usize>,
    budget: Option<Budget>,
    /// The robot's data budget, if its owner set one (see [`crate::budget`]).
    data_budget: Option<DataBudget>,
    /// The budget held the unprotected topics back at the last look: a message such a
    /// topic loses from its queue meanwhile is lost to the budget (the topic is thinned).
    budget_refused: bool,
}

impl<T: WireLen> Scheduler<T> {
    pub fn new(config: SchedulerConfig) -> Self {
        let in_flight_sizes = VecDeque::with_capacity(config.max_in_flight.min(1024));
        Scheduler {
            config,
            topics: Vec::new(),
            index: HashMap::new(),
            groups: Vec::new(),
            group_priority: Vec::new(),
            group_head: Vec::new(),
            no_drop: VecDeque::new(),
            in_flight: 0,
            in_flight_sizes,
            in_flight_bytes: 0,
            window_bytes: None,
            budget: None,
            data_budget: None,
            budget_refused: false,
        }
    }

    /// Registers a topic; `qos` is validated here.
    pub fn add_topic(&mut self, id: TopicId, qos: TopicQos) -> Result<(), QosError> {
        qos.validate()?;
        if self.index.contains_key(&id) {
            return Err(QosError::DuplicateTopic(id));
        }
        let group = self.group_for(qos.priority);
        let lane = if qos.no_drop {
            // A durable outbox sets a queue length that only its byte bound limits.
            self.no_drop.reserve(qos.queue.min(1024));
            Lane::NoDrop {
                queued: 0,
                capacity: qos.queue,
            }
        } else {
            self.groups[group].ready.reserve(1);
            Lane::Queue(TopicQueue::with_seed(&qos, u64::from(id.0)))
        };
        let index = self.topics.len() as u32;
        self.topics.push(Topic {
            id,
            lane,
            group,
            last_sent: None,
            ready: false,
            held: false,
            thinned_at: None,
        });
        self.index.insert(id, index);
        Ok(())
    }

    /// Gives registered `topic` a new `qos` (a configuration changed while it flows): its
    /// priority group, queue length, drop policy and rate limit. What it has queued stays
    /// queued, oldest first, as far as the new queue holds it (the rest counts as dropped
    /// by policy, returned). `no_drop` cannot change ([`QosError::NoDropChange`]).
    pub fn set_qos(
        &mut self,
        topic: TopicId,
        qos: TopicQos,
        now: Nanos,
    ) -> Result<Vec<T>, QosError> {
        qos.validate()?;
        let index = *self
            .index
            .get(&topic)
            .ok_or(QosError::UnknownTopic(topic))?;
        let was_no_drop = matches!(self.topics[index as usize].lane, Lane::NoDrop { .. });
        if was_no_drop != qos.no_drop {
            return Err(QosError::NoDropChange(topic));
        }
        // Out of its group's ready heap (it goes back below, into its new group's).
        let old_group = self.topics[index as usize].group;
        if self.topics[index as usize].ready {
            self.groups[old_group]
                .ready
                .retain(|Reverse((_, i))| *i != index);
            self.refresh_head(old_group);
            self.topics[index as usize].ready = false;
        }
        let group = self.group_for(qos.priority);
        let t = &mut self.topics[index as usize];
        t.group = group;
        let mut dropped = Vec::new();
        match &mut t.lane {
            Lane::NoDrop { capacity, .. } => *capacity = qos.queue,
            Lane::Queue(queue) => {
                let mut new = TopicQueue::with_seed(&qos, u64::from(topic.0));
                while let Some(item) = queue.pop(now) {
                    // Re-queued, not offered anew: the rate limit applies to arrivals.
                    match new.push_kept(item) {
                        Push::Dropped { item, .. } | Push::Backpressure(item) => dropped.push(item),
                        _ => {}
                    }
                }
                *queue = new;
            }
        }
        let t = &mut self.topics[index as usize];
        if let Lane::Queue(queue) = &t.lane
            && !t.held
            && !queue.is_empty()
        {
            t.ready = true;
            let since = t.last_sent.unwrap_or(now);
            self.groups[group].ready.push(Reverse((since, index)));
            self.refresh_head(group);
        }
        Ok(dropped)
    }

    /// The index of the group of `priority`, made if there is none yet (groups are kept
    /// in descending priority, so equal scores favour the higher).
    fn group_for(&mut self, priority: f32) -> usize {
        if let Some(g) = self.groups.iter().position(|g| g.priority == priority) {
            return g;
        }
        let at = self.groups.partition_point(|g| g.priority > priority);
        self.groups.insert(
            at,
            Group {
                priority,
                ready: BinaryHeap::new(),
            },
        );
        self.group_priority.insert(at, f64::from(priority));
        self.group_head.insert(at, f64::INFINITY);
        for t in &mut self.topics {
            if t.group >= at {
                t.group += 1;
            }
        }
        at
    }

    /// Offers a message of `topic` arriving at `now`. Drops (by rate limit or policy) and
    /// backpressure (`fifo` and no-drop topics whose queue is full) are reported, with the
    /// item, in the result.
    pub fn offer(&mut self, topic: TopicId, item: T, now: Nanos) -> Offer<T> {
        let Some(&index) = self.index.get(&topic) else {
            return Push::Dropped {
                item,
                reason: DropReason::UnknownTopic,
            };
        };
        let t = &mut self.topics[index as usize];
        match &mut t.lane {
            Lane::NoDrop { queued, capacity } => {
                if *queued >= *capacity {
                    return Push::Backpressure(item);
                }
                *queued += 1;
                self.no_drop.push_back((index, item));
                Push::Queued
            }
            Lane::Queue(queue) => {
                let outcome = queue.push(item, now);
                if self.budget_refused
                    && matches!(&outcome, Push::Dropped { reason, .. } if *reason != DropReason::RateLimit)
                {
                    t.thinned_at = Some(now);
                }
                if !t.ready && !t.held && !queue.is_empty() {
                    t.ready = true;
                    let since = t.last_sent.unwrap_or(now);
                    let g = t.group;
                    self.groups[g].ready.push(Reverse((since, index)));
                    self.refresh_head(g);
                }
                outcome
            }
        }
    }

    /// Whether `topic` is a no-drop topic (its messages go through the no-drop FIFO).
    pub fn is_no_drop(&self, topic: TopicId) -> bool {
        self.index
            .get(&topic)
            .is_some_and(|&i| matches!(self.topics[i as usize].lane, Lane::NoDrop { .. }))
    }

    /// Whether no-drop topic `topic` can take another message without backpressure
    /// (`true` for other topics and unknown ones).
    pub fn no_drop_room(&self, topic: TopicId) -> bool {
        match self
            .index
            .get(&topic)
            .map(|&i| &self.topics[i as usize].lane)
        {
            Some(Lane::NoDrop { queued, capacity }) => queued < capacity,
            _ => true,
        }
    }

    /// Puts a no-drop `item` back at the head of the no-drop FIFO: it was sent on a
    /// connection that died before the peer confirmed it. Call in reverse send order so
    /// the oldest goes first. Ignores the queue length (the item was admitted before).
    pub fn requeue_no_drop(&mut self, topic: TopicId, item: T) -> Result<(), T> {
        let Some(&index) = self.index.get(&topic) else {
            return Err(item);
        };
        match &mut self.topics[index as usize].lane {
            Lane::NoDrop { queued, .. } => {
                *queued += 1;
                self.no_drop.push_front((index, item));
                Ok(())
            }
            Lane::Queue(_) => Err(item),
        }
    }

    /// The next message to put on the link, if sending is allowed at `now`. The caller
    /// sends it as one frame and later reports its acknowledgement with [`Self::on_acked`].
    pub fn poll_next(&mut self, now: Nanos) -> Option<(TopicId, T)> {
        if self.in_flight >= self.config.max_in_flight {
            return None;
        }
        // The byte window: at least one item may always be in flight, so a window
        // smaller than a message cannot stall the link.
        if let Some(w) = self.window_bytes
            && self.in_flight > 0
            && self.in_flight_bytes >= w
        {
            return None;
        }
        if let Some(b) = &mut self.budget {
            b.refill(now);
            if b.tokens <= 0.0 {
                return None;
            }
        }
        let (index, item) = match self.no_drop.pop_front() {
            Some((index, item)) => {
                if let Lane::NoDrop { queued, .. } = &mut self.topics[index as usize].lane {
                    *queued -= 1;
                }
                (index, item)
            }
            None => {
                // A closed data budget leaves only the protected priorities eligible.
                let eligible = self.budget_eligible(now);
                // Under a data budget the highest priority goes first, so what the budget
                // leaves is taken from the lowest priorities up.
                let strict = self.data_budget.is_some();
                self.pick_weighted(now, eligible, strict)?
            }
        };
        let topic = &mut self.topics[index as usize];
        topic.last_sent = Some(now);
        self.in_flight += 1;
        let len = item.wire_len();
        self.in_flight_bytes += len;
        self.in_flight_sizes.push_back(len);
        if let Some(b) = &mut self.budget {
            b.tokens -= item.wire_len() as f64;
        }
        Some((topic.id, item))
    }

    /// Re-reads group `g`'s longest-waiting ready topic into the flat scan array.
    fn refresh_head(&mut self, g: usize) {
        self.group_head[g] = match self.groups[g].ready.peek() {
            Some(Reverse((since, _))) => since.0 as f64,
            None => f64::INFINITY,
        };
    }

    /// Releases every held topic: the connection whose writer held them (a large
    /// message going out in chunks) is gone, and with it the lane that would have.
    pub fn release_all_held(&mut self, now: Nanos) {
        let held: Vec<TopicId> = self
            .index
            .iter()
            .filter(|(_, i)| self.topics[**i as usize].held)
            .map(|(id, _)| *id)
            .collect();
        for id in held {
            self.set_held(id, false, now);
        }
    }

    /// Holds back (or releases) a topic that is not a no-drop one: while held it is never
    /// picked, and what it publishes waits in its own queue under its drop policy. The
    /// link writer holds a topic while one of its large messages is still going out in
    /// chunks, so the next one is chosen (or dropped) by the queue's policy when the link
    /// can take it, not committed to the link early.
    pub fn set_held(&mut self, topic: TopicId, held: bool, now: Nanos) {
        let Some(&index) = self.index.get(&topic) else {
            return;
        };
        let t = &mut self.topics[index as usize];
        let Lane::Queue(queue) = &t.lane else {
            return;
        };
        t.held = held;
        if !held && !t.ready && !queue.is_empty() {
            t.ready = true;
            let since = t.last_sent.unwrap_or(now);
            let g = t.group;
            self.groups[g].ready.push(Reverse((since, index)));
            self.refresh_head(g);
        }
    }

    /// How many groups (from the highest priority) may send now under the data budget:
    /// all of them while the next message of the highest ready priority fits it (or is
    /// protected), else only the protected ones — the others wait (and a topic whose queue
    /// drops a message meanwhile is noted thinned, see [`Scheduler::offer`]).
    fn budget_eligible(&mut self, now: Nanos) -> usize {
        let all = self.groups.len();
        self.budget_refused = false;
        let Some(b) = self.data_budget.as_mut() else {
            return all;
        };
        let protect = f64::from(b.config().protect_priority);
        let protected = self.group_priority.partition_point(|p| *p >= protect);
        let Some(g) = self.group_head.iter().position(|h| h.is_finite()) else {
            return all;
        };
        if g < protected {
            return all;
        }
        let cost = self.groups[g].ready.peek().map_or(0, |Reverse((_, i))| {
            match &self.topics[*i as usize].lane {
                Lane::Queue(q) => q.peek().map_or(0, |m| m.wire_len()),
                Lane::NoDrop { .. } => 0,
            }
        });
        // Asked at what the message will be counted (see `Outbox::take_into`).
        if b.admits(crate::budget::wire_cost(cost), now) {
            return all;
        }
        self.budget_refused = true;
        protected
    }

    /// Pops from the topic with the largest `priority × wait` among the first `eligible`
    /// groups (the highest priorities) — or, `strict`, from the highest priority that has
    /// something ready — skipping held topics (they leave the heap when met and return on
    /// release).
    fn pick_weighted(&mut self, now: Nanos, eligible: usize, strict: bool) -> Option<(u32, T)> {
        loop {
            let g = if strict {
                self.group_head[..eligible]
                    .iter()
                    .position(|h| h.is_finite())?
            } else {
                self.best_group(now, eligible)?
            };
            let Reverse((_, index)) = self.groups[g].ready.pop()?;
            self.refresh_head(g);
            let topic = &mut self.topics[index as usize];
            if topic.held {
                topic.ready = false;
                continue;
            }
            let Lane::Queue(queue) = &mut topic.lane else {
                return None;
            };
            let item = queue.pop(now)?;
            if queue.is_empty() {
                topic.ready = false;
            } else {
                self.groups[g].ready.push(Reverse((now, index)));
                self.refresh_head(g);
            }
            return Some((index, item));
        }
    }

    /// The group whose longest-waiting ready topic has the largest `priority × wait`.
    /// Groups are in descending priority, so on equal scores the higher priority wins
    /// (strict `>`).
    fn best_group(&self, now: Nanos, eligible: usize) -> Option<usize> {
        let now_f = now.0 as f64;
        let mut best = f64::NEG_INFINITY;
        let mut best_g = usize::MAX;
        // Empty groups hold +inf, so their score is -inf and never wins. Scores are
        // compared a block at a time (a branch-free max the compiler vectorises); only a
        // block that beats the best so far is searched for its index.
        const BLOCK: usize = 8;
        let (prio, head) = (
            &self.group_priority[..eligible],
            &self.group_head[..eligible],
        );
        for (b, (ps, hs)) in prio.chunks(BLOCK).zip(head.chunks(BLOCK)).enumerate() {
            let mut scores = [f64::NEG_INFINITY; BLOCK];
            for i in 0..ps.len() {
                scores[i] = ps[i] * (now_f - hs[i]);
            }
            let block_max = scores.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            if block_max > best {
                // First index with the block's maximum: equal scores favour the higher
                // priority, which comes first.
                let i = scores.iter().position(|&x| x == block_max).unwrap_or(0);
                best = block_max;
                best_g = b * BLOCK + i;
            }
        }
        (best_g != usize::MAX).then_some(best_g)
    }

    /// `n` frames were acknowledged by the peer (pong or explicit ack).
    pub fn on_acked(&mut self, n_frames: usize, _now: Nanos) {
        self.in_flight = self.in_flight.saturating_sub(n_frames);
        for _ in 0..n_frames {
            match self.in_flight_sizes.pop_front() {
                Some(len) => self.in_flight_bytes -= len,
                None => break,
            }
        }
    }

    /// The link was re-established: nothing is in flight any more. (Frames lost with the
    /// old connection are the session layer's business.)
    pub fn on_link_reset(&mut self) {
        self.in_flight = 0;
        self.in_flight_sizes.clear();
        self.in_flight_bytes = 0;
    }

    /// Caps the sending rate at `bytes_per_sec` (the capacity share); `None` lifts the cap.
    pub fn set_rate_budget(&mut self, bytes_per_sec: Option<f64>, now: Nanos) {
        self.budget = match (bytes_per_sec, self.budget.take()) {
            (Some(rate), previous) if rate.is_finite() && rate > 0.0 => {
                let burst = (rate * self.config.budget_burst_secs).max(1.0);
                let mut b = previous.unwrap_or(Budget {
                    bytes_per_sec: rate,
                    burst,
                    tokens: burst,
                    at: now,
                });
                b.refill(now);
                b.bytes_per_sec = rate;
                b.burst = burst;
                b.tokens = b.tokens.min(burst);
                Some(b)
            }
            (Some(_), _) => Some(Budget {
                bytes_per_sec: 0.0,
                burst: 0.0,
                tokens: 0.0,
                at: now,
            }),
            (None, _) => None,
        };
    }

    /// Sets (or lifts, with `None`) the robot's data budget.
    pub fn set_data_budget(&mut self, budget: Option<DataBudget>) {
        self.data_budget = budget;
    }

    pub fn data_budget(&self) -> Option<&DataBudget> {
        self.data_budget.as_ref()
    }

    /// `bytes` left on the link at `now`: taken from the data budget, if one is set.
    pub fn debit_data(&mut self, bytes: usize, now: Nanos) {
        if let Some(b) = &mut self.data_budget {
            b.debit(bytes, now);
        }
    }

    /// `bytes` debited that did not leave after all (see [`DataBudget::credit`]).
    pub fn credit_data(&mut self, bytes: usize) {
        if let Some(b) = &mut self.data_budget {
            b.credit(bytes);
        }
    }

    /// Topics that lost a message to the data budget at or after `since` (their queue
    /// dropped one while the budget held them back).
    pub fn thinned_since(&self, since: Nanos) -> impl Iterator<Item = TopicId> + '_ {
        self.topics
            .iter()
            .filter(move |t| t.thinned_at.is_some_and(|at| at >= since))
            .map(|t| t.id)
    }

    /// The time at which [`Self::poll_next`] may succeed again when only a byte budget
    /// (the capacity share, or the data budget) holds it back; `None` if sending is not
    /// budget-limited (nothing queued, a free window, or waiting on acknowledgements).
    pub fn poll_timeout(&self, now: Nanos) -> Option<Nanos> {
        let data = self
            .data_budget
            .as_ref()
            .and_then(DataBudget::opens_at)
            .filter(|at| *at > now && self.has_queued());
        match (self.share_timeout(now), data) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    fn share_timeout(&self, now: Nanos) -> Option<Nanos> {
        let b = self.budget.as_ref()?;
        if !self.has_queued()
            || self.in_flight >= self.config.max_in_flight
            || b.bytes_per_sec <= 0.0
        {
            return None;
        }
        let tokens = b.tokens + now.saturating_sub(b.at).as_secs_f64() * b.bytes_per_sec;
        if tokens > 0.0 {
            return None;
        }
        Some(now + Nanos::from_secs_f64(-tokens / b.bytes_per_sec) + Nanos(1))
    }

    pub fn has_queued(&self) -> bool {
        !self.no_drop.is_empty() || self.groups.iter().any(|g| !g.ready.is_empty())
    }

    /// Frames sent and not yet acknowledged.
    /// Caps the bytes sent but not yet acknowledged (`None` = only the item count nT
    /// applies). Set it near the link's bandwidth-delay product: when capacity falls, the
    /// excess then waits here, where priorities still apply, instead of in the link's own
    /// queue where a small urgent message would wait behind it.
    pub fn set_window_bytes(&mut self, window: Option<usize>) {
        self.window_bytes = window;
    }

    /// Bytes sent and not yet acknowledged.
    pub fn in_flight_bytes(&self) -> usize {
        self.in_flight_bytes
    }

    pub fn in_flight(&self) -> usize {
        self.in_flight
    }

    /// Messages of `topic` waiting to be sent.
    pub fn queued(&self, topic: TopicId) -> usize {
        let Some(&i) = self.index.get(&topic) else {
            return 0;
        };
        match &self.topics[i as usize].lane {
            Lane::NoDrop { queued, .. } => *queued,
            Lane::Queue(q) => q.len(),
        }
    }
}
