//! Editable values shown in the side panel: how to read each from the scene,
//! how to write a new value (on a copy of a node or of the settings), and
//! how fast a drag changes it.

use crate::anim::Property;
use crate::scene::{LightKind, Node, NodeKind, Settings};
use glam::{EulerRot, Quat, Vec3};

/// Which value a field shows. Axis/channel indices are 0..3.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FieldId {
    Fps,
    Duration,
    /// The current frame (editor state, not part of the scene).
    Frame,
    Name,
    Translation(u8),
    /// Euler angle in degrees (XYZ order).
    Rotation(u8),
    Scale(u8),
    LightIntensity,
    LightColor(u8),
    LightLocation(u8),
    LightDirection(u8),
    /// Spot cut-off angle in degrees.
    LightCutOff,
    /// A parameter of the selected keys (the key panel, `keyprops.rs`).
    Key(KeyField),
    /// Morph target weight i of the selection (`rig/morph.rs`).
    Morph(u8),
    /// The playing clip's name (`rig/clips.rs`).
    ClipName,
    /// A value of the selection's material (`material/`).
    Material(super::material::MatField),
    /// The preview range's first (0) or last (1) frame (editor state,
    /// typed only).
    Preview(u8),
}

/// A field's value.
#[derive(Clone, Debug, PartialEq)]
pub enum FieldValue {
    Number(f32),
    Text(String),
}

impl FieldValue {
    /// The text shown in the field (numbers with up to 3 decimals, no
    /// trailing zeros).
    pub fn display(&self) -> String {
        match self {
            FieldValue::Text(s) => s.clone(),
            FieldValue::Number(x) => format_number(*x),
        }
    }
}

/// Like [`format_number`] but with fewer decimals when the text would be
/// longer than `max_chars` (never cutting the integer part).
pub fn format_fit(x: f32, max_chars: usize) -> String {
    for decimals in (0..=3).rev() {
        let x = if x.abs() < 0.5 * 10f32.powi(-decimals) {
            0.0
        } else {
            x
        };
        let s = format!("{x:.*}", decimals as usize);
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        };
        if s.chars().count() <= max_chars || decimals == 0 {
            return s;
        }
    }
    format_number(x)
}

