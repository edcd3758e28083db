//! `Value` ⇄ plain numbers, as written in VRML/Inventor fields, on the
//! command line and in JSON: scalars `[x]`, vectors and colours `[x, y, z]`,
//! rotations as axis-angle `[x, y, z, angle]` (radians, VRML SFRotation),
//! booleans `[0]` / `[1]`.

use super::{Value, ValueKind, Weights, MAX_MORPH_TARGETS};
use glam::{Quat, Vec3};

/// Why numbers could not become a value.
#[derive(Clone, Debug, PartialEq)]
pub enum ValueError {
    /// Wrong count of numbers for the kind.
    Count {
        kind: ValueKind,
        expected: usize,
        got: usize,
    },
    /// A NaN or infinite number.
    NotFinite,
    /// A rotation with a zero axis and a non-zero angle.
    ZeroAxis,
    /// A boolean that is neither 0 nor 1.
    NotBool(f32),
}

impl std::fmt::Display for ValueError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ValueError::Count {
                kind,
                expected,
                got,
            } => write!(
                f,
                "a {} value needs {expected} number{}, got {got}",
                kind.name(),
                if *expected == 1 { "" } else { "s" }
            ),
            ValueError::NotFinite => write!(f, "values must be finite numbers"),
            ValueError::ZeroAxis => write!(f, "a rotation axis must not be zero"),
            ValueError::NotBool(x) => write!(f, "a boolean must be 0 or 1, got {x}"),
        }
    }
}

impl std::error::Error for ValueError {}

impl ValueKind {
    /// How many numbers a value of this kind is written with (weights: one
    /// per morph target, so 1 here stands for "at least one").
    pub fn arity(self) -> usize {
        match self {
            ValueKind::Scalar | ValueKind::Bool | ValueKind::Weights => 1,
            ValueKind::Vec3 | ValueKind::Color => 3,
            ValueKind::Rotation => 4,
        }
    }

    /// Lower-case name for messages: scalar, vec3, color, rotation, bool.
    pub fn name(self) -> &'static str {
        match self {
            ValueKind::Scalar => "scalar",
            ValueKind::Vec3 => "vec3",
            ValueKind::Color => "color",
            ValueKind::Rotation => "rotation",
            ValueKind::Bool => "bool",
            ValueKind::Weights => "weights",
        }
    }
}

impl Value {
    /// The kind of this value (colours are `Vec3` values).
    pub fn kind(&self) -> ValueKind {
        match self {
            Value::Scalar(_) => ValueKind::Scalar,
            Value::Vec3(_) => ValueKind::Vec3,
            Value::Rotation(_) => ValueKind::Rotation,
            Value::Bool(_) => ValueKind::Bool,
            Value::Weights(_) => ValueKind::Weights,
        }
    }

    /// The numbers this value is written as. Rotations become axis-angle
    /// with the angle in [0, π] and a unit axis; the identity is `[0, 0, 1, 0]`
    /// (the VRML97 default rotation).
    pub fn to_numbers(&self) -> Vec<f32> {
        match *self {
            Value::Scalar(x) => vec![x],
            Value::Vec3(v) => vec![v.x, v.y, v.z],
            Value::Rotation(q) => axis_angle(q).to_vec(),
            Value::Bool(b) => vec![if b { 1.0 } else { 0.0 }],
            Value::Weights(w) => w.as_slice().to_vec(),
        }
    }

