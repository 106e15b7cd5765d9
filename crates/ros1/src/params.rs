//! The robot's ROS 1 parameter server, offered to the fleet.
//!
//! With `ros1: parameters: true` (the default) the bridge provides rosapi's parameter
//! services in the agent's call table — `/rosapi/get_param`, `set_param`, `has_param`,
//! `delete_param`, `get_param_names`, `search_param` — answered from the ROS master's
//! parameter API (`getParam`, `setParam`, ...). The agent offers every local service to
//! the hub, so they appear there as `/<robot>/rosapi/...`, and the hub's own
//! `/rosapi/get_param` of `/<robot>/max_speed` is forwarded to them as `/max_speed`
//! (docs/ros1.md, "Parameters"). A local rosbridge client of the agent reaches the same
//! services under their own names.
//!
//! Values travel as rosapi has them: JSON texts. JSON maps onto XML-RPC as rospy's
//! parameter client does it: integers that fit 32 bits are `i4`, other numbers `double`,
//! objects `struct`s, arrays `array`s; `null` has no XML-RPC form and is refused.

use fleetlink_proto::Payload;
use fleetlink_relay::calls::{CallRequest, CallStatus};
use fleetlink_relay::params;
use serde_json::{Value as Json, json};

use crate::master::ApiError;
use crate::node::Node;
use crate::xmlrpc::Value;

/// Answers one call of a parameter service.
pub async fn serve(node: &Node, req: &CallRequest) {
    let (status, payload, text) = match answer(node, req).await {
        Ok(values) => (
            CallStatus::Ok,
            Some(Payload::json(serde_json::to_vec(&values).expect("JSON"))),
            String::new(),
        ),
        Err(text) => (CallStatus::Failed, None, text),
    };
    node.router
        .calls
        .respond(node.client, req.id, status, payload, text);
}

async fn answer(node: &Node, req: &CallRequest) -> Result<Json, String> {
    let args = params::call_args(&req.payload)
        .filter(Json::is_object)
        .ok_or("the arguments must be an object (JSON or CBOR)")?;
    let service = req.service.name.as_str();
    let call = service.strip_prefix("/rosapi/").unwrap_or(service);
    let name = || -> Result<String, String> {
        let n = args.get("name").and_then(Json::as_str).unwrap_or_default();
        params::param_name_or_root(n)
    };
    let master = &node.master;
    Ok(match call {
        "get_param" => {
            let n = name()?;
            match master.call("getParam", vec![n.as_str().into()]).await {
                Ok(v) => json!({"value": to_json(&v).to_string()}),
                // Not set: the caller's default (a JSON text), `null` without one.
                Err(ApiError::Refused { .. }) => json!({"value": params::default_text(&args)}),
                Err(e) => return Err(unreachable_master(&e)),
            }
        }
        "has_param" => {
            let n = name()?;
            let v = master
                .call("hasParam", vec![n.as_str().into()])
                .await
                .map_err(|e| unreachable_master(&e))?;
            json!({"exists": matches!(v, Value::Bool(true))})
        }
        "search_param" => {
            let n = name()?;
            // The master answers a failure when the search finds nothing.
            match master.call("searchParam", vec![n.as_str().into()]).await {
                Ok(v) => json!({"global_name": v.as_str().unwrap_or_default()}),
                Err(ApiError::Refused { .. }) => json!({"global_name": ""}),
                Err(e) => return Err(unreachable_master(&e)),
            }
        }
        "get_param_names" => {
            let v = master
                .call("getParamNames", vec![])
                .await
                .map_err(|e| unreachable_master(&e))?;
            json!({"names": v.as_str_list().unwrap_or_default()})
        }
        "set_param" => {
            let n = name()?;
            let (_, v) = params::value_to_set(&args, &n)?;
            let v = to_xmlrpc(&v).map_err(|e| format!("value of {n}: {e}"))?;
            master
                .call("setParam", vec![n.as_str().into(), v])
                .await
                .map_err(|e| unreachable_master(&e))?;
            json!({})
        }
        "delete_param" => {
            let n = name()?;
            match master.call("deleteParam", vec![n.as_str().into()]).await {
                Ok(_) => json!({}),
                Err(ApiError::Refused { .. }) => return Err(format!("parameter {n} is not set")),
                Err(e) => return Err(unreachable_master(&e)),
            }
        }
        other => return Err(format!("{other} is not a parameter service")),
    })
}

