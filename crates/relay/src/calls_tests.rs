use super::*;

/// A peer that records what the table tells it.
#[derive(Default)]
struct Rec {
    calls: Mutex<Vec<CallRequest>>,
    cancels: Mutex<Vec<CallId>>,
    events: Mutex<Vec<CallEvent>>,
    changes: Mutex<Vec<(bool, String)>>,
}

impl CallPeer for Rec {
    fn deliver_call(&self, call: CallRequest) {
        self.calls.lock().unwrap().push(call);
    }
    fn deliver_cancel(&self, id: CallId) {
        self.cancels.lock().unwrap().push(id);
    }
    fn deliver_event(&self, event: CallEvent) {
        self.events.lock().unwrap().push(event);
    }
    fn service_changed(&self, change: ServiceChange) {
        let c = match change {
            ServiceChange::Added(s) => (true, s.name.to_string()),
            ServiceChange::Removed(s) => (false, s.name.to_string()),
        };
        self.changes.lock().unwrap().push(c);
    }
}

impl Rec {
    fn done(&self) -> Vec<(CallId, CallStatus, String)> {
        self.events
            .lock()
            .unwrap()
            .iter()
            .filter_map(|e| match e {
                CallEvent::Done {
                    id, status, text, ..
                } => Some((*id, *status, text.clone())),
                CallEvent::Feedback { .. } => None,
            })
            .collect()
    }
}

fn name(s: &str) -> TopicName {
    TopicName::parse(s).unwrap()
}

fn json(s: &str) -> Payload {
    Payload::json(s.as_bytes().to_vec())
}

struct Setup {
    calls: Calls,
    provider: Arc<Rec>,
    caller: Arc<Rec>,
}

const P: ClientId = ClientId(1);
const C: ClientId = ClientId(2);

fn setup(limits: CallLimits) -> Setup {
    let calls = Calls::new(limits);
    let (provider, caller) = (Arc::new(Rec::default()), Arc::new(Rec::default()));
    calls.attach(P, provider.clone());
    calls.attach(C, caller.clone());
    calls.advertise(
        P,
        name("/r1/set_mode"),
        Schema::named("std_srvs/srv/SetBool"),
        false,
    );
    calls.advertise(P, name("/r1/nav"), Schema::named("x/action/Nav"), true);
    Setup {
        calls,
        provider,
        caller,
    }
}

#[test]
fn each_concurrent_call_is_answered_to_its_own_caller() {
    let s = setup(CallLimits::default());
    let ids: Vec<CallId> = (0..50)
        .map(|i| {
            let args = json(&format!("{{\"data\":{i}}}"));
            s.calls
                .call(C, &name("/r1/set_mode"), args, CallOptions::default())
                .unwrap()
        })
        .collect();
    assert_eq!(s.provider.calls.lock().unwrap().len(), 50);
    // The provider answers in reverse order, echoing each request.
    let reqs: Vec<CallRequest> = s.provider.calls.lock().unwrap().drain(..).rev().collect();
    for r in reqs {
        assert!(s.calls.respond(
            P,
            r.id,
            CallStatus::Ok,
            Some(r.payload.clone()),
            String::new()
        ));
    }
    let events = s.caller.events.lock().unwrap();
    assert_eq!(events.len(), 50);
    for e in events.iter() {
        let CallEvent::Done {
            id,
            status,
            payload,
            ..
        } = e
        else {
            panic!("feedback for a service call")
        };
        assert_eq!(*status, CallStatus::Ok);
        let i = ids.iter().position(|x| x == id).unwrap();
        assert_eq!(payload.as_ref().unwrap().bytes, format!("{{\"data\":{i}}}"));
    }
    assert_eq!(s.calls.bookkeeping(), 0, "nothing outlives a call");
}

#[test]
fn unknown_services_and_wrong_kinds_are_refused_with_the_reason() {
    let s = setup(CallLimits::default());
    let e = s
        .calls
        .call(C, &name("/nope"), json("{}"), CallOptions::default())
        .unwrap_err();
    assert_eq!(e.status, CallStatus::NoProvider);
    assert!(e.text.contains("/nope"), "{}", e.text);
    let e = s
        .calls
        .call(C, &name("/r1/nav"), json("{}"), CallOptions::default())
        .unwrap_err();
    assert!(e.text.contains("send_action_goal"), "{}", e.text);
    let goal = CallOptions {
        goal: true,
        ..CallOptions::default()
    };
    let e = s
        .calls
        .call(C, &name("/r1/set_mode"), json("{}"), goal)
        .unwrap_err();
    assert!(e.text.contains("call_service"), "{}", e.text);
    assert_eq!(s.calls.bookkeeping(), 0);
}

