//! Files the commands write: atomically (a temporary file in the target's
//! directory, renamed over it by `tempfile`'s persist; an interrupted run
//! leaves the old file or none, and the temporary file is removed when
//! dropped), with the `wrote …` note on standard error so that standard
//! output carries only results.
//!
//! A temporary file is named `.trig-audit-PID-XXXXXX` after the process
//! that writes it; one left by a killed process (`SIGKILL` leaves no time
//! to remove it) is removed by the next write into the same directory, so
//! they never accumulate. A symbolic link is written through (its target
//! is replaced, never the link); a device, pipe or socket is written in
//! place; `-` is not a file name here (the commands that can print to
//! standard output do so without `--output`).
//!
//! Every command that prints takes `--output FILE` ([`OutputArg`]; `audit`
//! has its own, which also places the report's figures): the text goes to
//! the file, written atomically, instead of standard output.

use std::io::Write;
use std::path::{Path, PathBuf};

use super::commands::CliError;

/// `--output FILE` of a command that prints its result.
#[derive(Debug, Clone, Default, clap::Args)]
pub struct OutputArg {
    /// Write the output to this file (atomically: the old file or the whole
    /// new one, never a part) instead of standard output (`-`: standard output).
    #[arg(long, value_name = "FILE")]
    output: Option<PathBuf>,
}

impl OutputArg {
    /// The file to write, if any (`-` is standard output).
    pub fn path(&self) -> Option<&Path> {
        self.output.as_deref().filter(|p| p.as_os_str() != "-")
    }
}

/// The prefix of this program's temporary files.
const PREFIX: &str = ".trig-audit-";

/// Writes `bytes` to `path` atomically (a regular file; a device or pipe
/// is written in place, a symbolic link written through).
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    write_atomically_with(path, &mut |w| w.write_all(bytes).map_err(CliError::Write))
}

/// Writes what `write` produces to `path` atomically, as it is produced
/// (`eval --at-file` row by row, in bounded memory): the file appears whole
/// when `write` succeeds, and not at all when it fails.
pub fn write_atomically_with(
    path: &Path,
    write: &mut dyn FnMut(&mut dyn Write) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let path = &resolve(path)?;
    let fail = |e: std::io::Error| cannot_write(path, e.kind());
    // a write error of the file is the file's, not standard output's
    let written = |r: Result<(), CliError>| match r {
        Err(CliError::Write(e)) => Err(fail(e)),
        other => other,
    };
    // a device, pipe or socket is written in place: renaming over it would
    // replace it (`--output /dev/full` must fail as the device fails, not
    // turn /dev/full into a regular file)
    if is_special(path) {
        let mut f = std::fs::OpenOptions::new()
            .write(true)
            .open(path)
            .map_err(fail)?;
        written(write(&mut f))?;
        return f.flush().map_err(fail);
    }
    let dir = directory_of(path);
    remove_stale_temporaries(dir);
    let mut file = tempfile::Builder::new()
        .prefix(&format!("{PREFIX}{}-", std::process::id()))
        .tempfile_in(dir)
        .map_err(fail)?;
    {
        let mut buffered = std::io::BufWriter::new(file.as_file_mut());
        written(write(&mut buffered))?;
        buffered.flush().map_err(fail)?;
    }
    // the temporary file is private (0600): give the result the mode of the
    // file it replaces, or the usual 0644
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(path).map_or(0o644, |m| m.permissions().mode() & 0o7777);
        file.as_file()
            .set_permissions(std::fs::Permissions::from_mode(mode))
            .map_err(fail)?;
    }
    file.as_file().sync_all().map_err(fail)?;
    file.persist(path).map_err(|e| fail(e.error))?;
    Ok(())
}

/// True for a device, pipe or socket: written in place, never replaced.
fn is_special(path: &Path) -> bool {
    std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir())
}

/// The directory a file `path` is written in (`.` for a bare name).
fn directory_of(path: &Path) -> &Path {
    path.parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
}

/// The error of a write to `path` that failed with `kind` (the kind only:
/// tempfile's errors name the temporary file, not the target).
fn cannot_write(path: &Path, kind: std::io::ErrorKind) -> CliError {
    use std::io::ErrorKind;
    let why = match kind {
        ErrorKind::NotFound => "its directory does not exist".to_string(),
        ErrorKind::NotADirectory => "a part of its path is not a directory".to_string(),
        ErrorKind::IsADirectory => "it is a directory (give a file name)".to_string(),
        ErrorKind::PermissionDenied => "permission denied".to_string(),
        other => std::io::Error::from(other).to_string(),
    };
    CliError::Usage(format!("cannot write {}: {why}", path.display()))
}

/// Fails before any work when `path` cannot be written because its
/// directory is missing or is not a directory, with the error the write
/// would give (a long audit should not run first). Everything else is left
/// to [`write_atomically`].
pub fn check_directory(path: &Path) -> Result<(), CliError> {
    let path = &resolve(path)?;
    if is_special(path) {
        return Ok(());
    }
    if std::fs::metadata(path).is_ok_and(|m| m.is_dir()) {
        return Err(cannot_write(path, std::io::ErrorKind::IsADirectory));
    }
    match std::fs::metadata(directory_of(path)) {
        Ok(m) if m.is_dir() => Ok(()),
        Ok(_) => Err(cannot_write(path, std::io::ErrorKind::NotADirectory)),
        Err(e) => Err(cannot_write(path, e.kind())),
    }
}

/// The file `path` names: `-` refused, a symbolic link followed to its
/// target (which must exist: a dangling link or a loop is refused).
pub fn resolve(path: &Path) -> Result<PathBuf, CliError> {
    if path.as_os_str() == "-" {
        return Err(CliError::Usage(
            "--output -: standard output is not a file here (this command writes files only)"
                .into(),
        ));
    }
    match std::fs::symlink_metadata(path) {
        Ok(m) if m.file_type().is_symlink() => std::fs::canonicalize(path).map_err(|e| {
            CliError::Usage(format!(
                "cannot write {}: a symbolic link whose target cannot be reached ({}); it is never replaced",
                path.display(),
                std::io::Error::from(e.kind())
            ))
        }),
        _ => Ok(path.to_path_buf()),
    }
}

/// Removes the temporary files of processes that no longer run
/// (`.trig-audit-PID-…` with no `/proc/PID`) from `dir`; nothing where
/// `/proc` is not there to tell.
fn remove_stale_temporaries(dir: &Path) {
    if !Path::new("/proc/self").exists() {
        return;
    }
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(pid) = name
            .to_str()
            .and_then(|n| n.strip_prefix(PREFIX))
            .and_then(|rest| rest.split_once('-'))
            .and_then(|(pid, _)| pid.parse::<u32>().ok())
        else {
            continue;
        };
        let gone = !Path::new(&format!("/proc/{pid}")).exists();
        if gone && entry.file_type().is_ok_and(|t| t.is_file()) {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

/// Notes a written file on standard error: `wrote PATH (WHAT)`.
pub fn wrote(path: &Path, what: &str) {
    eprintln!("wrote {} ({what})", path.display());
}
