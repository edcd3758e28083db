//! X3D's XML encoding (ISO/IEC 19776-1) → the generic node tree the
//! classic parser makes, so both encodings build the same scene.
//!
//! Elements are nodes; attributes are their untyped field values (read
//! like classic values: numbers, TRUE/FALSE words, quoted MFString lists,
//! or one SFString); child nodes go into the field their `containerField`
//! names (or their type's default: `geometry`, `appearance`, `material`,
//! `texture`, `coord`…, else `children`). DEF/USE, ROUTE, ProtoDeclare
//! (ProtoInterface `field`s, ProtoBody with `IS`/`connect`), ProtoInstance
//! (`fieldValue`) and ExternProtoDeclare (warned, skipped) are handled as
//! in the classic encoding; PROTO expansion is the classic parser's own.
//! The XML parser is roxmltree (comments, CDATA and entities handled
//! there); positions are its line:column.

use super::nodes;
use super::xml_checks::{self, RouteEnd};
use crate::format::lexer::Pos;
use crate::format::limits::{self, Limit, LimitError};
use crate::format::syntax::events::Typed;
use crate::format::syntax::{self, AstNode, Field, NodeRef, Parsed, ProtoDef, Route, Unit, Value};
use roxmltree::{Document, Node};
use std::collections::HashMap;
use std::rc::Rc;

type PResult<T> = Result<T, (Pos, String)>;

/// A node's interface (X3D's table, a ProtoDeclare's fields, a Script's
/// declarations), shared.
type Iface = Rc<Vec<Typed>>;

/// Whether the bytes look like an X3D XML document (an XML declaration or
/// an `<X3D` root, after any byte-order mark, blanks and comments).
pub fn is_xml(bytes: &[u8]) -> bool {
    let head = &bytes[..bytes.len().min(4096)];
    let head = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(head);
    let text = String::from_utf8_lossy(head);
    let t = text.trim_start();
    t.starts_with("<?xml") || t.starts_with("<X3D") || t.starts_with("<!DOCTYPE X3D")
}

struct Scope {
    defs: HashMap<String, NodeRef>,
    protos: HashMap<String, Rc<ProtoDef>>,
    externs: Vec<String>,
    routes: Vec<Route>,
    /// Each DEF name's node type as the file wrote it (before the rewrite)
    /// and its interface when known: what ROUTEs are checked against.
    kinds: HashMap<String, (String, Option<Iface>)>,
    /// The typed interfaces of this scope's ProtoDeclares.
    proto_ifaces: HashMap<String, Rc<Vec<Typed>>>,
}

impl Scope {
    fn new() -> Self {
        Scope {
            defs: HashMap::new(),
            protos: HashMap::new(),
            externs: Vec::new(),
            routes: Vec::new(),
            kinds: HashMap::new(),
            proto_ifaces: HashMap::new(),
        }
    }
}

struct Reader<'d, 'i> {
    doc: &'d Document<'i>,
    scopes: Vec<Scope>,
    parsed: Parsed,
    depth: usize,
    max_depth: usize,
    /// The interfaces of the ProtoDeclares whose bodies are being read,
    /// innermost last: what a `<connect>` is checked against.
    body_ifaces: Vec<Rc<Vec<Typed>>>,
}

