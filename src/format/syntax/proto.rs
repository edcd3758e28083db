//! PROTO expansion (VRML97 §4.8): each instance gets its own copy of the
//! body with `IS` fields bound to the instance's values (or the defaults),
//! and the body's ROUTEs copied onto the copied nodes.

use super::parser::Rewrite;
use super::{AstNode, Field, NodeRef, ProtoInstance, Route, Value, X3dHead};
use crate::format::lexer::Pos;
use crate::format::limits;
use std::collections::HashMap;
use std::rc::Rc;

/// A PROTO declaration.
#[derive(Debug)]
pub struct ProtoDef {
    /// Interface: name and default value (`None` for events).
    pub fields: Vec<(String, Option<Value>)>,
    pub body: Vec<NodeRef>,
    pub routes: Vec<Route>,
}

struct Binder<'a> {
    /// Interface name → (value, whether the instance gave it). Defaults are
    /// copied per instance; the instance's own nodes are shared, so outer
    /// DEF names and ROUTEs keep pointing at them.
    values: HashMap<&'a str, Option<(&'a Value, bool)>>,
    memo: HashMap<*const AstNode, NodeRef>,
    is_map: HashMap<String, Vec<(NodeRef, String)>>,
    count: usize,
    /// The reader's node rewrite (X3D), run again on body nodes whose IS
    /// fields were just bound: at parse time their values were not known.
    hook: Option<(Rewrite, &'a X3dHead)>,
    warnings: &'a mut Vec<(Pos, String)>,
}

/// Expands `inst` (an instance of `def`) into a fresh body; also returns
/// how many nodes the copy made (already charged to the input budget).
pub fn expand<'a>(
    def: &'a ProtoDef,
    inst: &'a AstNode,
    hook: Option<(Rewrite, &'a X3dHead)>,
    warnings: &'a mut Vec<(Pos, String)>,
) -> Result<(ProtoInstance, Vec<Route>, usize), (Pos, String)> {
    let mut values: HashMap<&str, Option<(&Value, bool)>> = HashMap::new();
    for (name, default) in &def.fields {
        values.insert(name.as_str(), default.as_ref().map(|v| (v, false)));
    }
    for f in &inst.fields {
        if values.contains_key(f.name.as_str()) {
            values.insert(f.name.as_str(), Some((&f.value, true)));
        }
    }
    let mut b = Binder {
        values,
        memo: HashMap::new(),
        is_map: HashMap::new(),
        count: 0,
        hook,
        warnings,
    };
    let body: Vec<NodeRef> = def.body.iter().map(|n| b.copy(n)).collect();
    if let Err(e) = limits::charge_nodes(b.count as u64) {
        return Err((inst.pos, format!("PROTO expansion: {e}")));
    }
    let routes = def
        .routes
        .iter()
        .filter_map(|r| {
            Some(Route {
                from: b.memo.get(&Rc::as_ptr(&r.from))?.clone(),
                from_field: r.from_field.clone(),
                to: b.memo.get(&Rc::as_ptr(&r.to))?.clone(),
                to_field: r.to_field.clone(),
                pos: r.pos,
            })
        })
        .collect();
    // An empty body stands for nothing; an empty group keeps the tree simple.
    let root = body.first().cloned().unwrap_or_else(|| {
        Rc::new(AstNode {
            kind: "Group".into(),
            def: None,
            fields: Vec::new(),
            pos: inst.pos,
            proto: None,
            height: 1,
        })
    });
    Ok((
        ProtoInstance {
            root,
            is_map: b.is_map,
        },
        routes,
        b.count,
    ))
}

impl Binder<'_> {
    fn copy(&mut self, n: &NodeRef) -> NodeRef {
        if let Some(c) = self.memo.get(&Rc::as_ptr(n)) {
            return c.clone();
        }
        self.count += 1;
        let mut fields = Vec::with_capacity(n.fields.len());
        let mut bound: Vec<(String, String)> = Vec::new();
        for f in &n.fields {
            match &f.value {
                Value::Is(iface) => {
                    bound.push((iface.clone(), f.name.clone()));
                    // An event, or an unknown interface name, has no value.
                    if let Some(Some((v, from_instance))) = self.values.get(iface.as_str()) {
                        let v = if *from_instance {
                            (*v).clone()
                        } else {
                            self.copy_value(v)
                        };
                        fields.push(Field {
                            name: f.name.clone(),
                            value: v,
                            pos: f.pos,
                        });
                    }
                }
                v => {
                    let v = self.copy_value(v);
                    fields.push(Field {
                        name: f.name.clone(),
                        value: v,
                        pos: f.pos,
                    });
                }
            }
        }
        let proto = n.proto.as_ref().map(|p| ProtoInstance {
            root: self.copy(&p.root),
            is_map: p
                .is_map
                .iter()
                .map(|(k, v)| {
                    let v = v.iter().map(|(n, f)| (self.copy(n), f.clone())).collect();
                    (k.clone(), v)
                })
                .collect(),
        });
        let height = AstNode::height_of(&fields, proto.as_ref());
        let mut c = AstNode {
            kind: n.kind.clone(),
            def: n.def.clone(),
            fields,
            pos: n.pos,
            proto,
            height,
        };
        if let Some((rewrite, head)) = self.hook {
            if !bound.is_empty() && c.proto.is_none() {
                rewrite(&mut c, head, self.warnings);
                c.height = AstNode::height_of(&c.fields, None);
            }
        }
        let c = Rc::new(c);
        for (iface, field) in bound {
            self.is_map
                .entry(iface)
                .or_default()
                .push((c.clone(), field));
        }
        self.memo.insert(Rc::as_ptr(n), c.clone());
        c
    }

    fn copy_value(&mut self, v: &Value) -> Value {
        match v {
            Value::Nodes(ns) => Value::Nodes(ns.iter().map(|n| self.copy(n)).collect()),
            other => other.clone(),
        }
    }
}
