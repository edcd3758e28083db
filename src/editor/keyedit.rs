//! The key strip's edits on the animation: retiming keys (move, scale),
//! deleting them, copy and paste. The pure functions work on an
//! [`Animation`]; the editor methods turn them into one undo step each
//! (stopping playback and dropping a pending change).
//!
//! A key moved or pasted onto another key of the same track replaces it,
//! as in Blender; two *selected* keys of one track landing on one frame is
//! refused.

use super::keystrip::{row_name, Clipboard, KeyRef};
use crate::anim::{Animation, Key, KeyParams, Keys, Target, TargetRef, Value, KEY_EPS};

pub(super) fn typed(kind: crate::anim::ValueKind, keys: &[Key<Value>]) -> Result<Keys, String> {
    Keys::from_values(kind, keys).map_err(|e| e.to_string())
}

/// `anim` with the keys `keys` moved to `map(frame)`. A key already at a
/// destination (not itself moving) is replaced; two moving keys of one
/// track meeting on a frame is an error. Returns the moved keys' new refs.
pub fn retime(
    anim: &Animation,
    keys: &[KeyRef],
    map: impl Fn(f32) -> f32,
) -> Result<(Animation, Vec<KeyRef>), String> {
    let mut out = anim.clone();
    let mut moved_refs = Vec::new();
    let mut targets: Vec<Target> = keys.iter().map(KeyRef::target).collect();
    targets.dedup();
    let mut seen = Vec::new();
    for t in targets {
        if seen.contains(&t) {
            continue;
        }
        seen.push(t);
        let Some(track) = out.track_mut(t) else {
            continue;
        };
        let all: Vec<Key<Value>> = (0..track.key_count())
            .filter_map(|i| track.key(i))
            .collect();
        let is_moving = |f: f32| {
            keys.iter()
                .any(|k| k.target() == t && (k.frame - f).abs() <= KEY_EPS)
        };
        let mut moving: Vec<Key<Value>> = Vec::new();
        for k in all.iter().filter(|k| is_moving(k.frame)) {
            let to = map(k.frame);
            if !to.is_finite() {
                return Err("a key would leave the timeline".into());
            }
            if moving.iter().any(|m| (m.frame - to).abs() <= KEY_EPS) {
                return Err(format!(
                    "two {} keys would land on frame {}",
                    row_name(t.property),
                    super::fields::format_number(to)
                ));
            }
            moving.push(Key { frame: to, ..*k });
        }
        let mut list: Vec<Key<Value>> = all
            .iter()
            .filter(|k| !is_moving(k.frame))
            .filter(|k| !moving.iter().any(|m| (m.frame - k.frame).abs() <= KEY_EPS))
            .copied()
            .collect();
        for m in &moving {
            moved_refs.push(KeyRef {
                node: match t.of {
                    TargetRef::Node(n) => n,
                    TargetRef::Material(_) => continue,
                },
                property: t.property,
                frame: m.frame,
            });
        }
        list.extend(moving);
        track.keys = typed(t.property.kind(), &list)?;
    }
    Ok((out, moved_refs))
}

/// `anim` without `keys`; tracks left without keys are removed and
/// returned (their node keeps a value the caller chooses).
pub fn delete(anim: &Animation, keys: &[KeyRef]) -> Result<(Animation, Vec<Target>), String> {
    let mut out = anim.clone();
    let mut emptied = Vec::new();
    for k in keys {
        let t = k.target();
        let Some(track) = out.track_mut(t) else {
            continue;
        };
        if track.key_index_at(k.frame).is_none() {
            continue;
        }
        if track.key_count() == 1 {
            out.remove_tracks(t);
            emptied.push(t);
        } else {
            track.remove_key(k.frame).map_err(|e| e.to_string())?;
        }
    }
    Ok((out, emptied))
}

