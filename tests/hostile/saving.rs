//! Faults on the way out: a full disk, a killed run's temporaries, the
//! file's identity (permissions, symlinks, devices, read-only), and two
//! editors of one file at once.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("animed-hostile-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn animed(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_animed"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run animed")
}

/// Runs animed with files limited to 2 blocks (`ulimit -f`) and SIGXFSZ
/// ignored, so every write past that fails with EFBIG like a full disk.
fn animed_disk_full(dir: &Path, args: &[&str]) -> Output {
    Command::new("sh")
        .arg("-c")
        .arg("ulimit -f 2 && trap '' XFSZ && exec \"$@\"")
        .arg("sh")
        .arg(env!("CARGO_BIN_EXE_animed"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run sh + animed")
}

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

fn err(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn a_full_disk_fails_loudly_and_keeps_the_old_file() {
    let dir = temp_dir("full");
    std::fs::write(dir.join("out.png"), b"OLD").unwrap();
    std::fs::write(dir.join("out.wrl"), b"OLD").unwrap();
    // One picture.
    let o = animed_disk_full(&dir, &["render", "--size", "160x120", "-o", "out.png"]);
    assert_ne!(o.status.code(), Some(0), "{}", err(&o));
    assert!(err(&o).contains("out.png"), "{}", err(&o));
    assert_eq!(std::fs::read(dir.join("out.png")).unwrap(), b"OLD");
    // A sequence stops at the failing frame and names it.
    let o = animed_disk_full(
        &dir,
        &[
            "render", "--size", "160x120", "--range", "0:0.1:4", "-o", "f_#.png",
        ],
    );
    assert_ne!(o.status.code(), Some(0));
    let e = err(&o);
    assert!(e.contains("frame 0") || e.contains("f_0.png"), "{e}");
    assert!(!e.contains("wrote 4 frames"), "{e}");
    // A GIF.
    std::fs::write(dir.join("a.gif"), b"OLD").unwrap();
    let o = animed_disk_full(
        &dir,
        &[
            "render", "--size", "160x120", "--range", "0:0.1:4", "-o", "a.gif",
        ],
    );
    assert_ne!(o.status.code(), Some(0), "{}", err(&o));
    assert_eq!(std::fs::read(dir.join("a.gif")).unwrap(), b"OLD");
    // A scene.
    let o = animed_disk_full(&dir, &["convert", "../../nonexistent", "out.wrl"]);
    assert_ne!(o.status.code(), Some(0));
    std::fs::write(dir.join("big.wrl"), animed_demo_text()).unwrap();
    let o = animed_disk_full(&dir, &["convert", "big.wrl", "out.wrl"]);
    assert_ne!(o.status.code(), Some(0), "{}", err(&o));
    assert_eq!(std::fs::read(dir.join("out.wrl")).unwrap(), b"OLD");
    // Nothing but what was there (no temporaries, no empty frames).
    let left: Vec<String> = names(&dir)
        .into_iter()
        .filter(|n| !matches!(n.as_str(), "out.png" | "out.wrl" | "a.gif" | "big.wrl"))
        .collect();
    assert!(left.is_empty(), "left behind: {left:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

fn animed_demo_text() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/demo.wrl")).unwrap()
}

#[test]
fn a_killed_runs_temporary_is_cleaned_by_the_next_save() {
    let dir = temp_dir("stale");
    let pid_max: u64 = std::fs::read_to_string("/proc/sys/kernel/pid_max")
        .ok()
        .and_then(|s| s.trim().parse().ok())
        .unwrap_or(4_194_304);
    // pid_max itself is never a live process id.
    let stale = format!(".out.png.animed-{pid_max}.tmp");
    std::fs::write(dir.join(&stale), b"half a frame").unwrap();
    let o = animed(&dir, &["render", "--size", "32x24", "-o", "out.png"]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    assert_eq!(names(&dir), vec!["out.png".to_string()]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[cfg(unix)]
#[test]
fn saving_keeps_the_files_identity() {
    use std::os::unix::fs::PermissionsExt;
    let dir = temp_dir("ident");
    let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
    std::fs::write(dir.join("s.wrl"), animed_demo_text()).unwrap();
    // Permissions kept.
    std::fs::set_permissions(dir.join("s.wrl"), std::fs::Permissions::from_mode(0o600)).unwrap();
    let o = animed(&dir, &["key", "settings", "s.wrl", "--fps", "30"]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    assert_eq!(mode(&dir.join("s.wrl")), 0o600);
    // A symlink is followed: the target changes, the link stays a link.
    std::os::unix::fs::symlink("s.wrl", dir.join("link.wrl")).unwrap();
    let o = animed(&dir, &["key", "settings", "link.wrl", "--fps", "25"]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    assert!(std::fs::symlink_metadata(dir.join("link.wrl"))
        .unwrap()
        .file_type()
        .is_symlink());
    let o = animed(&dir, &["info", "s.wrl"]);
    assert!(
        String::from_utf8_lossy(&o.stdout).contains("25"),
        "the target was written"
    );
    // Read-only: refused, unless --force.
    std::fs::set_permissions(dir.join("s.wrl"), std::fs::Permissions::from_mode(0o444)).unwrap();
    let before = std::fs::read(dir.join("s.wrl")).unwrap();
    let o = animed(&dir, &["convert", "s.wrl", "s.wrl"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        err(&o).contains("read-only") && err(&o).contains("--force"),
        "{}",
        err(&o)
    );
    assert_eq!(std::fs::read(dir.join("s.wrl")).unwrap(), before);
    let o = animed(&dir, &["convert", "--force", "s.wrl", "s.wrl"]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    assert_eq!(mode(&dir.join("s.wrl")), 0o444);
    // A device is never replaced, even through a symlink.
    std::os::unix::fs::symlink("/dev/null", dir.join("null.wrl")).unwrap();
    let o = animed(&dir, &["convert", "s.wrl", "null.wrl"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(err(&o).contains("a device"), "{}", err(&o));
    std::os::unix::fs::symlink("/dev/null", dir.join("null.png")).unwrap();
    let o = animed(&dir, &["render", "--size", "32x24", "-o", "null.png"]);
    assert_ne!(o.status.code(), Some(0));
    assert!(err(&o).contains("a device"), "{}", err(&o));
    assert!(!Path::new("/dev/null").metadata().unwrap().is_file());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn concurrent_key_edits_of_one_file_all_land() {
    let dir = temp_dir("lock");
    let o = animed(&dir, &["key", "new", "s.wrl", "--box", "B"]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    let n = 6;
    // All at once: without the lock each reads the same file and the last
    // rename wins, dropping the others' keys.
    let procs: Vec<_> = (1..=n)
        .map(|i| {
            Command::new(env!("CARGO_BIN_EXE_animed"))
                .args([
                    "key",
                    "set",
                    "s.wrl",
                    "--target",
                    "B.translation",
                    "--frame",
                ])
                .arg(format!("{}", 100 + i))
                .args(["--value", &format!("{i},1,0")])
                .current_dir(&dir)
                .spawn()
                .unwrap()
        })
        .collect();
    for mut p in procs {
        assert!(p.wait().unwrap().success());
    }
    let o = animed(&dir, &["key", "list", "s.wrl"]);
    let list = String::from_utf8_lossy(&o.stdout).into_owned();
    for i in 1..=n {
        assert!(
            list.contains(&format!("{}", 100 + i)),
            "key {} lost:\n{list}",
            100 + i
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_file_changed_since_it_was_read_is_not_overwritten() {
    use animed::internals::format::export::atomic::Stamp;
    let dir = temp_dir("stamp");
    let f = dir.join("s.wrl");
    std::fs::write(&f, b"one").unwrap();
    let stamp = Stamp::of(&f).unwrap();
    stamp.check(&f).unwrap();
    // Another writer replaces it (a new file, as every save does).
    animed::internals::format::save::write_atomic(&f, b"two").unwrap();
    let e = stamp.check(&f).unwrap_err().to_string();
    assert!(e.contains("changed since it was read"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_editor_does_not_overwrite_a_file_changed_since_it_was_opened() {
    let dir = temp_dir("edsave");
    let f = dir.join("s.wrl");
    std::fs::write(&f, animed_demo_text()).unwrap();
    let loaded = animed::internals::format::load(&f).unwrap();
    let mut ed = animed::internals::editor::Editor::new(loaded.scene, Some(f.clone()), 160, 120);
    // Saving onto the file it opened works, again and again.
    ed.save_to(&f).unwrap();
    ed.save_to(&f).unwrap();
    // `animed key` changes the file meanwhile.
    let o = animed(&dir, &["key", "settings", "s.wrl", "--fps", "30"]);
    assert_eq!(o.status.code(), Some(0), "{}", err(&o));
    let theirs = std::fs::read(&f).unwrap();
    let e = ed.save_to(&f).unwrap_err();
    assert!(e.contains("changed since it was read"), "{e}");
    assert_eq!(std::fs::read(&f).unwrap(), theirs, "their change is kept");
    std::fs::remove_dir_all(&dir).unwrap();
}