/// Parses an X3D XML document into the generic node tree. A syntax error
/// (of the XML, or of X3D's use of it) stops reading but keeps what came
/// before, as the classic parser does.
pub fn parse(bytes: &[u8]) -> Parsed {
    let text = match std::str::from_utf8(bytes) {
        Ok(t) => t,
        Err(e) => {
            let pos = byte_pos(bytes, e.valid_up_to());
            return Parsed {
                error: Some((pos, "the file is not valid UTF-8".into())),
                ..Parsed::default()
            };
        }
    };
    let max_nodes = limits::current().max_nodes;
    let opts = roxmltree::ParsingOptions {
        allow_dtd: true,
        // Elements, attributes' text and comments: a generous multiple of
        // the node budget, so a hostile file cannot build a huge tree.
        nodes_limit: max_nodes
            .saturating_mul(8)
            .saturating_add(1024)
            .min(u32::MAX as u64) as u32,
    };
    let doc = match Document::parse_with_options(text, opts) {
        Ok(d) => d,
        Err(e) => {
            let p = e.pos();
            // roxmltree's message ends with the position we report first.
            let msg = e.to_string();
            let msg = msg
                .strip_suffix(&format!(" at {}:{}", p.row, p.col))
                .unwrap_or(&msg)
                .to_string();
            return Parsed {
                error: Some((
                    Pos {
                        line: p.row,
                        column: p.col,
                    },
                    format!("XML: {msg}"),
                )),
                ..Parsed::default()
            };
        }
    };
    let mut r = Reader {
        doc: &doc,
        scopes: vec![Scope::new()],
        parsed: Parsed::default(),
        depth: 0,
        max_depth: limits::depth_left() as usize,
        body_ifaces: Vec::new(),
    };
    let root = doc.root_element();
    let result = r.document(root);
    let scope = r.scopes.pop().unwrap_or_else(Scope::new);
    let mut parsed = r.parsed;
    parsed.routes = scope.routes;
    if let Err(e) = result {
        parsed.error = Some(e);
    }
    parsed
}

/// The 1-based line and column of a byte offset.
fn byte_pos(bytes: &[u8], at: usize) -> Pos {
    let before = &bytes[..at.min(bytes.len())];
    let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
    let col = before.iter().rev().take_while(|&&b| b != b'\n').count() + 1;
    Pos {
        line: line.min(u32::MAX as usize) as u32,
        column: col.min(u32::MAX as usize) as u32,
    }
}

/// Default `containerField` of a node type (ISO/IEC 19776-1 §5.1.2: each
/// node's table of fields names it).
pub(super) fn default_container(kind: &str) -> &'static str {
    match kind {
        "Appearance" => "appearance",
        "Material" | "PhysicalMaterial" | "UnlitMaterial" | "TwoSidedMaterial" => "material",
        "ImageTexture"
        | "PixelTexture"
        | "MovieTexture"
        | "MultiTexture"
        | "ComposedCubeMapTexture"
        | "ImageCubeMapTexture"
        | "GeneratedCubeMapTexture"
        | "ImageTexture3D"
        | "PixelTexture3D"
        | "ComposedTexture3D" => "texture",
        "TextureTransform" | "MultiTextureTransform" => "textureTransform",
        "TextureProperties" => "textureProperties",
        "Coordinate" | "CoordinateDouble" => "coord",
        "Color" | "ColorRGBA" => "color",
        "Normal" => "normal",
        "TextureCoordinate" | "MultiTextureCoordinate" | "TextureCoordinateGenerator" => "texCoord",
        "FontStyle" | "ScreenFontStyle" => "fontStyle",
        "FillProperties" => "fillProperties",
        "LineProperties" => "lineProperties",
        "AudioClip" => "source",
        "HAnimDisplacer" => "displacers",
        k if k.starts_with("Metadata") => "metadata",
        "Box"
        | "Cone"
        | "Cylinder"
        | "Sphere"
        | "IndexedFaceSet"
        | "IndexedLineSet"
        | "PointSet"
        | "ElevationGrid"
        | "Extrusion"
        | "Text"
        | "IndexedTriangleSet"
        | "TriangleSet"
        | "IndexedTriangleFanSet"
        | "TriangleFanSet"
        | "IndexedTriangleStripSet"
        | "TriangleStripSet"
        | "IndexedQuadSet"
        | "QuadSet"
        | "LineSet"
        | "Arc2D"
        | "ArcClose2D"
        | "Circle2D"
        | "Disk2D"
        | "Polyline2D"
        | "Polypoint2D"
        | "Rectangle2D"
        | "TriangleSet2D" => "geometry",
        _ => "children",
    }
}

