//! Figures that support a verdict where a picture helps, linked from the
//! report. A claim's file gives its figure (`[claims.figure]`: the file,
//! the caption, the `trig-audit plot` arguments that draw it, without a
//! title: the caption says what it shows); `./run.sh figures` redraws those
//! of the document files, and the test `tests/tests/cli_figures.rs` checks
//! that every one is drawn by its command and committed.

use std::path::{Component, Path, PathBuf};

use trig_specfile::ClaimFigure;

/// A figure supporting the verdict of a claim (`[claims.figure]` of its
/// file): the SVG, with its pgfplots code (`.tex`) and its data (`.csv`)
/// beside it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Figure {
    /// Path from the root the report's paths start at (the repository
    /// root for the audit of `documents/`).
    pub path: String,
    pub caption: String,
    /// The `trig-audit` arguments that draw it.
    pub command: String,
}

impl Figure {
    /// The figure of a claim's file, its path given from `root` (when it
    /// lies under it; otherwise as the file gives it), both simplified.
    pub fn of(figure: &ClaimFigure, root: &Path) -> Figure {
        let at = simplified(&figure.path);
        let root = simplified(root);
        let path = at
            .strip_prefix(&root)
            .unwrap_or(&at)
            .to_string_lossy()
            .into_owned();
        Figure {
            command: format!("plot {} --no-title --output {path}", figure.plot),
            caption: figure.caption.clone(),
            path,
        }
    }

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

/// `path` with `.` dropped and each `dir/..` folded, without reading the
/// file system (`documents/thesis/../../docs/x.svg` → `docs/x.svg`).
fn simplified(path: &Path) -> PathBuf {
    let mut out: Vec<Component> = Vec::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir if matches!(out.last(), Some(Component::Normal(_))) => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out.iter().collect()
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

    #[test]
    fn a_figure_is_given_from_the_root_with_its_command() {
        let spec = ClaimFigure {
            path: PathBuf::from("/r/./documents/thesis/../../docs/figures/a.svg"),
            caption: "c".into(),
            plot: "basis --family f".into(),
        };
        let f = Figure::of(&spec, Path::new("/r/documents/.."));
        assert_eq!(f.path, "docs/figures/a.svg");
        assert_eq!(
            f.command,
            "plot basis --family f --no-title --output docs/figures/a.svg"
        );
        assert_eq!(f.data_path(), "docs/figures/a.csv");
        let elsewhere = Figure::of(&spec, Path::new("/elsewhere"));
        assert_eq!(elsewhere.path, "/r/docs/figures/a.svg");
        let relative_file = ClaimFigure {
            path: PathBuf::from("documents/thesis/../../docs/figures/a.svg"),
            ..spec
        };
        assert_eq!(
            Figure::of(&relative_file, Path::new("")).path,
            "docs/figures/a.svg"
        );
    }
}
