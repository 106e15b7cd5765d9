//! The envelopes of a client's recent `publish`es, kept so the next one is read by
//! comparing text instead of scanning it.
//!
//! A client sends every publish of a topic in the same envelope: roslibjs writes
//! `{"op":"publish","id":"publish:/t:7","topic":"/t","msg":{…},"latch":false}`, roslibpy
//! much the same, and only the `id` (a counter) and the message change. An
//! [`EnvelopeShape`] is such an envelope cut into the text around those two:
//!
//! ```text
//!  {"op":"publish","id":"   publish:/t:7   ","topic":"/t","msg":   {…}   ,"latch":false}
//!  └────── head ──────────┘ └ id string ┘ └──────── middle ─────┘ └msg┘ └─── tail ───┘
//! ```
//!
//! A new frame that starts with the head, has a plain string (no escapes) where the id
//! was, then the middle, and ends with the tail is the same envelope around another id
//! and another message: the topic is where it was. The scan over the envelope's keys
//! is skipped, and so are the frame's UTF-8 check (the head, middle and tail are the
//! checked text of the shape; the id is checked here) and the syntax check of the
//! message, which the caller must then make: the check against the message's type does
//! both, and a message that fails it is read again the full way
//! ([`Publish::from_json_text`](super::Publish::from_json_text)), which says why.
//!
//! A few shapes are kept (a client publishing on several topics); one that stops
//! matching is replaced by the envelope read in full. A client whose envelopes keep
//! changing stops being compared for a while, so it pays for the comparisons only a few
//! times.

use std::ops::Range;

use fleetlink_msg::json_scan::string_stop;

use super::scan::Envelope;

/// Shapes kept per client.
const SLOTS: usize = 4;
/// Misses in a row after which shapes are not tried for [`REST`] frames.
const MISSES: u32 = 16;
const REST: u32 = 1024;

/// One envelope's text with the places of its `id` string and message.
#[derive(Debug, Default)]
struct EnvelopeShape {
    text: String,
    /// Where the id string's content lies (between its quotes), if there is one.
    id: Option<Range<usize>>,
    msg: Range<usize>,
    topic: Range<usize>,
}

/// Where the parts of a frame that has a kept shape lie.
#[derive(Debug, PartialEq)]
pub struct Matched {
    /// The id as JSON (with its quotes), checked as UTF-8.
    pub id: Option<Range<usize>>,
    /// The topic, as the shape's (checked) text has it.
    pub topic: Range<usize>,
    /// The message: not checked in any way, not even as UTF-8.
    pub msg: Range<usize>,
}

impl EnvelopeShape {
    /// The shape of `text`, read in full as `e`; `false` when it has none usable (an id
    /// that is not a plain string, or one after the message).
    fn learn(&mut self, text: &str, e: &Envelope<'_>, msg: &Range<usize>) -> bool {
        let Some(topic) = e.topic.map(|t| offset_in(text, t)) else {
            return false;
        };
        let id = match &e.id {
            None => None,
            Some(r) => {
                let b = text.as_bytes();
                let inner = r.start + 1..r.end.saturating_sub(1);
                let plain = b[r.start] == b'"'
                    && r.end >= r.start + 2
                    && string_stop(b, inner.start) == inner.end;
                if !plain || r.end > msg.start {
                    return false;
                }
                Some(inner)
            }
        };
        self.text.clear();
        self.text.push_str(text);
        self.id = id;
        self.msg = msg.clone();
        self.topic = topic;
        true
    }

    /// Where `x`'s parts lie if it has this shape.
    #[inline]
    fn fit(&self, x: &[u8]) -> Option<Matched> {
        let t = self.text.as_bytes();
        let head_end = self.id.as_ref().map_or(self.msg.start, |id| id.start);
        if !x.starts_with(&t[..head_end]) {
            return None;
        }
        // How far the frame's text after the id is from the shape's.
        let (shift, id) = match &self.id {
            None => (0isize, None),
            Some(id) => {
                let end = string_stop(x, head_end);
                if x.get(end) != Some(&b'"') {
                    return None;
                }
                let middle = &t[id.end..self.msg.start];
                if !x[end..].starts_with(middle) {
                    return None;
                }
                (end as isize - id.end as isize, Some(head_end - 1..end + 1))
            }
        };
        let tail = &t[self.msg.end..];
        let msg_start = (self.msg.start as isize + shift) as usize;
        if x.len() < msg_start + tail.len() + 2 || !x.ends_with(tail) || x[msg_start] != b'{' {
            return None;
        }
        let msg = msg_start..x.len() - tail.len();
        let topic = if self.topic.end <= head_end {
            self.topic.clone()
        } else if self.topic.start >= self.msg.end {
            let from_end = t.len() - self.topic.start;
            x.len() - from_end..x.len() - from_end + self.topic.len()
        } else {
            let s = (self.topic.start as isize + shift) as usize;
            s..s + self.topic.len()
        };
        Some(Matched { id, topic, msg })
    }
}

