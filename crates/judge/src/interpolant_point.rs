//! A witness on one piece of a thesis interpolant: an exact point where the
//! piece `P = Σ b_j(θ; m_i)·V_j` (basis (3.7), `θ = π(x − x_i)/(2h_i)`)
//! visibly breaks a bound the text states.
//!
//! The point is a rational point `(s, c) = (sin θ, cos θ)` of the unit
//! circle — `z = tan(θ/2)` rational, the simplest convergent of the
//! certified extremum's `z*` that still shows the violation — with the
//! piece's exact control points (`π` symbolic). The value records `P`'s
//! formula in `θ` and the control points, so a reader substitutes the point
//! and sees the sign; the violation is certified here with `π` enclosed.

use rug::Rational;
use trig_interp::BASIS;
use trig_interp::interval::{pi_hi, pi_lo};
use trig_interp::{Interval, Spline};
use trig_symbolic::{Sym, symbolic_atoms};

use trig_verdict::evidence::{Assignment, Expr, Relation, Value, Witness};

/// `(s, c)` at `z = tan(θ/2)`.
fn circle(z: &Rational) -> (Rational, Rational) {
    let d = Rational::from(1) + z.clone() * z;
    (
        Rational::from(2) * z / d.clone(),
        (Rational::from(1) - z.clone() * z) / d,
    )
}

/// The continued-fraction convergents of `q` (simplest first, ending at `q`).
fn convergents(q: &Rational) -> Vec<Rational> {
    let (mut h, mut h1) = (rug::Integer::from(1), rug::Integer::new());
    let (mut k, mut k1) = (rug::Integer::new(), rug::Integer::from(1));
    let mut x = q.clone();
    let mut out = Vec::new();
    loop {
        let a = x.clone().floor().numer().clone();
        (h, h1) = (a.clone() * &h + &h1, h);
        (k, k1) = (a.clone() * &k + &k1, k);
        out.push(Rational::from((h.clone(), k.clone())));
        let frac = x - Rational::from(a);
        if frac == 0 || out.len() > 64 {
            return out;
        }
        x = frac.recip();
    }
}

/// The certified bounds of `x` (a value in `ℚ(π)`), `π` enclosed.
fn enclose(x: &Sym) -> Option<(Rational, Rational)> {
    let pi = Interval::new(pi_lo(), pi_hi());
    let value = x
        .eval(&Interval::point(Rational::new()), &|n: &str| {
            (n == "pi").then(|| pi.clone())
        })
        .ok()?;
    value.bounds().map(|(a, b)| (a.clone(), b.clone()))
}

/// True when `stated` (`value` against `bound`) is certainly false for a
/// value enclosed in `[lo, hi]`.
fn violated(stated: Relation, (lo, hi): &(Rational, Rational), bound: &Rational) -> bool {
    match stated {
        Relation::AtLeast => hi < bound,
        Relation::Greater => hi <= bound,
        Relation::AtMost => lo > bound,
        Relation::Less => lo >= bound,
        Relation::Equal => hi < bound || lo > bound,
        Relation::Differ => lo == hi && lo == bound,
    }
}

