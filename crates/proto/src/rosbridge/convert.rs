//! Schema-less conversion between the JSON and CBOR forms of a message object.
//!
//! Without a type definition the mapping follows the rosbridge conventions as far as the
//! data itself shows them: CBOR byte strings become base64 strings in JSON (how rosbridge
//! writes `uint8[]`), RFC 8746 typed arrays become JSON arrays of numbers, and JSON maps,
//! arrays and scalars map one to one. Type-aware conversion (base64 strings back to byte
//! strings, numeric arrays to typed arrays) needs the message registry.

use base64::Engine;
use base64::engine::general_purpose::STANDARD as BASE64;
use serde_json::{Map, Number, Value};

/// Deepest nesting of arrays, maps and tags accepted in a CBOR value: 127 levels, the
/// most serde_json accepts in JSON, so what is accepted in one encoding converts to the
/// other and parses there too. It also keeps a hostile value far from exhausting a
/// thread's stack (ciborium's own default is 256 levels, and each level costs its
/// recursive decoder one to two kilobytes of stack in a debug build).
pub const MAX_DEPTH: usize = 127;

/// Parses one CBOR value, refusing nesting deeper than [`MAX_DEPTH`].
pub fn parse_cbor(bytes: &[u8]) -> Result<ciborium::Value, ConvertError> {
    use ciborium::de::Error;
    ciborium::de::from_reader_with_recursion_limit(bytes, MAX_DEPTH).map_err(|e| {
        // In words a client can act on, without the decoder's internal names.
        ConvertError::Cbor(match e {
            Error::Io(_) => format!(
                "the data ends in the middle of a value ({} bytes received)",
                bytes.len()
            ),
            Error::Syntax(at) => format!("malformed CBOR at byte {at}"),
            Error::Semantic(Some(at), msg) => format!("at byte {at}: {msg}"),
            Error::Semantic(None, msg) => msg,
            Error::RecursionLimitExceeded => {
                format!("values nested deeper than {MAX_DEPTH} levels")
            }
        })
    })
}

/// Why a conversion failed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ConvertError {
    #[error("invalid JSON: {0}")]
    Json(String),
    #[error("invalid CBOR: {0}")]
    Cbor(String),
    #[error("CBOR value has no JSON form: {0}")]
    Unrepresentable(String),
}

/// JSON text of a message object → CBOR bytes of the same object.
pub fn json_to_cbor(json: &[u8]) -> Result<Vec<u8>, ConvertError> {
    let v: Value = serde_json::from_slice(json).map_err(|e| ConvertError::Json(e.to_string()))?;
    let mut out = Vec::with_capacity(json.len());
    ciborium::into_writer(&v, &mut out).map_err(|e| ConvertError::Cbor(e.to_string()))?;
    Ok(out)
}

/// CBOR bytes of a message object → JSON text of the same object.
pub fn cbor_to_json(cbor: &[u8]) -> Result<Vec<u8>, ConvertError> {
    let v = parse_cbor(cbor)?;
    let j = cbor_value_to_json(v)?;
    Ok(serde_json::to_vec(&j).expect("a JSON value serializes"))
}

/// Converts one CBOR value to JSON following the rosbridge conventions.
pub fn cbor_value_to_json(v: ciborium::Value) -> Result<Value, ConvertError> {
    use ciborium::Value as C;
    Ok(match v {
        C::Null => Value::Null,
        C::Bool(b) => Value::Bool(b),
        C::Integer(i) => {
            let i: i128 = i.into();
            if let Ok(u) = u64::try_from(i) {
                Value::Number(u.into())
            } else if let Ok(s) = i64::try_from(i) {
                Value::Number(s.into())
            } else {
                return Err(ConvertError::Unrepresentable(format!(
                    "integer {i} out of 64-bit range"
                )));
            }
        }
        C::Float(f) => Number::from_f64(f)
            .map(Value::Number)
            .unwrap_or(Value::Null),
        C::Text(s) => Value::String(s),
        C::Bytes(b) => Value::String(BASE64.encode(b)),
        C::Array(items) => Value::Array(
            items
                .into_iter()
                .map(cbor_value_to_json)
                .collect::<Result<_, _>>()?,
        ),
        C::Map(entries) => {
            let mut m = Map::with_capacity(entries.len());
            for (k, v) in entries {
                let key = match k {
                    C::Text(s) => s,
                    C::Integer(i) => i128::from(i).to_string(),
                    other => {
                        return Err(ConvertError::Unrepresentable(format!("map key {other:?}")));
                    }
                };
                m.insert(key, cbor_value_to_json(v)?);
            }
            Value::Object(m)
        }
        C::Tag(tag, inner) => typed_array_to_json(tag, *inner)?,
        other => return Err(ConvertError::Unrepresentable(format!("{other:?}"))),
    })
}

