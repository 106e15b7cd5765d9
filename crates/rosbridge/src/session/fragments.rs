//! Operations a client sends cut into `fragment`s, held until they are whole and then
//! parsed. Apart because nothing else in the session touches the pieces.

use super::*;

/// Fragmented operations in progress, bounded: a client cannot make the session hold more
/// than a few partial operations, nor more bytes than one whole message may have.
#[derive(Default)]
pub(super) struct Fragments {
    parts: HashMap<String, (Vec<Option<String>>, usize)>,
}

/// Partial operations one session may have at once.
const MAX_FRAGMENTED: usize = 16;
/// Pieces one operation may be cut into.
const MAX_PIECES: u32 = 100_000;

impl Fragments {
    /// Adds a piece; returns the whole operation's text once every piece arrived.
    fn add(
        &mut self,
        id: String,
        data: String,
        num: u32,
        total: u32,
        max_bytes: usize,
    ) -> Result<Option<String>, String> {
        if total == 0 || total > MAX_PIECES {
            self.parts.remove(&id);
            return Err(format!(
                "fragment: 'total' must be 1 to {MAX_PIECES}, got {total}"
            ));
        }
        if num >= total {
            return Err(format!(
                "fragment: 'num' {num} is not below 'total' {total}"
            ));
        }
        if !self.parts.contains_key(&id) && self.parts.len() >= MAX_FRAGMENTED {
            return Err(format!(
                "fragment: {MAX_FRAGMENTED} fragmented operations are already in progress; \
                 finish one first"
            ));
        }
        let entry = self
            .parts
            .entry(id.clone())
            .or_insert_with(|| (vec![None; total as usize], 0));
        if entry.0.len() != total as usize {
            self.parts.remove(&id);
            return Err(format!(
                "fragment {id}: 'total' changed between pieces; the operation is dropped"
            ));
        }
        let slot = &mut entry.0[num as usize];
        let old = slot.as_ref().map_or(0, String::len);
        entry.1 = entry.1 - old + data.len();
        *slot = Some(data);
        if entry.1 > max_bytes {
            self.parts.remove(&id);
            return Err(format!(
                "fragment {id}: the operation is larger than {max_bytes} bytes; it is dropped"
            ));
        }
        if entry.0.iter().all(Option::is_some) {
            let (pieces, _) = self.parts.remove(&id).expect("present above");
            return Ok(Some(pieces.into_iter().flatten().collect()));
        }
        Ok(None)
    }
}

impl Session {
    /// A `fragment` op: kept until its operation is whole, which is then parsed.
    pub(super) fn fragment(&mut self, req: Request) -> Option<Result<Request, ParseError>> {
        let id = req.id.clone();
        let Op::Fragment { data, num, total } = req.op else {
            return Some(Ok(req));
        };
        let fid = match &id {
            Some(Value::String(s)) => s.clone(),
            Some(other) => other.to_string(),
            None => {
                return Some(Err(ParseError {
                    id: None,
                    op: Some("fragment".into()),
                    message: "fragment: missing field 'id' (it names the operation the pieces \
                              make up)"
                        .into(),
                }));
            }
        };
        let err = |message: String| ParseError {
            id: id.clone(),
            op: Some("fragment".into()),
            message,
        };
        match self
            .fragments
            .add(fid, data, num, total, self.cfg.max_message_size)
        {
            Ok(None) => None,
            Ok(Some(text)) => Some(Request::from_json(text.as_bytes())),
            Err(e) => Some(Err(err(e))),
        }
    }
}
