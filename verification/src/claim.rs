//! Claims as data: id, source, the statement as printed, and the checker
//! that decides it. A claim never carries its verdict.

use std::sync::OnceLock;

use trig_verdict::{Evidence, Status, Verdict};

/// The five source documents.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Seed {
    S000,
    S001,
    S002,
    S003,
    S004,
}

impl Seed {
    /// Every seed, in report order (the thesis first, as in `claims.md`).
    pub const ALL: [Seed; 5] = [Seed::S001, Seed::S000, Seed::S002, Seed::S003, Seed::S004];

    /// Short id used on the command line (`--seed 001`).
    pub fn id(&self) -> &'static str {
        match self {
            Seed::S000 => "000",
            Seed::S001 => "001",
            Seed::S002 => "002",
            Seed::S003 => "003",
            Seed::S004 => "004",
        }
    }

    /// File name in `shared/seeds/`.
    pub fn file(&self) -> &'static str {
        match self {
            Seed::S000 => "000_7005c3bc62610462.txt",
            Seed::S001 => "001_cf6c2ede0355a863.txt",
            Seed::S002 => "002_a40e75c8fd798756.txt",
            Seed::S003 => "003_eb2d8fda42cf564b.txt",
            Seed::S004 => "004_338937ef11bf75e2.txt",
        }
    }

    /// The document.
    pub fn title(&self) -> &'static str {
        match self {
            Seed::S000 => "Majeed et al. 2020, cubic trigonometric B-spline with shape parameter ζ",
            Seed::S001 => "PhD thesis, G² cubic trigonometric spline with shape parameter m",
            Seed::S002 => "Dube & Mishra 2017, rational quartic trigonometric Bézier curves",
            Seed::S003 => {
                "C³ trigonometric B-spline with shape parameter α (formulas missing in our copy)"
            }
            Seed::S004 => "Dube & Mishra 2016, EH B-spline with two shape parameters",
        }
    }
}

/// One published claim.
#[derive(Debug, Clone, Copy)]
pub struct Claim {
    /// Stable id from `shared/claims.md` (`T4`, `T4b`, …).
    pub id: &'static str,
    pub seed: Seed,
    /// Equation or section.
    pub source: &'static str,
    /// The statement as printed (short quotation), or for a `…b` claim the
    /// one obvious reading, labelled as such; its formulas marked `⟪…⟫`
    /// (`trig_tex::marked`), so that the LaTeX report sets them in math
    /// and the other reports show the text as printed (`trig_tex::plain`).
    pub statement: &'static str,
    /// The checker.
    pub check: fn() -> Verdict,
}

/// The verdict of `check`, computed once per process and kept in `cell`:
/// for a claim that is also quoted by an umbrella claim (T26 quotes
/// T26a–k, M8 quotes M4b), so the audit decides it once. Claims run in
/// parallel; a second caller waits for the first computation.
pub(crate) fn shared(cell: &'static OnceLock<Verdict>, check: impl FnOnce() -> Verdict) -> Verdict {
    cell.get_or_init(check).clone()
}

/// How an umbrella claim is decided, as the report states it.
const UMBRELLA: &str =
    "umbrella: holds only if every part holds (each part is reported as its own claim)";

/// An umbrella claim over separately reported claims (T24 over T24a–f):
/// a conjunction whose evidence is one line per part with its verdict,
/// and, for each part that does not hold, its first witness.
pub(crate) fn umbrella(parts: Vec<(String, Verdict)>) -> Verdict {
    let status = Status::conjunction(parts.iter().map(|(_, v)| v.status));
    let mut evidence = Vec::new();
    for (name, v) in parts {
        let mut line = Evidence::note(format!("reported as claim {name}"));
        line.subject = Some(name.clone());
        line.status = Some(v.status);
        evidence.push(line);
        if v.status != Status::Holds
            && let Some(w) = v
                .evidence
                .into_vec()
                .into_iter()
                .find(|e| e.witness.is_some())
        {
            evidence.push(w.in_part(name, v.status));
        }
    }
    Verdict::new(status, UMBRELLA, evidence)
}
