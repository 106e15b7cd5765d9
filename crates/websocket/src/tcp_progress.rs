//! A TCP connection's progress as the kernel counts it ([`TcpProgress`]), read with the
//! sock_diag netlink interface (`NETLINK_SOCK_DIAG`, the one `ss` uses), which gives the
//! connection's `tcp_info` by its addresses.
//!
//! Why this way: `getsockopt(TCP_INFO)` needs the socket's descriptor and an `unsafe`
//! call (neither rustix nor socket2 offers it); sock_diag needs neither — only the two
//! addresses, which the server has for plain and TLS connections alike — and rustix
//! offers netlink sockets safely. One netlink socket serves the whole process (a query is
//! a send and a receive of a few hundred bytes, answered by the kernel within the send);
//! it is asked only about clients that are overdue (docs/security.md, "Viewer liveness").
//!
//! Linux only; elsewhere, or where sock_diag is not allowed, [`sample`] gives `None` and
//! sessions go by what they read alone.

use std::net::SocketAddr;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use super::liveness::{ProgressProbe, TcpProgress};

/// Samples the TCP connection from `local` to `peer` (as the server sees it).
pub fn sample(local: SocketAddr, peer: SocketAddr) -> Option<TcpProgress> {
    imp::sample(local, peer)
}

/// The probe of a server connection from `local` to `peer`: the kernel's count when it
/// can be read at the first sample, else the bytes the connection's writer handed the
/// socket (`written`, [`super::Writer::written`]) — which go on a little longer for a
/// frozen client, while its receive buffer fills. One or the other for the
/// connection's life, as their numbers do not compare.
pub fn probe(local: SocketAddr, peer: SocketAddr, written: Arc<AtomicU64>) -> ProgressProbe {
    let mut kernel = None;
    Box::new(move || {
        if *kernel.get_or_insert_with(|| sample(local, peer).is_some()) {
            return sample(local, peer);
        }
        let n = written.load(Ordering::Relaxed);
        Some(TcpProgress {
            acked: n,
            window_end: n,
            ..TcpProgress::default()
        })
    })
}

/// The fields of `tcp_info` (include/uapi/linux/tcp.h) this reads: their offsets are
/// fixed by the kernel's ABI.
mod tcp_info {
    /// `tcpi_snd_wscale` (the low four bits) and `tcpi_rcv_wscale`.
    pub const WSCALE: usize = 6;
    /// `tcpi_bytes_acked` (u64, Linux 4.1).
    pub const BYTES_ACKED: usize = 120;
    /// `tcpi_data_segs_out` (u32, Linux 4.6).
    pub const DATA_SEGS_OUT: usize = 156;
    /// `tcpi_snd_wnd` (u32, Linux 5.4): the peer's advertised window, scaled.
    pub const SND_WND: usize = 228;

    /// The progress in a `tcp_info` of `info.len()` bytes (older kernels give less).
    pub fn progress(info: &[u8]) -> Option<super::TcpProgress> {
        let u32_at = |at: usize| -> Option<u32> {
            Some(u32::from_ne_bytes(info.get(at..at + 4)?.try_into().ok()?))
        };
        let acked = u64::from_ne_bytes(info.get(BYTES_ACKED..BYTES_ACKED + 8)?.try_into().ok()?);
        let wnd = u32_at(SND_WND)?;
        Some(super::TcpProgress {
            acked,
            window_end: acked + u64::from(wnd),
            segments: u64::from(u32_at(DATA_SEGS_OUT)?),
            window_scale: info.get(WSCALE)? & 0x0f,
        })
    }
}

#[cfg(target_os = "linux")]
mod imp {
    use std::net::{IpAddr, SocketAddr};
    use std::os::fd::OwnedFd;
    use std::sync::Mutex;
    use std::time::Duration;

    use rustix::net::netlink::{self, SocketAddrNetlink};
    use rustix::net::{AddressFamily, RecvFlags, SendFlags, SocketFlags, SocketType};

    use super::TcpProgress;

