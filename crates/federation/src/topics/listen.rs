//! The receiving side of a topic wanted here: the want token that tells the hubs with
//! publishers to send it, and one Zenoh subscriber to what any hub puts of it, handed to
//! the topic's intake ([`Inlet`]) straight from Zenoh's callback.

use std::sync::Arc;
use std::sync::atomic::Ordering::Relaxed;
use std::time::Instant;

use fleetlink_relay::{Topic, TopicName};
use zenoh::Session;
use zenoh::liveliness::LivelinessToken;
use zenoh::pubsub::Subscriber;
use zenoh::sample::Locality;

use crate::inlet::Inlet;
use crate::keyframes::Asker;
use crate::keys::{self, MessageHeader, Offer};
use crate::{FederationError, ImportFigures, Shared, zerr};

/// A topic wanted here: the want token, the Zenoh subscriber to every hub's key for it,
/// and the intake that decides what of it is taken ([`Inlet`]).
pub(super) struct Listening {
    _want: LivelinessToken,
    _sub: Subscriber<()>,
    pub(super) inlet: Arc<Inlet>,
}

/// The want token that tells the hubs with publishers to send `name`, and one Zenoh
/// subscriber to what any hub puts of it, taken by an [`Inlet`] (declared while
/// someone here subscribes, whether or not a hub offers it yet).
pub(super) async fn want(
    session: &Session,
    shared: &Arc<Shared>,
    asker: &Arc<Asker>,
    name: &TopicName,
    topic: Arc<Topic>,
    figures: Arc<ImportFigures>,
) -> Result<Listening, FederationError> {
    let not_a_key = || FederationError::Zenoh(format!("{name} cannot be a Zenoh key"));
    let want = keys::offer_key(
        &shared.fleet,
        &shared.me,
        &Offer::Want {
            name: name.as_str().to_owned(),
        },
    )
    .ok_or_else(not_a_key)?;
    let key = keys::topic_key(&shared.fleet, "*", name.as_str()).ok_or_else(not_a_key)?;
    let inlet = Inlet::new(topic, shared.clone(), figures, asker.clone());
    let prefix = format!("{}/t/", keys::root(&shared.fleet));
    let shared = shared.clone();
    let into = inlet.clone();
    let sub = session
        .declare_subscriber(key)
        .allowed_origin(Locality::Remote)
        .callback(move |sample| {
            let counters = &shared.counters;
            let Some(hub) = sample
                .key_expr()
                .as_str()
                .strip_prefix(&prefix)
                .and_then(|rest| rest.split('/').next())
            else {
                counters.malformed.fetch_add(1, Relaxed);
                return;
            };
            let header = match sample
                .attachment()
                .map(|a| MessageHeader::decode(&a.to_bytes()))
            {
                Some(Ok(h)) => h,
                Some(Err(e)) => {
                    counters.malformed.fetch_add(1, Relaxed);
                    tracing::debug!("federation: message on {}: {e}", sample.key_expr());
                    return;
                }
                None => {
                    counters.malformed.fetch_add(1, Relaxed);
                    return;
                }
            };
            let bytes = bytes::Bytes::from(sample.payload().to_bytes().into_owned());
            into.take(hub, header, bytes, Instant::now());
        })
        .await
        .map_err(zerr)?;
    let token = session
        .liveliness()
        .declare_token(want)
        .await
        .map_err(zerr)?;
    Ok(Listening {
        _want: token,
        _sub: sub,
        inlet,
    })
}
