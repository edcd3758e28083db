//! The key note: every authored track as plain text, stored in the file's
//! own info node (VRML97 `WorldInfo.info`, Inventor `Info.string`), so a
//! file exported by animed opens again with every key, interpolation, TCB
//! and ease value exactly as authored — the sampled interpolators or engines
//! in the same file are only for other viewers.
//!
//! Format (version 1), one item per line, words separated by spaces:
//! ```text
//! animed-keys 1
//! fps 24
//! duration 96
//! background R G B                  (the background colour)
//! headlight on|off                  (only when the scene says)
//! ambient R G B                     (Inventor's global ambient, when not 0)
//! hidden NAME                       (a node whose own visibility is off)
//! style NAME lines|points|hidden    (a node's render style, when not filled)
//! track node|material NAME PROPERTY constant|loop
//! key FRAME INTERP T C B EASE_IN EASE_OUT V1 V2 …
//! end
//! ```
//! * `NAME` is the DEF name the same file gives the node or material;
//!   `PROPERTY` is [`Property::name`]; `INTERP` is `step`, `linear` or `tcb`.
//! * Values: scalar 1 number; vector and colour 3 (x y z / r g b);
//!   rotation 4, the unit quaternion `x y z w` (exact, unlike axis-angle);
//!   boolean `0` or `1`.
//! * Numbers are Rust's shortest round-trip form of an `f32`, so reading
//!   gives back the very same bits.
//! * Lines after `end` are ignored; blank lines and lines starting with `#`
//!   are skipped.

use super::plan::WritePlan;
use crate::anim::{
    Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track, ValueKind, Weights,
    MAX_MORPH_TARGETS,
};
use crate::format::Loaded;
use crate::scene::{NodeKind, RenderStyle, Scene};
use glam::{Quat, Vec3};
use std::fmt::Write as _;
use std::path::Path;

/// The first line of every note; also how a note is recognised.
pub const MARKER: &str = "animed-keys 1";

/// Whether a track's target is a node or a material.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Owner {
    Node,
    Material,
}

/// One track as the note spells it: target by name.
#[derive(Clone, Debug, PartialEq)]
pub struct NoteTrack {
    pub owner: Owner,
    pub name: String,
    pub property: Property,
    pub repeat: Repeat,
    pub keys: Keys,
}

/// A parsed note.
#[derive(Clone, Debug, PartialEq)]
pub struct Note {
    pub fps: f32,
    pub duration: f32,
    pub background: Option<Vec3>,
    pub headlight: Option<bool>,
    /// Inventor's global ambient (`Settings::ambient`), when not zero.
    pub ambient: Option<Vec3>,
    pub hidden: Vec<String>,
    pub styles: Vec<(String, RenderStyle)>,
    pub tracks: Vec<NoteTrack>,
}

/// A note that could not be read: 1-based line within the note.
#[derive(Clone, Debug, PartialEq)]
pub struct NoteError {
    pub line: usize,
    pub message: String,
}

impl std::fmt::Display for NoteError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "key note line {}: {}", self.line, self.message)
    }
}

impl std::error::Error for NoteError {}

fn style_name(s: RenderStyle) -> &'static str {
    match s {
        RenderStyle::Filled => "filled",
        RenderStyle::Lines => "lines",
        RenderStyle::Points => "points",
        RenderStyle::Hidden => "hidden",
    }
}