#[test]
fn a_late_or_foreign_answer_is_rejected_and_changes_nothing() {
    let s = setup(CallLimits::default());
    let id = s
        .calls
        .call(C, &name("/r1/set_mode"), json("{}"), CallOptions::default())
        .unwrap();
    assert!(!s.calls.respond(C, id, CallStatus::Ok, None, String::new()));
    assert!(
        !s.calls
            .respond(P, id + 100, CallStatus::Ok, None, String::new())
    );
    assert_eq!(s.calls.pending(), 1);
    assert!(s.calls.respond(P, id, CallStatus::Ok, None, String::new()));
    assert!(!s.calls.respond(P, id, CallStatus::Ok, None, String::new()));
    assert_eq!(s.caller.done().len(), 1);
}

#[test]
fn the_deadline_answers_timeout_and_tells_the_provider_to_stop() {
    let s = setup(CallLimits::default());
    let opts = CallOptions {
        timeout: Some(Duration::from_millis(100)),
        ..CallOptions::default()
    };
    let id = s
        .calls
        .call(C, &name("/r1/set_mode"), json("{}"), opts)
        .unwrap();
    let t0 = Instant::now();
    assert!(s.calls.expire(t0).is_some(), "a deadline is pending");
    assert!(s.caller.done().is_empty());
    assert_eq!(s.calls.expire(t0 + Duration::from_millis(150)), None);
    let done = s.caller.done();
    assert_eq!(done.len(), 1);
    assert_eq!((done[0].0, done[0].1), (id, CallStatus::Timeout));
    assert!(done[0].2.contains("/r1/set_mode"), "{}", done[0].2);
    assert_eq!(*s.provider.cancels.lock().unwrap(), vec![id]);
    // A provider answering after the deadline is ignored.
    assert!(!s.calls.respond(P, id, CallStatus::Ok, None, String::new()));
    assert_eq!(s.calls.bookkeeping(), 0);
}

#[test]
fn a_provider_leaving_fails_its_pending_calls_at_once() {
    let s = setup(CallLimits::default());
    let watcher = Arc::new(Rec::default());
    s.calls.attach(ClientId(3), watcher.clone());
    s.calls.watch(ClientId(3), Regex::new("^/r1/.*$").unwrap());
    for _ in 0..3 {
        s.calls
            .call(C, &name("/r1/set_mode"), json("{}"), CallOptions::default())
            .unwrap();
    }
    s.calls.detach(P);
    let done = s.caller.done();
    assert_eq!(done.len(), 3);
    assert!(done.iter().all(|d| d.1 == CallStatus::NoProvider));
    assert!(done[0].2.contains("went away"), "{}", done[0].2);
    assert!(s.calls.services().is_empty());
    let changes = watcher.changes.lock().unwrap().clone();
    assert_eq!(changes.iter().filter(|c| c.0).count(), 2);
    assert_eq!(changes.iter().filter(|c| !c.0).count(), 2);
    assert_eq!(s.calls.bookkeeping(), 0);
}

#[test]
fn a_caller_leaving_cancels_its_calls_at_their_providers() {
    let s = setup(CallLimits::default());
    let goal = CallOptions {
        goal: true,
        ..CallOptions::default()
    };
    let id = s.calls.call(C, &name("/r1/nav"), json("{}"), goal).unwrap();
    s.calls.detach(C);
    assert_eq!(*s.provider.cancels.lock().unwrap(), vec![id]);
    assert_eq!(s.calls.bookkeeping(), 0);
}

#[test]
fn pending_calls_are_bounded_per_caller_and_per_provider() {
    let limits = CallLimits {
        max_pending_per_caller: 2,
        max_pending_per_provider: 3,
        ..CallLimits::default()
    };
    let s = setup(limits);
    let svc = name("/r1/set_mode");
    for _ in 0..2 {
        s.calls
            .call(C, &svc, json("{}"), CallOptions::default())
            .unwrap();
    }
    let e = s
        .calls
        .call(C, &svc, json("{}"), CallOptions::default())
        .unwrap_err();
    assert_eq!(e.status, CallStatus::Busy);
    assert!(e.text.contains("limit per caller"), "{}", e.text);
    let other = ClientId(9);
    s.calls.attach(other, Arc::new(Rec::default()));
    s.calls
        .call(other, &svc, json("{}"), CallOptions::default())
        .unwrap();
    let e = s
        .calls
        .call(other, &svc, json("{}"), CallOptions::default())
        .unwrap_err();
    assert!(e.text.contains("limit per provider"), "{}", e.text);
}

#[test]
fn a_cancelled_service_call_ends_at_once() {
    let s = setup(CallLimits::default());
    let id = s
        .calls
        .call(C, &name("/r1/set_mode"), json("{}"), CallOptions::default())
        .unwrap();
    assert!(
        !s.calls.cancel(ClientId(7), id),
        "only the caller may cancel"
    );
    assert!(s.calls.cancel(C, id));
    assert_eq!(s.caller.done()[0].1, CallStatus::Cancelled);
    assert_eq!(*s.provider.cancels.lock().unwrap(), vec![id]);
    assert_eq!(s.calls.bookkeeping(), 0);
}

