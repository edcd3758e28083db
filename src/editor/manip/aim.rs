//! Naming a handle (scripts' `drag-handle`, tests); finding a window pixel
//! where the named handle of the current tool can be grabbed is the
//! editor's (`route/aim.rs`).
//!
//! Names: `x`, `y`, `z` (the arrow, ring or scale box of that axis, as the
//! tool has it), `yz`, `xz`, `xy` (move plane squares), `view` (the outer
//! rotate ring), `uniform` (the scale centre box), `body` (a pixel of the
//! selected object that is on no handle).

use super::{Handle, Tool};

/// The handle `name` means for `tool` (`None` for an unknown name or one
/// the tool does not have).
pub fn parse(tool: Tool, name: &str) -> Option<Handle> {
    let i = match name.to_ascii_lowercase().as_str() {
        "x" => 0,
        "y" => 1,
        "z" => 2,
        "yz" if tool == Tool::Translate => return Some(Handle::Plane(0)),
        "xz" | "zx" if tool == Tool::Translate => return Some(Handle::Plane(1)),
        "xy" | "yx" if tool == Tool::Translate => return Some(Handle::Plane(2)),
        "view" if tool == Tool::Rotate => return Some(Handle::ViewRing),
        "uniform" if tool == Tool::Scale => return Some(Handle::Uniform),
        "body" => return Some(Handle::Body),
        _ => return None,
    };
    Some(match tool {
        Tool::Translate => Handle::Axis(i),
        Tool::Rotate => Handle::Ring(i),
        Tool::Scale => Handle::ScaleAxis(i),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_depend_on_the_tool() {
        assert_eq!(parse(Tool::Translate, "y"), Some(Handle::Axis(1)));
        assert_eq!(parse(Tool::Rotate, "Z"), Some(Handle::Ring(2)));
        assert_eq!(parse(Tool::Scale, "x"), Some(Handle::ScaleAxis(0)));
        assert_eq!(parse(Tool::Translate, "xz"), Some(Handle::Plane(1)));
        assert_eq!(parse(Tool::Rotate, "xz"), None);
        assert_eq!(parse(Tool::Rotate, "view"), Some(Handle::ViewRing));
        assert_eq!(parse(Tool::Scale, "uniform"), Some(Handle::Uniform));
        assert_eq!(parse(Tool::Scale, "body"), Some(Handle::Body));
        assert_eq!(parse(Tool::Translate, "w"), None);
    }
}