/// Prints the note for `scene`, naming targets as `plan` writes them.
/// Tracks whose target has no name in the plan are skipped (the plan names
/// every animated target, so that only happens for dangling ids).
pub fn write(scene: &Scene, plan: &WritePlan) -> String {
    let mut s = String::new();
    // `write!` into a String cannot fail.
    let _ = writeln!(s, "{MARKER}");
    let _ = writeln!(s, "fps {}", scene.settings.fps);
    let _ = writeln!(s, "duration {}", scene.settings.duration);
    let b = scene.settings.background;
    let _ = writeln!(s, "background {} {} {}", b.x, b.y, b.z);
    if let Some(h) = scene.settings.headlight {
        let _ = writeln!(s, "headlight {}", if h { "on" } else { "off" });
    }
    let a = scene.settings.ambient;
    if a != Vec3::ZERO {
        let _ = writeln!(s, "ambient {} {} {}", a.x, a.y, a.z);
    }
    // Sorted by name: the order must not depend on how a reader orders nodes.
    let mut flags: Vec<(String, String)> = Vec::new();
    for id in scene.walk() {
        let node = scene.node(id);
        let Some(name) = plan.node_name(id) else {
            continue;
        };
        if !node.visible {
            flags.push((name.to_string(), format!("hidden {name}")));
        }
        if node.style != RenderStyle::Filled {
            flags.push((
                format!("{name}~"),
                format!("style {name} {}", style_name(node.style)),
            ));
        }
    }
    flags.sort();
    for (_, line) in flags {
        let _ = writeln!(s, "{line}");
    }
    for t in &scene.animation.tracks {
        let Some((owner, name)) = plan.target_name(t.target.of, t.target.property) else {
            continue;
        };
        let repeat = match t.repeat {
            Repeat::Constant => "constant",
            Repeat::Loop => "loop",
        };
        let _ = writeln!(
            s,
            "track {owner} {name} {} {repeat}",
            t.target.property.name()
        );
        match &t.keys {
            Keys::Scalar(k) => write_keys(&mut s, k, |v| vec![*v]),
            Keys::Vec3(k) => write_keys(&mut s, k, |v| v.to_array().to_vec()),
            Keys::Rotation(k) => write_keys(&mut s, k, |q| q.to_array().to_vec()),
            Keys::Bool(k) => write_keys(&mut s, k, |b| vec![if *b { 1.0 } else { 0.0 }]),
            Keys::Weights(k) => write_keys(&mut s, k, |w| w.as_slice().to_vec()),
        }
    }
    s.push_str("end\n");
    s
}

fn write_keys<V>(s: &mut String, keys: &[Key<V>], numbers: impl Fn(&V) -> Vec<f32>) {
    for k in keys {
        let interp = match k.interp {
            Interp::Step => "step",
            Interp::Linear => "linear",
            Interp::Tcb => "tcb",
        };
        let _ = write!(
            s,
            "key {} {interp} {} {} {} {} {}",
            k.frame, k.tension, k.continuity, k.bias, k.ease_in, k.ease_out
        );
        for x in numbers(&k.value) {
            let _ = write!(s, " {x}");
        }
        s.push('\n');
    }
}

/// Whether `text` is (starts with) a key note.
pub fn is_note(text: &str) -> bool {
    text.trim_start()
        .lines()
        .next()
        .is_some_and(|l| l.trim() == MARKER)
}

