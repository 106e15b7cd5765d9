//! A stream's target bitrate following its link: between the configured floor and top, down
//! when the stream's frames wait on the link, up again while they do not, and never above
//! what the link may carry by rule (the hub's capacity share, the data budget).
//!
//! Design choice: the signal is the stream's own backlog in the robot's link queue (frames
//! encoded and not yet sent), read once a second. A link measured only while data flows
//! cannot say how much more it would carry, so the rate is not set from the measured
//! capacity; it is found as a TCP sender finds its window: multiplicative decrease when
//! frames queue (a quarter of a second of video or more: the link carries less than is
//! offered), a slower increase while nothing waits. The share and the budget are known
//! limits, so they cap the rate at once.

/// Frames waiting on the link, as a fraction of a second of video, from which the rate
/// comes down.
const BACKLOG_S: f32 = 0.25;
/// The cut when frames wait.
const DECREASE: f64 = 0.7;
/// The rise per look while nothing waits.
const INCREASE: f64 = 1.1;
/// The part of a limit (share, budget) the video may take: the rest is for the other
/// topics and the frame headers.
const OF_LIMIT: f64 = 0.8;
/// Changes smaller than this fraction are not passed to the encoder.
const MIN_CHANGE: f64 = 0.05;

/// What a stream's link says, once a second.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LinkState {
    /// The stream's frames waiting in the link's queue.
    pub backlog_frames: usize,
    /// What the link may carry by rule, bytes a second: the smallest of the hub's share for
    /// the robot and its data budget's rate; `None` without either.
    pub limit_bytes_per_sec: Option<f64>,
}

/// The target bitrate of one stream.
#[derive(Debug, Clone)]
pub struct LinkFollower {
    min_bps: u32,
    max_bps: u32,
    fps: f32,
    target: f64,
    /// The target the encoder has.
    applied: u32,
}

impl LinkFollower {
    /// Starts at the top, `max_bps`; never below `min_bps`.
    pub fn new(min_bps: u32, max_bps: u32, fps: f32) -> LinkFollower {
        let min_bps = min_bps.min(max_bps);
        LinkFollower {
            min_bps,
            max_bps,
            fps,
            target: f64::from(max_bps),
            applied: max_bps,
        }
    }

    /// The target the encoder has now.
    pub fn bitrate(&self) -> u32 {
        self.applied
    }

    /// Takes a look at the link; returns a new target for the encoder when it moved by
    /// more than a little.
    pub fn update(&mut self, link: LinkState) -> Option<u32> {
        let waiting = (self.fps * BACKLOG_S).ceil().max(2.0) as usize;
        if link.backlog_frames >= waiting {
            self.target *= DECREASE;
        } else if link.backlog_frames == 0 {
            self.target *= INCREASE;
        }
        let cap = link
            .limit_bytes_per_sec
            .map_or(f64::INFINITY, |b| b * 8.0 * OF_LIMIT);
        self.target = self
            .target
            .min(cap)
            .clamp(f64::from(self.min_bps), f64::from(self.max_bps));
        let target = self.target.round() as u32;
        let moved = (f64::from(target) - f64::from(self.applied)).abs();
        let edge = target == self.min_bps || target == self.max_bps;
        if target != self.applied && (moved > f64::from(self.applied) * MIN_CHANGE || edge) {
            self.applied = target;
            return Some(target);
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn waiting(n: usize) -> LinkState {
        LinkState {
            backlog_frames: n,
            limit_bytes_per_sec: None,
        }
    }

    #[test]
    fn frames_waiting_bring_the_rate_down_to_the_floor_and_an_empty_queue_back_up() {
        let mut f = LinkFollower::new(200_000, 1_500_000, 15.0);
        assert_eq!(f.bitrate(), 1_500_000, "starts at the top");
        // One or two frames waiting is the link at work, not a backlog.
        assert_eq!(f.update(waiting(2)), None);
        assert_eq!(f.update(waiting(4)), Some(1_050_000));
        let mut looks = 1;
        while f.update(waiting(10)).is_some() {
            looks += 1;
        }
        assert_eq!(f.bitrate(), 200_000, "the floor");
        assert!(looks <= 6, "{looks} looks to the floor");
        // Nothing waiting: back to the top within a minute.
        let mut looks = 0;
        while f.bitrate() < 1_500_000 {
            f.update(waiting(0));
            looks += 1;
            assert!(looks < 60);
        }
        assert!(looks >= 10, "a slower rise ({looks} looks) than fall");
    }

    #[test]
    fn the_share_and_the_budget_cap_the_rate_at_once() {
        let mut f = LinkFollower::new(100_000, 2_000_000, 15.0);
        // 50 kB/s allowed: 400 kbit/s, of which the video takes 80 %.
        let limited = LinkState {
            backlog_frames: 0,
            limit_bytes_per_sec: Some(50_000.0),
        };
        assert_eq!(f.update(limited), Some(320_000));
        assert_eq!(f.update(limited), None);
        // Below the floor: the floor (the link queue then drops what does not fit).
        let tiny = LinkState {
            backlog_frames: 0,
            limit_bytes_per_sec: Some(1_000.0),
        };
        assert_eq!(f.update(tiny), Some(100_000));
    }
}
