//! Reading what users give — spec files, outlines, point files, standard
//! input — the same way everywhere: bounded in size (a file such as
//! `/dev/zero` or an endless pipe is an error after the limit, never an
//! allocation that grows until memory runs out), UTF-8 checked, and a
//! byte-order mark at the start dropped.
//!
//! [`read_text`] reads a whole (small) file; [`Lines`] reads one line at a
//! time with a bound on each line, so a long input streams in bounded
//! memory.

use std::fs::File;
use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};

/// The byte-order mark, dropped at the start of any input.
pub const BOM: char = '\u{feff}';

/// Largest file read whole (spec files, outlines): 8 MiB.
pub const MAX_TEXT_BYTES: u64 = 8 << 20;

/// Longest line of a line-by-line input (a number has at most 10,000
/// characters; the rest is room for spaces and a comment).
pub const MAX_LINE_BYTES: u64 = 20_000;

/// Where input comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Source {
    File(PathBuf),
    /// Standard input (`-` on the command line).
    Stdin,
}

impl Source {
    /// `-` is standard input, anything else a file.
    pub fn of(path: &Path) -> Source {
        if path.as_os_str() == "-" {
            Source::Stdin
        } else {
            Source::File(path.to_path_buf())
        }
    }

    /// The name in messages.
    pub fn name(&self) -> String {
        match self {
            Source::File(p) => p.display().to_string(),
            Source::Stdin => "standard input".into(),
        }
    }

    fn open(&self) -> Result<Box<dyn BufRead>, InputError> {
        Ok(match self {
            Source::Stdin => Box::new(BufReader::new(std::io::stdin())),
            Source::File(p) => {
                let file = File::open(p).map_err(|e| self.io(&e))?;
                if file.metadata().is_ok_and(|m| m.is_dir()) {
                    return Err(InputError::Io {
                        input: self.name(),
                        reason: "is a directory".into(),
                    });
                }
                Box::new(BufReader::new(file))
            }
        })
    }

    fn io(&self, e: &std::io::Error) -> InputError {
        InputError::Io {
            input: self.name(),
            reason: e.to_string(),
        }
    }
}

/// Why input could not be read.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum InputError {
    #[error("cannot read {input}: {reason}")]
    Io { input: String, reason: String },
    #[error("{input} is larger than {limit} bytes (the limit of an input read whole)")]
    TooLarge { input: String, limit: u64 },
    #[error("{input} line {line} is longer than {limit} bytes")]
    LineTooLong {
        input: String,
        line: usize,
        limit: u64,
    },
    #[error("{input} line {line} is not UTF-8 text")]
    NotUtf8 { input: String, line: usize },
}

impl InputError {
    /// What went wrong, without the name of the input.
    pub fn reason(&self) -> String {
        match self {
            InputError::Io { reason, .. } => reason.clone(),
            InputError::TooLarge { limit, .. } => {
                format!("larger than {limit} bytes (the limit of an input read whole)")
            }
            InputError::LineTooLong { line, limit, .. } => {
                format!("line {line} is longer than {limit} bytes")
            }
            InputError::NotUtf8 { line, .. } => format!("line {line} is not UTF-8 text"),
        }
    }
}

/// The whole text of `source`, at most `limit` bytes, without a leading
/// byte-order mark.
pub fn read_text(source: &Source, limit: u64) -> Result<String, InputError> {
    let mut bytes = Vec::new();
    source
        .open()?
        .take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| source.io(&e))?;
    if bytes.len() as u64 > limit {
        return Err(InputError::TooLarge {
            input: source.name(),
            limit,
        });
    }
    let text = String::from_utf8(bytes).map_err(|e| {
        let line = e.as_bytes()[..e.utf8_error().valid_up_to()]
            .iter()
            .filter(|b| **b == b'\n')
            .count()
            + 1;
        InputError::NotUtf8 {
            input: source.name(),
            line,
        }
    })?;
    Ok(match text.strip_prefix(BOM) {
        Some(rest) => rest.to_string(),
        None => text,
    })
}

