//! The node tree of a classic-syntax file (Inventor, VRML 1.0, VRML97) as
//! written, before any meaning is given to it.
//!
//! Field values are kept untyped (numbers, strings, words, nodes): the
//! readers convert them when they know what a node's field means, so one
//! parser serves all three dialects and unknown nodes cost nothing.

mod checks;
pub(crate) mod events;
pub(crate) mod node_table;
mod parser;
mod proto;
pub(crate) mod value_types;
pub(crate) mod x3d_table;

pub use parser::{parse, Options, Rewrite};
pub use proto::{expand, ProtoDef};

use super::lexer::Pos;
use std::collections::HashMap;
use std::rc::Rc;

/// A node shared by DEF/USE.
pub type NodeRef = Rc<AstNode>;

/// One node as written: `DEF name Type { fields }`.
#[derive(Debug)]
pub struct AstNode {
    pub kind: String,
    pub def: Option<String>,
    pub fields: Vec<Field>,
    pub pos: Pos,
    /// Set when `kind` names a PROTO: the expanded body.
    pub proto: Option<ProtoInstance>,
    /// Levels of nodes from this one down (1 for a leaf), PROTO expansion
    /// included: what following this node costs in recursion.
    pub height: u32,
}

/// An expanded PROTO instance.
#[derive(Debug)]
pub struct ProtoInstance {
    /// The first node of the body: what the instance is in the scene.
    pub root: NodeRef,
    /// Interface name → the body fields it is bound to with IS.
    pub is_map: HashMap<String, Vec<(NodeRef, String)>>,
}

#[derive(Debug, Clone)]
pub struct Field {
    pub name: String,
    pub value: Value,
    pub pos: Pos,
}

/// An untyped field value.
#[derive(Debug, Clone)]
pub enum Value {
    Nums(Vec<f64>),
    Strs(Vec<String>),
    /// Bare words: TRUE/FALSE, enum names, bit-mask names.
    Words(Vec<String>),
    /// SFNode / MFNode (NULL is an empty list).
    Nodes(Vec<NodeRef>),
    /// `IS name` inside a PROTO body, not yet bound.
    Is(String),
    /// `[ ]`.
    Empty,
}

/// `ROUTE from.field TO to.field`.
#[derive(Debug, Clone)]
pub struct Route {
    pub from: NodeRef,
    pub from_field: String,
    pub to: NodeRef,
    pub to_field: String,
    pub pos: Pos,
}

/// A parsed file.
#[derive(Debug, Default)]
pub struct Parsed {
    pub roots: Vec<NodeRef>,
    pub routes: Vec<Route>,
    /// Non-fatal problems with their positions.
    pub warnings: Vec<(Pos, String)>,
    /// A syntax error that stopped parsing early (what came before is kept).
    pub error: Option<(Pos, String)>,
    /// X3D: the PROFILE, COMPONENT, UNIT and META statements.
    pub x3d: X3dHead,
}

/// The statements an X3D file makes about itself (ISO/IEC 19776-2 §6.2:
/// PROFILE, COMPONENT, UNIT, META), in either encoding.
#[derive(Debug, Default, Clone)]
pub struct X3dHead {
    pub profile: Option<String>,
    /// `name:level` as written.
    pub components: Vec<String>,
    pub units: Vec<Unit>,
    /// META name/content pairs, in file order.
    pub meta: Vec<(String, String)>,
}

/// `UNIT category name conversionFactor` (ISO/IEC 19775-1 §4.3.6): one
/// unit of the file is `factor` base units (metres, radians…).
#[derive(Debug, Clone, PartialEq)]
pub struct Unit {
    pub category: String,
    pub name: String,
    pub factor: f64,
}

impl X3dHead {
    /// The conversion factor of a unit category (1 when none is declared).
    pub fn factor(&self, category: &str) -> f64 {
        self.units
            .iter()
            .rev()
            .find(|u| u.category == category)
            .map_or(1.0, |u| u.factor)
    }
}

impl AstNode {
    /// The [`AstNode::height`] of a node with these fields and expansion.
    pub fn height_of(fields: &[Field], proto: Option<&ProtoInstance>) -> u32 {
        let below = fields
            .iter()
            .filter_map(|f| match &f.value {
                Value::Nodes(ns) => ns.iter().map(|n| n.height).max(),
                _ => None,
            })
            .chain(proto.map(|p| p.root.height))
            .max()
            .unwrap_or(0);
        below.saturating_add(1)
    }