/// An attribute's text as an untyped field value (see the module doc).
pub(super) fn attribute_value(s: &str) -> Value {
    let t = s.trim();
    if t.starts_with('"') {
        return Value::Strs(mf_string(t));
    }
    let tokens: Vec<&str> = t
        .split(|c: char| c.is_ascii_whitespace() || c == ',')
        .filter(|w| !w.is_empty())
        .collect();
    if tokens.is_empty() {
        return Value::Strs(vec![s.to_string()]);
    }
    if tokens
        .iter()
        .all(|w| matches!(*w, "true" | "false" | "TRUE" | "FALSE"))
    {
        return Value::Words(tokens.iter().map(|w| w.to_string()).collect());
    }
    let nums: Option<Vec<f64>> = tokens.iter().map(|w| number(w)).collect();
    match nums {
        Some(v) => Value::Nums(v),
        None => Value::Strs(vec![s.to_string()]),
    }
}

/// A decimal or `0x` hex number as X3D writes it (no `inf`/`nan` words).
fn number(w: &str) -> Option<f64> {
    let first = w.as_bytes()[0];
    if !(first.is_ascii_digit() || matches!(first, b'+' | b'-' | b'.')) {
        return None;
    }
    let (neg, body) = match w.strip_prefix('-') {
        Some(b) => (true, b),
        None => (false, w.strip_prefix('+').unwrap_or(w)),
    };
    if let Some(hex) = body.strip_prefix("0x").or_else(|| body.strip_prefix("0X")) {
        let v = u64::from_str_radix(hex, 16).ok()? as f64;
        return Some(if neg { -v } else { v });
    }
    if body.starts_with(['+', '-']) {
        return None;
    }
    let v: f64 = w.parse().ok()?;
    v.is_finite().then_some(v)
}

/// `"a" "b \"quoted\""` → its strings (§5.3.15 MFString in XML).
fn mf_string(t: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut chars = t.chars().peekable();
    loop {
        while chars.peek().is_some_and(|c| c.is_whitespace() || *c == ',') {
            chars.next();
        }
        match chars.next() {
            Some('"') => {}
            Some(_) | None => return out,
        }
        let mut s = String::new();
        while let Some(c) = chars.next() {
            match c {
                '\\' => {
                    if let Some(n) = chars.next() {
                        s.push(n);
                    }
                }
                '"' => break,
                c => s.push(c),
            }
        }
        out.push(s);
    }
}

/// Attributes that are not fields.
fn is_meta_attribute(name: &str) -> bool {
    matches!(
        name,
        "DEF" | "USE" | "containerField" | "class" | "id" | "style"
    )
}

impl Reader<'_, '_> {
    fn pos(&self, n: Node) -> Pos {
        let p = self.doc.text_pos_at(n.range().start);
        Pos {
            line: p.row,
            column: p.col,
        }
    }

    /// An element's own `containerField` attribute, with where it is.
    fn explicit_container(&self, e: Node) -> Option<(String, Pos)> {
        let a = e
            .attributes()
            .find(|a| a.name() == "containerField" && a.namespace().is_none())?;
        let p = self.doc.text_pos_at(a.range().start);
        let pos = Pos {
            line: p.row,
            column: p.col,
        };
        Some((a.value().to_string(), pos))
    }

    fn warn(&mut self, pos: Pos, msg: impl Into<String>) {
        if self.parsed.warnings.len() < 1000 {
            self.parsed.warnings.push((pos, msg.into()));
        }
    }

    fn scope(&mut self) -> &mut Scope {
        self.scopes
            .last_mut()
            .expect("the file scope is never popped")
    }

