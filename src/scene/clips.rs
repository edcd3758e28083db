//! Named animation clips (a glTF file's `animations`, a walk and a run of
//! one character). Exactly one clip plays at a time.
//!
//! Low churn by design: the *playing* clip's tracks stay in
//! [`Scene::animation`] and its length in [`Settings::duration`], where every
//! evaluator, editor command and writer already looks. [`Clips`] holds the
//! clip order, the playing clip's name and the clips that are not playing;
//! [`Scene::play_clip`] swaps one in. A scene whose [`Clips`] is empty has the
//! single unnamed clip every format had before clips existed.
//!
//! [`Settings::duration`]: super::Settings::duration

use super::Scene;
use crate::anim::Animation;

/// One clip: a name, its tracks and its length in frames.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Clip {
    pub name: String,
    pub animation: Animation,
    /// Length in frames (the scene's fps), like [`super::Settings::duration`].
    pub duration: f32,
}

/// The scene's clips in file order.
///
/// Invariant: either empty (one unnamed clip, the scene's own), or
/// `active < list.len()`; the slot at `active` holds only the name (its
/// tracks and duration live in the scene while it plays).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Clips {
    list: Vec<Clip>,
    active: usize,
}

impl Clips {
    /// Number of named clips (0 for a scene with only its unnamed clip).
    pub fn len(&self) -> usize {
        self.list.len()
    }

    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// Index of the playing clip (0 when there are no named clips).
    pub fn active(&self) -> usize {
        self.active
    }

    /// Clip names in order.
    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.list.iter().map(|c| c.name.as_str())
    }

    /// The name of the playing clip, `None` when the scene has no named clips.
    pub fn active_name(&self) -> Option<&str> {
        self.list.get(self.active).map(|c| c.name.as_str())
    }
}

/// A clip as a writer or a lister sees it: the playing one read from the
/// scene, the others from the store.
#[derive(Clone, Copy, Debug)]
pub struct ClipRef<'a> {
    pub index: usize,
    pub name: &'a str,
    pub animation: &'a Animation,
    /// Length in frames.
    pub duration: f32,
    pub playing: bool,
}

impl Scene {
    /// Replaces the scene's clips with `clips` (in order) and plays clip
    /// `active`: its tracks become [`Scene::animation`], its length the
    /// scene's duration. An empty list leaves one unnamed, empty clip.
    /// `active` past the end plays the first clip.
    pub fn set_clips(&mut self, mut clips: Vec<Clip>, active: usize) {
        if clips.is_empty() {
            self.clips = Clips::default();
            self.animation = Animation::default();
            return;
        }
        let active = if active < clips.len() { active } else { 0 };
        let slot = &mut clips[active];
        self.animation = std::mem::take(&mut slot.animation);
        self.settings.duration = std::mem::take(&mut slot.duration);
        self.clips = Clips {
            list: clips,
            active,
        };
    }

