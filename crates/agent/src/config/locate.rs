//! Source positions for configuration fields.
//!
//! The typed structs in [`super`] do not carry spans (they are plain data the rest of the agent
//! uses), so when something is wrong the text is parsed a second time into a [`LocationTree`]:
//! every mapping key and value wrapped in `serde_saphyr::Spanned`. Two questions are answered
//! from it: "where is field `sim.point_cloud.rate_hz`?" (for semantic errors found on the typed
//! value) and "which field is at line 12, column 5?" (for type errors the parser reports with a
//! position but no path). This only runs on the error path; a valid file is parsed once.

use std::fmt;

use serde::Deserialize;
use serde::de::{self, MapAccess, SeqAccess, Visitor};
use serde_saphyr::Spanned;

/// One step of a path into the configuration document.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Segment {
    Key(String),
    Index(usize),
}

/// A path to a field, displayed the way users write it: `sim.point_cloud.rate_hz`,
/// `subscribe[1].hub`, `remap["/map"]`.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub(crate) struct FieldPath(pub(crate) Vec<Segment>);

impl FieldPath {
    pub(crate) fn key(&self, key: impl Into<String>) -> Self {
        let mut segments = self.0.clone();
        segments.push(Segment::Key(key.into()));
        Self(segments)
    }

    pub(crate) fn index(&self, index: usize) -> Self {
        let mut segments = self.0.clone();
        segments.push(Segment::Index(index));
        Self(segments)
    }
}

impl From<&str> for FieldPath {
    /// A dotted path of plain identifiers (`"sim.laser_scan.topic"`).
    fn from(dotted: &str) -> Self {
        Self(
            dotted
                .split('.')
                .map(|k| Segment::Key(k.to_owned()))
                .collect(),
        )
    }
}

impl fmt::Display for FieldPath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0.is_empty() {
            return f.write_str("(document)");
        }
        for (i, segment) in self.0.iter().enumerate() {
            match segment {
                Segment::Key(k) if is_identifier(k) => {
                    if i > 0 {
                        f.write_str(".")?;
                    }
                    f.write_str(k)?;
                }
                Segment::Key(k) => write!(f, "[{k:?}]")?,
                Segment::Index(n) => write!(f, "[{n}]")?,
            }
        }
        Ok(())
    }
}

fn is_identifier(key: &str) -> bool {
    !key.is_empty() && key.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_')
}

/// A 1-based line and column.
pub(crate) type LineCol = (u64, u64);

/// The document's shape with the position of every key and value.
pub(crate) struct LocationTree {
    root: Spanned<Node>,
}

enum Node {
    Map(Vec<(Spanned<String>, Spanned<Node>)>),
    Seq(Vec<Spanned<Node>>),
    Scalar,
}

fn line_col<T>(s: &Spanned<T>) -> LineCol {
    (s.referenced.line(), s.referenced.column())
}

impl LocationTree {
    /// Parses `text`. This accepts any YAML document, so an error here is a syntax error
    /// (reported more precisely than by the typed parse, which may stop at a type mismatch
    /// first).
    pub(crate) fn parse(text: &str) -> Result<Self, serde_saphyr::Error> {
        serde_saphyr::from_str::<Spanned<Node>>(text).map(|root| Self { root })
    }

    /// Whether the document's top-level mapping has key `key` (written, not defaulted).
    pub(crate) fn has_top_key(&self, key: &str) -> bool {
        matches!(&self.root.value, Node::Map(entries) if entries.iter().any(|(k, _)| k.value == key))
    }

    /// The keys of the mapping at `path` (`&[]`: the document's top level), each with its
    /// position; `None` when there is no mapping there.
    pub(crate) fn keys_at(&self, path: &[&str]) -> Option<Vec<(String, LineCol)>> {
        let mut node = &self.root;
        for k in path {
            let Node::Map(entries) = &node.value else {
                return None;
            };
            node = &entries.iter().find(|(key, _)| key.value == *k)?.1;
        }
        match &node.value {
            Node::Map(entries) => Some(
                entries
                    .iter()
                    .map(|(k, _)| (k.value.clone(), line_col(k)))
                    .collect(),
            ),
            _ => None,
        }
    }