    fn document(&mut self, root: Node) -> PResult<()> {
        let pos = self.pos(root);
        if root.tag_name().name() != "X3D" {
            return Err((
                pos,
                format!(
                    "expected an <X3D> root element, found <{}>",
                    root.tag_name().name()
                ),
            ));
        }
        if let Some(p) = root.attribute("profile") {
            self.parsed.x3d.profile = Some(p.to_string());
        }
        if let Some(v) = root.attribute("version") {
            if !matches!(v, "3.0" | "3.1" | "3.2" | "3.3" | "4.0") {
                self.warn(pos, format!("X3D version {v}: read as 4.0"));
            }
        }
        let mut roots = Vec::new();
        for c in root.children().filter(|c| c.is_element()) {
            match c.tag_name().name() {
                "head" => self.head(c),
                "Scene" => self.statements(c, &mut roots, &mut Vec::new())?,
                other => {
                    let p = self.pos(c);
                    self.warn(p, format!("<{other}> outside <head> and <Scene> ignored"));
                }
            }
        }
        self.parsed.roots = roots;
        Ok(())
    }

    fn head(&mut self, head: Node) {
        for c in head.children().filter(|c| c.is_element()) {
            let a = |n: &str| c.attribute(n).unwrap_or("").to_string();
            match c.tag_name().name() {
                "component" => {
                    let comp = format!("{}:{}", a("name"), a("level"));
                    self.parsed.x3d.components.push(comp);
                }
                "unit" => {
                    let factor = a("conversionFactor").trim().parse::<f64>().ok();
                    match factor {
                        Some(f) if f.is_finite() && f > 0.0 => self.parsed.x3d.units.push(Unit {
                            category: a("category"),
                            name: a("name"),
                            factor: f,
                        }),
                        _ => {
                            let p = self.pos(c);
                            self.warn(p, "unit: conversionFactor must be a number > 0; ignored");
                        }
                    }
                }
                "meta" => self.parsed.x3d.meta.push((a("name"), a("content"))),
                _ => {}
            }
        }
    }

    /// The statements among `parent`'s children: nodes (into `out`, by
    /// containerField into `fields` when given), ROUTEs, PROTOs.
    fn statements(
        &mut self,
        parent: Node,
        out: &mut Vec<NodeRef>,
        fields: &mut Vec<(String, NodeRef)>,
    ) -> PResult<()> {
        for c in parent.children().filter(|c| c.is_element()) {
            let pos = self.pos(c);
            match c.tag_name().name() {
                "ROUTE" => self.route(c),
                "ProtoDeclare" => self.proto_declare(c)?,
                "ExternProtoDeclare" => {
                    let name = c.attribute("name").unwrap_or("").to_string();
                    self.warn(
                        pos,
                        format!(
                            "ExternProtoDeclare {name} is not supported; its instances are skipped"
                        ),
                    );
                    self.scope().externs.push(name);
                }
                "IMPORT" | "EXPORT" => {
                    let tag = c.tag_name().name().to_string();
                    self.warn(pos, format!("{tag} is not supported; skipped"));
                }
                "IS" | "field" | "fieldValue" | "ProtoInterface" | "ProtoBody" | "connect" => {
                    let tag = c.tag_name().name().to_string();
                    self.warn(pos, format!("<{tag}> is out of place here; ignored"));
                }
                _ => {
                    if let Some((container, n)) = self.node(c)? {
                        if container == "children" {
                            out.push(n.clone());
                        }
                        fields.push((container, n));
                    }
                }
            }
        }
        Ok(())
    }

    fn lookup(&self, name: &str) -> Option<NodeRef> {
        self.scopes.last()?.defs.get(name).cloned()
    }

    fn find_proto_iface(&self, name: &str) -> Option<Rc<Vec<Typed>>> {
        self.scopes
            .iter()
            .rev()
            .find_map(|s| s.proto_ifaces.get(name).cloned())
    }

    fn find_proto(&self, name: &str) -> Option<Rc<ProtoDef>> {
        self.scopes
            .iter()
            .rev()
            .find_map(|s| s.protos.get(name).cloned())
    }