    pub fn field(&self, name: &str) -> Option<&Field> {
        self.fields.iter().rev().find(|f| f.name == name)
    }

    /// Inventor: the engine (and its output's name) that field `name` is
    /// connected from (`name value = Engine { … } . output`). The parser
    /// keeps it as a field named `name=output` holding the engine node, a
    /// name no real field has.
    pub fn connection(&self, name: &str) -> Option<(&NodeRef, &str)> {
        self.fields.iter().rev().find_map(|f| {
            let output = f.name.strip_prefix(name)?.strip_prefix('=')?;
            match &f.value {
                Value::Nodes(n) => Some((n.first()?, output)),
                _ => None,
            }
        })
    }

    /// Whether field `f` is a kept connection (see [`AstNode::connection`]).
    pub fn is_connection(f: &Field) -> bool {
        f.name.contains('=')
    }

    pub fn value(&self, name: &str) -> Option<&Value> {
        self.field(name).map(|f| &f.value)
    }

    /// The node a PROTO instance stands for (itself otherwise).
    pub fn effective(self: &Rc<Self>) -> NodeRef {
        let mut n = self.clone();
        // Each level is a distinct instance; depth is bounded by the parser.
        while let Some(p) = &n.proto {
            let next = p.root.clone();
            n = next;
        }
        n
    }

    pub fn nums(&self, name: &str) -> Option<&[f64]> {
        match self.value(name)? {
            Value::Nums(v) => Some(v),
            Value::Empty => Some(&[]),
            _ => None,
        }
    }

    pub fn num(&self, name: &str) -> Option<f64> {
        self.nums(name)?.first().copied()
    }

    pub fn f32(&self, name: &str, default: f32) -> f32 {
        self.num(name).map(|v| v as f32).unwrap_or(default)
    }

    pub fn vec3(&self, name: &str, default: glam::Vec3) -> glam::Vec3 {
        match self.nums(name) {
            Some(v) if v.len() >= 3 => glam::Vec3::new(v[0] as f32, v[1] as f32, v[2] as f32),
            _ => default,
        }
    }

    /// An SFRotation (axis x y z, angle) as a quaternion.
    pub fn rotation(&self, name: &str) -> Option<glam::Quat> {
        match self.nums(name) {
            Some(v) if v.len() >= 4 => Some(axis_angle(v[0], v[1], v[2], v[3])),
            _ => None,
        }
    }

    pub fn bool(&self, name: &str, default: bool) -> bool {
        match self.value(name) {
            Some(Value::Words(w)) if !w.is_empty() => match w[0].as_str() {
                "TRUE" | "true" => true,
                "FALSE" | "false" => false,
                _ => default,
            },
            Some(Value::Nums(n)) if !n.is_empty() => n[0] != 0.0,
            _ => default,
        }
    }

    /// The words of an enum / bit-mask field.
    pub fn words(&self, name: &str) -> &[String] {
        match self.value(name) {
            Some(Value::Words(w)) => w,
            _ => &[],
        }
    }

    pub fn strings(&self, name: &str) -> Vec<String> {
        match self.value(name) {
            Some(Value::Strs(s)) => s.clone(),
            Some(Value::Words(w)) => w.clone(),
            _ => Vec::new(),
        }
    }

    pub fn nodes(&self, name: &str) -> &[NodeRef] {
        match self.value(name) {
            Some(Value::Nodes(n)) => n,
            _ => &[],
        }
    }

    pub fn node(&self, name: &str) -> Option<&NodeRef> {
        self.nodes(name).first()
    }
}

/// Axis-angle to a unit quaternion; a zero axis gives the identity.
pub fn axis_angle(x: f64, y: f64, z: f64, angle: f64) -> glam::Quat {
    let axis = glam::DVec3::new(x, y, z);
    let len = axis.length();
    if len.is_nan() || len <= 1e-12 || !angle.is_finite() {
        return glam::Quat::IDENTITY;
    }
    let q = glam::DQuat::from_axis_angle(axis / len, angle);
    glam::Quat::from_xyzw(q.x as f32, q.y as f32, q.z as f32, q.w as f32)
}
