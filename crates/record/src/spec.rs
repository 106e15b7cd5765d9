//! What a recording is asked to do: the `POST /api/v1/recordings` body, also built by
//! `fleetlink record` from its flags.

use serde::{Deserialize, Serialize};

/// Per-topic queue of a recording when the request names none: about two seconds of a
/// 30 Hz camera or point cloud, so a pause of the disk is absorbed without a drop.
pub const DEFAULT_QUEUE: usize = 64;
/// Longest per-topic queue a request may ask for (a queue holds whole messages).
pub const MAX_QUEUE: usize = 10_000;
/// Smallest size a file may be split at.
pub const MIN_SPLIT_BYTES: u64 = 1 << 20;

/// Chunk compression.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Compression {
    /// zstd at its default level: the smallest files.
    #[default]
    Zstd,
    /// LZ4: several times less CPU than zstd for larger files; for high rates.
    Lz4,
    None,
}

/// A recording request.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RecordSpec {
    /// Whole-name regular expressions of the topics to record (as in subscriptions and
    /// access rules: a plain name matches itself).
    pub topics: Vec<String>,
    /// A label for people; the files are named after it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// Start a new file once this many bytes are written.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub split_size_bytes: Option<u64>,
    /// Start a new file after this many seconds.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub split_duration_s: Option<u64>,
    /// Stop by itself after this many seconds.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub duration_s: Option<u64>,
    #[serde(default)]
    pub compression: Compression,
    /// Messages kept per topic while the disk is behind; more drop the oldest.
    #[serde(default = "default_queue")]
    pub queue: usize,
}

fn default_queue() -> usize {
    DEFAULT_QUEUE
}

impl RecordSpec {
    /// A request for `topics` with every default.
    pub fn topics<S: Into<String>>(topics: impl IntoIterator<Item = S>) -> RecordSpec {
        RecordSpec {
            topics: topics.into_iter().map(Into::into).collect(),
            name: None,
            split_size_bytes: None,
            split_duration_s: None,
            duration_s: None,
            compression: Compression::Zstd,
            queue: DEFAULT_QUEUE,
        }
    }

