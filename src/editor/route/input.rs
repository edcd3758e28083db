//! The editor's side of `input`: routes events to it and applies what it returns.

use crate::editor::browser::Purpose;
use crate::editor::browser_ui::Reply;
use crate::editor::command::Command;
use crate::editor::dialog::Answer;
use crate::editor::field_press::FieldEvent;
use crate::editor::fields::{parse_number, FieldId, FieldValue};
#[allow(unused_imports)]
use crate::editor::gesture::*;
use crate::editor::ops;
use crate::editor::panel::{Action, WidgetKind};
use crate::editor::side_faces::is_face_field;
use crate::editor::{After, Dialog, Editor, Mode, Playback, TextEdit};
use crate::input::{Event, Key, Mods, MouseButton};
use crate::scene::RenderStyle;

impl Editor {
    /// Feeds one event; returns true when the picture needs redrawing.
    pub fn handle(&mut self, ev: Event) -> bool {
        self.autosave.note_input(&ev);
        let (sel, status) = (self.selection, self.status.clone());
        let redraw = self.dispatch(ev);
        if self.selection != sel && self.status == status {
            // The line must not keep talking about the old selection.
            self.status_for_selection();
        }
        self.reveal_selection();
        redraw
    }

    /// "Selected NAME" for the selection, or an empty line without one.
    pub(in crate::internals::editor) fn status_for_selection(&mut self) {
        match self.selection {
            Some(id) => {
                let name = ops::display_name(&self.scene, id);
                self.set_status(&format!("Selected {name}"), false);
            }
            None => self.set_status("", false),
        }
    }

    pub(in crate::internals::editor) fn dispatch(&mut self, ev: Event) -> bool {
        if let Some(redraw) = self.search_event(&ev) {
            return redraw;
        }
        if let Some(redraw) = self.menu_event(&ev) {
            return redraw;
        }
        if let Some(redraw) = self.dialog_event(&ev) {
            return redraw;
        }
        if let Some(redraw) = self.browser_event(&ev) {
            return redraw;
        }
        match ev {
            Event::Resize { width, height } => self.split.resize(width, height),
            Event::Tick { time } => self.tick(time),
            Event::MouseMove { x, y, mods } => {
                let tip_gone = self.hover_move(x, y);
                self.mouse_move(x, y, mods) | tip_gone
            }
            Event::MouseDown { .. } | Event::KeyDown { .. } if self.help_shown() => {
                // Any key or click closes the help.
                self.set_help(false);
                true
            }
            Event::MouseDown { button, x, y, mods } => {
                self.hover.moved(None);
                self.mouse = (x, y);
                self.mouse_down(button, x, y, mods);
                true
            }
            Event::MouseUp { button, x, y, mods } => {
                self.mouse = (x, y);
                self.mouse_up(button, x, y, mods);
                true
            }
            Event::Wheel { delta, x, y, mods } => self.wheel(delta, x, y, mods),
            Event::KeyDown { key, mods } => {
                self.key_down(key, mods);
                true
            }
            Event::KeyUp { .. } => false,
            Event::Text(s) => self.text(&s),
        }
    }

    /// Restarts the tooltip timer for the widget under (x, y) (none during
    /// drags, menus and dialogs); `true` when a shown tooltip went away.
    fn hover_move(&mut self, x: f32, y: f32) -> bool {
        let over = match (&self.drag, &self.menu, &self.dialog, &self.browser) {
            (Drag::None, None, None, None) => self
                .widget_at(x, y)
                .map(|w| w.kind)
                .or_else(|| self.strip_tip(x, y)),
            _ => None,
        };
        self.hover.moved(over)
    }

    pub(in crate::internals::editor) fn tick(&mut self, time: f64) -> bool {
        let status = self.autosave_tick(time) | self.hover.tick(time);
        let Some(pb) = &mut self.playback else {
            return status;
        };
        let start = *pb.start_time.get_or_insert(time);
        let start_frame = pb.start_frame;
        // Real time: frames are dropped rather than slowed down; loops
        // over the preview range or the whole scene.
        let f = self.playback_frame(start_frame, time - start);
        let changed = f != self.frame;
        self.frame = f;
        changed || status
    }

