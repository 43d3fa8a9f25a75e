//! Plots of a basis with several parameters: `--param NAME=VALUE` fixes
//! parameters (read exactly, as `eval --param` reads them), `--vary NAME`
//! chooses the one drawn as a family; the fixed values are stated in the
//! title, the labels are math in the pgfplots code and Unicode in the SVG,
//! and the pgfplots fragment compiles in a plain article.

use std::path::Path;

use crate::cli_paste::{compiles_cleanly, draw, scratch};
use crate::cli_spec_features::figure_points;
use trig_e2e::{assert_errors, example};

/// The pgfplots code with its coordinates left out (one line per plot):
/// the header, axis options, legend and the options of every plot.
fn pgf_outline(tex: &str) -> String {
    tex.lines()
        .filter(|l| !l.starts_with("  ("))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The text elements of an SVG, in order (title, ticks, axis labels, legend).
fn svg_texts(svg: &str) -> String {
    svg.split("<text")
        .skip(1)
        .filter_map(|t| {
            t.split_once('>')
                .and_then(|(_, rest)| rest.split('<').next())
        })
        .map(str::trim)
        .collect::<Vec<_>>()
        .join("\n")
}

/// The largest difference between the drawn `series` of the figure at
/// `svg` and `f` at the same abscissas.
fn deviation(svg: &Path, series: &str, f: impl Fn(f64) -> f64) -> f64 {
    let points = figure_points(svg, &format!("\"{series}\""));
    assert_eq!(points.len(), 201, "{series}");
    points
        .iter()
        .map(|&(x, y)| (y - f(x)).abs())
        .fold(0.0, f64::max)
}

/// Han, Ma & Huang's cubic with μ = 1/2 fixed draws λ's family at μ = 1/2:
/// `b2 = c(1 − c)(2 + μ − μc)` (μ alone) at μ = 1/2 for every λ, and
/// `b0 = (1 − s)²(1 − λs)` (λ alone) at each drawn λ; the value is stated
/// in the title in math (pgfplots) and Unicode (SVG); the fragment compiles
/// in a plain article with no error and no overfull box.
#[test]
fn a_two_parameter_basis_is_drawn_with_one_parameter_fixed() {
    let dir = scratch("params");
    let spec = example("han-ma-huang-cubic.toml");
    let (svg, tex) = draw(
        &dir,
        "hmh",
        &["basis", "--spec", &spec, "--param", "mu=1/2"],
    );
    let path = dir.join("hmh.svg");
    let mu = 0.5;
    for lambda in ["−2", "−5/4", "−1/2", "1/4", "1"] {
        let b2 = |t: f64| t.cos() * (1.0 - t.cos()) * (2.0 + mu - mu * t.cos());
        let d = deviation(&path, &format!("b2, λ = {lambda}"), b2);
        assert!(d < 1e-12, "b2 at λ = {lambda}: {d}");
    }
    let b0 = |t: f64| (1.0 - t.sin()).powi(2) * (1.0 + 1.25 * t.sin());
    let d = deviation(&path, "b0, λ = −5/4", b0);
    assert!(d < 1e-12, "b0 at λ = −5/4: {d}");
    // math in the pgfplots code, never raw Unicode; the citation a comment
    assert!(tex.is_ascii(), "{tex}");
    for piece in [
        r"title={cubic trigonometric Bezier basis with two shape parameters at $\mu = \frac{1}{2}$},",
        r"\addlegendentry{$b_{0}$}",
        r"\addlegendentry{$\lambda = -\frac{5}{4}$}",
        r"xlabel={$t \in [0,\allowbreak \frac{\pi}{2}]$ (radians)},",
        "% source: Han, Ma \\& Huang, Appl. Math. Lett. 22 (2009) 226-231, (1)\n",
    ] {
        assert!(tex.contains(piece), "{piece}:\n{tex}");
    }
    for piece in ["at μ = 1/2", "b₀", "λ = −5/4", "t ∈ [0, π/2] (radians)"] {
        assert!(svg.contains(piece), "{piece}");
    }
    insta::assert_snapshot!("hmh_mu_half_pgf", pgf_outline(&tex));
    insta::assert_snapshot!("hmh_mu_half_svg_text", svg_texts(&svg));
    // \input into a plain article, as a paper does
    let body = format!(
        "\\begin{{figure}}\n\\centering\n\\input{{{}}}\n\\caption{{Han, Ma and Huang's basis at $\\mu = 1/2$.}}\n\\end{{figure}}\n",
        path.with_extension("tex").display()
    );
    let doc = format!(
        "\\documentclass{{article}}\n\\usepackage{{pgfplots}}\n\\pgfplotsset{{compat=1.16}}\n\\begin{{document}}\n{body}\\end{{document}}\n"
    );
    compiles_cleanly(&doc, "plot-two-parameters", true);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--vary` chooses the varied parameter (by name or printed symbol), for
/// a curve too; every parameter fixed draws one setting.
#[test]
fn the_varied_parameter_is_chosen_and_the_others_fixed() {
    let dir = scratch("vary");
    let spec = example("han-ma-huang-cubic.toml");
    let (svg, tex) = draw(
        &dir,
        "mu",
        &[
            "basis",
            "--spec",
            &spec,
            "--vary",
            "μ",
            "--param",
            "λ=-1",
            "--values=-2,0",
        ],
    );
    assert!(tex.contains(r"\addlegendentry{$\mu = -2$}"), "{tex}");
    assert!(tex.contains(r"at $\lambda = -1$}"), "{tex}");
    assert!(svg.contains("at λ = −1") && svg.contains("μ = 0"));
    // b3 = (1 − c)²(1 − μc) at μ = 0 whatever λ
    let b3 = |t: f64| (1.0 - t.cos()).powi(2);
    let d = deviation(&dir.join("mu.svg"), "b3, μ = 0", b3);
    assert!(d < 1e-12, "{d}");
    let (_, tex) = draw(
        &dir,
        "curve",
        &["curve", "--spec", &spec, "--param", "mu=1", "--values=-1,1"],
    );
    assert!(
        tex.contains(r"\addlegendentry{$\lambda = -1$}") && tex.contains(r"at $\mu = 1$}"),
        "{tex}"
    );
    let (_, tex) = draw(
        &dir,
        "fixed",
        &[
            "basis", "--spec", &spec, "--param", "mu=1", "--param", "lambda=0",
        ],
    );
    assert!(
        tex.contains(r"at $\lambda = 0$, $\mu = 1$}") && !tex.contains(r"\addlegendentry{$\lambda"),
        "{tex}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_missing_choice_unknown_names_and_values_outside_are_usage_errors() {
    let dir = scratch("refused");
    let spec = example("han-ma-huang-cubic.toml");
    let out = dir.join("x.svg").display().to_string();
    let basis = |extra: &[&'static str]| -> Vec<String> {
        let mut args: Vec<String> = ["plot", "basis", "--spec", &spec, "--output", &out]
            .map(String::from)
            .to_vec();
        args.extend(extra.iter().map(|a| a.to_string()));
        args
    };
    let cases: Vec<(Vec<String>, &str)> = vec![
        (
            basis(&[]),
            "2 free parameters (lambda, mu); basis plots vary one",
        ),
        (basis(&[]), "--param NAME=VALUE"),
        (basis(&[]), "--vary NAME"),
        (
            basis(&["--param", "nu=0"]),
            "no parameter `nu` (expected: lambda, mu)",
        ),
        (basis(&["--vary", "nu"]), "no parameter `nu`"),
        (
            basis(&["--param", "mu=2"]),
            "outside the published range [-2, 1]",
        ),
        (basis(&["--param", "mu=2"]), "--allow-outside-range"),
        (basis(&["--param", "mu=1/2", "--vary", "mu"]), "both fixed"),
        (basis(&["--param", "mu=x"]), "cannot read `x`"),
        (basis(&["--param", "mu"]), "expected NAME=VALUE"),
    ];
    let cases: Vec<(Vec<&str>, &str)> = cases
        .iter()
        .map(|(args, e)| (args.iter().map(String::as_str).collect(), *e))
        .collect();
    let cases: Vec<(&[&str], &str)> = cases.iter().map(|(a, e)| (a.as_slice(), *e)).collect();
    assert_errors(&cases);
    // outside the range when asked
    let (_, tex) = draw(
        &dir,
        "outside",
        &[
            "basis",
            "--spec",
            &spec,
            "--param",
            "mu=2",
            "--allow-outside-range",
        ],
    );
    assert!(tex.contains(r"at $\mu = 2$}"), "{tex}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `fit --optimise` on a basis with two parameters searches the one
/// `--vary` names (or the one `--param` leaves free), the other held at
/// its `--param` value in every segment; `plot fit` says so in its title.
#[test]
fn fit_optimises_the_varied_parameter_with_the_others_fixed() {
    let spec = example("han-ma-huang-cubic.toml");
    let glyph = format!("{}/../data/glyphs/epsilon.csv", env!("CARGO_MANIFEST_DIR"));
    let json = trig_e2e::stdout_ok(&[
        "fit",
        "--spec",
        &spec,
        "--glyph",
        &glyph,
        "--param",
        "lambda=0",
        "--param",
        "mu=1/2",
        "--vary",
        "mu",
        "--optimise",
        "--format",
        "json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    let methods = v["methods"].as_array().expect("methods");
    assert_eq!(methods.len(), 2, "the fixed fit and the optimised one");
    let params = |m: &serde_json::Value| -> Vec<(f64, f64)> {
        m["fit"]["segments"]
            .as_array()
            .expect("segments")
            .iter()
            .map(|s| {
                let p = s["params"].as_array().expect("params");
                (p[0].as_f64().expect("λ"), p[1].as_f64().expect("μ"))
            })
            .collect()
    };
    assert!(params(&methods[0]).iter().all(|&p| p == (0.0, 0.5)));
    let searched = params(&methods[1]);
    assert!(
        searched
            .iter()
            .all(|&(l, m)| l == 0.0 && (-2.0..=1.0).contains(&m))
    );
    assert!(searched.iter().any(|&(_, m)| m != 0.5), "{searched:?}");
    let setting = methods[1]["setting"].as_str().expect("setting");
    assert!(setting.starts_with("μ optimised in [-2, 1]") && setting.ends_with("λ = 0"));
    // the free parameter is searched without --vary; none free is an error
    let dir = scratch("fit");
    let (_, tex) = draw(
        &dir,
        "fit",
        &[
            "fit",
            "--spec",
            &spec,
            "--glyph",
            &glyph,
            "--param",
            "mu=1/2",
            "--optimise",
        ],
    );
    assert!(
        tex.contains(r"($\lambda$ optimised per segment, $\mu = 0.5$, "),
        "{tex}"
    );
    let out = dir.join("x.svg").display().to_string();
    assert_errors(&[
        (
            &[
                "plot",
                "fit",
                "--spec",
                &spec,
                "--glyph",
                &glyph,
                "--optimise",
                "--output",
                &out,
            ],
            "has 2 (λ, μ): fix all but one with --param NAME=VALUE (--vary NAME",
        ),
        (
            &[
                "fit", "--spec", &spec, "--glyph", &glyph, "--param", "lambda=0", "--vary", "mu",
            ],
            "--vary chooses the parameter --optimise searches",
        ),
        (
            &[
                "plot",
                "fit",
                "--spec",
                &spec,
                "--glyph",
                &glyph,
                "--vary",
                "nu",
                "--optimise",
                "--output",
                &out,
            ],
            "no parameter `nu`",
        ),
        (
            &[
                "plot",
                "fit",
                "--spec",
                &spec,
                "--glyph",
                &glyph,
                "--param",
                "lambda=2",
                "--optimise",
                "--output",
                &out,
            ],
            "outside the published range",
        ),
    ]);
    let _ = std::fs::remove_dir_all(&dir);
}
