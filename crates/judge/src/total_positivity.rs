//! The total-positivity judge: "the basis is normalized totally positive,
//! hence variation diminishing (and convexity preserving for planar
//! curves)" for any basis, decided by the totally positive factorisation
//! of [`trig_certify::total_positivity`] and refuted by a collocation
//! matrix with a negative minor.
//!
//! A basis `(b₀, …, b_{n−1})` is totally positive (TP) when every
//! collocation matrix `(b_j(x_i))`, `x₀ < ⋯ < x_m`, has all minors `≥ 0`;
//! normalized TP (also `Σ bⱼ = 1`) makes every curve `Σ bⱼPⱼ` variation
//! diminishing — it crosses a line (plane) no more often than its control
//! polygon — and so a planar curve with a convex control polygon is convex
//! (Goodman, "Shape preserving representations", 1989; Carnicer & Peña,
//! "Totally positive bases for shape preserving curve design", 1993).

use rug::Rational;
use trig_certify::total_positivity::{NegativeMinor, TpCertificate, TpError, certify, refute};
use trig_certify::tp_box::BoxOutcome;
use trig_certify::{Bound, ParamBox};
use trig_core::{ParamRange, Parameter};
use trig_symbolic::Sym;

use super::nonnegative::pieces;
use super::tp_wronskian::{WRONSKIAN, by_wronskians};
use super::unity::unity;
use crate::exact::ExactBasis;
use trig_verdict::evidence::{Evidence, Kind};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;
use trig_verdict::witness::witness;

/// How total positivity is decided, as the report states it.
pub const TOTALLY_POSITIVE: &str = "certified: totally positive factorisation — z = tan(θ/2) (or t) maps the domain increasingly onto [0, 1]; the numerators over their positive common denominator are written in the Bernstein basis of their degree (elevated up to 4 times); all minors of that coefficient matrix ≥ 0, exactly, prove total positivity (Cauchy–Binet with the totally positive Bernstein basis); with a parameter every minor is a polynomial in it and the set where all are ≥ 0 is decided exactly (Sturm sequences, algebraic ends); refutation: a collocation matrix at exact rational points with a negative minor";

/// What normalized total positivity gives, as the evidence states it.
pub const CONSEQUENCES: &str = "normalized TP (TP and Σ b_i = 1) ⇒ variation diminishing: a curve Σ b_i P_i crosses any line (plane) no more often than its control polygon; hence a planar curve with a convex control polygon is convex (convexity preservation follows from variation diminishing)";

/// Decides "normalized totally positive on the range" (the claim's range,
/// else the declared one): partition of unity and total positivity.
pub fn normalized_totally_positive<B: ExactBasis>(
    basis: &B,
    range: Option<&ParamRange>,
) -> Verdict {
    let tp = totally_positive(basis, range);
    // the method of the part that decided it: the factorisation, or the
    // Wronskian criterion where that took over
    let method = if tp.method == WRONSKIAN {
        WRONSKIAN
    } else {
        TOTALLY_POSITIVE
    };
    let mut v = Verdict::all(
        method,
        vec![
            ("partition of unity".into(), unity(basis)),
            ("total positivity".into(), tp),
        ],
    );
    v.evidence.insert(0, CONSEQUENCES);
    v
}

