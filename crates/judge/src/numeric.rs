//! Counterexamples evaluated in 256-bit MPFR, for statements that leave the
//! symbolic ring (e.g. a reflection `u ↦ π/2 − u` of a variable that is not
//! the angle).

use trig_core::{Mpfr, Real, Ring};

use trig_verdict::evidence::{Assignment, Evidence, Expr, Kind, Value, Witness};

/// Working precision of every counterexample.
pub const PREC: u32 = 256;

/// Prints a value with 30 significant digits.
pub fn show(x: &Mpfr) -> String {
    x.0.to_string_radix(10, Some(30))
}

/// A numeric counterexample as evidence: `text` says what was evaluated;
/// the witness gives the point (`printed` name, SymPy `symbol`, exact
/// `value`) and the two values at 30 significant digits (not exact:
/// `exact` is false), each with the expression it is the value of, in
/// SymPy syntax with the point's symbols free (see [`at_sympy`]).
pub fn counterexample_item(
    text: String,
    point: &[(String, String, String)],
    values: [(String, &Mpfr, String); 2],
) -> Evidence {
    let witness = Witness {
        point: point
            .iter()
            .map(|(n, symbol, v)| Assignment {
                name: n.clone(),
                value: v.clone(),
                latex: format!("{} = {}", trig_tex::math(n), trig_tex::math(v)),
                symbol: Some(symbol.clone()),
                sympy: Some(v.clone()),
            })
            .collect(),
        note: Some(format!(
            "values in {PREC}-bit MPFR, shown to 30 significant digits"
        )),
        values: values
            .into_iter()
            .map(|(label, x, of)| Value {
                of: Some(Expr::literal(&label, &of)),
                label,
                value: Expr::numeric(&show(x)),
            })
            .collect(),
        exact: false,
        stated: None,
    };
    Evidence::new(Kind::Numeric, text).witnessed(Some(witness))
}

/// `f` (exact, in the atoms `s`, `c`, `t`) at the value `x` of a basis's
/// variable, in SymPy syntax (`x` in SymPy syntax too): `θ = πx/2` for a
/// variable `u` of the unit angle, `θ = x` for an angle, `t = x` for a
/// polynomial variable.
pub fn at_sympy(f: &trig_symbolic::Sym, variable: Option<trig_core::Variable>, x: &str) -> String {
    use trig_core::Variable;
    match variable {
        Some(Variable::Polynomial) => f
            .to_sympy()
            .split_inclusive(|c: char| !c.is_alphanumeric() && c != '_')
            .map(|piece| {
                let (word, rest) = piece.split_at(
                    piece
                        .trim_end_matches(|c: char| !c.is_alphanumeric() && c != '_')
                        .len(),
                );
                if word == "t" {
                    format!("({x}){rest}")
                } else {
                    piece.to_string()
                }
            })
            .collect(),
        Some(Variable::UnitAngle) => f.to_sympy().replace("theta", &format!("(pi/2*({x}))")),
        _ => f.to_sympy().replace("theta", &format!("({x})")),
    }
}

/// True when `|a − b|` exceeds `2⁻²⁰⁰`, far above the 256-bit rounding of
/// these short evaluations: a certified inequality of the two values.
pub fn differ(a: &Mpfr, b: &Mpfr) -> bool {
    let d = a.clone() - b;
    let abs = if d < d.int(0) { -d } else { d };
    abs.to_f64() > 2f64.powi(-200)
}