/// The byte range of `part` (a slice of `text`) within `text`.
fn offset_in(text: &str, part: &str) -> Range<usize> {
    let start = part.as_ptr() as usize - text.as_ptr() as usize;
    start..start + part.len()
}

/// A client's recent envelope shapes.
#[derive(Debug, Default)]
pub struct EnvelopeShapes {
    slots: [EnvelopeShape; SLOTS],
    used: usize,
    /// The slot to replace next.
    next: usize,
    /// The slot that matched last, tried first.
    last: usize,
    misses: u32,
    /// Frames left before shapes are tried again, after many misses.
    resting: u32,
}

impl EnvelopeShapes {
    /// The parts of `text` (a text frame, not yet checked as UTF-8) if it has one of the
    /// kept shapes. Everything but the message is then known to be UTF-8.
    #[inline]
    pub fn fit(&mut self, text: &[u8]) -> Option<Matched> {
        let m = self.fit_any(text)?;
        if let Some(id) = &m.id
            && !text[id.clone()].is_ascii()
            && std::str::from_utf8(&text[id.clone()]).is_err()
        {
            return None;
        }
        Some(m)
    }

    #[inline]
    fn fit_any(&mut self, text: &[u8]) -> Option<Matched> {
        if self.resting > 0 {
            self.resting -= 1;
            return None;
        }
        if self.used == 0 {
            return None;
        }
        if let Some(m) = self.slots[self.last].fit(text) {
            self.misses = 0;
            return Some(m);
        }
        for i in (0..self.used).filter(|i| *i != self.last) {
            if let Some(m) = self.slots[i].fit(text) {
                self.last = i;
                self.misses = 0;
                return Some(m);
            }
        }
        None
    }

