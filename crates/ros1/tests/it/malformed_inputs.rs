//! What a hostile or broken peer can send the agent's ROS 1 node, one attack per test:
//! every decoder answers with an error (never a panic, never an unbounded allocation), and
//! says whether the input was cut short or can never be valid.

use fleetlink_ros1::tcpros::{FrameError, Header, MAX_HEADER, read_header, read_message};
use fleetlink_ros1::xmlrpc::{XmlRpcError, decode_call, decode_response};
use tokio::io::AsyncWriteExt;

#[test]
fn xmlrpc_billion_nested_arrays_are_refused_not_recursed() {
    let text =
        "<methodResponse><params><param>".to_owned() + &"<value><array><data>".repeat(100_000);
    assert!(matches!(
        decode_response(&text),
        Err(XmlRpcError::Invalid { .. })
    ));
}

#[test]
fn xmlrpc_integer_overflow_is_invalid() {
    let text = "<methodResponse><params><param><value><int>99999999999999999999999</int></value></param></params></methodResponse>";
    assert!(matches!(
        decode_response(text),
        Err(XmlRpcError::Invalid { .. })
    ));
}

#[test]
fn xmlrpc_unknown_entities_and_bad_code_points_are_invalid() {
    for body in ["&xxe;", "&#xD800;", "&#99999999999;", "&#x;", "&amp"] {
        let text = format!(
            "<methodCall><methodName>getPid</methodName><params><param><value>{body}</value></param></params></methodCall>"
        );
        assert!(
            matches!(decode_call(&text), Err(XmlRpcError::Invalid { .. })),
            "{body}"
        );
    }
}

#[test]
fn xmlrpc_truncated_body_is_incomplete() {
    let text =
        "<methodCall><methodName>requestTopic</methodName><params><param><value><string>/cal";
    assert!(matches!(decode_call(text), Err(XmlRpcError::Incomplete(_))));
}

#[test]
fn xmlrpc_mismatched_tags_are_invalid() {
    let text = "<methodResponse><params><param><value><array><data></array></data></value></param></params></methodResponse>";
    assert!(matches!(
        decode_response(text),
        Err(XmlRpcError::Invalid { .. })
    ));
}

#[test]
fn xmlrpc_doctype_and_comments_do_not_expand() {
    // No DTD processing: a declared entity stays unknown.
    let text = "<?xml version=\"1.0\"?><!-- c --><methodResponse><params><param><value>&lol;</value></param></params></methodResponse>";
    assert!(matches!(
        decode_response(text),
        Err(XmlRpcError::Invalid { .. })
    ));
}

#[tokio::test]
async fn tcpros_header_claiming_gigabytes_is_refused_before_allocating() {
    let (mut a, mut b) = tokio::io::duplex(64);
    a.write_all(&(u32::MAX).to_le_bytes()).await.unwrap();
    match read_header(&mut b).await {
        Err(FrameError::TooLarge { limit, .. }) => assert_eq!(limit, MAX_HEADER),
        other => panic!("{other:?}"),
    }
}

#[tokio::test]
async fn tcpros_message_claiming_gigabytes_is_refused_before_allocating() {
    let (mut a, mut b) = tokio::io::duplex(64);
    a.write_all(&(u32::MAX).to_le_bytes()).await.unwrap();
    assert!(matches!(
        read_message(&mut b).await,
        Err(FrameError::TooLarge { .. })
    ));
}

#[test]
fn tcpros_header_field_longer_than_the_header_is_invalid() {
    let mut body = 1000u32.to_le_bytes().to_vec();
    body.extend_from_slice(b"topic=/x");
    assert!(matches!(Header::decode(&body), Err(FrameError::Invalid(_))));
}

#[tokio::test]
async fn tcpros_peer_hanging_up_mid_header_is_not_a_panic() {
    let (mut a, mut b) = tokio::io::duplex(64);
    a.write_all(&20u32.to_le_bytes()).await.unwrap();
    a.write_all(b"short").await.unwrap();
    drop(a);
    assert!(matches!(
        read_header(&mut b).await,
        Err(FrameError::Invalid(_))
    ));
}
