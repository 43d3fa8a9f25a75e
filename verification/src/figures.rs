//! Figures that support a verdict where a picture helps, linked from the
//! report. Each is drawn by `trig-audit plot` into `docs/figures/` with the
//! command stated here (`./run.sh figures` redraws them all), without a
//! title (the caption says what each shows); the test
//! `tests/tests/cli_figures.rs` checks that every file exists.

use std::path::{Component, Path};

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

/// `target` (a path from the current directory) relative to the directory
/// `base`; `target` itself when the two have no common root.
pub fn relative(target: &str, base: Option<&Path>) -> String {
    let Some(base) = base else {
        return target.to_string();
    };
    let (Ok(to), Ok(from)) = (Path::new(target).canonicalize(), base.canonicalize()) else {
        return target.to_string();
    };
    let to: Vec<Component> = to.components().collect();
    let from: Vec<Component> = from.components().collect();
    let common = to.iter().zip(&from).take_while(|(a, b)| a == b).count();
    if common == 0 {
        return target.to_string();
    }
    let mut out: Vec<String> = vec!["..".to_string(); from.len() - common];
    out.extend(
        to[common..]
            .iter()
            .map(|c| c.as_os_str().to_string_lossy().into_owned()),
    );
    out.join("/")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_are_relative_to_the_output_directory() {
        let here = std::env::current_dir().unwrap();
        let dir = here.join("src");
        assert_eq!(relative("Cargo.toml", Some(&dir)), "../Cargo.toml");
        assert_eq!(relative("src/lib.rs", Some(&here)), "src/lib.rs");
        assert_eq!(relative("src/lib.rs", None), "src/lib.rs");
        assert_eq!(relative("no/such/file", Some(&dir)), "no/such/file");
    }
}
