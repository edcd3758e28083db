//! Where a statement sits in an OBJ or MTL text, so that warnings say
//! `path:line:column` like every other reader's: tobj reports what it read
//! but not where it read it.

/// Line and column (1-based) of the first statement whose keyword is
/// `keyword` and whose argument text contains `arg` (empty: any).
pub fn find(text: &[u8], keyword: &str, arg: &str) -> Option<(usize, usize)> {
    statements(text)
        .find(|s| s.keyword == keyword && s.rest.contains(arg))
        .map(|s| (s.line, s.column))
}

/// Line and column of `keyword` inside the block of MTL material `name`
/// (from `newmtl name` to the next `newmtl`), else of its `newmtl` line.
pub fn find_in_material(text: &[u8], name: &str, keyword: &str) -> Option<(usize, usize)> {
    let mut head = None;
    for s in statements(text) {
        if s.keyword == "newmtl" {
            if head.is_some() {
                break;
            }
            if s.rest == name {
                head = Some((s.line, s.column));
            }
        } else if head.is_some() && s.keyword.eq_ignore_ascii_case(keyword) {
            return Some((s.line, s.column));
        }
    }
    head
}

struct Statement<'a> {
    line: usize,
    column: usize,
    keyword: &'a str,
    rest: &'a str,
}

fn statements(text: &[u8]) -> impl Iterator<Item = Statement<'_>> {
    text.split(|&b| b == b'\n')
        .enumerate()
        .filter_map(|(i, raw)| {
            let line = std::str::from_utf8(raw).ok()?;
            let start = line.len() - line.trim_start().len();
            let body = line.trim();
            let (keyword, rest) = body.split_once(char::is_whitespace).unwrap_or((body, ""));
            (!keyword.is_empty() && !keyword.starts_with('#')).then(|| Statement {
                line: i + 1,
                column: start + 1,
                keyword,
                rest: rest.trim(),
            })
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    const MTL: &[u8] =
        b"# lib\nnewmtl a\nKd 1 0 0\n  map_Kd a.png\nnewmtl b\nKd 0 1 0\nmap_d b.png\n";

    #[test]
    fn statements_are_found_where_they_are() {
        assert_eq!(find(MTL, "newmtl", "b"), Some((5, 1)));
        assert_eq!(
            find(b"v 0 0 0\nmtllib x.mtl\n", "mtllib", "x.mtl"),
            Some((2, 1))
        );
        assert_eq!(find(MTL, "mtllib", ""), None);
    }

    #[test]
    fn material_blocks_bound_the_search() {
        assert_eq!(find_in_material(MTL, "a", "map_Kd"), Some((4, 3)));
        // b has no map_Kd: its own newmtl line, never a's map_Kd.
        assert_eq!(find_in_material(MTL, "b", "map_Kd"), Some((5, 1)));
        assert_eq!(find_in_material(MTL, "b", "map_d"), Some((7, 1)));
        assert_eq!(find_in_material(MTL, "c", "map_d"), None);
    }
}
