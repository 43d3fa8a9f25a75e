//! Reading a spec file: the functions first ([`crate::spec`]), then the
//! claims against them ([`crate::claims`]).

use crate::claims;
use crate::error::{Result, SpecError};
use crate::raw::RawSpec;
use crate::source::Source;
use crate::spec::{Spec, build};

impl Spec {
    /// Reads and validates the spec file at `path`.
    pub fn from_file(path: &std::path::Path) -> Result<Spec> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| SpecError::Io {
            file: file.clone(),
            reason: e.to_string(),
        })?;
        Spec::from_str_named(&text, &file)
    }

    /// Reads and validates spec text; `file` names it in errors.
    pub fn from_str_named(text: &str, file: &str) -> Result<Spec> {
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
