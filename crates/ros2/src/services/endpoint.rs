//! One service of a local server as this bridge calls it ([`Endpoint`]): a request
//! writer, a reply reader, and the waiting requests matched to their replies in the
//! server's [`Mapping`].
//!
//! Every call the bridge makes into the graph goes through one: exposed services and
//! actions ([`super::exposed`]) and nodes' parameter services ([`crate::params`]).

use std::collections::HashMap;
use std::sync::atomic::{AtomicI32, AtomicI64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use bytes::Bytes;
use futures::StreamExt;
use rustdds::{
    DataReaderStatus, DataWriterStatus, GUID, RTPSEntity, SampleIdentity, SequenceNumber,
    StatusEvented, WriteOptionsBuilder,
};
use tokio::sync::{Semaphore, oneshot};
use tokio::task::AbortHandle;

use crate::bridge::{Bridge, RawReader, RawWriter};
use crate::names;
use crate::qos;
use crate::raw::{RawCdr, RequestHeader};

/// How long a request waits for its server's request reader and reply writer to be
/// matched before it is sent (a volatile request, or its reply, written before matching
/// would be lost).
const MATCH_WAIT: Duration = Duration::from_secs(3);

/// How many requests one service of a local server has unanswered at once. A ROS 2
/// server's request reader keeps the last 10 requests (rmw's default service QoS): a
/// burst of more than that, arriving before the server takes them, would push the
/// oldest out unanswered. Further calls wait here, in order, for a reply to free a slot.
/// `get_result` is not limited: its requests wait for goals to end and are taken at once.
pub(crate) const IN_FLIGHT: usize = 10;

/// How a request and its reply are tied together, by the middleware of the other side.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Mapping {
    /// rmw_cyclonedds: a 16-byte header (client id, sequence number) before the fields.
    Cyclone,
    /// rmw_fastrtps (Fast DDS, ROS 2's default): no header; a request carries the GUID of
    /// the client's reply reader as its related sample identity, and the reply carries
    /// that GUID with the request's sequence number.
    FastDds,
}

impl Mapping {
    /// The mapping of the participant that owns `guid`, from its vendor id: RTPS
    /// implementations start their GUID prefixes with it, eProsima's being 01.0f.
    pub(crate) fn of(guid: GUID) -> Mapping {
        if guid.prefix.as_ref().starts_with(&[0x01, 0x0f]) {
            Mapping::FastDds
        } else {
            Mapping::Cyclone
        }
    }
}

/// One service of a local server, as this bridge calls it.
pub(crate) struct Endpoint {
    service: String,
    writer: RawWriter,
    mapping: Mapping,
    /// The reply reader's GUID (a Fast DDS server answers to it).
    reply_reader: GUID,
    client: u64,
    seq: AtomicI64,
    /// Readers matched to `writer` (the server's), from the writer's status events.
    matched: AtomicI32,
    /// Writers matched to the reply reader (the server's), from the reader's events: a
    /// reply written before its writer is matched with this reader would be lost.
    reply_matched: AtomicI32,
    waiting: Mutex<HashMap<i64, oneshot::Sender<Bytes>>>,
    /// Unanswered requests allowed at once ([`IN_FLIGHT`]); `None`: no limit.
    slots: Option<Semaphore>,
}

impl Endpoint {
    pub(super) fn new(
        bridge: &Bridge,
        service: &str,
        type_base: &str,
        client: u64,
        limited: bool,
        mapping: Mapping,
    ) -> Result<(Arc<Endpoint>, RawReader), String> {
        let dds = |suffix: &str| {
            names::dds_type(&format!("{type_base}{suffix}"))
                .ok_or_else(|| format!("{type_base} is not a ROS type name"))
        };
        let writer = bridge.writer(
            &names::request_topic(service),
            &dds("_Request")?,
            qos::service(),
        )?;
        let reader = bridge.reader(
            &names::reply_topic(service),
            &dds("_Response")?,
            qos::service(),
        )?;
        Ok((
            Arc::new(Endpoint {
                service: service.to_owned(),
                writer,
                mapping,
                reply_reader: reader.guid(),
                client,
                seq: AtomicI64::new(0),
                matched: AtomicI32::new(0),
                reply_matched: AtomicI32::new(0),
                waiting: Mutex::new(HashMap::new()),
                slots: limited.then(|| Semaphore::new(IN_FLIGHT)),
            }),
            reader,
        ))
    }

    /// An endpoint of this bridge for `service` of a local server (type `type_base`,
    /// in `mapping`), at most [`IN_FLIGHT`] requests unanswered, its replies read by a
    /// task of its own.
    pub(crate) fn start(
        bridge: &Bridge,
        service: &str,
        type_base: &str,
        mapping: Mapping,
    ) -> Result<(Arc<Endpoint>, AbortHandle), String> {
        let (call, reader) =
            Endpoint::new(bridge, service, type_base, client_id(bridge), true, mapping)?;
        let task = tokio::spawn(call.clone().pump(reader)).abort_handle();
        Ok((call, task))
    }

