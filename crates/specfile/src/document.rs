//! A document file: the claims one source document prints, each as printed
//! with its source, each naming the basis it is about. The bases are spec
//! files referenced by path (relative to the document file), so one
//! document states claims about several bases and a basis is written once
//! (`examples/catalog/`). The layout is in `docs/spec.md`, "Document files".
//!
//! ```toml
//! [document]
//! id = "001"
//! heading = "Seed 001"
//! title = "PhD thesis, G² cubic trigonometric spline with shape parameter m"
//! location = "shared/seeds/001_cf6c2ede0355a863.txt"
//!
//! [bases]
//! cubic = "../../examples/catalog/thesis-cubic.toml"
//!
//! [[claims]]
//! id = "T6"
//! basis = "cubic"
//! source = "3.3.2 ii"
//! statement = "⟪Σ b_i(u; m) = 1⟫"
//! check = "unity"
//! ```

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use toml::Spanned;
use trig_core::input::{MAX_TEXT_BYTES, Source as Input, read_text};

use crate::check::{Check, ClaimFigure, SpecClaim};
use crate::claims::{claim, umbrellas_among};
use crate::error::{Result, SpecError};
use crate::raw::RawClaim;
use crate::source::Source;
use crate::spec::Spec;

/// A whole document file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDocument {
    document: Header,
    #[serde(default)]
    bases: BTreeMap<String, Spanned<String>>,
    #[serde(default)]
    claims: Vec<RawClaim>,
}

/// `[document]`: what the report says of the document.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Header {
    /// Short id (the report's summary table, `--seed`).
    pub id: String,
    /// The heading of the report's section (`Seed 001`).
    pub heading: String,
    pub title: String,
    /// Where the document is (as the report states it).
    pub location: String,
}

impl Header {
    /// The file name of [`Header::location`].
    pub fn file_name(&self) -> &str {
        self.location.rsplit('/').next().unwrap_or(&self.location)
    }
}

/// One claim of a document file.
#[derive(Debug, Clone)]
pub enum DocumentClaim {
    /// A claim of the spec language about the basis `basis` (an index of
    /// [`DocumentFile::bases`]).
    Stated { basis: usize, claim: Box<SpecClaim> },
    /// An umbrella over printed parts about several bases (`check = "all"`
    /// with `[[claims.parts]]`): it holds when every counted part holds,
    /// fails when one fails, otherwise it is not-checkable.
    Parts {
        id: String,
        source: String,
        statement: String,
        parts: Vec<Part>,
        /// Remarks shown after the parts' evidence.
        notes: Vec<String>,
        /// A figure supporting the verdict.
        figure: Option<ClaimFigure>,
    },
}

/// One part of a [`DocumentClaim::Parts`] umbrella: a claim of the spec
/// language about the basis `basis`, shown under its statement.
#[derive(Debug, Clone)]
pub struct Part {
    pub basis: usize,
    pub claim: SpecClaim,
    /// Shown for information (`shown = true`, "their maximal ranges"): its
    /// verdict is reported and never decides the umbrella.
    pub shown: bool,
}

impl DocumentClaim {
    pub fn id(&self) -> &str {
        match self {
            DocumentClaim::Stated { claim, .. } => &claim.id,
            DocumentClaim::Parts { id, .. } => id,
        }
    }

    pub fn source(&self) -> &str {
        match self {
            DocumentClaim::Stated { claim, .. } => &claim.source,
            DocumentClaim::Parts { source, .. } => source,
        }
    }

    pub fn statement(&self) -> &str {
        match self {
            DocumentClaim::Stated { claim, .. } => &claim.statement,
            DocumentClaim::Parts { statement, .. } => statement,
        }
    }

    /// The figure supporting the claim's verdict, if the file gives one.
    pub fn figure(&self) -> Option<&ClaimFigure> {
        match self {
            DocumentClaim::Stated { claim, .. } => claim.figure.as_ref(),
            DocumentClaim::Parts { figure, .. } => figure.as_ref(),
        }
    }
}

/// A document file, read: its header, its bases (each a spec file whose
/// `claims` are the document's claims about it) and its claims in order.
#[derive(Debug, Clone)]
pub struct DocumentFile {
    pub header: Header,
    /// The file's path as given.
    pub file: String,
    /// The bases by the names the file gives them, in the order of the names.
    pub bases: Vec<(String, Spec)>,
    pub claims: Vec<DocumentClaim>,
}

