//! End-to-end tests: hub and agents in-process on port 0, real WebSocket clients.
//! One test binary (ripgrep style); shared plumbing in `util`.

mod util;

mod e2e {
    mod acl;
    mod audit;
    mod bench_cli;
    mod blackbox;
    mod calls;
    mod capacity;
    mod cli;
    mod interest;
    mod isolation;
    mod kept_changes;
    mod link;
    mod mirror;
    mod no_drop;
    mod oidc;
    mod priority;
    mod recording;
    mod relay;
    mod rosbridge;
    mod runtime_config;
    mod shutdown;
    mod site;
    mod tls;
    mod video;
    mod viewer_deflate;
    mod viewer_liveness;
}
