use std::fmt;
use std::path::{Path, PathBuf};

/// A reader error with its position (line and column are 1-based; 0 = unknown
/// or not a text position, e.g. a glTF error whose message starts with its
/// JSON pointer; then it prints as `path: message`, never `path:0:0:`).
#[derive(Debug, Clone, PartialEq)]
pub struct LoadError {
    pub path: PathBuf,
    pub line: u32,
    pub column: u32,
    pub message: String,
}

impl LoadError {
    pub fn new(path: &Path, line: u32, column: u32, message: impl Into<String>) -> Self {
        LoadError {
            path: path.to_path_buf(),
            line,
            column,
            message: message.into(),
        }
    }
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            return write!(f, "{}: {}", self.path.display(), self.message);
        }
        write!(
            f,
            "{}:{}:{}: {}",
            self.path.display(),
            self.line,
            self.column,
            self.message
        )
    }
}

impl std::error::Error for LoadError {}