/// A witness that piece `i` of the exact interpolant `spline` breaks
/// "`P stated bound`": at the simplest convergent of `z` (tan of half the
/// angle of the certified extremum) where it certainly does. Values: `P`
/// (with its formula), then `bound` labelled `bound_label` (absent when the
/// bound is 0). `None` when no convergent shows it.
pub fn piece_witness(
    spline: &Spline<Sym>,
    i: usize,
    z: &Rational,
    stated: Relation,
    bound: (&str, &Rational),
) -> Option<Witness> {
    let piece = spline.pieces.get(i)?;
    let names = ["V", "W", "X", "Y"].map(|l| format!("{l}{i}"));
    let b = BASIS.eval(&symbolic_atoms(), &[Sym::rational(piece.m.clone())]);
    let formula = b.iter().zip(&names).fold(Sym::zero(), |acc, (bj, n)| {
        acc + &(bj.clone() * &Sym::var(n))
    });
    let with_points = names
        .iter()
        .zip(&piece.points)
        .fold(formula.clone(), |acc, (n, v)| acc.subs(n, v));
    let (value, s, c) = convergents(z).into_iter().find_map(|z| {
        let (s, c) = circle(&z);
        let value = with_points
            .try_subs("s", &Sym::rational(s.clone()))
            .and_then(|x| x.try_subs("c", &Sym::rational(c.clone())))
            .ok()?;
        violated(stated, &enclose(&value)?, bound.1).then_some((value, s, c))
    })?;
    let (s, c) = (Sym::rational(s), Sym::rational(c));
    let mut point = vec![Assignment::exact("s", &s), Assignment::exact("c", &c)];
    point.extend(Assignment::angle(Some(&s), Some(&c)));
    point.extend(
        names
            .iter()
            .zip(&piece.points)
            .map(|(n, v)| Assignment::exact(n, v)),
    );
    let mut values = vec![Value::new("P", Expr::new(&value)).of(&formula)];
    if *bound.1 != 0 {
        values.push(Value::new(
            bound.0,
            Expr::new(&Sym::rational(bound.1.clone())),
        ));
    }
    Some(Witness {
        point,
        note: Some(format!(
            "{} ({}), piece {}: P = Σ b_j(θ; m = {})·V_j with θ = {}, s = sin θ, c = cos θ; {} its control points; π kept as a symbol, the sign certified with π ∈ [3.14159265358979323846264338327, …328]",
            spline.data.table.name,
            spline.variant,
            i + 1,
            piece.m,
            angle(&piece.x0, &piece.h),
            names
                .iter()
                .map(|n| Sym::var(n).to_unicode())
                .collect::<Vec<_>>()
                .join(", ")
        )),
        values,
        exact: true,
        stated: Some(stated),
    })
}

/// The angle `θ = π(x − x₀)/(2h)` of a piece on `[x₀, x₀ + h]`, with `2h`
/// evaluated and the shift's sign written out (`π(x − 1)/2`, `πx/3`,
/// `π(x + 1/2)/(2/3)`).
fn angle(x0: &Rational, h: &Rational) -> String {
    let shift = match x0.cmp0() {
        std::cmp::Ordering::Equal => "x".to_string(),
        std::cmp::Ordering::Less => format!("(x + {})", Rational::from(-x0)),
        std::cmp::Ordering::Greater => format!("(x − {x0})"),
    };
    let two_h = Rational::from(2 * h);
    if two_h == 1 {
        format!("π{shift}")
    } else if *two_h.denom() == 1 {
        format!("π{shift}/{two_h}")
    } else {
        format!("π{shift}/({two_h})")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angles_are_written_with_2h_evaluated() {
        let q = |n: i64, d: i64| Rational::from((n, d));
        assert_eq!(angle(&q(1, 1), &q(1, 1)), "π(x − 1)/2");
        assert_eq!(angle(&q(0, 1), &q(3, 2)), "πx/3");
        assert_eq!(angle(&q(-1, 2), &q(1, 3)), "π(x + 1/2)/(2/3)");
        assert_eq!(angle(&q(4, 1), &q(1, 2)), "π(x − 4)");
    }

    #[test]
    fn convergents_end_at_the_number_and_start_simple() {
        let q = Rational::from((415, 93));
        let c = convergents(&q);
        assert_eq!(c.first(), Some(&Rational::from(4)));
        assert_eq!(c.last(), Some(&q));
        assert_eq!(c[1], Rational::from((9, 2)));
        let (s, c) = circle(&Rational::from((1, 2)));
        assert_eq!((s, c), (Rational::from((4, 5)), Rational::from((3, 5))));
    }

    #[test]
    fn a_violation_is_certified_against_the_enclosure() {
        let range = (Rational::from(-1), Rational::from((-1, 2)));
        assert!(violated(Relation::AtLeast, &range, &Rational::new()));
        assert!(!violated(Relation::AtMost, &range, &Rational::new()));
        assert!(violated(Relation::Less, &range, &Rational::from(-1)));
        let x = Sym::pi() - &Sym::int(3);
        let (lo, hi) = enclose(&x).unwrap();
        assert!(lo > 0 && hi < Rational::from((15, 100)));
    }
}
