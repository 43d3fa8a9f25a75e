//! A basis on a general domain brought to the engine's standard domains.
//!
//! The engine decides signs on `θ ∈ [0, π/2]` (formulas in `s = sin θ`,
//! `c = cos θ`) or `t ∈ [0, 1]` ([`crate::domain`]). A function of a
//! general [`Domain`] is brought there exactly when it is a polynomial in
//! `s`, `c` whose angle `θ = ωx` runs between multiples of π/2 — split
//! into quarter turns `θ = kπ/2 + φ`, `φ ∈ [0, π/2]`, each rotated exactly
//! (`sin(kπ/2 + φ)` is `±sin φ` or `±cos φ`) — or a polynomial in `t` on
//! rational ends `[a, b]`, mapped by `t = a + (b − a)τ`. The function is
//! `≥ 0` on its domain exactly when every piece is on the standard one.
//! Other functions (the variable together with `s`, `c`, exponentials,
//! sines of parameters, parameter-dependent ends) are not standard: the
//! caller reports that they need another method.

use rug::Rational;
use trig_core::Domain;
use trig_symbolic::Sym;

/// The pieces of a function on the standard domain.
#[derive(Debug, Clone, PartialEq)]
pub struct Standard {
    /// True for pieces in `s`, `c` (θ ∈ [0, π/2]), false for `t ∈ [0, 1]`.
    pub trigonometric: bool,
    /// The function on each piece.
    pub pieces: Vec<Sym>,
    /// Where each piece lies in the original domain (`θ ∈ [π/2, π]`);
    /// empty strings when there is one piece with the identity map.
    pub labels: Vec<String>,
    /// How each piece's own variable maps to the original one.
    pub maps: Vec<PieceMap>,
}

/// How a piece's own variable (the one its formula, and a witness found on
/// it, is written in) maps to the basis variable.
#[derive(Debug, Clone, PartialEq)]
pub enum PieceMap {
    /// The piece is the function itself.
    Identity,
    /// `θ = kπ/2 + φ`, the piece written in `s = sin φ`, `c = cos φ`.
    Quarter(i64),
    /// `t = a + (b − a)τ`, the piece written in `τ` (printed `t`).
    Affine { a: Rational, b: Rational },
}

impl PieceMap {
    /// How a witness point on the piece reads in the basis variable, for
    /// a note (`None` for the identity).
    pub fn note(&self) -> Option<String> {
        match self {
            PieceMap::Identity | PieceMap::Quarter(0) => None,
            PieceMap::Quarter(k) => Some(format!(
                "the point is in the piece's own angle φ = θ − {0} ∈ [0, π/2] (its formula rotated exactly): z = tan(φ/2), s = sin φ, c = cos φ, and θ = {0} + φ",
                half_pi(*k)
            )),
            PieceMap::Affine { a, b } => Some(format!(
                "the point is in the piece's own variable τ ∈ [0, 1], printed t: the basis variable is {a} + {}·τ",
                Rational::from(b - a)
            )),
        }
    }
}

/// `(s, c) ↦ (sin(kπ/2 + φ), cos(kπ/2 + φ))` in the atoms of `φ`.
fn rotate(f: &Sym, k: i64) -> Sym {
    let (s, c) = (Sym::var("s"), Sym::var("c"));
    let (s_new, c_new) = match k.rem_euclid(4) {
        0 => return f.clone(),
        1 => (c.clone(), -s.clone()),
        2 => (-s.clone(), -c.clone()),
        _ => (-c.clone(), s.clone()),
    };
    let tmp = Sym::var("__rotate");
    f.subs("s", &tmp).subs("c", &c_new).subs("__rotate", &s_new)
}