    /// Reads a value of `kind` from its numbers (see [`Value::to_numbers`]).
    /// Rotation axes need not be unit length; a zero angle gives the
    /// identity whatever the axis.
    pub fn from_numbers(kind: ValueKind, n: &[f32]) -> Result<Value, ValueError> {
        let expected = kind.arity();
        let count_ok = match kind {
            ValueKind::Weights => (1..=MAX_MORPH_TARGETS).contains(&n.len()),
            _ => n.len() == expected,
        };
        if !count_ok {
            return Err(ValueError::Count {
                kind,
                expected,
                got: n.len(),
            });
        }
        if n.iter().any(|x| !x.is_finite()) {
            return Err(ValueError::NotFinite);
        }
        Ok(match kind {
            ValueKind::Scalar => Value::Scalar(n[0]),
            ValueKind::Vec3 | ValueKind::Color => Value::Vec3(Vec3::new(n[0], n[1], n[2])),
            ValueKind::Rotation => {
                let axis = Vec3::new(n[0], n[1], n[2]);
                let angle = n[3];
                if angle == 0.0 {
                    Value::Rotation(Quat::IDENTITY)
                } else {
                    let l = axis.length();
                    if l <= 1e-12 || !l.is_finite() {
                        return Err(ValueError::ZeroAxis);
                    }
                    let half = 0.5 * angle;
                    let a = axis * (libm::sinf(half) / l);
                    Value::Rotation(Quat::from_xyzw(a.x, a.y, a.z, libm::cosf(half)))
                }
            }
            ValueKind::Weights => Value::Weights(Weights::from_slice_truncated(n)),
            ValueKind::Bool => {
                if n[0] == 0.0 {
                    Value::Bool(false)
                } else if n[0] == 1.0 {
                    Value::Bool(true)
                } else {
                    return Err(ValueError::NotBool(n[0]));
                }
            }
        })
    }
}

/// Axis-angle `[x, y, z, angle]` of a unit quaternion, angle in [0, π].
fn axis_angle(q: Quat) -> [f32; 4] {
    let q = if q.w < 0.0 { -q } else { q };
    let v = Vec3::new(q.x, q.y, q.z);
    let s = v.length();
    if s < 1e-7 {
        return [0.0, 0.0, 1.0, 0.0];
    }
    let angle = 2.0 * libm::atan2f(s, q.w);
    let axis = v / s;
    [axis.x, axis.y, axis.z, angle]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_round_trip() {
        let v = Value::from_numbers(ValueKind::Rotation, &[0.0, 2.0, 0.0, 1.5]).unwrap();
        let Value::Rotation(q) = v else {
            panic!("not a rotation")
        };
        // Half-angle 0.75 about +y.
        assert!((q.y - 0.75f32.sin()).abs() < 1e-6 && (q.w - 0.75f32.cos()).abs() < 1e-6);
        let n = v.to_numbers();
        let want = [0.0, 1.0, 0.0, 1.5];
        for (a, b) in n.iter().zip(want) {
            assert!((a - b).abs() < 1e-5, "{n:?}");
        }
        // Negated quaternion: same rotation, same numbers.
        assert_eq!(Value::Rotation(-q).to_numbers(), n);
        assert_eq!(
            Value::Rotation(Quat::IDENTITY).to_numbers(),
            vec![0.0, 0.0, 1.0, 0.0]
        );
    }

    #[test]
    fn errors() {
        assert!(matches!(
            Value::from_numbers(ValueKind::Vec3, &[1.0, 2.0]),
            Err(ValueError::Count {
                expected: 3,
                got: 2,
                ..
            })
        ));
        assert_eq!(
            Value::from_numbers(ValueKind::Scalar, &[f32::NAN]),
            Err(ValueError::NotFinite)
        );
        assert_eq!(
            Value::from_numbers(ValueKind::Rotation, &[0.0, 0.0, 0.0, 1.0]),
            Err(ValueError::ZeroAxis)
        );
        assert_eq!(
            Value::from_numbers(ValueKind::Bool, &[0.5]),
            Err(ValueError::NotBool(0.5))
        );
        assert_eq!(
            Value::from_numbers(ValueKind::Bool, &[1.0]),
            Ok(Value::Bool(true))
        );
        let msg = Value::from_numbers(ValueKind::Color, &[1.0])
            .unwrap_err()
            .to_string();
        assert_eq!(msg, "a color value needs 3 numbers, got 1");
    }
}
