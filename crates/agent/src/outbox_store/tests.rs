//! The durable outbox on real files: restart, torn tails, compaction, limits, locking.

use super::disk::{COMPACT_MIN, FILE, frame};
use super::*;
use bytes::Bytes;
use fleetlink_proto::{Encoding, Schema};
use fleetlink_relay::names::TopicId;
use std::fs::OpenOptions;

struct Dir(PathBuf);

impl Dir {
    fn new(tag: &str) -> Dir {
        let d = std::env::temp_dir().join(format!(
            "fleetlink-outbox-{tag}-{}-{}",
            std::process::id(),
            fastrand::u64(..)
        ));
        Dir(d)
    }
    fn cfg(&self, max_bytes: u64) -> OutboxStoreConfig {
        OutboxStoreConfig {
            dir: self.0.clone(),
            max_bytes,
            fsync: Fsync::Never,
        }
    }
}

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn meta(name: &str) -> TopicMeta {
    TopicMeta::new(
        TopicId(1),
        TopicName::parse(name).unwrap(),
        Schema {
            type_name: "std_msgs/msg/String".into(),
            encoding: "ros2msg".into(),
            text: "string data".into(),
        },
        false,
    )
}

fn payload(s: &str) -> Payload {
    Payload::new(Encoding::Json, Bytes::copy_from_slice(s.as_bytes()))
}

fn seqs(o: &Opened) -> Vec<(String, u64, String)> {
    o.recovered
        .iter()
        .map(|r| {
            (
                r.topic.to_string(),
                r.seq,
                String::from_utf8_lossy(&r.payload).into_owned(),
            )
        })
        .collect()
}

#[test]
fn unconfirmed_messages_survive_a_restart_in_order() {
    let d = Dir::new("restart");
    let (a, b) = (meta("/a"), meta("/b"));
    let epoch = {
        let mut o = open(&d.cfg(1 << 20)).unwrap();
        assert!(o.recovered.is_empty());
        for i in 1..=3 {
            o.journal
                .append(&a, i, 10 + i, &payload(&format!("a{i}")))
                .unwrap();
            o.journal
                .append(&b, i, 20 + i, &payload(&format!("b{i}")))
                .unwrap();
        }
        o.journal.confirm(&a.name, 2);
        o.epoch
    };
    let o = open(&d.cfg(1 << 20)).unwrap();
    assert_eq!(o.epoch, epoch, "the numbering epoch is kept");
    assert_eq!(
        seqs(&o),
        [
            ("/b".to_owned(), 1, "b1".to_owned()),
            ("/b".to_owned(), 2, "b2".to_owned()),
            ("/a".to_owned(), 3, "a3".to_owned()),
            ("/b".to_owned(), 3, "b3".to_owned()),
        ]
    );
    assert_eq!(o.recovered[2].stamp_ns, 13);
    assert_eq!(o.recovered[0].schema.type_name, "std_msgs/msg/String");
    assert_eq!(o.next_seq[&a.name], 4);
    assert_eq!(o.next_seq[&b.name], 4);
}

#[test]
fn a_torn_last_record_is_cut_and_the_rest_kept() {
    let d = Dir::new("torn");
    let a = meta("/a");
    {
        let mut o = open(&d.cfg(1 << 20)).unwrap();
        o.journal.append(&a, 1, 1, &payload("one")).unwrap();
        o.journal.append(&a, 2, 2, &payload("two")).unwrap();
    }
    let path = d.0.join(FILE);
    let full = std::fs::metadata(&path).unwrap().len();
    // The agent died half-way through writing the second message.
    let f = OpenOptions::new().write(true).open(&path).unwrap();
    f.set_len(full - 3).unwrap();
    drop(f);
    let o = open(&d.cfg(1 << 20)).unwrap();
    assert_eq!(seqs(&o), [("/a".to_owned(), 1, "one".to_owned())]);
    assert!(std::fs::metadata(&path).unwrap().len() < full - 3);
    drop(o);
    // Flipped bits in a record are caught by its checksum the same way.
    let mut bytes = std::fs::read(&path).unwrap();
    let last = bytes.len() - 1;
    bytes[last] ^= 0xff;
    std::fs::write(&path, &bytes).unwrap();
    let o = open(&d.cfg(1 << 20)).unwrap();
    assert!(o.recovered.is_empty());
}

#[test]
fn a_full_outbox_refuses_with_the_setting_to_raise() {
    let d = Dir::new("full");
    let a = meta("/a");
    let mut o = open(&d.cfg(10)).unwrap();
    o.journal.append(&a, 1, 1, &payload("12345678")).unwrap();
    let e = o.journal.append(&a, 2, 1, &payload("123")).unwrap_err();
    assert!(
        matches!(e, JournalError::Full { used: 8, limit: 10 }),
        "{e}"
    );
    assert!(e.to_string().contains("outbox.max_mb"), "{e}");
    // Confirmed messages make room again.
    o.journal.confirm(&a.name, 1);
    o.journal.append(&a, 2, 1, &payload("123")).unwrap();
}

