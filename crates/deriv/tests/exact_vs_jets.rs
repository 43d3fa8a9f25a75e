//! Exact endpoint-derivative tables against numeric ones.
//!
//! The exact tables are built once in the symbolic ring, with every shape
//! parameter and the interval length `h` as symbols, so the entries are
//! rational functions of the parameters, `h` and `pi`. For random rational
//! parameter values inside the published ranges and random rational `h`,
//! each entry is evaluated in 256-bit MPFR and compared with the table
//! computed directly by `endpoint_derivatives` on MPFR and on f64 numbers.
//! The two sides share the jet code but not the ring: one runs the
//! recurrences on polynomials and reduces exactly, the other rounds at every
//! step, and only the former is evaluated afterwards.

use std::cmp::Ordering::{Equal, Less};

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use rug::Rational;
use trig_core::{Bound, Family, Mpfr, ParamSpec, Ring};
use trig_deriv::{End, Wrt, endpoint_derivatives};
use trig_symbolic::Sym;

/// Orders 0–6.
const K: usize = 7;
const PREC: u32 = 256;
const CASES: u32 = 32;
const ENDS: [End; 2] = [End::Start, End::End];
const WRTS: [Wrt; 3] = [Wrt::Angle, Wrt::U, Wrt::X];
/// Stand-in for an unbounded end of a parameter range.
const CAP: i64 = 1000;

/// MPFR against the exact values: 2⁻²⁰⁰ relative (absolute below 1).
/// 256-bit arithmetic rounds each operation to 2⁻²⁵⁷ relative; an entry
/// takes O(K²) jet operations on terms of magnitude ≲ 10⁷ < 2²⁴ (see
/// [`F64_TOL`]), plus the rounding of the parameters, h and π, so the error
/// is ≲ 2⁻²²⁵ (measured: ≤ 1.3·10⁻⁷² ≈ 2⁻²³⁹) and 2⁻²⁰⁰ leaves ample headroom
/// while any mathematical discrepancy (ordinarily O(1)) is caught.
fn mpfr_tol() -> Mpfr {
    Mpfr::from_rational(PREC, &(Rational::from(1) >> 200u32))
}

/// f64 against the exact values: 1e-9 relative (absolute below 1).
///
/// An order-k entry in x is rateᵏ times the θ-derivative, with
/// rate = π/(2h) ≤ 2π for h ≥ 1/4, so rateᵏ ≤ (2π)⁶ ≈ 6·10⁴. The θ-derivative
/// is k!·x_k, x_k a sum of O(K²) products of the atoms' Taylor coefficients
/// (±1/j!, exact seeds 0, 1, π/2) and of coefficients that are at most a few
/// hundred for |parameters| ≤ 4 (the thesis quadratic's β ≤ 1000 enters only
/// through β/(β+1) ≤ 1 and 1/(β+1)). So the terms entering one entry are of
/// magnitude ≲ 10⁷ and a few f64 roundings of them (2⁻⁵³ ≈ 1.1·10⁻¹⁶ each)
/// give ≲ 10⁻⁹ absolute; when the entry is itself large the same count of
/// roundings is relative to it. Measured: the worst error over 1500 random
/// cases (× 72 tables) was 1.4·10⁻¹⁰, and 3.1·10⁻¹⁰ with h fixed at 1/4
/// (Usman, order 6 in x, an exact zero) — about 3× below the bound, and
/// the error is a deterministic function of parameters and h that peaks at
/// the range end, so the random test does not flake. A genuine discrepancy is
/// O(1) and is far above it.
const F64_TOL: f64 = 1e-9;

/// The families with formulas.
fn families() -> Vec<Family> {
    Family::ALL
        .into_iter()
        .filter(Family::has_formulas)
        .collect()
}

/// One exact table with its coordinates.
struct Exact {
    family: Family,
    end: End,
    wrt: Wrt,
    table: Vec<Vec<Sym>>,
}

/// The exact tables for every family, end and convention.
fn exact_tables() -> Vec<Exact> {
    let mut out = Vec::new();
    for family in families() {
        let params: Vec<Sym> = family
            .info()
            .params
            .iter()
            .map(|spec| Sym::var(spec.name))
            .collect();
        for end in ENDS {
            for wrt in WRTS {
                let table =
                    endpoint_derivatives::<Sym, K>(family, &params, end, wrt, &Sym::var("h"));
                out.push(Exact {
                    family,
                    end,
                    wrt,
                    table,
                });
            }
        }
    }
    out
}

