//! Files the commands write: atomically (a temporary file in the target's
//! directory, renamed over it by `tempfile`'s persist; an interrupted run
//! leaves the old file or none, and the temporary file is removed when
//! dropped), with the `wrote …` note on standard error so that standard
//! output carries only results.

use std::io::Write;
use std::path::Path;

use super::commands::CliError;

/// Writes `bytes` to `path` atomically (a regular file; a device or pipe
/// is written in place).
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    // the kind only: tempfile's errors name the temporary file, not the target
    let fail = |e: std::io::Error| {
        CliError::Usage(format!(
            "cannot write {}: {}",
            path.display(),
            std::io::Error::from(e.kind())
        ))
    };
    // a device, pipe or socket is written in place: renaming over it would
    // replace it (`--output /dev/full` must fail as the device fails, not
    // turn /dev/full into a regular file)
    if std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir()) {
        return std::fs::OpenOptions::new()
            .write(true)
            .open(path)
            .and_then(|mut f| f.write_all(bytes).and_then(|()| f.flush()))
            .map_err(fail);
    }
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let mut file = tempfile::Builder::new()
        .prefix(".trig-audit-")
        .tempfile_in(dir)
        .map_err(fail)?;
    file.write_all(bytes).map_err(fail)?;
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

/// Notes a written file on standard error: `wrote PATH (WHAT)`.
pub fn wrote(path: &Path, what: &str) {
    eprintln!("wrote {} ({what})", path.display());
}