    pub(in crate::internals::editor) fn toggle_play(&mut self) {
        self.playback = match self.playback {
            Some(_) => None,
            None => Some(Playback {
                start_time: None,
                start_frame: self.frame,
            }),
        };
        self.say_playback();
    }

    pub(in crate::internals::editor) fn stop_playback(&mut self) {
        self.playback = None;
    }

    // ----- mouse -----

    pub(in crate::internals::editor) fn mouse_move(&mut self, x: f32, y: f32, mods: Mods) -> bool {
        let (lx, ly) = self.mouse;
        self.mouse = (x, y);
        // The part that holds the gesture gets the move, and only it.
        let ev = Event::MouseMove { x, y, mods };
        let part = match &self.drag {
            Drag::Graph => self.graph_event(&ev),
            Drag::Keys => self.strip_event(&ev),
            Drag::Side => self.side_mouse(&ev),
            // The viewport's gesture, or hover over its handles.
            Drag::Viewport | Drag::None => self.viewport_event(&ev),
            _ => None,
        };
        if let Some(redraw) = part {
            return redraw;
        }
        match self.drag.clone() {
            Drag::Viewport | Drag::Keys | Drag::Graph | Drag::Side => false,
            Drag::None => {
                // Hover highlight only changes the picture when the widget
                // under the mouse changes.
                let before = self.widget_at(lx, ly);
                let after = self.widget_at(x, y);
                before != after
            }
            Drag::TimeField(_) => self.time_field_move(x),
            Drag::Seek => {
                self.seek_to_x(x);
                true
            }
            Drag::StripPan { last_x } => {
                self.pan_timeline(x - last_x);
                self.drag = Drag::StripPan { last_x: x };
                true
            }
            Drag::Preview { from } => {
                let l = self.layout();
                let to = l.x_to_frame_in(x, self.time_span());
                let dur = self.scene.settings.duration;
                self.timeline.set_preview(from, to, dur);
                true
            }
            Drag::StripResize { y0, h0 } => {
                self.split.drag_strip(h0 + (y0 - y).round() as i32);
                true
            }
        }
    }

    pub(in crate::internals::editor) fn seek_to_x(&mut self, x: f32) {
        let l = self.layout();
        self.stop_playback();
        let dur = self.scene.settings.duration.max(0.0);
        self.frame = l.x_to_frame_in(x, self.time_span()).clamp(0.0, dur).round();
    }

