//! Files written whole or not at all, and only over regular files.
//!
//! Every file the workbook writes (figures, GIFs, the `--events` CSV, the course text
//! refreshed by `render`) is first written to a temporary file in the same folder and
//! then renamed over the target. A rename within one folder is atomic on POSIX file
//! systems, so a reader, a second run or an interrupted run (Ctrl-C, SIGTERM, a full
//! disk) sees either the old file or the new one, never a half-written one. The
//! temporary names are hidden and end in `.tmp.<ext>` (`.gitignore` lists the pattern),
//! so a run killed between the write and the rename leaves no tracked change, and they
//! carry the writer's process id: the next run writing into that folder removes those
//! whose process is gone ([`clean_stale_temporaries`]).
//!
//! A path that is a symbolic link is written through to the link's final target (the
//! temporary beside the target, renamed over the target; the link stays a link). A path
//! that exists and is not a regular file (a folder, a FIFO, a device node, a socket) is
//! refused with a reason naming it ([`resolve`]), before any write and again just before
//! the rename: nothing is ever renamed over a device.

use std::collections::HashSet;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

static COUNTER: AtomicU64 = AtomicU64::new(0);

/// The marker of temporary names: `.<file name>.<pid>-<n>.tmp.<ext>`.
const TMP_MARK: &str = ".tmp.";

/// A fresh temporary path beside `path`: `.<file name>.<pid>-<n>.tmp.<ext>`, unique within
/// this process (the counter) and between processes (the pid). It keeps the target's
/// extension last, since some encoders choose the format by it (PNG).
pub fn temp_path(path: &Path) -> PathBuf {
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let name = path
        .file_name()
        .map_or_else(|| "file".into(), |s| s.to_string_lossy().into_owned());
    let ext = path
        .extension()
        .map_or_else(String::new, |e| e.to_string_lossy().into_owned());
    let tmp = format!(".{name}.{}-{n}{TMP_MARK}{ext}", std::process::id());
    path.with_file_name(tmp)
}

/// The process id in a temporary name of [`temp_path`]'s form, if it is one.
pub fn temp_owner(file_name: &str) -> Option<u32> {
    let rest = file_name.strip_prefix('.')?;
    let (stem, _ext) = rest.rsplit_once(TMP_MARK)?;
    let (_name, tag) = stem.rsplit_once('.')?;
    let (pid, n) = tag.split_once('-')?;
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    (digits(pid) && digits(n))
        .then(|| pid.parse().ok())
        .flatten()
}

/// Whether process `pid` is alive (`/proc/<pid>` exists); `None` where there is no
/// `/proc` to ask.
fn process_alive(pid: u32) -> Option<bool> {
    if !Path::new("/proc/self").exists() {
        return None;
    }
    Some(Path::new(&format!("/proc/{pid}")).exists())
}

/// Folders already cleaned by this process.
static CLEANED: Mutex<Option<HashSet<PathBuf>>> = Mutex::new(None);

/// Removes from `dir` the regular files named as [`temp_path`] names them whose process
/// is gone (a run killed between its write and its rename); once per folder and process.
/// Nothing else is touched, and nothing where liveness cannot be asked. Returns how many
/// were removed.
pub fn clean_stale_temporaries(dir: &Path) -> usize {
    let key = dir.to_path_buf();
    {
        let mut done = CLEANED.lock().unwrap_or_else(|e| e.into_inner());
        if !done.get_or_insert_with(HashSet::new).insert(key) {
            return 0;
        }
    }
    let Ok(entries) = std::fs::read_dir(dir) else {
        return 0;
    };
    let me = std::process::id();
    let mut removed = 0;
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(pid) = temp_owner(&name.to_string_lossy()) else {
            continue;
        };
        let regular = entry.file_type().is_ok_and(|t| t.is_file());
        if pid != me && regular && process_alive(pid) == Some(false) {
            removed += usize::from(std::fs::remove_file(entry.path()).is_ok());
        }
    }
    removed
}

/// The path a write to `path` lands on: `path` itself, or the final target of the
/// symbolic link(s) it names (a dangling link's target is created). An error names what
/// is in the way if that exists and is not a regular file.
pub fn resolve(path: &Path) -> std::io::Result<PathBuf> {
    use std::io::{Error, ErrorKind};
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        let meta = match std::fs::symlink_metadata(&p) {
            Err(e) if e.kind() == ErrorKind::NotFound => return Ok(p),
            Err(e) => return Err(e),
            Ok(m) => m,
        };
        let ft = meta.file_type();
        if ft.is_symlink() {
            let target = std::fs::read_link(&p)?;
            p = match p.parent() {
                Some(dir) if target.is_relative() => dir.join(target),
                _ => target,
            };
            continue;
        }
        if ft.is_file() {
            return Ok(p);
        }
        let through = if p == path {
            String::new()
        } else {
            format!(" (the target of the link, {})", p.display())
        };
        let why = format!("it is {}{through}, not a regular file", kind_of(&ft));
        return Err(Error::new(ErrorKind::InvalidInput, why));
    }
    Err(Error::new(
        ErrorKind::InvalidInput,
        "too many levels of symbolic links",
    ))
}