    /// Position of the field at `path`: its key when `at_key` (for problems with the key
    /// itself, like a bad topic name in `remap`), otherwise its value. When the path is
    /// only partly present (a default that was never written), the deepest present
    /// ancestor's position.
    pub(crate) fn position_of(&self, path: &FieldPath, at_key: bool) -> LineCol {
        let mut node = &self.root;
        let mut best = line_col(node);
        for (i, segment) in path.0.iter().enumerate() {
            let last = i + 1 == path.0.len();
            let next = match (&node.value, segment) {
                (Node::Map(entries), Segment::Key(k)) => entries
                    .iter()
                    .find(|(key, _)| key.value == *k)
                    .map(|(key, value)| {
                        if last && at_key {
                            (line_col(key), value)
                        } else {
                            (line_col(value), value)
                        }
                    }),
                (Node::Seq(items), Segment::Index(n)) => items.get(*n).map(|v| (line_col(v), v)),
                _ => None,
            };
            match next {
                Some((pos, child)) => {
                    best = pos;
                    node = child;
                }
                None => break,
            }
        }
        best
    }

    /// Whether the document writes the field at `path`: the path is in it, or a shorthand
    /// written in its place holds it (`publish: [/a]` writes `publish.include[0]`, not
    /// `publish.exclude`).
    pub(crate) fn written(&self, path: &FieldPath) -> bool {
        let mut node = &self.root;
        for segment in &path.0 {
            node = match (&node.value, segment) {
                (Node::Map(entries), Segment::Key(k)) => {
                    match entries.iter().find(|(key, _)| key.value == *k) {
                        Some((_, value)) => value,
                        None => return false,
                    }
                }
                (Node::Seq(items), Segment::Index(n)) => match items.get(*n) {
                    Some(item) => item,
                    None => return false,
                },
                // A list or a name written for a section: its main list.
                (Node::Seq(_) | Node::Scalar, Segment::Key(k)) => {
                    return k == "include" || k == "expose";
                }
                // One value written for a list (`hub: ws://…`).
                (Node::Scalar, Segment::Index(0)) => return true,
                _ => return false,
            };
        }
        true
    }

    /// The field at or just before `pos`: an exact key or value position wins; otherwise the
    /// last key or value that starts before `pos` (parser errors inside a value point past
    /// its start).
    pub(crate) fn path_at(&self, pos: LineCol) -> FieldPath {
        let mut found = (FieldPath::default(), (0, 0));
        walk(&self.root, &FieldPath::default(), pos, &mut found);
        found.0
    }
}

/// Visits positions in document order, keeping the latest one at or before `pos`
/// (later and deeper entries at the same position replace earlier ones).
fn walk(node: &Spanned<Node>, path: &FieldPath, pos: LineCol, found: &mut (FieldPath, LineCol)) {
    match &node.value {
        Node::Map(entries) => {
            for (key, value) in entries {
                let child = path.key(key.value.clone());
                for p in [line_col(key), line_col(value)] {
                    if p <= pos && p >= found.1 {
                        *found = (child.clone(), p);
                    }
                }
                walk(value, &child, pos, found);
            }
        }
        Node::Seq(items) => {
            for (i, item) in items.iter().enumerate() {
                let child = path.index(i);
                let p = line_col(item);
                if p <= pos && p >= found.1 {
                    *found = (child.clone(), p);
                }
                walk(item, &child, pos, found);
            }
        }
        Node::Scalar => {}
    }
}

impl<'de> Deserialize<'de> for Node {
    fn deserialize<D: de::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(NodeVisitor)
    }
}

struct NodeVisitor;