/// The keys `keys` with frames relative to the earliest.
pub(super) fn copy(anim: &Animation, keys: &[KeyRef]) -> Clipboard {
    let f0 = keys.iter().map(|k| k.frame).fold(f32::INFINITY, f32::min);
    Clipboard {
        keys: keys
            .iter()
            .filter_map(|k| {
                let key = k.get(anim)?;
                Some((
                    k.property,
                    Key {
                        frame: key.frame - f0,
                        ..key
                    },
                ))
            })
            .collect(),
    }
}

/// Which ease a menu item sets on the selected keys.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ease {
    /// Slow into the key (ease in = 1, ease out kept).
    In,
    /// Slow out of the key (ease out = 1, ease in kept).
    Out,
    Both,
    None,
}

impl Ease {
    /// Sets this ease on a key's parameters.
    pub fn apply(self, key: &mut KeyParams) {
        match self {
            Ease::In => key.ease_in = 1.0,
            Ease::Out => key.ease_out = 1.0,
            Ease::Both => (key.ease_in, key.ease_out) = (1.0, 1.0),
            Ease::None => (key.ease_in, key.ease_out) = (0.0, 0.0),
        }
    }

    /// The undo label and menu line.
    pub fn label(self) -> &'static str {
        match self {
            Ease::In => "Ease in",
            Ease::Out => "Ease out",
            Ease::Both => "Ease in and out",
            Ease::None => "No ease",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::Property;
    use crate::editor::keystrip::track_keys;
    use crate::scene::NodeId;
    use glam::Vec3;

    fn anim() -> (Animation, NodeId) {
        let id = NodeId(0);
        let mut a = Animation::default();
        let t = Target {
            of: TargetRef::Node(id),
            property: Property::Translation,
        };
        for f in [0.0, 10.0, 20.0] {
            a.set_key(t, f, Value::Vec3(Vec3::splat(f))).unwrap();
        }
        (a, id)
    }

    fn r(id: NodeId, f: f32) -> KeyRef {
        KeyRef {
            node: id,
            property: Property::Translation,
            frame: f,
        }
    }

    #[test]
    fn ease_in_and_out_are_set_separately() {
        let mut k = KeyParams {
            ease_out: 0.5,
            ..KeyParams::default()
        };
        Ease::In.apply(&mut k);
        assert_eq!((k.ease_in, k.ease_out), (1.0, 0.5));
        Ease::None.apply(&mut k);
        Ease::Out.apply(&mut k);
        assert_eq!((k.ease_in, k.ease_out), (0.0, 1.0));
        Ease::Both.apply(&mut k);
        assert_eq!((k.ease_in, k.ease_out), (1.0, 1.0));
    }

    #[test]
    fn moving_onto_a_key_replaces_it() {
        let (a, id) = anim();
        let (b, refs) = retime(&a, &[r(id, 10.0)], |f| f + 10.0).unwrap();
        assert_eq!(refs, vec![r(id, 20.0)]);
        let frames = track_keys(&b, id, Property::Translation);
        assert_eq!(frames, vec![r(id, 0.0), r(id, 20.0)]);
        assert_eq!(
            r(id, 20.0).get(&b).unwrap().value,
            Value::Vec3(Vec3::splat(10.0))
        );
    }

    #[test]
    fn squeezing_two_selected_keys_together_is_refused() {
        let (a, id) = anim();
        let e = retime(&a, &[r(id, 10.0), r(id, 20.0)], |_| 5.0).unwrap_err();
        assert!(e.contains("frame 5"), "{e}");
    }

    #[test]
    fn deleting_every_key_removes_the_track() {
        let (a, id) = anim();
        let (b, emptied) = delete(&a, &[r(id, 0.0)]).unwrap();
        assert!(emptied.is_empty());
        assert_eq!(track_keys(&b, id, Property::Translation).len(), 2);
        let all = track_keys(&a, id, Property::Translation);
        let (c, emptied) = delete(&a, &all).unwrap();
        assert_eq!(emptied.len(), 1);
        assert!(c.tracks.is_empty());
    }
}
