//! The input budget: what one load may cost, in one place.
//!
//! Every byte a load reads (the file, its Inline/File/WWWInline files,
//! OBJ `mtllib`s, textures, glTF buffers, gzip output) goes through
//! [`read_file`] / [`charge_bytes`], and the readers charge the nodes,
//! numbers and geometry they make, so a small hostile file cannot make a
//! large scene. A load that would pass a limit fails with an error naming
//! the limit and how to raise it (`--max-…` or `ANIMED_MAX_…`).
//!
//! The budget of the load running on this thread lives in a thread-local:
//! `format::load` opens it ([`scope`]) and nested loads (inlines) share it,
//! so readers need no extra parameter to stay within it.
//!
//! Nesting depth is one number for the whole load: syntactic nesting, PROTO
//! expansion and Inline files all count against [`Limits::max_depth`], and
//! the recursion that follows a depth (parser, PROTO copy, builders, drop)
//! stays far below a 2 MiB thread stack at that depth (tested in debug).

use std::cell::RefCell;
use std::fmt;
use std::io::Read;
use std::path::Path;
use std::sync::RwLock;

/// One limit: its name in messages, its CLI flag and environment variable.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Limit {
    /// Bytes read in one load (files, inlines, gzip output).
    Bytes,
    /// Parsed nodes (PROTO copies included) and scene nodes (USE copies included).
    Nodes,
    /// Nesting depth: syntax, PROTO expansion and Inline files together.
    Depth,
    /// Vertices + triangles generated, counted once per instance.
    Geometry,
    /// Numbers (and strings) in the field values of one load.
    Numbers,
}

impl Limit {
    pub const ALL: [Limit; 5] = [
        Limit::Bytes,
        Limit::Nodes,
        Limit::Depth,
        Limit::Geometry,
        Limit::Numbers,
    ];

    /// What is counted, for messages.
    pub fn what(self) -> &'static str {
        match self {
            Limit::Bytes => "bytes read",
            Limit::Nodes => "nodes",
            Limit::Depth => "levels of nesting (syntax, PROTO and Inline together)",
            Limit::Geometry => "vertices + triangles",
            Limit::Numbers => "numbers in field values (a field counts 12, a string 4 + length/8)",
        }
    }

    pub fn flag(self) -> &'static str {
        match self {
            Limit::Bytes => "--max-bytes",
            Limit::Nodes => "--max-nodes",
            Limit::Depth => "--max-depth",
            Limit::Geometry => "--max-geometry",
            Limit::Numbers => "--max-numbers",
        }
    }

    pub fn env(self) -> &'static str {
        match self {
            Limit::Bytes => "ANIMED_MAX_BYTES",
            Limit::Nodes => "ANIMED_MAX_NODES",
            Limit::Depth => "ANIMED_MAX_DEPTH",
            Limit::Geometry => "ANIMED_MAX_GEOMETRY",
            Limit::Numbers => "ANIMED_MAX_NUMBERS",
        }
    }
}

/// The limits of one load. Defaults keep the peak memory of any load well
/// under 1.5 GB (measured by `tests/hostile.rs`); raise them for big scenes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Limits {
    pub max_bytes: u64,
    pub max_nodes: u64,
    pub max_depth: u64,
    pub max_geometry: u64,
    pub max_numbers: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_bytes: 256 * 1024 * 1024,
            max_nodes: 1_000_000,
            max_depth: 256,
            max_geometry: 16_000_000,
            max_numbers: 32_000_000,
        }
    }
}

/// Deepest `--max-depth` accepted: the recursion per level is tested to fit
/// a 2 MiB stack at this depth.
pub const DEPTH_CEILING: u64 = 1024;

impl Limits {
    pub fn get(&self, l: Limit) -> u64 {
        match l {
            Limit::Bytes => self.max_bytes,
            Limit::Nodes => self.max_nodes,
            Limit::Depth => self.max_depth,
            Limit::Geometry => self.max_geometry,
            Limit::Numbers => self.max_numbers,
        }
    }