    /// The request's topics as one pattern, checked; an error names the field and what
    /// to write instead.
    pub fn check(&self) -> Result<regex::Regex, String> {
        if self.topics.is_empty() {
            return Err(
                "topics: give at least one topic name or pattern (e.g. \"/robot1/.*\")".into(),
            );
        }
        let pattern = one_pattern(&self.topics)?;
        if let Some(n) = &self.name
            && (n.is_empty()
                || n.len() > 64
                || !n
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_'))
        {
            return Err(format!(
                "name: {:?} must be 1 to 64 letters, digits, '-' or '_' (it names the files)",
                n.chars().take(80).collect::<String>()
            ));
        }
        if let Some(b) = self.split_size_bytes
            && b < MIN_SPLIT_BYTES
        {
            return Err(format!(
                "split_size_bytes: {b} is below the smallest split of {MIN_SPLIT_BYTES} bytes (1 MiB)"
            ));
        }
        if self.split_duration_s == Some(0) {
            return Err("split_duration_s: must be at least 1 second (or left out)".into());
        }
        if self.duration_s == Some(0) {
            return Err(
                "duration_s: must be at least 1 second (or left out to record until stopped)"
                    .into(),
            );
        }
        if self.queue == 0 || self.queue > MAX_QUEUE {
            return Err(format!(
                "queue: {} is outside 1..={MAX_QUEUE} messages per topic",
                self.queue
            ));
        }
        Ok(pattern)
    }
}

/// Whole-name patterns (`topics`) as one pattern; an error names the field and the
/// pattern that is wrong.
pub fn one_pattern(topics: &[String]) -> Result<regex::Regex, String> {
    for t in topics {
        if t.trim().is_empty() {
            return Err("topics: an empty pattern matches nothing; remove it".into());
        }
        fleetlink_relay::Router::compile_pattern(t).map_err(|e| format!("topics: {e}"))?;
    }
    let joined = topics
        .iter()
        .map(|t| format!("(?:{t})"))
        .collect::<Vec<_>>()
        .join("|");
    fleetlink_relay::Router::compile_pattern(&joined).map_err(|e| format!("topics: {e}"))
}

/// A size as people write it: `500MB`, `2GiB`, `1.5G`, `750k`, or a number of bytes.
pub fn parse_size(text: &str) -> Result<u64, String> {
    let t = text.trim();
    let split = t
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(t.len());
    let (num, unit) = t.split_at(split);
    let n: f64 = num
        .parse()
        .map_err(|_| format!("{text:?} is not a size (write e.g. 500MB or 2GiB)"))?;
    let mult: f64 = match unit.trim().to_ascii_lowercase().as_str() {
        "" | "b" => 1.0,
        "k" | "kb" => 1e3,
        "kib" => 1024.0,
        "m" | "mb" => 1e6,
        "mib" => 1048576.0,
        "g" | "gb" => 1e9,
        "gib" => 1073741824.0,
        "t" | "tb" => 1e12,
        "tib" => 1099511627776.0,
        u => {
            return Err(format!(
                "{text:?}: unknown unit {u:?} (use B, kB, MB, GB, KiB, MiB, GiB)"
            ));
        }
    };
    let v = n * mult;
    if !v.is_finite() || !(1.0..=1e18).contains(&v) {
        return Err(format!("{text:?} is out of range"));
    }
    Ok(v as u64)
}

/// A duration as people write it: `90s`, `10m`, `2h`, `1d`, or a number of seconds.
pub fn parse_duration_s(text: &str) -> Result<u64, String> {
    let t = text.trim();
    let split = t.find(|c: char| !c.is_ascii_digit()).unwrap_or(t.len());
    let (num, unit) = t.split_at(split);
    let n: u64 = num
        .parse()
        .map_err(|_| format!("{text:?} is not a duration (write e.g. 90s, 10m or 2h)"))?;
    let mult = match unit.trim() {
        "" | "s" => 1,
        "m" | "min" => 60,
        "h" => 3600,
        "d" => 86400,
        u => return Err(format!("{text:?}: unknown unit {u:?} (use s, m, h or d)")),
    };
    n.checked_mul(mult)
        .filter(|v| *v > 0)
        .ok_or_else(|| format!("{text:?} is out of range (at least 1 s)"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_topics_become_one_whole_name_pattern() {
        let re = RecordSpec::topics(["/robot1/.*", "/rosout"])
            .check()
            .unwrap();
        assert!(re.is_match("/robot1/scan"));
        assert!(re.is_match("/rosout"));
        assert!(!re.is_match("/robot2/scan"));
        assert!(!re.is_match("/rosout_agg"));
    }

    #[test]
    fn bad_requests_name_the_field() {
        let mut s = RecordSpec::topics(Vec::<String>::new());
        assert!(s.check().unwrap_err().starts_with("topics:"));
        s.topics = vec!["/a/(".into()];
        assert!(s.check().unwrap_err().starts_with("topics:"));
        s.topics = vec!["/a".into()];
        s.name = Some("../etc".into());
        assert!(s.check().unwrap_err().starts_with("name:"));
        s.name = None;
        s.split_size_bytes = Some(10);
        assert!(s.check().unwrap_err().starts_with("split_size_bytes:"));
        s.split_size_bytes = None;
        s.queue = 0;
        assert!(s.check().unwrap_err().starts_with("queue:"));
        s.queue = 5;
        s.duration_s = Some(0);
        assert!(s.check().unwrap_err().starts_with("duration_s:"));
    }

    #[test]
    fn unknown_fields_are_refused() {
        let e = serde_json::from_str::<RecordSpec>(r#"{"topics":["/a"],"split":3}"#)
            .unwrap_err()
            .to_string();
        assert!(e.contains("unknown field `split`"), "{e}");
    }

    #[test]
    fn sizes_and_durations_read_as_written() {
        assert_eq!(parse_size("500MB").unwrap(), 500_000_000);
        assert_eq!(parse_size("2GiB").unwrap(), 2 << 30);
        assert_eq!(parse_size("1.5G").unwrap(), 1_500_000_000);
        assert_eq!(parse_size("4096").unwrap(), 4096);
        assert!(parse_size("5 parsecs").is_err());
        assert!(parse_size("MB").is_err());
        assert_eq!(parse_duration_s("90s").unwrap(), 90);
        assert_eq!(parse_duration_s("10m").unwrap(), 600);
        assert_eq!(parse_duration_s("2h").unwrap(), 7200);
        assert_eq!(parse_duration_s("30").unwrap(), 30);
        assert!(parse_duration_s("0").is_err());
        assert!(parse_duration_s("1w").is_err());
    }
}