    pub(in crate::internals::editor) fn mouse_down(
        &mut self,
        button: MouseButton,
        x: f32,
        y: f32,
        mods: Mods,
    ) {
        if self.dialog.is_some() || self.browser.is_some() {
            // Their own clicks (`dialog.rs`, `browser_ui.rs`).
            return;
        }
        let l = self.layout();
        if self.split.graph && l.key_rows.contains(x, y) {
            // A drag it starts becomes the gesture (`graph_event`).
            self.commit_edit();
            self.graph_event(&Event::MouseDown { button, x, y, mods });
            return;
        }
        let edge = l.timeline.y as f32;
        if !self.split.graph && button == MouseButton::Left && (y - edge).abs() <= 2.5 {
            // The timeline's top edge: resize the key strip.
            self.commit_edit();
            self.drag = Drag::StripResize {
                y0: y,
                h0: l.key_rows.h,
            };
            return;
        }
        if l.viewport.contains(x, y) {
            // The viewport's press: its gesture (orbit, pan, pick, menu,
            // a handle, the IK target) becomes the editor's.
            self.commit_edit();
            self.viewport_event(&Event::MouseDown { button, x, y, mods });
            return;
        }
        if button == MouseButton::Right {
            if let Some(WidgetKind::Row { node, .. }) = self.widget_at(x, y).map(|w| w.kind) {
                self.commit_edit();
                self.selection = Some(node);
                self.open_list_menu(x as i32, y as i32);
                return;
            }
        }
        if button == MouseButton::Right && l.key_rows.contains(x, y) {
            self.commit_edit();
            self.open_strip_menu(x, y);
            return;
        }
        let on_strip = l.ruler.contains(x, y) || l.key_rows.contains(x, y);
        if button == MouseButton::Middle && on_strip {
            self.commit_edit();
            self.drag = Drag::StripPan { last_x: x };
            return;
        }
        if button != MouseButton::Left {
            return;
        }
        if l.ruler.contains(x, y) && mods.shift {
            self.commit_edit();
            let from = l.x_to_frame_in(x, self.time_span());
            self.drag = Drag::Preview { from };
            return;
        }
        if l.ruler.contains(x, y) {
            self.commit_edit();
            self.drag = Drag::Seek;
            self.seek_to_x(x);
            return;
        }
        if l.key_rows.contains(x, y) {
            self.commit_edit();
            self.key_strip_press(button, x, y, mods);
            return;
        }
        let Some(widget) = self.widget_at(x, y) else {
            self.commit_edit();
            return;
        };
        match widget.kind {
            WidgetKind::Field(id) => {
                if self.edit.as_ref().is_some_and(|e| e.field == id) {
                    return;
                }
                self.commit_edit();
                if is_face_field(id) {
                    // The side panel's faces hold their own presses.
                    self.face_event(FieldEvent::Press { field: id, x });
                } else {
                    // The controls bar's Frame and preview range fields.
                    self.time_field_press(id, x);
                }
            }
            WidgetKind::Button { action, .. } | WidgetKind::Check { action, .. } => {
                self.commit_edit();
                self.run_action(action);
            }
            WidgetKind::Row { .. } => {
                self.commit_edit();
                self.side_event(&Event::MouseDown { button, x, y, mods });
            }
            _ => self.commit_edit(),
        }
    }

    pub(in crate::internals::editor) fn mouse_up(
        &mut self,
        button: MouseButton,
        x: f32,
        y: f32,
        mods: Mods,
    ) {
        // The part that holds the gesture ends it.
        match &self.drag {
            Drag::Graph => {
                self.graph_event(&Event::MouseUp { button, x, y, mods });
                return;
            }
            Drag::Viewport => {
                self.viewport_event(&Event::MouseUp { button, x, y, mods });
                return;
            }
            Drag::Keys => {
                self.strip_event(&Event::MouseUp { button, x, y, mods });
                return;
            }
            Drag::Side => {
                self.side_mouse(&Event::MouseUp { button, x, y, mods });
                return;
            }
            _ => {}
        }
        match std::mem::take(&mut self.drag) {
            Drag::TimeField(p) => self.time_field_release(p),
            Drag::Preview { .. } => {
                let r = self.timeline.preview;
                self.set_preview_range(r);
            }
            Drag::StripPan { .. } => self.say_timeline_span(),
            _ => {}
        }
    }

    pub(in crate::internals::editor) fn wheel(
        &mut self,
        delta: f32,
        x: f32,
        y: f32,
        mods: Mods,
    ) -> bool {
        if self.dialog.is_some() {
            return false;
        }
        let l = self.layout();
        if self.split.graph && l.key_rows.contains(x, y) {
            let ev = Event::Wheel { delta, x, y, mods };
            return self.graph_event(&ev).unwrap_or(false);
        }
        if l.viewport.contains(x, y) {
            let ev = Event::Wheel { delta, x, y, mods };
            return self.viewport_event(&ev).unwrap_or(false);
        }
        if let Some(redraw) = self.side_event(&Event::Wheel { delta, x, y, mods }) {
            return redraw;
        }
        // Over the key rows the wheel scrolls rows that overflow (Ctrl:
        // zooms); elsewhere on the ruler and strip it zooms the frames.
        if let Some(redraw) = self.strip_event(&Event::Wheel { delta, x, y, mods }) {
            return redraw;
        }
        if l.ruler.contains(x, y) || l.key_rows.contains(x, y) {
            self.zoom_timeline(x, delta);
            return true;
        }
        if l.timeline.contains(x, y) {
            self.step_frame(if delta > 0.0 { 1.0 } else { -1.0 });
            return true;
        }
        false
    }

