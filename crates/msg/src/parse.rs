//! Parser for `.msg`, `.srv` and `.action` texts, ROS 1 and ROS 2 flavours.
//!
//! Design choice: one line-oriented parser accepts the union of both languages (bounded
//! types and default values are simply never present in ROS 1 files); the [`Dialect`]
//! only changes how string constants end, because ROS 1 takes everything after `=`
//! verbatim while ROS 2 allows quotes and trailing comments. Every error carries the
//! source name, line and column.

use crate::error::ParseError;
use crate::name::{InterfaceKind, TypeName};
use crate::spec::{
    ArrayKind, ConstantSpec, Definition, Dialect, Element, FieldSpec, FieldType, MsgSpec, Primitive,
};
use crate::value::Value;

/// Parses one interface file. `name.kind()` says whether it is a msg, srv or action.
pub fn parse_definition(
    name: &TypeName,
    text: &str,
    dialect: Dialect,
) -> Result<Definition, ParseError> {
    let sections = split_sections(text);
    let src = name.to_string();
    let want = match name.kind() {
        InterfaceKind::Msg => 1,
        InterfaceKind::Srv => 2,
        InterfaceKind::Action => 3,
    };
    if sections.len() != want {
        let (line, _) = sections.last().map(|s| (s.0, ())).unwrap_or((1, ()));
        return Err(ParseError {
            source_name: src,
            line,
            column: 1,
            message: format!(
                "a {} has {} section(s) separated by `---`, found {}",
                name.kind().as_str(),
                want,
                sections.len()
            ),
        });
    }
    let part = |i: usize, suffix: &str| -> Result<MsgSpec, ParseError> {
        let (first_line, body) = &sections[i];
        let part_name = name.sibling(format!("{}{}", name.name(), suffix));
        parse_section(&part_name, body, *first_line, dialect)
    };
    Ok(match name.kind() {
        InterfaceKind::Msg => Definition::Msg(part(0, "")?),
        InterfaceKind::Srv => Definition::Srv {
            name: name.clone(),
            request: part(0, "_Request")?,
            response: part(1, "_Response")?,
        },
        InterfaceKind::Action => Definition::Action {
            name: name.clone(),
            goal: part(0, "_Goal")?,
            result: part(1, "_Result")?,
            feedback: part(2, "_Feedback")?,
        },
    })
}

/// Parses a message text (no `---` separators allowed).
pub fn parse_message(name: &TypeName, text: &str, dialect: Dialect) -> Result<MsgSpec, ParseError> {
    match parse_definition(&name.with_kind(InterfaceKind::Msg), text, dialect)? {
        Definition::Msg(mut m) => {
            m.name = name.clone();
            Ok(m)
        }
        _ => unreachable!("a msg kind always parses to Definition::Msg"),
    }
}

/// Splits on lines that are exactly `---`; returns (first line number, text) per section.
fn split_sections(text: &str) -> Vec<(usize, String)> {
    let mut sections = vec![(1usize, String::new())];
    for (i, line) in text.lines().enumerate() {
        if line.trim() == "---" {
            sections.push((i + 2, String::new()));
        } else if let Some((_, body)) = sections.last_mut() {
            body.push_str(line);
            body.push('\n');
        }
    }
    sections
}

fn parse_section(
    name: &TypeName,
    text: &str,
    first_line: usize,
    dialect: Dialect,
) -> Result<MsgSpec, ParseError> {
    let mut spec = MsgSpec {
        name: name.clone(),
        fields: Vec::new(),
        constants: Vec::new(),
        text: text.trim_end_matches('\n').to_owned(),
    };
    let src = name.to_string();
    for (i, line) in text.lines().enumerate() {
        let lineno = first_line + i;
        let err = |column: usize, message: String| ParseError {
            source_name: src.clone(),
            line: lineno,
            column,
            message,
        };
        match parse_line(line, dialect).map_err(|(col, msg)| err(col, msg))? {
            None => {}
            Some(Item::Field(mut f)) => {
                if spec.fields.iter().any(|g| g.name == f.name) {
                    return Err(err(1, format!("field `{}` declared twice", f.name)));
                }
                f.line = lineno;
                spec.fields.push(f);
            }
            Some(Item::Constant(c)) => {
                if spec.constants.iter().any(|g| g.name == c.name) {
                    return Err(err(1, format!("constant `{}` declared twice", c.name)));
                }
                spec.constants.push(c);
            }
        }
    }
    Ok(spec)
}