pub fn format_number(x: f32) -> String {
    let x = if x.abs() < 5e-4 { 0.0 } else { x };
    let s = format!("{x:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.to_string()
}

impl FieldId {
    /// Whether the field belongs to the scene settings (else to a node).
    pub fn is_setting(self) -> bool {
        matches!(self, FieldId::Fps | FieldId::Duration)
    }

    pub fn is_text(self) -> bool {
        matches!(self, FieldId::Name | FieldId::ClipName)
    }

    /// The field's name in messages ("Fps", "Translation x", "Color g").
    pub fn label(self) -> String {
        let axis = |i: u8| ["x", "y", "z"][(i as usize).min(2)];
        let rgb = |i: u8| ["r", "g", "b"][(i as usize).min(2)];
        match self {
            FieldId::Translation(i) => format!("Translation {}", axis(i)),
            FieldId::Rotation(i) => format!("Rotation {}", axis(i)),
            FieldId::Scale(i) => format!("Scale {}", axis(i)),
            FieldId::LightColor(i) => format!("Color {}", rgb(i)),
            FieldId::LightLocation(i) => format!("Location {}", axis(i)),
            FieldId::LightDirection(i) => format!("Direction {}", axis(i)),
            FieldId::LightIntensity => "Intensity".into(),
            FieldId::LightCutOff => "Cut-off angle".into(),
            FieldId::Key(k) => format!("Key {k:?}"),
            FieldId::Morph(i) => format!("Weight {i}"),
            FieldId::ClipName => "Clip name".into(),
            FieldId::Material(m) => m.label(),
            FieldId::Preview(0) => "Preview start".into(),
            FieldId::Preview(_) => "Preview end".into(),
            other => format!("{other:?}"),
        }
    }

    /// Change per pixel of horizontal drag.
    pub fn drag_step(self) -> f32 {
        match self {
            FieldId::Fps | FieldId::Duration | FieldId::Frame => 0.25,
            FieldId::Rotation(_) | FieldId::LightCutOff => 0.5,
            FieldId::LightColor(_)
            | FieldId::LightDirection(_)
            | FieldId::Morph(_)
            | FieldId::Material(_) => 0.005,
            FieldId::LightIntensity | FieldId::Scale(_) => 0.01,
            _ => 0.02,
        }
    }

    /// Clamps a candidate value to what the property accepts.
    pub fn clamp(self, v: f32) -> f32 {
        match self {
            FieldId::Fps => v.clamp(1.0, 240.0).round(),
            FieldId::Duration => v.clamp(1.0, 100_000.0).round(),
            FieldId::Frame => v.max(0.0),
            FieldId::LightColor(_) | FieldId::LightIntensity => v.clamp(0.0, 1.0),
            FieldId::LightCutOff => v.clamp(0.0, 90.0),
            FieldId::Material(m) => m.clamp(v),
            _ => v,
        }
    }

    pub fn read_settings(self, s: &Settings) -> Option<FieldValue> {
        match self {
            FieldId::Fps => Some(FieldValue::Number(s.fps)),
            FieldId::Duration => Some(FieldValue::Number(s.duration)),
            _ => None,
        }
    }

    /// Writes into a copy of the settings.
    pub fn write_settings(self, s: &mut Settings, v: &FieldValue) -> bool {
        let FieldValue::Number(x) = v else {
            return false;
        };
        match self {
            FieldId::Fps => s.fps = self.clamp(*x),
            FieldId::Duration => s.duration = self.clamp(*x),
            _ => return false,
        }
        true
    }

    pub fn read_node(self, n: &Node) -> Option<FieldValue> {
        let t = &n.transform;
        let num = |x: f32| Some(FieldValue::Number(x));
        match (self, &n.kind) {
            (FieldId::Name, _) => Some(FieldValue::Text(n.name.clone())),
            (FieldId::Translation(i), _) => num(t.translation[i as usize]),
            (FieldId::Rotation(i), _) => num(euler_degrees(t.rotation)[i as usize]),
            (FieldId::Scale(i), _) => num(t.scale[i as usize]),
            (FieldId::LightIntensity, NodeKind::Light(l)) => num(l.intensity),
            (FieldId::LightColor(i), NodeKind::Light(l)) => num(l.color[i as usize]),
            (FieldId::LightLocation(i), NodeKind::Light(l)) => num(l.location[i as usize]),
            (FieldId::LightDirection(i), NodeKind::Light(l)) => num(l.direction[i as usize]),
            (FieldId::LightCutOff, NodeKind::Light(l)) => match l.kind {
                LightKind::Spot { cut_off_angle, .. } => num(cut_off_angle.to_degrees()),
                _ => None,
            },
            _ => None,
        }
    }

    /// Writes into a copy of a node; returns false when the field does not
    /// apply or the value has the wrong type.
    pub fn write_node(self, n: &mut Node, v: &FieldValue) -> bool {
        if let (FieldId::Name, FieldValue::Text(s)) = (self, v) {
            n.name = sanitize_name(s);
            return true;
        }
        let FieldValue::Number(x) = v else {
            return false;
        };
        let x = self.clamp(*x);
        if !x.is_finite() {
            return false;
        }
        let t = &mut n.transform;
        match (self, &mut n.kind) {
            (FieldId::Translation(i), _) => t.translation[i as usize] = x,
            (FieldId::Rotation(i), _) => {
                let mut e = euler_degrees(t.rotation);
                e[i as usize] = x;
                t.rotation = from_euler_degrees(e);
            }
            (FieldId::Scale(i), _) => t.scale[i as usize] = x,
            (FieldId::LightIntensity, NodeKind::Light(l)) => l.intensity = x,
            (FieldId::LightColor(i), NodeKind::Light(l)) => l.color[i as usize] = x,
            (FieldId::LightLocation(i), NodeKind::Light(l)) => l.location[i as usize] = x,
            (FieldId::LightDirection(i), NodeKind::Light(l)) => l.direction[i as usize] = x,
            (FieldId::LightCutOff, NodeKind::Light(l)) => match &mut l.kind {
                LightKind::Spot { cut_off_angle, .. } => *cut_off_angle = x.to_radians(),
                _ => return false,
            },
            _ => return false,
        }
        true
    }
}

/// VRML/Inventor names cannot hold spaces, quotes, braces and a few more;
/// replace them so the writers never produce an unreadable DEF.
pub fn sanitize_name(s: &str) -> String {
    s.trim()
        .chars()
        .map(|c| {
            if c.is_whitespace() || "\"'#,.[]\\{}+".contains(c) || c.is_control() {
                '_'
            } else {
                c
            }
        })
        .collect()
}

pub fn euler_degrees(q: Quat) -> Vec3 {
    let (x, y, z) = q.to_euler(EulerRot::XYZ);
    Vec3::new(x.to_degrees(), y.to_degrees(), z.to_degrees())
}

pub fn from_euler_degrees(e: Vec3) -> Quat {
    Quat::from_euler(
        EulerRot::XYZ,
        e.x.to_radians(),
        e.y.to_radians(),
        e.z.to_radians(),
    )
}

/// Parses a typed number; accepts a leading `+`, and simple `a+b`, `a-b`,
/// `a*b`, `a/b` arithmetic as Blender does for quick offsets.
/// What the status line says when a typed number was not taken as typed
/// (clamped into range or rounded); `None` when it was.
pub fn clamp_note(name: &str, typed: f32, kept: f32) -> Option<String> {
    if (typed - kept).abs() <= 1e-6 * typed.abs().max(1.0) {
        return None;
    }
    let (t, k) = (format_number(typed), format_number(kept));
    Some(
        if (typed.round() - kept).abs() <= 1e-6 * typed.abs().max(1.0) {
            format!("{name}: {t} rounded to {k} (whole numbers only)")
        } else if kept < typed {
            format!("{name}: {t} is above the largest allowed value; set to {k}")
        } else {
            format!("{name}: {t} is below the smallest allowed value; set to {k}")
        },
    )
}

pub fn parse_number(s: &str) -> Option<f32> {
    let s = s.trim();
    if let Ok(x) = s.parse::<f32>() {
        return x.is_finite().then_some(x);
    }
    // Split at the last binary operator that is not a leading sign:
    // + and - first (lowest precedence), then * and /.
    let bytes = s.as_bytes();
    for ops in ["+-", "*/"] {
        for i in (1..bytes.len()).rev() {
            let op = bytes[i] as char;
            let prev = bytes[i - 1] as char;
            if ops.contains(op) && !matches!(prev, 'e' | 'E' | '+' | '-' | '*' | '/') {
                let a = parse_number(&s[..i])?;
                let b = parse_number(&s[i + 1..])?;
                let r = match op {
                    '+' => a + b,
                    '-' => a - b,
                    '*' => a * b,
                    _ => a / b,
                };
                return r.is_finite().then_some(r);
            }
        }
    }
    None
}

/// Which key parameter a key panel field edits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KeyField {
    Frame,
    /// Component of the value (x/y/z, r/g/b, Euler degrees; 0 for scalars).
    Value(u8),
    Tension,
    Continuity,
    Bias,
    EaseIn,
    EaseOut,
}