fn unreachable_master(e: &ApiError) -> String {
    format!("the robot's ROS master did not answer: {e}")
}

/// An XML-RPC value as JSON. `base64` and dates are kept as their text.
pub fn to_json(v: &Value) -> Json {
    match v {
        Value::Int(i) => json!(i),
        Value::Bool(b) => json!(b),
        Value::Str(s) | Value::Other(s) => json!(s),
        Value::Double(d) => serde_json::Number::from_f64(*d).map_or(Json::Null, Json::Number),
        Value::Array(items) => Json::Array(items.iter().map(to_json).collect()),
        Value::Struct(members) => Json::Object(
            members
                .iter()
                .map(|(k, v)| (k.clone(), to_json(v)))
                .collect(),
        ),
    }
}

/// A JSON value as the XML-RPC value rospy would send for it.
pub fn to_xmlrpc(v: &Json) -> Result<Value, String> {
    Ok(match v {
        Json::Null => return Err("null cannot be a ROS 1 parameter value".into()),
        Json::Bool(b) => Value::Bool(*b),
        Json::Number(n) => match n.as_i64().and_then(|i| i32::try_from(i).ok()) {
            Some(i) => Value::Int(i),
            None => Value::Double(n.as_f64().ok_or("number out of range")?),
        },
        Json::String(s) => Value::Str(s.clone()),
        Json::Array(items) => Value::Array(items.iter().map(to_xmlrpc).collect::<Result<_, _>>()?),
        Json::Object(m) => Value::Struct(
            m.iter()
                .map(|(k, v)| Ok((k.clone(), to_xmlrpc(v)?)))
                .collect::<Result<_, String>>()?,
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_values_map_onto_xmlrpc_and_back() {
        let v = json!({"speed": 1.5, "n": 3, "big": 5_000_000_000i64, "on": true,
                       "name": "r1", "list": [1, "a"], "nested": {"k": -2}});
        let x = to_xmlrpc(&v).unwrap();
        let Value::Struct(members) = &x else {
            panic!("an object is a struct")
        };
        let get = |k: &str| members.iter().find(|(n, _)| n == k).map(|(_, v)| v.clone());
        assert_eq!(get("n"), Some(Value::Int(3)));
        // Beyond 32 bits: XML-RPC's i4 cannot hold it; rospy sends a double.
        assert_eq!(get("big"), Some(Value::Double(5e9)));
        assert_eq!(get("speed"), Some(Value::Double(1.5)));
        let back = to_json(&x);
        assert_eq!(back["speed"], json!(1.5));
        assert_eq!(back["n"], json!(3));
        assert_eq!(back["list"], json!([1, "a"]));
        assert_eq!(back["nested"], json!({"k": -2}));
        let err = to_xmlrpc(&json!({"a": null})).unwrap_err();
        assert!(err.contains("null"), "{err}");
    }

    #[test]
    fn every_parameter_service_is_recognised_and_others_are_not() {
        for (name, ty, def) in params::SERVICES {
            assert!(params::is_param_service(name));
            assert!(ty.starts_with("rosapi/srv/"));
            assert!(def.contains("---"));
        }
        assert!(!params::is_param_service("/rosapi/topics"));
        assert_eq!(
            params::param_name_or_root("max_speed").unwrap(),
            "/max_speed"
        );
        assert_eq!(params::param_name_or_root("/").unwrap(), "/");
        assert!(params::param_name_or_root("  ").is_err());
    }
}