/// The standard pieces of `f` on `domain`, or why there are none.
pub fn standardize(f: &Sym, domain: &Domain) -> Result<Standard, String> {
    let vars = f.variables();
    if let Some(v) = vars
        .iter()
        .find(|v| v.as_str() == "E" || v.as_str() == "pi" || v.contains('('))
    {
        return Err(format!(
            "`{v}` occurs: not a polynomial in sin, cos or the variable with rational coefficients"
        ));
    }
    let trig = vars.contains("s") || vars.contains("c");
    if trig && vars.contains("t") {
        return Err(
            "the variable occurs beside sin and cos (an algebraic-trigonometric function)".into(),
        );
    }
    if trig {
        let w = domain.angle.as_ref().ok_or("sin/cos without an angle")?;
        let quarter = |x: &trig_core::Affine| x.times(w).and_then(|a| a.quarter_turns());
        let (Some(ka), Some(kb)) = (quarter(&domain.start), quarter(&domain.end)) else {
            return Err("the angle's ends are not multiples of π/2".into());
        };
        let pieces: Vec<Sym> = (ka..kb).map(|k| rotate(f, k)).collect();
        let labels = if kb - ka == 1 && ka == 0 {
            vec![String::new()]
        } else {
            (ka..kb)
                .map(|k| format!("θ ∈ [{}, {}]", half_pi(k), half_pi(k + 1)))
                .collect()
        };
        return Ok(Standard {
            trigonometric: true,
            pieces,
            labels,
            maps: (ka..kb).map(PieceMap::Quarter).collect(),
        });
    }
    if !vars.contains("t") {
        return Ok(Standard {
            trigonometric: domain.is_trigonometric(),
            pieces: vec![f.clone()],
            labels: vec![String::new()],
            maps: vec![PieceMap::Identity],
        });
    }
    let (Some(a), Some(b)) = (domain.start.as_rational(), domain.end.as_rational()) else {
        return Err("the domain's ends are not rational numbers".into());
    };
    let identity = *a == 0 && *b == 1;
    let map = Sym::rational(a.clone()) + &(Sym::rational(Rational::from(b - a)) * &Sym::var("t"));
    Ok(Standard {
        trigonometric: false,
        pieces: vec![if identity {
            f.clone()
        } else {
            f.subs("t", &map)
        }],
        labels: vec![if identity {
            String::new()
        } else {
            format!("t = {a} + {}τ", Rational::from(b - a))
        }],
        maps: vec![if identity {
            PieceMap::Identity
        } else {
            PieceMap::Affine {
                a: a.clone(),
                b: b.clone(),
            }
        }],
    })
}

fn half_pi(k: i64) -> String {
    match k {
        0 => "0".into(),
        1 => "π/2".into(),
        -1 => "−π/2".into(),
        k if k % 2 == 0 => format!("{}π", k / 2).replace("1π", "π").replace('-', "−"),
        k => format!("{k}π/2").replace('-', "−"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::{Affine, Variable};

    fn q(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    #[test]
    fn legacy_domains_are_standard_already() {
        let f = Sym::var("s") * &Sym::var("m");
        let d = Domain::from_variable(Variable::UnitAngle, &["m"]);
        let st = standardize(&f, &d).unwrap();
        assert!(st.trigonometric && st.pieces == vec![f.clone()]);
        let p = Domain::from_variable(Variable::Polynomial, &[]);
        let g = Sym::var("t") * &Sym::var("t");
        assert_eq!(standardize(&g, &p).unwrap().pieces, vec![g]);
    }

    #[test]
    fn quarter_turns_and_affine_maps() {
        // sin t on [−π/2, π/2]: −cos φ on the first quarter, sin φ on the second
        let d = Domain {
            start: Affine::pi_times(q(-1, 2)),
            end: Affine::pi_times(q(1, 2)),
            ..Domain::from_variable(Variable::Angle, &[])
        };
        let st = standardize(&Sym::var("s"), &d).unwrap();
        assert_eq!(st.pieces, vec![-Sym::var("c"), Sym::var("s")]);
        assert_eq!(st.labels, vec!["θ ∈ [−π/2, 0]", "θ ∈ [0, π/2]"]);
        // t on [−1, 3]: −1 + 4τ
        let p = Domain {
            start: Affine::rational(q(-1, 1)),
            end: Affine::rational(q(3, 1)),
            ..Domain::from_variable(Variable::Polynomial, &[])
        };
        let st = standardize(&Sym::var("t"), &p).unwrap();
        assert_eq!(st.pieces[0], Sym::int(4) * &Sym::var("t") - &Sym::one());
        // not standard: the variable with sin, or a half-angle end
        let mixed = Sym::var("t") * &Sym::var("s");
        assert!(standardize(&mixed, &d).is_err());
        let half = Domain {
            angle: Some(Affine::rational(q(1, 2))),
            ..Domain::from_variable(Variable::Angle, &[])
        };
        assert!(standardize(&Sym::var("s"), &half).is_err());
    }
}
