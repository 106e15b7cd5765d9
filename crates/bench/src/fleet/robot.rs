//! A simulated robot of the fleet: its connection and announcements, its publishing
//! schedule and interest, its pings; and the start of the whole fleet of them.

use std::net::IpAddr;
use std::sync::atomic::Ordering::Relaxed;
use std::time::Duration;

use anyhow::bail;
use bytes::{Bytes, BytesMut};
use fleetlink_proto::frame::{self, Frame, Level};
use fleetlink_proto::{Encoding, Schema};
use fleetlink_relay::link::LinkEvent;
use fleetlink_relay::unix_nanos;
use futures_util::{SinkExt, StreamExt};
use tokio::sync::mpsc;
use tokio::task::JoinSet;
use tokio::time::Instant;
use tokio_tungstenite::tungstenite::Message as WsMessage;

use super::args::Args;
use super::clients::{
    Crew, Phase, RobotSent, connect_retrying, heartbeat_of, robot_name, source_for, topic_name,
};
use crate::conn::{BARRIER_PING, Ws, pong, put_ping};

/// Type the fleet's topics are announced with; the hub never looks inside.
const FLEET_TYPE: &str = "fleetlink_bench/msg/Blob";

/// Starts every robot (robot `i` on hub `i mod H`) and waits until each has announced
/// its topics. Returns their tasks and the channel on which each reports what it sent
/// once its schedule is over.
pub async fn start_all(
    args: &Args,
    urls: &[String],
    crew: &Crew,
) -> anyhow::Result<(JoinSet<()>, mpsc::UnboundedReceiver<(usize, RobotSent)>)> {
    let payload = Bytes::from(vec![0x5a; args.size]);
    let mut robots = JoinSet::new();
    let (up_tx, mut up_rx) = mpsc::unbounded_channel::<anyhow::Result<()>>();
    let (done_tx, done_rx) = mpsc::unbounded_channel::<(usize, RobotSent)>();
    for i in 0..args.robots {
        let url = urls[i % urls.len()].clone();
        let plan = RobotPlan {
            probe: (args.probe_ms > 0).then(|| Duration::from_millis(args.probe_ms)),
            index: i,
            topics: args.topics,
            source: source_for(&url, i),
            url,
            token: args.token.clone(),
            payload: payload.clone(),
            phase: phase_of(i),
        };
        robots.spawn(robot(plan, crew.clone(), up_tx.clone(), done_tx.clone()));
    }
    drop((up_tx, done_tx));
    for _ in 0..args.robots {
        match up_rx.recv().await {
            Some(Ok(())) => {}
            Some(Err(e)) => return Err(e),
            None => bail!("the robots' tasks ended before the fleet was up"),
        }
    }
    Ok((robots, done_rx))
}

/// A fraction in [0, 1) for robot `i`, spread evenly (golden ratio): its phase within the
/// message period, so robots do not publish in step.
fn phase_of(i: usize) -> f64 {
    (i as f64 * 0.618_033_988_749_895).fract()
}

struct RobotPlan {
    /// Ping period when shorter than the heartbeat (the agent's probes).
    probe: Option<Duration>,
    index: usize,
    topics: usize,
    url: String,
    source: Option<IpAddr>,
    token: String,
    payload: Bytes,
    phase: f64,
}