enum Item {
    Field(FieldSpec),
    Constant(ConstantSpec),
}

type LineError = (usize, String);

/// Column (1-based, in characters) of byte offset `at` in `line`.
fn col(line: &str, at: usize) -> usize {
    line[..at.min(line.len())].chars().count() + 1
}

fn parse_line(line: &str, dialect: Dialect) -> Result<Option<Item>, LineError> {
    let start = line.len() - line.trim_start().len();
    let rest = &line[start..];
    if rest.is_empty() || rest.starts_with('#') {
        return Ok(None);
    }
    let type_len = rest.find(char::is_whitespace).unwrap_or(rest.len());
    let type_text = &rest[..type_len];
    let ty = parse_type(type_text).map_err(|m| (col(line, start), m))?;

    let after_type = start + type_len;
    let name_start =
        after_type + (line[after_type..].len() - line[after_type..].trim_start().len());
    let name_len = line[name_start..]
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(line.len() - name_start);
    let name = &line[name_start..name_start + name_len];
    if name.is_empty() || name_start == after_type {
        return Err((
            col(line, name_start),
            "expected a field or constant name after the type".into(),
        ));
    }
    if !name.starts_with(|c: char| c.is_ascii_alphabetic()) {
        return Err((
            col(line, name_start),
            format!("`{name}` is not a valid name"),
        ));
    }
    let after_name = name_start + name_len;
    let tail = &line[after_name..];
    let tail_trim = tail.trim_start();
    let tail_at = after_name + (tail.len() - tail_trim.len());

    if let Some(value_raw) = tail_trim.strip_prefix('=') {
        let value_at = tail_at + 1;
        let Element::Primitive(prim) = ty.element else {
            return Err((
                col(line, start),
                "constants must have a primitive type".into(),
            ));
        };
        if ty.array != ArrayKind::Single || matches!(prim, Primitive::Time | Primitive::Duration) {
            return Err((
                col(line, start),
                format!("`{type_text}` cannot be a constant type"),
            ));
        }
        let value_text = if matches!(prim, Primitive::String | Primitive::WString) {
            match dialect {
                Dialect::Ros1 => value_raw.trim().to_owned(),
                Dialect::Ros2 => unquote(strip_comment(value_raw).trim())
                    .map_err(|m| (col(line, value_at), m))?,
            }
        } else {
            let v = strip_comment(value_raw).trim().to_owned();
            parse_scalar(prim, &v).map_err(|m| (col(line, value_at), m))?;
            v
        };
        return Ok(Some(Item::Constant(ConstantSpec {
            name: name.to_owned(),
            ty: prim,
            value_text,
        })));
    }
    if !(tail.is_empty() || tail.starts_with(char::is_whitespace) || tail.starts_with('#')) {
        return Err((
            col(line, after_name),
            format!(
                "unexpected `{}` after the name",
                tail.chars().next().unwrap_or(' ')
            ),
        ));
    }
    let default_text = strip_comment(tail_trim).trim();
    let default = if default_text.is_empty() {
        None
    } else {
        if let Element::Named { .. } = ty.element {
            return Err((
                col(line, tail_at),
                "only primitive fields can have default values".into(),
            ));
        }
        Some(default_text.to_owned())
    };
    Ok(Some(Item::Field(FieldSpec {
        name: name.to_owned(),
        ty,
        default,
        line: 0,
    })))
}

