//! An independent test of six checks of the spec language added in session
//! 5 — `cylinder`, `leaves-hull`, `table-count`, `table-compare`,
//! `data-values`, `interpolant-maximum` — on published bases with two shape
//! parameters, neither in the catalog: the generalized Bernstein basis of
//! degree 2 (Han, Ma & Huang, JCAM 217 (2008) 180–193, as quoted in Hu, Bo &
//! Qin, J. Inequal. Appl. 2017:115, Def. 1) and the cubic trigonometric Bézier
//! basis of Han, Ma & Huang (Appl. Math. Lett. 22 (2009) 226–231), in the
//! document `examples/session5-checks-b/`.
//!
//! Every expected verdict, value and witness value is derived in
//! `examples/independent/session5_checks_b.py` (SymPy, mpmath), which also
//! writes the document's data files: the formulas below are those
//! derivations, evaluated exactly at the point the audit names; the table
//! cells are read from the data files.

use std::sync::OnceLock;

use rug::Rational;
use serde_json::Value;
use trig_e2e::example;

use crate::constructs_independent::{audit, claim, evidence_text, int, verdict};

fn document() -> &'static Value {
    static REPORT: OnceLock<Value> = OnceLock::new();
    REPORT.get_or_init(|| audit(&example("session5-checks-b/")))
}

fn r(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}

/// An exact number of a report's SymPy form (`169/10000`, `-5/64`).
fn q(text: &str) -> Rational {
    text.parse::<Rational>()
        .unwrap_or_else(|e| panic!("{text}: {e}"))
}

/// A printed decimal as an exact rational (`0.0169`).
fn decimal(text: &str) -> Rational {
    let (whole, frac) = text.split_once('.').unwrap_or((text, ""));
    q(&format!("{whole}{frac}/1{}", "0".repeat(frac.len())))
}

/// The witness of an evidence item or claim: a point coordinate by symbol
/// and a value by label, in SymPy syntax.
fn point_sympy(w: &Value, symbol: &str) -> String {
    w["point"]
        .as_array()
        .expect("point")
        .iter()
        .find(|p| p["symbol"] == symbol || p["name"] == symbol)
        .unwrap_or_else(|| panic!("{symbol} in {w}"))["sympy"]
        .as_str()
        .expect("sympy")
        .to_string()
}

fn value_sympy(w: &Value, label: &str) -> String {
    w["values"]
        .as_array()
        .expect("values")
        .iter()
        .find(|v| v["label"] == label)
        .unwrap_or_else(|| panic!("{label} in {w}"))["value"]["sympy"]
        .as_str()
        .expect("sympy")
        .to_string()
}

/// The evidence item of a claim with `subject`.
fn item<'a>(c: &'a Value, subject: &str) -> &'a Value {
    c["evidence"]
        .as_array()
        .expect("evidence")
        .iter()
        .find(|e| e["subject"] == subject)
        .unwrap_or_else(|| panic!("{subject}: {c}"))
}

/// GB2 `b0, b1, b2` at `t` (SymPy: `gb2`).
fn gb2(t: &Rational, l1: &Rational, l2: &Rational) -> [Rational; 3] {
    let s = int(1) - t.clone();
    [
        s.clone() * &s * (int(1) - l1.clone() * t),
        t.clone() * &s * (int(2) + l1.clone() - l1.clone() * t + l2.clone() * t),
        t.clone() * t * (int(1) - l2.clone() + l2.clone() * t),
    ]
}

/// HMH `b0 … b3` at the atoms `s = sin t`, `c = cos t` (SymPy: `hmh`).
fn hmh(s: &Rational, c: &Rational, l: &Rational, m: &Rational) -> [Rational; 4] {
    let (s1, c1) = (int(1) - s.clone(), int(1) - c.clone());
    [
        s1.clone() * &s1 * (int(1) - l.clone() * s),
        s.clone() * &s1 * (int(2) + l.clone() - l.clone() * s),
        c.clone() * &c1 * (int(2) + m.clone() - m.clone() * c),
        c1.clone() * &c1 * (int(1) - m.clone() * c),
    ]
}