    pub(in crate::internals::editor) fn step_frame(&mut self, d: f32) {
        self.stop_playback();
        self.frame = (self.frame.round() + d).clamp(0.0, self.scene.settings.duration);
    }

    // ----- fields -----

    /// Ends typing into a field: parses and records the value.
    pub(in crate::internals::editor) fn commit_edit(&mut self) {
        let Some(edit) = self.edit.take() else { return };
        if edit.fresh {
            // Nothing typed: the value stands (no undo step, nothing left
            // pending on an animated property), as Tab does.
            return;
        }
        let value = if edit.field.is_text() {
            FieldValue::Text(edit.text.clone())
        } else {
            match parse_number(&edit.text) {
                Some(x) => FieldValue::Number(x),
                None => {
                    self.set_status(&format!("'{}' is not a number", edit.text), true);
                    return;
                }
            }
        };
        if is_face_field(edit.field) {
            self.face_typed(edit.field, value);
            return;
        }
        if let (FieldId::Preview(i), FieldValue::Number(x)) = (edit.field, &value) {
            self.set_preview_field(i, *x);
            return;
        }
        if edit.field == FieldId::Frame {
            if let FieldValue::Number(x) = value {
                self.stop_playback();
                self.frame = x.round().clamp(0.0, self.scene.settings.duration);
                let (x, f) = (x, self.frame);
                if let Some(n) = crate::editor::fields::clamp_note("Frame", x, f) {
                    let end = self.scene.settings.duration;
                    self.set_status(&format!("{n} (the scene has frames 0 to {end})"), false);
                }
            }
        }
    }

    pub(in crate::internals::editor) fn text(&mut self, s: &str) -> bool {
        if let Some(e) = &mut self.edit {
            if e.fresh {
                e.text.clear();
                e.fresh = false;
            }
            e.text.extend(s.chars().filter(|c| !c.is_control()));
            return true;
        }
        false
    }

    // ----- picking -----

    pub(in crate::internals::editor) fn pick(&mut self, x: f32, y: f32) {
        let hit = self.pick_at(x, y);
        self.selection = hit;
        match hit {
            Some(id) => {
                let name = ops::display_name(&self.scene, id);
                self.set_status(&format!("Selected {name}"), false);
            }
            None => self.set_status("", false),
        }
    }

    // ----- keyboard -----

    pub(in crate::internals::editor) fn key_down(&mut self, key: Key, mods: Mods) {
        if let Some(e) = &mut self.edit {
            match key {
                Key::Enter => self.commit_edit(),
                Key::Tab => self.tab_field(mods.shift),
                Key::Escape => self.edit = None,
                Key::Backspace => {
                    if e.fresh {
                        e.text.clear();
                        e.fresh = false;
                    } else {
                        e.text.pop();
                    }
                }
                _ => {}
            }
            return;
        }
        if self.graph_event(&Event::KeyDown { key, mods }).is_some()
            || self.graph_shortcut(key, mods)
        {
            return;
        }
        if self.viewport_key(key, mods) || self.key_strip_key(key, mods) {
            return;
        }
        if !matches!(self.drag, Drag::None) {
            if key == Key::Escape {
                self.cancel_drag();
            }
            return;
        }
        self.shortcut(key, mods);
    }

    /// Esc during a drag: put back what the drag changed.
    pub(in crate::internals::editor) fn cancel_drag(&mut self) {
        if let Drag::Side = self.drag {
            let esc = Event::KeyDown {
                key: Key::Escape,
                mods: Mods::NONE,
            };
            self.side_mouse(&esc);
            return;
        }
        let drag = std::mem::take(&mut self.drag);
        if let Drag::Viewport = drag {
            self.cancel_viewport();
        }
        if let Drag::TimeField(p) = drag {
            self.time_field_cancel(p);
        }
    }