    /// `SOCK_DIAG_BY_FAMILY`.
    const SOCK_DIAG_BY_FAMILY: u16 = 20;
    const NLMSG_ERROR: u16 = 2;
    const NLM_F_REQUEST: u16 = 1;
    const IPPROTO_TCP: u8 = 6;
    const TCP_LISTEN: u8 = 10;
    const AF_INET: u8 = 2;
    const AF_INET6: u8 = 10;
    /// The `inet_diag` attribute holding `tcp_info`, and the request bit asking for it.
    const INET_DIAG_INFO: u16 = 2;
    /// `nlmsghdr` and `inet_diag_msg`.
    const NLMSG_HDR: usize = 16;
    const DIAG_MSG: usize = 72;

    /// The process's netlink socket and its message numbers. std Mutex: held for one
    /// send and one receive, never across an await.
    static SOCKET: Mutex<Option<(OwnedFd, u32)>> = Mutex::new(None);

    pub fn sample(local: SocketAddr, peer: SocketAddr) -> Option<TcpProgress> {
        let mut guard = SOCKET.lock().unwrap_or_else(|p| p.into_inner());
        if guard.is_none() {
            *guard = Some((open().ok()?, 0));
        }
        let (fd, seq) = guard.as_mut()?;
        *seq = seq.wrapping_add(1);
        match query(fd, *seq, local, peer) {
            Ok(p) => p,
            Err(_) => {
                // A socket in a bad state is made anew at the next sample.
                *guard = None;
                None
            }
        }
    }

    fn open() -> std::io::Result<OwnedFd> {
        let fd = rustix::net::socket_with(
            AddressFamily::NETLINK,
            SocketType::DGRAM,
            SocketFlags::CLOEXEC,
            Some(netlink::SOCK_DIAG),
        )?;
        // The kernel answers within the send; the bound is for a kernel that does not.
        rustix::net::sockopt::set_socket_timeout(
            &fd,
            rustix::net::sockopt::Timeout::Recv,
            Some(Duration::from_millis(100)),
        )?;
        Ok(fd)
    }

    /// The request: `nlmsghdr` + `inet_diag_req_v2` naming the connection exactly.
    fn request(seq: u32, local: SocketAddr, peer: SocketAddr) -> Vec<u8> {
        let mut m = Vec::with_capacity(NLMSG_HDR + 56);
        m.extend_from_slice(&((NLMSG_HDR + 56) as u32).to_ne_bytes());
        m.extend_from_slice(&SOCK_DIAG_BY_FAMILY.to_ne_bytes());
        m.extend_from_slice(&NLM_F_REQUEST.to_ne_bytes());
        m.extend_from_slice(&seq.to_ne_bytes());
        m.extend_from_slice(&0u32.to_ne_bytes());
        let family = if local.is_ipv4() { AF_INET } else { AF_INET6 };
        m.extend_from_slice(&[family, IPPROTO_TCP, 1 << (INET_DIAG_INFO - 1), 0]);
        m.extend_from_slice(&u32::MAX.to_ne_bytes()); // every state
        // inet_diag_sockid: ports and addresses in network order.
        m.extend_from_slice(&local.port().to_be_bytes());
        m.extend_from_slice(&peer.port().to_be_bytes());
        for ip in [local.ip(), peer.ip()] {
            let mut a = [0u8; 16];
            match ip {
                IpAddr::V4(v4) => a[..4].copy_from_slice(&v4.octets()),
                IpAddr::V6(v6) => a = v6.octets(),
            }
            m.extend_from_slice(&a);
        }
        m.extend_from_slice(&0u32.to_ne_bytes()); // any interface
        m.extend_from_slice(&[0xff; 8]); // INET_DIAG_NOCOOKIE
        m
    }