/// `Σ wᵢ Pᵢ` of plane points.
fn combine(w: &[Rational], points: &[(i64, i64)]) -> (Rational, Rational) {
    let mut x = (int(0), int(0));
    for (b, (px, py)) in w.iter().zip(points) {
        x.0 += b.clone() * int(*px);
        x.1 += b.clone() * int(*py);
    }
    x
}

// ---------------------------------------------------------------- cylinder

/// GB2 at `λ1 = 1/2, λ2 = −1`: over a net on the ruling `(3/5, 4/5, z)` the
/// surface lies on `x² + y² = 1`; over the quadratic Bézier quarter circle
/// `(1, 0), (1, 1), (0, 1)` (each row) `g = x² + y² − 1 = 5/4 v⁶ − 6v⁵ +
/// 21/2 v⁴ − 8v³ + 9/4 v²`, largest on the 16 × 16 grid at `(0, 3/8)`:
/// `64125/1048576`; the largest distance `√(1 + g) − 1 ≈ 0.0301422` at
/// `v ≈ 0.36754`. Free parameters or a trigonometric basis: not decided.
#[test]
fn a_gb2_surface_against_the_cylinder() {
    let c = claim(document(), "CY-ruling");
    assert_eq!(c["verdict"], "holds", "{c}");
    assert!(evidence_text(c).contains("x² + y² − r² ≡ 0"), "{c}");

    let (l1, l2) = (r(1, 2), int(-1));
    // each row of the net is the arc (1, 0), (1, 1), (0, 1): g depends on v alone
    let g = |v: &Rational| {
        let (x, y) = combine(&gb2(v, &l1, &l2), &[(1, 0), (1, 1), (0, 1)]);
        x.clone() * &x + y.clone() * &y - int(1)
    };
    for id in ["CY-arc", "CY-arc-not"] {
        let c = claim(document(), id);
        let expected = if id == "CY-arc" { "fails" } else { "holds" };
        assert_eq!(c["verdict"], expected, "{c}");
        let w = if id == "CY-arc" {
            &c["witness"]
        } else {
            &c["evidence"]
                .as_array()
                .unwrap()
                .iter()
                .find(|e| e["witness"].is_object())
                .expect("the counterexample")["witness"]
        };
        assert_eq!(q(&point_sympy(w, "u")), 0);
        let v = q(&point_sympy(w, "v"));
        let at = g(&v);
        assert_eq!(q(&value_sympy(w, "x² + y² − r²")), at);
        // the grid point of largest |g|, the first in (u, v) order
        let grid: Vec<Rational> = (0..=16).map(|j| g(&r(j, 16)).abs()).collect();
        let top = grid.iter().max().unwrap();
        assert_eq!(at.clone().abs(), *top);
        assert_eq!(v, r(grid.iter().position(|x| x == top).unwrap() as i64, 16));
    }
    // the certified bracket of the largest distance holds the sampled one
    let text = evidence_text(claim(document(), "CY-arc"));
    let bracket: Vec<f64> = text
        .split("lies in [")
        .nth(1)
        .and_then(|t| t.split(']').next())
        .expect("the bracket")
        .split(", ")
        .map(|x| x.parse().unwrap())
        .collect();
    let sampled = (0..=100_000)
        .map(|k| {
            let v = f64::from(k) / 100_000.0;
            let b = [
                (1.0 - v).powi(2) * (1.0 - v / 2.0),
                v * (1.0 - v) * (2.5 - v / 2.0 - v),
                v * v * (2.0 - v),
            ];
            let (x, y) = (b[0] + b[1], b[1] + b[2]);
            x.hypot(y) - 1.0
        })
        .fold(0.0, f64::max);
    assert!(
        bracket[0] <= sampled && sampled <= bracket[1] && bracket[1] - bracket[0] < 1e-4,
        "{bracket:?} {sampled}"
    );

    // through the axis (GB2 at λ1 = λ2 = 0: x = 3v − 1, y = 1 − 3v), inside a
    // piece of the judge's subdivision: the defect fixed with this test (the
    // Bernstein bound of g fell below −r² and the claim was not decided)
    let c = claim(document(), "CY-axis");
    assert_eq!(c["verdict"], "fails", "{c}");
    let w = &c["witness"];
    let v = q(&point_sympy(w, "v"));
    // each row (−1, 1), (1/2, −1/2), (2, −2)
    let b = gb2(&v, &int(0), &int(0));
    let x: Rational = b[1].clone() / 2 + int(2) * &b[2] - &b[0];
    let y = -x.clone();
    let at = x.clone() * &x + y.clone() * &y - int(1);
    assert_eq!(q(&value_sympy(w, "x² + y² − r²")), at);
    assert_eq!((v, at), (int(1), int(7)));
    assert!(evidence_text(c).contains("lies in [1.8284, 1.8285]"), "{c}");

    let c = claim(document(), "CY-free");
    assert_eq!(c["verdict"], "not-checkable", "{c}");
    assert!(evidence_text(c).contains("fix every parameter with"), "{c}");
    let c = claim(document(), "CY-hmh");
    assert_eq!(c["verdict"], "not-checkable", "{c}");
    assert!(
        evidence_text(c).contains("polynomial bases on [0, 1]"),
        "{c}"
    );
}

