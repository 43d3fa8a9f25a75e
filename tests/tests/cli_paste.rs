//! What a researcher pastes into a paper: `table --format tex` and the
//! pgfplots code of `plot` are fragments to `\input` into a plain
//! `article` with standard packages only (`booktabs`, `longtable`,
//! `amsmath`; `pgfplots` for figures), `--standalone` a whole document.
//! The string checks always run; when `pdflatex` (with pgfplots) is on
//! the machine, the fragments are compiled in a plain article and must
//! give no error and no overfull box.

use std::path::{Path, PathBuf};
use std::process::Command;

use trig_e2e::{error_line, example, stdout_ok, written};

/// A scratch directory of this test process.
pub(crate) fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("trig-audit-paste-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch directory");
    dir
}

/// A plain `article` with the `preamble` lines around `body`.
fn article(preamble: &str, body: &str) -> String {
    format!(
        "\\documentclass{{article}}\n{preamble}\n\\begin{{document}}\n{body}\\end{{document}}\n"
    )
}

/// Compiles `tex` when pdflatex (and pgfplots, for `figure`) is on the
/// machine: no error, no overfull box, at least one page.
pub(crate) fn compiles_cleanly(tex: &str, name: &str, figure: bool) {
    let pgfplots = Command::new("kpsewhich")
        .arg("pgfplots.sty")
        .output()
        .is_ok_and(|o| o.status.success());
    if figure && !pgfplots {
        assert!(
            std::env::var_os(trig_tex::REQUIRE_TEX).is_none(),
            "{name}: pgfplots is not installed, and {} requires it",
            trig_tex::REQUIRE_TEX
        );
        eprintln!("skipped: pdflatex with pgfplots is not on this machine ({name})");
        return;
    }
    match trig_tex::compile(tex, name) {
        Some(log) => {
            assert!(log.errors.is_empty(), "{name}: {:#?}", log.errors);
            assert_eq!(log.overfull, 0, "{name}: {:#?}", log.overfull_lines);
            assert!(log.pages >= 1, "{name}");
        }
        None => eprintln!("skipped: pdflatex is not on this machine ({name})"),
    }
}

#[test]
fn table_fragments_use_standard_packages_and_real_fractions() {
    let tex = stdout_ok(&["table", "thesis-cubic", "--wrt", "u", "--format", "tex"]);
    assert!(tex.starts_with("% thesis-cubic"), "{tex}");
    assert!(
        !tex.contains("\\documentclass") && !tex.contains("\\newcolumntype"),
        "{tex}"
    );
    assert!(
        tex.contains("\\usepackage{booktabs,longtable,amsmath}"),
        "{tex}"
    );
    assert!(tex.contains("\\toprule") && tex.contains("\\midrule") && !tex.contains("\\hline"));
    // b2''''''(0) in u: −15/8 m π⁶ + 31/32 π⁶, a fraction as a fraction
    assert!(
        tex.contains("$-\\frac{15}{8}\\, m \\pi^{6} + \\frac{31}{32}\\, \\pi^{6}$"),
        "{tex}"
    );
    // the heading's punctuation stays outside its formulas
    assert!(tex.contains("$(\\frac{\\pi}{2})^{k}$), exact"), "{tex}");
    let whole = stdout_ok(&["table", "thesis-cubic", "--format", "tex", "--standalone"]);
    assert!(
        whole.starts_with("\\documentclass{article}\n\\usepackage{booktabs,longtable,amsmath}\n")
            && whole.ends_with("\\end{document}\n"),
        "{whole}"
    );
    let refused = error_line(&["table", "thesis-cubic", "--standalone"]);
    assert!(refused.contains("--format tex"), "{refused}");
}

#[test]
fn table_fragments_fit_a_plain_article() {
    let rational_spec = example("rational-cubic.toml");
    let cases: [(&str, &[&str]); 5] = [
        ("basis", &["thesis-cubic", "--wrt", "u"]),
        ("curve", &["bernstein3", "--curve"]),
        (
            "rational",
            &["thesis-cubic", "--curve", "--rational", "--order", "4"],
        ),
        ("uniform", &["seed000-uniform", "--order", "4"]),
        ("spec", &["--spec", &rational_spec, "--order", "4"]),
    ];
    for (name, args) in cases {
        let fragment = stdout_ok(&[&["table"], args, &["--format", "tex"]].concat());
        assert!(!fragment.contains("\\documentclass"), "{name}");
        compiles_cleanly(
            &article("\\usepackage{booktabs,longtable,amsmath}", &fragment),
            &format!("paste-table-{name}"),
            false,
        );
    }
}

