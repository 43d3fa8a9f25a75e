//! Reading a spec file: the functions first ([`crate::spec`]), then the
//! claims against them ([`crate::claims`]).

use trig_core::input::{MAX_TEXT_BYTES, Source as Input, read_text};

use crate::claims;
use crate::error::{Result, SpecError};
use crate::raw::RawSpec;
use crate::source::Source;
use crate::spec::{Spec, build};

impl Spec {
    /// Reads and validates the spec file at `path`.
    pub fn from_file(path: &std::path::Path) -> Result<Spec> {
        let file = path.display().to_string();
        // bounded, a byte-order mark dropped: the same reader as every input
        let text = read_text(&Input::of(path), MAX_TEXT_BYTES).map_err(|e| SpecError::Io {
            file: file.clone(),
            reason: e.reason(),
        })?;
        Spec::from_str_named(&text, &file)
    }

    /// The basis of the spec file at `path` without its claims (a basis
    /// another file's claim compares with: its own claims are not read, so
    /// files that name each other are read once each).
    pub fn basis_from_file(path: &std::path::Path) -> Result<Spec> {
        let file = path.display().to_string();
        let text = read_text(&Input::of(path), MAX_TEXT_BYTES).map_err(|e| SpecError::Io {
            file: file.clone(),
            reason: e.reason(),
        })?;
        let text = text.strip_prefix(trig_core::input::BOM).unwrap_or(&text);
        let src = Source { file: &file, text };
        let raw: RawSpec = toml::from_str(text).map_err(|e| SpecError::Malformed {
            at: src.at(e.span().map_or(0, |s| s.start)),
            message: e.message().trim().replace('\n', "; "),
        })?;
        build(&src, &raw)
    }

    /// Reads and validates spec text; `file` names it in errors.
    pub fn from_str_named(text: &str, file: &str) -> Result<Spec> {
        let text = text.strip_prefix(trig_core::input::BOM).unwrap_or(text);
        let src = Source { file, text };
        let raw: RawSpec = toml::from_str(text).map_err(|e| SpecError::Malformed {
            at: src.at(e.span().map_or(0, |s| s.start)),
            message: e.message().trim().replace('\n', "; "),
        })?;
        let mut spec = build(&src, &raw)?;
        claims::attach(&src, &mut spec, &raw.claims)?;
        Ok(spec)
    }
}
