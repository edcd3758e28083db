//! The one error type of the library front door ([`crate::load`],
//! [`crate::render`], [`crate::Image`], [`crate::check`]).
//!
//! Inside the crate each stage keeps the error it needs (`LoadError` with
//! its position, `String` messages); the front door converts them here so a
//! user matches on one type and prints one format:
//! `path:line:column: message` when the problem has a place in a file.

use std::fmt;
use std::path::{Path, PathBuf};

/// `Result` with [`Error`] as the error type.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Where in a file an error is. `line` and `column` are 1-based; 0 means
/// the position is not known (the file as a whole is the problem).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    /// The file, as the caller named it.
    pub path: PathBuf,
    /// 1-based line, 0 = unknown.
    pub line: u32,
    /// 1-based column, 0 = unknown.
    pub column: u32,
}

/// What kind of thing went wrong, for callers that react differently
/// (a CI tool exits 2 on a bad suite, 1 on a differing picture).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A scene file could not be read or understood.
    Scene,
    /// A picture could not be read, decoded or written.
    Image,
    /// A check suite (TOML) is malformed or names something that is not there.
    Suite,
    /// A request the scene or the renderer cannot satisfy: an unknown
    /// viewpoint, a zero or huge size, a time that is not a number.
    Invalid,
    /// The file system refused (permissions, missing folder, disk full).
    Io,
}

/// Every fallible function of the front door returns this error.
///
/// It prints as `path:line:column: message` when it has a position in a
/// file, `path: message` when only the file is known, else `message`.
///
/// ```
/// let err = animed::load("no/such/scene.wrl").unwrap_err();
/// assert_eq!(err.kind(), animed::ErrorKind::Scene);
/// assert!(err.to_string().starts_with("no/such/scene.wrl"));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Error {
    kind: ErrorKind,
    location: Option<Location>,
    message: String,
}

impl Error {
    /// An error with no file position.
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Error {
        Error {
            kind,
            location: None,
            message: message.into(),
        }
    }

    /// An error at `line`:`column` (1-based; 0 = unknown) of `path`.
    pub fn at(
        kind: ErrorKind,
        path: impl AsRef<Path>,
        line: u32,
        column: u32,
        message: impl Into<String>,
    ) -> Error {
        Error {
            kind,
            location: Some(Location {
                path: path.as_ref().to_path_buf(),
                line,
                column,
            }),
            message: message.into(),
        }
    }

    /// An error about the file `path` as a whole.
    pub fn in_file(kind: ErrorKind, path: impl AsRef<Path>, message: impl Into<String>) -> Error {
        Error::at(kind, path, 0, 0, message)
    }

    /// What kind of problem this is.
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }

    /// The file and position, when the problem has one.
    pub fn location(&self) -> Option<&Location> {
        self.location.as_ref()
    }

    /// The message without the location.
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.location {
            Some(l) if l.line > 0 => write!(
                f,
                "{}:{}:{}: {}",
                l.path.display(),
                l.line,
                l.column,
                self.message
            ),
            Some(l) => write!(f, "{}: {}", l.path.display(), self.message),
            None => f.write_str(&self.message),
        }
    }
}

impl std::error::Error for Error {}

impl From<crate::format::LoadError> for Error {
    fn from(e: crate::format::LoadError) -> Error {
        Error::at(ErrorKind::Scene, &e.path, e.line, e.column, e.message)
    }
}