impl DocumentFile {
    /// Reads the document file at `path`, or `path/document.toml` when
    /// `path` is a folder.
    pub fn from_path(path: &Path) -> Result<DocumentFile> {
        let path = if path.is_dir() {
            path.join("document.toml")
        } else {
            path.to_path_buf()
        };
        let file = path.display().to_string();
        let text = read_text(&Input::of(&path), MAX_TEXT_BYTES).map_err(|e| SpecError::Io {
            file: file.clone(),
            reason: e.reason(),
        })?;
        let dir = path.parent().map_or_else(PathBuf::new, Path::to_path_buf);
        DocumentFile::from_str_in(&text, &file, &dir)
    }

    /// Reads document text; `file` names it in errors and the bases' paths
    /// are relative to `dir`.
    pub fn from_str_in(text: &str, file: &str, dir: &Path) -> Result<DocumentFile> {
        let text = text.strip_prefix(trig_core::input::BOM).unwrap_or(text);
        let src = Source { file, text };
        let raw: RawDocument = toml::from_str(text).map_err(|e| SpecError::Malformed {
            at: src.at(e.span().map_or(0, |s| s.start)),
            message: e.message().trim().replace('\n', "; "),
        })?;
        let mut bases = Vec::new();
        for (name, path) in &raw.bases {
            let mut spec = Spec::from_file(&dir.join(path.get_ref()))?;
            // the basis's own file may list claims: the document states its own
            spec.claims.clear();
            bases.push((name.clone(), spec));
        }
        let mut claims: Vec<DocumentClaim> = Vec::new();
        for c in &raw.claims {
            let c = &other_as_path(c, &raw.bases);
            let read = document_claim(&src, &mut bases, c)?;
            if claims.iter().any(|d| d.id() == read.id()) {
                return src.invalid(
                    c.id.span(),
                    "claims.id",
                    format!("`{}` is used twice", read.id()),
                );
            }
            claims.push(read);
        }
        umbrellas_of_document(&src, &claims)?;
        Ok(DocumentFile {
            header: raw.document,
            file: file.to_string(),
            bases,
            claims,
        })
    }
}

/// `other = "han"` (a same-basis claim, or part, naming a basis of the
/// file) read as that basis's spec file; any other `other` is a path.
fn other_as_path(c: &RawClaim, bases: &BTreeMap<String, Spanned<String>>) -> RawClaim {
    let mut c = c.clone();
    if let Some(other) = &c.other
        && let Some(path) = bases.get(other.get_ref().trim())
    {
        c.other = Some(Spanned::new(other.span(), path.get_ref().clone()));
    }
    if let Some(parts) = &mut c.parts {
        for p in parts.iter_mut() {
            *p = other_as_path(p, bases);
        }
    }
    c
}

/// One claim, read against the basis it names (the file's only basis when
/// it names none) and recorded among that basis's claims.
fn document_claim(
    src: &Source<'_>,
    bases: &mut [(String, Spec)],
    c: &RawClaim,
) -> Result<DocumentClaim> {
    if c.parts.is_some() {
        return umbrella_of_parts(src, bases, c);
    }
    let basis = basis_of(src, bases, c)?;
    let spec = &mut bases[basis].1;
    let claim = claim(src, spec, c)?;
    spec.claims.push(claim.clone());
    Ok(DocumentClaim::Stated {
        basis,
        claim: Box::new(claim),
    })
}

