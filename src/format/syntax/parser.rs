//! The generic classic-syntax parser: nodes, DEF/USE, untyped field values,
//! and (VRML97) PROTO, EXTERNPROTO and ROUTE statements.
//!
//! Hostile input is bounded: nesting depth, numbers per field and the total
//! number of nodes (PROTO expansion included) have limits. A syntax error
//! stops parsing but keeps every node read so far (see [`Parsed::error`]).

use super::checks;
use super::node_table::Access;
use super::proto::{expand, ProtoDef};
use super::value_types;
use super::x3d_table;
use super::{AstNode, Field, NodeRef, Parsed, Route, Unit, Value, X3dHead};
use crate::format::lexer::{LexError, Lexer, Pos, Tok};
use crate::format::limits::{self, Limit, LimitError};
use std::collections::HashMap;
use std::rc::Rc;

mod interfaces;
use interfaces::Typed;

/// Dialect switches and limits. Nodes and numbers are counted against the
/// running load's budget ([`limits`]); the depth left for this file is
/// taken from it when the options are made.
#[derive(Clone, Debug)]
pub struct Options {
    /// VRML97: PROTO/EXTERNPROTO/ROUTE statements and interface declarations.
    pub vrml97: bool,
    /// Levels of nesting this file may use (PROTO expansion included).
    pub max_depth: usize,
    /// X3D classic: PROFILE, COMPONENT, UNIT, META, IMPORT and EXPORT
    /// statements.
    pub x3d: bool,
    /// Run on every node as it is made (the X3D reader maps its nodes onto
    /// VRML97 ones here, so one scene builder serves both).
    pub rewrite: Option<Rewrite>,
}

/// A reader's node rewrite: changes a freshly parsed node in place, may
/// add warnings. PROTO instances are not passed to it (their roots are).
pub type Rewrite = fn(&mut AstNode, &X3dHead, &mut Vec<(Pos, String)>);

impl Options {
    pub fn new(vrml97: bool) -> Self {
        Options {
            vrml97,
            max_depth: limits::depth_left() as usize,
            x3d: false,
            rewrite: None,
        }
    }
}

type PResult<T> = Result<T, (Pos, String)>;

/// `nan`, `inf`, `infinity` (any case, any sign) where a value stands:
/// VRML has no such numbers, and reading them as words would silently
/// give the field its default.
fn not_a_number_word(w: &str, pos: Pos) -> PResult<()> {
    let bare = w.trim_start_matches(['+', '-']).to_ascii_lowercase();
    if matches!(bare.as_str(), "nan" | "inf" | "infinity") {
        return Err((
            pos,
            format!("'{w}' is not a number VRML allows (field values must be finite)"),
        ));
    }
    Ok(())
}

fn lex_err(e: LexError) -> (Pos, String) {
    (e.pos, e.message)
}

struct Scope {
    defs: HashMap<String, NodeRef>,
    protos: HashMap<String, Rc<ProtoDef>>,
    /// EXTERNPROTO name → its interface's field names.
    externs: HashMap<String, Vec<String>>,
    /// PROTO and EXTERNPROTO name → its typed interface (ROUTE/IS checks).
    interfaces: HashMap<String, Rc<Vec<Typed>>>,
    routes: Vec<Route>,
}

impl Scope {
    fn new() -> Self {
        Scope {
            defs: HashMap::new(),
            protos: HashMap::new(),
            externs: HashMap::new(),
            interfaces: HashMap::new(),
            routes: Vec::new(),
        }
    }
}

pub(super) struct Parser<'a> {
    lx: Lexer<'a>,
    opts: Options,
    depth: usize,
    pub(super) nodes: usize,
    scopes: Vec<Scope>,
    /// Interfaces (keyword, type, name) of the PROTOs whose bodies are being
    /// read, innermost last: what an IS may name.
    ifaces: Vec<Vec<(String, String, String)>>,
    /// The interfaces Script nodes declare, innermost Script last while
    /// they are read; then by node (kept alive beside its address).
    script_decls: Vec<Vec<Typed>>,
    node_ifaces: HashMap<*const AstNode, (NodeRef, Rc<Vec<Typed>>)>,
    /// X3D nodes the reader's rewrite gave another type (IndexedTriangleSet
    /// → IndexedFaceSet…), by node, with the type the file wrote: what
    /// ROUTEs to them are checked against.
    written_kinds: HashMap<*const AstNode, (NodeRef, String)>,
    warnings: Vec<(Pos, String)>,
    head: X3dHead,
    /// The engine output the last field value was connected from
    /// (Inventor's `field value = Engine { … } . output`), for the node
    /// body to keep beside the field.
    connection: Option<(NodeRef, String)>,
}