    pub(in crate::internals::editor) fn shortcut(&mut self, key: Key, m: Mods) {
        if key == Key::Char('p') && m.alt {
            self.set_preview_range(None);
            return;
        }
        if key == Key::Char('i') && m.alt {
            self.clear_selection_keys();
            return;
        }
        match (key, m.ctrl, m.shift) {
            (Key::Char('n'), true, _) => self.run_action(Action::New),
            (Key::Char('o'), true, _) => self.run_action(Action::Open),
            (Key::Char('i'), true, _) => self.run_action(Action::Import),
            (Key::Char('s'), true, false) => self.run_action(Action::Save),
            (Key::Char('s'), true, true) => self.run_action(Action::SaveAs),
            (Key::Char('q'), true, _) => self.ask_unsaved(After::Quit),
            (Key::Char('z'), true, false) => self.run_action(Action::Undo),
            (Key::Char('z'), true, true) | (Key::Char('y'), true, _) => {
                self.run_action(Action::Redo)
            }
            (Key::Char('p'), true, _) | (Key::Space, false, _) => self.run_action(Action::Play),
            (Key::Char('g'), false, _) => self.run_action(Action::Grid),
            (Key::Char('a'), false, true) => {
                let (x, y) = self.mouse;
                self.open_add_menu(x as i32, y as i32);
            }
            (Key::Char('d'), false, true) => self.run_action(Action::Duplicate),
            (Key::Char('i'), false, false) => self.toggle_ik(),
            (Key::Char('m'), false, false) => self.toggle_material_panel(),
            (Key::Char('c'), false, false) => {
                let (x, y) = self.mouse;
                self.open_clip_menu(x as i32, y as i32);
            }
            (Key::Num(n), ctrl, _) => {
                if let Some(v) = crate::editor::views::ViewCmd::from_numpad(n, ctrl) {
                    self.view_command(v);
                }
            }
            (Key::F(1), _, _) => self.set_help(true),
            (Key::F(3), _, _) => self.open_search(),
            (Key::Char('f'), false, _) => self.frame_selection(),
            (Key::Home, _, _) if self.layout().timeline.contains(self.mouse.0, self.mouse.1) => {
                self.reset_timeline_view()
            }
            (Key::Home, _, _) => self.frame_all(),
            (Key::Char('['), false, _) => self.preview_end_here(true),
            (Key::Char(']'), false, _) => self.preview_end_here(false),
            (Key::Escape, _, _) => self.run_action(Action::Mode),
            (Key::Delete, _, _) => self.delete_key(),
            (Key::Char('r'), false, _) => self.run_action(Action::Record),
            (Key::Char('l'), false, _) => {
                if let Some(s) = self.selection {
                    self.run_action(Action::ToggleLight(s));
                }
            }
            (Key::Char('k'), false, _) => self.insert_keys(),
            (Key::Up, false, _) => self.jump_key(1),
            (Key::Down, false, _) => self.jump_key(-1),
            (Key::Left, _, _) => self.step_frame(-1.0),
            (Key::Right, _, _) => self.step_frame(1.0),
            (Key::End, _, _) => {
                self.stop_playback();
                self.frame = self.scene.settings.duration;
            }
            _ => {}
        }
    }

    /// Runs `then` now, or first asks what to do with unsaved changes.
    pub(in crate::internals::editor) fn ask_unsaved(&mut self, then: After) {
        if self.is_dirty() {
            self.dialog = Some(Dialog::new("Save changes first?", then));
        } else {
            self.continue_with(then);
        }
    }