    /// One node element: its containerField and node (`None` for a USE of
    /// an unknown name or an instance of an unsupported EXTERNPROTO).
    fn node(&mut self, e: Node) -> PResult<Option<(String, NodeRef)>> {
        let pos = self.pos(e);
        let tag = e.tag_name().name().to_string();
        if let Some(name) = e.attribute("USE") {
            let Some(n) = self.lookup(name) else {
                self.warn(pos, format!("USE of undefined name '{name}' ignored"));
                return Ok(None);
            };
            let container = e
                .attribute("containerField")
                .map(str::to_string)
                .unwrap_or_else(|| default_container(&n.kind).to_string());
            let container = if tag == "ProtoInstance" && e.attribute("containerField").is_none() {
                "children".to_string()
            } else {
                container
            };
            return Ok(Some((container, n)));
        }
        limits::charge_nodes(1).map_err(|err| (pos, err.to_string()))?;
        self.depth += 1;
        if self.depth > self.max_depth {
            let err = limits::trip(LimitError {
                limit: Limit::Depth,
                max: limits::current().max_depth,
            });
            return Err((pos, err.to_string()));
        }
        let (r, written) = if tag == "ProtoInstance" {
            let name = e.attribute("name").unwrap_or("").to_string();
            let iface = self.find_proto_iface(&name);
            (self.proto_instance(e, pos), (name, iface))
        } else {
            match self.plain_node(e, &tag, pos) {
                Ok((n, iface)) => (Ok(Some(n)), (tag.clone(), iface)),
                Err(err) => (Err(err), (tag.clone(), None)),
            }
        };
        self.depth -= 1;
        let Some(node) = r? else { return Ok(None) };
        if self.depth + node.height as usize > self.max_depth {
            let err = limits::trip(LimitError {
                limit: Limit::Depth,
                max: limits::current().max_depth,
            });
            return Err((pos, err.to_string()));
        }
        let container = e.attribute("containerField").map(str::to_string);
        let container = container.unwrap_or_else(|| {
            if tag == "ProtoInstance" {
                "children".into()
            } else {
                default_container(&tag).into()
            }
        });
        if let Some(def) = &node.def {
            let def = def.clone();
            self.scope().kinds.insert(def.clone(), written);
            self.scope().defs.insert(def, node.clone());
        }
        Ok(Some((container, node)))
    }

    fn attributes(&mut self, e: Node, pos: Pos, fields: &mut Vec<Field>) -> PResult<()> {
        for a in e.attributes() {
            if is_meta_attribute(a.name()) || a.namespace().is_some() {
                continue;
            }
            let value = attribute_value(a.value());
            charge(&value, pos)?;
            fields.push(Field {
                name: a.name().to_string(),
                value,
                pos,
            });
        }
        Ok(())
    }

