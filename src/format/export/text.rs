//! Number and string spelling shared by the VRML97 and Inventor writers.
//!
//! Numbers use Rust's shortest round-trip form of an `f32` (`{}`), so a
//! reader that parses to `f32` gets the same bits back; rotations are
//! written as the axis-angle that reads back to a quaternion which writes
//! the same axis-angle again (so export → import → export is stable).

use crate::scene::Transform;
use glam::{Quat, Vec3};
use std::fmt::Write as _;

/// An indenting text buffer.
#[derive(Default)]
pub struct Out {
    pub text: String,
    pub depth: usize,
}

/// Deepest indentation written: past it lines stay at this depth, so a
/// deep scene's file grows linearly with the scene, not with depth × lines.
pub const MAX_INDENT: usize = 32;

impl Out {
    /// Writes one line at the current indentation.
    pub fn line(&mut self, s: &str) {
        for _ in 0..self.depth.min(MAX_INDENT) {
            self.text.push_str("  ");
        }
        self.text.push_str(s);
        self.text.push('\n');
    }

    /// `head {` and indent.
    pub fn open(&mut self, head: &str) {
        self.line(&format!("{head} {{"));
        self.depth += 1;
    }

    /// Dedent and `}` (or `]`).
    pub fn close(&mut self, end: &str) {
        self.depth = self.depth.saturating_sub(1);
        self.line(end);
    }

    /// A field holding many numbers: `name [` then rows, then `]`.
    pub fn list(&mut self, name: &str, rows: impl IntoIterator<Item = String>) {
        self.open_list(name);
        for r in rows {
            self.line(&r);
        }
        self.close("]");
    }

    fn open_list(&mut self, name: &str) {
        self.line(&format!("{name} ["));
        self.depth += 1;
    }
}

/// The `scaleOrientation` and `center` lines of a transform when they are
/// not the default: VRML97 and Inventor transforms name them alike.
pub fn pivot_fields(out: &mut Out, t: &Transform) {
    let d = Transform::default();
    if t.scale_orientation != d.scale_orientation {
        out.line(&format!(
            "scaleOrientation {}",
            rotation(t.scale_orientation)
        ));
    }
    if t.center != d.center {
        out.line(&format!("center {}", vec3(t.center)));
    }
}

/// One number; non-finite values (which a scene should never hold) as 0.
pub fn num(x: f32) -> String {
    if x.is_finite() {
        format!("{x}")
    } else {
        "0".to_string()
    }
}

pub fn vec3(v: Vec3) -> String {
    format!("{} {} {}", num(v.x), num(v.y), num(v.z))
}

/// `x y z angle` that reads back (as `Quat::from_axis_angle(axis.normalize(), angle)`)
/// to a rotation which prints the same four numbers again.
pub fn rotation(q: Quat) -> String {
    let (axis, angle) = axis_angle(q);
    format!("{} {}", vec3(axis), num(angle))
}

/// The stable axis-angle of `q` (see [`rotation`]).
pub fn axis_angle(q: Quat) -> (Vec3, f32) {
    let q = if q.is_finite() && q.length_squared() > 0.0 {
        q.normalize()
    } else {
        Quat::IDENTITY
    };
    let mut aa = q.to_axis_angle();
    for _ in 0..8 {
        let back = Quat::from_axis_angle(aa.0.normalize_or(Vec3::X), aa.1);
        let next = back.to_axis_angle();
        if next == aa {
            break;
        }
        aa = next;
    }
    aa
}

/// A double-quoted string with `"` and `\` escaped (VRML97 and Inventor).
pub fn quoted(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        if c == '"' || c == '\\' {
            out.push('\\');
        }
        out.push(c);
    }
    out.push('"');
    out
}

/// Rows of numbers, `per_row` items to a line, each item followed by `sep`.
pub fn rows<T>(items: &[T], per_row: usize, item: impl Fn(&T) -> String, sep: &str) -> Vec<String> {
    items
        .chunks(per_row.max(1))
        .map(|chunk| {
            let mut s = String::new();
            for (i, x) in chunk.iter().enumerate() {
                if i > 0 {
                    s.push(' ');
                }
                let _ = write!(s, "{}{sep}", item(x));
            }
            s
        })
        .collect()
}

/// How deep the nodes of a written file nest: the deepest `{` outside
/// strings and comments (each node of our output opens one). Checked on
/// save against the reader's depth limit.
pub fn nesting(text: &str) -> usize {
    let (mut depth, mut deepest) = (0usize, 0usize);
    let mut chars = text.chars();
    while let Some(c) = chars.next() {
        match c {
            '"' => {
                while let Some(c) = chars.next() {
                    match c {
                        '\\' => {
                            chars.next();
                        }
                        '"' => break,
                        _ => {}
                    }
                }
            }
            '#' => {
                for c in chars.by_ref() {
                    if c == '\n' {
                        break;
                    }
                }
            }
            '{' => {
                depth += 1;
                deepest = deepest.max(depth);
            }
            '}' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    deepest
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_round_trip_exactly() {
        for x in [0.1f32, 1.0 / 3.0, 1e-7, 123456.79, -0.0, 3.4e38] {
            assert_eq!(num(x).parse::<f32>().unwrap().to_bits(), x.to_bits());
        }
        assert_eq!(num(f32::NAN), "0");
    }

    #[test]
    fn rotation_text_is_a_fixed_point() {
        for (axis, angle) in [
            (Vec3::new(1.0, 2.0, 3.0), 0.7f32),
            (Vec3::Y, 3.0),
            (Vec3::new(-0.3, 0.1, 0.9), 5.9),
            (Vec3::X, 0.0),
        ] {
            let q = Quat::from_axis_angle(axis.normalize(), angle);
            let text = rotation(q);
            let n: Vec<f32> = text.split(' ').map(|w| w.parse().unwrap()).collect();
            let back =
                Quat::from_axis_angle(Vec3::new(n[0], n[1], n[2]).normalize_or(Vec3::X), n[3]);
            assert_eq!(rotation(back), text);
            assert!(back.dot(q).abs() > 0.99999);
        }
    }

    #[test]
    fn strings_are_escaped() {
        assert_eq!(quoted(r#"a "b" \c"#), r#""a \"b\" \\c""#);
    }
}
