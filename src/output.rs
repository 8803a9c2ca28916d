//! Files written whole or not at all.
//!
//! Every file the workbook writes (figures, GIFs, the `--events` CSV, the course text
//! refreshed by `render`) is first written to a temporary file in the same folder and
//! then renamed over the target. A rename within one folder is atomic on POSIX file
//! systems, so a reader, a second run or an interrupted run (Ctrl-C, SIGTERM, a full
//! disk) sees either the old file or the new one, never a half-written one. The
//! temporary names are hidden and end in `.tmp.<ext>` (`.gitignore` lists the pattern),
//! so a run killed between the write and the rename leaves no tracked change.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

static COUNTER: AtomicU64 = AtomicU64::new(0);

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
    let tmp = format!(".{name}.{}-{n}.tmp.{ext}", std::process::id());
    path.with_file_name(tmp)
}

/// Writes a file through `write_to(temporary path)`, then renames it to `path`. On any
/// error the temporary file is removed and `path` is left as it was. The error text
/// names `path`.
pub fn with_temp_file<F>(path: &Path, write_to: F) -> Result<(), String>
where
    F: FnOnce(&Path) -> Result<(), String>,
{
    let tmp = temp_path(path);
    let result = write_to(&tmp)
        .and_then(|()| sync(&tmp))
        .and_then(|()| std::fs::rename(&tmp, path).map_err(|e| e.to_string()));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result.map_err(|e| format!("cannot write {}: {e}", path.display()))
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
/// not a folder, not read-only, and its folder accepts new files. An existing file is
/// left as it is until the run's output replaces it whole.
pub fn probe_file(path: &Path) -> std::io::Result<()> {
    use std::io::{Error, ErrorKind};
    if path.as_os_str().is_empty() {
        return Err(Error::new(ErrorKind::InvalidInput, "empty path"));
    }
    if let Ok(meta) = std::fs::metadata(path) {
        if meta.is_dir() {
            return Err(Error::new(ErrorKind::InvalidInput, "it is a folder"));
        }
        if meta.permissions().readonly() {
            return Err(Error::new(
                ErrorKind::PermissionDenied,
                "the file is read-only",
            ));
        }
    }
    let dir = match path.parent() {
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
}