    /// Sends the request and reads its answer: `Ok(None)` when the kernel knows no such
    /// connection (it closed) or gives no `tcp_info`.
    fn query(
        fd: &OwnedFd,
        seq: u32,
        local: SocketAddr,
        peer: SocketAddr,
    ) -> std::io::Result<Option<TcpProgress>> {
        let kernel = SocketAddrNetlink::new(0, 0);
        rustix::net::sendto(fd, &request(seq, local, peer), SendFlags::empty(), &kernel)?;
        let mut buf = [0u8; 1024];
        // Answers to earlier requests that timed out are skipped by their number.
        for _ in 0..4 {
            let (_, n) = rustix::net::recv(fd, &mut buf[..], RecvFlags::empty())?;
            let msg = &buf[..n.min(buf.len())];
            if msg.len() < NLMSG_HDR {
                return Ok(None);
            }
            let kind = u16::from_ne_bytes([msg[4], msg[5]]);
            let got = u32::from_ne_bytes([msg[8], msg[9], msg[10], msg[11]]);
            if got != seq {
                continue;
            }
            if kind == NLMSG_ERROR || kind != SOCK_DIAG_BY_FAMILY {
                return Ok(None);
            }
            let len =
                (u32::from_ne_bytes([msg[0], msg[1], msg[2], msg[3]]) as usize).min(msg.len());
            let body = &msg[NLMSG_HDR.min(len)..len];
            // A connection that closed is not found, but its port's listener may be (it
            // matches any peer): only the connection itself is an answer.
            let state = body.get(1).copied();
            let dport = body.get(6..8).map(|p| u16::from_be_bytes([p[0], p[1]]));
            if state == Some(TCP_LISTEN) || dport != Some(peer.port()) {
                return Ok(None);
            }
            return Ok(info_attr(body).and_then(super::tcp_info::progress));
        }
        Ok(None)
    }

    /// The `INET_DIAG_INFO` attribute's payload after an `inet_diag_msg`.
    fn info_attr(body: &[u8]) -> Option<&[u8]> {
        let mut at = DIAG_MSG;
        while at + 4 <= body.len() {
            let len = u16::from_ne_bytes([body[at], body[at + 1]]) as usize;
            let kind = u16::from_ne_bytes([body[at + 2], body[at + 3]]);
            if len < 4 || at + len > body.len() {
                return None;
            }
            if kind == INET_DIAG_INFO {
                return Some(&body[at + 4..at + len]);
            }
            at += (len + 3) & !3;
        }
        None
    }
}

#[cfg(not(target_os = "linux"))]
mod imp {
    pub fn sample(_: std::net::SocketAddr, _: std::net::SocketAddr) -> Option<super::TcpProgress> {
        None
    }
}

#[cfg(all(test, target_os = "linux"))]
mod tests {
    use std::io::{Read, Write};
    use std::net::{TcpListener, TcpStream};
    use std::time::Duration;

    use super::*;

    /// A loopback connection: what one side wrote and the other read is acknowledged,
    /// and the reader's window stays open beyond it.
    #[test]
    fn a_connection_is_sampled_by_its_addresses() {
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        let mut client = TcpStream::connect(listener.local_addr().unwrap()).unwrap();
        let (mut server, peer) = listener.accept().unwrap();
        let local = server.local_addr().unwrap();
        let first = sample(local, peer).expect("sock_diag answers for a live connection");
        let data = vec![7u8; 100_000];
        server.write_all(&data).unwrap();
        let mut got = vec![0u8; data.len()];
        client.read_exact(&mut got).unwrap();
        // The acknowledgement of the last bytes may trail the read by a moment.
        let mut after = sample(local, peer).unwrap();
        for _ in 0..100 {
            if after.acked >= first.acked + data.len() as u64 {
                break;
            }
            std::thread::sleep(Duration::from_millis(10));
            after = sample(local, peer).unwrap();
        }
        assert_eq!(after.acked, first.acked + data.len() as u64);
        assert!(after.window_end > after.acked, "{after:?}");
        assert!(after.segments > first.segments, "{after:?}");
        assert!(
            after.window_scale > 0,
            "loopback connections scale their windows: {after:?}"
        );
        assert!(after.progressed_since(&first));
        // Another connection's addresses name nothing.
        drop((client, server));
        let gone = std::net::SocketAddr::from(([127, 0, 0, 1], 1));
        assert_eq!(sample(local, gone), None);
    }
}