    /// An element that is a built-in (or unknown) node, and its interface
    /// when X3D's table knows its type.
    fn plain_node(
        &mut self,
        e: Node,
        tag: &str,
        pos: Pos,
    ) -> PResult<(NodeRef, Option<Rc<Vec<Typed>>>)> {
        let mut fields = Vec::new();
        self.attributes(e, pos, &mut fields)?;
        for (p, m) in xml_checks::attribute_problems(tag, &fields) {
            self.warn(p, m);
        }
        let mut declared = Vec::new();
        let mut connects = Vec::new();
        let mut children: Vec<(String, NodeRef)> = Vec::new();
        // Explicit containerFields, checked once the declarations are in.
        let mut containers: Vec<(String, Pos)> = Vec::new();
        for c in e.children().filter(|c| c.is_element()) {
            let cpos = self.pos(c);
            match c.tag_name().name() {
                "IS" => {
                    for k in c.children().filter(|k| k.has_tag_name("connect")) {
                        let (Some(nf), Some(pf)) =
                            (k.attribute("nodeField"), k.attribute("protoField"))
                        else {
                            let kp = self.pos(k);
                            self.warn(kp, "connect needs nodeField and protoField; ignored");
                            continue;
                        };
                        if self.scopes.len() < 2 {
                            let kp = self.pos(k);
                            self.warn(kp, "IS outside a ProtoBody; ignored");
                            continue;
                        }
                        connects.push((nf.to_string(), pf.to_string(), self.pos(k)));
                        fields.push(Field {
                            name: nf.to_string(),
                            value: Value::Is(pf.to_string()),
                            pos: cpos,
                        });
                    }
                }
                // Script / shader interface declarations: their values.
                "field" => {
                    declared.extend(xml_checks::typed_decl(c));
                    if let Some((name, Some(v))) = self.field_decl(c)? {
                        fields.push(Field {
                            name,
                            value: v,
                            pos: cpos,
                        });
                    }
                }
                _ => {
                    containers.extend(self.explicit_container(c));
                    self.child(c, &mut children)?
                }
            }
        }
        for (name, p) in &containers {
            if let Some(m) = xml_checks::container_problem(tag, &declared, name) {
                self.warn(*p, m);
            }
        }
        // Child nodes grouped by containerField, in document order.
        let mut order: Vec<String> = Vec::new();
        for (name, _) in &children {
            if !order.contains(name) {
                order.push(name.clone());
            }
        }
        for name in order {
            let nodes: Vec<NodeRef> = children
                .iter()
                .filter(|(n, _)| *n == name)
                .map(|(_, n)| n.clone())
                .collect();
            fields.push(Field {
                name,
                value: Value::Nodes(nodes),
                pos,
            });
        }
        let height = AstNode::height_of(&fields, None);
        let mut node = AstNode {
            kind: tag.to_string(),
            def: e.attribute("DEF").map(str::to_string),
            fields,
            pos,
            proto: None,
            height,
        };
        // Kept only where a ROUTE or a connect can need it.
        let needed = node_def_or_connects(e, &connects);
        let iface = needed
            .then(|| xml_checks::builtin(tag, &declared))
            .flatten();
        self.check_connects(tag, iface.as_deref().map(|v| v.as_slice()), &connects);
        let head = self.parsed.x3d.clone();
        nodes::rewrite(&mut node, &head, &mut self.parsed.warnings);
        node.height = AstNode::height_of(&node.fields, None);
        Ok((Rc::new(node), iface))
    }

    /// Warns about each `<connect nodeField protoField>` of a node of type
    /// `kind` (interface `iface`) whose fields do not fit (see
    /// `xml_checks::connect_problem`).
    fn check_connects(
        &mut self,
        kind: &str,
        iface: Option<&[Typed]>,
        connects: &[(String, String, Pos)],
    ) {
        let (Some(node), Some(proto)) = (iface, self.body_ifaces.last().cloned()) else {
            return;
        };
        for (nf, pf, p) in connects {
            if let Some(m) = xml_checks::connect_problem(kind, node, nf, &proto, pf) {
                self.warn(*p, m);
            }
        }
    }

    /// A child element of a node: a ROUTE, a PROTO, or a child node.
    fn child(&mut self, c: Node, children: &mut Vec<(String, NodeRef)>) -> PResult<()> {
        let pos = self.pos(c);
        match c.tag_name().name() {
            "ROUTE" => self.route(c),
            "ProtoDeclare" => self.proto_declare(c)?,
            "fieldValue" | "ProtoInterface" | "ProtoBody" | "connect" => {
                let tag = c.tag_name().name().to_string();
                self.warn(pos, format!("<{tag}> is out of place here; ignored"));
            }
            _ => {
                if let Some(cn) = self.node(c)? {
                    children.push(cn);
                }
            }
        }
        Ok(())
    }