    /// Keeps the shape of `text`, a publish that fitted none and was read in full as `e`
    /// with its message at `msg`.
    pub(crate) fn learn(&mut self, text: &str, e: &Envelope<'_>, msg: &Range<usize>) {
        if self.resting > 0 {
            return;
        }
        self.misses += 1;
        if self.misses >= MISSES {
            self.misses = 0;
            self.resting = REST;
            return;
        }
        let slot = self.next;
        if self.slots[slot].learn(text, e, msg) {
            self.last = slot;
            self.next = (slot + 1) % SLOTS;
            self.used = (self.used + 1).min(SLOTS);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn learned(text: &str) -> EnvelopeShapes {
        let mut s = EnvelopeShapes::default();
        let e = super::super::scan::envelope(text).expect("an envelope");
        let msg = e.msg.clone().expect("a msg");
        s.learn(text, &e, &msg);
        s
    }

    fn parts<'t>(text: &'t str, m: &Matched) -> (Option<&'t str>, &'t str, &'t str) {
        (
            m.id.clone().map(|r| &text[r]),
            &text[m.topic.clone()],
            &text[m.msg.clone()],
        )
    }

    #[test]
    fn another_id_and_message_in_the_same_envelope_fit() {
        let mut s = learned(
            r#"{"op":"publish","id":"publish:/t:1","topic":"/t","msg":{"data":"a"},"latch":false}"#,
        );
        let next = r#"{"op":"publish","id":"publish:/t:1234","topic":"/t","msg":{"data":"bb", "n": [1,2]},"latch":false}"#;
        let m = s.fit(next.as_bytes()).expect("fits");
        assert_eq!(
            parts(next, &m),
            (
                Some(r#""publish:/t:1234""#),
                "/t",
                r#"{"data":"bb", "n": [1,2]}"#
            )
        );
    }

    #[test]
    fn the_topic_is_found_before_between_and_after_the_holes() {
        for (first, next, topic) in [
            (
                r#"{"topic":"/a","op":"publish","id":"x","msg":{}}"#,
                r#"{"topic":"/a","op":"publish","id":"xyz","msg":{"k":1}}"#,
                "/a",
            ),
            (
                r#"{"op":"publish","id":"x","topic":"/b","msg":{}}"#,
                r#"{"op":"publish","id":"xyz","topic":"/b","msg":{"k":1}}"#,
                "/b",
            ),
            (
                r#"{"op":"publish","msg":{},"topic":"/c"}"#,
                r#"{"op":"publish","msg":{"k":[1,2,3]},"topic":"/c"}"#,
                "/c",
            ),
        ] {
            let mut s = learned(first);
            let m = s
                .fit(next.as_bytes())
                .unwrap_or_else(|| panic!("{next} fits {first}"));
            assert_eq!(&next[m.topic.clone()], topic, "{next}");
            assert!(next[m.msg.clone()].starts_with('{'));
        }
    }

    #[test]
    fn anything_else_does_not_fit() {
        let mut s =
            learned(r#"{"op":"publish","id":"publish:/t:1","topic":"/t","msg":{"data":"a"}}"#);
        for other in [
            // Another topic, another op, an escape in the id, no id, a changed tail.
            r#"{"op":"publish","id":"publish:/u:1","topic":"/u","msg":{"data":"a"}}"#,
            r#"{"op":"publisx","id":"publish:/t:1","topic":"/t","msg":{"data":"a"}}"#,
            r#"{"op":"publish","id":"pub\"lish","topic":"/t","msg":{"data":"a"}}"#,
            r#"{"op":"publish","topic":"/t","msg":{"data":"a"}}"#,
            // Not an object where the message was; too short to hold one.
            r#"{"op":"publish","id":"publish:/t:1","topic":"/t","msg":[1]}"#,
            r#"{"op":"publish","id":"publish:/t:1","topic":"/t","msg":}"#,
            r#"{"op":"publish","id":""#,
        ] {
            assert_eq!(s.fit(other.as_bytes()), None, "{other}");
        }
        // A key added after the message fits, with more than the message where the
        // message was: the message's own check (which the caller must make) refuses it.
        let more = r#"{"op":"publish","id":"publish:/t:1","topic":"/t","msg":{"data":"a"},"x":1}"#;
        let m = s.fit(more.as_bytes()).expect("fits by its ends");
        assert!(!super::super::is_json_value(more[m.msg].as_bytes()));
    }

    #[test]
    fn a_frame_whose_id_is_not_utf8_does_not_fit() {
        let mut s = learned(r#"{"op":"publish","id":"p:1","topic":"/t","msg":{}}"#);
        let mut bad = br#"{"op":"publish","id":"p:"#.to_vec();
        bad.extend_from_slice(&[0xC3, 0x28]);
        bad.extend_from_slice(br#"","topic":"/t","msg":{}}"#);
        assert_eq!(s.fit(&bad), None);
        let good = r#"{"op":"publish","id":"p:é","topic":"/t","msg":{}}"#;
        assert!(s.fit(good.as_bytes()).is_some());
    }

    #[test]
    fn ids_that_are_not_plain_strings_or_come_after_the_message_make_no_shape() {
        for text in [
            r#"{"op":"publish","id":7,"topic":"/t","msg":{}}"#,
            r#"{"op":"publish","id":"a\nb","topic":"/t","msg":{}}"#,
            r#"{"op":"publish","topic":"/t","msg":{},"id":"x"}"#,
        ] {
            let mut s = learned(text);
            assert_eq!(s.fit(text.as_bytes()), None, "{text}");
        }
    }

    #[test]
    fn several_topics_keep_their_shapes_and_a_changing_client_is_left_alone() {
        let mut s = EnvelopeShapes::default();
        let text = |t: usize, n: usize| {
            format!(r#"{{"op":"publish","id":"publish:/t{t}:{n}","topic":"/t{t}","msg":{{}}}}"#)
        };
        for t in 0..SLOTS {
            let first = text(t, 0);
            let e = super::super::scan::envelope(&first).unwrap();
            let msg = e.msg.clone().unwrap();
            s.learn(&first, &e, &msg);
        }
        for n in 1..10 {
            for t in 0..SLOTS {
                let next = text(t, n);
                let m = s.fit(next.as_bytes()).unwrap_or_else(|| panic!("{next}"));
                assert_eq!(&next[m.topic.clone()], format!("/t{t}"));
            }
        }
        // Publishes that never fit: after a few, no more comparing for a while.
        for n in 0..MISSES {
            let other = format!(r#"{{"op":"publish","topic":"/x{n}","msg":{{}}}}"#);
            assert_eq!(s.fit(other.as_bytes()), None);
            let e = super::super::scan::envelope(&other).unwrap();
            let msg = e.msg.clone().unwrap();
            s.learn(&other, &e, &msg);
        }
        assert!(s.resting > 0);
        assert_eq!(s.fit(text(0, 99).as_bytes()), None, "resting: not compared");
    }
}
