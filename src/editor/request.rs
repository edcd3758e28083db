//! File work the editor asks for instead of doing it. The state machine
//! (`Editor::handle` and everything it routes to) never reads or writes a
//! file: it queues a [`Request`], the shell (`shell.rs`, run by the window
//! loop in `app` and by the headless script runner) performs it and hands
//! the outcome back through the editor's `*_done` methods — egui's
//! `Context::run(RawInput) -> FullOutput` returning its side effects is the
//! model. Tests can drive the editor with events alone and assert on the
//! requests it returns.

use crate::editor::views::Memo;
use crate::format::export::atomic::Stamp;
use crate::scene::{Image, MaterialId, Scene};
use std::path::PathBuf;

/// One piece of file work, with what the editor needs to continue.
#[derive(Clone, Debug, PartialEq)]
pub enum Request {
    /// Read a scene and show it in place of the current one.
    Open(PathBuf),
    /// Read a model and add its content as a new object.
    Import(PathBuf),
    /// Write the scene atomically to `path`, first checking that the file
    /// is still what `expect` saw (another program's save is never
    /// overwritten). Once written, continue with `then`.
    Save {
        path: PathBuf,
        expect: Option<Stamp>,
        then: Option<After>,
    },
    /// Write the recovery copy of unsaved work to `path`.
    Autosave { path: PathBuf, why: AutosaveWhy },
    /// Delete a recovery copy that is out of date (already gone is fine).
    Remove(PathBuf),
    /// Look for a recovery copy newer than the scene file `scene`.
    FindRecovery { scene: PathBuf },
    /// Read the recovery copy `copy` into the open scene (one undo step).
    Recover { copy: PathBuf },
    /// Read an untitled session's copy as new untitled work and take the
    /// copy over as this session's (renamed to `mine`).
    RecoverUntitled { copy: PathBuf, mine: PathBuf },
    /// Make the recovered `copy` this session's own copy `mine` (renamed;
    /// kept where it is if that fails).
    TakeOver { copy: PathBuf, mine: PathBuf },
    /// Read and decode the image file `path` as the new texture of
    /// `material` (the material panel's Load).
    ReadTexture { path: PathBuf, material: MaterialId },
    /// Read what the file browser asked for (a folder's listing, or what
    /// a typed path is), filtered for `purpose`.
    Look {
        ask: crate::editor::browser::Ask,
        purpose: crate::editor::browser::Purpose,
    },
    /// Read the view remembered for the scene `key` from `memory`.
    RecallView { memory: PathBuf, key: PathBuf },
    /// Remember the view (camera, timeline zoom, preview range) for the
    /// scene `key` in `memory`.
    RememberView {
        memory: PathBuf,
        key: PathBuf,
        memo: Memo,
    },
}

/// Why a recovery copy is written (the status line differs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AutosaveWhy {
    /// The autosave clock ran out.
    Clock,
    /// Asked for directly (`Editor::autosave_now`, the window closing).
    Now,
}

/// What to do once unsaved changes are dealt with (a save carries it:
/// the editor continues when the shell reports the file written).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum After {
    Quit,
    New,
    Open,
    /// The recovery question when opening a scene (see `recovery`).
    Recover,
    /// Delete the selected object (asked when Delete is pressed over the
    /// key strip with no key selected: the object is not what has focus).
    DeleteObject,
}

/// An image the shell read for a texture, or why it could not.
pub type ReadImage = Result<Image, String>;

/// A scene the shell read: the scene, its warning count, and the file's
/// stamp taken before reading (a later save checks nobody changed it).
pub type Read = Result<(Scene, usize, Option<Stamp>), String>;