    fn route(&mut self, c: Node) {
        let pos = self.pos(c);
        let a = |n: &str| c.attribute(n).unwrap_or("").to_string();
        let (from, to) = (a("fromNode"), a("toNode"));
        match (self.lookup(&from), self.lookup(&to)) {
            (Some(f), Some(t)) => {
                let r = Route {
                    from: f,
                    from_field: a("fromField"),
                    to: t,
                    to_field: a("toField"),
                    pos,
                };
                self.check_route(&from, &r.from_field, &to, &r.to_field, pos);
                self.scope().routes.push(r);
            }
            (f, _) => {
                let missing = if f.is_none() { from } else { to };
                self.warn(
                    pos,
                    format!("ROUTE names undefined node '{missing}', ignored"),
                );
            }
        }
    }

    /// Warns about a ROUTE between the DEF names `from` and `to` whose
    /// fields do not fit (see `xml_checks::route_problems`).
    fn check_route(&mut self, from: &str, ff: &str, to: &str, tf: &str, pos: Pos) {
        let kinds = &self.scopes.last().expect("the file scope").kinds;
        let (Some((fk, fi)), Some((tk, ti))) = (kinds.get(from), kinds.get(to)) else {
            return;
        };
        let problems = xml_checks::route_problems(
            &RouteEnd {
                node: from,
                kind: fk,
                iface: fi.as_deref().map(|v| v.as_slice()),
                field: ff,
            },
            &RouteEnd {
                node: to,
                kind: tk,
                iface: ti.as_deref().map(|v| v.as_slice()),
                field: tf,
            },
        );
        for m in problems {
            self.warn(pos, m);
        }
    }

    /// A `<field name type accessType value>` declaration: its name and
    /// value (`None` for events).
    fn field_decl(&mut self, f: Node) -> PResult<Option<(String, Option<Value>)>> {
        let pos = self.pos(f);
        let Some(name) = f.attribute("name") else {
            self.warn(pos, "field without a name ignored");
            return Ok(None);
        };
        let access = f.attribute("accessType").unwrap_or("initializeOnly");
        let is_event = matches!(access, "inputOnly" | "outputOnly" | "eventIn" | "eventOut");
        if is_event {
            return Ok(Some((name.to_string(), None)));
        }
        let ty = f.attribute("type").unwrap_or("");
        let value = self.value_of(f, pos, ty.ends_with("Node"))?;
        Ok(Some((name.to_string(), value)))
    }

    /// The value of a `field` / `fieldValue` element: its `value`
    /// attribute, or its child nodes.
    fn value_of(&mut self, f: Node, pos: Pos, node_type: bool) -> PResult<Option<Value>> {
        if let Some(v) = f.attribute("value") {
            let v = attribute_value(v);
            charge(&v, pos)?;
            return Ok(Some(v));
        }
        let mut children = Vec::new();
        for c in f.children().filter(|c| c.is_element()) {
            if let Some((_, n)) = self.node(c)? {
                children.push(n);
            }
        }
        if !children.is_empty() || node_type {
            return Ok(Some(Value::Nodes(children)));
        }
        Ok(None)
    }

    fn proto_declare(&mut self, d: Node) -> PResult<()> {
        let pos = self.pos(d);
        let name = d.attribute("name").unwrap_or("").to_string();
        let mut fields = Vec::new();
        let mut body = Vec::new();
        let mut routes = Vec::new();
        let mut typed = Vec::new();
        for c in d.children().filter(|c| c.is_element()) {
            match c.tag_name().name() {
                "ProtoInterface" => {
                    for f in c.children().filter(|f| f.has_tag_name("field")) {
                        typed.extend(xml_checks::typed_decl(f));
                        if let Some(decl) = self.field_decl(f)? {
                            fields.push(decl);
                        }
                    }
                }
                "ProtoBody" => {
                    self.depth += 1;
                    self.scopes.push(Scope::new());
                    self.body_ifaces.push(Rc::new(typed.clone()));
                    let mut all = Vec::new();
                    let r = self.statements(c, &mut Vec::new(), &mut all);
                    self.body_ifaces.pop();
                    let scope = self.scopes.pop().unwrap_or_else(Scope::new);
                    self.depth -= 1;
                    // The body's nodes whatever their containerField: the
                    // first is what an instance is.
                    body = all.into_iter().map(|(_, n)| n).collect();
                    routes = scope.routes;
                    r?;
                }
                _ => {}
            }
        }
        if body.is_empty() {
            self.warn(pos, format!("ProtoDeclare {name} has an empty ProtoBody"));
        }
        let def = ProtoDef {
            fields,
            body,
            routes,
        };
        self.scope()
            .proto_ifaces
            .insert(name.clone(), Rc::new(typed));
        self.scope().protos.insert(name, Rc::new(def));
        Ok(())
    }