// ------------------------------------------------------------- leaves-hull

/// The triangle's supporting half-planes `2x − y ≥ 0`, `2x + y ≤ 4`,
/// `y ≥ 0` (edges P0P1, P1P2, P2P0), each as `a·x + b·y + c ≥ 0`.
const TRIANGLE: [(i64, i64, i64); 3] = [(2, -1, 0), (-2, -1, 4), (0, 1, 0)];
const TRIANGLE_POINTS: [(i64, i64); 3] = [(0, 0), (1, 2), (2, 0)];

fn inside(q: &(Rational, Rational), planes: &[(i64, i64, i64)]) -> bool {
    planes
        .iter()
        .all(|(a, b, c)| int(*a) * q.0.clone() + int(*b) * q.1.clone() + int(*c) >= 0)
}

/// GB2 at `λ2 = −1`, the triangle `(0, 0), (1, 2), (2, 0)`: at `λ1 = 3` the
/// first sample outside is `t = 7/20` (`b0 < 0` for `t > 1/3`), `Q =
/// (4893/4000, 819/500)` beyond `2x + y ≤ 4`; at `λ1 = −4` it is `t = 1/20`
/// (`b1 < 0` near 0), `Q = (−5/64, −703/4000)` below `y ≥ 0`. The surface
/// over `hull-net.txt` (rows at heights 0, 2, 2): `S(1/2, 0) = (0, 3/2, 9/4)`
/// at `λ1 = 3`, `S(0, 1/6) = (−23/216, 0, 0)` at `λ1 = −4`. HMH at `μ = −1`,
/// `λ = 3`: at `z = 1/5` (`s = 5/13`, `c = 12/13`) `Q = (3000/2197,
/// 4600/2197)` above `y ≤ 2`. Inside the range (`λ1 = 1/2`, every weight
/// `≥ 0`) and with `λ2` free: not decided.
#[test]
fn curves_and_surfaces_leave_their_hull_outside_the_range() {
    let c = claim(document(), "LH-gb2");
    assert_eq!(c["verdict"], "holds", "{c}");
    for (value, k, edge) in [
        (3, 7, "2x + y ≤ 4 (edge P1P2)"),
        (-4, 1, "y ≥ 0 (edge P2P0)"),
    ] {
        let shown = format!("{value}").replace('-', "−");
        let e = item(c, &format!("curve, λ1 = {shown}"));
        assert_eq!(e["status"], "holds", "{e}");
        assert!(e["text"].as_str().unwrap().contains(edge), "{e}");
        let w = &e["witness"];
        let t = q(&point_sympy(w, "t"));
        assert_eq!(t, r(k, 20));
        let at = |t: &Rational| combine(&gb2(t, &int(value), &int(-1)), &TRIANGLE_POINTS);
        let point = at(&t);
        assert_eq!((q(&value_sympy(w, "x")), q(&value_sympy(w, "y"))), point);
        assert!(!inside(&point, &TRIANGLE));
        // every earlier sample lies in the hull
        assert!((0..k).all(|j| inside(&at(&r(j, 20)), &TRIANGLE)));
    }
    // the surface over the net P_ij = (j, i, (0, 2, 2)_i)
    let surface = |u: &Rational, v: &Rational, l1: i64| {
        let (bu, bv) = (gb2(u, &int(l1), &int(-1)), gb2(v, &int(l1), &int(-1)));
        let mut s = [int(0), int(0), int(0)];
        for (i, wu) in bu.iter().enumerate() {
            for (j, wv) in bv.iter().enumerate() {
                let p = [j as i64, i as i64, [0, 2, 2][i]];
                for (coordinate, x) in s.iter_mut().zip(p) {
                    *coordinate += wu.clone() * wv * int(x);
                }
            }
        }
        s
    };
    for (value, outside) in [(3, "z > 2"), (-4, "x < 0")] {
        let shown = format!("{value}").replace('-', "−");
        let e = item(c, &format!("surface, λ1 = {shown}"));
        assert_eq!(e["status"], "holds", "{e}");
        assert!(e["text"].as_str().unwrap().contains(outside), "{e}");
        let w = &e["witness"];
        let (u, v) = (q(&point_sympy(w, "u")), q(&point_sympy(w, "v")));
        let s = surface(&u, &v, value);
        assert_eq!(["x", "y", "z"].map(|n| q(&value_sympy(w, n))), s, "{value}");
        assert!(s.iter().any(|x| *x < 0 || *x > 2), "{s:?}");
    }

    let c = claim(document(), "LH-hmh");
    assert_eq!(c["verdict"], "holds", "{c}");
    let e = item(c, "curve, λ = 3");
    assert!(
        e["text"].as_str().unwrap().contains("y ≤ 2 (edge P1P2)"),
        "{e}"
    );
    let w = &e["witness"];
    let (s, cs) = (q(&point_sympy(w, "s")), q(&point_sympy(w, "c")));
    assert_eq!(s.clone() * &s + cs.clone() * &cs, 1);
    assert_eq!(s.clone() / (int(1) + cs.clone()), r(1, 5));
    let weights = hmh(&s, &cs, &int(3), &int(-1));
    let point = combine(&weights, &[(0, 0), (1, 2), (3, 2), (4, 0)]);
    assert_eq!((q(&value_sympy(w, "x")), q(&value_sympy(w, "y"))), point);
    assert!(point.1 > 2 && weights[0] < 0, "{point:?} {weights:?}");

    let c = claim(document(), "LH-inside");
    assert_eq!(c["verdict"], "not-checkable", "{c}");
    for part in ["curve, λ1 = 1/2", "surface, λ1 = 1/2"] {
        assert_eq!(item(c, part)["status"], "not-checkable", "{part}");
    }
    let c = claim(document(), "LH-free");
    assert_eq!(c["verdict"], "not-checkable", "{c}");
    assert!(
        evidence_text(c).contains("another number of parameters"),
        "{c}"
    );
}

