//! Binary Inventor (`#Inventor V1.0 / V2.0 / V2.1 binary`) read into the
//! same node tree the ASCII parser makes, so one builder serves both.
//!
//! The format (Inventor Mentor/Toolmaker; Coin's `SoInput`, `SoBase`,
//! `SoFieldData` and `SoField` readers follow it): everything is big-endian
//! 32-bit words after the header line. A string is its length, then its
//! bytes padded to a whole word. A node is its type name (or `DEF` name
//! type, `USE` name, `NULL`); from 2.1 on a flags word (group, engine);
//! then a word whose low byte counts the fields written (and whose bit
//! 0x4000 says the node is not built in: a type name and a field name per
//! field follow); then per field its name, its value and a flags word
//! (ignored, connected — a connection's engine and output follow —,
//! default). A group's children follow as a count and the nodes. Values
//! are raw: a multiple-value field is a count and the values, so the
//! reader must know each built-in field's type (`binary_fields`).
//!
//! Hostile input: every count is checked against the bytes left before
//! anything is allocated, strings are at most [`MAX_STRING`] bytes, nodes,
//! numbers and nesting are charged to the same input budget as ASCII
//! files. Errors carry the byte offset they were found at.

use super::binary_fields::{self, FieldType, Single};
use crate::format::lexer::Pos;
use crate::format::limits::{self, Limit, LimitError};
use crate::format::syntax::{AstNode, Field, NodeRef, Parsed, Value};
use std::collections::HashMap;
use std::rc::Rc;

/// Longest string accepted (Coin's limit is 10 KiB; Info strings may
/// hold an animed key note, so allow more).
const MAX_STRING: usize = 1 << 20;
/// A node's binary flags word: it is a group (children follow).
const IS_GROUP: u32 = 0x02;
/// A field flags word: a connection follows the value.
const CONNECTED: u32 = 0x02;
/// The fields word: the node is not built in (descriptions follow).
const NOT_BUILT_IN: u32 = 0x40;

/// A read error: the byte offset and what was wrong there.
pub type Error = (usize, String);
type R<T> = Result<T, Error>;

/// Reads a binary Inventor file into parsed nodes (routes, warnings and
/// X3D statements stay empty).
pub fn parse(bytes: &[u8]) -> R<Parsed> {
    let end = bytes
        .iter()
        .position(|&b| b == b'\n')
        .ok_or((0, "no end to the header line".to_string()))?;
    let header = String::from_utf8_lossy(&bytes[..end]);
    let version = match header.split_whitespace().nth(1) {
        Some("V1.0") => 1.0,
        Some("V2.0") => 2.0,
        Some("V2.1") => 2.1,
        v => {
            return Err((
                0,
                format!("unsupported binary Inventor version {}", v.unwrap_or("?")),
            ))
        }
    };
    let mut r = Reader {
        bytes,
        at: end + 1,
        version,
        defs: HashMap::new(),
        depth: 0,
        max_depth: limits::depth_left() as usize,
    };
    let mut roots = Vec::new();
    while r.left() >= 4 {
        // Inventor 1.0 ends its files with 0xffffffff.
        if r.peek_u32() == Some(u32::MAX) {
            break;
        }
        if let Some(n) = r.node()? {
            roots.push(n);
        }
    }
    if (1..4).contains(&r.left()) {
        return r.err(r.at, format!("{} stray bytes at the end", r.left()));
    }
    Ok(Parsed {
        roots,
        ..Parsed::default()
    })
}

struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
    version: f32,
    defs: HashMap<String, NodeRef>,
    depth: usize,
    max_depth: usize,
}

