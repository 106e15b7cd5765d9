//! The PostgreSQL backend of the hub [`Store`]: the hub's tables in a database several
//! hubs share (`--database`), and every statement the store runs there.
//!
//! Design choice: batches go to the server as arrays in one statement (`UNNEST`), one
//! round trip however many rows; a parameter change notifies the other hubs in the same
//! transaction ([`Change::Params`]), so they reload at once.

use std::collections::BTreeMap;

use fleetlink_postgres::Database;
use fleetlink_postgres::changes::{Change, notify};

use super::{Engine, KeptConfig, RobotRecord, Store, StoreError};

/// The PostgreSQL schema, one entry per version (never edit one that shipped; add one).
const PG_MIGRATIONS: &[&str] = &[
    "
    CREATE TABLE robots (
        name TEXT PRIMARY KEY,
        first_seen_ms BIGINT NOT NULL,
        last_seen_ms BIGINT NOT NULL,
        last_addr TEXT NOT NULL,
        connects BIGINT NOT NULL DEFAULT 0
    );
    CREATE TABLE params (
        name TEXT PRIMARY KEY,
        value TEXT NOT NULL
    );
    CREATE TABLE delivered (
        robot TEXT NOT NULL,
        topic TEXT NOT NULL,
        epoch BIGINT NOT NULL,
        seq BIGINT NOT NULL,
        PRIMARY KEY (robot, topic)
    );
",
    "
    CREATE TABLE robot_configs (
        robot TEXT PRIMARY KEY,
        overlay TEXT NOT NULL,
        by_whom TEXT NOT NULL,
        at_ms BIGINT NOT NULL
    );
",
];

impl Store {
    /// The hub's tables in a shared PostgreSQL database, created or brought up to date
    /// first (safe when several hubs start at once). Blocks: call it from a blocking
    /// thread.
    pub fn postgres(db: Database) -> Result<Store, StoreError> {
        db.migrate("hub", PG_MIGRATIONS)?;
        Ok(Store::new(Postgres { db }))
    }
}

struct Postgres {
    db: Database,
}

impl Engine for Postgres {
    fn is_shared(&self) -> bool {
        true
    }

    fn on_params_changed(&self, f: Box<dyn Fn() -> bool + Send + Sync>) {
        self.db.on_change(move |c| match c {
            Change::Params | Change::Everything => f(),
            _ => true,
        });
    }

    fn robot_seen(
        &self,
        name: &str,
        addr: &str,
        now: i64,
        connected: i64,
    ) -> Result<(), StoreError> {
        self.db.execute(
            "INSERT INTO robots (name, first_seen_ms, last_seen_ms, last_addr, connects)
                     VALUES ($1, $2, $2, $3, $4)
                     ON CONFLICT (name) DO UPDATE SET last_seen_ms = $2, last_addr = $3,
                         connects = robots.connects + $4",
            &[&name, &now, &addr, &connected],
        )?;
        Ok(())
    }

    fn robot_config(&self, robot: &str) -> Result<Option<KeptConfig>, StoreError> {
        const SQL: &str = "SELECT overlay, by_whom, at_ms FROM robot_configs WHERE robot = $1";
        self.db
            .query(SQL, &[&robot])?
            .first()
            .map(|r| -> Result<KeptConfig, StoreError> {
                Ok(KeptConfig {
                    overlay: r.try_get(0)?,
                    by: r.try_get(1)?,
                    at_ms: r.try_get(2)?,
                })
            })
            .transpose()
    }

    fn set_robot_config(
        &self,
        robot: &str,
        overlay: &str,
        by: &str,
        now: i64,
    ) -> Result<(), StoreError> {
        self.db.execute(
            "INSERT INTO robot_configs (robot, overlay, by_whom, at_ms) VALUES ($1, $2, $3, $4)
                     ON CONFLICT (robot) DO UPDATE SET overlay = $2, by_whom = $3, at_ms = $4",
            &[&robot, &overlay, &by, &now],
        )?;
        Ok(())
    }