/// Removes a trailing `# comment`, ignoring `#` inside quotes.
fn strip_comment(text: &str) -> &str {
    let mut quote: Option<char> = None;
    let mut escaped = false;
    for (i, c) in text.char_indices() {
        match quote {
            Some(q) => {
                if escaped {
                    escaped = false;
                } else if c == '\\' {
                    escaped = true;
                } else if c == q {
                    quote = None;
                }
            }
            None if c == '"' || c == '\'' => quote = Some(c),
            None if c == '#' => return &text[..i],
            None => {}
        }
    }
    text
}

/// `"a\"b"` → `a"b`; unquoted text is returned as is.
pub(crate) fn unquote(text: &str) -> Result<String, String> {
    let Some(q) = text.chars().next().filter(|c| *c == '"' || *c == '\'') else {
        return Ok(text.to_owned());
    };
    if text.len() < 2 || !text.ends_with(q) {
        return Err(format!("unterminated string {text}"));
    }
    let inner = &text[1..text.len() - 1];
    let mut out = String::with_capacity(inner.len());
    let mut chars = inner.chars();
    while let Some(c) = chars.next() {
        if c == '\\' {
            match chars.next() {
                Some('n') => out.push('\n'),
                Some('t') => out.push('\t'),
                Some(other) => out.push(other),
                None => return Err("string ends with a lone backslash".into()),
            }
        } else {
            out.push(c);
        }
    }
    Ok(out)
}

fn parse_type(text: &str) -> Result<FieldType, String> {
    let (base, array) = match text.find('[') {
        Some(open) => {
            let inner = text[open + 1..]
                .strip_suffix(']')
                .ok_or_else(|| format!("`{text}`: array suffix must end with `]`"))?;
            let array = if inner.is_empty() {
                ArrayKind::Unbounded
            } else if let Some(n) = inner.strip_prefix("<=") {
                ArrayKind::Bounded(parse_bound(n, text)?)
            } else {
                ArrayKind::Fixed(parse_bound(inner, text)?)
            };
            (&text[..open], array)
        }
        None => (text, ArrayKind::Single),
    };
    let (base, string_bound) = match base.split_once("<=") {
        Some((b @ ("string" | "wstring"), n)) => (b, Some(parse_bound(n, text)?)),
        Some(_) => return Err(format!("`{text}`: only strings can have a `<=` bound")),
        None => (base, None),
    };
    let element = if let Some(p) = Primitive::from_keyword(base) {
        Element::Primitive(p)
    } else {
        let parts: Vec<&str> = base.split('/').collect();
        let (package, name) = match parts.as_slice() {
            [name] => (None, *name),
            [pkg, name] | [pkg, "msg", name] => (Some((*pkg).to_owned()), *name),
            _ => return Err(format!("`{base}` is not a type name")),
        };
        let ident = |s: &str| {
            s.starts_with(|c: char| c.is_ascii_alphabetic())
                && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        };
        if !ident(name) || !package.as_deref().is_none_or(ident) {
            return Err(format!(
                "`{base}` is neither a built-in type nor a type name"
            ));
        }
        Element::Named {
            package,
            name: name.to_owned(),
        }
    };
    Ok(FieldType {
        element,
        string_bound,
        array,
    })
}

fn parse_bound(n: &str, whole: &str) -> Result<u32, String> {
    n.parse::<u32>()
        .map_err(|_| format!("`{whole}`: `{n}` is not a valid size"))
}

