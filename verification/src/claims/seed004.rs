//! Seed 004 (Dube & Mishra 2016): the Hermite-type interpolant segment of
//! a basis, for the property checkers that still need it in Rust (its
//! claims are data: documents/eh-bspline2016/document.toml).

use trig_core::Family;
use trig_symbolic::Sym;

use trig_judge::exact::combination;

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
