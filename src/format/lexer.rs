//! The one tokenizer for the classic Inventor / VRML 1.0 / VRML97 syntax.
//!
//! Comments (`#` to end of line), strings with `\"` and `\\` escapes,
//! numbers (decimal and Inventor's `0x` hex integers), identifiers, the four
//! brackets, and the few punctuation marks Inventor uses (`( ) | = ~`).
//! Commas are white space. Every token carries its 1-based line and column.

/// Where a token starts (1-based).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Pos {
    pub line: u32,
    pub column: u32,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Tok {
    Ident(String),
    Str(String),
    Num(f64),
    LBrace,
    RBrace,
    LBracket,
    RBracket,
    /// One of `( ) | = ~`.
    Punct(u8),
    Eof,
}

impl Tok {
    /// A short description for error messages.
    pub fn describe(&self) -> String {
        match self {
            Tok::Ident(s) => format!("'{s}'"),
            Tok::Str(_) => "a string".into(),
            Tok::Num(n) => format!("number {n}"),
            Tok::LBrace => "'{'".into(),
            Tok::RBrace => "'}'".into(),
            Tok::LBracket => "'['".into(),
            Tok::RBracket => "']'".into(),
            Tok::Punct(c) => format!("'{}'", *c as char),
            Tok::Eof => "end of file".into(),
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Token {
    pub tok: Tok,
    pub pos: Pos,
}

/// A lexing error with its position.
#[derive(Clone, Debug, PartialEq)]
pub struct LexError {
    pub pos: Pos,
    pub message: String,
}

/// Which dialect the header line announces.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Header {
    /// `#Inventor V2.x ascii` (2.0 and 2.1).
    Inventor2,
    /// `#Inventor V1.0 ascii`: read like VRML 1.0's Inventor subset.
    Inventor1,
    /// `#Inventor V… binary`: read by `iv::binary` (not by this lexer).
    InventorBinary,
    /// `#VRML V1.0 ascii`.
    Vrml1,
    /// `#VRML V2.0 utf8`.
    Vrml97,
    /// `#X3D V3.0`…`V3.3` or `V4.0` `utf8`: the X3D classic encoding.
    X3dClassic,
}

/// Reads the header line. Binary Inventor and unknown headers are errors
/// whose message says what to do.
pub fn read_header(bytes: &[u8]) -> Result<Header, LexError> {
    let end = bytes
        .iter()
        .position(|&b| b == b'\n' || b == b'\r')
        .unwrap_or(bytes.len())
        .min(200);
    let line = String::from_utf8_lossy(&bytes[..end]);
    let line = line.trim_start_matches('\u{feff}');
    let words: Vec<&str> = line.split_whitespace().collect();
    let err = |m: &str| LexError {
        pos: Pos { line: 1, column: 1 },
        message: m.to_string(),
    };
    match words.as_slice() {
        ["#Inventor", v, kind, ..] => {
            if kind.eq_ignore_ascii_case("binary") {
                return Ok(Header::InventorBinary);
            }
            match *v {
                "V2.1" | "V2.0" => Ok(Header::Inventor2),
                "V1.0" => Ok(Header::Inventor1),
                _ => Err(err(&format!("unsupported Inventor version {v}"))),
            }
        }
        ["#VRML", "V1.0", ..] => Ok(Header::Vrml1),
        ["#VRML", "V2.0", ..] => Ok(Header::Vrml97),
        ["#VRML", v, ..] => Err(err(&format!("unsupported VRML version {v}"))),
        ["#X3D", "V3.0" | "V3.1" | "V3.2" | "V3.3" | "V4.0", ..] => Ok(Header::X3dClassic),
        ["#X3D", v, ..] => Err(err(&format!(
            "unsupported X3D version {v} (animed reads V3.0 to V3.3 and V4.0)"
        ))),
        _ => Err(err(
            "not an Inventor, VRML or X3D file (expected a '#Inventor V2.1 ascii', '#VRML V2.0 utf8' or '#X3D V4.0 utf8' header, or X3D's XML)",
        )),
    }
}

/// A streaming tokenizer with a small look-ahead.
pub struct Lexer<'a> {
    src: &'a [u8],
    at: usize,
    line: u32,
    col: u32,
    ahead: std::collections::VecDeque<Token>,
}

fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r' | b',' | 0x0b | 0x0c | 0)
}

/// Bytes that end an identifier.
fn ends_word(b: u8) -> bool {
    is_space(b)
        || matches!(
            b,
            b'{' | b'}' | b'[' | b']' | b'"' | b'#' | b'(' | b')' | b'|' | b'=' | b'~'
        )
}

impl<'a> Lexer<'a> {
    pub fn new(src: &'a [u8]) -> Self {
        Lexer {
            src,
            at: 0,
            line: 1,
            col: 1,
            ahead: Default::default(),
        }
    }

    /// The position of the next token (after skipping space and comments).
    pub fn pos(&mut self) -> Pos {
        match self.peek() {
            Ok(t) => t.pos,
            Err(e) => e.pos,
        }
    }