/// Decides "every collocation matrix has all minors ≥ 0" for every
/// parameter in the range.
pub fn totally_positive<B: ExactBasis>(basis: &B, range: Option<&ParamRange>) -> Verdict {
    let (trig, fs, _) = match pieces(basis) {
        Ok(p) => p,
        Err(why) => {
            return by_wronskians(
                basis,
                range,
                &format!(
                    "the factorisation needs functions polynomial in sin, cos or the variable on one standard domain ({why})"
                ),
            );
        }
    };
    if fs.len() != basis.function_names().len() {
        return Verdict::not_checkable(
            "the standard domain splits into several pieces: the factorisation needs one increasing change of variable over the whole domain",
        );
    }
    let params = basis.parameters();
    let (param, published) = match params.as_slice() {
        [] => (None, None),
        [p] => (Some(p), Some(range.unwrap_or(&p.range))),
        _ => return several(basis, &fs, trig, &params),
    };
    let bx = published.map(ParamBox::from_range);
    let named = param.map(|p| p.name.as_str()).zip(bx.as_ref());
    let cert = match certify(&fs, trig, named) {
        Ok(c) => c,
        Err(TpError::Factorisation(why)) => {
            return Verdict::not_checkable(format!("no factorisation: {why}"));
        }
        Err(TpError::TooLarge(too_large)) => {
            let why = match param {
                Some(_) => format!(
                    "the totally positive factorisation checks every minor of its coefficient matrix, and {too_large}; with a parameter the bidiagonal factorisation (Neville elimination), which would not enumerate them, is not implemented"
                ),
                None => format!(
                    "the bidiagonal factorisation (Neville elimination) of the coefficient matrix was not found, and {too_large}"
                ),
            };
            // a negative collocation minor still refutes (without a
            // parameter: at the basis itself)
            if param.is_none() {
                if let Some(neg) = refute(&fs, trig, &[]) {
                    let evidence = vec![Evidence::note(why), refutation(basis, &neg, &[], trig)];
                    return Verdict::new(Status::Fails, TOTALLY_POSITIVE, evidence);
                }
            }
            return Verdict::not_checkable(why);
        }
    };
    let symbol = param.map_or("p", |p| p.symbol.as_str());
    let mut evidence = vec![certificate_line(&cert, symbol, published)];
    if let Some(b) = &bx {
        // the same minors on the whole line: where this certificate reaches
        let whole = ParamBox {
            lo: Bound::Infinite,
            hi: Bound::Infinite,
        };
        match cert.set_within(&whole) {
            Ok(set) => evidence.push(Evidence::note(format!(
                "on the whole line the minors of this certificate (degree {}) are all ≥ 0 exactly for {symbol} ∈ {}; the range decided is {b}",
                cert.factorisation.degree,
                set.describe(symbol)
            ))),
            Err(why) => evidence.push(Evidence::note(format!(
                "the minors of this certificate on the whole line: {why}"
            ))),
        }
    }
    if cert.set.covers {
        return Verdict::new(Status::Holds, TOTALLY_POSITIVE, evidence);
    }
    // refute: a negative collocation minor at a parameter value where the
    // certificate fails (or, without a parameter, at all)
    let tries: Vec<Option<Rational>> = match param {
        Some(_) => cert
            .set
            .failures
            .iter()
            .map(|f| Some(f.p.clone()))
            .collect(),
        None => vec![None],
    };
    for p in tries {
        let at: Vec<(&str, &Rational)> = param
            .map(|q| q.name.as_str())
            .zip(p.as_ref())
            .into_iter()
            .collect();
        if let Some(neg) = refute(&fs, trig, &at) {
            let shown: Vec<(String, String, Rational)> = param
                .zip(p)
                .map(|(q, v)| (q.name.clone(), q.symbol.clone(), v))
                .into_iter()
                .collect();
            evidence.push(refutation(basis, &neg, &shown, trig));
            return Verdict::new(Status::Fails, TOTALLY_POSITIVE, evidence);
        }
    }
    evidence.push(Evidence::note(
        "no collocation matrix with a negative minor was found at the failing parameter values (rational grids of [0, 1] in z)",
    ));
    // where the certificate stalls, the Wronskian criterion may decide
    with_wronskians(basis, range, evidence)
}

/// The certificate in words: degrees, matrix size, minors, the set.
fn certificate_line(
    cert: &TpCertificate,
    symbol: &str,
    published: Option<&ParamRange>,
) -> Evidence {
    let f = &cert.factorisation;
    let checked = match cert.neville {
        Some(b) => format!(
            "too large to enumerate its minors, it is the product of bidiagonal factors found by Neville elimination without row exchanges (Gasca & Peña), its {} multipliers and {} pivots all > 0 exactly, so it is totally positive",
            b.multipliers, b.pivots
        ),
        None => format!("{} nonzero minors checked exactly", cert.minors),
    };
    let text = format!(
        "{}; {checked}",
        factorisation_text(&f.common, cert.first_degree, f.degree, f.rows.len())
    );
    let text = match published {
        Some(r) => format!(
            "{text}: all ≥ 0 exactly for {symbol} ∈ {} within the range {r}",
            cert.set.describe(symbol)
        ),
        None if cert.set.covers => format!("{text}: all ≥ 0"),
        None => format!("{text}: not all ≥ 0"),
    };
    let line = Evidence::new(Kind::Certificate, text);
    if cert.set.covers {
        line.about("total positivity", Status::Holds)
    } else {
        line
    }
}