impl Reader<'_> {
    fn left(&self) -> usize {
        self.bytes.len().saturating_sub(self.at)
    }

    fn err<T>(&self, at: usize, msg: impl Into<String>) -> R<T> {
        Err((at, msg.into()))
    }

    fn peek_u32(&self) -> Option<u32> {
        let b = self.bytes.get(self.at..self.at + 4)?;
        Some(u32::from_be_bytes([b[0], b[1], b[2], b[3]]))
    }

    fn u32(&mut self) -> R<u32> {
        let v = self
            .peek_u32()
            .ok_or((self.at, "unexpected end of file".to_string()))?;
        self.at += 4;
        Ok(v)
    }

    fn f32(&mut self) -> R<f32> {
        self.u32().map(f32::from_bits)
    }

    fn f64(&mut self) -> R<f64> {
        let hi = self.u32()? as u64;
        let lo = self.u32()? as u64;
        Ok(f64::from_bits(hi << 32 | lo))
    }

    /// A count of items of at least `size` bytes each, checked against the
    /// bytes left (so nothing is allocated for a count the file cannot hold).
    fn count(&mut self, size: usize, what: &str) -> R<usize> {
        let at = self.at;
        let n = self.u32()? as usize;
        if n.saturating_mul(size.max(1)) > self.left() {
            return self.err(at, format!("{what} count {n} is more than the file holds"));
        }
        Ok(n)
    }

    fn string(&mut self) -> R<String> {
        let at = self.at;
        let n = self.u32()? as usize;
        if n > MAX_STRING {
            return self.err(at, format!("string of {n} bytes (at most {MAX_STRING})"));
        }
        let padded = n.div_ceil(4) * 4;
        if padded > self.left() {
            return self.err(
                at,
                format!("string of {n} bytes runs past the end of the file"),
            );
        }
        let s = String::from_utf8_lossy(&self.bytes[self.at..self.at + n]).into_owned();
        self.at += padded;
        Ok(s)
    }

    fn pos(at: usize) -> Pos {
        // Binary files have no lines: line 0 marks a byte offset.
        Pos {
            line: 0,
            column: at.min(u32::MAX as usize) as u32,
        }
    }

    /// One node statement (`None` for NULL).
    fn node(&mut self) -> R<Option<NodeRef>> {
        let at = self.at;
        let word = self.string()?;
        let (def, kind) = match word.as_str() {
            "USE" => {
                let name = self.string()?;
                return match self.defs.get(&name) {
                    Some(n) => Ok(Some(n.clone())),
                    None => self.err(at, format!("USE of undefined name '{name}'")),
                };
            }
            "NULL" => return Ok(None),
            "DEF" => {
                let name = self.string()?;
                (Some(name), self.string()?)
            }
            _ => (None, word),
        };
        if kind.is_empty() || !kind.bytes().all(|b| b.is_ascii_graphic()) {
            return self.err(at, "expected a node type name");
        }
        limits::charge_nodes(1).map_err(|e| (at, e.to_string()))?;
        if self.depth >= self.max_depth {
            let e = limits::trip(LimitError {
                limit: Limit::Depth,
                max: limits::current().max_depth,
            });
            return self.err(at, e.to_string());
        }
        self.depth += 1;
        let r = self.node_body(kind, def, at);
        self.depth -= 1;
        let node = Rc::new(r?);
        if let Some(name) = &node.def {
            self.defs.insert(name.clone(), node.clone());
        }
        Ok(Some(node))
    }

    fn node_body(&mut self, kind: String, def: Option<String>, at: usize) -> R<AstNode> {
        let flags = if self.version > 2.0 { self.u32()? } else { 0 };
        let group = binary_fields::is_group(&kind) || flags & IS_GROUP != 0;
        // Inventor 1.0 groups, and 2.0 plain Groups, write no fields word.
        let no_fields = group && (self.version < 2.0 || (self.version < 2.1 && kind == "Group"));
        let mut fields = if no_fields {
            Vec::new()
        } else {
            self.fields(&kind)?
        };
        if group {
            let cat = self.at;
            let n = self.count(8, "child")?;
            let mut children = Vec::with_capacity(n);
            for _ in 0..n {
                if let Some(c) = self.node()? {
                    children.push(c);
                }
            }
            fields.push(Field {
                name: "children".into(),
                value: Value::Nodes(children),
                pos: Self::pos(cat),
            });
        }
        let height = AstNode::height_of(&fields, None);
        Ok(AstNode {
            kind,
            def,
            fields,
            pos: Self::pos(at),
            proto: None,
            height,
        })
    }

    /// The fields word, the field descriptions of a node that is not built
    /// in, and the fields.
    fn fields(&mut self, kind: &str) -> R<Vec<Field>> {
        let word = self.u32()?;
        let count = (word & 0xff) as usize;
        let mut own: Vec<(String, FieldType)> = Vec::new();
        if (word >> 8) & NOT_BUILT_IN != 0 {
            for _ in 0..count {
                let at = self.at;
                let mut ty = self.string()?;
                if matches!(
                    ty.as_str(),
                    "field" | "exposedField" | "eventIn" | "eventOut"
                ) {
                    ty = self.string()?;
                }
                let name = self.string()?;
                let t = FieldType::from_name(&ty)
                    .ok_or((at, format!("unknown field type '{ty}' in '{kind}'")))?;
                own.push((name, t));
            }
        }
        let mut fields = Vec::with_capacity(count);
        for _ in 0..count {
            let at = self.at;
            let name = self.string()?;
            let ty = own
                .iter()
                .find(|(n, _)| *n == name)
                .map(|&(_, t)| t)
                .or_else(|| binary_fields::field_type(kind, &name));
            let Some(ty) = ty else {
                let why = if binary_fields::field_type(kind, "").is_none()
                    && !binary_fields::is_group(kind)
                {
                    format!("'{kind}' is not a node this reader knows the fields of")
                } else {
                    format!("'{kind}' has no field '{name}' this reader knows the type of")
                };
                return self.err(
                    at,
                    format!("{why}, so the rest of the binary file cannot be read"),
                );
            };
            let value = self.value(ty)?;
            let flags = self.u32()?;
            if flags & CONNECTED != 0 {
                let cat = self.at;
                let engine = self.node()?;
                let output = self.string()?;
                if let Some(e) = engine {
                    fields.push(Field {
                        name: format!("{name}={output}"),
                        value: Value::Nodes(vec![e]),
                        pos: Self::pos(cat),
                    });
                }
            }
            fields.push(Field {
                name,
                value,
                pos: Self::pos(at),
            });
        }
        Ok(fields)
    }

    /// One field value of type `ty`, as the ASCII parser would hold it.
    fn value(&mut self, ty: FieldType) -> R<Value> {
        Ok(match ty {
            FieldType::Multi(one) => {
                let size = match one {
                    Single::Floats(k) | Single::Ints(k) => 4 * k as usize,
                    Single::Double => 8,
                    _ => 4,
                };
                let n = self.count(size, "value")?;
                self.values(one, n)?
            }
            FieldType::Floats(k) => self.values(Single::Floats(k), 1)?,
            FieldType::Ints(k) => self.values(Single::Ints(k), 1)?,
            FieldType::Double => self.values(Single::Double, 1)?,
            FieldType::Bool => self.values(Single::Bool, 1)?,
            FieldType::Name => self.values(Single::Name, 1)?,
            FieldType::String => self.values(Single::String, 1)?,
            FieldType::Node => self.values(Single::Node, 1)?,
            FieldType::BitMask => {
                let mut words = Vec::new();
                loop {
                    let w = self.string()?;
                    if w.is_empty() {
                        break;
                    }
                    if words.len() >= 64 {
                        return self.err(self.at, "bit mask of more than 64 names");
                    }
                    words.push(w);
                }
                Value::Words(words)
            }
            FieldType::Image => self.image()?,
        })
    }

    /// `n` values of one single-value type.
    fn values(&mut self, one: Single, n: usize) -> R<Value> {
        let at = self.at;
        let numbers = match one {
            Single::Floats(k) | Single::Ints(k) => n * k as usize,
            Single::Double => n,
            _ => 0,
        };
        limits::charge_numbers(numbers as u64).map_err(|e| (at, e.to_string()))?;
        Ok(match one {
            Single::Floats(_) => Value::Nums(self.many(numbers, |r| r.f32().map(f64::from))?),
            Single::Ints(_) => {
                Value::Nums(self.many(numbers, |r| r.u32().map(|v| v as i32 as f64))?)
            }
            Single::Double => Value::Nums(self.many(numbers, Self::f64)?),
            Single::Bool => Value::Words(self.many(n, |r| {
                r.u32()
                    .map(|v| if v != 0 { "TRUE" } else { "FALSE" }.to_string())
            })?),
            Single::Name => Value::Words(self.many(n, Self::string)?),
            Single::String => Value::Strs(self.many(n, Self::string)?),
            Single::Node => Value::Nodes(self.many(n, Self::node)?.into_iter().flatten().collect()),
        })
    }

    /// `n` items read by `one` (`n` was checked against the bytes left).
    fn many<T>(&mut self, n: usize, mut one: impl FnMut(&mut Self) -> R<T>) -> R<Vec<T>> {
        let mut v = Vec::with_capacity(n);
        for _ in 0..n {
            v.push(one(self)?);
        }
        Ok(v)
    }

    /// SFImage: width, height, components, then the pixels — one word per
    /// pixel before 2.1, packed bytes padded to a word from 2.1 on — as
    /// the ASCII form's numbers (one integer per pixel).
    fn image(&mut self) -> R<Value> {
        let at = self.at;
        let (w, h, nc) = (
            self.u32()? as usize,
            self.u32()? as usize,
            self.u32()? as usize,
        );
        if nc > 4 || (w.saturating_mul(h) > 0 && nc == 0) {
            return self.err(at, format!("image of {nc} components"));
        }
        let pixels = w.saturating_mul(h);
        let bytes = if self.version >= 2.1 {
            pixels.saturating_mul(nc).div_ceil(4).saturating_mul(4)
        } else {
            pixels.saturating_mul(4)
        };
        if bytes > self.left() {
            return self.err(
                at,
                format!("image of {w}×{h} pixels runs past the end of the file"),
            );
        }
        limits::charge_numbers(pixels as u64 + 3).map_err(|e| (at, e.to_string()))?;
        let mut v = Vec::with_capacity(pixels + 3);
        v.extend([w as f64, h as f64, nc as f64]);
        let data = &self.bytes[self.at..self.at + bytes];
        for p in 0..pixels {
            let px = if self.version >= 2.1 {
                data[p * nc..p * nc + nc]
                    .iter()
                    .fold(0u32, |acc, &b| acc << 8 | b as u32)
            } else {
                let b = &data[p * 4..p * 4 + 4];
                u32::from_be_bytes([b[0], b[1], b[2], b[3]])
            };
            v.push(px as f64);
        }
        self.at += bytes;
        Ok(Value::Nums(v))
    }
}