// ------------------------------------------------------------- table-count

/// `survey.tsv`, its columns derived from the formulas (SymPy), row 8 (the
/// document's own basis) excluded: 7 bases; shape parameters 2: 4, 1: 2,
/// 3: 1 (a majority, strictly ordered); kinds trigonometric 3, polynomial
/// 3, rational 1 (no plurality); degree 3: 3, 2: 2, 4: 2; 5 before 2010.
#[test]
fn counts_quoted_from_a_survey_of_bases() {
    let c = claim(document(), "TC-holds");
    assert_eq!(c["verdict"], "holds", "{c}");
    let text = evidence_text(c);
    for line in [
        "recomputed rows of Table S.1 other than those with Basis = this document: HMH at lambda = mu = m = 7",
        "recomputed rows with Kind = trigonometric = 3",
        "recomputed rows with Year < 2010 = 5",
        "Degree = 3: 3, Degree = 2: 2, Degree = 4: 2",
        "more than half of the 7 rows are rows with Shape parameters = 2",
        "Shape parameters = 2: 4, Shape parameters = 1: 2, Shape parameters = 3: 1",
    ] {
        assert!(text.contains(line), "{line}: {text}");
    }
    let c = claim(document(), "TC-miscount");
    assert_eq!(c["verdict"], "fails", "{c}");
    let w = &c["witness"];
    assert_eq!(
        (value_sympy(w, "quoted"), value_sympy(w, "recomputed")),
        ("8".into(), "7".into())
    );
    let c = claim(document(), "TC-most");
    assert_eq!(c["verdict"], "fails", "{c}");
    assert!(
        evidence_text(c)
            .contains("Kind = trigonometric: 3, Kind = polynomial: 3, Kind = rational: 1"),
        "{c}"
    );
    let c = claim(document(), "TC-order");
    assert_eq!(c["verdict"], "fails", "{c}");
    assert!(
        evidence_text(c)
            .contains("Shape parameters = 2: 4, Shape parameters = 3: 1, Shape parameters = 1: 2"),
        "{c}"
    );
    let c = claim(document(), "TC-malformed");
    assert_eq!(c["verdict"], "not-checkable", "{c}");
    assert!(evidence_text(c).contains("no column `Surface`"), "{c}");
}