/// Parses a note; errors carry the 1-based line within the note.
pub fn parse(text: &str) -> Result<Note, NoteError> {
    let mut lines = text
        .trim_start_matches(['\n', '\r'])
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let err = |line: usize, message: String| NoteError { line, message };
    match lines.next() {
        Some((_, l)) if l == MARKER => {}
        Some((n, l)) => {
            return Err(err(n, format!("expected `{MARKER}`, found `{l}`")));
        }
        None => return Err(err(1, "empty key note".into())),
    }
    let mut note = Note {
        fps: 24.0,
        duration: 96.0,
        background: None,
        headlight: None,
        ambient: None,
        hidden: Vec::new(),
        styles: Vec::new(),
        tracks: Vec::new(),
    };
    let mut ended = false;
    let mut last_line = 1;
    for (n, line) in lines.by_ref() {
        last_line = n;
        let words: Vec<&str> = line.split_whitespace().collect();
        match words[0] {
            "fps" | "duration" => {
                let [_, v] = words[..] else {
                    return Err(err(n, format!("`{}` takes one number", words[0])));
                };
                let v = number(v).map_err(|m| err(n, m))?;
                if v <= 0.0 {
                    return Err(err(n, format!("{} must be positive", words[0])));
                }
                if words[0] == "fps" {
                    note.fps = v;
                } else {
                    note.duration = v;
                }
            }
            "background" | "ambient" => {
                let [what, r, g, b] = words[..] else {
                    return Err(err(n, format!("`{}` takes three numbers", words[0])));
                };
                let c = [r, g, b]
                    .iter()
                    .map(|w| number(w))
                    .collect::<Result<Vec<f32>, _>>()
                    .map_err(|m| err(n, m))?;
                let c = Some(Vec3::new(c[0], c[1], c[2]));
                if what == "ambient" {
                    note.ambient = c;
                } else {
                    note.background = c;
                }
            }
            "headlight" => {
                note.headlight = match words[..] {
                    [_, "on"] => Some(true),
                    [_, "off"] => Some(false),
                    _ => return Err(err(n, "`headlight` takes `on` or `off`".into())),
                };
            }
            "hidden" => {
                let [_, name] = words[..] else {
                    return Err(err(n, "`hidden` takes one name".into()));
                };
                note.hidden.push(name.to_string());
            }
            "style" => {
                let [_, name, style] = words[..] else {
                    return Err(err(n, "`style` takes a name and a style".into()));
                };
                let style = match style {
                    "filled" => RenderStyle::Filled,
                    "lines" => RenderStyle::Lines,
                    "points" => RenderStyle::Points,
                    "hidden" => RenderStyle::Hidden,
                    _ => return Err(err(n, format!("unknown style `{style}`"))),
                };
                note.styles.push((name.to_string(), style));
            }
            "track" => {
                let [_, owner, name, prop, repeat] = words[..] else {
                    return Err(err(
                        n,
                        "`track` takes: node|material NAME PROPERTY constant|loop".into(),
                    ));
                };
                let owner = match owner {
                    "node" => Owner::Node,
                    "material" => Owner::Material,
                    _ => return Err(err(n, format!("unknown target kind `{owner}`"))),
                };
                let property = Property::parse(prop)
                    .ok_or_else(|| err(n, format!("unknown property `{prop}`")))?;
                if (owner == Owner::Material) != (property.owner() == "material") {
                    return Err(err(
                        n,
                        format!("property `{prop}` does not belong to a {}", words[1]),
                    ));
                }
                let repeat = match repeat {
                    "constant" => Repeat::Constant,
                    "loop" => Repeat::Loop,
                    _ => return Err(err(n, format!("unknown repeat mode `{repeat}`"))),
                };
                let keys = match property.kind() {
                    ValueKind::Scalar => Keys::Scalar(Vec::new()),
                    ValueKind::Vec3 | ValueKind::Color => Keys::Vec3(Vec::new()),
                    ValueKind::Rotation => Keys::Rotation(Vec::new()),
                    ValueKind::Bool => Keys::Bool(Vec::new()),
                    ValueKind::Weights => Keys::Weights(Vec::new()),
                };
                note.tracks.push(NoteTrack {
                    owner,
                    name: name.to_string(),
                    property,
                    repeat,
                    keys,
                });
            }
            "key" => {
                let Some(track) = note.tracks.last_mut() else {
                    return Err(err(n, "`key` before any `track`".into()));
                };
                parse_key(&words, &mut track.keys).map_err(|m| err(n, m))?;
            }
            "end" => {
                ended = true;
                break;
            }
            w => return Err(err(n, format!("unknown item `{w}`"))),
        }
    }
    if !ended {
        return Err(err(last_line, "the note has no `end` line".into()));
    }
    for t in &note.tracks {
        if t.keys.is_empty() {
            return Err(err(
                last_line,
                format!("track {} {} has no keys", t.name, t.property.name()),
            ));
        }
    }
    Ok(note)
}

fn number(s: &str) -> Result<f32, String> {
    match s.parse::<f32>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(format!("`{s}` is not a finite number")),
    }
}

