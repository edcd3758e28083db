//! minifb keys → editor keys.

use crate::editor::Key;
use minifb::Key as K;

pub fn key(k: K) -> Option<Key> {
    let letters = [
        (K::A, 'a'),
        (K::B, 'b'),
        (K::C, 'c'),
        (K::D, 'd'),
        (K::E, 'e'),
        (K::F, 'f'),
        (K::G, 'g'),
        (K::H, 'h'),
        (K::I, 'i'),
        (K::J, 'j'),
        (K::K, 'k'),
        (K::L, 'l'),
        (K::M, 'm'),
        (K::N, 'n'),
        (K::O, 'o'),
        (K::P, 'p'),
        (K::Q, 'q'),
        (K::R, 'r'),
        (K::S, 's'),
        (K::T, 't'),
        (K::U, 'u'),
        (K::V, 'v'),
        (K::W, 'w'),
        (K::X, 'x'),
        (K::Y, 'y'),
        (K::Z, 'z'),
        (K::Key0, '0'),
        (K::Key1, '1'),
        (K::Key2, '2'),
        (K::Key3, '3'),
        (K::Key4, '4'),
        (K::Key5, '5'),
        (K::Key6, '6'),
        (K::Key7, '7'),
        (K::Key8, '8'),
        (K::Key9, '9'),
    ];
    if let Some((_, c)) = letters.iter().find(|(m, _)| *m == k) {
        return Some(Key::Char(*c));
    }
    Some(match k {
        K::Escape => Key::Escape,
        K::Enter | K::NumPadEnter => Key::Enter,
        K::Tab => Key::Tab,
        K::Backspace => Key::Backspace,
        K::Delete => Key::Delete,
        K::Home => Key::Home,
        K::End => Key::End,
        K::Left => Key::Left,
        K::Right => Key::Right,
        K::Up => Key::Up,
        K::Down => Key::Down,
        K::PageUp => Key::PageUp,
        K::PageDown => Key::PageDown,
        K::Space => Key::Space,
        K::F1 => Key::F(1),
        K::F2 => Key::F(2),
        K::F3 => Key::F(3),
        K::F4 => Key::F(4),
        K::F5 => Key::F(5),
        _ => return None,
    })
}