// ----------------------------------------------------------- table-compare

/// The cells of a row of `runge-errors.txt` (the summary's `Ave. Error`, a
/// segment row of a table), as printed.
fn cells(table: &str, row: &str) -> Vec<Rational> {
    let text = std::fs::read_to_string(example("session5-checks-b/runge-errors.txt"))
        .expect("runge-errors.txt");
    let body = text
        .split(&format!("== {table} |"))
        .nth(1)
        .and_then(|t| t.split("\n== ").next())
        .expect("the table");
    body.lines()
        .find_map(|l| l.strip_prefix(&format!("{row}\t")))
        .unwrap_or_else(|| panic!("{row} in {table}"))
        .split('\t')
        .map(decimal)
        .collect()
}

/// The C¹ Hermite interpolants of `10/(1 + x²)` by HMH at (λ, μ) = (1, 1),
/// (1, −1), (−1, 1), (1/2, 1/2) (SymPy, mpmath): by Ave. Error (1/2, 1/2) <
/// (1, 1) < (−1, 1) < (1, −1); before tuning (λ = μ = 0) one curve; (1, 1)
/// and (−1, 1) agree on segment 1 only (`g'(0) = 0`: λ does not enter); the
/// Before Error row ties all four, so no scheme is strictly least.
#[test]
fn readings_between_the_error_tables_of_four_schemes() {
    let c = claim(document(), "CMP-holds");
    assert_eq!(c["verdict"], "holds", "{c}");
    let ave = cells("R.5", "Ave. Error"); // proposed, Majeed, Han, Usman
    for (id, relation) in [("CMP-order", "less"), ("CMP-least", "greater")] {
        let c = claim(document(), id);
        assert_eq!(c["verdict"], "fails", "{id}: {c}");
        let w = &c["witness"];
        assert_eq!(w["stated"], relation, "{id}: {w}");
        assert_eq!(q(&point_sympy(w, "proposed")), ave[0]);
        assert_eq!(q(&point_sympy(w, "Usman")), ave[3]);
        assert!(ave[3] < ave[0]);
    }
    let c = claim(document(), "CMP-equal");
    assert_eq!(c["verdict"], "fails", "{c}");
    let w = &c["witness"];
    let (a, b) = (cells("R.1", "2"), cells("R.3", "2"));
    assert_eq!(q(&point_sympy(w, "proposed₂")), a[1]);
    assert_eq!(q(&point_sympy(w, "Han₂")), b[1]);
    assert_ne!(a[1], b[1]);
    assert!(
        evidence_text(c).contains("HMH (1, 1) = HMH (-1, 1) in 1 of 3 segments"),
        "{c}"
    );
    let c = claim(document(), "CMP-count");
    assert_eq!(c["verdict"], "fails", "{c}");
    let w = &c["witness"];
    assert_eq!(
        (value_sympy(w, "quoted"), value_sympy(w, "recomputed")),
        ("2".into(), "1".into())
    );

    // a tie for the smallest value: neither scheme is least, whichever is
    // printed first (the defect fixed with this test: the first printed held)
    let before = cells("R.5", "Before Error");
    assert!(before.iter().all(|x| *x == before[0]));
    let c = claim(document(), "CMP-tie");
    assert_eq!(c["verdict"], "fails", "{c}");
    for scheme in ["HMH (1/2, 1/2)", "HMH (1, 1)"] {
        let e = item(c, &format!("Runge: {scheme} least"));
        assert_eq!(e["status"], "fails", "{scheme}: {e}");
        assert!(
            e["text"]
                .as_str()
                .unwrap()
                .contains("no scheme is strictly least"),
            "{e}"
        );
        assert_eq!(e["witness"]["stated"], "greater", "{e}");
    }
    assert_eq!(verdict(document(), "CMP-unmeasured"), "not-checkable");
}