fn parse_key(words: &[&str], keys: &mut Keys) -> Result<(), String> {
    let want = match keys {
        Keys::Scalar(_) | Keys::Bool(_) => 1,
        Keys::Vec3(_) => 3,
        Keys::Rotation(_) => 4,
        // One per morph target.
        Keys::Weights(_) => words.len().saturating_sub(8).clamp(1, MAX_MORPH_TARGETS),
    };
    if words.len() != 8 + want {
        return Err(format!(
            "`key` takes FRAME INTERP T C B EASE_IN EASE_OUT and {want} value number(s), found {} words",
            words.len() - 1
        ));
    }
    let frame = number(words[1])?;
    let interp = match words[2] {
        "step" => Interp::Step,
        "linear" => Interp::Linear,
        "tcb" => Interp::Tcb,
        w => return Err(format!("unknown interpolation `{w}`")),
    };
    let mut p = [0.0f32; 5];
    for (i, w) in words[3..8].iter().enumerate() {
        p[i] = number(w)?;
    }
    for (i, what) in ["tension", "continuity", "bias"].iter().enumerate() {
        if !(-1.0..=1.0).contains(&p[i]) {
            return Err(format!("{what} {} is outside [-1, 1]", p[i]));
        }
    }
    for (i, what) in [(3, "ease in"), (4, "ease out")] {
        if !(0.0..=1.0).contains(&p[i]) {
            return Err(format!("{what} {} is outside [0, 1]", p[i]));
        }
    }
    let v: Vec<f32> = words[8..]
        .iter()
        .map(|w| number(w))
        .collect::<Result<_, _>>()?;
    let prev = keys.frames().last().copied();
    if let Some(prev) = prev {
        if frame <= prev {
            return Err(format!(
                "key frame {frame} is not after the previous key ({prev})"
            ));
        }
    }
    fn mk<V>(frame: f32, value: V, interp: Interp, p: [f32; 5]) -> Key<V> {
        Key {
            frame,
            value,
            interp,
            tension: p[0],
            continuity: p[1],
            bias: p[2],
            ease_in: p[3],
            ease_out: p[4],
        }
    }
    match keys {
        Keys::Scalar(k) => k.push(mk(frame, v[0], interp, p)),
        Keys::Vec3(k) => k.push(mk(frame, Vec3::new(v[0], v[1], v[2]), interp, p)),
        Keys::Rotation(k) => {
            let q = Quat::from_xyzw(v[0], v[1], v[2], v[3]);
            if (q.length() - 1.0).abs() > 1e-3 {
                return Err("rotation quaternion is not of unit length".into());
            }
            k.push(mk(frame, q, interp, p))
        }
        Keys::Bool(k) => {
            let b = match words[8] {
                "0" => false,
                "1" => true,
                w => return Err(format!("boolean value must be 0 or 1, found `{w}`")),
            };
            k.push(mk(frame, b, interp, p))
        }
        Keys::Weights(k) => k.push(mk(frame, Weights::from_slice_truncated(&v), interp, p)),
    }
    Ok(())
}

/// Whether a node can hold `property` (transform properties: any node).
fn node_owns(kind: &NodeKind, property: Property) -> bool {
    match property.owner() {
        "light" => matches!(kind, NodeKind::Light(_)),
        "camera" => matches!(kind, NodeKind::Camera(_)),
        "node" => true,
        "shape" => matches!(kind, NodeKind::Shape(_) | NodeKind::Group),
        _ => false,
    }
}

/// Puts the note's settings and tracks into `scene`, resolving names.
/// The scene's tracks are replaced by the note's.
pub fn apply(note: &Note, scene: &mut Scene) -> Result<(), String> {
    let mut tracks = Vec::with_capacity(note.tracks.len());
    for t in &note.tracks {
        let of = match t.owner {
            Owner::Node => {
                let id = scene
                    .find_node(&t.name)
                    .ok_or_else(|| format!("no node named `{}` in the scene", t.name))?;
                if !node_owns(&scene.node(id).kind, t.property) {
                    return Err(format!(
                        "node `{}` has no property `{}`",
                        t.name,
                        t.property.name()
                    ));
                }
                TargetRef::Node(id)
            }
            Owner::Material => TargetRef::Material(
                scene
                    .find_material(&t.name)
                    .ok_or_else(|| format!("no material named `{}` in the scene", t.name))?,
            ),
        };
        // Weights keyed for targets the file no longer has as such (a .wrl
        // plays a morph as a CoordinateInterpolator, read back with one
        // target per key): keep the reader's track, which plays the file.
        if t.property == Property::MorphWeights && !weights_fit(scene, of, &t.keys) {
            tracks.extend(
                scene
                    .animation
                    .tracks
                    .iter()
                    .filter(|k| k.target.of == of && k.target.property == t.property)
                    .cloned(),
            );
            continue;
        }
        tracks.push(Track {
            target: Target {
                of,
                property: t.property,
            },
            repeat: t.repeat,
            keys: t.keys.clone(),
        });
    }
    // Morph weights the reader made from the file (a .wrl's
    // CoordinateInterpolator) that the note does not key: the only record of
    // a deformation (a skin's, say) that the file plays.
    for t in &scene.animation.tracks {
        if t.target.property == Property::MorphWeights
            && !tracks.iter().any(|k| k.target == t.target)
        {
            tracks.push(t.clone());
        }
    }
    let mut hidden = Vec::new();
    for name in &note.hidden {
        hidden.push(
            scene
                .find_node(name)
                .ok_or_else(|| format!("no node named `{name}` in the scene"))?,
        );
    }
    let mut styles = Vec::new();
    for (name, style) in &note.styles {
        let id = scene
            .find_node(name)
            .ok_or_else(|| format!("no node named `{name}` in the scene"))?;
        styles.push((id, *style));
    }
    for id in hidden {
        scene.node_mut(id).visible = false;
    }
    for (id, style) in styles {
        scene.node_mut(id).style = style;
    }
    scene.settings.fps = note.fps;
    scene.settings.duration = note.duration;
    if let Some(b) = note.background {
        scene.settings.background = b;
    }
    if let Some(a) = note.ambient {
        scene.settings.ambient = a;
    }
    if note.headlight.is_some() {
        scene.settings.headlight = note.headlight;
    }
    scene.animation.tracks = tracks;
    Ok(())
}

