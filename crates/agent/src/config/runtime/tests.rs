//! Reading changes and merging them entry by entry: what a change writes changes, nothing
//! else does; removals are written; no_drop is the file's; errors are the file's.

use super::kept::{change_doc, settle};
use super::*;

fn running() -> AgentConfig {
    AgentConfig::from_str(
        "ros2:\n  publish: [/a, /b]\ntopics:\n  /a: { priority: 3 }\n",
        "robot.yaml",
    )
    .expect("a valid file")
}

/// `text` applied to `file` as the first change.
fn first(file: &AgentConfig, text: &str) -> Result<Changed, ConfigError> {
    change(
        file,
        file,
        &[],
        text,
        "change",
        "user:ana",
        1_718_000_000_000,
    )
}

/// `text` applied on top of `c`, the configuration `file` runs with.
fn then(file: &AgentConfig, c: &Changed, text: &str) -> Result<Changed, ConfigError> {
    change(
        file,
        &c.config,
        &c.kept,
        text,
        "change",
        "user:bo",
        1_718_000_060_000,
    )
}

/// The changes in force, written as a change, applied again to the file.
fn again(file: &AgentConfig, c: &Changed) -> AgentConfig {
    let doc = serde_json::to_string(&change_doc(&c.kept)).unwrap();
    first(file, &doc)
        .unwrap_or_else(|e| panic!("{doc}: {e}"))
        .config
}

#[test]
fn a_change_sets_the_entries_it_writes_and_keeps_the_others() {
    let cfg = running();
    let c = first(
        &cfg,
        "ros2: { publish: [/c] }\ntopics: { /c: { rate_limit_hz: 2 } }\n",
    )
    .expect("a valid change");
    assert_eq!(c.fields, vec!["topics", "ros2.publish"]);
    let r2 = c.config.ros2.as_ref().expect("ros2 kept");
    assert_eq!(
        r2.publish.include,
        vec!["/a", "/b", "/c"],
        "a name written is added"
    );
    assert_eq!(c.config.topics["/a"].priority, Some(3.0), "/a untouched");
    assert_eq!(c.config.topics["/c"].rate_limit_hz, Some(2.0));
    assert_eq!(r2.discovery_ms, cfg.ros2.as_ref().unwrap().discovery_ms);
    assert_eq!(again(&cfg, &c), c.config);
}