/// The node field that edits the same value as `Value(i)` of a key of
/// `p` (for clamping and drag speed).
fn value_field(p: Property, i: u8) -> Option<FieldId> {
    Some(match p {
        Property::Translation => FieldId::Translation(i),
        Property::Rotation => FieldId::Rotation(i),
        Property::Scale => FieldId::Scale(i),
        Property::LightIntensity => FieldId::LightIntensity,
        Property::LightColor => FieldId::LightColor(i),
        Property::LightLocation => FieldId::LightLocation(i),
        Property::LightDirection => FieldId::LightDirection(i),
        _ => return None,
    })
}

impl KeyField {
    /// Change per pixel of horizontal drag for a key of `p`.
    pub fn drag_step(self, p: Property) -> f32 {
        match self {
            KeyField::Frame => 0.25,
            KeyField::Value(i) => value_field(p, i).map(|f| f.drag_step()).unwrap_or(0.02),
            _ => 0.01,
        }
    }

    /// What the parameter accepts (TCB [-1, 1], ease [0, 1], frames >= 0).
    pub fn clamp(self, p: Property, v: f32) -> f32 {
        match self {
            KeyField::Frame => v.max(0.0).round(),
            KeyField::Value(i) => value_field(p, i).map(|f| f.clamp(v)).unwrap_or(v),
            KeyField::Tension | KeyField::Continuity | KeyField::Bias => v.clamp(-1.0, 1.0),
            KeyField::EaseIn | KeyField::EaseOut => v.clamp(0.0, 1.0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Light;

    #[test]
    fn numbers_fit_their_field() {
        assert_eq!(format_fit(-0.05, 5), "-0.05");
        assert_eq!(format_fit(-0.05, 4), "-0.1");
        assert_eq!(format_fit(-0.05, 2), "0");
        assert_eq!(format_fit(123.456, 6), "123.46");
        assert_eq!(format_fit(12345.0, 3), "12345");
    }

    #[test]
    fn clamped_values_are_named() {
        assert_eq!(clamp_note("Fps", 24.0, 24.0), None);
        let n = clamp_note("Fps", 500.0, FieldId::Fps.clamp(500.0)).unwrap();
        assert_eq!(n, "Fps: 500 is above the largest allowed value; set to 240");
        let n = clamp_note("Fps", 24.4, FieldId::Fps.clamp(24.4)).unwrap();
        assert_eq!(n, "Fps: 24.4 rounded to 24 (whole numbers only)");
        let n = clamp_note("Intensity", -2.0, FieldId::LightIntensity.clamp(-2.0)).unwrap();
        assert!(n.contains("below") && n.ends_with("set to 0"), "{n}");
        assert_eq!(FieldId::LightColor(1).label(), "Color g");
    }

    #[test]
    fn numbers_format_and_parse() {
        assert_eq!(format_number(1.5), "1.5");
        assert_eq!(format_number(2.0), "2");
        assert_eq!(format_number(-0.0001), "0");
        assert_eq!(parse_number(" 2.5 "), Some(2.5));
        assert_eq!(parse_number("1+2*3"), Some(7.0));
        assert_eq!(parse_number("-1"), Some(-1.0));
        assert_eq!(parse_number("1e-1"), Some(0.1));
        assert_eq!(parse_number("abc"), None);
        assert_eq!(parse_number("1/0"), None);
    }

    #[test]
    fn rotation_field_round_trips() {
        let mut n = Node::group("a");
        assert!(FieldId::Rotation(1).write_node(&mut n, &FieldValue::Number(30.0)));
        let FieldValue::Number(y) = FieldId::Rotation(1).read_node(&n).unwrap() else {
            panic!("number")
        };
        assert!((y - 30.0).abs() < 1e-3);
    }

    #[test]
    fn light_fields_apply_only_to_lights() {
        let mut g = Node::group("g");
        assert!(!FieldId::LightIntensity.write_node(&mut g, &FieldValue::Number(0.5)));
        let mut l = Node::new("l", NodeKind::Light(Light::spot()));
        assert!(FieldId::LightIntensity.write_node(&mut l, &FieldValue::Number(5.0)));
        assert_eq!(l.light().unwrap().intensity, 1.0, "clamped to 0..1");
        assert!(FieldId::LightCutOff.write_node(&mut l, &FieldValue::Number(30.0)));
        let Some(FieldValue::Number(c)) = FieldId::LightCutOff.read_node(&l) else {
            panic!("spot lights have a cut-off")
        };
        assert!((c - 30.0).abs() < 1e-4);
    }

    #[test]
    fn names_are_made_safe() {
        assert_eq!(sanitize_name(" my box{1} "), "my_box_1_");
    }
}
