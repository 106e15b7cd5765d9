//! Type names: parsing the forms people and peers use, and the DDS mangled form.
//!
//! Design choice: one [`TypeName`] value normalises `pkg/T`, `pkg/msg/T` and
//! `pkg::msg::dds_::T_`; the registry keys on `(package, name)` only, so all spellings
//! resolve to the same definition. The interface kind (`msg`, `srv`, `action`) is kept
//! for display and DDS names but is not part of identity.

use std::fmt;

use crate::error::RegistryError;

/// Which kind of interface file a type comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum InterfaceKind {
    Msg,
    Srv,
    Action,
}

impl InterfaceKind {
    /// The namespace word: `msg`, `srv` or `action`.
    pub fn as_str(self) -> &'static str {
        match self {
            InterfaceKind::Msg => "msg",
            InterfaceKind::Srv => "srv",
            InterfaceKind::Action => "action",
        }
    }
}

/// Packages whose types only ROS 1 programs exchange ([`TypeName::is_ros1_only`]):
/// actionlib's, whose clients and servers talk over topics (`actionlib_msgs` also ships
/// in ROS 2's common interfaces, for bridges, but ROS 2's own actions do not use it),
/// and other ROS 1 tools' messages.
pub const ROS1_PACKAGES: &[&str] = &[
    "actionlib",
    "actionlib_msgs",
    "actionlib_tutorials",
    "dynamic_reconfigure",
    "move_base_msgs",
    "roscpp",
    "rospy_tutorials",
    "smach_msgs",
    "tf",
    "topic_tools",
];

/// A fully qualified ROS type name, e.g. `sensor_msgs/msg/PointCloud2`.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TypeName {
    package: String,
    kind: InterfaceKind,
    name: String,
}

fn valid_ident(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic())
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

impl TypeName {
    /// Builds a name from its parts, checking they are identifiers.
    pub fn new(package: &str, kind: InterfaceKind, name: &str) -> Result<Self, RegistryError> {
        if !valid_ident(package) {
            return Err(RegistryError::BadName {
                name: format!("{package}/{name}"),
                reason: "package is not an identifier",
            });
        }
        if !valid_ident(name) {
            return Err(RegistryError::BadName {
                name: format!("{package}/{name}"),
                reason: "type is not an identifier",
            });
        }
        Ok(TypeName {
            package: package.to_owned(),
            kind,
            name: name.to_owned(),
        })
    }

    /// Parses `pkg/T`, `pkg/msg/T`, `pkg/srv/T`, `pkg/action/T` or a DDS name
    /// (`pkg::msg::dds_::T_`). A missing kind means `msg`.
    pub fn parse(text: &str) -> Result<Self, RegistryError> {
        let text = text.trim();
        if text.contains("::") {
            return from_dds_name(text);
        }
        let parts: Vec<&str> = text.split('/').collect();
        match parts.as_slice() {
            [pkg, name] => TypeName::new(pkg, InterfaceKind::Msg, name),
            [pkg, kind, name] => {
                let kind = match *kind {
                    "msg" => InterfaceKind::Msg,
                    "srv" => InterfaceKind::Srv,
                    "action" => InterfaceKind::Action,
                    _ => {
                        return Err(RegistryError::BadName {
                            name: text.to_owned(),
                            reason: "middle part must be msg, srv or action",
                        });
                    }
                };
                TypeName::new(pkg, kind, name)
            }
            _ => Err(RegistryError::BadName {
                name: text.to_owned(),
                reason: "expected pkg/Type or pkg/msg/Type",
            }),
        }
    }

    pub fn package(&self) -> &str {
        &self.package
    }
    pub fn kind(&self) -> InterfaceKind {
        self.kind
    }
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The same name with another kind (used for service and action parts).
    pub fn with_kind(&self, kind: InterfaceKind) -> Self {
        TypeName {
            kind,
            ..self.clone()
        }
    }

    /// A sibling type in the same package and kind, e.g. `Fibonacci_Goal`.
    pub fn sibling(&self, name: String) -> Self {
        TypeName {
            package: self.package.clone(),
            kind: self.kind,
            name,
        }
    }

    /// Whether only ROS 1 has this type, so that rosbridge clients meet it with ROS 1's
    /// field names (time as `{secs, nsecs}`, a header with `seq`): a type of a package
    /// only ROS 1's tools use ([`ROS1_PACKAGES`]), or one that ROS 1's actionlib
    /// generates for an action (`FooActionGoal`, `FooActionResult`, `FooActionFeedback`;
    /// ROS 2 actions have no such messages).
    pub fn is_ros1_only(&self) -> bool {
        ROS1_PACKAGES.contains(&self.package.as_str())
            || (self.kind == InterfaceKind::Msg
                && ["ActionGoal", "ActionResult", "ActionFeedback"]
                    .iter()
                    .any(|s| self.name.len() > s.len() && self.name.ends_with(s)))
    }

    /// `pkg/T`, the ROS 1 and rosbridge form.
    pub fn short(&self) -> String {
        format!("{}/{}", self.package, self.name)
    }

    /// `pkg::msg::dds_::T_`, the name ROS 2 gives the type on DDS.
    pub fn dds_name(&self) -> String {
        format!(
            "{}::{}::dds_::{}_",
            self.package,
            self.kind.as_str(),
            self.name
        )
    }

    pub(crate) fn key(&self) -> (String, String) {
        (self.package.clone(), self.name.clone())
    }
}

impl fmt::Display for TypeName {
    /// `pkg/msg/T`, the ROS 2 form.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}/{}", self.package, self.kind.as_str(), self.name)
    }
}

impl std::str::FromStr for TypeName {
    type Err = RegistryError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        TypeName::parse(s)
    }
}

/// `pkg/msg/T` → `pkg::msg::dds_::T_`. Service parts (`pkg/srv/T_Request`) and action
/// parts (`pkg/action/T_Goal`, `T_SendGoal_Request`, ...) follow the same rule.
pub fn ros2_dds_name(type_name: &str) -> Result<String, RegistryError> {
    Ok(TypeName::parse(type_name)?.dds_name())
}

/// `pkg::msg::dds_::T_` → `pkg/msg/T`.
pub fn from_dds_name(dds: &str) -> Result<TypeName, RegistryError> {
    let bad = |reason| RegistryError::BadName {
        name: dds.to_owned(),
        reason,
    };
    let parts: Vec<&str> = dds.split("::").collect();
    let [pkg, kind, dds_, name] = parts.as_slice() else {
        return Err(bad("expected pkg::kind::dds_::Type_"));
    };
    if *dds_ != "dds_" {
        return Err(bad("third part must be dds_"));
    }
    let name = name
        .strip_suffix('_')
        .ok_or_else(|| bad("type must end with _"))?;
    let kind = match *kind {
        "msg" => InterfaceKind::Msg,
        "srv" => InterfaceKind::Srv,
        "action" => InterfaceKind::Action,
        _ => return Err(bad("kind must be msg, srv or action")),
    };
    TypeName::new(pkg, kind, name)
}
