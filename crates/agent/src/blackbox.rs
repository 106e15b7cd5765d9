//! The robot's black box (`blackbox:` in the agent's YAML): the ring of chosen local
//! topics on disk ([`fleetlink_record::blackbox::ring`]), and the fetch service through
//! which the hub asks for a slice of it.
//!
//! A fetch call names a slice (the hub's recording id), its time range and topics, and a
//! window of bytes. The first call for a slice finishes the open segment, cuts the slice
//! into `slices/<id>.mcap` (with `<id>.json` describing it) and answers with its size and
//! SHA-256; later calls reuse that file, so a fetch resumed after a blackout, or after the
//! agent restarted, reads the same bytes. Each call queues its window as pieces on the
//! data topic, which the uplink sends below every live topic ([`data_qos`]).

use std::path::{Path, PathBuf};
use std::sync::Arc;

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_qos::{Policy, TopicQos};
use fleetlink_record::blackbox::ring::{Ring, RingOptions};
use fleetlink_record::blackbox::{
    self as bb, DATA_TOPIC, FETCH_SERVICE, FETCH_TYPE, FetchReply, FetchRequest, PIECE_BYTES,
    PIECE_DEFINITION, PIECE_TYPE, Piece,
};
use fleetlink_relay::calls::{CallRequest, CallStatus, ChannelPeer, PeerMsg};
use fleetlink_relay::{ClientId, ClientKind, Router, Topic, TopicName};
use tokio_util::sync::CancellationToken;

/// Slices kept on the robot; cutting a new one deletes the oldest past this.
const KEEP_SLICES: usize = 4;

/// The uplink's QoS of the data topic: lowest priority of the defaults (live topics start
/// at 1), FIFO so a window goes in order, a queue that holds more than one window, sent
/// without waiting for the hub's interest (pieces exist only because the hub asked), and
/// not compressed again (the slice is zstd already).
pub fn data_qos() -> TopicQos {
    TopicQos {
        priority: 0.25,
        policy: Policy::Fifo,
        queue: 64,
        always: true,
        compression: fleetlink_qos::Compression::None,
        ..TopicQos::default()
    }
}

/// Runs the black box until `shutdown`: the ring, and the fetch service.
pub async fn serve(opts: RingOptions, router: Arc<Router>, shutdown: CancellationToken) {
    let slices = opts.dir.join("slices");
    let ring = match Ring::start(router.clone(), opts, tokio::runtime::Handle::current()) {
        Ok(r) => r,
        Err(e) => {
            tracing::error!("black box: {e}");
            return;
        }
    };
    if let Err(e) = std::fs::create_dir_all(&slices) {
        tracing::error!("black box: cannot create {}: {e}", slices.display());
    }
    let (client, _) = router.connect(
        ClientKind::Internal {
            role: "blackbox".into(),
        },
        None,
    );
    let data_name = TopicName::parse(DATA_TOPIC).expect("a constant name");
    let schema = Schema {
        type_name: PIECE_TYPE.into(),
        encoding: "ros2msg".into(),
        text: PIECE_DEFINITION.into(),
    };
    let data = match router.advertise(client, &data_name, schema, false) {
        Ok(t) => t,
        Err(e) => {
            tracing::error!("black box: cannot advertise {DATA_TOPIC}: {e}");
            router.disconnect(client);
            ring.stop().await;
            return;
        }
    };
    let (peer, calls) = ChannelPeer::new();
    router.calls.attach(client, peer);
    router.calls.advertise(
        client,
        TopicName::parse(FETCH_SERVICE).expect("a constant name"),
        Schema::named(FETCH_TYPE),
        false,
    );
    let mut sender = Sender {
        client,
        topic: data,
        seq: 0,
    };
    loop {
        tokio::select! {
            m = calls.recv() => match m {
                Some(PeerMsg::Call(req)) => {
                    let (status, payload, text) = match answer(&ring, &slices, &req, &mut sender).await {
                        Ok(reply) => {
                            let body = serde_json::to_vec(&reply).unwrap_or_default();
                            (CallStatus::Ok, Some(Payload::json(body)), String::new())
                        }
                        Err(text) => {
                            tracing::warn!("black box: a fetch was refused: {text}");
                            (CallStatus::Failed, None, text)
                        }
                    };
                    router.calls.respond(client, req.id, status, payload, text);
                }
                Some(_) => {}
                None => break,
            },
            _ = shutdown.cancelled() => break,
        }
    }
    router.disconnect(client);
    ring.stop().await;
}

struct Sender {
    client: ClientId,
    topic: Arc<Topic>,
    seq: u64,
}

