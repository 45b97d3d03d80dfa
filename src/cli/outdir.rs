//! Writing files safely: every file through a temporary file in the same
//! folder, renamed into place (an interrupted run leaves the old file or the
//! new one, never half of one, and the next run removes the temporary file
//! it left; a symlink at the target is replaced, not followed; a folder,
//! named pipe or device at the target is refused), and output folders that
//! are ours.
//!
//! An output folder (`suite --out`, `figures --out`, `bench --out`) is created
//! if missing; an existing one must be empty or carry the marker file
//! [`MARKER`] that fricosc writes into every folder it fills: a user's folder
//! with other files in it is refused, so that `--out proj` cannot replace
//! `proj/README.md`. Below the folder, no subfolder may be a symlink (it could
//! lead out of the folder); the folder itself is the one the user named.

use crate::error::{Error, Result};
use std::io::Write;
use std::path::{Path, PathBuf};

/// The marker file of a folder fricosc writes.
pub const MARKER: &str = ".fricosc-output";

/// Write `bytes` to `path` through a temporary file beside it, renamed into place.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let name = path.display().to_string();
    let werr = |e: std::io::Error| Error::write(&name, e);
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let file =
        path.file_name().ok_or_else(|| Error::Parse { context: name.clone(), reason: "not a file name".into() })?;
    match std::fs::symlink_metadata(path) {
        Ok(m) if !m.is_file() && !m.file_type().is_symlink() => {
            return Err(Error::parse(
                name.clone(),
                "exists and is not a regular file (a folder, named pipe or device is not replaced)",
            ))
        }
        _ => {}
    }
    clean_stale(&dir, &file.to_string_lossy());
    let mut options = std::fs::OpenOptions::new();
    options.write(true).create_new(true);
    for attempt in 0..16 {
        let tmp = dir.join(format!(".{}.fricosc-{}-{attempt}.tmp", file.to_string_lossy(), std::process::id()));
        let mut f = match options.open(&tmp) {
            Ok(f) => f,
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(werr(e)),
        };
        let written = f.write_all(bytes).and_then(|()| f.sync_all());
        drop(f);
        if let Err(e) = written.and_then(|()| std::fs::rename(&tmp, path)) {
            let _ = std::fs::remove_file(&tmp);
            return Err(werr(e));
        }
        return Ok(());
    }
    Err(werr(std::io::Error::new(std::io::ErrorKind::AlreadyExists, "no free temporary name")))
}

/// Remove what an earlier run that was killed left of its temporary files
/// for `file` in `dir` (`.{file}.fricosc-{pid}-{n}.tmp`, the process gone).
fn clean_stale(dir: &Path, file: &str) {
    let prefix = format!(".{file}.fricosc-");
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(rest) = name.to_str().and_then(|n| n.strip_prefix(&prefix)).and_then(|r| r.strip_suffix(".tmp"))
        else {
            continue;
        };
        let Some((Ok(pid), Ok(_))) = rest.split_once('-').map(|(p, n)| (p.parse::<u32>(), n.parse::<u32>())) else {
            continue;
        };
        if pid != std::process::id() && !alive(pid, &entry) && entry.file_type().is_ok_and(|t| t.is_file()) {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

/// Whether process `pid` may still be writing `entry`: it is running (where
/// `/proc` tells), or the file is less than a day old (where it does not).
fn alive(pid: u32, entry: &std::fs::DirEntry) -> bool {
    if Path::new("/proc/self").exists() {
        return Path::new("/proc").join(pid.to_string()).exists();
    }
    let age = entry.metadata().ok().and_then(|m| m.modified().ok()).and_then(|t| t.elapsed().ok());
    age.is_none_or(|a| a.as_secs() < 86_400)
}

/// An output folder of fricosc's (module docs).
pub struct OutDir {
    root: PathBuf,
    option: String,
}

impl OutDir {
    /// The folder `path` (named by `option`, for messages), created if missing;
    /// refused if it exists and is not a folder, or holds files without [`MARKER`].
    pub fn open(option: &str, path: &str) -> Result<OutDir> {
        let bad = |reason: String| Error::Parse { context: option.into(), reason };
        if path.trim().is_empty() {
            return Err(bad("the output folder is empty".into()));
        }
        let root = PathBuf::from(path);
        match std::fs::metadata(&root) {
            Ok(m) if !m.is_dir() => return Err(bad(format!("'{path}' exists and is not a folder"))),
            Ok(_) => {
                let mut entries = std::fs::read_dir(&root).map_err(|e| Error::read(path, e))?;
                let has_marker = root.join(MARKER).is_file();
                if !has_marker && entries.next().is_some() {
                    return Err(bad(format!(
                        "'{path}' is not empty and was not written by fricosc (it has no {MARKER} file): \
                         give a new or empty folder"
                    )));
                }
            }
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                std::fs::create_dir_all(&root).map_err(|e| Error::write(path, e))?;
            }
            Err(e) => return Err(Error::read(path, e)),
        }
        let out = OutDir { root, option: option.into() };
        out.write(MARKER, b"This folder was written by fricosc; fricosc may replace its files.\n")?;
        Ok(out)
    }

    /// The folder.
    pub fn path(&self) -> &Path {
        &self.root
    }

    /// Write `bytes` to `rel` (a relative path of plain names) in the folder,
    /// creating subfolders; a subfolder that is a symlink is refused.
    pub fn write(&self, rel: &str, bytes: &[u8]) -> Result<()> {
        let bad = |reason: String| Error::Parse { context: self.option.clone(), reason };
        let rel_path = Path::new(rel);
        if rel_path.components().any(|c| !matches!(c, std::path::Component::Normal(_))) {
            return Err(bad(format!("'{rel}' is not a plain relative path")));
        }
        let mut dir = self.root.clone();
        if let Some(parent) = rel_path.parent() {
            for c in parent.components() {
                dir.push(c);
                match std::fs::symlink_metadata(&dir) {
                    Ok(m) if m.file_type().is_symlink() => {
                        return Err(bad(format!(
                            "'{}' is a symlink: fricosc does not write through links",
                            dir.display()
                        )))
                    }
                    Ok(m) if m.is_dir() => {}
                    Ok(_) => return Err(bad(format!("'{}' exists and is not a folder", dir.display()))),
                    Err(_) => std::fs::create_dir(&dir).map_err(|e| Error::write(&dir.display().to_string(), e))?,
                }
            }
        }
        write_atomic(&self.root.join(rel_path), bytes)
    }
}
