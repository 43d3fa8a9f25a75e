//! Claims of total positivity, variation diminishing and convexity
//! preservation (second list of `shared/claims.md`), decided by the
//! total-positivity judge ([`trig_judge::total_positivity`]) and, for
//! the Bézier-like properties, by the endpoint, convex-hull and unity
//! judges.

use rug::Rational;
use trig_certify::ParamBox;
use trig_certify::nonneg::{Certificate, certify as certify_nonnegative};
use trig_certify::total_positivity::certify as certify_tp;
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_judge::certificate::CERTIFIED;
use trig_judge::exact::{IDENTITY, identities, symbols};
use trig_judge::total_positivity::CONSEQUENCES;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// In report order (after the other second-list claims).
pub const CLAIMS: &[Claim] = &[Claim {
    id: "T70",
    check: t70,
}];

/// Degrees of the Bernstein checks of T70.
const T70_DEGREES: std::ops::RangeInclusive<usize> = 1..=6;

/// `B_{i,n}(t) = C(n, i) tⁱ (1 − t)^{n−i}` (zero outside `0 ≤ i ≤ n`).
fn bernstein(i: i64, n: i64) -> Sym {
    if i < 0 || i > n {
        return Sym::zero();
    }
    let t = Sym::var("t");
    let one_minus = Sym::one() - &t;
    let binomial = rug::Integer::binomial_u(n as u32, i as u32);
    let mut b = Sym::rational(Rational::from(rug::Integer::from(binomial)));
    for _ in 0..i {
        b = b * &t;
    }
    for _ in 0..n - i {
        b = b * &one_minus;
    }
    b
}

/// The printed Bernstein facts, exactly, for each degree of
/// [`T70_DEGREES`]; nonnegativity certified, total positivity by the
/// factorisation engine (the Bernstein basis is its own certificate).
fn t70() -> Verdict {
    let parts = T70_DEGREES
        .map(|n| (format!("n = {n}"), t70_degree(n as i64)))
        .collect();
    let mut v = Verdict::all(IDENTITY, parts);
    v.evidence.insert(
        0,
        "the text states the facts for every n; they are decided here for n = 1, …, 6 (textbook facts for all n, e.g. Farin, Curves and Surfaces for CAGD). Convex hull from nonnegativity and unity; affine invariance from unity; variation diminishing from total positivity and unity",
    );
    v
}

/// The facts of T70 at one degree.
fn t70_degree(n: i64) -> Verdict {
    let b: Vec<Sym> = (0..=n).map(|i| bernstein(i, n)).collect();
    let t = Sym::var("t");
    let reflect = |f: &Sym| f.subs("t", &(Sym::one() - &t));
    let at = |f: &Sym, x: i64| f.subs("t", &Sym::int(x));
    let mut parts = vec![(
        "Σ B_{i,n} = 1".to_string(),
        trig_judge::exact::sum(&b),
        Sym::one(),
    )];
    for i in 0..=n {
        let u = i as usize;
        parts.push((
            format!("B_{{{},{n}}}(t) = B_{{{i},{n}}}(1 − t)", n - i),
            b[(n - i) as usize].clone(),
            reflect(&b[u]),
        ));
        parts.push((
            format!(
                "B_{{{i},{n}}} = (1 − t)B_{{{i},{}}} + tB_{{{},{}}}",
                n - 1,
                i - 1,
                n - 1
            ),
            b[u].clone(),
            (Sym::one() - &t) * &bernstein(i, n - 1) + &(t.clone() * &bernstein(i - 1, n - 1)),
        ));
    }
    let p = symbols("P", n as usize + 1);
    let curve = trig_judge::exact::combination(&b, &p);
    let (first, last) = (p[0].clone(), p[n as usize].clone());
    let slope = curve.d_t();
    parts.push(("B(0) = P0".into(), at(&curve, 0), first.clone()));
    parts.push((format!("B(1) = P{n}"), at(&curve, 1), last.clone()));
    parts.push((
        "B'(0) = n(P1 − P0)".into(),
        at(&slope, 0),
        Sym::int(n) * &(p[1].clone() - &first),
    ));
    parts.push((
        format!("B'(1) = n(P{n} − P{})", n - 1),
        at(&slope, 1),
        Sym::int(n) * &(last - &p[n as usize - 1]),
    ));
    let exact = identities(parts);
    let signs: Vec<Status> = b
        .iter()
        .map(
            |f| match certify_nonnegative(f, false, None, &ParamBox::point(Rational::new())) {
                Certificate::NonNegative { .. } => Status::Holds,
                Certificate::Counterexample { .. } => Status::Fails,
                _ => Status::NotCheckable,
            },
        )
        .collect();
    let tp = certify_tp(&b, false, None);
    let tp_status = match &tp {
        Ok(c) if c.set.covers => Status::Holds,
        Ok(_) => Status::NotCheckable,
        Err(_) => Status::NotCheckable,
    };
    let tp_text = match &tp {
        Ok(c) => format!(
            "total positivity: coefficient matrix {} × {} in the Bernstein basis of degree {}, {} nonzero minors, {}; {CONSEQUENCES}",
            c.factorisation.rows.len(),
            c.factorisation.degree + 1,
            c.factorisation.degree,
            c.minors,
            if c.set.covers {
                "all ≥ 0"
            } else {
                "not all ≥ 0"
            }
        ),
        Err(why) => format!("total positivity: {why}"),
    };
    Verdict::all(
        IDENTITY,
        vec![
            ("identities".into(), exact),
            (
                "nonnegativity on [0, 1]".into(),
                Verdict::new(
                    Status::conjunction(signs),
                    CERTIFIED,
                    ["every B_{i,n} certified ≥ 0 by exact Bernstein subdivision"],
                ),
            ),
            (
                "variation diminishing".into(),
                Verdict::new(tp_status, IDENTITY, [tp_text]),
            ),
        ],
    )
}
