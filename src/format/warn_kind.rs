//! Which load warnings say that a file breaks its spec, and which only say
//! that animed leaves something out (a node or feature it does not support)
//! or that a file the scene refers to is not there. `animed info --strict`
//! fails on the first kind only: a validator's verdict is about the file,
//! not about this viewer's limits or the disk it was copied to.
//!
//! Warnings are plain text (`Loaded::warnings`); each phrase below is one
//! the readers write for such a case (see the `sources` test), so a new
//! reader message is a spec break until it is listed here.

/// Phrases of warnings about animed's own limits or missing files.
const NOT_THE_FILES_FAULT: &[&str] = &[
    // A node, field animation, texture kind, extension or EXTERNPROTO
    // animed does not implement ("Script is not supported; skipped",
    // "animating Extrusion.spine is not supported; not imported").
    " is not supported; ",
    " is not supported (",
    // Inventor field connections (engines) are read, not run.
    "field connections (engines) are not evaluated",
    // A legal file: a disabled TimeSensor, an interpolator driven by
    // something other than a TimeSensor, an Inventor node that describes
    // its own fields (the Inventor file format allows it).
    "is disabled (enabled FALSE)",
    "is not driven by a TimeSensor",
    "(declared with fields [...]) skipped",
    // Files the scene names that are not on this disk.
    "file not found",
    "No such file or directory",
    // animed's own nesting limit for Inline files.
    "inline files nested deeper than",
];

/// Whether `warning` (one of `Loaded::warnings`) says the file breaks its
/// spec; false for animed's own limits and missing files.
pub fn breaks_the_spec(warning: &str) -> bool {
    !NOT_THE_FILES_FAULT.iter().any(|p| warning.contains(p))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    fn warnings(name: &str, src: &str) -> Vec<String> {
        let dir = std::env::temp_dir().join(format!("animed-warn-kind-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(name);
        std::fs::write(&path, src).unwrap();
        let loaded = crate::format::load(Path::new(&path)).unwrap();
        loaded.warnings
    }

    /// Warnings the readers really write: unsupported nodes, engines and
    /// missing files are not the file's fault; an unknown field, an
    /// unknown node and a USE of an undefined name are.
    #[test]
    fn limits_and_missing_files_are_not_spec_breaks() {
        let ok = warnings(
            "limits.wrl",
            "#VRML V2.0 utf8\nTouchSensor { }\nScript { }\n\
             Shape { appearance Appearance { texture ImageTexture { url \"gone.png\" } } geometry Box { } }\n\
             Inline { url \"nothere.wrl\" }\n",
        );
        assert!(ok.len() >= 4, "{ok:?}");
        for w in &ok {
            assert!(!breaks_the_spec(w), "{w}");
        }
        let engines = warnings(
            "engines.iv",
            "#Inventor V2.1 ascii\nSeparator { DEF T Translation { } \
             Translation { translation 0 0 0 = USE T . translation } Cube { } }\n",
        );
        assert!(!engines.is_empty(), "{engines:?}");
        assert!(engines.iter().all(|w| !breaks_the_spec(w)), "{engines:?}");
        let bad = warnings(
            "bad.wrl",
            "#VRML V2.0 utf8\nTransform { translate 1 0 0 }\nFoo { }\nUSE Nobody\n",
        );
        assert_eq!(bad.len(), 3, "{bad:?}");
        for w in &bad {
            assert!(breaks_the_spec(w), "{w}");
        }
    }
}
