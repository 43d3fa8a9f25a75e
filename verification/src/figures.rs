//! Figures that support a verdict where a picture helps, linked from the
//! report. Each is drawn by `trig-audit plot` into `docs/figures/` with the
//! command stated here (`./run.sh figures` redraws them all), without a
//! title (the caption says what each shows); the test
//! `tests/tests/cli_figures.rs` checks that every file exists.

/// A figure supporting the verdict of one claim: the SVG, with its
/// pgfplots code (`.tex`) and its data (`.csv`) beside it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Figure {
    pub claim: &'static str,
    /// Path from the repository root.
    pub path: &'static str,
    pub caption: &'static str,
    /// The `trig-audit` arguments that draw it.
    pub command: &'static str,
}

/// Every figure, by claim.
pub const FIGURES: &[Figure] = &[
    Figure {
        claim: "T7",
        path: "docs/figures/audit-T7-thesis-cubic-outside-range.svg",
        caption: "the thesis cubic basis at m = −5/2, 0, 3/2: outside [−2, 1] functions dip below 0",
        command: "plot basis --family thesis-cubic --values=-2.5,0,1.5 --allow-outside-range --no-title --output docs/figures/audit-T7-thesis-cubic-outside-range.svg",
    },
    Figure {
        claim: "T30",
        path: "docs/figures/audit-T30-han-versus-listing.svg",
        caption: "the Appendix 2 listing's functions (wide, light; b20 with sin) under Han's (6.2) as printed (thin) at λ = −1 (solid), 0 (dashed), 1 (dotted): b0, b1, b3 coincide, b2 differs except at λ = 0",
        command: "plot basis --family han-listing --versus han --values=-1,0,1 --no-title --output docs/figures/audit-T30-han-versus-listing.svg",
    },
    Figure {
        claim: "T24f",
        path: "docs/figures/audit-T24f-table-4.6-g1.svg",
        caption: "the G¹ interpolant of Table 4.6 as printed: it dips below 0 near x = 1.57",
        command: "plot interp --data thesis-table-4.6 --scheme g1 --no-title --output docs/figures/audit-T24f-table-4.6-g1.svg",
    },
    Figure {
        claim: "M2",
        path: "docs/figures/audit-M2-seed000-uniform.svg",
        caption: "the seed 000 uniform segment functions at ζ = 0, 1/2, 4",
        command: "plot basis --family seed000-uniform --values=0,0.5,4 --no-title --output docs/figures/audit-M2-seed000-uniform.svg",
    },
];

impl Figure {
    /// The file beside the figure with extension `ext`.
    fn beside(&self, ext: &str) -> String {
        match self.path.rsplit_once('.') {
            Some((stem, _)) => format!("{stem}.{ext}"),
            None => format!("{}.{ext}", self.path),
        }
    }

    /// The data of the figure: a CSV file beside it (same name).
    pub fn data_path(&self) -> String {
        self.beside("csv")
    }

    /// The pgfplots code of the figure: a `.tex` file beside it.
    pub fn pgf_path(&self) -> String {
        self.beside("tex")
    }
}

/// The figure of a claim, if any.
pub fn for_claim(id: &str) -> Option<&'static Figure> {
    FIGURES.iter().find(|f| f.claim == id)
}