    pub(in crate::internals::editor) fn continue_with(&mut self, then: After) {
        match then {
            After::Quit => self.quit = true,
            After::New => self.new_scene(),
            After::Open => self.browse(Purpose::Open, None),
            After::Recover => {}
            After::DeleteObject => self.delete_selection(),
        }
    }

    pub(in crate::internals::editor) fn run_action(&mut self, a: Action) {
        match a {
            Action::Clip(c) => self.clip_action(c),
            Action::Material(m) => self.material_action(m),
            Action::TypePreview => self.type_preview_range(),
            Action::New => self.ask_unsaved(After::New),
            Action::Open => self.ask_unsaved(After::Open),
            Action::Import => self.browse(Purpose::Import, None),
            Action::Save => match self.path.clone() {
                Some(p) if is_writable_type(&p) => self.request_save(p, None),
                _ => self.browse(Purpose::SaveAs, None),
            },
            Action::SaveAs => self.browse(Purpose::SaveAs, None),
            Action::Record => {
                self.record = !self.record;
                let s = if self.record { "on" } else { "off" };
                self.set_status(&format!("Record mode {s}"), false);
            }
            Action::Play => self.toggle_play(),
            Action::Grid => self.show_grid = !self.show_grid,
            Action::ViewStyle => {
                self.view_style = match self.view_style {
                    None => Some(RenderStyle::Filled),
                    Some(RenderStyle::Filled) => Some(RenderStyle::Lines),
                    Some(RenderStyle::Lines) => Some(RenderStyle::Points),
                    Some(_) => None,
                }
            }
            Action::Mode => {
                self.mode = match self.mode {
                    Mode::Select => Mode::View,
                    Mode::View => Mode::Select,
                };
            }
            Action::Tool(t) => self.set_tool(t),
            Action::Onion => self.toggle_onion(),
            Action::ToggleGraph => self.toggle_graph(),
            Action::Undo => self.undo(),
            Action::Redo => self.redo(),
            Action::AddLight(which) => {
                let (c, r) = self.scene_radius();
                let before = Box::new(self.scene.clone());
                let mut after = self.scene.clone();
                let id = ops::add_light(&mut after, which, c, r);
                if which != ops::NewLight::Directional {
                    // Where the user looks, not somewhere off-screen.
                    let cam = &self.camera;
                    let spot = ops::in_view_spot(cam.target, cam.back(), cam.distance);
                    // Beside, not on top of, lights already placed there.
                    let right = glam::Vec3::Y.cross(cam.back()).normalize_or(glam::Vec3::X);
                    let taken = |p: glam::Vec3| {
                        self.scene.nodes.iter().any(|n| {
                            n.light()
                                .is_some_and(|l| (l.location - p).length() < 0.05 * cam.distance)
                        })
                    };
                    let at = (0..5)
                        .map(|k| spot - right * (0.12 * k as f32 * cam.distance))
                        .find(|p| !taken(*p))
                        .unwrap_or(spot);
                    if let crate::scene::NodeKind::Light(l) = &mut after.nodes[id.0 as usize].kind {
                        l.location = at;
                        l.direction = (c - at).normalize_or(glam::Vec3::NEG_Y);
                    }
                }
                let name = after.node(id).name.clone();
                self.execute(
                    &format!("Add {name}"),
                    Command::ReplaceScene {
                        before,
                        after: Box::new(after),
                    },
                );
                self.selection = Some(id);
                self.set_status(&format!("Added {name}"), false);
            }
            Action::ToggleLight(id) => {
                let before = Box::new(self.posed_node(id));
                let mut after = before.clone();
                if let crate::scene::NodeKind::Light(l) = &mut after.kind {
                    l.on = !l.on;
                    let label = if l.on { "Light on" } else { "Light off" };
                    let c = Command::SetNode { id, before, after };
                    let c = self.recorded(c, &[crate::anim::Property::LightOn]);
                    self.execute(label, c);
                }
            }
            Action::ObjectStyle => self.cycle_object_style(),
            Action::Add(what) => self.add_thing(what),
            Action::AddMenuHere => {
                let (x, y) = self.mouse;
                self.open_add_menu(x as i32, y as i32);
            }
            Action::ViewMenu => {
                let (x, y) = self.mouse;
                self.open_view_menu(x as i32, y as i32);
            }
            Action::View(v) => self.view_command(v),
            Action::KeySelection => self.insert_keys(),
            Action::ClearKeys => self.clear_selection_keys(),
            Action::Duplicate => self.duplicate_selection(),
            Action::AddMenu => {
                let at = self.under_button(Action::AddMenu).unwrap_or((0, 0));
                self.open_add_menu(at.0, at.1);
            }
            Action::Delete => self.delete_selection(),
            Action::Rename => {
                if let Some(sel) = self.selection {
                    self.side.keys.node_shown = true;
                    let name = self.scene.node(sel).name.clone();
                    self.edit = Some(TextEdit {
                        field: FieldId::Name,
                        text: name,
                        fresh: true,
                    });
                    self.set_status("Type the new name, Enter sets it, Esc cancels", false);
                }
            }
            // The dialog's buttons (it answers its own clicks).
            Action::DialogSave => self.dialog_answer(Answer::Yes),
            Action::DialogDiscard => self.dialog_answer(Answer::Discard),
            Action::DialogCancel => self.dialog_answer(Answer::Cancel),
            Action::Key(a) => self.key_action(a),
            Action::BrowserAccept => {
                if let Some(b) = &mut self.browser {
                    let r = b.choose();
                    self.browser_reply(r);
                }
            }
            Action::BrowserCancel => {
                self.browser_reply(Reply::Cancel);
            }
            Action::BrowserUp => {
                if let Some(b) = &mut self.browser {
                    b.up();
                }
            }
        }
    }

