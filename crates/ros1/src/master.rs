//! Calls to the ROS master and to other nodes' slave APIs over XML-RPC.
//!
//! Every ROS API answers `[code, statusMessage, value]`; `code` 1 is success, anything
//! else becomes [`ApiError::Refused`] carrying the status text.

use std::time::Duration;

use crate::http::{HttpError, post};
use crate::xmlrpc::{Value, XmlRpcError, decode_response, encode_call};

/// How long one XML-RPC call may take (master and nodes answer in milliseconds).
const CALL_TIMEOUT: Duration = Duration::from_secs(3);

#[derive(Debug, thiserror::Error)]
pub enum ApiError {
    #[error(transparent)]
    Http(#[from] HttpError),
    #[error("{method} at {uri}: {source}")]
    XmlRpc {
        method: String,
        uri: String,
        source: XmlRpcError,
    },
    #[error("{method} at {uri} refused: {status}")]
    Refused {
        method: String,
        uri: String,
        status: String,
    },
    #[error("{method} at {uri} answered an unexpected value: {value:?}")]
    Unexpected {
        method: String,
        uri: String,
        value: Value,
    },
}

/// Calls `method` at `uri` and returns the `value` part of a successful answer.
pub async fn call(uri: &str, method: &str, params: &[Value]) -> Result<Value, ApiError> {
    let body = post(uri, &encode_call(method, params), CALL_TIMEOUT).await?;
    let v = decode_response(&body).map_err(|source| ApiError::XmlRpc {
        method: method.into(),
        uri: uri.into(),
        source,
    })?;
    let unexpected = |value: Value| ApiError::Unexpected {
        method: method.into(),
        uri: uri.into(),
        value,
    };
    let mut parts = match v {
        Value::Array(parts) => parts,
        other => return Err(unexpected(other)),
    };
    if parts.len() != 3 {
        return Err(unexpected(Value::Array(parts)));
    }
    let value = parts.pop().expect("three parts");
    let status = parts.pop().expect("three parts");
    match parts[0].as_i32() {
        Some(1) => Ok(value),
        _ => Err(ApiError::Refused {
            method: method.into(),
            uri: uri.into(),
            status: status.as_str().unwrap_or("").to_owned(),
        }),
    }
}

/// The master's view of the graph (`getSystemState`): `(name, nodes)` per topic or
/// service.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SystemState {
    pub publishers: Vec<(String, Vec<String>)>,
    pub subscribers: Vec<(String, Vec<String>)>,
    pub services: Vec<(String, Vec<String>)>,
}

fn name_lists(v: &Value) -> Option<Vec<(String, Vec<String>)>> {
    v.as_array()?
        .iter()
        .map(|entry| {
            let pair = entry.as_array()?;
            Some((
                pair.first()?.as_str()?.to_owned(),
                pair.get(1)?.as_str_list()?,
            ))
        })
        .collect()
}

/// A node's handle on the master: its name and its own slave API URI go with every call.
#[derive(Debug, Clone)]
pub struct Master {
    pub uri: String,
    pub caller_id: String,
    pub caller_api: String,
}

impl Master {
    pub(crate) async fn call(
        &self,
        method: &str,
        mut params: Vec<Value>,
    ) -> Result<Value, ApiError> {
        params.insert(0, Value::from(self.caller_id.as_str()));
        call(&self.uri, method, &params).await
    }

    fn list(&self, method: &str, v: Value) -> Result<Vec<String>, ApiError> {
        v.as_str_list().ok_or_else(|| ApiError::Unexpected {
            method: method.into(),
            uri: self.uri.clone(),
            value: v,
        })
    }

    /// The master's process id: a different one means the master restarted.
    pub async fn pid(&self) -> Result<i32, ApiError> {
        let v = self.call("getPid", vec![]).await?;
        v.as_i32().ok_or_else(|| ApiError::Unexpected {
            method: "getPid".into(),
            uri: self.uri.clone(),
            value: v,
        })
    }

    /// Registers a publication; returns the current subscribers' APIs.
    pub async fn register_publisher(&self, topic: &str, ty: &str) -> Result<Vec<String>, ApiError> {
        let v = self
            .call(
                "registerPublisher",
                vec![topic.into(), ty.into(), self.caller_api.as_str().into()],
            )
            .await?;
        self.list("registerPublisher", v)
    }