/// A random rational strictly inside / on the closed ends of `spec`'s range:
/// `lo + (hi − lo)·n/d` with `n` drawn from `raw` (unbounded ends at ±[`CAP`]).
fn pick(spec: &ParamSpec, raw: u32, d: u32) -> Rational {
    let lo = spec.range.lo.value().unwrap_or(Rational::from(-CAP));
    let hi = spec.range.hi.value().unwrap_or(Rational::from(CAP));
    let n_lo = u32::from(matches!(spec.range.lo, Bound::Open(..)));
    let n_hi = d - u32::from(matches!(spec.range.hi, Bound::Open(..)));
    let n = n_lo + raw % (n_hi - n_lo + 1);
    let x = lo.clone() + (hi - lo) * Rational::from((n, d));
    assert!(
        spec.range.contains(&x),
        "{} = {x} outside {}",
        spec.name,
        spec.range
    );
    x
}

/// Random rational in [1/4, 4]: `n/d` with `d ≤ 60`.
fn pick_h(raw: u32, d: u32) -> Rational {
    let (n_lo, n_hi) = (d.div_ceil(4), 4 * d);
    Rational::from((n_lo + raw % (n_hi - n_lo + 1), d))
}

/// Exact parameter values for every family, drawn from one random vector.
type Draw = (Vec<(u32, u32)>, (u32, u32));

fn draw_strategy() -> impl Strategy<Value = Draw> {
    let count: usize = families().iter().map(|f| f.info().params.len()).sum();
    (
        prop::collection::vec((any::<u32>(), 2u32..=97), count),
        (any::<u32>(), 1u32..=60),
    )
}

/// Per family, the parameter values (in `info().params` order), and `h`.
fn values(draw: &Draw) -> (Vec<(Family, Vec<Rational>)>, Rational) {
    let (raws, (hr, hd)) = draw;
    let mut raws = raws.iter();
    let params = families()
        .into_iter()
        .map(|family| {
            let p = family
                .info()
                .params
                .iter()
                .map(|spec| {
                    let (r, d) = raws.next().expect("one draw per parameter");
                    pick(spec, *r, *d)
                })
                .collect();
            (family, p)
        })
        .collect();
    (params, pick_h(*hr, *hd))
}

fn mp(q: &Rational) -> Mpfr {
    Mpfr::from_rational(PREC, q)
}

/// The exact table evaluated in 256-bit MPFR.
fn evaluate(e: &Exact, params: &[Rational], h: &Rational) -> Vec<Vec<Mpfr>> {
    let specs = e.family.info().params;
    let like = mp(h);
    let assign = |name: &str| -> Option<Mpfr> {
        match name {
            "h" => Some(mp(h)),
            "pi" => Some(like.pi()),
            _ => specs
                .iter()
                .position(|s| s.name == name)
                .map(|i| mp(&params[i])),
        }
    };
    e.table
        .iter()
        .map(|row| {
            row.iter()
                .map(|x| {
                    x.eval(&like, &assign).unwrap_or_else(|err| {
                        panic!("{} {} {}: {x}: {err:?}", e.family.info().id, e.end, e.wrt)
                    })
                })
                .collect()
        })
        .collect()
}

fn abs(x: Mpfr) -> Mpfr {
    Mpfr(x.0.abs())
}

/// The first entry where `|got − want| > tol·max(1, |want|)`, described;
/// `None` when the tables agree (same shape required).
fn mismatch(want: &[Vec<Mpfr>], got: &[Vec<Mpfr>], tol: &Mpfr) -> Option<String> {
    if want.len() != got.len() {
        return Some(format!("{} functions vs {}", want.len(), got.len()));
    }
    for (i, (w, g)) in want.iter().zip(got).enumerate() {
        if w.len() != K || g.len() != K {
            return Some(format!("function {i}: {} orders vs {}", w.len(), g.len()));
        }
        for (k, (a, b)) in w.iter().zip(g).enumerate() {
            let one = a.int(1);
            let mag = abs(a.clone());
            let scale = if mag > one { mag } else { one };
            let err = abs(b.clone() - a);
            // NaN (e.g. a division by zero) must fail too
            if !matches!(err.partial_cmp(&(tol.clone() * &scale)), Some(Less | Equal)) {
                return Some(format!(
                    "function {i} order {k}: exact {a}, numeric {b}, error {err}"
                ));
            }
        }
    }
    None
}

