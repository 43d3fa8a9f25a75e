//! Seed 004 (Dube & Mishra 2016): the standard cubic Hermite bases and the EH
//! bases with shape parameters λ, μ; the EH curve's terminal properties and
//! rewritten form.

use trig_core::Family;
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_judge::exact::{IDENTITY, combination, identities};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "E1c",
        check: e1c,
    },
    Claim {
        id: "E1cb",
        check: e1cb,
    },
];

/// `H(x) = α0(t)y_i + α1(t)y_{i+1} + β0(t)h_i d_i + β1(t)·hd·d_{i+1}` for a
/// given `t(x)` and the factor `hd` of `d_{i+1}`, and the four interpolation
/// conditions at `x_i`, `x_{i+1} = x_i + h_i` (derivatives in `x`).
fn hermite_conditions(t: &Sym, hd: &Sym) -> Vec<(String, Sym, Sym)> {
    interpolation_conditions(Family::Hermite, &[], t, hd)
}

/// The segment `H_i(x) = b0(t)y_i + b1(t)y_{i+1} + b2(t)h_i d_i + b3(t)·hd·d_{i+1}`
/// of a Hermite-type `family` (parameters `params`) at `t` (an expression in
/// `x`, `x_i`, `h_i`), with `index` naming its data: `y_i`, `y_i1`, `d_i`, `d_i1`
/// for segment `i`, `y_i1`, `y_i2`, … for segment `i + 1`.
pub(super) fn hermite_segment(
    family: Family,
    params: &[Sym],
    t: &Sym,
    hd: &Sym,
    index: usize,
) -> Sym {
    let name = |k: usize| {
        if k == 0 {
            "i".to_string()
        } else {
            format!("i{k}")
        }
    };
    let [y0, y1, d0, d1] = [
        format!("y_{}", name(index)),
        format!("y_{}", name(index + 1)),
        format!("d_{}", name(index)),
        format!("d_{}", name(index + 1)),
    ]
    .map(|n| Sym::var(&n));
    let h = Sym::var(&format!("h_{}", name(index)));
    let atoms = trig_core::Atoms {
        s: Sym::zero(),
        c: Sym::one(),
        t: t.clone(),
        e: Sym::one(),
    };
    let b = family.eval(&atoms, params);
    combination(&b, &[y0, y1, h * &d0, hd.clone() * &d1])
}

/// The four interpolation conditions of [`hermite_segment`] (segment `i`)
/// at `x_i` and `x_{i+1} = x_i + h_i`.
pub(super) fn interpolation_conditions(
    family: Family,
    params: &[Sym],
    t: &Sym,
    hd: &Sym,
) -> Vec<(String, Sym, Sym)> {
    let (x0, hi) = (Sym::var("x_i"), Sym::var("h_i"));
    let x1 = x0.clone() + &hi;
    let [y0, y1, d0, d1] = ["y_i", "y_i1", "d_i", "d_i1"].map(Sym::var);
    let h = hermite_segment(family, params, t, hd, 0);
    let dh = h.diff("x");
    vec![
        ("H_i(x_i) − y_i".into(), h.subs("x", &x0), y0),
        ("H_i(x_{i+1}) − y_{i+1}".into(), h.subs("x", &x1), y1),
        ("H_i'(x_i) − d_i".into(), dh.subs("x", &x0), d0),
        ("H_i'(x_{i+1}) − d_{i+1}".into(), dh.subs("x", &x1), d1),
    ]
}

/// As printed: `t = (x_{i+1} − x_i)/h_i`, which is the constant 1.
fn e1c() -> Verdict {
    let (x0, hi) = (Sym::var("x_i"), Sym::var("h_i"));
    let t = (x0.clone() + &hi - &x0) / &hi;
    let mut v = identities(hermite_conditions(&t, &Sym::var("h_i1")));
    v.evidence.insert(
        0,
        format!("x_{{i+1}} = x_i + h_i; the printed t = (x_{{i+1}} − x_i)/h_i equals {t} for every x, so H_i(x) = α0(1)y_i + α1(1)y_{{i+1}} + β0(1)h_i d_i + β1(1)h_{{i+1}}d_{{i+1}} is the constant y_{{i+1}}"),
    );
    v
}

/// Reading: `t = (x − x_i)/h_i`; the printed factor `h_{i+1}` of `d_{i+1}`
/// is kept, and the correction `h_{i+1} → h_i` is checked.
fn e1cb() -> Verdict {
    let hi = Sym::var("h_i");
    let t = (Sym::var("x") - &Sym::var("x_i")) / &hi;
    let printed = identities(hermite_conditions(&t, &Sym::var("h_i1")));
    if printed.status == Status::Holds {
        return printed;
    }
    let corrected = identities(hermite_conditions(&t, &hi));
    if corrected.status != Status::Holds {
        return printed;
    }
    let mut evidence = printed.evidence;
    evidence.extend(corrected.into_part("with h_i d_{i+1}"));
    Verdict::new(Status::HoldsAfterCorrection, IDENTITY, evidence)
        .with_correction("β1(t) h_i d_{i+1} instead of β1(t) h_{i+1} d_{i+1} (t is measured in units of h_i on [x_i, x_{i+1}])")
}