/// RFC 8746 typed arrays (tags 64–87) carried as byte strings become arrays of numbers.
fn typed_array_to_json(tag: u64, inner: ciborium::Value) -> Result<Value, ConvertError> {
    let ciborium::Value::Bytes(b) = inner else {
        return cbor_value_to_json(inner);
    };
    // Tag layout (RFC 8746 §2.1): bit 4 = float, bit 3 = signed, bit 2 = little endian,
    // bits 0-1 = log2 of element length (for floats, length 2^(l+1)).
    if !(64..=87).contains(&tag) {
        return Ok(Value::String(BASE64.encode(b)));
    }
    let t = tag - 64;
    let float = t & 0x10 != 0;
    let signed = t & 0x08 != 0;
    let little = t & 0x04 != 0;
    let ll = (t & 0x03) as u32;
    let width = if float { 2usize << ll } else { 1usize << ll };
    if tag == 64 || tag == 68 {
        return Ok(Value::Array(b.into_iter().map(Value::from).collect()));
    }
    if b.len() % width != 0 {
        return Err(ConvertError::Cbor(format!(
            "typed array tag {tag}: {} bytes is not a multiple of {width}",
            b.len()
        )));
    }
    let mut out = Vec::with_capacity(b.len() / width);
    for chunk in b.chunks_exact(width) {
        let mut raw = [0u8; 8];
        if little {
            raw[..width].copy_from_slice(chunk);
        } else {
            for (i, byte) in chunk.iter().rev().enumerate() {
                raw[i] = *byte;
            }
        }
        let bits = u64::from_le_bytes(raw);
        let v = match (float, signed, width) {
            (true, _, 4) => {
                Number::from_f64(f64::from(f32::from_bits(bits as u32))).map(Value::Number)
            }
            (true, _, 8) => Number::from_f64(f64::from_bits(bits)).map(Value::Number),
            (true, _, _) => None,
            (false, false, _) => Some(Value::from(bits)),
            (false, true, w) => {
                let shift = 64 - 8 * w as u32;
                Some(Value::from(((bits << shift) as i64) >> shift))
            }
        };
        out.push(v.unwrap_or(Value::Null));
    }
    Ok(Value::Array(out))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bytes_become_base64_like_rosbridge_uint8_arrays() {
        let mut buf = Vec::new();
        ciborium::into_writer(&ciborium::Value::Bytes(vec![0, 1, 2, 255]), &mut buf).unwrap();
        assert_eq!(cbor_to_json(&buf).unwrap(), br#""AAEC/w==""#);
    }

    #[test]
    fn little_endian_float32_typed_array_decodes() {
        let data: Vec<u8> = [1.5f32, -2.0]
            .iter()
            .flat_map(|f| f.to_le_bytes())
            .collect();
        let v = ciborium::Value::Tag(85, Box::new(ciborium::Value::Bytes(data)));
        assert_eq!(
            cbor_value_to_json(v).unwrap(),
            serde_json::json!([1.5, -2.0])
        );
    }

    #[test]
    fn signed_int16_typed_array_decodes() {
        let data: Vec<u8> = [-3i16, 300].iter().flat_map(|f| f.to_le_bytes()).collect();
        let v = ciborium::Value::Tag(77, Box::new(ciborium::Value::Bytes(data)));
        assert_eq!(cbor_value_to_json(v).unwrap(), serde_json::json!([-3, 300]));
    }

    #[test]
    fn json_round_trips_through_cbor() {
        let j = br#"{"a":[1,2.5,"x",null,true],"b":{"c":-4}}"#;
        let back = cbor_to_json(&json_to_cbor(j).unwrap()).unwrap();
        assert_eq!(
            serde_json::from_slice::<Value>(&back).unwrap(),
            serde_json::from_slice::<Value>(j).unwrap()
        );
    }
}