impl<'de> Visitor<'de> for NodeVisitor {
    type Value = Node;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("any YAML value")
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Node, A::Error> {
        let mut entries = Vec::new();
        while let Some(key) = map.next_key::<Spanned<KeyText>>()? {
            let value = map.next_value()?;
            let key = Spanned::new(key.value.0, key.referenced, key.defined);
            entries.push((key, value));
        }
        Ok(Node::Map(entries))
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Node, A::Error> {
        let mut items = Vec::new();
        while let Some(item) = seq.next_element()? {
            items.push(item);
        }
        Ok(Node::Seq(items))
    }

    fn visit_bool<E>(self, _: bool) -> Result<Node, E> {
        Ok(Node::Scalar)
    }
    fn visit_i64<E>(self, _: i64) -> Result<Node, E> {
        Ok(Node::Scalar)
    }
    fn visit_u64<E>(self, _: u64) -> Result<Node, E> {
        Ok(Node::Scalar)
    }
    fn visit_i128<E>(self, _: i128) -> Result<Node, E> {
        Ok(Node::Scalar)
    }
    fn visit_u128<E>(self, _: u128) -> Result<Node, E> {
        Ok(Node::Scalar)
    }
    fn visit_f64<E>(self, _: f64) -> Result<Node, E> {
        Ok(Node::Scalar)
    }
    fn visit_str<E>(self, _: &str) -> Result<Node, E> {
        Ok(Node::Scalar)
    }
    fn visit_bytes<E>(self, _: &[u8]) -> Result<Node, E> {
        Ok(Node::Scalar)
    }
    fn visit_unit<E>(self) -> Result<Node, E> {
        Ok(Node::Scalar)
    }
    fn visit_none<E>(self) -> Result<Node, E> {
        Ok(Node::Scalar)
    }
    fn visit_some<D: de::Deserializer<'de>>(self, d: D) -> Result<Node, D::Error> {
        d.deserialize_any(NodeVisitor)
    }
}

/// A mapping key as text, whatever scalar type YAML gave it (`1: x` has an integer key).
struct KeyText(String);

impl<'de> Deserialize<'de> for KeyText {
    fn deserialize<D: de::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct KeyVisitor;
        impl Visitor<'_> for KeyVisitor {
            type Value = KeyText;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a scalar mapping key")
            }
            fn visit_str<E>(self, v: &str) -> Result<KeyText, E> {
                Ok(KeyText(v.to_owned()))
            }
            fn visit_bool<E>(self, v: bool) -> Result<KeyText, E> {
                Ok(KeyText(v.to_string()))
            }
            fn visit_i64<E>(self, v: i64) -> Result<KeyText, E> {
                Ok(KeyText(v.to_string()))
            }
            fn visit_u64<E>(self, v: u64) -> Result<KeyText, E> {
                Ok(KeyText(v.to_string()))
            }
            fn visit_f64<E>(self, v: f64) -> Result<KeyText, E> {
                Ok(KeyText(v.to_string()))
            }
            fn visit_unit<E>(self) -> Result<KeyText, E> {
                Ok(KeyText(String::new()))
            }
        }
        deserializer.deserialize_any(KeyVisitor)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const DOC: &str = "\
name: r1
sim:
  point_cloud: { topic: /points, rate_hz: 0 }
subscribe:
  - hub: /a
    local: /b
remap:
  /map: /fleet/map
";

    #[test]
    fn finds_values_keys_and_ancestors() {
        let tree = LocationTree::parse(DOC).expect("valid yaml");
        assert_eq!(
            tree.position_of(&"sim.point_cloud.rate_hz".into(), false),
            (3, 43)
        );
        assert_eq!(
            tree.position_of(&FieldPath::from("subscribe").index(0).key("local"), false),
            (6, 12)
        );
        assert_eq!(
            tree.position_of(&FieldPath::from("remap").key("/map"), true),
            (8, 3)
        );
        // `sim.laser_scan` is absent: the nearest present ancestor is `sim`'s value.
        assert_eq!(
            tree.position_of(&"sim.laser_scan.rate_hz".into(), false),
            (3, 3)
        );
    }

    #[test]
    fn maps_positions_back_to_paths() {
        let tree = LocationTree::parse(DOC).expect("valid yaml");
        assert_eq!(tree.path_at((3, 43)).to_string(), "sim.point_cloud.rate_hz");
        assert_eq!(tree.path_at((6, 5)).to_string(), "subscribe[0].local");
        assert_eq!(tree.path_at((8, 9)).to_string(), "remap[\"/map\"]");
    }
}