/// The lines of an input, one at a time: `(line number, text)` without the
/// line break (and without a byte-order mark on the first line), each at
/// most [`MAX_LINE_BYTES`].
pub struct Lines {
    source: Source,
    reader: Box<dyn BufRead>,
    number: usize,
    done: bool,
}

impl std::fmt::Debug for Lines {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Lines")
            .field("source", &self.source)
            .field("number", &self.number)
            .finish_non_exhaustive()
    }
}

impl Lines {
    /// Opens `source` for reading line by line.
    pub fn open(source: &Source) -> Result<Lines, InputError> {
        Ok(Lines {
            reader: source.open()?,
            source: source.clone(),
            number: 0,
            done: false,
        })
    }
}

impl Iterator for Lines {
    type Item = Result<(usize, String), InputError>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.done {
            return None;
        }
        let mut bytes = Vec::new();
        let read = (&mut self.reader)
            .take(MAX_LINE_BYTES + 1)
            .read_until(b'\n', &mut bytes);
        self.number += 1;
        let fail = |e: InputError, done: &mut bool| {
            *done = true;
            Some(Err(e))
        };
        match read {
            Err(e) => return fail(self.source.io(&e), &mut self.done),
            Ok(0) => {
                self.done = true;
                return None;
            }
            Ok(_) => {}
        }
        if bytes.last() == Some(&b'\n') {
            bytes.pop();
            if bytes.last() == Some(&b'\r') {
                bytes.pop();
            }
        } else if bytes.len() as u64 > MAX_LINE_BYTES {
            let e = InputError::LineTooLong {
                input: self.source.name(),
                line: self.number,
                limit: MAX_LINE_BYTES,
            };
            return fail(e, &mut self.done);
        }
        match String::from_utf8(bytes) {
            Ok(text) => {
                let text = match (self.number, text.strip_prefix(BOM)) {
                    (1, Some(rest)) => rest.to_string(),
                    _ => text,
                };
                Some(Ok((self.number, text)))
            }
            Err(_) => {
                let e = InputError::NotUtf8 {
                    input: self.source.name(),
                    line: self.number,
                };
                fail(e, &mut self.done)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str, bytes: &[u8]) -> Source {
        let dir = std::env::temp_dir().join(format!("trig-core-input-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(name);
        std::fs::write(&path, bytes).unwrap();
        Source::File(path)
    }

    #[test]
    fn a_byte_order_mark_is_dropped_by_every_reader() {
        let src = scratch("bom.txt", "\u{feff}0.5\n1/3\r\n".as_bytes());
        assert_eq!(read_text(&src, 100).unwrap(), "0.5\n1/3\r\n");
        let lines: Vec<_> = Lines::open(&src).unwrap().map(Result::unwrap).collect();
        assert_eq!(lines, [(1, "0.5".to_string()), (2, "1/3".to_string())]);
    }

    #[test]
    fn inputs_are_bounded() {
        let zero = Source::File("/dev/zero".into());
        if Path::new("/dev/zero").exists() {
            assert!(matches!(
                read_text(&zero, 1000),
                Err(InputError::TooLarge { limit: 1000, .. })
            ));
            let mut lines = Lines::open(&zero).unwrap();
            assert!(matches!(
                lines.next(),
                Some(Err(InputError::LineTooLong { line: 1, .. }))
            ));
            assert!(lines.next().is_none());
        }
        let bad = scratch("latin1.txt", b"0.5\n\xe9\n");
        let mut lines = Lines::open(&bad).unwrap();
        assert!(lines.next().unwrap().is_ok());
        assert_eq!(
            lines.next().unwrap().unwrap_err().to_string(),
            format!("{} line 2 is not UTF-8 text", bad.name())
        );
        assert!(
            read_text(&bad, 100)
                .unwrap_err()
                .to_string()
                .contains("line 2")
        );
        let missing = Source::File("/nonexistent/points".into());
        assert!(
            read_text(&missing, 10)
                .unwrap_err()
                .to_string()
                .starts_with("cannot read /nonexistent/points")
        );
    }
}
