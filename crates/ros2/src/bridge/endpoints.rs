//! The bridge's own DDS readers and writers, and the list of them its node shows.
//!
//! Every reader and writer the bridge makes is wrapped in a [`Tracked`] that keeps its
//! GUID in [`OwnEndpoints`] for as long as it lives, so `ros_discovery_info`
//! ([`crate::node_info`]) lists exactly the endpoints that exist.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, MutexGuard};

use rustdds::GUID;
use rustdds::no_key::{DataReader, DataWriter};

use crate::raw::{RawAdapter, RawCdr};

/// A reader or writer of this bridge, listed among its node's endpoints while it lives.
pub type RawReader = Tracked<DataReader<RawCdr, RawAdapter>>;
pub type RawWriter = Tracked<DataWriter<RawCdr, RawAdapter>>;

/// The GUIDs of the bridge's own readers and writers (`true`: a writer): what its node
/// lists in `ros_discovery_info` ([`crate::node_info`]).
#[derive(Debug, Default)]
pub(crate) struct OwnEndpoints(Mutex<HashMap<GUID, bool>>);

impl OwnEndpoints {
    fn lock(&self) -> MutexGuard<'_, HashMap<GUID, bool>> {
        self.0.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// `inner` (GUID `guid`; `writer`: a writer) listed until the returned [`Tracked`]
    /// is dropped.
    pub(super) fn track<T>(self: &Arc<Self>, guid: GUID, writer: bool, inner: T) -> Tracked<T> {
        self.lock().insert(guid, writer);
        Tracked {
            inner,
            _entry: Entry(self.clone(), guid),
        }
    }

    /// The readers' and the writers' GUIDs, each sorted.
    pub(crate) fn list(&self) -> (Vec<GUID>, Vec<GUID>) {
        let all = self.lock();
        let mut readers: Vec<GUID> = all.iter().filter(|(_, w)| !**w).map(|(g, _)| *g).collect();
        let mut writers: Vec<GUID> = all.iter().filter(|(_, w)| **w).map(|(g, _)| *g).collect();
        readers.sort_by_key(|g| g.to_bytes());
        writers.sort_by_key(|g| g.to_bytes());
        (readers, writers)
    }
}

/// A DDS entity of the bridge with its entry in [`OwnEndpoints`], removed when it is
/// dropped (with the entity).
pub struct Tracked<T> {
    inner: T,
    _entry: Entry,
}

#[derive(Debug)]
struct Entry(Arc<OwnEndpoints>, GUID);

impl Drop for Entry {
    fn drop(&mut self) {
        self.0.lock().remove(&self.1);
    }
}

impl<T> std::ops::Deref for Tracked<T> {
    type Target = T;
    fn deref(&self) -> &T {
        &self.inner
    }
}

impl<T> std::ops::DerefMut for Tracked<T> {
    fn deref_mut(&mut self) -> &mut T {
        &mut self.inner
    }
}

impl RawReader {
    /// The reader's samples as a stream, which keeps the reader listed while it lives.
    pub fn async_sample_stream(
        self,
    ) -> Tracked<rustdds::no_key::DataReaderStream<RawCdr, RawAdapter>> {
        Tracked {
            inner: self.inner.async_sample_stream(),
            _entry: self._entry,
        }
    }
}
