//! rosapi `typedefs` (what `/rosapi/message_details` answers) turned into the
//! concatenated definition text schemas carry (`.msg` text, then `MSG: pkg/T` sections
//! for the types it uses), so the hub learns a robot type nobody bundled.
//!
//! Design choice: typedefs say field names, types and array lengths, which is all a
//! message's layout needs. They do not say the types of constants, so constants are left
//! out: they are never on the wire, and a definition without them converts the same.

use serde::Deserialize;

/// One entry of a `typedefs` list.
#[derive(Debug, Clone, Deserialize)]
pub struct TypeDef {
    #[serde(rename = "type")]
    pub type_name: String,
    #[serde(default)]
    pub fieldnames: Vec<String>,
    #[serde(default)]
    pub fieldtypes: Vec<String>,
    /// -1 a single value, 0 an unbounded array, N a fixed array of N.
    #[serde(default)]
    pub fieldarraylen: Vec<i64>,
}

#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TypedefsError {
    #[error("typedefs are not a list of type definitions: {0}")]
    Shape(String),
    #[error("typedefs do not define {0}")]
    Missing(String),
    #[error("typedef of {type_name} lists {names} field names but {types} types")]
    Lengths {
        type_name: String,
        names: usize,
        types: usize,
    },
}

/// `pkg/msg/T` or `pkg/T` as `pkg/T` (how definitions name the types they use).
fn short(name: &str) -> String {
    let parts: Vec<&str> = name.split('/').collect();
    match parts[..] {
        [pkg, "msg", t] => format!("{pkg}/{t}"),
        _ => name.to_owned(),
    }
}

/// The full definition text of `type_name` from the server's `typedefs` answer.
pub fn full_text(type_name: &str, typedefs: &serde_json::Value) -> Result<String, TypedefsError> {
    let defs: Vec<TypeDef> = serde_json::from_value(typedefs.clone())
        .map_err(|e| TypedefsError::Shape(e.to_string()))?;
    let find = |name: &str| defs.iter().find(|d| short(&d.type_name) == short(name));
    let main = find(type_name).ok_or_else(|| TypedefsError::Missing(type_name.to_owned()))?;
    let mut out = own_text(main)?;
    // Dependencies depth first in field order, each once (as ROS writes them).
    fn collect<'d>(
        d: &'d TypeDef,
        find: &dyn Fn(&str) -> Option<&'d TypeDef>,
        order: &mut Vec<&'d TypeDef>,
    ) {
        for ty in &d.fieldtypes {
            if let Some(dep) = find(ty)
                && !order.iter().any(|o| std::ptr::eq(*o, dep))
            {
                order.push(dep);
                collect(dep, find, order);
            }
        }
    }
    let mut order: Vec<&TypeDef> = vec![main];
    collect(main, &find, &mut order);
    order.remove(0);
    for dep in order {
        out.push('\n');
        out.push_str(&"=".repeat(80));
        out.push_str(&format!("\nMSG: {}\n", short(&dep.type_name)));
        out.push_str(&own_text(dep)?);
    }
    Ok(out)
}

fn own_text(d: &TypeDef) -> Result<String, TypedefsError> {
    if d.fieldnames.len() != d.fieldtypes.len() {
        return Err(TypedefsError::Lengths {
            type_name: d.type_name.clone(),
            names: d.fieldnames.len(),
            types: d.fieldtypes.len(),
        });
    }
    let mut out = String::new();
    for (i, (name, ty)) in d.fieldnames.iter().zip(&d.fieldtypes).enumerate() {
        let suffix = match d.fieldarraylen.get(i).copied().unwrap_or(-1) {
            n if n < 0 => String::new(),
            0 => "[]".to_owned(),
            n => format!("[{n}]"),
        };
        out.push_str(&format!("{}{suffix} {name}\n", short(ty)));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn nested_types_become_msg_sections() {
        let defs = json!([
            {"type": "geometry_msgs/msg/PoseStamped", "fieldnames": ["header", "pose"],
             "fieldtypes": ["std_msgs/msg/Header", "geometry_msgs/msg/Pose"],
             "fieldarraylen": [-1, -1]},
            {"type": "std_msgs/msg/Header", "fieldnames": ["stamp", "frame_id"],
             "fieldtypes": ["builtin_interfaces/msg/Time", "string"], "fieldarraylen": [-1, -1]},
            {"type": "builtin_interfaces/msg/Time", "fieldnames": ["sec", "nanosec"],
             "fieldtypes": ["int32", "uint32"], "fieldarraylen": [-1, -1]},
            {"type": "geometry_msgs/msg/Pose", "fieldnames": ["c", "d"],
             "fieldtypes": ["float64", "uint8"], "fieldarraylen": [3, 0]},
        ]);
        let text = full_text("geometry_msgs/msg/PoseStamped", &defs).unwrap();
        let line = "=".repeat(80);
        assert_eq!(
            text,
            format!(
                "std_msgs/Header header\ngeometry_msgs/Pose pose\n\n{line}\nMSG: std_msgs/Header\n\
                 builtin_interfaces/Time stamp\nstring frame_id\n\n{line}\nMSG: builtin_interfaces/Time\n\
                 int32 sec\nuint32 nanosec\n\n{line}\nMSG: geometry_msgs/Pose\nfloat64[3] c\nuint8[] d\n"
            )
        );
    }

    #[test]
    fn broken_typedefs_are_errors_naming_the_problem() {
        assert_eq!(
            full_text("a/B", &json!([])).unwrap_err(),
            TypedefsError::Missing("a/B".into())
        );
        let uneven = json!([{"type": "a/B", "fieldnames": ["x"], "fieldtypes": []}]);
        assert_eq!(
            full_text("a/B", &uneven).unwrap_err().to_string(),
            "typedef of a/B lists 1 field names but 0 types"
        );
        assert!(matches!(
            full_text("a/B", &json!({"x": 1})).unwrap_err(),
            TypedefsError::Shape(_)
        ));
    }
}