    /// Every clip in order (one unnamed clip for a scene without named
    /// clips); the playing one's tracks and length come from the scene.
    pub fn clip_refs(&self) -> Vec<ClipRef<'_>> {
        if self.clips.list.is_empty() {
            return vec![ClipRef {
                index: 0,
                name: "",
                animation: &self.animation,
                duration: self.settings.duration,
                playing: true,
            }];
        }
        self.clips
            .list
            .iter()
            .enumerate()
            .map(|(index, c)| {
                let playing = index == self.clips.active;
                ClipRef {
                    index,
                    name: &c.name,
                    animation: if playing {
                        &self.animation
                    } else {
                        &c.animation
                    },
                    duration: if playing {
                        self.settings.duration
                    } else {
                        c.duration
                    },
                    playing,
                }
            })
            .collect()
    }

    /// Every clip in order, owned (the playing one copied from the scene).
    pub fn clips_owned(&self) -> Vec<Clip> {
        self.clip_refs()
            .into_iter()
            .map(|c| Clip {
                name: c.name.to_string(),
                animation: c.animation.clone(),
                duration: c.duration,
            })
            .collect()
    }

    /// Finds a clip by name (exact first, then ignoring ASCII case) or by
    /// 0-based index, as `--animation NAME|INDEX` takes it.
    pub fn find_clip(&self, spec: &str) -> Result<usize, String> {
        let names: Vec<&str> = self.clips.names().collect();
        let count = names.len().max(1);
        if let Some(i) = names.iter().position(|n| *n == spec) {
            return Ok(i);
        }
        if let Some(i) = names.iter().position(|n| n.eq_ignore_ascii_case(spec)) {
            return Ok(i);
        }
        if let Ok(i) = spec.trim().parse::<usize>() {
            if i < count {
                return Ok(i);
            }
            return Err(format!(
                "there is no animation {i}: the scene has {count} (0..{})",
                count - 1
            ));
        }
        if names.is_empty() {
            return Err(format!(
                "there is no animation named `{spec}`: the scene has one unnamed animation (use 0)"
            ));
        }
        Err(format!(
            "there is no animation named `{spec}` (the scene has: {})",
            names
                .iter()
                .enumerate()
                .map(|(i, n)| format!("{i} `{n}`"))
                .collect::<Vec<_>>()
                .join(", ")
        ))
    }

    /// Makes clip `index` the playing one: the playing clip's tracks and
    /// duration go back to the store, clip `index`'s come out. Nothing
    /// changes when it already plays.
    pub fn play_clip_index(&mut self, index: usize) -> Result<(), String> {
        let count = self.clips.list.len();
        if count == 0 {
            return if index == 0 {
                Ok(())
            } else {
                Err(format!(
                    "there is no animation {index}: the scene has 1 (0..0)"
                ))
            };
        }
        if index >= count {
            return Err(format!(
                "there is no animation {index}: the scene has {count} (0..{})",
                count - 1
            ));
        }
        let old = self.clips.active;
        if index == old {
            return Ok(());
        }
        let list = &mut self.clips.list;
        list[old].animation = std::mem::take(&mut self.animation);
        list[old].duration = self.settings.duration;
        self.animation = std::mem::take(&mut list[index].animation);
        self.settings.duration = list[index].duration;
        list[index].duration = 0.0;
        self.clips.active = index;
        Ok(())
    }

    /// Plays the clip `spec` names (`--animation NAME|INDEX`).
    pub fn play_clip(&mut self, spec: &str) -> Result<(), String> {
        let i = self.find_clip(spec)?;
        self.play_clip_index(i)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::anim::{Key, Keys, Property, Repeat, Target, TargetRef, Track};
    use crate::scene::{Node, NodeId};
    use glam::Vec3;

    fn anim(node: NodeId, x: f32) -> Animation {
        let target = Target {
            of: TargetRef::Node(node),
            property: Property::Translation,
        };
        let keys = Keys::Vec3(vec![Key::new(0.0, Vec3::ZERO), Key::new(10.0, Vec3::X * x)]);
        Animation {
            tracks: vec![Track::new(target, Repeat::Constant, keys).unwrap()],
        }
    }

    fn three_clips() -> Scene {
        let mut s = Scene::new();
        let n = s.add_node(None, Node::group("Ball"));
        let clips = ["Walk", "Run", "Idle"]
            .iter()
            .enumerate()
            .map(|(i, name)| Clip {
                name: name.to_string(),
                animation: anim(n, i as f32 + 1.0),
                duration: 10.0 * (i as f32 + 1.0),
            })
            .collect();
        s.set_clips(clips, 1);
        s
    }

    fn end_x(s: &Scene) -> f32 {
        match s.animation.tracks[0].sample(100.0) {
            crate::anim::Value::Vec3(v) => v.x,
            v => panic!("{v:?}"),
        }
    }

    #[test]
    fn set_clips_plays_the_chosen_clip() {
        let s = three_clips();
        assert_eq!(s.clips.active(), 1);
        assert_eq!(s.clips.active_name(), Some("Run"));
        assert_eq!(end_x(&s), 2.0);
        assert_eq!(s.settings.duration, 20.0);
        let names: Vec<_> = s.clips.names().collect();
        assert_eq!(names, ["Walk", "Run", "Idle"]);
    }

    #[test]
    fn switching_keeps_every_clip_intact() {
        let mut s = three_clips();
        let before = s.clips_owned();
        s.play_clip("idle").unwrap();
        assert_eq!(s.clips.active_name(), Some("Idle"));
        assert_eq!((end_x(&s), s.settings.duration), (3.0, 30.0));
        s.play_clip("0").unwrap();
        assert_eq!((end_x(&s), s.settings.duration), (1.0, 10.0));
        assert_eq!(s.clips_owned(), before, "no clip lost or changed");
        let refs = s.clip_refs();
        assert!(refs[0].playing && !refs[1].playing);
        assert_eq!(refs[2].duration, 30.0);
    }

    #[test]
    fn edits_to_the_playing_clip_are_kept_when_switching() {
        let mut s = three_clips();
        s.animation.tracks.clear();
        s.settings.duration = 5.0;
        s.play_clip("Walk").unwrap();
        s.play_clip("Run").unwrap();
        assert!(s.animation.tracks.is_empty());
        assert_eq!(s.settings.duration, 5.0);
    }

    #[test]
    fn names_win_over_indices_and_errors_list_the_clips() {
        let mut s = three_clips();
        let mut clips = s.clips_owned();
        clips[2].name = "0".into();
        s.set_clips(clips, 0);
        assert_eq!(s.find_clip("0"), Ok(2), "a clip named 0 wins");
        assert_eq!(s.find_clip("1"), Ok(1));
        let e = s.find_clip("Jump").unwrap_err();
        assert!(e.contains("`Jump`") && e.contains("1 `Run`"), "{e}");
        let e = s.find_clip("7").unwrap_err();
        assert!(e.contains("has 3"), "{e}");
        assert!(s.play_clip_index(3).is_err());
    }

    #[test]
    fn a_scene_without_named_clips_has_one() {
        let mut s = Scene::new();
        let n = s.add_node(None, Node::group("Ball"));
        s.animation = anim(n, 4.0);
        assert!(s.clips.is_empty());
        assert_eq!(s.find_clip("0"), Ok(0));
        s.play_clip("0").unwrap();
        assert_eq!(end_x(&s), 4.0);
        assert!(s.play_clip("1").is_err());
        assert!(s.play_clip("Walk").unwrap_err().contains("unnamed"));
        let refs = s.clip_refs();
        assert_eq!(refs.len(), 1);
        assert!(refs[0].playing && refs[0].name.is_empty());
        s.set_clips(Vec::new(), 0);
        assert!(s.animation.tracks.is_empty());
    }
}