/// Parses a whole file body (the header line is a comment to the lexer).
pub fn parse(src: &[u8], opts: Options) -> Parsed {
    let mut p = Parser {
        lx: Lexer::new(src),
        opts,
        depth: 0,
        nodes: 0,
        scopes: vec![Scope::new()],
        ifaces: Vec::new(),
        script_decls: Vec::new(),
        node_ifaces: HashMap::new(),
        written_kinds: HashMap::new(),
        warnings: Vec::new(),
        head: X3dHead::default(),
        connection: None,
    };
    let mut roots = Vec::new();
    let error = p.statements(&mut roots, true).err();
    let scope = p.scopes.pop().unwrap_or_else(Scope::new);
    Parsed {
        roots,
        routes: scope.routes,
        warnings: p.warnings,
        error,
        x3d: p.head,
    }
}

impl Parser<'_> {
    fn peek(&mut self) -> PResult<Tok> {
        self.lx.peek().map(|t| t.tok.clone()).map_err(lex_err)
    }

    fn peek_is_ident(&mut self, word: &str) -> bool {
        matches!(self.lx.peek(), Ok(t) if matches!(&t.tok, Tok::Ident(s) if s == word))
    }

    fn next(&mut self) -> PResult<(Tok, Pos)> {
        self.lx
            .next_token()
            .map(|t| (t.tok, t.pos))
            .map_err(lex_err)
    }

    fn expect(&mut self, want: Tok, what: &str) -> PResult<Pos> {
        let (t, pos) = self.next()?;
        if t == want {
            Ok(pos)
        } else {
            Err((pos, format!("expected {what}, found {}", t.describe())))
        }
    }

    fn ident(&mut self, what: &str) -> PResult<(String, Pos)> {
        match self.next()? {
            (Tok::Ident(s), p) => Ok((s, p)),
            (t, p) => Err((p, format!("expected {what}, found {}", t.describe()))),
        }
    }

    /// The error for a nesting depth past [`Options::max_depth`].
    fn too_deep(&self, pos: Pos) -> (Pos, String) {
        let e = limits::trip(LimitError {
            limit: Limit::Depth,
            max: limits::current().max_depth,
        });
        (pos, e.to_string())
    }

    /// Counts one more number of a field value.
    fn count_number(&self, pos: Pos) -> PResult<()> {
        limits::charge_numbers(1).map_err(|e| (pos, e.to_string()))
    }

    /// Counts a string or word of a field value by the memory it takes, in
    /// numbers' worth (8 bytes): its header and allocation, then its bytes.
    fn count_string(&self, pos: Pos, len: usize) -> PResult<()> {
        limits::charge_numbers(4 + len as u64 / 8).map_err(|e| (pos, e.to_string()))
    }

    fn warn(&mut self, pos: Pos, msg: impl Into<String>) {
        if self.warnings.len() < 1000 {
            self.warnings.push((pos, msg.into()));
        }
    }

    fn scope(&mut self) -> &mut Scope {
        // The parser always holds at least the file scope.
        self.scopes.last_mut().expect("scope stack is never empty")
    }

    /// Statements until EOF (`top`) or a closing `}` / `]` (left unread).
    fn statements(&mut self, out: &mut Vec<NodeRef>, top: bool) -> PResult<()> {
        loop {
            match self.peek()? {
                Tok::Eof if top => return Ok(()),
                Tok::Eof => {
                    let pos = self.lx.pos();
                    return Err((pos, "unexpected end of file (missing '}' or ']')".into()));
                }
                Tok::RBrace | Tok::RBracket if !top => return Ok(()),
                Tok::RBrace | Tok::RBracket => {
                    let (t, pos) = self.next()?;
                    self.warn(pos, format!("stray {} ignored", t.describe()));
                }
                _ => {
                    if let Some(n) = self.statement()? {
                        out.push(n);
                    }
                }
            }
        }
    }

    /// One statement: a node, PROTO, EXTERNPROTO or ROUTE.
    fn statement(&mut self) -> PResult<Option<NodeRef>> {
        if self.opts.vrml97 {
            if self.peek_is_ident("PROTO") {
                self.proto()?;
                return Ok(None);
            }
            if self.peek_is_ident("EXTERNPROTO") {
                self.externproto()?;
                return Ok(None);
            }
        }
        if self.peek_is_ident("ROUTE") {
            self.route()?;
            return Ok(None);
        }
        if self.opts.x3d {
            if let Tok::Ident(w) = self.peek()? {
                if matches!(
                    w.as_str(),
                    "PROFILE" | "COMPONENT" | "UNIT" | "META" | "EXPORT" | "IMPORT"
                ) {
                    self.x3d_statement()?;
                    return Ok(None);
                }
            }
        }
        self.node_statement()
    }

    /// An X3D classic statement (ISO/IEC 19776-2 §6.2, §6.3.7): PROFILE,
    /// COMPONENT, UNIT and META are kept; EXPORT and IMPORT are read and
    /// skipped with a warning (animed does not connect Inline scenes).
    /// Never inlined: its locals would grow the frame of `statement`, which
    /// recurses once per nesting level.
    #[inline(never)]
    fn x3d_statement(&mut self) -> PResult<()> {
        let (kw, pos) = self.ident("a statement")?;
        match kw.as_str() {
            "PROFILE" => {
                let (p, _) = self.ident("a profile name")?;
                self.head.profile = Some(p);
            }
            "COMPONENT" => {
                let (c, _) = self.ident("a component name:level")?;
                // `Name : level` or `Name :level` written with spaces.
                let colon = match self.peek()? {
                    Tok::Punct(b':') => Some(String::new()),
                    Tok::Ident(w) if w.starts_with(':') => Some(w[1..].to_string()),
                    _ => None,
                };
                let c = match colon {
                    None => c,
                    Some(level) if !level.is_empty() => {
                        self.next()?;
                        format!("{c}:{level}")
                    }
                    Some(_) => {
                        self.next()?;
                        match self.next()? {
                            (Tok::Num(n), _) => format!("{c}:{n}"),
                            (t, p) => {
                                return Err((
                                    p,
                                    format!("expected a level, found {}", t.describe()),
                                ))
                            }
                        }
                    }
                };
                self.head.components.push(c);
            }
            "UNIT" => {
                let (category, _) = self.ident("a unit category (angle, force, length, mass)")?;
                let (name, _) = self.ident("a unit name")?;
                let factor = match self.next()? {
                    (Tok::Num(n), _) => n,
                    (t, p) => {
                        return Err((
                            p,
                            format!("expected a conversion factor, found {}", t.describe()),
                        ))
                    }
                };
                if !(factor.is_finite() && factor > 0.0) {
                    self.warn(
                        pos,
                        format!("UNIT {category} {name}: the factor must be > 0; ignored"),
                    );
                } else {
                    self.head.units.push(Unit {
                        category,
                        name,
                        factor,
                    });
                }
            }
            "META" => {
                let mut strs = Vec::new();
                for what in ["a META name string", "a META content string"] {
                    match self.next()? {
                        (Tok::Str(s), p) => {
                            self.count_string(p, s.len())?;
                            strs.push(s)
                        }
                        (t, p) => {
                            return Err((p, format!("expected {what}, found {}", t.describe())))
                        }
                    }
                }
                let content = strs.pop().unwrap_or_default();
                let name = strs.pop().unwrap_or_default();
                self.head.meta.push((name, content));
            }
            "EXPORT" => {
                let (name, _) = self.ident("a DEF name after EXPORT")?;
                if self.peek_is_ident("AS") {
                    self.next()?;
                    self.ident("a name after AS")?;
                }
                self.warn(pos, format!("EXPORT {name} is not used by animed; skipped"));
            }
            _ => {
                let (name, _) = self.ident("InlineName.exportedName after IMPORT")?;
                if self.peek_is_ident("AS") {
                    self.next()?;
                    self.ident("a name after AS")?;
                }
                self.warn(
                    pos,
                    format!(
                        "IMPORT {name} is not supported (Inline scenes are not connected); skipped"
                    ),
                );
            }
        }
        Ok(())
    }

    /// `DEF name Node`, `USE name`, `NULL` or `Node`.
    fn node_statement(&mut self) -> PResult<Option<NodeRef>> {
        let (t, pos) = self.next()?;
        match t {
            Tok::Ident(w) if w == "DEF" => {
                let (name, _) = self.lx.next_name().map_err(lex_err)?;
                let (kind, kpos) = self.ident("a node type after DEF")?;
                let n = self.node_body(kind, Some(name.clone()), kpos)?;
                self.scope().defs.insert(name, n.clone());
                Ok(Some(n))
            }
            Tok::Ident(w) if w == "USE" => {
                let (name, npos) = self.lx.next_name().map_err(lex_err)?;
                match self.lookup(&name) {
                    Some(n) => Ok(Some(n)),
                    None => {
                        self.warn(npos, format!("USE of undefined name '{name}' ignored"));
                        Ok(None)
                    }
                }
            }
            Tok::Ident(w) if w == "NULL" => Ok(None),
            Tok::Ident(kind) => self.node_body(kind, None, pos).map(Some),
            other => Err((pos, format!("expected a node, found {}", other.describe()))),
        }
    }

    fn lookup(&self, name: &str) -> Option<NodeRef> {
        self.scopes.last()?.defs.get(name).cloned()
    }

    /// `{ fields }` after a node type name.
    fn node_body(&mut self, kind: String, def: Option<String>, pos: Pos) -> PResult<NodeRef> {
        self.nodes += 1;
        limits::charge_nodes(1).map_err(|e| (pos, e.to_string()))?;
        self.depth += 1;
        if self.depth > self.opts.max_depth {
            return Err(self.too_deep(pos));
        }
        let script = x3d_table::declares_fields(&kind);
        if script {
            self.script_decls.push(Vec::new());
        }
        let r = self.node_fields(&kind, pos);
        self.depth -= 1;
        let fields = r?;
        let proto = self
            .scopes
            .iter()
            .rev()
            .find_map(|s| s.protos.get(&kind).cloned());
        let height = AstNode::height_of(&fields, None);
        let mut node = AstNode {
            kind,
            def,
            fields,
            pos,
            proto: None,
            height,
        };
        if self.opts.vrml97 {
            let interface: Option<Vec<String>> = match &proto {
                Some(def) => Some(def.fields.iter().map(|(n, _)| n.clone()).collect()),
                None => self
                    .scopes
                    .iter()
                    .rev()
                    .find_map(|s| s.externs.get(&node.kind).cloned()),
            };
            for f in interface
                .iter()
                .flat_map(|i| node.fields.iter().filter(move |f| !i.contains(&f.name)))
            {
                let msg = format!("{} has no field '{}' in its interface", node.kind, f.name);
                self.warn(f.pos, msg);
            }
        }
        let mut written = None;
        if let Some(def) = proto {
            self.expand_into(&def, &mut node)?;
        } else if let Some(rewrite) = self.opts.rewrite {
            written = Some(node.kind.clone());
            self.rewrite(rewrite, &mut node);
        }
        // PROTO expansion can nest far deeper than the text: what counts is
        // how deep following the node goes, from where it stands.
        if self.depth + node.height as usize > self.opts.max_depth {
            return Err(self.too_deep(pos));
        }
        let node = Rc::new(node);
        if script {
            self.keep_script_interface(&node);
        }
        if let Some(kind) = written.filter(|k| *k != node.kind) {
            self.written_kinds
                .insert(Rc::as_ptr(&node), (node.clone(), kind));
        }
        Ok(node)
    }

    /// Expands a PROTO instance in place. Never inlined (see
    /// `x3d_statement`): `node_body` recurses once per nesting level.
    #[inline(never)]
    fn expand_into(&mut self, def: &ProtoDef, node: &mut AstNode) -> PResult<()> {
        let hook = self.opts.rewrite.map(|r| (r, &self.head));
        let (inst, routes, count) = expand(def, node, hook, &mut self.warnings)?;
        self.nodes += count;
        node.height = AstNode::height_of(&node.fields, Some(&inst));
        node.proto = Some(inst);
        self.scope().routes.extend(routes);
        Ok(())
    }

    /// Runs the reader's node rewrite. Never inlined (see `x3d_statement`).
    #[inline(never)]
    fn rewrite(&mut self, rewrite: Rewrite, node: &mut AstNode) {
        rewrite(node, &self.head, &mut self.warnings);
        node.height = AstNode::height_of(&node.fields, None);
    }

    fn node_fields(&mut self, kind: &str, pos: Pos) -> PResult<Vec<Field>> {
        match self.next()? {
            (Tok::LBrace, _) => {}
            (t, p) => {
                return Err((
                    p,
                    format!(
                        "expected '{{' after node type '{kind}', found {}",
                        t.describe()
                    ),
                ))
            }
        }
        let _ = pos;
        let mut fields = Vec::new();
        // Inventor / VRML 1.0 write child nodes straight into the body.
        let mut children: Vec<NodeRef> = Vec::new();
        let mut children_pos = None;
        loop {
            if self.is_node_start()? {
                children_pos.get_or_insert(self.lx.pos());
                if let Some(c) = self.node_statement()? {
                    children.push(c);
                }
                continue;
            }
            let (t, fpos) = self.next()?;
            let name = match t {
                Tok::RBrace => {
                    if let Some(pos) = children_pos {
                        fields.push(Field {
                            name: "children".into(),
                            value: Value::Nodes(children),
                            pos,
                        });
                    }
                    return Ok(fields);
                }
                Tok::Ident(s) => s,
                Tok::Eof => {
                    return Err((
                        fpos,
                        format!("unexpected end of file inside '{kind}' (missing '}}')"),
                    ))
                }
                other => {
                    return Err((
                        fpos,
                        format!(
                            "expected a field name or '}}' in '{kind}', found {}",
                            other.describe()
                        ),
                    ))
                }
            };
            match name.as_str() {
                "ROUTE" => {
                    self.route_after_keyword(fpos)?;
                    continue;
                }
                "PROTO" if self.opts.vrml97 => {
                    self.proto_after_keyword()?;
                    continue;
                }
                "EXTERNPROTO" if self.opts.vrml97 => {
                    self.externproto_after_keyword(fpos)?;
                    continue;
                }
                "eventIn" | "eventOut" | "inputOnly" | "outputOnly" | "field" | "exposedField"
                | "initializeOnly" | "inputOutput" => {
                    self.declaration(kind, &name, fpos, &mut fields)?;
                    continue;
                }
                _ => {}
            }
            let vpos = self.lx.peek().map_or(fpos, |t| t.pos);
            let value = self.value()?;
            self.check_field(kind, &name, &value, fpos, None);
            self.check_value(kind, &name, &value, vpos);
            if self.connection.is_some() {
                self.keep_connection(&mut fields, &name, vpos);
            }
            fields.push(Field {
                name,
                value,
                pos: fpos,
            });
        }
    }

    /// A Script's interface declaration `keyword type name` with its value
    /// (fields) or `IS other` (events may have either or nothing). Never
    /// inlined: its locals would grow the frame of `node_fields`, which
    /// recurses once per nesting level.
    #[inline(never)]
    fn declaration(
        &mut self,
        kind: &str,
        keyword: &str,
        fpos: Pos,
        fields: &mut Vec<Field>,
    ) -> PResult<()> {
        let event = matches!(keyword, "eventIn" | "eventOut" | "inputOnly" | "outputOnly");
        if self.opts.vrml97 && kind == "Script" && keyword == "exposedField" {
            self.warn(
                fpos,
                "a VRML97 Script cannot declare an exposedField (§6.40: field, eventIn and eventOut only)",
            );
        }
        let (ty, _) = self.ident("a field type")?;
        let (n, npos) = self.ident("a field name")?;
        let own = self.declare(kind, keyword, &ty, &n);
        let value = if !event {
            self.value()?
        } else if self.peek_is_ident("IS") {
            // `eventIn SFType name IS other`.
            self.next()?;
            Value::Is(self.ident("an interface name after IS")?.0)
        } else {
            return Ok(());
        };
        self.check_field(kind, &n, &value, npos, own);
        fields.push(Field {
            name: n,
            value,
            pos: npos,
        });
        Ok(())
    }

    /// VRML97 rules for one field of a node body (see `checks`): IS only
    /// inside a PROTO body, naming a field of its interface of a matching
    /// type and kind (`interfaces`); events take no value. `own` is the
    /// field's declared access and type when a Script declares it. Never
    /// inlined (see `declaration`).
    #[inline(never)]
    fn check_field(
        &mut self,
        kind: &str,
        field: &str,
        value: &Value,
        pos: Pos,
        own: Option<(Access, String)>,
    ) {
        if !self.opts.vrml97 {
            return;
        }
        let msg = match value {
            Value::Is(iface) => match self.ifaces.last() {
                None => Some(format!(
                    "'{field} IS {iface}' outside a PROTO body (§4.8.3: IS belongs in PROTO bodies)"
                )),
                Some(decls) => match decls.iter().find(|d| d.2 == *iface) {
                    None => Some(format!(
                        "'{field} IS {iface}': the PROTO interface declares no '{iface}'"
                    )),
                    Some((kw, ty, _)) => self.is_mismatch(kind, field, own, kw, ty, iface),
                },
            },
            _ if checks::is_event_name(field) && !self.is_proto_name(kind) => Some(format!(
                "'{field}' is an event and takes no value in a node body (§4.10.2)"
            )),
            _ if own.is_none() && !self.is_proto_name(kind) => self.unknown_field(kind, field),
            _ => None,
        };
        if let Some(m) = msg {
            self.warn(pos, m);
        }
    }

    /// Warns at `pos` when the value given to `field` does not fit the
    /// type its built-in node gives it (`value_types`), or, for a node
    /// whose fields are not known, when a name that holds numbers in every
    /// node has a word or a string (`checks`). Never inlined (see
    /// `declaration`).
    #[inline(never)]
    fn check_value(&mut self, kind: &str, field: &str, value: &Value, pos: Pos) {
        if !self.opts.vrml97 || self.is_proto_name(kind) {
            return;
        }
        let m = match self.builtin_field_type(kind, field) {
            Some(ty) => value_types::mismatch(kind, field, ty, value),
            None => checks::number_field_mismatch(field, value),
        };
        if let Some(m) = m {
            self.warn(pos, m);
        }
    }

    fn is_proto_name(&self, kind: &str) -> bool {
        self.scopes
            .iter()
            .any(|s| s.protos.contains_key(kind) || s.externs.contains_key(kind))
    }

    /// One untyped field value, plus Inventor's trailing `~` (ignore flag)
    /// and `= Engine.output` connections (not evaluated; the engine and its
    /// output are left in `self.connection` for the node body to keep).
    fn value(&mut self) -> PResult<Value> {
        // A field costs about 100 bytes before its value's numbers.
        let pos = self.lx.pos();
        limits::charge_numbers(12).map_err(|e| (pos, e.to_string()))?;
        self.connection = None;
        let v = self.raw_value()?;
        loop {
            match self.peek()? {
                Tok::Punct(b'~') => {
                    self.next()?;
                }
                Tok::Punct(b'=') => self.connection_after_equals()?,
                _ => return Ok(v),
            }
        }
    }

    /// `= Engine { … } . output` after a field value. Never inlined: its
    /// locals would otherwise sit in every frame of the node recursion
    /// (`value` → `node_statement` → … once per nesting level).
    #[inline(never)]
    fn connection_after_equals(&mut self) -> PResult<()> {
        let (_, pos) = self.next()?;
        self.warn(pos, "field connections (engines) are not evaluated");
        let Tok::Ident(_) = self.peek()? else {
            return Ok(());
        };
        if !self.is_node_start()? {
            self.next()?;
            return Ok(());
        }
        let engine = self.node_statement()?;
        // `.output` follows the node's closing brace.
        let mut output = String::new();
        if let Tok::Ident(s) = self.peek()? {
            if s == "." {
                // `USE X . output` written with spaces.
                self.next()?;
                if let Tok::Ident(o) = self.peek()? {
                    self.next()?;
                    output = o;
                }
            } else if let Some(o) = s.strip_prefix('.') {
                output = o.to_string();
                self.next()?;
            }
        }
        if !self.opts.vrml97 {
            self.connection = engine.map(|e| (e, output));
        }
        Ok(())
    }

    /// Inventor: keeps the connection the last value had as a field
    /// `name=output` holding the engine (see `AstNode::connection`). Never
    /// inlined, for the same reason as `connection_after_equals`.
    #[inline(never)]
    fn keep_connection(&mut self, fields: &mut Vec<Field>, name: &str, pos: Pos) {
        if let Some((engine, output)) = self.connection.take() {
            fields.push(Field {
                name: format!("{name}={output}"),
                value: Value::Nodes(vec![engine]),
                pos,
            });
        }
    }

    /// True if the next tokens start a node (`DEF`, `USE`, `Type {`).
    fn is_node_start(&mut self) -> PResult<bool> {
        let t0 = self.peek()?;
        if let Tok::Ident(w) = &t0 {
            if w == "DEF" || w == "USE" {
                return Ok(true);
            }
            let t1 = self.lx.peek_nth(1).map_err(lex_err)?.tok.clone();
            return Ok(t1 == Tok::LBrace);
        }
        Ok(false)
    }

    fn raw_value(&mut self) -> PResult<Value> {
        match self.peek()? {
            // Inventor: a field given only by a connection (`origin = USE X.out`).
            Tok::Punct(b'=') => Ok(Value::Empty),
            Tok::Num(_) => {
                let mut v = Vec::new();
                self.numbers(&mut v)?;
                Ok(Value::Nums(v))
            }
            Tok::Str(_) => {
                let (t, p) = self.next()?;
                let Tok::Str(s) = t else { unreachable!() };
                self.count_string(p, s.len())?;
                Ok(Value::Strs(vec![s]))
            }
            Tok::LBracket => {
                self.next()?;
                self.list()
            }
            Tok::Punct(b'(') => {
                self.next()?;
                let mut words = Vec::new();
                loop {
                    match self.next()? {
                        (Tok::Punct(b')'), _) => break,
                        (Tok::Punct(b'|'), _) => {}
                        (Tok::Ident(w), _) => words.push(w),
                        (t, p) => {
                            return Err((
                                p,
                                format!("expected a flag name, found {}", t.describe()),
                            ))
                        }
                    }
                }
                Ok(Value::Words(words))
            }
            Tok::Ident(w) => {
                if w == "IS" {
                    self.next()?;
                    let (name, _) = self.ident("an interface name after IS")?;
                    return Ok(Value::Is(name));
                }
                if w == "NULL" {
                    self.next()?;
                    return Ok(Value::Nodes(Vec::new()));
                }
                if self.is_node_start()? {
                    return Ok(Value::Nodes(self.node_statement()?.into_iter().collect()));
                }
                let (_, wpos) = self.next()?;
                not_a_number_word(&w, wpos)?;
                let mut words = vec![w];
                // Bit masks written without parentheses: `SIDES | TOP`.
                while self.peek()? == Tok::Punct(b'|') {
                    self.next()?;
                    let (w, _) = self.ident("a flag name after '|'")?;
                    words.push(w);
                }
                Ok(Value::Words(words))
            }
            Tok::Eof => {
                let pos = self.lx.pos();
                Err((
                    pos,
                    "unexpected end of file where a field value was expected".into(),
                ))
            }
            t => {
                let pos = self.lx.pos();
                Err((
                    pos,
                    format!("expected a field value, found {}", t.describe()),
                ))
            }
        }
    }

    fn numbers(&mut self, v: &mut Vec<f64>) -> PResult<()> {
        while let Ok(t) = self.lx.peek() {
            let Tok::Num(n) = t.tok else { break };
            let pos = t.pos;
            if !n.is_finite() {
                return Err((pos, "number out of range (VRML numbers are finite)".into()));
            }
            self.count_number(pos)?;
            v.push(n);
            self.lx.next_token().map_err(lex_err)?;
        }
        // `0 NaN 0`: the word would otherwise be read as the next field's
        // name and the field keep only its first numbers.
        if let Ok(t) = self.lx.peek() {
            if let Tok::Ident(w) = &t.tok {
                not_a_number_word(w, t.pos)?;
            }
        }
        Ok(())
    }

    /// The inside of `[ ... ]` (the `[` is read).
    fn list(&mut self) -> PResult<Value> {
        match self.peek()? {
            Tok::RBracket => {
                self.next()?;
                Ok(Value::Empty)
            }
            Tok::Num(_) => {
                let mut v = Vec::new();
                self.numbers(&mut v)?;
                match self.next()? {
                    (Tok::RBracket, _) => Ok(Value::Nums(v)),
                    (t, p) => Err((
                        p,
                        format!("expected a number or ']', found {}", t.describe()),
                    )),
                }
            }
            Tok::Str(_) => {
                let mut v = Vec::new();
                loop {
                    match self.next()? {
                        (Tok::Str(s), p) => {
                            self.count_string(p, s.len())?;
                            v.push(s)
                        }
                        (Tok::RBracket, _) => return Ok(Value::Strs(v)),
                        (t, p) => {
                            return Err((
                                p,
                                format!("expected a string or ']', found {}", t.describe()),
                            ))
                        }
                    }
                }
            }
            _ => {
                if self.is_node_start()? || self.peek_is_ident("ROUTE") {
                    let mut nodes = Vec::new();
                    self.statements(&mut nodes, false)?;
                    self.expect(Tok::RBracket, "']'")?;
                    return Ok(Value::Nodes(nodes));
                }
                // Words (MFEnum, field declarations, TRUE/FALSE lists).
                let mut words = Vec::new();
                loop {
                    match self.next()? {
                        (Tok::RBracket, _) => return Ok(Value::Words(words)),
                        (Tok::Ident(w), p) => {
                            not_a_number_word(&w, p)?;
                            self.count_string(p, w.len())?;
                            words.push(w)
                        }
                        (Tok::Num(n), p) => {
                            self.count_string(p, 0)?;
                            words.push(format!("{n}"))
                        }
                        (Tok::Punct(_), _) => {}
                        (t, p) => {
                            return Err((p, format!("unexpected {} in a list", t.describe())))
                        }
                    }
                }
            }
        }
    }

    fn route(&mut self) -> PResult<()> {
        let (_, pos) = self.next()?;
        self.route_after_keyword(pos)
    }

    /// `from.field TO to.field` (the ROUTE keyword is read).
    fn route_after_keyword(&mut self, pos: Pos) -> PResult<()> {
        let (from, _) = self.ident("'Node.eventOut' after ROUTE")?;
        let (to_kw, tpos) = self.ident("TO")?;
        if to_kw != "TO" {
            return Err((tpos, format!("expected TO in ROUTE, found '{to_kw}'")));
        }
        let (to, _) = self.ident("'Node.eventIn' after TO")?;
        let split = |s: &str| {
            s.rsplit_once('.')
                .map(|(a, b)| (a.to_string(), b.to_string()))
        };
        let (Some((fnode, ffield)), Some((tnode, tfield))) = (split(&from), split(&to)) else {
            return Err((pos, "ROUTE needs Node.field on both sides".into()));
        };
        match (self.lookup(&fnode), self.lookup(&tnode)) {
            (Some(f), Some(t)) => {
                self.check_route(&fnode, &f, &ffield, &tnode, &t, &tfield, pos);
                self.scope().routes.push(Route {
                    from: f,
                    from_field: ffield,
                    to: t,
                    to_field: tfield,
                    pos,
                })
            }
            (f, _) => {
                let missing = if f.is_none() { fnode } else { tnode };
                self.warn(
                    pos,
                    format!("ROUTE names undefined node '{missing}', ignored"),
                );
            }
        }
        Ok(())
    }

    fn proto(&mut self) -> PResult<()> {
        self.next()?;
        self.proto_after_keyword()
    }

    /// `Name [ interface ] { body }` (the PROTO keyword is read).
    fn proto_after_keyword(&mut self) -> PResult<()> {
        let (name, pos) = self.ident("a PROTO name")?;
        self.expect(Tok::LBracket, "'[' after the PROTO name")?;
        let mut fields = Vec::new();
        let mut decls: Vec<(String, String, String)> = Vec::new();
        loop {
            let (t, p) = self.next()?;
            let kw = match t {
                Tok::RBracket => break,
                Tok::Ident(s) => s,
                t => {
                    return Err((
                        p,
                        format!(
                            "expected a PROTO interface declaration, found {}",
                            t.describe()
                        ),
                    ))
                }
            };
            let (ftype, _) = self.ident("a field type")?;
            let (fname, _) = self.ident("a field name")?;
            decls.push((kw.clone(), ftype, fname.clone()));
            match kw.as_str() {
                "field" | "exposedField" | "initializeOnly" | "inputOutput" => {
                    let v = self.value()?;
                    fields.push((fname, Some(v)));
                }
                "eventIn" | "eventOut" | "inputOnly" | "outputOnly" => fields.push((fname, None)),
                other => {
                    return Err((
                        p,
                        format!("expected field/exposedField/eventIn/eventOut, found '{other}'"),
                    ))
                }
            }
        }
        let pairs: Vec<(String, String)> = decls
            .iter()
            .map(|(k, _, n)| (k.clone(), n.clone()))
            .collect();
        for m in checks::interface_conflicts(&pairs) {
            self.warn(pos, format!("PROTO {name}: {m}"));
        }
        self.expect(Tok::LBrace, "'{' to open the PROTO body")?;
        self.depth += 1;
        if self.depth > self.opts.max_depth {
            return Err(self.too_deep(pos));
        }
        // The body is its own DEF scope; PROTOs declared outside stay visible.
        self.record_interface(&name, &decls);
        self.scopes.push(Scope::new());
        self.ifaces.push(decls);
        let mut body = Vec::new();
        let r = self.statements(&mut body, false);
        self.ifaces.pop();
        let scope = self.scopes.pop().unwrap_or_else(Scope::new);
        self.depth -= 1;
        r?;
        self.expect(Tok::RBrace, "'}' to close the PROTO body")?;
        if body.is_empty() {
            self.warn(pos, format!("PROTO {name} has an empty body"));
        }
        let def = ProtoDef {
            fields,
            body,
            routes: scope.routes,
        };
        self.scope().protos.insert(name, Rc::new(def));
        Ok(())
    }

    fn externproto(&mut self) -> PResult<()> {
        let (_, pos) = self.next()?;
        self.externproto_after_keyword(pos)
    }

    /// `Name [ interface ] url` — skipped with a warning; instances of it
    /// then parse as unknown nodes.
    fn externproto_after_keyword(&mut self, pos: Pos) -> PResult<()> {
        let (name, _) = self.ident("an EXTERNPROTO name")?;
        self.expect(Tok::LBracket, "'[' after the EXTERNPROTO name")?;
        // Declarations are `keyword type name` triples.
        let mut words: Vec<String> = Vec::new();
        loop {
            match self.next()? {
                (Tok::RBracket, _) => break,
                (Tok::Ident(w), _) => words.push(w),
                (t, p) => {
                    return Err((
                        p,
                        format!("unexpected {} in EXTERNPROTO interface", t.describe()),
                    ))
                }
            }
        }
        self.value()?; // the URL(s)
        let pairs: Vec<(String, String)> = words
            .chunks_exact(3)
            .map(|d| (d[0].clone(), d[2].clone()))
            .collect();
        for m in checks::interface_conflicts(&pairs) {
            self.warn(pos, format!("EXTERNPROTO {name}: {m}"));
        }
        let typed: Vec<(String, String, String)> = words
            .chunks_exact(3)
            .map(|d| (d[0].clone(), d[1].clone(), d[2].clone()))
            .collect();
        self.record_interface(&name, &typed);
        let names = pairs.into_iter().map(|(_, n)| n).collect();
        self.scope().externs.insert(name.clone(), names);
        self.warn(
            pos,
            format!("EXTERNPROTO {name} is not supported; its instances are skipped"),
        );
        Ok(())
    }
}
