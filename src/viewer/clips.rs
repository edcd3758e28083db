//! The viewer's clip key: `C` plays the next animation clip, Shift+C the
//! previous one, and the playing clip's name is shown in the viewport's
//! corner (issue 13 item 3, issue 14 item 5).
//!
//! Switching goes through [`Scene::play_clip_index`], so the clip's tracks
//! and length become the scene's and everything that reads them (clock,
//! key marks, framing) simply restarts from the new clip at its frame 0.

use super::Viewer;
use crate::scene::Scene;
use crate::ui::{theme, Painter};

/// Times (seconds) of every key of the playing clip, sorted, no repeats:
/// the marks on the scrub bar.
pub(super) fn key_times(scene: &Scene) -> Vec<f32> {
    let fps = scene.settings.fps;
    let mut key_times: Vec<f32> = scene
        .animation
        .tracks
        .iter()
        .flat_map(|t| t.keys.frames())
        .map(|f| f / fps.max(1e-6))
        .filter(|t| t.is_finite())
        .collect();
    key_times.sort_by(f32::total_cmp);
    key_times.dedup();
    key_times
}

impl Viewer {
    /// Plays the clip `step` places after the playing one (wrapping);
    /// returns whether anything changed. A scene with one clip stays.
    pub(super) fn cycle_clip(&mut self, step: i64) -> bool {
        let n = self.scene.clips.len() as i64;
        if n < 2 {
            return false;
        }
        let next = (self.scene.clips.active() as i64 + step).rem_euclid(n) as usize;
        if self.scene.play_clip_index(next).is_err() {
            return false;
        }
        let playing = self.clock.is_playing();
        self.clock = super::Clock::new(self.scene.settings.fps, self.scene.settings.duration);
        if !playing {
            self.clock.toggle_pause();
        }
        self.key_times = key_times(&self.scene);
        self.layer = None;
        true
    }

    /// "Walk (3/14)" for a scene with named clips, `None` otherwise.
    pub fn clip_label(&self) -> Option<String> {
        let c = &self.scene.clips;
        let name = c.active_name()?;
        Some(format!("{name} ({}/{})", c.active() + 1, c.len()))
    }

    /// The playing clip's name at the viewport's top left, with the key
    /// that changes it.
    pub(super) fn draw_clip_name(&self, p: &mut Painter) {
        let Some(label) = self.clip_label() else {
            return;
        };
        let hint = if self.scene.clips.len() > 1 {
            "  C/Shift+C: next/previous clip"
        } else {
            ""
        };
        // Below the stats when they are shown.
        let y = if self.show_stats {
            7 + 3 * crate::ui::text::LINE_H
        } else {
            6
        };
        let used = p.text_clipped(
            8,
            y,
            &format!("Clip: {label}"),
            theme::TEXT,
            self.width as i32 - 16,
        );
        p.text_clipped(
            8 + used,
            y,
            hint,
            theme::TEXT_DIM,
            self.width as i32 - 16 - used,
        );
    }
}