/// Whether weights keys have one number per morph target of the shape
/// (or of each morphed child shape of a group).
fn weights_fit(scene: &Scene, of: TargetRef, keys: &Keys) -> bool {
    let TargetRef::Node(id) = of else {
        return false;
    };
    let Keys::Weights(k) = keys else {
        return false;
    };
    let count = |id: crate::scene::NodeId| match &scene.node(id).kind {
        NodeKind::Shape(s) => scene
            .meshes
            .get(s.mesh.0 as usize)
            .and_then(|m| m.morph.as_ref())
            .map(|m| m.len()),
        _ => None,
    };
    let n = count(id).or_else(|| scene.node(id).children.iter().find_map(|&c| count(c)));
    n.is_some_and(|n| k.iter().all(|k| k.value.len() == n))
}

/// The post-load hook: if the scene's info holds an animed key note, take
/// it out of `info` and let it replace the tracks the reader built from the
/// sampled interpolators. A note that cannot be used becomes a warning and
/// the reader's tracks stay.
pub fn apply_to_loaded(loaded: &mut Loaded, path: &Path) {
    let Some(i) = loaded.scene.info.iter().position(|s| is_note(s)) else {
        return;
    };
    let text = loaded.scene.info.remove(i);
    let result = parse(&text)
        .map_err(|e| e.to_string())
        .and_then(|note| apply(&note, &mut loaded.scene));
    match result {
        // The note replaces what the engines would drive, so the reader's
        // remark that it does not evaluate them no longer applies.
        Ok(()) => loaded
            .warnings
            .retain(|w| !w.contains("field connections (engines) are not evaluated")),
        Err(e) => loaded.warnings.push(format!(
            "{}: ignored the animed key note ({e}); using the file's interpolators",
            path.display()
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Light, LightKind, Material, Node};

    fn scene() -> Scene {
        let mut s = Scene::new();
        let a = s.add_node(None, Node::group("Box"));
        let l = s.add_node(
            Some(a),
            Node::new("Lamp", NodeKind::Light(Light::new(LightKind::Point))),
        );
        let m = s.add_material(Material {
            name: "Red".into(),
            ..Default::default()
        });
        s.settings.fps = 30.0;
        s.settings.duration = 61.5;
        s.node_mut(a).visible = false;
        let mut k = Key::new(0.0, Vec3::new(0.1, -2.5, 1e-7)).with_tcb(0.5, -0.25, 1.0);
        k.ease_in = 0.3;
        s.animation.tracks = vec![
            Track {
                target: Target {
                    of: TargetRef::Node(a),
                    property: Property::Translation,
                },
                repeat: Repeat::Loop,
                keys: Keys::Vec3(vec![
                    k,
                    Key::new(12.25, Vec3::ONE).with_interp(Interp::Linear),
                ]),
            },
            Track {
                target: Target {
                    of: TargetRef::Node(l),
                    property: Property::LightOn,
                },
                repeat: Repeat::Constant,
                keys: Keys::Bool(vec![
                    Key::new(0.0, true).with_interp(Interp::Step),
                    Key::new(5.0, false).with_interp(Interp::Step),
                ]),
            },
            Track {
                target: Target {
                    of: TargetRef::Node(a),
                    property: Property::Rotation,
                },
                repeat: Repeat::Constant,
                keys: Keys::Rotation(vec![Key::new(
                    3.0,
                    Quat::from_axis_angle(Vec3::new(0.6, 0.8, 0.0), 2.0),
                )]),
            },
            Track {
                target: Target {
                    of: TargetRef::Material(m),
                    property: Property::Diffuse,
                },
                repeat: Repeat::Constant,
                keys: Keys::Vec3(vec![Key::new(1.0, Vec3::new(1.0, 0.0, 0.0))]),
            },
        ];
        s
    }

    #[test]
    fn print_then_parse_then_apply_gives_the_same_tracks() {
        let s = scene();
        let plan = WritePlan::new(&s);
        let text = write(&s, &plan);
        assert!(text.starts_with("animed-keys 1\nfps 30\nduration 61.5\nbackground 0 0 0\n"));
        assert!(text.contains("hidden Box\n"), "{text}");
        assert!(text.contains("track material Red diffuseColor constant\n"));
        let note = parse(&text).unwrap();
        let mut t = s.clone();
        t.animation.tracks.clear();
        t.settings = Default::default();
        t.node_mut(crate::scene::NodeId(0)).visible = true;
        apply(&note, &mut t).unwrap();
        assert_eq!(t.animation, s.animation);
        assert_eq!(t.settings, s.settings);
        assert!(!t.nodes[0].visible);
        assert_eq!(write(&t, &WritePlan::new(&t)), text);
    }

    #[test]
    fn errors_name_the_line() {
        let bad = "animed-keys 1\nfps 24\ntrack node A translation constant\nkey 0 tcb 0 0 0 0 0 1 2\nend\n";
        let e = parse(bad).unwrap_err();
        assert_eq!(e.line, 4);
        assert!(e.message.contains("3 value number"), "{}", e.message);
        let e = parse("animed-keys 1\nkey 0 step 0 0 0 0 0 1\nend").unwrap_err();
        assert_eq!(e.line, 2);
        let e = parse(
            "animed-keys 1\ntrack node A translation constant\nkey 1 tcb 2 0 0 0 0 1 2 3\nend",
        )
        .unwrap_err();
        assert!(e.message.contains("tension"));
        let e = parse("animed-keys 1\ntrack node A visible constant\nkey 1 step 0 0 0 0 0 1\nkey 1 step 0 0 0 0 0 0\nend").unwrap_err();
        assert_eq!(e.line, 4);
        let e = parse("animed-keys 1\nfps 24\n").unwrap_err();
        assert!(e.message.contains("end"));
        let e = parse("animed-keys 1\ntrack node A on constant\nkey 1 step 0 0 0 0 0 NaN\nend")
            .unwrap_err();
        assert!(e.message.contains("finite"));
    }

    #[test]
    fn unresolved_names_are_reported() {
        let note = parse("animed-keys 1\ntrack node Nope translation constant\nkey 0 linear 0 0 0 0 0 1 2 3\nend\n").unwrap();
        let mut s = scene();
        let e = apply(&note, &mut s).unwrap_err();
        assert!(e.contains("Nope"));
        let note = parse(
            "animed-keys 1\ntrack node Box intensity constant\nkey 0 linear 0 0 0 0 0 1\nend\n",
        )
        .unwrap();
        assert!(apply(&note, &mut s).unwrap_err().contains("no property"));
    }

    #[test]
    fn hook_takes_the_note_out_of_info() {
        let s = scene();
        let text = write(&s, &WritePlan::new(&s));
        let mut t = s.clone();
        t.animation.tracks.clear();
        t.info = vec!["made by hand".into(), text];
        let mut loaded = Loaded {
            scene: t,
            warnings: vec![],
        };
        apply_to_loaded(&mut loaded, Path::new("x.wrl"));
        assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
        assert_eq!(loaded.scene.info, vec!["made by hand".to_string()]);
        assert_eq!(loaded.scene.animation, s.animation);

        let mut broken = Loaded {
            scene: s.clone(),
            warnings: vec![],
        };
        broken.scene.info = vec!["animed-keys 1\nfps x\nend\n".into()];
        apply_to_loaded(&mut broken, Path::new("x.wrl"));
        assert_eq!(broken.warnings.len(), 1);
        assert!(
            broken.warnings[0].contains("line 2"),
            "{:?}",
            broken.warnings
        );
        assert_eq!(broken.scene.animation, s.animation);
    }
}