/// One robot from connection until the bench stops. Reports on `up` once its topics are
/// announced (or why it could not connect), and on `done` what it sent in the window once
/// its schedule is over.
///
/// One task owns the robot's WebSocket: it reads (interest, pings) and writes (messages
/// when due, keepalive pings) in turn, with one timer re-armed in place. A robot costs
/// the bench no lock shared with the other robots on its hot path: it reads the phase
/// when it wakes (at least every keepalive), it is never woken by a change of it.
async fn robot(
    plan: RobotPlan,
    crew: Crew,
    up: mpsc::UnboundedSender<anyhow::Result<()>>,
    done: mpsc::UnboundedSender<(usize, RobotSent)>,
) {
    let Crew {
        admission,
        deadline,
        counters,
        schedule,
        stop,
    } = crew;
    let name = robot_name(plan.index);
    let c = match connect_retrying(
        &plan.url,
        &name,
        &plan.token,
        plan.source,
        &admission,
        &counters,
        deadline,
    )
    .await
    {
        Ok(c) => c,
        Err(e) => {
            let _ = up.send(Err(e));
            return;
        }
    };
    let heartbeat = heartbeat_of(&c);
    // While it publishes, a robot pings as often as the agent's estimator probes.
    let busy_ping = heartbeat.min(plan.probe.unwrap_or(Duration::MAX));
    let mut r = Robot {
        ws: c.ws,
        link: c.link,
        wanted: 0,
        buf: BytesMut::new(),
        keepalive: heartbeat,
        next_ping: Instant::now() + heartbeat,
        ping_id: 0,
    };
    match tokio::time::timeout(Duration::from_secs(30), r.announce(&plan)).await {
        Ok(Ok(())) => {}
        Ok(Err(e)) => {
            let _ = up.send(Err(e.context(format!("{name}: announcing topics"))));
            return;
        }
        Err(_) => {
            let _ = up.send(Err(anyhow::anyhow!(
                "{name}: no answer from the hub to its topic announcements in 30 s"
            )));
            return;
        }
    }
    counters.connected.fetch_add(1, Relaxed);
    let _ = up.send(Ok(()));
    drop(up);

    let mut sent: RobotSent = vec![0; plan.topics];
    let mut m: u64 = 0;
    let mut reported = false;
    let cancelled = stop.cancelled();
    tokio::pin!(cancelled);
    let timer = tokio::time::sleep_until(r.next_ping);
    tokio::pin!(timer);
    let ok = loop {
        let phase = *schedule.borrow();
        let next_msg = match phase {
            Phase::Publish(s) => {
                Some(s.start + s.step.mul_f64(plan.phase + m as f64)).filter(|at| *at < s.end)
            }
            Phase::Wait | Phase::Done => None,
        };
        let over = match phase {
            Phase::Publish(s) => next_msg.is_none() || Instant::now() >= s.end,
            Phase::Done => true,
            Phase::Wait => false,
        };
        r.keepalive = if next_msg.is_some() {
            busy_ping
        } else {
            heartbeat
        };
        if !reported && over {
            // The schedule is over (or there was none): report, keep the link up.
            reported = true;
            let _ = done.send((plan.index, std::mem::take(&mut sent)));
        }
        timer
            .as_mut()
            .reset(next_msg.map_or(r.next_ping, |at| at.min(r.next_ping)));
        tokio::select! {
            biased;
            _ = &mut cancelled => return,
            m = r.ws.next() => match m {
                Some(Ok(WsMessage::Binary(b))) => {
                    r.on_hub(&b);
                }
                Some(Ok(_)) => {}
                _ => break false,
            },
            _ = &mut timer => {}
        }
        let now = Instant::now();
        if let (Phase::Publish(s), Some(_)) = (phase, next_msg) {
            let stamp = unix_nanos();
            let mut n = 0;
            loop {
                let at = s.start + s.step.mul_f64(plan.phase + m as f64);
                if at > now || at >= s.end {
                    break;
                }
                let k = (m % plan.topics as u64) as usize;
                if r.wanted & (1 << k) != 0 {
                    let seq = m / plan.topics as u64;
                    frame::encode_message(&mut r.buf, k as u32 + 1, seq, stamp, &plan.payload);
                    n += 1;
                    if s.window.contains(stamp) {
                        sent[k] += 1;
                    }
                }
                m += 1;
            }
            if n > 0 {
                counters.sent.fetch_add(n, Relaxed);
            }
        }
        if now >= r.next_ping {
            r.ping();
        }
        if !r.buf.is_empty() {
            let out = r.buf.split().freeze();
            if r.ws.send(WsMessage::Binary(out)).await.is_err() {
                break false;
            }
        }
    };
    if !ok && !stop.is_cancelled() {
        counters.lost.fetch_add(1, Relaxed);
        eprintln!("bench: {name} lost its link to the hub");
    }
}

/// A simulated robot's link.
struct Robot {
    ws: Ws,
    link: fleetlink_relay::link::LinkIn,
    /// Bit k: the hub wants topic k (alias k + 1).
    wanted: u64,
    /// What goes out with the next write.
    buf: BytesMut,
    keepalive: Duration,
    next_ping: Instant,
    ping_id: u64,
}

impl Robot {
    /// Sends the `ADVERTISE`s and a barrier `PING`, and reads until its `PONG`.
    async fn announce(&mut self, plan: &RobotPlan) -> anyhow::Result<()> {
        for k in 0..plan.topics {
            Frame::Advertise {
                alias: k as u32 + 1,
                topic: topic_name(plan.index, k),
                schema: Schema {
                    type_name: FLEET_TYPE.into(),
                    encoding: "ros2msg".into(),
                    text: "uint8[] data\n".into(),
                },
                encoding: Encoding::Cdr,
                flags: 0,
            }
            .encode(&mut self.buf);
        }
        Frame::Ping {
            id: BARRIER_PING,
            sent_ns: unix_nanos(),
        }
        .encode(&mut self.buf);
        let out = self.buf.split().freeze();
        self.ws.send(WsMessage::Binary(out)).await?;
        loop {
            let Some(m) = self.ws.next().await else {
                bail!("the hub closed the link");
            };
            let WsMessage::Binary(b) = m? else { continue };
            if self.on_hub(&b) {
                break;
            }
        }
        if !self.buf.is_empty() {
            let out = self.buf.split().freeze();
            self.ws.send(WsMessage::Binary(out)).await?;
        }
        Ok(())
    }

    /// Handles what the hub sent: interest, pings (answered with the next write), errors.
    /// True when it held the announcement barrier's `PONG`.
    fn on_hub(&mut self, b: &Bytes) -> bool {
        let mut barrier = false;
        for f in fleetlink_proto::frame::frames(b) {
            let Ok(f) = f else { break };
            match self.link.on_frame(f) {
                Ok(LinkEvent::Control(Frame::Interest { alias, wanted })) => {
                    if let Some(bit) = alias.checked_sub(1).filter(|b| *b < 64) {
                        if wanted {
                            self.wanted |= 1 << bit;
                        } else {
                            self.wanted &= !(1 << bit);
                        }
                    }
                }
                Ok(LinkEvent::Control(Frame::Pong { id, .. })) if id == BARRIER_PING => {
                    barrier = true;
                }
                Ok(LinkEvent::Control(Frame::Ping { id, sent_ns })) => {
                    self.buf.extend_from_slice(&pong(id, sent_ns));
                }
                Ok(LinkEvent::Control(Frame::Status { level, text, .. }))
                    if level != Level::Info =>
                {
                    eprintln!("bench: hub to robot: {text}");
                }
                _ => {}
            }
        }
        self.link.unacked = 0;
        barrier
    }

    fn ping(&mut self) {
        self.ping_id += 1;
        put_ping(&mut self.buf, self.ping_id);
        self.next_ping = Instant::now() + self.keepalive;
    }
}
