//! JSON pointers (RFC 6901) that name the place in a glTF file a problem
//! comes from: glTF has no useful line numbers once a .glb or a minified
//! .gltf is involved, so errors say `/meshes/3/primitives/0/attributes/POSITION`.

use std::fmt::Write as _;

/// Builds a pointer from its reference tokens, escaping `~` and `/`.
pub fn pointer(parts: &[&dyn std::fmt::Display]) -> String {
    let mut s = String::new();
    for p in parts {
        s.push('/');
        let token = p.to_string();
        for c in token.chars() {
            match c {
                '~' => s.push_str("~0"),
                '/' => s.push_str("~1"),
                c => s.push(c),
            }
        }
    }
    s
}

/// Converts a path as the `gltf` crate's validation spells it
/// (`meshes[3].primitives[0].attributes["POSITION"]`) into a JSON pointer.
pub fn from_crate_path(path: &str) -> String {
    // `extensionsRequired[0] = "EXT_x"`: the value is not part of the place.
    let path = path.split(" = ").next().unwrap_or(path);
    let mut out = String::new();
    let mut chars = path.chars().peekable();
    let mut token = String::new();
    let flush = |out: &mut String, token: &mut String| {
        if !token.is_empty() {
            let _ = write!(out, "{}", pointer(&[token]));
            token.clear();
        }
    };
    while let Some(c) = chars.next() {
        match c {
            '.' => flush(&mut out, &mut token),
            '[' => {
                flush(&mut out, &mut token);
                let quoted = chars.peek() == Some(&'"');
                if quoted {
                    chars.next();
                }
                for c in chars.by_ref() {
                    if (quoted && c == '"') || (!quoted && c == ']') {
                        break;
                    }
                    token.push(c);
                }
                if quoted {
                    // Skip the closing `]`.
                    chars.next();
                }
                flush(&mut out, &mut token);
            }
            c => token.push(c),
        }
    }
    flush(&mut out, &mut token);
    if out.is_empty() {
        "/".to_string()
    } else {
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crate_paths_become_pointers() {
        assert_eq!(
            from_crate_path("meshes[3].primitives[0].attributes[\"POSITION\"]"),
            "/meshes/3/primitives/0/attributes/POSITION"
        );
        assert_eq!(from_crate_path("asset.version"), "/asset/version");
        assert_eq!(from_crate_path(""), "/");
        assert_eq!(
            from_crate_path("extensionsRequired[1] = \"EXT_x\""),
            "/extensionsRequired/1"
        );
        assert_eq!(pointer(&[&"a/b~c", &7]), "/a~1b~0c/7");
    }
}