    fn proto_instance(&mut self, e: Node, pos: Pos) -> PResult<Option<NodeRef>> {
        let name = e.attribute("name").unwrap_or("").to_string();
        let Some(def) = self.find_proto(&name) else {
            let known_extern = self.scopes.iter().any(|s| s.externs.contains(&name));
            if !known_extern {
                self.warn(pos, format!("ProtoInstance of undeclared '{name}' skipped"));
            }
            return Ok(None);
        };
        let mut fields = Vec::new();
        let mut connects = Vec::new();
        for c in e.children().filter(|c| c.is_element()) {
            let cpos = self.pos(c);
            match c.tag_name().name() {
                "fieldValue" => {
                    let Some(fname) = c.attribute("name") else {
                        self.warn(cpos, "fieldValue without a name ignored");
                        continue;
                    };
                    if !def.fields.iter().any(|(n, _)| n == fname) {
                        self.warn(
                            cpos,
                            format!("{name} has no field '{fname}' in its interface"),
                        );
                    }
                    if let Some(v) = self.value_of(c, cpos, false)? {
                        fields.push(Field {
                            name: fname.to_string(),
                            value: v,
                            pos: cpos,
                        });
                    }
                }
                "IS" => {
                    for k in c.children().filter(|k| k.has_tag_name("connect")) {
                        if let (Some(nf), Some(pf)) =
                            (k.attribute("nodeField"), k.attribute("protoField"))
                        {
                            connects.push((nf.to_string(), pf.to_string(), self.pos(k)));
                            fields.push(Field {
                                name: nf.to_string(),
                                value: Value::Is(pf.to_string()),
                                pos: cpos,
                            });
                        }
                    }
                }
                other => {
                    let other = other.to_string();
                    self.warn(cpos, format!("<{other}> inside ProtoInstance ignored"));
                }
            }
        }
        let iface = self.find_proto_iface(&name);
        self.check_connects(&name, iface.as_deref().map(|v| v.as_slice()), &connects);
        let mut node = AstNode {
            kind: name,
            def: e.attribute("DEF").map(str::to_string),
            height: AstNode::height_of(&fields, None),
            fields,
            pos,
            proto: None,
        };
        let head = self.parsed.x3d.clone();
        let (inst, routes, _count) = syntax::expand(
            &def,
            &node,
            Some((nodes::rewrite, &head)),
            &mut self.parsed.warnings,
        )?;
        node.height = AstNode::height_of(&node.fields, Some(&inst));
        node.proto = Some(inst);
        self.scope().routes.extend(routes);
        Ok(Some(Rc::new(node)))
    }
}

/// Whether an element's interface can be needed: it has a DEF (ROUTEs
/// name it) or `<connect>`s.
fn node_def_or_connects(e: Node, connects: &[(String, String, Pos)]) -> bool {
    e.attribute("DEF").is_some() || !connects.is_empty()
}

/// Counts a field value's numbers and strings against the input budget.
fn charge(v: &Value, pos: Pos) -> PResult<()> {
    let n = match v {
        Value::Nums(n) => n.len() as u64,
        Value::Strs(s) | Value::Words(s) => s.iter().map(|s| 4 + s.len() as u64 / 8).sum(),
        _ => 0,
    };
    limits::charge_numbers(12 + n).map_err(|e| (pos, e.to_string()))
}