/// Issue 57: a kept change that rate-limits `/pose` next to a file with several topics
/// changes `/pose`, and only its rate: `/probe/reliable` stays no_drop.
#[test]
fn issue57_a_change_to_one_topic_leaves_the_files_other_topics_alone() {
    let file = AgentConfig::from_str(
        "topics:\n  /probe/reliable: { no_drop: true }\n  /probe/fast: { priority: 10, policy: latest }\n  /pose: { priority: 8 }\n",
        "robot.yaml",
    )
    .unwrap();
    let c = first(&file, r#"{"topics": {"/pose": {"rate_limit_hz": 0.5}}}"#).unwrap();
    assert_eq!(c.config.topics["/probe/reliable"].no_drop, Some(true));
    assert_eq!(c.config.topics["/probe/fast"], file.topics["/probe/fast"]);
    assert_eq!(
        c.config.topics["/pose"].priority,
        Some(8.0),
        "its other fields stay"
    );
    assert_eq!(c.config.topics["/pose"].rate_limit_hz, Some(0.5));
    assert_eq!(c.kept.len(), 1, "{:?}", c.kept);
    // Kept and merged with the file at the next start: the same.
    let s = settle(&file, c.kept.clone());
    assert_eq!(s.config, c.config);
    assert!(s.set_aside.is_empty());
}

#[test]
fn removing_is_written_and_a_null_field_is_unset() {
    let cfg = running();
    let c = first(
        &cfg,
        "remove: { ros2: { publish: [/b] }, topics: [/a] }\nros2: { publish: [/c] }\n",
    )
    .unwrap();
    let r2 = c.config.ros2.as_ref().unwrap();
    assert_eq!(r2.publish.include, vec!["/a", "/c"]);
    assert!(!c.config.topics.contains_key("/a"));
    assert_eq!(c.fields, vec!["topics", "ros2.publish"]);
    assert_eq!(again(&cfg, &c), c.config);
    // Remove and set in one change: replaced whole.
    let c = first(
        &cfg,
        "remove: { topics: [/a] }\ntopics: { /a: { rate_limit_hz: 1 } }",
    )
    .unwrap();
    assert_eq!(c.config.topics["/a"].priority, None);
    assert_eq!(c.config.topics["/a"].rate_limit_hz, Some(1.0));
    // One field unset.
    let c = first(&cfg, "topics: { /a: { priority: null } }").unwrap();
    assert!(!c.config.topics.contains_key("/a"));
    assert_eq!(again(&cfg, &c), c.config);
    // Back to the file's value: no change in force any more.
    let back = then(&cfg, &c, "topics: { /a: { priority: 3 } }").unwrap();
    assert_eq!(back.config, cfg);
    assert!(back.kept.is_empty(), "{:?}", back.kept);
}

#[test]
fn no_change_turns_no_drop_on_or_off() {
    let file = AgentConfig::from_str(
        "topics:\n  /probe/reliable: { no_drop: true }\n  /x: { priority: 2 }\n",
        "robot.yaml",
    )
    .unwrap();
    for (text, topic, what) in [
        (
            "topics: { /probe/reliable: { no_drop: false } }",
            "/probe/reliable",
            "off",
        ),
        (
            "remove: { topics: [/probe/reliable] }",
            "/probe/reliable",
            "off",
        ),
        ("topics: { /x: { no_drop: true } }", "/x", "on"),
        ("topics: { /y: { no_drop: true } }", "/y", "on"),
        ("topics: { /map: { policy: latest } }", "/map", "by default"),
    ] {
        let e = first(&file, text).unwrap_err();
        let said = e.to_string();
        assert_eq!(
            e.field(),
            Some(format!("topics[{topic:?}].no_drop").as_str()),
            "{said}"
        );
        assert!(said.contains(topic) && said.contains("YAML file"), "{said}");
        assert!(
            what == "by default" && said.contains("by default") || said.contains(what),
            "{said}"
        );
        assert!(e.position().is_some(), "{said}");
    }
    // Writing the value the file gives is no change of it.
    first(
        &file,
        "topics: { /probe/reliable: { no_drop: true, queue: 64 } }",
    )
    .unwrap();
    // A kept change that would is set aside at start; the file's value runs.
    let mut turned_off = file.clone();
    turned_off
        .topics
        .get_mut("/probe/reliable")
        .unwrap()
        .no_drop = Some(false);
    let kept = kept::carry(&file, &turned_off, &[], "an older agent", 1);
    let s = settle(&file, kept);
    assert_eq!(s.config, file);
    assert_eq!(s.set_aside.len(), 1);
    assert!(s.set_aside[0].no_drop && s.set_aside[0].why.contains("/probe/reliable"));
}

#[test]
fn a_change_is_refused_with_the_files_error_text() {
    let cfg = running();
    let bad = "topics:\n  /a: { rate_limit_hz: 0 }\n";
    let from_change = first(&cfg, bad).unwrap_err();
    let from_file = AgentConfig::from_str(bad, "change").unwrap_err();
    assert_eq!(from_change.to_string(), from_file.to_string());
    assert!(
        from_change.to_string().starts_with("change:2:"),
        "{from_change}"
    );
    for text in [
        "topics:\n  /a: { rate_limit: 1 }\n",
        "ros2:\n  publish: [\"bad name\"]\n",
        "remap:\n  /a: not/a/topic\n",
    ] {
        let file = AgentConfig::from_str(&format!("ros2: {{}}\n{text}"), "change")
            .unwrap_err()
            .to_string();
        let changed = first(&cfg, &format!("ros2: {{}}\n{text}"))
            .unwrap_err()
            .to_string();
        assert_eq!(changed, file, "for {text:?}");
    }
}

#[test]
fn fields_that_need_a_restart_are_refused_by_name() {
    let cfg = running();
    let e = first(&cfg, "hub: ws://other:8080\n").unwrap_err();
    assert_eq!(e.field(), Some("hub"));
    assert!(e.to_string().contains("restart"), "{e}");
    let e = first(&cfg, "ros2: { domain_id: 3 }\n").unwrap_err();
    assert_eq!(e.field(), Some("ros2.domain_id"));
    let e = first(&cfg, "remove: { ros2: { domain_id: 3 } }\n").unwrap_err();
    assert_eq!(e.field(), Some("remove.ros2.domain_id"));
    let e = first(&cfg, "ros1: { publish: [/x] }\n").unwrap_err();
    assert!(e.to_string().contains("no ROS 1 bridge"), "{e}");
    let e = first(&cfg, "topcs: {}\n").unwrap_err();
    assert!(e.to_string().contains("unknown field `topcs`"), "{e}");
}

#[test]
fn changes_accumulate_and_keep_when_and_by_whom() {
    let cfg = running();
    let one = first(&cfg, "ros2: { subscribe: [/cmd] }").unwrap();
    let two = then(&cfg, &one, "{\"remap\": {\"/a\": \"/x/a\"}}").unwrap();
    assert_eq!(two.config.ros2.as_ref().unwrap().subscribe, vec!["/cmd"]);
    assert_eq!(two.config.remap.get("/a").map(String::as_str), Some("/x/a"));
    let by: Vec<(String, &str)> = two
        .kept
        .iter()
        .map(|k| (k.entry.to_string(), k.by.as_str()))
        .collect();
    assert_eq!(
        by,
        vec![
            ("remap[\"/a\"]".to_owned(), "user:bo"),
            ("ros2.subscribe /cmd".to_owned(), "user:ana"),
        ]
    );
    assert_eq!(again(&cfg, &two), two.config);
    // The same change again changes nothing, and keeps who made it.
    let three = then(&cfg, &two, "ros2: { subscribe: [/cmd] }").unwrap();
    assert_eq!(three.kept, two.kept);
}

proptest::proptest! {
    /// Whatever a change says, reading it never panics; a change that is taken gives a
    /// configuration that checks out, turns no topic's no_drop on or off, and that its
    /// changes in force, applied to the file's configuration, give again; one that is
    /// refused says why.
    #[test]
    fn any_change_is_taken_whole_or_refused_with_a_reason(
        entries in proptest::collection::vec(
            (
                proptest::sample::select(vec![
                    "remap", "subscribe", "topics", "ros2", "ros1", "hub", "name", "sim",
                    "ros2.publish", "ros2.subscribe", "ros2.services", "ros2.actions",
                    "ros2.read", "ros2.domain_id", "topics./a", "topics./a.rate_limit_hz",
                    "topics./a.priority", "topics./a.policy", "topics./a.no_drop", "remap./a",
                    "remove.topics", "remove.ros2.publish", "remove.remap", "remove",
                    "video", "video./a", "video./a.topic", "video./a.fps",
                    "video./a.bitrate_kbps", "video./a.min_bitrate_kbps", "remove.video",
                ]),
                proptest::sample::select(vec![
                    "[/a, /b]", "[]", "{}", "0", "2", "-1", "latest", "/x/a", "null", "true",
                    "{ include: [/a], exclude: [/b] }", "[{ hub: /h, local: /l }]",
                    "{ rate_limit_hz: 2 }", "\"bad name\"", "[1, 2]", "{ x: 1 }", "[/a]",
                    "{ topic: /a/video }", "{ topic: /v, fps: 5 }", "/a/video", "600",
                ]),
            ),
            0..5,
        )
    ) {
        let cfg = running();
        // Dotted keys become nested mappings, written in flow style.
        let mut doc = serde_json::Map::new();
        let mut text = String::new();
        for (key, value) in &entries {
            let mut parts: Vec<&str> = key.split('.').collect();
            if key.starts_with("topics./") || key.starts_with("remap./") || key.starts_with("video./") {
                let (section, rest) = key.split_once('.').unwrap();
                let mut p = vec![section];
                p.extend(rest.splitn(2, '.'));
                parts = p;
            }
            let mut line = String::new();
            for p in &parts[..parts.len() - 1] {
                line.push_str(&format!("{p}: {{ "));
            }
            line.push_str(&format!("{}: {value}", parts[parts.len() - 1]));
            for _ in 1..parts.len() {
                line.push_str(" }");
            }
            // One key once: a second would be a duplicate, which the parser refuses too.
            if doc.insert(parts[0].to_owned(), serde_json::Value::Null).is_none() {
                text.push_str(&line);
                text.push('\n');
            }
        }
        match first(&cfg, &text) {
            Ok(c) => {
                proptest::prop_assert!(c.config.validate().is_ok());
                proptest::prop_assert!(no_drop_flips(&cfg, &c.config).is_empty());
                let doc = serde_json::to_string(&change_doc(&c.kept)).unwrap();
                let again = first(&cfg, &doc);
                proptest::prop_assert!(again.is_ok(), "{:?} from {}", again, doc);
                proptest::prop_assert_eq!(&again.unwrap().config, &c.config);
                let s = settle(&cfg, c.kept.clone());
                proptest::prop_assert!(s.set_aside.is_empty(), "{:?}", s.set_aside);
                proptest::prop_assert_eq!(s.config, c.config);
            }
            Err(e) => {
                let said = e.to_string();
                proptest::prop_assert!(!said.is_empty() && (e.field().is_some() || e.position().is_some()), "{}", said);
            }
        }
    }
}

/// A camera's video stream changes field by field; a stream is added and removed whole;
/// the changes merge again with a file that changed meanwhile.
#[test]
fn video_streams_change_field_by_field_and_merge_again() {
    let file = AgentConfig::from_str(
        "video:\n  /cam/a: { topic: /cam/a/video, fps: 10 }\n  /cam/b: { topic: /cam/b/video }\n",
        "robot.yaml",
    )
    .unwrap();
    let c = first(&file, "video: { /cam/a: { bitrate_kbps: 400 } }\n").unwrap();
    assert_eq!(c.fields, vec!["video"]);
    let a = &c.config.video["/cam/a"];
    assert_eq!(
        (a.topic.as_str(), a.fps, a.bitrate_kbps),
        ("/cam/a/video", 10.0, 400)
    );
    assert_eq!(
        c.config.video["/cam/b"], file.video["/cam/b"],
        "/cam/b untouched"
    );
    assert_eq!(
        c.kept
            .iter()
            .map(|k| k.entry.to_string())
            .collect::<Vec<_>>(),
        vec![r#"video["/cam/a"].bitrate_kbps"#]
    );
    assert_eq!(again(&file, &c), c.config);

    // A new stream, and one removed; a field written null takes its default.
    let c = then(
        &file,
        &c,
        "video: { /cam/c: { topic: /cam/c/video, keyframe_s: 1 }, /cam/a: { fps: null } }\nremove: { video: [/cam/b] }\n",
    )
    .unwrap();
    assert_eq!(c.config.video["/cam/a"].fps, 15.0);
    assert_eq!(c.config.video["/cam/a"].bitrate_kbps, 400);
    assert!(!c.config.video.contains_key("/cam/b"));
    assert_eq!(c.config.video["/cam/c"].keyframe_s, 1.0);
    assert_eq!(again(&file, &c), c.config);

    // The file raises /cam/a's fps meanwhile: the kept bitrate still applies, and the
    // kept fps (the default, written by the change) is set aside as the file changed it.
    let newer = AgentConfig::from_str(
        "video:\n  /cam/a: { topic: /cam/a/video, fps: 20 }\n  /cam/b: { topic: /cam/b/video }\n",
        "robot.yaml",
    )
    .unwrap();
    let settled = settle(&newer, c.kept.clone());
    assert_eq!(settled.config.video["/cam/a"].bitrate_kbps, 400);
    assert_eq!(settled.config.video["/cam/a"].fps, 20.0);
    assert!(
        settled
            .set_aside
            .iter()
            .any(|a| a.kept.entry.to_string() == r#"video["/cam/a"].fps"#),
        "{:?}",
        settled.set_aside
    );
    assert!(!settled.config.video.contains_key("/cam/b"));
    assert!(settled.config.video.contains_key("/cam/c"));
}

#[test]
fn video_changes_are_checked_like_the_file() {
    let file =
        AgentConfig::from_str("video:\n  /cam/a: { topic: /cam/a/video }\n", "robot.yaml").unwrap();
    for (change, expected) in [
        (
            "video: { /cam/a: { fps: 0 } }\n",
            "video[\"/cam/a\"].fps: must be 1 to 60",
        ),
        (
            "video: { /cam/x: { fps: 5 } }\n",
            "/cam/x has no video stream to change; a new stream names its video topic",
        ),
        (
            "video: { /cam/b: { topic: /cam/a/video } }\n",
            "/cam/a/video is already the video of /cam/a",
        ),
        ("video: { /cam/a: { crf: 5 } }\n", "unknown field `crf`"),
    ] {
        let e = first(&file, change).expect_err(change).to_string();
        assert!(e.contains(expected), "{change}: {e}");
    }
}