/// Parses a literal for a scalar primitive (constants and default values).
pub(crate) fn parse_scalar(prim: Primitive, text: &str) -> Result<Value, String> {
    let int = |lo: i128, hi: i128| -> Result<i128, String> {
        let v: i128 = text
            .parse()
            .map_err(|_| format!("`{text}` is not an integer"))?;
        if v < lo || v > hi {
            return Err(format!("{text} is out of range for {}", prim.keyword()));
        }
        Ok(v)
    };
    let float = || -> Result<f64, String> {
        text.parse::<f64>()
            .map_err(|_| format!("`{text}` is not a number"))
    };
    // The ranges were checked by `int`, so the casts below cannot truncate.
    Ok(match prim {
        Primitive::Bool => match text.to_ascii_lowercase().as_str() {
            "true" | "1" => Value::Bool(true),
            "false" | "0" => Value::Bool(false),
            _ => return Err(format!("`{text}` is not a bool")),
        },
        Primitive::Int8 => Value::I8(int(i8::MIN.into(), i8::MAX.into())? as i8),
        Primitive::Byte | Primitive::Char | Primitive::UInt8 => {
            Value::U8(int(0, u8::MAX.into())? as u8)
        }
        Primitive::Int16 => Value::I16(int(i16::MIN.into(), i16::MAX.into())? as i16),
        Primitive::UInt16 => Value::U16(int(0, u16::MAX.into())? as u16),
        Primitive::Int32 => Value::I32(int(i32::MIN.into(), i32::MAX.into())? as i32),
        Primitive::UInt32 => Value::U32(int(0, u32::MAX.into())? as u32),
        Primitive::Int64 => Value::I64(int(i64::MIN.into(), i64::MAX.into())? as i64),
        Primitive::UInt64 => Value::U64(int(0, u64::MAX.into())? as u64),
        Primitive::Float32 => Value::F32(float()? as f32),
        Primitive::Float64 => Value::F64(float()?),
        Primitive::String | Primitive::WString => Value::String(unquote(text)?),
        Primitive::Time | Primitive::Duration => {
            return Err(format!("{} cannot have a literal value", prim.keyword()));
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn msg(text: &str) -> Result<MsgSpec, ParseError> {
        let name = TypeName::parse("pkg/T").expect("valid name");
        parse_message(&name, text, Dialect::Ros2)
    }

    #[test]
    fn parses_fields_arrays_bounds_and_defaults() {
        let m =
            msg("# c\nint32 a\nstring<=5 s \"hi\" # note\nfloat64[3] f [1, 2, 3]\nPoint[<=4] p\n")
                .expect("parses");
        assert_eq!(m.fields.len(), 4);
        assert_eq!(m.fields[1].ty.string_bound, Some(5));
        assert_eq!(m.fields[1].default.as_deref(), Some("\"hi\""));
        assert_eq!(m.fields[2].ty.array, ArrayKind::Fixed(3));
        assert_eq!(m.fields[3].ty.array, ArrayKind::Bounded(4));
        assert_eq!(m.fields[3].line, 5);
    }

    #[test]
    fn parses_constants_in_both_dialects() {
        let m = msg("int8 A = -1\nstring S = 'x # y' # comment\n").expect("parses");
        assert_eq!(m.constants[0].value_text, "-1");
        assert_eq!(m.constants[1].value_text, "x # y");
        let name = TypeName::parse("pkg/T").expect("valid name");
        let r1 = parse_message(&name, "string S = a # not a comment  \n", Dialect::Ros1)
            .expect("parses");
        assert_eq!(r1.constants[0].value_text, "a # not a comment");
    }

    #[test]
    fn errors_name_source_line_and_column() {
        let e = msg("int32 a\n  flaot32[x] b\n").expect_err("bad type");
        assert_eq!((e.line, e.column), (2, 3));
        assert!(e.to_string().starts_with("pkg/msg/T:2:3:"), "{e}");
        let e = msg("int8 A = 300\n").expect_err("out of range");
        assert_eq!((e.line, e.column), (1, 9));
        let e = msg("int32\n").expect_err("no name");
        assert_eq!(e.line, 1);
    }

    #[test]
    fn splits_services_and_actions() {
        let n = TypeName::parse("pkg/srv/S").expect("valid name");
        let d = parse_definition(&n, "int64 a\n---\nint64 sum\n", Dialect::Ros2).expect("parses");
        let Definition::Srv {
            request, response, ..
        } = d
        else {
            panic!("not a srv")
        };
        assert_eq!(request.name.name(), "S_Request");
        assert_eq!(response.fields[0].name, "sum");
        let n = TypeName::parse("pkg/action/A").expect("valid name");
        assert!(parse_definition(&n, "int32 x\n---\n", Dialect::Ros2).is_err());
    }
}
