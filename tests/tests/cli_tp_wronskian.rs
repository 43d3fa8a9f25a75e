//! Total positivity by Karlin's Wronskian criterion (issue 38): bases the
//! totally positive factorisation does not take — the variable beside
//! `sin t` (C-Bézier), exponentials, domains `[0, α]` — decided both ways.
//! Expected values: `examples/independent/issue38-wronskian.md` (SymPy and
//! mpmath, written without reading the crates).

use std::path::PathBuf;

use crate::cli_spec_engine::claim;
use trig_e2e::example;

/// A copy of a shipped example with extra claims appended, for one test.
fn with_claims(name: &str, claims: &str) -> String {
    let text = std::fs::read_to_string(example(name)).expect("read example");
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_tp_wronskian");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(format!("with-{name}"));
    std::fs::write(&path, format!("{text}\n{claims}")).expect("write spec");
    path.display().to_string()
}

#[test]
fn a_domain_that_moves_with_its_parameter() {
    let path = example("trig-bernstein-alpha.toml");
    let (v, e) = claim(&path, "TBA-totally-positive");
    assert_eq!(v, "holds", "{e}");
    assert!(e.contains("all 6 consecutive Wronskians"), "{e}");
    let (v, e) = claim(&path, "TBA-totally-positive-wide");
    assert_eq!(v, "fails", "{e}");
    assert!(
        e.contains("W(b1) < 0") && e.contains("negative 1 × 1 minor"),
        "{e}"
    );
    // b1 ≡ 0 at α = π/2: the closed end by continuity, and the range is
    // exactly the maximal set (issue38-wronskian.md: TP exactly on (0, π/2])
    let (v, e) = claim(&path, "TBA-totally-positive-maximal");
    assert_eq!(v, "holds", "{e}");
    assert!(
        e.contains("the closed ends of the range by continuity"),
        "{e}"
    );
}

#[test]
fn c_bezier_cubic_both_ways_and_its_maximal_set() {
    let path = example("c-bezier-cubic.toml");
    let (v, e) = claim(&path, "CB-totally-positive");
    assert_eq!(v, "holds", "{e}");
    assert!(e.contains("W(b0, b1, b2, b3) > 0"), "{e}");
    // the printed (0, π) is not the maximal set: at α = π it holds too
    let (v, e) = claim(&path, "CB-totally-positive-maximal");
    assert_eq!(v, "fails", "{e}");
    assert!(
        e.contains("α = 1·π") && e.contains("shrinks to a point"),
        "{e}"
    );
    // beyond 2π the basis is not even nonnegative: b1 < 0 inside
    let beyond = with_claims(
        "c-bezier-cubic.toml",
        "[[claims]]\nid = \"beyond\"\nsource = \"test\"\nstatement = \"TP\"\ncheck = \"total-positivity\"\nrange = \"[13/2, 7]\"\n",
    );
    let (v, e) = claim(&beyond, "beyond");
    assert_eq!(v, "fails", "{e}");
    assert!(e.contains("W(b1) < 0"), "{e}");
}

#[test]
fn c_bezier_cubic_is_totally_positive_exactly_below_two_pi() {
    let path = with_claims(
        "c-bezier-cubic-2pi.toml",
        "[[claims]]\nid = \"tp-max\"\nsource = \"test\"\nstatement = \"TP\"\ncheck = \"total-positivity\"\nmaximal = true\n",
    );
    let (v, e) = claim(&path, "tp-max");
    assert_eq!(v, "holds", "{e}");
    assert!(e.contains("exactly the maximal set"), "{e}");
}