    /// Sends `msg` (a CDR request message) and waits for the reply message.
    pub(crate) async fn request(&self, msg: Bytes) -> Result<Bytes, String> {
        // Held until the reply came or the call ended (timeout, cancel: dropped).
        let _slot = match &self.slots {
            Some(s) => Some(
                s.acquire()
                    .await
                    .map_err(|_| "the bridge is closing".to_owned())?,
            ),
            None => None,
        };
        let started = Instant::now();
        while !(self.server_matched() && self.reply_matched.load(Relaxed) > 0) {
            if started.elapsed() > MATCH_WAIT {
                return Err(format!(
                    "the server of {} is not reachable over DDS",
                    self.service
                ));
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
        let (tx, rx) = oneshot::channel();
        let seq = match self.mapping {
            Mapping::Cyclone => {
                let seq = self.seq.fetch_add(1, Relaxed) + 1;
                self.lock().insert(seq, tx);
                let header = RequestHeader {
                    client: self.client,
                    seq,
                };
                if let Err(e) = self.writer.write(RawCdr(header.prepend(&msg)), None) {
                    self.lock().remove(&seq);
                    return Err(format!("sending a request to {}: {e:?}", self.service));
                }
                seq
            }
            Mapping::FastDds => {
                // The request's sequence number is known once it is written, and its
                // reply could be read before that: the table stays locked meanwhile.
                let mut waiting = self.lock();
                let to = SampleIdentity {
                    writer_guid: self.reply_reader,
                    sequence_number: SequenceNumber::default(),
                };
                let options = WriteOptionsBuilder::new()
                    .related_sample_identity(to)
                    .build();
                match self.writer.write_with_options(RawCdr(msg), options) {
                    Ok(id) => {
                        let seq = i64::from(id.sequence_number);
                        waiting.insert(seq, tx);
                        seq
                    }
                    Err(e) => {
                        return Err(format!("sending a request to {}: {e:?}", self.service));
                    }
                }
            }
        };
        let forget = Forget(self, seq);
        let reply = rx.await.map_err(|_| format!("{} went away", self.service));
        drop(forget);
        reply
    }

    /// True once the server's request reader is matched with this endpoint's writer.
    fn server_matched(&self) -> bool {
        while let Some(ev) = self.writer.try_recv_status() {
            if let DataWriterStatus::PublicationMatched { current, .. } = ev {
                self.matched.store(current.count(), Relaxed);
            }
        }
        self.matched.load(Relaxed) > 0
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, HashMap<i64, oneshot::Sender<Bytes>>> {
        self.waiting.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Hands replies meant for this bridge to their waiting requests, and follows which
    /// writers the reply reader is matched with.
    pub(super) async fn pump(self: Arc<Self>, reader: RawReader) {
        let mut samples = reader.async_sample_stream();
        let mut events = samples.async_event_stream();
        let own = [self.reply_reader, self.writer.guid()];
        loop {
            let r = tokio::select! {
                r = samples.next() => match r {
                    Some(r) => r,
                    None => return,
                },
                Some(ev) = events.next() => {
                    if let DataReaderStatus::SubscriptionMatched { current, .. } = ev {
                        self.reply_matched.store(current.count(), Relaxed);
                    }
                    continue;
                }
            };
            let Ok(sample) = r else { continue };
            if self.mapping == Mapping::FastDds {
                // Ours when the reply names this endpoint's reader (or writer).
                let Some(to) = sample.sample_info().related_sample_identity() else {
                    continue;
                };
                if !own.contains(&to.writer_guid) {
                    continue;
                }
                let seq = i64::from(to.sequence_number);
                if let Some(tx) = self.lock().remove(&seq) {
                    let _ = tx.send(sample.into_value().0);
                }
                continue;
            }
            let raw = sample.into_value().0;
            let Some(h) = RequestHeader::read(&raw) else {
                continue;
            };
            if h.client != self.client {
                continue; // another client's reply
            }
            if let (Some(tx), Some(msg)) = (self.lock().remove(&h.seq), RequestHeader::strip(&raw))
            {
                let _ = tx.send(msg);
            }
        }
    }
}

/// Removes a request's waiter when the request is dropped (timeout, cancel).
struct Forget<'a>(&'a Endpoint, i64);

impl Drop for Forget<'_> {
    fn drop(&mut self) {
        self.0.lock().remove(&self.1);
    }
}

/// This bridge's client id in request headers: from its participant's GUID, so two agents
/// on one graph never read each other's replies.
pub(super) fn client_id(bridge: &Bridge) -> u64 {
    let p = bridge.own.prefix.as_ref();
    let mut b = [0u8; 8];
    b.copy_from_slice(&p[4..12]);
    u64::from_le_bytes(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn guid(prefix: [u8; 2]) -> GUID {
        let mut b = [0x5a; 16];
        b[..2].copy_from_slice(&prefix);
        GUID::from_bytes(b)
    }

    #[test]
    fn the_request_mapping_follows_the_vendor_in_the_guid() {
        assert_eq!(Mapping::of(guid([0x01, 0x0f])), Mapping::FastDds); // eProsima
        assert_eq!(Mapping::of(guid([0x01, 0x10])), Mapping::Cyclone); // Eclipse Cyclone
        assert_eq!(Mapping::of(guid([0x01, 0x12])), Mapping::Cyclone); // rustdds
        assert_eq!(Mapping::of(GUID::GUID_UNKNOWN), Mapping::Cyclone);
    }
}