    pub fn set(&mut self, l: Limit, v: u64) {
        let v = if l == Limit::Depth {
            v.min(DEPTH_CEILING)
        } else {
            v
        };
        match l {
            Limit::Bytes => self.max_bytes = v,
            Limit::Nodes => self.max_nodes = v,
            Limit::Depth => self.max_depth = v,
            Limit::Geometry => self.max_geometry = v,
            Limit::Numbers => self.max_numbers = v,
        }
    }

    /// The defaults overridden by the `ANIMED_MAX_*` environment variables.
    pub fn from_env() -> Result<Limits, String> {
        let mut l = Limits::default();
        for lim in Limit::ALL {
            if let Ok(s) = std::env::var(lim.env()) {
                l.set(
                    lim,
                    parse_amount(&s).map_err(|e| format!("{}: {e}", lim.env()))?,
                );
            }
        }
        Ok(l)
    }
}

/// A count with an optional K/M/G suffix (powers of 1024 for bytes are not
/// guessed: K = 1e3, Ki = 1024).
pub fn parse_amount(s: &str) -> Result<u64, String> {
    let t = s.trim();
    let (num, mul) = [
        ("Ki", 1u64 << 10),
        ("Mi", 1 << 20),
        ("Gi", 1 << 30),
        ("K", 1_000),
        ("M", 1_000_000),
        ("G", 1_000_000_000),
    ]
    .iter()
    .find_map(|(suf, m)| t.strip_suffix(suf).map(|n| (n, *m)))
    .unwrap_or((t, 1));
    let n: u64 = num
        .trim()
        .parse()
        .map_err(|_| format!("{s:?} is not a count (e.g. 5000000, 512Mi, 2G)"))?;
    n.checked_mul(mul)
        .filter(|&v| v > 0)
        .ok_or_else(|| format!("{s:?} is out of range (1 ..= 2^64-1)"))
}

static DEFAULTS: RwLock<Option<Limits>> = RwLock::new(None);

/// Sets the limits later loads start from (the CLI's `--max-…` flags).
pub fn set_defaults(l: Limits) {
    if let Ok(mut g) = DEFAULTS.write() {
        *g = Some(l);
    }
}

/// The limits a new load starts from: [`set_defaults`], else the
/// environment, else [`Limits::default`] (a bad variable is reported by
/// the CLI at start-up and ignored here).
pub fn defaults() -> Limits {
    if let Some(l) = DEFAULTS.read().ok().and_then(|g| g.clone()) {
        return l;
    }
    Limits::from_env().unwrap_or_default()
}

/// A limit passed: says which, by how much, and how to raise it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LimitError {
    pub limit: Limit,
    pub max: u64,
}

impl fmt::Display for LimitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "input budget exceeded: more than {} {} in one load (raise it with {} N or {}=N)",
            self.max,
            self.limit.what(),
            self.limit.flag(),
            self.limit.env()
        )
    }
}

impl std::error::Error for LimitError {}

/// What the running load has used so far.
#[derive(Debug)]
struct Budget {
    limits: Limits,
    bytes: u64,
    nodes: u64,
    geometry: u64,
    numbers: u64,
    /// Nesting depth already used by the files that include the one being
    /// read (Inline inside Inline…).
    depth_base: u64,
    /// The first limit passed: the load fails with it even where a reader
    /// would turn an error into a warning (a broken inline).
    tripped: Option<LimitError>,
}

thread_local! {
    static BUDGET: RefCell<Option<Budget>> = const { RefCell::new(None) };
}

/// Runs `f` as one load: opens a fresh budget with `limits` unless a load
/// is already running on this thread (then `f` shares its budget).
pub fn scope_with<T>(limits: Limits, f: impl FnOnce() -> T) -> T {
    let opened = BUDGET.with(|b| {
        let mut b = b.borrow_mut();
        if b.is_some() {
            return false;
        }
        *b = Some(Budget {
            limits,
            bytes: 0,
            nodes: 0,
            geometry: 0,
            numbers: 0,
            depth_base: 0,
            tripped: None,
        });
        true
    });
    struct Close(bool);
    impl Drop for Close {
        fn drop(&mut self) {
            if self.0 {
                BUDGET.with(|b| *b.borrow_mut() = None);
            }
        }
    }
    let _close = Close(opened);
    f()
}