/// What a non-regular file is, in words.
fn kind_of(ft: &std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if ft.is_fifo() {
            return "a FIFO";
        }
        if ft.is_char_device() || ft.is_block_device() {
            return "a device node";
        }
        if ft.is_socket() {
            return "a socket";
        }
    }
    if ft.is_dir() {
        "a folder"
    } else {
        "not a regular file"
    }
}

/// Writes a file through `write_to(temporary path)`, then renames it over `path` (or over
/// the target of the symbolic link `path` is). On any error the temporary file is
/// removed and the target is left as it was. The error text names `path`.
pub fn with_temp_file<F>(path: &Path, write_to: F) -> Result<(), String>
where
    F: FnOnce(&Path) -> Result<(), String>,
{
    let fail = |e: String| format!("cannot write {}: {e}", path.display());
    let target = resolve(path).map_err(|e| fail(e.to_string()))?;
    if let Some(dir) = target.parent() {
        clean_stale_temporaries(if dir.as_os_str().is_empty() {
            Path::new(".")
        } else {
            dir
        });
    }
    let tmp = temp_path(&target);
    let result = write_to(&tmp)
        .and_then(|()| sync(&tmp))
        // checked again just before the rename: never over a device, a FIFO, a folder
        .and_then(|()| resolve(&target).map(drop).map_err(|e| e.to_string()))
        .and_then(|()| std::fs::rename(&tmp, &target).map_err(|e| e.to_string()));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result.map_err(fail)
}

/// Writes `bytes` to `path` atomically (see the module documentation).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), String> {
    with_temp_file(path, |tmp| {
        let mut f = std::fs::File::create(tmp).map_err(|e| e.to_string())?;
        f.write_all(bytes).map_err(|e| e.to_string())
    })
}

/// Flushes a written file to the disk, so that a full disk is reported here and not
/// lost on close.
fn sync(path: &Path) -> Result<(), String> {
    std::fs::File::open(path)
        .and_then(|f| f.sync_all())
        .map_err(|e| e.to_string())
}

/// Checks that a file can be created in folder `dir` (which must exist), with a probe
/// name unique to this process and call, so that concurrent runs sharing the folder
/// never remove each other's probe.
pub fn probe_folder(dir: &Path) -> std::io::Result<()> {
    let probe = temp_path(&dir.join("workbook-write-check"));
    std::fs::write(&probe, b"")?;
    std::fs::remove_file(&probe)
}