    pub async fn unregister_publisher(&self, topic: &str) -> Result<(), ApiError> {
        self.call(
            "unregisterPublisher",
            vec![topic.into(), self.caller_api.as_str().into()],
        )
        .await
        .map(drop)
    }

    /// Registers a subscription; returns the current publishers' APIs.
    pub async fn register_subscriber(
        &self,
        topic: &str,
        ty: &str,
    ) -> Result<Vec<String>, ApiError> {
        let v = self
            .call(
                "registerSubscriber",
                vec![topic.into(), ty.into(), self.caller_api.as_str().into()],
            )
            .await?;
        self.list("registerSubscriber", v)
    }

    pub async fn unregister_subscriber(&self, topic: &str) -> Result<(), ApiError> {
        self.call(
            "unregisterSubscriber",
            vec![topic.into(), self.caller_api.as_str().into()],
        )
        .await
        .map(drop)
    }

    pub async fn register_service(&self, service: &str, service_api: &str) -> Result<(), ApiError> {
        self.call(
            "registerService",
            vec![
                service.into(),
                service_api.into(),
                self.caller_api.as_str().into(),
            ],
        )
        .await
        .map(drop)
    }

    pub async fn unregister_service(
        &self,
        service: &str,
        service_api: &str,
    ) -> Result<(), ApiError> {
        self.call(
            "unregisterService",
            vec![service.into(), service_api.into()],
        )
        .await
        .map(drop)
    }

    /// The `rosrpc://host:port` of a service's provider.
    pub async fn lookup_service(&self, service: &str) -> Result<String, ApiError> {
        let v = self.call("lookupService", vec![service.into()]).await?;
        match v {
            Value::Str(s) => Ok(s),
            value => Err(ApiError::Unexpected {
                method: "lookupService".into(),
                uri: self.uri.clone(),
                value,
            }),
        }
    }

    pub async fn system_state(&self) -> Result<SystemState, ApiError> {
        let v = self.call("getSystemState", vec![]).await?;
        let parsed = v.as_array().and_then(|parts| {
            Some(SystemState {
                publishers: name_lists(parts.first()?)?,
                subscribers: name_lists(parts.get(1)?)?,
                services: name_lists(parts.get(2)?)?,
            })
        });
        parsed.ok_or_else(|| ApiError::Unexpected {
            method: "getSystemState".into(),
            uri: self.uri.clone(),
            value: v,
        })
    }

    /// `(topic, type)` of every topic with a publisher.
    pub async fn topic_types(&self) -> Result<Vec<(String, String)>, ApiError> {
        let v = self.call("getTopicTypes", vec![]).await?;
        let parsed: Option<Vec<(String, String)>> = v.as_array().and_then(|a| {
            a.iter()
                .map(|e| {
                    let p = e.as_array()?;
                    Some((
                        p.first()?.as_str()?.to_owned(),
                        p.get(1)?.as_str()?.to_owned(),
                    ))
                })
                .collect()
        });
        parsed.ok_or_else(|| ApiError::Unexpected {
            method: "getTopicTypes".into(),
            uri: self.uri.clone(),
            value: v,
        })
    }
}

/// Asks the publisher at `publisher_api` for a TCPROS endpoint of `topic`.
pub async fn request_topic(
    caller_id: &str,
    publisher_api: &str,
    topic: &str,
) -> Result<(String, u16), ApiError> {
    let protocols = Value::Array(vec![Value::Array(vec!["TCPROS".into()])]);
    let v = call(
        publisher_api,
        "requestTopic",
        &[caller_id.into(), topic.into(), protocols],
    )
    .await?;
    let endpoint = v.as_array().and_then(|p| {
        (p.first()?.as_str()? == "TCPROS").then_some(())?;
        let port = u16::try_from(p.get(2)?.as_i32()?).ok()?;
        Some((p.get(1)?.as_str()?.to_owned(), port))
    });
    endpoint.ok_or(ApiError::Unexpected {
        method: "requestTopic".into(),
        uri: publisher_api.into(),
        value: v,
    })
}