    fn delivered(&self, robot: &str) -> Result<Vec<(String, u64, u64)>, StoreError> {
        self.db
            .query(
                "SELECT topic, epoch, seq FROM delivered WHERE robot = $1",
                &[&robot],
            )?
            .iter()
            .map(|r| {
                Ok((
                    r.try_get(0)?,
                    r.try_get::<_, i64>(1)? as u64,
                    r.try_get::<_, i64>(2)? as u64,
                ))
            })
            .collect()
    }

    fn record_delivered(
        &self,
        robot: &str,
        marks: &[(String, u64, u64)],
    ) -> Result<(), StoreError> {
        let topics: Vec<&str> = marks.iter().map(|(t, _, _)| t.as_str()).collect();
        let epochs: Vec<i64> = marks.iter().map(|(_, e, _)| *e as i64).collect();
        let seqs: Vec<i64> = marks.iter().map(|(_, _, s)| *s as i64).collect();
        self.db.transaction(async |tx| {
            // One statement for all marks: one round trip however many topics.
            tx.execute(
                "INSERT INTO delivered (robot, topic, epoch, seq)
                         SELECT $1, * FROM UNNEST($2::TEXT[], $3::BIGINT[], $4::BIGINT[])
                         ON CONFLICT (robot, topic)
                         DO UPDATE SET epoch = excluded.epoch, seq = excluded.seq",
                &[&robot, &topics, &epochs, &seqs],
            )
            .await?;
            if let Some(epoch) = epochs.first() {
                tx.execute(
                    "DELETE FROM delivered WHERE robot = $1 AND epoch != $2",
                    &[&robot, epoch],
                )
                .await?;
            }
            Ok(())
        })?;
        Ok(())
    }

    fn params(&self) -> Result<BTreeMap<String, String>, StoreError> {
        self.db
            .query("SELECT name, value FROM params", &[])?
            .iter()
            .map(|r| Ok((r.try_get(0)?, r.try_get(1)?)))
            .collect()
    }

    fn write_params(&self, changes: &[(String, Option<String>)]) -> Result<(), StoreError> {
        let (mut names, mut values, mut gone) = (Vec::new(), Vec::new(), Vec::new());
        for (name, value) in changes {
            match value {
                Some(v) => {
                    names.push(name.as_str());
                    values.push(v.as_str());
                }
                None => gone.push(name.as_str()),
            }
        }
        Ok(self.db.transaction(async |tx| {
            if !names.is_empty() {
                tx.execute(
                    "INSERT INTO params (name, value)
                             SELECT * FROM UNNEST($1::TEXT[], $2::TEXT[])
                             ON CONFLICT (name) DO UPDATE SET value = excluded.value",
                    &[&names, &values],
                )
                .await?;
            }
            if !gone.is_empty() {
                tx.execute("DELETE FROM params WHERE name = ANY($1)", &[&gone])
                    .await?;
            }
            notify(tx, Change::Params).await
        })?)
    }

    fn delete_params(&self, name: &str, below: &str) -> Result<(), StoreError> {
        Ok(self.db.transaction(async |tx| {
            tx.execute(
                "DELETE FROM params WHERE name = $1 OR name LIKE $2",
                &[&name, &below],
            )
            .await?;
            notify(tx, Change::Params).await
        })?)
    }

    fn robots(&self) -> Result<Vec<RobotRecord>, StoreError> {
        const SQL: &str = "SELECT name, first_seen_ms, last_seen_ms, last_addr, connects \
                           FROM robots ORDER BY name";
        self.db
            .query(SQL, &[])?
            .iter()
            .map(|r| {
                Ok(RobotRecord {
                    name: r.try_get(0)?,
                    first_seen_ms: r.try_get(1)?,
                    last_seen_ms: r.try_get(2)?,
                    last_addr: r.try_get(3)?,
                    connects: r.try_get(4)?,
                })
            })
            .collect()
    }
}