#[test]
fn a_cancelled_goal_waits_for_its_provider_within_the_grace_period() {
    let s = setup(CallLimits {
        cancel_grace: Duration::from_millis(50),
        ..CallLimits::default()
    });
    let goal = CallOptions {
        goal: true,
        ..CallOptions::default()
    };
    let id = s.calls.call(C, &name("/r1/nav"), json("{}"), goal).unwrap();
    assert!(s.provider.calls.lock().unwrap()[0].goal_id.is_some());
    assert!(
        s.calls
            .feedback(P, id, json("{\"distance_remaining\":3.0}"))
    );
    assert!(s.calls.cancel(C, id));
    assert!(
        s.caller.done().is_empty(),
        "the provider confirms a goal's end"
    );
    assert!(
        s.calls.feedback(P, id, json("{}")),
        "feedback may still come"
    );
    assert!(s.calls.respond(
        P,
        id,
        CallStatus::Cancelled,
        Some(json("{}")),
        String::new()
    ));
    assert_eq!(s.caller.done()[0].1, CallStatus::Cancelled);
    // A second goal whose provider never confirms: the grace period ends it.
    let goal = CallOptions {
        goal: true,
        ..CallOptions::default()
    };
    let id2 = s.calls.call(C, &name("/r1/nav"), json("{}"), goal).unwrap();
    s.calls.cancel(C, id2);
    s.calls.expire(Instant::now() + Duration::from_millis(100));
    let done = s.caller.done();
    assert_eq!((done[1].0, done[1].1), (id2, CallStatus::Cancelled));
    assert!(done[1].2.contains("did not confirm"), "{}", done[1].2);
    assert_eq!(s.calls.bookkeeping(), 0);
}

#[test]
fn watchers_see_existing_and_new_services_but_not_their_own() {
    let s = setup(CallLimits::default());
    s.calls.watch(P, Regex::new(".*").unwrap());
    assert!(s.provider.changes.lock().unwrap().is_empty(), "its own");
    s.calls.watch(C, Regex::new(".*").unwrap());
    assert_eq!(s.caller.changes.lock().unwrap().len(), 2);
    s.calls
        .advertise(C, name("/cloud/plan"), Schema::named("x/srv/Plan"), false);
    let pc = s.provider.changes.lock().unwrap().clone();
    assert_eq!(pc, vec![(true, "/cloud/plan".to_owned())]);
    assert!(s.calls.unadvertise(C, &name("/cloud/plan")));
    assert!(!s.calls.unadvertise(P, &name("/cloud/plan")));
    assert_eq!(s.provider.changes.lock().unwrap().len(), 2);
}

#[test]
fn a_new_provider_takes_a_name_over() {
    let s = setup(CallLimits::default());
    let newer = Arc::new(Rec::default());
    s.calls.attach(ClientId(5), newer.clone());
    let prev = s.calls.advertise(
        ClientId(5),
        name("/r1/set_mode"),
        Schema::named("std_srvs/srv/SetBool"),
        false,
    );
    assert_eq!(prev, Some(P));
    s.calls
        .call(C, &name("/r1/set_mode"), json("{}"), CallOptions::default())
        .unwrap();
    assert_eq!(newer.calls.lock().unwrap().len(), 1);
    assert!(!s.calls.unadvertise(P, &name("/r1/set_mode")));
}

#[test]
fn a_hundred_thousand_calls_leave_no_state_behind() {
    let s = setup(CallLimits::default());
    let svc = name("/r1/set_mode");
    for i in 0..100_000u64 {
        let id = s
            .calls
            .call(C, &svc, json("{}"), CallOptions::default())
            .unwrap();
        let req = s.provider.calls.lock().unwrap().pop().unwrap();
        assert_eq!(req.id, id);
        if i % 3 == 0 {
            s.calls.cancel(C, id);
        } else {
            s.calls.respond(P, id, CallStatus::Ok, None, String::new());
        }
        s.caller.events.lock().unwrap().clear();
        s.provider.cancels.lock().unwrap().clear();
    }
    assert_eq!(s.calls.bookkeeping(), 0);
    // Deadlines of ended calls are dropped lazily, but never pile up.
    assert!(
        s.calls.deadline_entries() <= 1024,
        "{}",
        s.calls.deadline_entries()
    );
    s.calls.expire(Instant::now() + Duration::from_secs(60));
    assert_eq!(s.calls.deadline_entries(), 0);
}

#[test]
fn goal_ids_are_version_4_uuids() {
    let a = new_goal_id();
    assert_ne!(a, new_goal_id());
    let t = goal_id_text(&a);
    assert_eq!(t.len(), 36);
    assert_eq!(&t[14..15], "4");
}
