//! Input events every screen understands. The window (`app/`) and headless
//! scripts (`script.rs`) both translate their input into these.

/// Modifier keys held during an event.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Mods {
    pub ctrl: bool,
    pub shift: bool,
    pub alt: bool,
}

impl Mods {
    pub const NONE: Mods = Mods {
        ctrl: false,
        shift: false,
        alt: false,
    };
    pub fn ctrl() -> Mods {
        Mods {
            ctrl: true,
            ..Mods::NONE
        }
    }
    pub fn shift() -> Mods {
        Mods {
            shift: true,
            ..Mods::NONE
        }
    }
    pub fn alt() -> Mods {
        Mods {
            alt: true,
            ..Mods::NONE
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MouseButton {
    Left,
    Middle,
    Right,
}

/// Keys the editor binds (letters and digits are `Char`, lower case).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Key {
    Char(char),
    Escape,
    Enter,
    Tab,
    Backspace,
    Delete,
    Home,
    End,
    Left,
    Right,
    Up,
    Down,
    PageUp,
    PageDown,
    Space,
    F(u8),
    /// A numpad digit (0-9): the editor's standard views.
    Num(u8),
}

impl Key {
    /// Parses a key name as written in scripts: `a`, `5`, `esc`, `enter`,
    /// `delete`, `home`, `f1`, `space`, `left`, ...
    pub fn parse(s: &str) -> Option<Key> {
        let l = s.to_ascii_lowercase();
        let k = match l.as_str() {
            "esc" | "escape" => Key::Escape,
            "enter" | "return" => Key::Enter,
            "tab" => Key::Tab,
            "backspace" => Key::Backspace,
            "delete" | "del" => Key::Delete,
            "home" => Key::Home,
            "end" => Key::End,
            "left" => Key::Left,
            "right" => Key::Right,
            "up" => Key::Up,
            "down" => Key::Down,
            "pageup" => Key::PageUp,
            "pagedown" => Key::PageDown,
            "space" => Key::Space,
            n if n.len() == 4 && n.starts_with("num") => {
                Key::Num(n[3..].parse::<u8>().ok().filter(|d| *d <= 9)?)
            }
            _ => {
                let mut chars = l.chars();
                match (chars.next(), chars.next()) {
                    (Some(c), None) if c.is_ascii_graphic() => Key::Char(c),
                    (Some('f'), Some(_)) => {
                        let n: u8 = l[1..].parse().ok()?;
                        if !(1..=12).contains(&n) {
                            return None;
                        }
                        Key::F(n)
                    }
                    _ => return None,
                }
            }
        };
        Some(k)
    }
}

/// One input event. Coordinates are window pixels (top-left origin).
#[derive(Clone, Debug, PartialEq)]
pub enum Event {
    KeyDown {
        key: Key,
        mods: Mods,
    },
    KeyUp {
        key: Key,
        mods: Mods,
    },
    /// Printable text typed (after keyboard layout), one or more characters.
    Text(String),
    MouseMove {
        x: f32,
        y: f32,
        mods: Mods,
    },
    MouseDown {
        button: MouseButton,
        x: f32,
        y: f32,
        mods: Mods,
    },
    MouseUp {
        button: MouseButton,
        x: f32,
        y: f32,
        mods: Mods,
    },
    /// Wheel notches: positive = away from the user (zoom in).
    Wheel {
        delta: f32,
        x: f32,
        y: f32,
        mods: Mods,
    },
    Resize {
        width: u32,
        height: u32,
    },
    /// Time in seconds since some fixed start; drives playback.
    Tick {
        time: f64,
    },
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn key_names() {
        assert_eq!(Key::parse("N"), Some(Key::Char('n')));
        assert_eq!(Key::parse("esc"), Some(Key::Escape));
        assert_eq!(Key::parse("f5"), Some(Key::F(5)));
        assert_eq!(Key::parse("f13"), None);
        assert_eq!(Key::parse("banana"), None);
        assert_eq!(Key::parse("delete"), Some(Key::Delete));
        assert_eq!(Key::parse("num7"), Some(Key::Num(7)));
        assert_eq!(Key::parse("numx"), None);
    }
}