/// An umbrella over parts about several bases: each part read against the
/// basis it names, none of them a claim of the file (their ids are labels).
fn umbrella_of_parts(
    src: &Source<'_>,
    bases: &[(String, Spec)],
    c: &RawClaim,
) -> Result<DocumentClaim> {
    if c.check.get_ref().trim() != "all" {
        return src.invalid(
            c.check.span(),
            "claims.check",
            format!(
                "`{}`: `[[claims.parts]]` belong to `check = \"all\"`",
                c.check.get_ref()
            ),
        );
    }
    let stray = [
        ("basis", c.basis.is_some()),
        ("claims", c.claims.is_some()),
        ("shown", c.shown.is_some()),
        ("negated", c.negated.is_some()),
        ("at", c.at.is_some()),
        ("range", c.range.is_some()),
        ("ranges", c.ranges.is_some()),
        ("region", c.region.is_some()),
        ("knots", c.knots.is_some()),
    ];
    if let Some((field, _)) = stray.iter().find(|(_, given)| *given) {
        return src.invalid(
            c.id.span(),
            &format!("claims.{field}"),
            format!("`{field}` on an umbrella of parts: each part states its own basis and values"),
        );
    }
    if let Err(e) = trig_tex::marked::check(c.statement.get_ref()) {
        return src.invalid(
            c.statement.span(),
            "claims.statement",
            format!("math marks ⟪…⟫: {e}"),
        );
    }
    let raw = c.parts.as_deref().unwrap_or_default();
    if raw.is_empty() {
        return src.invalid(
            c.id.span(),
            "claims.parts",
            "an umbrella lists at least one part".into(),
        );
    }
    let mut parts = Vec::new();
    for p in raw {
        let basis = basis_of(src, bases, p)?;
        let shown = p.shown.unwrap_or(false);
        let unflagged = RawClaim {
            shown: None,
            ..p.clone()
        };
        let claim = claim(src, &bases[basis].1, &unflagged)?;
        if matches!(claim.check, crate::check::Check::All { .. }) {
            return src.invalid(
                p.check.span(),
                "claims.parts.check",
                "a part is one check of one basis, not an umbrella".into(),
            );
        }
        parts.push(Part {
            basis,
            claim,
            shown,
        });
    }
    Ok(DocumentClaim::Parts {
        id: c.id.get_ref().trim().to_string(),
        source: c.source.clone(),
        statement: c.statement.get_ref().clone(),
        parts,
        notes: c.notes.clone().unwrap_or_default(),
        figure: crate::fields::figure_field(src, c)?,
    })
}

/// The checks that use no basis: in a file with several bases their claims
/// need not name one.
pub const BASIS_FREE: &[&str] = &[
    "all",
    "not-printed",
    "table-arithmetic",
    "table-quotes",
    "table-compare",
    "table-count",
    "data-values",
];

/// The basis a claim names (the file's only basis when it names none, the
/// first for a check of [`BASIS_FREE`]).
fn basis_of(src: &Source<'_>, bases: &[(String, Spec)], c: &RawClaim) -> Result<usize> {
    Ok(match &c.basis {
        Some(name) => bases
            .iter()
            .position(|(n, _)| n == name.get_ref().trim())
            .ok_or_else(|| SpecError::Invalid {
                at: src.at(name.span().start),
                field: "claims.basis".into(),
                message: format!(
                    "`{}`: expected one of the file's bases ({})",
                    name.get_ref(),
                    names(bases)
                ),
            })?,
        None if bases.len() == 1 => 0,
        // a check about no basis (an umbrella, a reason, printed tables) is
        // read against the first: it uses none of it
        None if !bases.is_empty() && BASIS_FREE.contains(&c.check.get_ref().trim()) => 0,
        None if bases.is_empty() => {
            return src.invalid(
                c.id.span(),
                "claims.basis",
                format!(
                    "claim `{}` needs a basis, and the file has no `[bases]` (name = \"spec file\")",
                    c.id.get_ref()
                ),
            );
        }
        None => {
            return src.invalid(
                c.id.span(),
                "claims.basis",
                format!(
                    "claim `{}` names no basis: expected one of {}",
                    c.id.get_ref(),
                    names(bases)
                ),
            );
        }
    })
}

/// The umbrellas of a document file (`check = "all"`) list claims of the
/// file — about any of its bases — and none lists itself
/// through others.
fn umbrellas_of_document(src: &Source<'_>, claims: &[DocumentClaim]) -> Result<()> {
    let ids: Vec<&str> = claims.iter().map(DocumentClaim::id).collect();
    umbrellas_among(src, &ids, |id| match claims.iter().find(|c| c.id() == id) {
        Some(DocumentClaim::Stated { claim, .. }) => match &claim.check {
            Check::All { claims, .. } => Some(claims.clone()),
            _ => None,
        },
        _ => None,
    })
}