fn numeric_mpfr(e: &Exact, params: &[Rational], h: &Rational) -> Vec<Vec<Mpfr>> {
    let p: Vec<Mpfr> = params.iter().map(mp).collect();
    endpoint_derivatives::<Mpfr, K>(e.family, &p, e.end, e.wrt, &mp(h))
}

/// The f64 table, converted exactly to MPFR for the comparison.
fn numeric_f64(e: &Exact, params: &[Rational], h: &Rational) -> Vec<Vec<Mpfr>> {
    let p: Vec<f64> = params.iter().map(Rational::to_f64).collect();
    endpoint_derivatives::<f64, K>(e.family, &p, e.end, e.wrt, &h.to_f64())
        .into_iter()
        .map(|row| row.into_iter().map(|x| Mpfr::from_f64(PREC, x)).collect())
        .collect()
}

type Numeric = fn(&Exact, &[Rational], &Rational) -> Vec<Vec<Mpfr>>;

/// Runs the property: every exact table agrees with `numeric` within `tol`.
fn check_all(numeric: Numeric, tol: &Mpfr) {
    let tables = exact_tables();
    assert_eq!(tables.len(), 13 * ENDS.len() * WRTS.len());
    let mut runner = TestRunner::new(Config {
        cases: CASES,
        failure_persistence: None,
        ..Config::default()
    });
    runner
        .run(&draw_strategy(), |draw| {
            let (params, h) = values(&draw);
            for e in &tables {
                let p = &params
                    .iter()
                    .find(|(f, _)| *f == e.family)
                    .expect("every family drawn")
                    .1;
                let want = evaluate(e, p, &h);
                let got = numeric(e, p, &h);
                if let Some(m) = mismatch(&want, &got, tol) {
                    let id = e.family.info().id;
                    return Err(TestCaseError::fail(format!(
                        "{id} {} wrt {} params {p:?} h {h}: {m}",
                        e.end, e.wrt
                    )));
                }
            }
            Ok(())
        })
        .unwrap();
}

#[test]
fn exact_tables_match_mpfr_jets_to_2_pow_minus_200() {
    check_all(numeric_mpfr, &mpfr_tol());
}

#[test]
fn exact_tables_match_f64_jets_to_1e_minus_9() {
    check_all(numeric_f64, &Mpfr::from_f64(PREC, F64_TOL));
}

/// The comparison is not vacuous: the wrong end, or derivatives in θ taken
/// for derivatives in u, are rejected for every family, at both tolerances.
#[test]
fn wrong_end_and_wrong_convention_are_detected() {
    let tables = exact_tables();
    let h = Rational::from((3, 2));
    let mpfr = mpfr_tol();
    let f64_tol = Mpfr::from_f64(PREC, F64_TOL);
    for e in &tables {
        let info = e.family.info();
        // mid-range parameters (draw 1 of 2 ⇒ the midpoint; β ⇒ 500)
        let p: Vec<Rational> = info.params.iter().map(|s| pick(s, 1, 2)).collect();
        let want = evaluate(e, &p, &h);
        let other_end = match e.end {
            End::Start => End::End,
            End::End => End::Start,
        };
        let swapped = Exact {
            family: e.family,
            end: other_end,
            wrt: e.wrt,
            table: Vec::new(),
        };
        for (name, got) in [
            ("mpfr", numeric_mpfr(&swapped, &p, &h)),
            ("f64", numeric_f64(&swapped, &p, &h)),
        ] {
            let tol = if name == "mpfr" { &mpfr } else { &f64_tol };
            assert!(
                mismatch(&want, &got, tol).is_some(),
                "{} {} vs {other_end} ({name}) not told apart",
                info.id,
                e.end
            );
        }
        // θ vs u differ by (π/2)^k from order 1 on (polynomial families
        // have no angle: there both mean t).
        if e.wrt == Wrt::U && info.variable.is_trigonometric() {
            let angle = Exact {
                end: e.end,
                wrt: Wrt::Angle,
                ..swapped
            };
            assert!(
                mismatch(&want, &numeric_mpfr(&angle, &p, &h), &mpfr).is_some(),
                "{} {}: θ and u not told apart",
                info.id,
                e.end
            );
        }
    }
    // and the matching table does agree (same parameters, same end)
    let e = &tables[0];
    let p: Vec<Rational> = e
        .family
        .info()
        .params
        .iter()
        .map(|s| pick(s, 1, 2))
        .collect();
    assert_eq!(
        mismatch(&evaluate(e, &p, &h), &numeric_mpfr(e, &p, &h), &mpfr),
        None
    );
}
