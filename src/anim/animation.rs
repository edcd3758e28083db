//! Finding and creating tracks in an [`Animation`].

use super::{Animation, Key, Keys, Repeat, Target, TargetRef, Track, TrackError, Value};

impl Animation {
    /// The track driving `target` (the last one if several do: it is the
    /// one `evaluate` applies last, so it wins).
    pub fn track(&self, target: Target) -> Option<&Track> {
        self.tracks.iter().rev().find(|t| t.target == target)
    }

    /// Mutable access to the track driving `target`.
    pub fn track_mut(&mut self, target: Target) -> Option<&mut Track> {
        self.tracks.iter_mut().rev().find(|t| t.target == target)
    }

    /// The track driving `target`, created with one key (`frame`, `value`)
    /// and [`Repeat::Constant`] if there is none. An existing track is
    /// returned unchanged (set the key on it yourself).
    pub fn track_or_insert(
        &mut self,
        target: Target,
        frame: f32,
        value: Value,
    ) -> Result<&mut Track, TrackError> {
        match self.tracks.iter().rposition(|t| t.target == target) {
            Some(i) => Ok(&mut self.tracks[i]),
            None => {
                let keys = Keys::from_values(target.property.kind(), &[Key::new(frame, value)])?;
                let track = Track::new(target, Repeat::Constant, keys)?;
                self.tracks.push(track);
                let last = self.tracks.len() - 1;
                Ok(&mut self.tracks[last])
            }
        }
    }

    /// Sets a key on `target`'s track, creating the track if needed; returns
    /// the key's index.
    pub fn set_key(
        &mut self,
        target: Target,
        frame: f32,
        value: Value,
    ) -> Result<usize, TrackError> {
        self.track_or_insert(target, frame, value)?
            .set_key(frame, value)
    }

    /// Removes every track driving `target`; returns how many were removed.
    pub fn remove_tracks(&mut self, target: Target) -> usize {
        let before = self.tracks.len();
        self.tracks.retain(|t| t.target != target);
        before - self.tracks.len()
    }

    /// Tracks of one node or material.
    pub fn tracks_of(&self, of: TargetRef) -> impl Iterator<Item = &Track> {
        self.tracks.iter().filter(move |t| t.target.of == of)
    }

    /// First and last key frame over all tracks, `None` without keys.
    pub fn frame_range(&self) -> Option<(f32, f32)> {
        self.tracks
            .iter()
            .filter_map(Track::frame_range)
            .reduce(|(a, b), (c, d)| (a.min(c), b.max(d)))
    }
}