fn names(bases: &[(String, Spec)]) -> String {
    if bases.is_empty() {
        return "none".into();
    }
    bases
        .iter()
        .map(|(n, _)| format!("`{n}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The list of a folder of document files (`documents/audit.toml`): the
/// folders of its documents, in report order.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawList {
    documents: Vec<String>,
}

/// The file listing a folder's documents.
pub const LIST: &str = "audit.toml";

/// Reads the documents that `dir/audit.toml` lists, in its order.
pub fn read_set(dir: &Path) -> Result<Vec<DocumentFile>> {
    let path = dir.join(LIST);
    let file = path.display().to_string();
    let text = read_text(&Input::of(&path), MAX_TEXT_BYTES).map_err(|e| SpecError::Io {
        file: file.clone(),
        reason: e.reason(),
    })?;
    let src = Source {
        file: &file,
        text: &text,
    };
    let list: RawList = toml::from_str(&text).map_err(|e| SpecError::Malformed {
        at: src.at(e.span().map_or(0, |s| s.start)),
        message: e.message().trim().replace('\n', "; "),
    })?;
    list.documents
        .iter()
        .map(|d| DocumentFile::from_path(&dir.join(d)))
        .collect()
}

/// Whether `path` is a document file (or a folder holding one) rather than
/// a spec file: a folder, or TOML with a `[document]` table.
pub fn is_document(path: &Path) -> bool {
    if path.is_dir() {
        return true;
    }
    read_text(&Input::of(path), MAX_TEXT_BYTES)
        .ok()
        .and_then(|text| text.parse::<toml::Table>().ok())
        .is_some_and(|t| t.contains_key("document"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::Check;

    fn catalog() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/catalog")
    }

    const HEADER: &str = "[document]\nid = \"x\"\nheading = \"Paper x\"\ntitle = \"t\"\nlocation = \"papers/x.pdf\"\n";

    fn read(body: &str) -> Result<DocumentFile> {
        DocumentFile::from_str_in(&format!("{HEADER}{body}"), "x.toml", &catalog())
    }

    fn claim(id: &str, basis: Option<&str>, check: &str) -> String {
        let basis = basis.map_or(String::new(), |b| format!("basis = \"{b}\"\n"));
        format!(
            "[[claims]]\nid = \"{id}\"\nsource = \"(1)\"\nstatement = \"s\"\n{basis}check = \"{check}\"\n"
        )
    }

    #[test]
    fn claims_name_their_basis_and_keep_their_order() {
        let doc = read(&format!(
            "[bases]\ncubic = \"thesis-cubic.toml\"\nquadratic = \"thesis-quadratic.toml\"\n{}{}{}",
            claim("b", Some("quadratic"), "unity"),
            claim("a", Some("cubic"), "unity"),
            claim("c", Some("cubic"), "unity"),
        ))
        .unwrap();
        assert_eq!(doc.header.file_name(), "x.pdf");
        let ids: Vec<&str> = doc.claims.iter().map(DocumentClaim::id).collect();
        assert_eq!(ids, ["b", "a", "c"]);
        let DocumentClaim::Stated { basis, claim } = &doc.claims[0] else {
            panic!("a stated claim");
        };
        assert_eq!(doc.bases[*basis].1.id, "thesis-quadratic");
        assert_eq!(claim.check, Check::Unity);
        // each basis holds the document's claims about it, and only those
        let about_cubic: Vec<&str> = doc.bases[0]
            .1
            .claims
            .iter()
            .map(|c| c.id.as_str())
            .collect();
        assert_eq!(about_cubic, ["a", "c"]);
    }

    #[test]
    fn every_claim_is_decided_by_a_check() {
        // the Rust checkers of the five documents are gone: `built-in` is
        // no check
        let e = read(&format!(
            "[bases]\ncubic = \"thesis-cubic.toml\"\n{}",
            claim("a", None, "built-in")
        ))
        .unwrap_err();
        assert!(e.to_string().contains("built-in"), "{e}");
    }

    #[test]
    fn a_figure_is_read_relative_to_the_file_without_output() {
        let with = |file: &str, plot: &str| {
            read(&format!(
                "[bases]\ncubic = \"thesis-cubic.toml\"\n{}[claims.figure]\nfile = \"{file}\"\ncaption = \" c \"\nplot = \"{plot}\"\n",
                claim("a", None, "unity")
            ))
        };
        let doc = with("Cargo.toml", "basis --family f").unwrap();
        let figure = doc.claims[0].figure().expect("the figure");
        assert_eq!(figure.path, Path::new("Cargo.toml"));
        assert_eq!(
            (figure.caption.as_str(), figure.plot.as_str()),
            ("c", "basis --family f")
        );
        let e = with("Cargo.toml", "basis --output x.svg").unwrap_err();
        assert!(e.to_string().contains("without `--output`"), "{e}");
    }

    #[test]
    fn a_claim_must_name_one_of_several_bases() {
        let two = "[bases]\ncubic = \"thesis-cubic.toml\"\nquadratic = \"thesis-quadratic.toml\"\n";
        let e = read(&format!("{two}{}", claim("a", None, "unity"))).unwrap_err();
        assert!(
            e.to_string()
                .contains("names no basis: expected one of `cubic`, `quadratic`"),
            "{e}"
        );
        let reason = "reason = \"not in this copy\"\n";
        let doc = read(&format!("{two}{}{reason}", claim("a", None, "not-printed"))).unwrap();
        assert_eq!(doc.claims[0].id(), "a");
        let e = read(&format!("{two}{}", claim("a", Some("quartic"), "unity"))).unwrap_err();
        assert!(
            e.to_string()
                .contains("`quartic`: expected one of the file's bases"),
            "{e}"
        );
        let e = read(&claim("a", None, "unity")).unwrap_err();
        assert!(
            e.to_string()
                .contains("needs a basis, and the file has no `[bases]`"),
            "{e}"
        );
    }

    #[test]
    fn ids_are_unique_across_bases_and_a_missing_basis_file_is_named() {
        let e = read(&format!(
            "[bases]\ncubic = \"thesis-cubic.toml\"\n{}{}",
            claim("a", None, "unity"),
            claim("a", None, "unity")
        ))
        .unwrap_err();
        assert!(e.to_string().contains("`a` is used twice"), "{e}");
        let e = read("[bases]\ncubic = \"no-such-basis.toml\"\n").unwrap_err();
        assert!(matches!(e, SpecError::Io { .. }), "{e}");
    }

    #[test]
    fn a_spec_file_refuses_basis() {
        let text = std::fs::read_to_string(catalog().join("bernstein3.toml")).unwrap();
        let e = Spec::from_str_named(
            &format!("{text}\n{}", claim("a", Some("b"), "unity")),
            "b.toml",
        )
        .unwrap_err();
        assert!(
            e.to_string().contains("a spec file states one basis"),
            "{e}"
        );
    }

    fn part(id: &str, basis: &str, check: &str, extra: &str) -> String {
        format!(
            "[[claims.parts]]\nid = \"{id}\"\nsource = \"(1)\"\nstatement = \"{id} as printed\"\nbasis = \"{basis}\"\ncheck = \"{check}\"\n{extra}"
        )
    }

    #[test]
    fn an_umbrella_of_parts_reads_each_part_against_its_own_basis() {
        let bases = "[bases]\ncubic = \"thesis-cubic.toml\"\nhan = \"han.toml\"\n";
        let doc = read(&format!(
            "{bases}{}{}{}",
            claim("u", None, "all"),
            part("p", "han", "unity", ""),
            part(
                "q",
                "cubic",
                "nonnegative",
                "maximal = true\nshown = true\n"
            ),
        ))
        .unwrap();
        let DocumentClaim::Parts { id, parts, .. } = &doc.claims[0] else {
            panic!("an umbrella of parts");
        };
        assert_eq!(id, "u");
        let labels: Vec<(&str, &str, bool)> = parts
            .iter()
            .map(|p| {
                (
                    doc.bases[p.basis].0.as_str(),
                    p.claim.statement.as_str(),
                    p.shown,
                )
            })
            .collect();
        assert_eq!(
            labels,
            [
                ("han", "p as printed", false),
                ("cubic", "q as printed", true)
            ]
        );
        // the parts are not claims of their bases (no umbrella lists them)
        assert!(doc.bases.iter().all(|(_, spec)| spec.claims.is_empty()));
        // parts belong to `all`, and a part is one check
        let e = read(&format!(
            "{bases}{}{}",
            claim("u", None, "unity"),
            part("p", "han", "unity", "")
        ))
        .unwrap_err();
        assert!(e.to_string().contains("belong to `check = \"all\"`"), "{e}");
        let e = read(&format!(
            "{bases}{}{}",
            claim("u", None, "all"),
            part("p", "han", "all", "claims = [\"x\"]\n")
        ))
        .unwrap_err();
        assert!(e.to_string().contains("not an umbrella"), "{e}");
        let e = read(&format!(
            "{bases}{}{}",
            claim("u", Some("han"), "all"),
            part("p", "han", "unity", "")
        ))
        .unwrap_err();
        assert!(
            e.to_string().contains("each part states its own basis"),
            "{e}"
        );
        // `shown` outside the parts of an umbrella is refused
        let e = read(&format!(
            "{bases}{}shown = true\n",
            claim("u", Some("han"), "unity")
        ))
        .unwrap_err();
        assert!(
            e.to_string()
                .contains("belong to a document file's umbrella"),
            "{e}"
        );
    }

    #[test]
    fn an_interpolant_claim_reads_its_table_file_beside_the_document() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../documents/thesis");
        let file = dir.join("x.toml").display().to_string();
        let read = |fields: &str, check: &str| {
            DocumentFile::from_str_in(
                &format!(
                    "{HEADER}[bases]\ncubic = \"../../examples/catalog/thesis-cubic.toml\"\n[[claims]]\nid = \"a\"\nsource = \"(1)\"\nstatement = \"s\"\ncheck = \"{check}\"\n{fields}"
                ),
                &file,
                &dir,
            )
        };
        let scheme_of = |doc: DocumentFile| match &doc.claims[0] {
            DocumentClaim::Stated { claim, .. } => match &claim.check {
                Check::InterpolantNonnegative { data, scheme, path } => {
                    assert_eq!(path, "table-4.6.tsv");
                    assert_eq!(data.f[1], rug::Rational::from((1, 10)));
                    *scheme
                }
                other => panic!("{other:?}"),
            },
            _ => panic!("a stated claim"),
        };
        let check = "interpolant-nonnegative";
        let doc = read("data = \"table-4.6.tsv\"\n", check).unwrap();
        assert_eq!(
            scheme_of(doc),
            trig_interp::Scheme::G1,
            "the table's own scheme"
        );
        let doc = read("data = \"table-4.6.tsv\"\nscheme = \"c2\"\n", check).unwrap();
        assert_eq!(scheme_of(doc), trig_interp::Scheme::C2);
        let e = |fields: &str, check: &str| read(fields, check).unwrap_err().to_string();
        assert!(e("data = \"no-such.tsv\"\n", check).contains("no-such.tsv"));
        assert!(
            e("data = \"table-4.6.tsv\"\nscheme = \"c3\"\n", check).contains("unknown scheme `c3`")
        );
        assert!(e("", check).contains("needs the field `data`"));
        assert!(e("data = \"document.toml\"\n", check).contains("expected `FIELD: value`"));
        assert!(
            e("data = \"table-4.6.tsv\"\n", "unity")
                .contains("`data` belongs to `check = \"interpolant-nonnegative`")
        );
        assert!(
            e("at = { m = \"0\" }\ndata = \"table-4.6.tsv\"\n", check).contains("fixes no values")
        );
        // the knot continuity of the same interpolant: the table, the scheme and the order
        let doc = read(
            "data = \"table-4.2.tsv\"\norder = 2\n",
            "interpolant-continuity",
        )
        .unwrap();
        match &doc.claims[0] {
            DocumentClaim::Stated { claim, .. } => match &claim.check {
                Check::InterpolantContinuity {
                    scheme,
                    order,
                    path,
                    ..
                } => {
                    assert_eq!(path, "table-4.2.tsv");
                    assert_eq!((*scheme, *order), (trig_interp::Scheme::C2, 2));
                }
                other => panic!("{other:?}"),
            },
            _ => panic!("a stated claim"),
        }
        assert!(
            e("data = \"table-4.2.tsv\"\n", "interpolant-continuity")
                .contains("needs the field `order`")
        );
    }

    #[test]
    fn a_document_is_told_apart_from_a_spec_file() {
        assert!(is_document(&catalog()));
        assert!(!is_document(&catalog().join("bernstein3.toml")));
    }

    #[test]
    fn an_umbrella_lists_claims_of_the_file_and_not_itself() {
        let bases = "[bases]\ncubic = \"thesis-cubic.toml\"\n";
        let umbrella = |id: &str, parts: &str| {
            format!(
                "[[claims]]\nid = \"{id}\"\nsource = \"(1)\"\nstatement = \"s\"\ncheck = \"all\"\nclaims = [{parts}]\n"
            )
        };
        // a claim of the file may be a part
        let doc = read(&format!(
            "{bases}{}{}",
            claim("a", None, "unity"),
            umbrella("u", "\"a\"")
        ));
        assert!(doc.is_ok(), "{doc:?}");
        let e = read(&format!("{bases}{}", umbrella("u", "\"b\""))).unwrap_err();
        assert!(
            e.to_string()
                .contains("lists `b`, which is not a claim of the file"),
            "{e}"
        );
        let e = read(&format!(
            "{bases}{}{}",
            umbrella("u", "\"v\""),
            umbrella("v", "\"u\"")
        ))
        .unwrap_err();
        assert!(e.to_string().contains("lists itself"), "{e}");
    }
}