#[test]
fn exponentials_and_a_degenerate_closed_end() {
    // the exponential Bernstein basis on its bounded printed range
    let path = with_claims(
        "exp-bernstein-cubic.toml",
        "[[claims]]\nid = \"tp\"\nsource = \"test\"\nstatement = \"TP\"\ncheck = \"total-positivity\"\n",
    );
    let (v, e) = claim(&path, "tp");
    assert_eq!(v, "holds", "{e}");
    // the quadratic C-Bézier basis degenerates at the closed end π (b1 ≡ 0
    // there, issue38-wronskian.md: still totally positive): the criterion
    // proves the open range, continuity reaches π
    let path = with_claims(
        "c-bezier-quadratic.toml",
        "[[claims]]\nid = \"tp\"\nsource = \"test\"\nstatement = \"TP\"\ncheck = \"total-positivity\"\n\n[[claims]]\nid = \"tp-open\"\nsource = \"test\"\nstatement = \"TP\"\ncheck = \"total-positivity\"\nrange = \"(0, pi)\"\n",
    );
    let (v, e) = claim(&path, "tp");
    assert_eq!(v, "holds", "{e}");
    assert!(
        e.contains("the closed ends of the range by continuity"),
        "{e}"
    );
    let (v, e) = claim(&path, "tp-open");
    assert_eq!(v, "holds", "{e}");
}

/// `plot region --property total-positivity`: Han, Ma & Huang's box
/// `[−2, 1]²` is the certified inside (examples/independent/issue38.md,
/// section 3: totally positive exactly there), a necessary condition fails
/// on certified cells around it.
#[test]
fn the_region_of_total_positivity_is_drawn() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_tp_wronskian");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let svg = dir.join("hmh-tp.svg");
    let out = trig_e2e::written(&[
        "plot",
        "region",
        "--spec",
        &example("han-ma-huang-cubic.toml"),
        "--property",
        "total-positivity",
        "--output",
        &svg.display().to_string(),
    ]);
    assert!(out.contains("wrote"), "{out}");
    let text = std::fs::read_to_string(&svg).expect("svg written");
    assert!(
        text.contains("where the basis is totally positive"),
        "{out}"
    );
    assert!(
        text.contains(
            "certified inside (totally positive: every minor of the factorisation ≥ 0): 1"
        ) && text.contains("certified outside (a necessary condition fails)"),
        "{text}"
    );
    for ext in ["svg", "tex", "csv"] {
        let _ = std::fs::remove_file(dir.join(format!("hmh-tp.{ext}")));
    }
}

/// `plot region --property independent`: GB2 is dependent only at the
/// corner (−2, −2) (examples/independent/issue38.md, section 2): every cell
/// away from it is certified independent, the undecided ones hold it.
#[test]
fn the_region_of_independence_is_drawn() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_tp_wronskian");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let svg = dir.join("gb2-ind.svg");
    let out = trig_e2e::written(&[
        "plot",
        "region",
        "--spec",
        &example("gb2-independence.toml"),
        "--property",
        "independent",
        "--output",
        &svg.display().to_string(),
    ]);
    assert!(out.contains("wrote"), "{out}");
    let csv = std::fs::read_to_string(dir.join("gb2-ind.csv")).expect("csv written");
    let text = std::fs::read_to_string(&svg).expect("svg written");
    assert!(text.contains("certified independent"), "{text}");
    // every undecided cell lies next to the corner (−2, −2), within 1/4
    // (near the dependence point the minors are too small to be certified
    // at the depth limit): the CSV gives each cell as its lower-left
    // (point 0) and upper-right (point 1) corners
    let corners: Vec<(f64, f64)> = csv
        .lines()
        .filter(|l| l.starts_with("edge cell"))
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            (f[2].parse().expect("x"), f[3].parse().expect("y"))
        })
        .collect();
    assert!(!corners.is_empty(), "{csv}");
    for cell in corners.chunks(2) {
        let [(x0, y0), (x1, y1)] = cell else {
            panic!("{cell:?}")
        };
        let near = |lo: f64, hi: f64| lo <= -1.75 && hi >= -2.25;
        assert!(near(*x0, *x1) && near(*y0, *y1), "{cell:?}");
    }
    for ext in ["svg", "tex", "csv"] {
        let _ = std::fs::remove_file(dir.join(format!("gb2-ind.{ext}")));
    }
}