// ------------------------------------------------------------- data-values

/// `gb2-samples.tsv`: `f(x) = y(x/4)`, `y = 8b1 + 6b2` at `λ1 = 1/2`,
/// `λ2 = −1`: `0, 123/32, 23/4, 201/32, 6`, one zero.
#[test]
fn queries_on_the_samples_of_a_gb2_function() {
    let y = |x: i64| {
        let b = gb2(&r(x, 4), &r(1, 2), &int(-1));
        int(8) * &b[1] + int(6) * &b[2]
    };
    let c = claim(document(), "DV-holds");
    assert_eq!(c["verdict"], "holds", "{c}");
    let c = claim(document(), "DV-misquote");
    assert_eq!(c["verdict"], "fails", "{c}");
    let w = &c["witness"];
    assert_eq!(q(&value_sympy(w, "printed f")), y(3));
    assert_eq!(q(&value_sympy(w, "stated")), r(628, 100));
    let c = claim(document(), "DV-several");
    assert_eq!(c["verdict"], "fails", "{c}");
    let zeros = (0..=4).filter(|x| y(*x) == 0).count();
    assert!(
        evidence_text(c).contains(&format!("{zeros} of 5 exactly 0")),
        "{c}"
    );
    assert_eq!(zeros, 1);
    let c = claim(document(), "DV-no-knot");
    assert_eq!(c["verdict"], "not-checkable", "{c}");
    assert!(evidence_text(c).contains("has no knot x = 2.5"), "{c}");
}

// ----------------------------------------------------- interpolant-maximum

/// Piece 4 (`[3, 4]`, `m = 1`) of the C¹ interpolant (4.21) of the samples:
/// HMH at `λ = μ = 1` in `θ = π(x − 3)/2` with `V = f₃`, `W = f₃ + 2d₃/(3π)`,
/// `X = f₄ − 2d₄/(3π)`, `Y = f₄`: the arithmetic-mean slopes (Hussain &
/// Sarfraz 2009, h = 1) `d₃ = (Δ₂ + Δ₃)/2 = 1/8`, `d₄ = Δ₃ + (Δ₃ − Δ₂)/2 =
/// −11/16` of `f₂, f₃, f₄ = 23/4, 201/32, 6`.
fn piece4(theta: f64) -> f64 {
    let pi = std::f64::consts::PI;
    let (f2, f3, f4) = (23.0 / 4.0, 201.0 / 32.0, 6.0);
    let (delta2, delta3) = (f3 - f2, f4 - f3);
    let (d3, d4) = ((delta2 + delta3) / 2.0, delta3 + (delta3 - delta2) / 2.0);
    let points = [
        f3,
        f3 + 2.0 * d3 / (3.0 * pi),
        f4 - 2.0 * d4 / (3.0 * pi),
        f4,
    ];
    let (s, c) = theta.sin_cos();
    let b = [
        (1.0 - s).powi(2) * (1.0 - s),
        s * (1.0 - s) * (3.0 - s),
        c * (1.0 - c) * (3.0 - c),
        (1.0 - c).powi(2) * (1.0 - c),
    ];
    b.iter().zip(points).map(|(b, p)| b * p).sum()
}