    /// The end of an object list drag: onto another object's row puts the
    /// dragged one under it; onto the list's empty space, at the top level.
    pub(in crate::internals::editor) fn cycle_object_style(&mut self) {
        let Some(sel) = self.selection else { return };
        let next = match self.scene.node(sel).style {
            RenderStyle::Filled => RenderStyle::Lines,
            RenderStyle::Lines => RenderStyle::Points,
            RenderStyle::Points => RenderStyle::Hidden,
            RenderStyle::Hidden => RenderStyle::Filled,
        };
        // The style applies to the object and everything under it.
        let cmds: Vec<Command> = ops::subtree(&self.scene, sel)
            .into_iter()
            .map(|id| {
                let before = Box::new(self.scene.node(id).clone());
                let mut after = before.clone();
                after.style = next;
                Command::SetNode { id, before, after }
            })
            .collect();
        self.execute(&format!("Draw as {next:?}"), Command::Group(cmds));
    }

    /// Delete acts on what has focus: selected keys are taken by the key
    /// strip before this; over the timeline with no key selected the
    /// object is not what the user looks at, so it asks first.
    pub(in crate::internals::editor) fn delete_key(&mut self) {
        let (x, y) = self.mouse;
        let over_strip = self.layout().timeline.contains(x, y);
        match self.selection {
            Some(sel) if over_strip => {
                let name = ops::display_name(&self.scene, sel);
                self.dialog = Some(Dialog::new(
                    format!(
                        "No key is selected in the key strip.\nDelete the object {name} and its keys?"
                    ),
                    After::DeleteObject,
                ));
            }
            _ => self.run_action(Action::Delete),
        }
    }

    pub(in crate::internals::editor) fn delete_selection(&mut self) {
        let Some(sel) = self.selection else {
            self.set_status("Nothing selected to delete", false);
            return;
        };
        let name = ops::display_name(&self.scene, sel);
        let after = ops::remove_subtree(&self.scene, sel);
        let before = Box::new(self.scene.clone());
        self.selection = None;
        self.execute(
            &format!("Delete {name}"),
            Command::ReplaceScene {
                before,
                after: Box::new(after),
            },
        );
        self.set_status(&format!("Deleted {name}"), false);
    }
}