/// [`scope_with`] the [`defaults`].
pub fn scope<T>(f: impl FnOnce() -> T) -> T {
    let running = BUDGET.with(|b| b.borrow().is_some());
    if running {
        f()
    } else {
        scope_with(defaults(), f)
    }
}

/// The limits of the running load (the defaults outside a load).
pub fn current() -> Limits {
    BUDGET
        .with(|b| b.borrow().as_ref().map(|b| b.limits.clone()))
        .unwrap_or_else(defaults)
}

fn charge(limit: Limit, n: u64) -> Result<(), LimitError> {
    BUDGET.with(|b| {
        let mut b = b.borrow_mut();
        let Some(b) = b.as_mut() else {
            return Ok(());
        };
        let max = b.limits.get(limit);
        let used = match limit {
            Limit::Bytes => &mut b.bytes,
            Limit::Nodes => &mut b.nodes,
            Limit::Geometry => &mut b.geometry,
            Limit::Numbers => &mut b.numbers,
            Limit::Depth => return Ok(()),
        };
        let total = used.saturating_add(n);
        if total > max {
            let e = LimitError { limit, max };
            b.tripped.get_or_insert(e.clone());
            return Err(e);
        }
        *used = total;
        Ok(())
    })
}

/// Counts `n` more bytes read (gzip output, a buffer decoded in memory).
pub fn charge_bytes(n: u64) -> Result<(), LimitError> {
    charge(Limit::Bytes, n)
}

/// Counts `n` more nodes.
pub fn charge_nodes(n: u64) -> Result<(), LimitError> {
    charge(Limit::Nodes, n)
}

/// Counts `n` more numbers (or strings) in field values.
pub fn charge_numbers(n: u64) -> Result<(), LimitError> {
    charge(Limit::Numbers, n)
}

/// Counts `n` more vertices + triangles (once per instance of a mesh).
pub fn charge_geometry(n: u64) -> Result<(), LimitError> {
    charge(Limit::Geometry, n)
}

/// Fails, without counting, if `n` more vertices + triangles would not fit:
/// generators (Extrusion, ElevationGrid) ask before they allocate.
pub fn check_geometry(n: u64) -> Result<(), LimitError> {
    check(Limit::Geometry, n)
}

fn check(limit: Limit, n: u64) -> Result<(), LimitError> {
    BUDGET.with(|b| {
        let mut b = b.borrow_mut();
        let Some(b) = b.as_mut() else {
            return Ok(());
        };
        let used = match limit {
            Limit::Bytes => b.bytes,
            Limit::Nodes => b.nodes,
            Limit::Geometry => b.geometry,
            Limit::Numbers => b.numbers,
            Limit::Depth => b.depth_base,
        };
        let max = b.limits.get(limit);
        if used.saturating_add(n) > max {
            let e = LimitError { limit, max };
            b.tripped.get_or_insert(e.clone());
            Err(e)
        } else {
            Ok(())
        }
    })
}

/// Records that `e` was passed (a reader that checks a limit itself, like
/// the parser's depth): the load fails with it.
pub fn trip(e: LimitError) -> LimitError {
    BUDGET.with(|b| {
        if let Some(b) = b.borrow_mut().as_mut() {
            b.tripped.get_or_insert(e.clone());
        }
    });
    e
}

/// The first limit the running load passed, if any.
pub fn tripped() -> Option<LimitError> {
    BUDGET.with(|b| b.borrow().as_ref().and_then(|b| b.tripped.clone()))
}

/// How many more levels of nesting the file being read may use (the
/// depth already used by the files including it is taken off).
pub fn depth_left() -> u64 {
    BUDGET.with(|b| match b.borrow().as_ref() {
        Some(b) => b.limits.max_depth.saturating_sub(b.depth_base),
        None => defaults().max_depth,
    })
}

