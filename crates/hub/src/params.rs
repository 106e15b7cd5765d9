//! The hub's parameters: served from memory, written through to the database so they
//! survive a restart. Writes go to one writer thread in order, so a `set_param` never
//! waits for the disk on the session's task; a failed write is logged. A stopping hub
//! waits for the writer ([`ParamStore::flush`]), so a change answered `true` just before
//! the stop is still there after the restart.

use std::collections::BTreeMap;
use std::sync::mpsc::{Sender, SyncSender, channel, sync_channel};

use fleetlink_relay::params::{MemoryParams, ParamStore};

use crate::store::{Store, StoreError};

enum Write {
    Set(String, String),
    Delete(String),
    /// Answered once everything sent before it is written.
    Flush(SyncSender<()>),
}

pub struct DurableParams {
    mem: MemoryParams,
    tx: Sender<Write>,
}

impl DurableParams {
    /// Loads the stored parameters and starts the writer thread.
    pub fn open(store: Store) -> Result<DurableParams, StoreError> {
        let mem = MemoryParams::with(store.params()?);
        let (tx, rx) = channel::<Write>();
        std::thread::Builder::new()
            .name("fleetlink-params".into())
            .spawn(move || {
                for w in rx {
                    let r = match &w {
                        Write::Set(n, v) => store.set_param(n, v),
                        Write::Delete(n) => store.delete_params(n),
                        Write::Flush(done) => {
                            let _ = done.send(());
                            Ok(())
                        }
                    };
                    if let Err(e) = r {
                        tracing::error!("parameters: cannot write to the database: {e}");
                    }
                }
            })
            .map_err(StoreError::Thread)?;
        Ok(DurableParams { mem, tx })
    }
}

impl ParamStore for DurableParams {
    fn snapshot(&self) -> BTreeMap<String, String> {
        self.mem.snapshot()
    }
    fn get(&self, name: &str) -> Option<String> {
        self.mem.get(name)
    }
    fn set(&self, name: &str, value_json: String) {
        let _ = self
            .tx
            .send(Write::Set(name.to_owned(), value_json.clone()));
        self.mem.set(name, value_json);
    }
    fn delete(&self, name: &str) -> bool {
        let _ = self.tx.send(Write::Delete(name.to_owned()));
        self.mem.delete(name)
    }
    fn flush(&self) {
        let (done_tx, done_rx) = sync_channel(1);
        if self.tx.send(Write::Flush(done_tx)).is_ok() {
            let _ = done_rx.recv();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flush_returns_once_every_change_is_in_the_database() {
        let dir = std::env::temp_dir().join(format!(
            "fleetlink-params-{}-{:?}",
            std::process::id(),
            std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .unwrap_or_default()
                .as_nanos()
        ));
        let params = DurableParams::open(Store::open(&dir).unwrap()).unwrap();
        for i in 0..2000 {
            params.set(&format!("/p/{i:04}"), i.to_string());
        }
        assert!(params.delete("/p/0000"));
        params.flush();
        // A second connection, as a restarted hub would open.
        let stored = Store::open(&dir).unwrap().params().unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(stored.len(), 1999, "changes missing after flush");
        assert_eq!(stored.get("/p/1999").map(String::as_str), Some("1999"));
        assert!(!stored.contains_key("/p/0000"));
    }
}