/// SymPy/mpmath: the maximum lies on piece 4, `6.28792987…` at `x ≈ 3.1084`,
/// above piece 3's `6.28125`; "about 6.29" and "about 6.3" hold, "about 6.28"
/// fails (at `z = 1/11`, `s = 11/61`, `c = 60/61`: `P = (8541891π +
/// 67595)/(1361886π) ≥ 6.285`), "near x = 2.5" fails; about GB2 not decided.
#[test]
fn the_maximum_of_the_c1_interpolant_of_the_samples() {
    let c = claim(document(), "IM-holds");
    assert_eq!(c["verdict"], "holds", "{c}");
    for e in c["evidence"].as_array().unwrap() {
        if e["status"].is_string() {
            assert_eq!(e["status"], "holds", "{e}");
        }
    }
    let text = evidence_text(c);
    assert!(text.contains("% below 6.29;"), "{text}");
    let sampled = (0..=100_000)
        .map(|k| piece4(std::f64::consts::FRAC_PI_2 * f64::from(k) / 100_000.0))
        .fold(f64::MIN, f64::max);
    let bracket: Vec<f64> = text
        .split("piece 4 [3, 4]: max P ∈ [")
        .nth(1)
        .and_then(|t| t.split(']').next())
        .expect("piece 4")
        .split(", ")
        .map(|x| x.parse().unwrap())
        .collect();
    assert!(
        bracket[0] <= sampled && sampled <= bracket[1],
        "{bracket:?} {sampled}"
    );
    assert!(sampled > 201.0 / 32.0 && (6.285..6.295).contains(&sampled));

    let c = claim(document(), "IM-about");
    assert_eq!(c["verdict"], "fails", "{c}");
    let w = &c["witness"];
    let (s, cs) = (q(&point_sympy(w, "s")), q(&point_sympy(w, "c")));
    assert_eq!(s.clone() / (int(1) + cs), r(1, 11));
    assert_eq!(point_sympy(w, "W3"), "(603*pi + 8)/(96*pi)");
    assert_eq!(point_sympy(w, "X3"), "(144*pi + 11)/(24*pi)");
    assert_eq!(value_sympy(w, "P"), "(8541891*pi + 67595)/(1361886*pi)");
    assert_eq!(q(&value_sympy(w, "upper end of about 6.28")), r(1257, 200));
    let pi = std::f64::consts::PI;
    let at = piece4((11.0f64).atan2(60.0));
    assert!((at - (8_541_891.0 * pi + 67_595.0) / (1_361_886.0 * pi)).abs() < 1e-12);
    assert!(at > 6.285);

    let c = claim(document(), "IM-near");
    assert_eq!(c["verdict"], "fails", "{c}");
    assert!(evidence_text(c).contains("lies on piece 4 [3, 4]"), "{c}");
    // "then drops" with the maximum on an inner piece (by hand: P(x_i) = f_i
    // and the maximum is at least max fᵢ = 8 = f₂): after it the data 8, 4,
    // 1 do not rise, and a decrease between them is not certified; the
    // data 8, 4, 6 rise from f₃ = 4 to f₄ = 6, so P rises after its maximum
    let c = claim(document(), "IM-drops-early");
    assert_eq!(c["verdict"], "not-checkable", "{c}");
    let c = claim(document(), "IM-rises-after");
    assert_eq!(c["verdict"], "fails", "{c}");
    assert!(
        evidence_text(c).contains("P(x_3) = f_3 = 4 < P(x_4) = f_4 = 6"),
        "{c}"
    );
    let c = claim(document(), "IM-gb2");
    assert_eq!(c["verdict"], "not-checkable", "{c}");
    assert!(
        evidence_text(c).contains("is not exactly that basis"),
        "{c}"
    );
}
