//! Login throttling: sans-IO failure counting per user name and per client address.
//!
//! Design choice: failures, not attempts, are counted, and a key is locked out only after
//! `max_failures` within `window_secs`; each further failure doubles the lockout up to
//! `max_lockout_secs`. Per-address limits stop one host from guessing many accounts;
//! per-user limits stop a botnet guessing one account (at the price that an attacker can
//! lock a user out for a while — the lockout is short and capped for that reason).
//! The table is bounded: when full, entries with no recent failure are dropped.

use std::collections::HashMap;
use std::net::IpAddr;

use crate::UnixTime;

/// Limits for one kind of key.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limit {
    pub max_failures: u32,
    pub window_secs: i64,
    pub base_lockout_secs: i64,
    pub max_lockout_secs: i64,
}

/// Limits for user names and for client addresses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RateLimitConfig {
    pub per_user: Limit,
    pub per_ip: Limit,
    /// Keys tracked at most, per kind.
    pub capacity: usize,
}

impl Default for RateLimitConfig {
    fn default() -> RateLimitConfig {
        RateLimitConfig {
            per_user: Limit {
                max_failures: 5,
                window_secs: 15 * 60,
                base_lockout_secs: 30,
                max_lockout_secs: 15 * 60,
            },
            per_ip: Limit {
                max_failures: 20,
                window_secs: 15 * 60,
                base_lockout_secs: 60,
                max_lockout_secs: 60 * 60,
            },
            capacity: 100_000,
        }
    }
}

#[derive(Debug, Clone, Copy)]
struct Entry {
    failures: u32,
    last_failure: UnixTime,
    locked_until: UnixTime,
}

#[derive(Debug)]
struct Table<K> {
    limit: Limit,
    entries: HashMap<K, Entry>,
}

impl<K: std::hash::Hash + Eq + Clone> Table<K> {
    fn retry_after(&self, key: &K, now: UnixTime) -> Option<i64> {
        let e = self.entries.get(key)?;
        (e.locked_until > now).then(|| e.locked_until.0 - now.0)
    }

    fn fail(&mut self, key: &K, now: UnixTime, capacity: usize) {
        if self.entries.len() >= capacity && !self.entries.contains_key(key) {
            let window = self.limit.window_secs;
            self.entries
                .retain(|_, e| e.locked_until > now || now.0 - e.last_failure.0 < window);
            if self.entries.len() >= capacity {
                // Still full of live entries: forget the oldest half rather than grow.
                let mut ages: Vec<i64> = self.entries.values().map(|e| e.last_failure.0).collect();
                ages.sort_unstable();
                let cutoff = ages[ages.len() / 2];
                self.entries.retain(|_, e| e.last_failure.0 > cutoff);
            }
        }
        let limit = self.limit;
        let e = self.entries.entry(key.clone()).or_insert(Entry {
            failures: 0,
            last_failure: now,
            locked_until: UnixTime(i64::MIN),
        });
        if now.0 - e.last_failure.0 >= limit.window_secs {
            e.failures = 0;
        }
        e.failures = e.failures.saturating_add(1);
        e.last_failure = now;
        if e.failures >= limit.max_failures {
            let doublings = (e.failures - limit.max_failures).min(20);
            let lockout = limit
                .base_lockout_secs
                .saturating_mul(1 << doublings)
                .min(limit.max_lockout_secs);
            e.locked_until = now.plus_secs(lockout);
        }
    }
}

/// The login limiter. Owned by the authenticator behind a short-held lock.
#[derive(Debug)]
pub struct LoginLimiter {
    capacity: usize,
    users: Table<String>,
    ips: Table<IpAddr>,
}

impl LoginLimiter {
    pub fn new(config: RateLimitConfig) -> LoginLimiter {
        LoginLimiter {
            capacity: config.capacity.max(2),
            users: Table {
                limit: config.per_user,
                entries: HashMap::new(),
            },
            ips: Table {
                limit: config.per_ip,
                entries: HashMap::new(),
            },
        }
    }

    /// `Some(seconds)` to wait if either the user or the address is locked out.
    pub fn check(&self, user: &str, ip: IpAddr, now: UnixTime) -> Option<i64> {
        let u = self.users.retry_after(&user.to_owned(), now);
        let i = self.ips.retry_after(&ip, now);
        u.max(i)
    }

    pub fn record_failure(&mut self, user: &str, ip: IpAddr, now: UnixTime) {
        self.users.fail(&user.to_owned(), now, self.capacity);
        self.ips.fail(&ip, now, self.capacity);
    }

    /// A successful login clears the user's record (the address keeps its history, so a
    /// host cannot reset its counter by logging into its own account between guesses).
    pub fn record_success(&mut self, user: &str) {
        self.users.entries.remove(user);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ip(s: &str) -> IpAddr {
        s.parse().unwrap()
    }

    #[test]
    fn lockout_starts_at_threshold_and_doubles() {
        let mut l = LoginLimiter::new(RateLimitConfig::default());
        let t = UnixTime(1_000);
        for _ in 0..4 {
            l.record_failure("alice", ip("192.0.2.1"), t);
        }
        assert_eq!(l.check("alice", ip("192.0.2.1"), t), None);
        l.record_failure("alice", ip("192.0.2.1"), t);
        assert_eq!(l.check("alice", ip("192.0.2.1"), t), Some(30));
        assert_eq!(l.check("alice", ip("192.0.2.1"), t.plus_secs(30)), None);
        l.record_failure("alice", ip("192.0.2.1"), t.plus_secs(30));
        assert_eq!(l.check("alice", ip("192.0.2.1"), t.plus_secs(30)), Some(60));
    }

    #[test]
    fn failures_outside_the_window_are_forgotten() {
        let mut l = LoginLimiter::new(RateLimitConfig::default());
        for i in 0..4 {
            l.record_failure("bob", ip("192.0.2.2"), UnixTime(i));
        }
        l.record_failure("bob", ip("192.0.2.2"), UnixTime(10_000));
        assert_eq!(l.check("bob", ip("192.0.2.2"), UnixTime(10_000)), None);
    }

    #[test]
    fn table_stays_bounded() {
        let mut l = LoginLimiter::new(RateLimitConfig {
            capacity: 100,
            ..RateLimitConfig::default()
        });
        for i in 0..10_000u32 {
            let addr = IpAddr::from(i.to_be_bytes());
            l.record_failure(&format!("u{i}"), addr, UnixTime(i64::from(i)));
        }
        assert!(l.users.entries.len() <= 100 && l.ips.entries.len() <= 100);
    }
}