    pub fn peek(&mut self) -> Result<&Token, LexError> {
        self.peek_nth(0)
    }

    /// The `n`-th token ahead (0 = next).
    pub fn peek_nth(&mut self, n: usize) -> Result<&Token, LexError> {
        while self.ahead.len() <= n {
            let t = self.lex()?;
            self.ahead.push_back(t);
        }
        Ok(&self.ahead[n])
    }

    pub fn next_token(&mut self) -> Result<Token, LexError> {
        match self.ahead.pop_front() {
            Some(t) => Ok(t),
            None => self.lex(),
        }
    }

    /// Reads a DEF/USE name: any run of non-space characters up to a bracket
    /// (Coin writes names such as `+0` that would otherwise lex as numbers).
    pub fn next_name(&mut self) -> Result<(String, Pos), LexError> {
        if let Some(t) = self.ahead.pop_front() {
            return match t.tok {
                Tok::Ident(s) => Ok((s, t.pos)),
                Tok::Num(n) => Ok((format!("{n}"), t.pos)),
                other => Err(LexError {
                    pos: t.pos,
                    message: format!("expected a name, found {}", other.describe()),
                }),
            };
        }
        self.skip_space();
        let pos = self.here();
        let start = self.at;
        while self.at < self.src.len() && !ends_word(self.src[self.at]) {
            self.bump();
        }
        if start == self.at {
            return Err(LexError {
                pos,
                message: "expected a name".into(),
            });
        }
        Ok((
            String::from_utf8_lossy(&self.src[start..self.at]).into_owned(),
            pos,
        ))
    }

    fn here(&self) -> Pos {
        Pos {
            line: self.line,
            column: self.col,
        }
    }

    fn bump(&mut self) {
        if self.src[self.at] == b'\n' {
            self.line = self.line.saturating_add(1);
            self.col = 1;
        } else {
            self.col = self.col.saturating_add(1);
        }
        self.at += 1;
    }

    fn skip_space(&mut self) {
        while self.at < self.src.len() {
            let b = self.src[self.at];
            if is_space(b) {
                self.bump();
            } else if b == b'#' {
                while self.at < self.src.len() && self.src[self.at] != b'\n' {
                    self.at += 1;
                    self.col = self.col.saturating_add(1);
                }
            } else {
                break;
            }
        }
    }

    fn lex(&mut self) -> Result<Token, LexError> {
        self.skip_space();
        let pos = self.here();
        let Some(&b) = self.src.get(self.at) else {
            return Ok(Token { tok: Tok::Eof, pos });
        };
        let single = match b {
            b'{' => Some(Tok::LBrace),
            b'}' => Some(Tok::RBrace),
            b'[' => Some(Tok::LBracket),
            b']' => Some(Tok::RBracket),
            b'(' | b')' | b'|' | b'=' | b'~' => Some(Tok::Punct(b)),
            _ => None,
        };
        if let Some(tok) = single {
            self.bump();
            return Ok(Token { tok, pos });
        }
        if b == b'"' {
            return self.string(pos);
        }
        if b.is_ascii_digit() || b == b'-' || b == b'+' || b == b'.' {
            if let Some(n) = self.number() {
                return Ok(Token {
                    tok: Tok::Num(n),
                    pos,
                });
            }
        }
        let start = self.at;
        while self.at < self.src.len() && !ends_word(self.src[self.at]) {
            self.bump();
        }
        if start == self.at {
            // Only reachable for a byte that neither starts a token nor a word.
            self.bump();
            return Err(LexError {
                pos,
                message: format!("unexpected character {:?}", b as char),
            });
        }
        let word = String::from_utf8_lossy(&self.src[start..self.at]).into_owned();
        Ok(Token {
            tok: Tok::Ident(word),
            pos,
        })
    }

    fn string(&mut self, pos: Pos) -> Result<Token, LexError> {
        self.bump(); // opening quote
        let mut out = Vec::new();
        loop {
            let Some(&b) = self.src.get(self.at) else {
                return Err(LexError {
                    pos,
                    message: "unterminated string".into(),
                });
            };
            self.bump();
            match b {
                b'"' => break,
                b'\\' => {
                    if let Some(&c) = self.src.get(self.at) {
                        self.bump();
                        out.push(c);
                    }
                }
                _ => out.push(b),
            }
        }
        Ok(Token {
            tok: Tok::Str(String::from_utf8_lossy(&out).into_owned()),
            pos,
        })
    }