/// Checks before a run that the file `path` can be written later without touching it:
/// a new path or a regular file (through symbolic links), not read-only, and its folder
/// accepts new files. An existing file is left as it is until the run's output replaces
/// it whole.
pub fn probe_file(path: &Path) -> std::io::Result<()> {
    use std::io::{Error, ErrorKind};
    if path.as_os_str().is_empty() {
        return Err(Error::new(ErrorKind::InvalidInput, "empty path"));
    }
    let target = resolve(path)?;
    if let Ok(meta) = std::fs::metadata(&target) {
        if meta.permissions().readonly() {
            return Err(Error::new(
                ErrorKind::PermissionDenied,
                "the file is read-only",
            ));
        }
    }
    let dir = match target.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if !dir.is_dir() {
        return Err(Error::new(ErrorKind::NotFound, "its folder does not exist"));
    }
    probe_folder(dir)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_failed_write_leaves_the_old_file_and_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.csv");
        std::fs::write(&path, "old").unwrap();
        let e = with_temp_file(&path, |tmp| {
            std::fs::write(tmp, "half").unwrap();
            Err("disk full".into())
        })
        .unwrap_err();
        assert!(e.contains("a.csv") && e.contains("disk full"), "{e}");
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "old");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
        write_atomic(&path, b"new").unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "new");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn temporary_names_are_hidden_unique_and_keep_the_extension() {
        let p = Path::new("figures/x/speed-map.png");
        let (a, b) = (temp_path(p), temp_path(p));
        assert_ne!(a, b);
        let name = a.file_name().unwrap().to_string_lossy().into_owned();
        assert!(
            name.starts_with(".speed-map.png.") && name.ends_with(".tmp.png"),
            "{name}"
        );
        assert_eq!(a.parent(), p.parent());
    }

    #[test]
    fn probes_refuse_folders_and_missing_folders() {
        let dir = tempfile::tempdir().unwrap();
        assert!(probe_file(dir.path()).is_err());
        assert!(probe_file(&dir.path().join("no/such/x.csv")).is_err());
        assert!(probe_file(&dir.path().join("x.csv")).is_ok());
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
    }

    #[cfg(unix)]
    fn mkfifo(path: &Path) {
        let ok = std::process::Command::new("mkfifo")
            .arg(path)
            .status()
            .is_ok_and(|s| s.success());
        assert!(ok, "mkfifo {}", path.display());
    }

    #[cfg(unix)]
    #[test]
    fn non_regular_files_are_refused_and_left_alone() {
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join("events.csv");
        mkfifo(&fifo);
        let e = probe_file(&fifo).unwrap_err().to_string();
        assert!(
            e.contains("a FIFO") && e.contains("not a regular file"),
            "{e}"
        );
        let e = write_atomic(&fifo, b"x").unwrap_err();
        assert!(e.contains("events.csv") && e.contains("a FIFO"), "{e}");
        let link = dir.path().join("link.csv");
        std::os::unix::fs::symlink(&fifo, &link).unwrap();
        let e = write_atomic(&link, b"x").unwrap_err();
        assert!(
            e.contains("link.csv") && e.contains("the target of the link"),
            "{e}"
        );
        assert!(std::fs::symlink_metadata(&fifo)
            .unwrap()
            .file_type()
            .is_fifo());
        // a device node: refused by the check, which never writes
        let e = resolve(Path::new("/dev/null")).unwrap_err().to_string();
        assert!(e.contains("a device node"), "{e}");
        assert!(probe_file(Path::new("/dev/null")).is_err());
        assert!(probe_file(dir.path())
            .unwrap_err()
            .to_string()
            .contains("a folder"));
        // nothing but the FIFO and the link was left in the folder
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
    }

    #[cfg(unix)]
    use std::os::unix::fs::FileTypeExt;

    #[cfg(unix)]
    #[test]
    fn a_symbolic_link_is_written_through_to_its_target() {
        let dir = tempfile::tempdir().unwrap();
        let sub = dir.path().join("sub");
        std::fs::create_dir(&sub).unwrap();
        let target = sub.join("real.csv");
        std::fs::write(&target, "old").unwrap();
        let link = dir.path().join("link.csv");
        std::os::unix::fs::symlink("sub/real.csv", &link).unwrap();
        write_atomic(&link, b"new").unwrap();
        assert!(std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "new");
        // the temporary was beside the target and is gone
        assert_eq!(std::fs::read_dir(&sub).unwrap().count(), 1);
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
        // a dangling link: its target is created, the link stays
        let dangling = dir.path().join("dangling.csv");
        std::os::unix::fs::symlink("sub/new.csv", &dangling).unwrap();
        probe_file(&dangling).unwrap();
        write_atomic(&dangling, b"made").unwrap();
        assert_eq!(
            std::fs::read_to_string(sub.join("new.csv")).unwrap(),
            "made"
        );
        assert!(std::fs::symlink_metadata(&dangling)
            .unwrap()
            .file_type()
            .is_symlink());
        // a loop of links is refused
        let (a, b) = (dir.path().join("a"), dir.path().join("b"));
        std::os::unix::fs::symlink(&b, &a).unwrap();
        std::os::unix::fs::symlink(&a, &b).unwrap();
        assert!(write_atomic(&a, b"x").unwrap_err().contains("levels"));
    }

    #[test]
    fn temporary_names_give_their_owner() {
        let p = temp_path(Path::new("x/speed-map.png"));
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        assert_eq!(temp_owner(&name), Some(std::process::id()));
        assert_eq!(temp_owner(".a.csv.12-3.tmp.csv"), Some(12));
        assert_eq!(temp_owner(".file.7-0.tmp."), Some(7));
        for other in [
            "a.csv",
            ".a.csv.tmp.csv",
            ".a.csv.x-1.tmp.csv",
            "a.12-3.tmp.csv",
        ] {
            assert_eq!(temp_owner(other), None, "{other}");
        }
    }

    #[cfg(target_os = "linux")]
    #[test]
    fn a_killed_runs_temporaries_are_removed_by_the_next_write() {
        let dir = tempfile::tempdir().unwrap();
        // a process that is gone: a child that has exited and been reaped
        let mut child = std::process::Command::new("true").spawn().unwrap();
        let dead = child.id();
        child.wait().unwrap();
        let stale = dir.path().join(format!(".events.csv.{dead}-0.tmp.csv"));
        std::fs::write(&stale, "half").unwrap();
        // a live process's temporary (this one's parent: alive), and an unrelated file
        let parent = std::os::unix::process::parent_id();
        let live = dir.path().join(format!(".events.csv.{parent}-0.tmp.csv"));
        std::fs::write(&live, "writing").unwrap();
        let other = dir.path().join(".notes.1-0.tmp");
        std::fs::write(&other, "keep").unwrap();
        write_atomic(&dir.path().join("events.csv"), b"whole").unwrap();
        assert!(!stale.exists(), "the dead run's temporary is left");
        assert!(live.exists() && other.exists());
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 3);
    }
}