/// The refuting minor as an exact witness: the parameter, the points, the
/// submatrix values and the minor.
fn refutation<B: ExactBasis>(
    basis: &B,
    neg: &NegativeMinor,
    at: &[(String, String, Rational)],
    trig: bool,
) -> Evidence {
    let names = basis.function_names();
    let mut point: Vec<(String, Rational)> =
        at.iter().map(|(n, _, p)| (n.clone(), p.clone())).collect();
    let var = if trig { "z" } else { "t" };
    for (k, z) in neg.points.iter().enumerate() {
        point.push((format!("{var}{}", k + 1), z.clone()));
    }
    let mut values = Vec::new();
    let mut labels = Vec::new();
    for (k, row) in neg.values.iter().enumerate() {
        for (j, v) in neg.functions.iter().zip(row) {
            labels.push(format!("{}({var}{})", names[*j], k + 1));
            values.push(Sym::rational(v.clone()));
        }
    }
    labels.push("minor".into());
    values.push(Sym::rational(neg.minor.clone()));
    let shown: Vec<String> = point.iter().map(|(n, _)| n.clone()).collect();
    let mut w = witness(
        &point,
        &shown,
        labels.iter().map(String::as_str).zip(values).collect(),
    );
    if trig {
        let circle: Vec<String> = neg
            .points
            .iter()
            .map(|z| {
                let d = Rational::from(1) + z.clone() * z;
                let s = Rational::from(2) * z / d.clone();
                let c = (Rational::from(1) - z.clone() * z) / d;
                format!("(s, c) = ({s}, {c})")
            })
            .collect();
        w.note = Some(format!(
            "z = tan(θ/2), s = sin θ, c = cos θ: {}",
            circle.join(", ")
        ));
    }
    let order = neg.functions.len();
    let fns: Vec<&str> = neg.functions.iter().map(|j| names[*j].as_str()).collect();
    let at_text = if at.is_empty() {
        String::new()
    } else {
        format!(" at {}", equalities(at))
    };
    Evidence::new(
        Kind::Certificate,
        format!(
            "not totally positive{at_text}: the {order}×{order} minor of the collocation matrix of ({}) at {var} = {} is {} < 0 (exact)",
            fns.join(", "),
            neg.points
                .iter()
                .map(Rational::to_string)
                .collect::<Vec<_>>()
                .join(" < "),
            neg.minor
        ),
    )
    .about("total positivity", Status::Fails)
    .witnessed(Some(w))
}

/// The factorisation in words: the common factor, the Bernstein degree
/// (and the degree it was elevated to), the size of the matrix.
fn factorisation_text(common: &str, first_degree: usize, degree: usize, rows: usize) -> String {
    let elevated = if degree > first_degree {
        format!(", elevated to {degree}")
    } else {
        String::new()
    };
    format!(
        "numerators over the positive common factor {common} in z = tan(θ/2) (or t): Bernstein degree {first_degree}{elevated}; coefficient matrix {rows} × {}",
        degree + 1
    )
}

