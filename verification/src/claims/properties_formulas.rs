//! Second-list claims about printed formulas, decided exactly: the ends
//! of the thesis's quadratic curve (T45).

use trig_core::Family;
use trig_deriv::{End, Wrt, endpoint_derivatives};
use trig_symbolic::Sym;

use trig_judge::exact::IDENTITY;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// `F(0) − P0` and `F(1) − P2` of the quadratic curve (3.1) as multiples
/// `c·(P1 − P0)`, `c·(P1 − P2)`: the claim needs `c ≠ 0` for every `β ≥ 0`
/// (a nonzero constant numerator) and `c → 0` as `β → ∞` (numerator of
/// lower degree in `β` than the denominator).
pub(super) fn t45() -> Verdict {
    let p = trig_judge::exact::symbols("P", 3);
    let beta = [Sym::var("beta")];
    let ends = [
        (
            "F(0) − P0",
            End::Start,
            0,
            "P1 − P0",
            "F(0) = P0 only if P1 = P0",
        ),
        (
            "F(1) − P2",
            End::End,
            2,
            "P1 − P2",
            "F(1) = P2 only if P1 = P2",
        ),
    ];
    let parts = ends
        .iter()
        .map(|(label, at, end, direction, only_if)| {
            // the functions' values at the end (order 0 of their jets)
            let values: Vec<Sym> = endpoint_derivatives::<Sym, 1>(
                Family::ThesisQuadratic,
                &beta,
                *at,
                Wrt::Angle,
                &Sym::one(),
            )
            .into_iter()
            .map(|d| d[0].clone())
            .collect();
            let gap = trig_judge::exact::combination(&values, &p) - &p[*end];
            let c = gap.diff("P1");
            let shape = trig_judge::exact::identity_item(
                &format!("{label} − c·({direction}), c = ∂/∂P1"),
                &gap,
                &(c.clone() * &(p[1].clone() - &p[*end])),
            );
            let never_zero = c.numerator().as_constant().is_some_and(|k| k != 0);
            let degree = |q: &trig_symbolic::Poly| q.degree_in("beta");
            let vanishes = degree(c.numerator()) < degree(&c.denominator_poly());
            let holds = shape.status == Some(Status::Holds) && never_zero && vanishes;
            let mut v = Verdict::new(
                if holds { Status::Holds } else { Status::Fails },
                IDENTITY,
                [shape],
            );
            v.evidence.push(format!(
                "c = {}: {}; {}",
                c.to_unicode(),
                if never_zero {
                    format!("its numerator is a nonzero constant, so c ≠ 0 wherever the basis is defined (its published range β ≥ 0): {only_if}")
                } else {
                    "its numerator is not a nonzero constant".to_string()
                },
                if vanishes {
                    "numerator of lower degree in β than the denominator, so c → 0 as β → ∞"
                } else {
                    "c does not tend to 0 as β → ∞"
                }
            ));
            ((*label).to_string(), v)
        })
        .collect();
    Verdict::all(IDENTITY, parts)
}