/// Runs `f` (reading an included file) `levels` deeper: the included
/// file's own nesting counts on top of the includer's.
pub fn deeper<T>(levels: u64, f: impl FnOnce() -> T) -> T {
    let add = |d: i64| {
        BUDGET.with(|b| {
            if let Some(b) = b.borrow_mut().as_mut() {
                b.depth_base = (b.depth_base as i64 + d).max(0) as u64;
            }
        })
    };
    add(levels as i64);
    struct Back<F: Fn(i64)>(F, i64);
    impl<F: Fn(i64)> Drop for Back<F> {
        fn drop(&mut self) {
            (self.0)(-self.1)
        }
    }
    let _back = Back(add, levels as i64);
    f()
}

/// Why a file could not be read.
#[derive(Debug)]
pub enum ReadError {
    Io(std::io::Error),
    /// A device, FIFO, socket or directory.
    NotRegular(&'static str),
    Limit(LimitError),
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReadError::Io(e) => write!(f, "{e}"),
            ReadError::NotRegular(kind) => write!(
                f,
                "not a regular file ({kind}); animed reads scene files, textures and \
                 inlines only from regular files"
            ),
            ReadError::Limit(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for ReadError {}

impl From<LimitError> for ReadError {
    fn from(e: LimitError) -> Self {
        ReadError::Limit(e)
    }
}

/// What kind of non-regular file `m` is (`None` for a regular file);
/// reads and saves both refuse the others.
pub(crate) fn kind_of(m: &std::fs::Metadata) -> Option<&'static str> {
    let t = m.file_type();
    if t.is_file() {
        return None;
    }
    if t.is_dir() {
        return Some("a directory");
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return Some("a FIFO");
        }
        if t.is_socket() {
            return Some("a socket");
        }
        if t.is_char_device() || t.is_block_device() {
            return Some("a device");
        }
    }
    Some("not a file")
}

/// Reads a whole regular file within the running load's byte budget. The
/// check is made on the opened file (no race with a rename) and the read
/// is capped, so a file that grows while read still stops at the budget.
pub fn read_file(path: &Path) -> Result<Vec<u8>, ReadError> {
    let file = open_regular(path)?;
    let left = bytes_left();
    let size = file.metadata().map(|m| m.len()).unwrap_or(0);
    if size > left {
        return Err(bytes_error().into());
    }
    read_capped(file, size as usize)
}

/// Bytes the running load may still read (the default budget outside one).
fn bytes_left() -> u64 {
    BUDGET
        .with(|b| {
            b.borrow()
                .as_ref()
                .map(|b| b.limits.max_bytes.saturating_sub(b.bytes))
        })
        .unwrap_or_else(|| defaults().max_bytes)
}

fn bytes_error() -> LimitError {
    trip(LimitError {
        limit: Limit::Bytes,
        max: current().max_bytes,
    })
}

/// Reads `r` to its end, failing as soon as it passes the bytes left.
fn read_capped(r: impl Read, capacity: usize) -> Result<Vec<u8>, ReadError> {
    let left = bytes_left();
    let mut out = Vec::with_capacity(capacity.min(left as usize));
    r.take(left.saturating_add(1))
        .read_to_end(&mut out)
        .map_err(ReadError::Io)?;
    if out.len() as u64 > left {
        return Err(bytes_error().into());
    }
    charge_bytes(out.len() as u64)?;
    Ok(out)
}

/// Opens `path` for reading if it is a regular file (symlinks followed).
pub fn open_regular(path: &Path) -> Result<std::fs::File, ReadError> {
    // Look before opening: opening a FIFO for reading blocks until a writer
    // comes. Check the opened file again (it may have been swapped).
    let m = std::fs::metadata(path).map_err(ReadError::Io)?;
    if let Some(kind) = kind_of(&m) {
        return Err(ReadError::NotRegular(kind));
    }
    let file = open_nonblocking(path).map_err(ReadError::Io)?;
    let m = file.metadata().map_err(ReadError::Io)?;
    if let Some(kind) = kind_of(&m) {
        return Err(ReadError::NotRegular(kind));
    }
    Ok(file)
}

#[cfg(unix)]
fn open_nonblocking(path: &Path) -> std::io::Result<std::fs::File> {
    use std::os::unix::fs::OpenOptionsExt;
    // O_NONBLOCK: a FIFO swapped in between the two checks cannot block the
    // open; it is then refused by the second check. Regular files ignore it.
    const O_NONBLOCK: i32 = 0o4000;
    std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(O_NONBLOCK)
        .open(path)
}

#[cfg(not(unix))]
fn open_nonblocking(path: &Path) -> std::io::Result<std::fs::File> {
    std::fs::File::open(path)
}

/// Reads `r` to its end within the byte budget (stdin, a decoder's output).
pub fn read_all(r: impl Read) -> Result<Vec<u8>, ReadError> {
    read_capped(r, 0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn small() -> Limits {
        Limits {
            max_bytes: 100,
            max_nodes: 10,
            max_depth: 4,
            max_geometry: 50,
            max_numbers: 20,
        }
    }

    #[test]
    fn charges_add_up_within_one_scope_and_reset_after() {
        scope_with(small(), || {
            charge_nodes(6).unwrap();
            let e = charge_nodes(5).unwrap_err();
            assert_eq!(e.limit, Limit::Nodes);
            let m = e.to_string();
            assert!(m.contains("more than 10 nodes"), "{m}");
            assert!(
                m.contains("--max-nodes") && m.contains("ANIMED_MAX_NODES"),
                "{m}"
            );
            // A nested scope shares the budget.
            scope_with(Limits::default(), || assert!(charge_nodes(5).is_err()));
            assert!(check_geometry(51).is_err());
            assert!(check_geometry(50).is_ok());
        });
        scope_with(small(), || charge_nodes(10).unwrap());
    }

    #[test]
    fn depth_is_shared_by_included_files() {
        scope_with(small(), || {
            assert_eq!(depth_left(), 4);
            deeper(3, || {
                assert_eq!(depth_left(), 1);
                deeper(3, || assert_eq!(depth_left(), 0));
            });
            assert_eq!(depth_left(), 4);
        });
    }

    #[test]
    fn read_file_is_bounded_and_refuses_devices() {
        let dir = std::env::temp_dir().join(format!("animed-limits-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let f = dir.join("a.txt");
        std::fs::write(&f, [b'x'; 150]).unwrap();
        scope_with(small(), || {
            let e = read_file(&f).unwrap_err();
            assert!(matches!(e, ReadError::Limit(_)), "{e}");
        });
        scope_with(Limits::default(), || {
            assert_eq!(read_file(&f).unwrap().len(), 150)
        });
        let e = read_file(&dir).unwrap_err().to_string();
        assert!(e.contains("not a regular file (a directory)"), "{e}");
        #[cfg(unix)]
        {
            let e = read_file(Path::new("/dev/zero")).unwrap_err().to_string();
            assert!(e.contains("(a device)"), "{e}");
            let fifo = dir.join("fifo");
            let _ = std::fs::remove_file(&fifo);
            let ok = std::process::Command::new("mkfifo")
                .arg(&fifo)
                .status()
                .map(|s| s.success())
                .unwrap_or(false);
            assert!(ok, "mkfifo is needed for this test");
            let e = read_file(&fifo).unwrap_err().to_string();
            assert!(e.contains("(a FIFO)"), "{e}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn amounts_parse_with_suffixes() {
        assert_eq!(parse_amount("512Mi").unwrap(), 512 << 20);
        assert_eq!(parse_amount("2G").unwrap(), 2_000_000_000);
        assert_eq!(parse_amount(" 7 ").unwrap(), 7);
        assert!(parse_amount("0").is_err());
        assert!(parse_amount("lots").is_err());
        assert!(parse_amount("99999999999G").is_err());
    }
}