/// `λ = 1, μ = 1/2`.
fn equalities(at: &[(String, String, Rational)]) -> String {
    at.iter()
        .map(|(_, symbol, p)| format!("{symbol} = {p}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Total positivity with two or more parameters: every minor of the
/// factorisation, a polynomial in all of them, certified `≥ 0` on the box
/// of their ranges ([`trig_certify::tp_box`]); where a minor is negative,
/// a negative collocation minor at that parameter vector (or a corner of
/// the box) refutes.
fn several<B: ExactBasis>(basis: &B, fs: &[Sym], trig: bool, params: &[Parameter]) -> Verdict {
    let boxes: Vec<(&str, ParamBox)> = params
        .iter()
        .map(|p| (p.name.as_str(), ParamBox::from_range(&p.range)))
        .collect();
    let cert = match trig_certify::tp_box::certify(fs, trig, &boxes) {
        Ok(c) => c,
        Err(why) => {
            return Verdict::not_checkable(format!(
                "no totally positive factorisation was formed: {why}"
            ));
        }
    };
    let symbols: Vec<&str> = params.iter().map(|p| p.symbol.as_str()).collect();
    let on_box = params
        .iter()
        .map(|p| format!("{} ∈ {}", p.symbol, p.range))
        .collect::<Vec<_>>()
        .join(", ");
    let head = format!(
        "{}; {} nonzero minors, each a polynomial in {}",
        factorisation_text(&cert.common, cert.first_degree, cert.degree, cert.functions),
        cert.minors,
        symbols.join(", ")
    );
    let (rows, cols, point, value) = match cert.outcome {
        BoxOutcome::Covers { boxes } => {
            let line = Evidence::new(
                Kind::Certificate,
                format!("{head}: each certified ≥ 0 for {on_box} (exact Bernstein subdivision in the parameters, {boxes} boxes)"),
            )
            .about("total positivity", Status::Holds);
            return Verdict::new(Status::Holds, TOTALLY_POSITIVE, vec![line]);
        }
        BoxOutcome::Undecided(why) => {
            return Verdict::new(
                Status::NotCheckable,
                TOTALLY_POSITIVE,
                vec![Evidence::note(format!("{head}: {why}"))],
            );
        }
        BoxOutcome::Negative {
            rows,
            cols,
            point,
            value,
        } => (rows, cols, point, value),
    };
    let at = |values: &[Rational]| -> Vec<(String, String, Rational)> {
        params
            .iter()
            .zip(values)
            .map(|(p, v)| (p.name.clone(), p.symbol.clone(), v.clone()))
            .collect()
    };
    let mut evidence = vec![Evidence::note(format!(
        "{head}: the minor of rows {rows:?} and columns {cols:?} is {value} < 0 at {} (exact), so the certificate does not reach the whole box {on_box}",
        equalities(&at(&point))
    ))];
    // where the certificate fails, then the corners of the box
    let mut tries = vec![point];
    tries.extend(corners(params));
    for values in tries {
        let inside = params.iter().zip(&values).all(|(p, v)| p.range.contains(v));
        if !inside {
            continue;
        }
        let named: Vec<(&str, &Rational)> = params
            .iter()
            .map(|p| p.name.as_str())
            .zip(&values)
            .collect();
        if let Some(neg) = refute(fs, trig, &named) {
            evidence.push(refutation(basis, &neg, &at(&values), trig));
            return Verdict::new(Status::Fails, TOTALLY_POSITIVE, evidence);
        }
    }
    evidence.push(Evidence::note(
        "no collocation matrix with a negative minor was found there or at the corners of the box (rational grids of [0, 1] in z): the certificate is sufficient, not necessary",
    ));
    with_wronskians(basis, None, evidence)
}

/// Where the factorisation's certificate stalls: the Wronskian criterion
/// on the same range, its evidence after the certificate's.
fn with_wronskians<B: ExactBasis>(
    basis: &B,
    range: Option<&ParamRange>,
    mut evidence: Vec<Evidence>,
) -> Verdict {
    let wronskians = by_wronskians(
        basis,
        range,
        "the factorisation's certificate does not cover the range",
    );
    evidence.extend(wronskians.evidence);
    let method = if wronskians.status == Status::NotCheckable {
        TOTALLY_POSITIVE
    } else {
        WRONSKIAN
    };
    Verdict::new(wronskians.status, method, evidence)
}

/// The corners of the parameters' box at their closed finite ends.
fn corners(params: &[Parameter]) -> Vec<Vec<Rational>> {
    let ends = |p: &Parameter| -> Vec<Rational> {
        if p.range.pi {
            return Vec::new();
        }
        [&p.range.lo, &p.range.hi]
            .into_iter()
            .filter_map(|e| match e {
                trig_core::End::Closed(q) => Some(q.clone()),
                _ => None,
            })
            .collect()
    };
    params.iter().fold(vec![Vec::new()], |acc, p| {
        acc.iter()
            .flat_map(|prefix| {
                ends(p).into_iter().map(move |v| {
                    let mut next = prefix.clone();
                    next.push(v);
                    next
                })
            })
            .collect()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_specfile::Spec;

    /// `C(n, i) sin²ⁱt cos²⁽ⁿ⁻ⁱ⁾t` on `[0, π/2]`; with `lambda`, the first
    /// function times `1 + λ`, `λ ∈ [0, 1]`.
    fn sin2_bernstein(n: u64, lambda: bool) -> Spec {
        let mut text = String::from("id = \"sin2\"\ncitation = \"test\"\nvariable = \"angle\"\n");
        if lambda {
            text.push_str(
                "[[parameters]]\nname = \"lambda\"\nrange = \"[0, 1]\"\nsource = \"test\"\n",
            );
        }
        let mut binomial = 1u64;
        for i in 0..=n {
            let scale = if lambda && i == 0 {
                "(1 + lambda)*"
            } else {
                ""
            };
            text.push_str(&format!(
                "[[functions]]\nname = \"b{i}\"\nformula = \"{scale}{binomial}*sin(t)^{}*cos(t)^{}\"\n",
                2 * i,
                2 * (n - i)
            ));
            binomial = binomial * (n - i) / (i + 1);
        }
        Spec::from_str_named(&text, "sin2").unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn beyond_the_enumeration_of_minors_neville_elimination_decides() {
        let start = std::time::Instant::now();
        let v = totally_positive(&sin2_bernstein(10, false), None);
        println!("sin² Bernstein n = 10: {:?}", start.elapsed());
        assert_eq!(v.status, Status::Holds, "{:?}", v.evidence);
        let text = format!("{:?}", v.evidence);
        assert!(text.contains("11 × 41"), "{text}");
        assert!(text.contains("Neville elimination"), "{text}");
    }

    #[test]
    fn with_a_parameter_the_limit_is_a_not_checkable_that_names_it() {
        let v = totally_positive(&sin2_bernstein(10, true), None);
        assert_eq!(v.status, Status::NotCheckable);
        let text = format!("{:?}", v.evidence);
        assert!(text.contains("11 × 41"), "{text}");
        assert!(text.contains("at most 31 rows and columns"), "{text}");
    }
}
