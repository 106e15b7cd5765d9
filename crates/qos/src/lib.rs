//! Schedulers, drop policies, link estimation and capacity sharing (see issue 3).