/// Handles one fetch call: the slice (cut now or found), and its window queued.
async fn answer(
    ring: &Ring,
    slices: &Path,
    req: &CallRequest,
    out: &mut Sender,
) -> Result<FetchReply, String> {
    let body = match req.payload.encoding {
        Encoding::Json => req.payload.bytes.to_vec(),
        Encoding::Cbor => fleetlink_proto::rosbridge::convert::cbor_to_json(&req.payload.bytes)
            .map_err(|e| format!("the request is not readable CBOR: {e}"))?,
        other => return Err(format!("requests are read as JSON, not {other}")),
    };
    let fetch: FetchRequest = serde_json::from_slice(&body).map_err(|e| {
        format!(
            "the request must look like {{\"slice\": \"bb-1\", \"range\": {{\"last_s\": 60}}, \
             \"offset\": 0, \"window\": 1048576}}: {e}"
        )
    })?;
    bb::check_slice_id(&fetch.slice)?;
    if fetch.window > bb::MAX_WINDOW {
        return Err(format!(
            "window: {} is more than the {} bytes one call may ask for",
            fetch.window,
            bb::MAX_WINDOW
        ));
    }
    let file = slices.join(format!("{}.mcap", fetch.slice));
    let about = slices.join(format!("{}.json", fetch.slice));
    let reply = match known(&file, &about) {
        Some(r) => r,
        None => cut(ring, slices, &fetch, &file, &about).await?,
    };
    let end = fetch.offset.saturating_add(fetch.window).min(reply.size);
    if fetch.offset < end {
        let (path, from) = (file.clone(), fetch.offset);
        let bytes = tokio::task::spawn_blocking(move || read_range(&path, from, end))
            .await
            .map_err(|e| e.to_string())?
            .map_err(|e| format!("reading {}: {e}", file.display()))?;
        for (i, piece) in bytes.chunks(PIECE_BYTES).enumerate() {
            let p = Piece {
                slice: &fetch.slice,
                offset: from + (i * PIECE_BYTES) as u64,
                size: reply.size,
                data: piece,
            };
            out.seq += 1;
            out.topic.publish(
                out.client,
                out.seq,
                fleetlink_relay::unix_nanos(),
                Payload::new(Encoding::Cdr, p.encode()),
            );
        }
    }
    Ok(reply)
}

/// A slice cut earlier, if its file is whole.
fn known(file: &Path, about: &Path) -> Option<FetchReply> {
    let r: FetchReply = serde_json::from_slice(&std::fs::read(about).ok()?).ok()?;
    (std::fs::metadata(file).ok()?.len() == r.size).then_some(r)
}

async fn cut(
    ring: &Ring,
    slices: &Path,
    fetch: &FetchRequest,
    file: &Path,
    about: &Path,
) -> Result<FetchReply, String> {
    let (from, to) = fetch.range.resolve(fleetlink_relay::unix_nanos())?;
    let pattern = fetch.range.pattern()?;
    let segments = ring.rotate().await;
    let inputs: Vec<PathBuf> = bb::slice::overlapping(&segments, from, to)
        .into_iter()
        .map(|s| s.path.clone())
        .collect();
    if inputs.is_empty() {
        return Err(format!(
            "the black box holds nothing between {from} and {to} (Unix ns); it keeps {}",
            match (segments.first(), segments.last()) {
                (Some(a), Some(_)) => format!("messages from {} on", a.start_ns),
                _ => "no messages yet".into(),
            }
        ));
    }
    prune_slices(slices);
    let (file, about) = (file.to_owned(), about.to_owned());
    tokio::task::spawn_blocking(move || {
        let paths: Vec<&Path> = inputs.iter().map(PathBuf::as_path).collect();
        let mut keep = |t: &str| pattern.as_ref().is_none_or(|p| p.is_match(t));
        let reply = bb::slice::cut(&paths, from, to, &mut keep, &file)?;
        let text = serde_json::to_vec_pretty(&reply).map_err(|e| e.to_string())?;
        std::fs::write(&about, text).map_err(|e| format!("writing {}: {e}", about.display()))?;
        tracing::info!(
            "black box: cut {} ({} messages, {} bytes)",
            file.display(),
            reply.messages,
            reply.size
        );
        Ok(reply)
    })
    .await
    .map_err(|e| e.to_string())?
}

/// Deletes the oldest slices past [`KEEP_SLICES`] (one is about to be cut).
fn prune_slices(dir: &Path) {
    let Ok(list) = std::fs::read_dir(dir) else {
        return;
    };
    let mut files: Vec<(std::time::SystemTime, PathBuf)> = list
        .flatten()
        .filter(|e| e.path().extension().is_some_and(|x| x == "mcap"))
        .filter_map(|e| Some((e.metadata().ok()?.modified().ok()?, e.path())))
        .collect();
    files.sort();
    while files.len() >= KEEP_SLICES {
        let (_, path) = files.remove(0);
        let _ = std::fs::remove_file(&path);
        let _ = std::fs::remove_file(path.with_extension("json"));
    }
}

fn read_range(path: &Path, from: u64, to: u64) -> std::io::Result<Vec<u8>> {
    use std::io::{Read, Seek, SeekFrom};
    let mut f = std::fs::File::open(path)?;
    f.seek(SeekFrom::Start(from))?;
    let mut buf = vec![0; (to - from) as usize];
    f.read_exact(&mut buf)?;
    Ok(buf)
}