/// Draws `plot ARGS` into `dir/name.svg` and returns (SVG, pgfplots code).
pub(crate) fn draw(dir: &Path, name: &str, args: &[&str]) -> (String, String) {
    let svg = dir.join(format!("{name}.svg"));
    let path = svg.display().to_string();
    let out = written(&[&["plot"], args, &["--output", &path]].concat());
    assert!(out.contains("wrote"), "{name}: {out}");
    (
        std::fs::read_to_string(&svg).expect("SVG written"),
        std::fs::read_to_string(svg.with_extension("tex")).expect("pgfplots code written"),
    )
}

#[test]
fn figure_fragments_take_a_width_a_title_or_none_and_a_real_minus() {
    let dir = scratch("options");
    let basis = ["basis", "--family", "thesis-cubic", "--values=-2,0,1"];
    let (svg, tex) = draw(&dir, "default", &basis);
    assert!(
        tex.starts_with('%') && !tex.contains("\\documentclass"),
        "{tex}"
    );
    assert!(tex.contains("\\begin{tikzpicture}") && tex.ends_with("\\end{tikzpicture}\n"));
    assert!(
        tex.contains("width={\\linewidth-") && tex.contains("title={"),
        "{tex}"
    );
    // the legend in math (−2 with a minus sign, not a hyphen), the
    // function names with their indices; the SVG in Unicode
    assert!(tex.contains("\\addlegendentry{$m = -2$}"), "{tex}");
    assert!(tex.contains("\\addlegendentry{$b_{0}$}"), "{tex}");
    assert!(!tex.contains("{m = -2}") && !tex.contains("{b0}"), "{tex}");
    // a short title: the basis's, not its citation (a comment beside it)
    assert!(
        tex.contains("title={cubic trigonometric basis $b_{i}(u;\\allowbreak m)$},"),
        "{tex}"
    );
    assert!(
        tex.contains("% source: seed 001 (thesis), (3.7)\n"),
        "{tex}"
    );
    assert!(svg.contains("m = −2") && svg.contains("b₀") && svg.contains("font-family=\"serif\""));
    let (svg, tex) = draw(
        &dir,
        "narrow",
        &[&basis[..], &["--width", "8cm", "--no-title"]].concat(),
    );
    assert!(
        tex.contains("width={8cm-") && !tex.contains("title={"),
        "{tex}"
    );
    assert!(
        !svg.contains("cubic trigonometric basis"),
        "the SVG without its title"
    );
    let (_, tex) = draw(&dir, "whole", &[&basis[..], &["--standalone"]].concat());
    assert!(
        tex.starts_with("\\documentclass{article}\n\\usepackage{pgfplots}\n")
            && tex.ends_with("\\end{document}\n"),
        "{tex}"
    );
    // a curve keeps one data unit as long on both axes at any width
    let (_, tex) = draw(
        &dir,
        "curve",
        &["curve", "--family", "han", "--values=-1,1"],
    );
    assert!(tex.contains("axis equal image"), "{tex}");
    let svg = dir.join("bad.svg").display().to_string();
    let bad = error_line(
        &[
            &["plot"],
            &basis[..],
            &["--width", "8cm]{x}", "--output", &svg],
        ]
        .concat(),
    );
    assert!(bad.contains("--width"), "{bad}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn figure_fragments_fit_a_plain_article() {
    let dir = scratch("compile");
    let spec = example("bashir-quadratic.toml");
    let cases: [(&str, &[&str]); 6] = [
        (
            "basis",
            &[
                "basis",
                "--family",
                "thesis-cubic",
                "--values=-2.5,0,1.5",
                "--allow-outside-range",
            ],
        ),
        (
            "versus",
            &[
                "basis",
                "--family",
                "han-listing",
                "--versus",
                "han",
                "--values=-1,0,1",
            ],
        ),
        ("curve", &["curve", "--family", "han", "--values=-2,-1,0,1"]),
        (
            "interp",
            &["interp", "--data", "thesis-table-4.6", "--scheme", "g1"],
        ),
        ("region", &["region", "--spec", &spec]),
        (
            "region-tp",
            &["region", "--spec", &spec, "--property", "total-positivity"],
        ),
    ];
    for (name, args) in cases {
        let (_, fragment) = draw(&dir, name, args);
        let body = format!(
            "\\begin{{figure}}\n\\centering\n{fragment}\\caption{{A figure.}}\n\\end{{figure}}\n"
        );
        let doc = article("\\usepackage{pgfplots}\n\\pgfplotsset{compat=1.16}", &body);
        compiles_cleanly(&doc, &format!("paste-figure-{name}"), true);
    }
    let _ = std::fs::remove_dir_all(&dir);
}