    /// Lexes a number at the cursor, or returns `None` (cursor unchanged)
    /// when the characters there are not one.
    fn number(&mut self) -> Option<f64> {
        let s = self.src;
        let start = self.at;
        let mut i = start;
        if i < s.len() && (s[i] == b'-' || s[i] == b'+') {
            i += 1;
        }
        // Hex integer (Inventor packed colours, masks).
        if i + 1 < s.len() && s[i] == b'0' && (s[i + 1] == b'x' || s[i + 1] == b'X') {
            let hs = i + 2;
            let mut j = hs;
            while j < s.len() && s[j].is_ascii_hexdigit() {
                j += 1;
            }
            if j > hs && (j == s.len() || ends_word(s[j])) {
                let digits = std::str::from_utf8(&s[hs..j]).ok()?;
                let v = u64::from_str_radix(digits, 16).ok()? as f64;
                let v = if s[start] == b'-' { -v } else { v };
                self.advance_to(j);
                return Some(v);
            }
            return None;
        }
        let int_start = i;
        while i < s.len() && s[i].is_ascii_digit() {
            i += 1;
        }
        let mut digits = i - int_start;
        if i < s.len() && s[i] == b'.' {
            i += 1;
            let f = i;
            while i < s.len() && s[i].is_ascii_digit() {
                i += 1;
            }
            digits += i - f;
        }
        if digits == 0 {
            return None;
        }
        if i < s.len() && (s[i] == b'e' || s[i] == b'E') {
            let mut j = i + 1;
            if j < s.len() && (s[j] == b'-' || s[j] == b'+') {
                j += 1;
            }
            let e = j;
            while j < s.len() && s[j].is_ascii_digit() {
                j += 1;
            }
            if j > e {
                i = j;
            }
        }
        // "1.2.3" or "12abc" is a word, not a number.
        if i < s.len() && !ends_word(s[i]) {
            return None;
        }
        let text = std::str::from_utf8(&s[start..i]).ok()?;
        let text = text.strip_prefix('+').unwrap_or(text);
        let v: f64 = text.parse().ok()?;
        self.advance_to(i);
        Some(v)
    }

    fn advance_to(&mut self, end: usize) {
        // Numbers hold no newlines: only the column moves.
        self.col = self.col.saturating_add((end - self.at) as u32);
        self.at = end;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn toks(s: &str) -> Vec<Tok> {
        let mut l = Lexer::new(s.as_bytes());
        let mut out = Vec::new();
        loop {
            let t = l.next_token().unwrap();
            if t.tok == Tok::Eof {
                return out;
            }
            out.push(t.tok);
        }
    }

    #[test]
    fn numbers_words_strings_and_commas() {
        let t = toks("Cube { width 2.5, -1e2 .5 0xFF } # comment\n \"a\\\"b\" +3");
        assert_eq!(
            t,
            vec![
                Tok::Ident("Cube".into()),
                Tok::LBrace,
                Tok::Ident("width".into()),
                Tok::Num(2.5),
                Tok::Num(-100.0),
                Tok::Num(0.5),
                Tok::Num(255.0),
                Tok::RBrace,
                Tok::Str("a\"b".into()),
                Tok::Num(3.0),
            ]
        );
    }

    #[test]
    fn punctuation_and_dotted_names() {
        let t = toks("parts (SIDES|TOP) Clock.fraction_changed");
        assert_eq!(
            t,
            vec![
                Tok::Ident("parts".into()),
                Tok::Punct(b'('),
                Tok::Ident("SIDES".into()),
                Tok::Punct(b'|'),
                Tok::Ident("TOP".into()),
                Tok::Punct(b')'),
                Tok::Ident("Clock.fraction_changed".into()),
            ]
        );
    }

    #[test]
    fn positions_are_line_and_column() {
        let mut l = Lexer::new(b"#VRML V2.0 utf8\n  Box {\n\t}");
        let a = l.next_token().unwrap();
        assert_eq!(a.pos, Pos { line: 2, column: 3 });
        l.next_token().unwrap();
        let c = l.next_token().unwrap();
        assert_eq!((c.tok, c.pos), (Tok::RBrace, Pos { line: 3, column: 2 }));
    }

    #[test]
    fn unterminated_string_is_an_error_at_its_start() {
        let mut l = Lexer::new(b"  \"abc");
        let e = l.next_token().unwrap_err();
        assert_eq!(e.pos, Pos { line: 1, column: 3 });
        assert!(e.message.contains("unterminated"));
    }

    #[test]
    fn coin_names_like_plus_zero() {
        let mut l = Lexer::new(b"DEF +0 Separator");
        l.next_token().unwrap();
        assert_eq!(l.next_name().unwrap().0, "+0");
        assert_eq!(l.next_token().unwrap().tok, Tok::Ident("Separator".into()));
    }

    #[test]
    fn headers() {
        assert_eq!(read_header(b"#VRML V2.0 utf8\n").unwrap(), Header::Vrml97);
        assert_eq!(read_header(b"#VRML V1.0 ascii\n").unwrap(), Header::Vrml1);
        assert_eq!(
            read_header(b"#Inventor V2.1 ascii\n").unwrap(),
            Header::Inventor2
        );
        assert_eq!(
            read_header(b"#Inventor V2.0 ascii\n").unwrap(),
            Header::Inventor2
        );
        assert_eq!(
            read_header(b"#Inventor V1.0 ascii\n").unwrap(),
            Header::Inventor1
        );
        assert_eq!(
            read_header(b"#Inventor V2.1 binary\n").unwrap(),
            Header::InventorBinary
        );
        assert!(read_header(b"hello").is_err());
    }
}
