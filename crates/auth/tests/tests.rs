//! Integration tests of the security core, through its public API only.

mod acl_matrix;
mod admin;
mod attacks;
mod audit;
mod jwt;
mod shared;
mod tls;
mod tls_openssl;
mod util;