#[test]
fn compaction_keeps_the_live_messages_and_the_numbering() {
    let d = Dir::new("compact");
    let a = meta("/a");
    let big = "x".repeat(64 << 10);
    {
        let mut o = open(&d.cfg(1 << 30)).unwrap();
        for i in 1..=200 {
            o.journal.append(&a, i, i, &payload(&big)).unwrap();
            o.journal.confirm(&a.name, i);
        }
        o.journal.append(&a, 201, 201, &payload("last")).unwrap();
    }
    let len = std::fs::metadata(d.0.join(FILE)).unwrap().len();
    assert!(len < 2 * COMPACT_MIN, "compacted file is {len} bytes");
    let o = open(&d.cfg(1 << 30)).unwrap();
    assert_eq!(seqs(&o), [("/a".to_owned(), 201, "last".to_owned())]);
    assert_eq!(o.next_seq[&a.name], 202);
    drop(o);
    // Everything confirmed: the numbering still goes on after a restart.
    let mut o = open(&d.cfg(1 << 30)).unwrap();
    o.journal.confirm(&a.name, 201);
    drop(o);
    assert_eq!(open(&d.cfg(1 << 30)).unwrap().next_seq[&a.name], 202);
}

#[test]
fn two_agents_cannot_share_one_outbox() {
    let d = Dir::new("lock");
    let _first = open(&d.cfg(1 << 20)).unwrap();
    match open(&d.cfg(1 << 20)) {
        Err(e @ StoreError::Locked { .. }) => assert!(e.to_string().contains("outbox.dir")),
        Err(e) => panic!("expected a lock error, got {e}"),
        Ok(_) => panic!("a second agent opened a locked outbox"),
    }
}

#[test]
fn a_file_that_is_not_an_outbox_is_refused_not_overwritten() {
    let d = Dir::new("foreign");
    std::fs::create_dir_all(&d.0).unwrap();
    std::fs::write(d.0.join(FILE), frame(b"\x03not a header")).unwrap();
    let e = open(&d.cfg(1 << 20)).err().expect("refused");
    assert!(matches!(e, StoreError::Foreign { .. }), "{e}");
    assert!(std::fs::metadata(d.0.join(FILE)).unwrap().len() > 0);
}

#[test]
fn a_batch_synced_outbox_is_free_to_reopen_as_soon_as_it_is_dropped() {
    // The batch policy syncs on a thread holding a copy of the file descriptor, and with
    // it the outbox's lock: dropping the journal must end that thread first.
    let d = Dir::new("batch-reopen");
    let cfg = OutboxStoreConfig {
        fsync: Fsync::Batch,
        ..d.cfg(1 << 20)
    };
    let a = meta("/a");
    for round in 1..=20u64 {
        let mut o = open(&cfg).unwrap_or_else(|e| panic!("round {round}: {e}"));
        assert_eq!(o.recovered.len() as u64, round - 1);
        o.journal
            .append(&a, round, round, &payload(&format!("a{round}")))
            .unwrap();
        // An idle tick hands the sync to the thread.
        o.journal.tick();
    }
}

/// Issue 36: the agent's thread hands records over and goes on; the journal thread does
/// the writing. With the disk slowed to 10 MB/s, compacting 4 MB takes at least 0.4 s on
/// the journal thread; the confirmation that starts it has returned long before the new
/// file replaces the old one.
#[test]
fn issue36_a_compaction_on_a_slow_disk_does_not_hold_up_the_agents_thread() {
    if !slow_disk::available() {
        return; // a release build has no slow disk to simulate
    }
    let d = Dir::new("slow");
    let (live, filler) = (meta("/live"), meta("/filler"));
    let mut o = open(&d.cfg(1 << 30)).unwrap();
    let mb = payload(&"x".repeat(1 << 20));
    for i in 1..=4 {
        o.journal.append(&live, i, i, &mb).unwrap();
    }
    for i in 1..=16 {
        o.journal.append(&filler, i, i, &mb).unwrap();
    }
    o.journal.wait_written();
    let path = d.0.join(FILE);
    let before = std::fs::metadata(&path).unwrap().len();
    assert!(before > 20 << 20, "{before}");
    slow_disk::set(10_000_000);
    // Confirms the filler: the file is five times the live data, so this compacts it.
    o.journal.confirm(&filler.name, 16);
    let right_after = std::fs::metadata(&path).unwrap().len();
    // A message handed over meanwhile is taken at once too.
    o.journal.append(&live, 5, 5, &payload("during")).unwrap();
    assert_eq!(
        right_after, before,
        "confirm() returned only after the compaction had replaced the file"
    );
    o.journal.wait_written();
    slow_disk::set(0);
    let after = std::fs::metadata(&path).unwrap().len();
    assert!(after < 5 << 20, "compacted to {after} bytes");
    drop(o);
    let o = open(&d.cfg(1 << 30)).unwrap();
    let got: Vec<u64> = o.recovered.iter().map(|r| r.seq).collect();
    assert_eq!(
        got,
        [1, 2, 3, 4, 5],
        "the live messages, and the one handed over meanwhile"
    );
}

#[test]
fn a_closed_journal_refuses_with_the_reason_and_kept_what_it_had() {
    let d = Dir::new("closed");
    let a = meta("/a");
    let mut o = open(&d.cfg(1 << 20)).unwrap();
    o.journal.append(&a, 1, 1, &payload("one")).unwrap();
    o.journal.close();
    let e = o.journal.append(&a, 2, 2, &payload("two")).unwrap_err();
    assert!(e.to_string().contains("closed"), "{e}");
    drop(o);
    let o = open(&d.cfg(1 << 20)).unwrap();
    assert_eq!(seqs(&o), [("/a".to_owned(), 1, "one".to_owned())]);
}
