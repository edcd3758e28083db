//! The X3D writers: X3D 4.0 in the classic encoding (`.x3dv`) and in XML
//! (`.x3d`).
//!
//! The classic file is the VRML97 writer's (same nodes, the same adaptive
//! sampling of every track, the same key note in a WorldInfo) with X3D's
//! header and profile, and orthographic cameras as OrthoViewpoint. The XML
//! file is that classic text read back by animed's own parser (no node
//! rewrite) and printed as elements and attributes, so the two encodings
//! hold the same scene by construction: nodes become elements, their
//! node fields child elements with a `containerField` where it is not the
//! type's default, DEF/USE attributes, ROUTE elements.

use super::xml::default_container;
use crate::format::export::options::{WriteOptions, WriteReport};
use crate::format::export::text::num;
use crate::format::limits;
use crate::format::syntax::{self, AstNode, NodeRef, Options, Value};
use crate::format::vrml97;
use crate::scene::Scene;
use std::collections::HashSet;
use std::fmt::Write as _;
use std::rc::Rc;

/// Prints `scene` as an X3D 4.0 classic-encoding file.
pub fn classic(scene: &Scene, opts: &WriteOptions) -> (String, WriteReport) {
    vrml97::write::write_x3d(scene, opts)
}

/// Fields whose value is one SFString (an attribute's raw text in XML);
/// every other string field the writers emit is an MFString.
const SF_STRINGS: &[&str] = &["description", "title"];

/// Prints `scene` as an X3D 4.0 XML-encoding file.
pub fn xml(scene: &Scene, opts: &WriteOptions) -> (String, WriteReport) {
    let (text, report) = classic(scene, opts);
    // What we just wrote is read back without an input budget (only the
    // deepest nesting any read allows, which the save checks anyway).
    let lim = limits::Limits {
        max_bytes: u64::MAX,
        max_nodes: u64::MAX,
        max_depth: limits::DEPTH_CEILING,
        max_geometry: u64::MAX,
        max_numbers: u64::MAX,
    };
    let parsed = limits::scope_with(lim, || {
        let mut o = Options::new(true);
        o.x3d = true;
        syntax::parse(text.as_bytes(), o)
    });
    let mut x = Xml {
        out: String::with_capacity(text.len() + text.len() / 2),
        written: HashSet::new(),
    };
    x.out
        .push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    x.out.push_str(
        "<!DOCTYPE X3D PUBLIC \"ISO//Web3D//DTD X3D 4.0//EN\" \"https://www.web3d.org/specifications/x3d-4.0.dtd\">\n",
    );
    let profile = parsed.x3d.profile.as_deref().unwrap_or("Immersive");
    let _ = writeln!(x.out, "<X3D profile='{}' version='4.0'>", attr(profile));
    x.out.push_str("<Scene>\n");
    x.out.push_str(
        "<!-- Written by animed. The authored keys are in the WorldInfo (the animed key note). -->\n",
    );
    for n in &parsed.roots {
        x.node(n, None, 1);
    }
    for r in &parsed.routes {
        let (Some(from), Some(to)) = (&r.from.def, &r.to.def) else {
            continue;
        };
        let _ = writeln!(
            x.out,
            "  <ROUTE fromNode='{}' fromField='{}' toNode='{}' toField='{}'/>",
            attr(from),
            attr(&r.from_field),
            attr(to),
            attr(&r.to_field)
        );
    }
    x.out.push_str("</Scene>\n</X3D>\n");
    (x.out, report)
}

struct Xml {
    out: String,
    written: HashSet<*const AstNode>,
}

/// Escapes text for a single-quoted XML attribute; line breaks and tabs
/// as character references, which attribute normalisation keeps.
fn attr(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '\'' => out.push_str("&apos;"),
            '"' => out.push_str("&quot;"),
            '\n' => out.push_str("&#10;"),
            '\r' => out.push_str("&#13;"),
            '\t' => out.push_str("&#9;"),
            c => out.push(c),
        }
    }
    out
}

/// One number as the writers print it: integers as integers, others as
/// the shortest f32 text (they were written from f32 values).
fn number(v: f64) -> String {
    // -0 keeps its sign (the classic text has it, and its bits matter).
    if v.fract() == 0.0 && v.abs() < 1e15 && !(v == 0.0 && v.is_sign_negative()) {
        format!("{}", v as i64)
    } else {
        num(v as f32)
    }
}

/// A field value as an attribute's text (`None`: a node field).
fn value_text(field: &str, v: &Value) -> Option<String> {
    Some(match v {
        Value::Nums(n) => n.iter().map(|x| number(*x)).collect::<Vec<_>>().join(" "),
        Value::Words(w) => w
            .iter()
            .map(|w| match w.as_str() {
                "TRUE" => "true".to_string(),
                "FALSE" => "false".to_string(),
                w => w.to_string(),
            })
            .collect::<Vec<_>>()
            .join(" "),
        Value::Strs(s) if SF_STRINGS.contains(&field) => s.first().cloned().unwrap_or_default(),
        Value::Strs(s) => s
            .iter()
            .map(|s| crate::format::export::text::quoted(s))
            .collect::<Vec<_>>()
            .join(" "),
        Value::Empty if matches!(field, "children" | "choice" | "level") => return None,
        Value::Empty => String::new(),
        Value::Nodes(_) | Value::Is(_) => return None,
    })
}

impl Xml {
    fn indent(&mut self, depth: usize) {
        for _ in 0..depth {
            self.out.push_str("  ");
        }
    }

    /// One node as an element; `container` is the field it sits in.
    fn node(&mut self, n: &NodeRef, container: Option<&str>, depth: usize) {
        let kind = &n.kind;
        let cf = match container {
            Some(c) if c != default_container(kind) => format!(" containerField='{}'", attr(c)),
            _ => String::new(),
        };
        self.indent(depth);
        if !self.written.insert(Rc::as_ptr(n)) {
            if let Some(d) = &n.def {
                let _ = writeln!(self.out, "<{kind} USE='{}'{cf}/>", attr(d));
            }
            return;
        }
        let _ = write!(self.out, "<{kind}");
        if let Some(d) = &n.def {
            let _ = write!(self.out, " DEF='{}'", attr(d));
        }
        self.out.push_str(&cf);
        let mut children: Vec<(&str, &NodeRef)> = Vec::new();
        for f in &n.fields {
            match &f.value {
                Value::Nodes(ns) => children.extend(ns.iter().map(|c| (f.name.as_str(), c))),
                v => {
                    if let Some(t) = value_text(&f.name, v) {
                        let _ = write!(self.out, " {}='{}'", f.name, attr(&t));
                    }
                }
            }
        }
        if children.is_empty() {
            self.out.push_str("/>\n");
            return;
        }
        self.out.push_str(">\n");
        for (field, c) in children {
            self.node(c, Some(field), depth + 1);
        }
        self.indent(depth);
        let _ = writeln!(self.out, "</{kind}>");
    }
}
