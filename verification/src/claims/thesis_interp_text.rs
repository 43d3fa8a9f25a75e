//! Thesis 4.3.4: what the text says about the interpolant of Table 4.4
//! (claim T55), decided on the curve the G² scheme of `trig-interp`
//! builds from the printed table.
//!
//! A maximum is the certified minimum of `−P`
//! ([`trig_interp::certified_minimum`] on the spline with every control
//! point negated): `max P ∈ [−upper, −lower]` on each piece.

use rug::Rational;
use trig_interp::{
    DataSet, Interval, PieceMinimum, Scheme, Spline, Variant, build, certified_minimum,
};

use super::thesis_interp::sym_spline;
use crate::claim::Claim;
use trig_judge::interpolant_point::piece_witness;
use trig_judge::recomputed::decimal;
use trig_verdict::evidence::{Evidence, Expr, Kind, Relation, Value, Witness};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[Claim {
    id: "T55",
    check: t55,
}];

/// How a maximum is certified, as the report states it.
const MAXIMUM: &str = "certified maximum per piece: the certified minimum of −P (control points enclosed for π ∈ [3.14159265358979323846264338327, …328], Weierstrass z = tan(θ/2) + exact Bernstein subdivision), so max P ∈ [−upper, −lower]; reading of \"about 55\": the maximum rounds to 55 at two significant digits (certified in [54.5, 55.5)); of \"near x = 4.5\": the maximum lies on the piece [4, 5], whose middle is 4.5";

/// `q` with 4 decimals, rounded down or up.
fn dec4(q: &Rational, up: bool) -> String {
    let scaled = q.clone() * Rational::from(10_000);
    let k = if up { scaled.ceil() } else { scaled.floor() };
    decimal(&(k / Rational::from(10_000)))
}

/// Certified bounds `[lo, hi]` of the maximum of each piece of `spline`,
/// where it is (`x`, and `z = tan(θ/2)` rational).
type PieceMaximum = (Rational, Rational, f64, Rational);

/// The certified maximum of each piece of `spline`.
fn piece_maxima(spline: &Spline<Interval>) -> Result<Vec<PieceMaximum>, String> {
    let mut negated = spline.clone();
    for piece in &mut negated.pieces {
        piece.points = piece.points.clone().map(|v| -v);
    }
    let minima =
        certified_minimum(&negated, &trig_judge::interpolant::prove).map_err(|e| e.to_string())?;
    minima
        .iter()
        .map(|m: &PieceMinimum| match &m.lower {
            Some(l) => Ok((-m.upper.clone(), -l.clone(), m.x, m.z.clone())),
            None => Err(format!(
                "piece {}: the maximum is not certified ({})",
                m.piece + 1,
                m.undecided.as_deref().unwrap_or("undecided")
            )),
        })
        .collect()
}

/// T55 on the interpolant `scheme`/`variant` of the table `name`.
fn peak(name: &str, scheme: Scheme, variant: Variant) -> Result<Verdict, String> {
    let data = DataSet::named(name).map_err(|e| e.to_string())?;
    let spline = build(&data, scheme, variant, &Interval::point(Rational::new()))
        .map_err(|e| e.to_string())?;
    let maxima = piece_maxima(&spline)?;
    let (j, (lo, hi, x, z)) = maxima
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.0.cmp(&b.1.0))
        .ok_or("no pieces")?;
    let mut items: Vec<Evidence> = maxima
        .iter()
        .enumerate()
        .map(|(i, (l, h, x, _))| {
            Evidence::note(format!(
                "piece {} [{}, {}]: max P ∈ [{}, {}] at x ≈ {x:.4}",
                i + 1,
                data.x[i],
                data.x[i + 1],
                dec4(l, false),
                dec4(h, true)
            ))
        })
        .collect();
    // the piece of the maximum is certified when its lower bound beats every other upper bound
    let alone = maxima
        .iter()
        .enumerate()
        .all(|(i, (_, h, _, _))| i == j || h < lo);
    let (a, b) = (&data.x[j], &data.x[j + 1]);
    let four_and_half = Rational::from((9, 2));
    let near = alone && (a.clone() + b) / 2u32 == four_and_half;
    items.push(
        Evidence::new(
            Kind::Comparison,
            format!(
                "the maximum over [{}, {}] lies on piece {} [{a}, {b}] (x ≈ {x:.4}){}",
                data.x[0],
                data.x[data.x.len() - 1],
                j + 1,
                if alone {
                    ", every other piece's certified maximum being lower"
                } else {
                    "; another piece's bound overlaps it"
                }
            ),
        )
        .about("near x = 4.5", status(near)),
    );
    let (low, high) = (Rational::from((109, 2)), Rational::from((111, 2)));
    let about = *lo >= low && *hi < high;
    items.push(
        Evidence::new(
            Kind::Comparison,
            format!(
                "max P ∈ [{}, {}] ⊂ [54.5, 55.5): {}",
                dec4(lo, false),
                dec4(hi, true),
                if about { "yes" } else { "no" }
            ),
        )
        .about("rises to about 55", status(about))
        .witnessed((!about).then(|| {
            // above the range: a simple point where P is exactly ≥ 55.5
            let exact = sym_spline(name, scheme, variant).ok();
            let above = exact.as_ref().filter(|_| *lo >= high).and_then(|spline| {
                piece_witness(
                    spline,
                    j,
                    z,
                    Relation::Less,
                    ("upper end of about 55", &high),
                )
            });
            above.unwrap_or_else(|| bound_witness(lo, hi))
        })),
    );
    let above = (lo.to_f64() / 55.0 - 1.0) * 100.0;
    let loose = lo.clone() * 10u32 >= 55 * 9 && hi.clone() * 10u32 <= 55 * 11;
    items.push(Evidence::note(format!(
        "for comparison: the certified maximum is {above:.1}% above 55; a looser reading of \"about\" (within 10%) would {}",
        if loose { "accept it" } else { "not accept it either" }
    )));
    let end = &data.f[data.f.len() - 1];
    let drops = end < lo && j + 1 == maxima.len();
    items.push(
        Evidence::new(
            Kind::Comparison,
            format!(
                "P(x_n) = f_n = {} below the maximum, which lies on the last piece: {}",
                decimal(end),
                if drops { "yes" } else { "no" }
            ),
        )
        .about("then drops towards the endpoint", status(drops)),
    );
    let st = Status::conjunction(items.iter().filter_map(|e| e.status));
    Ok(Verdict::new(st, MAXIMUM, items))
}

fn bound_witness(lo: &Rational, hi: &Rational) -> Witness {
    let v = |label: &str, q: &Rational, up: bool| Value {
        of: None,
        label: label.into(),
        value: Expr::decimal(q, &dec4(q, up)),
    };
    Witness {
        point: Vec::new(),
        note: Some("the certified maximum".into()),
        values: vec![
            v("lower bound of max P", lo, false),
            v("upper bound of max P", hi, true),
        ],
        exact: true,
        stated: None,
    }
}

fn status(ok: bool) -> Status {
    if ok { Status::Holds } else { Status::Fails }
}

fn t55() -> Verdict {
    peak("thesis-table-4.4", Scheme::G2, Variant::Printed).unwrap_or_else(Verdict::not_checkable)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_maximum_of_a_piece_brackets_its_values() {
        let data = DataSet::named("thesis-table-4.4").unwrap();
        let spline = build(
            &data,
            Scheme::G2,
            Variant::Printed,
            &Interval::point(Rational::new()),
        )
        .unwrap();
        let maxima = piece_maxima(&spline).unwrap();
        // every piece's maximum is at least its end values (the data)
        for (i, (lo, hi, _, _)) in maxima.iter().enumerate() {
            assert!(lo <= hi);
            assert!(*hi >= data.f[i] && *hi >= data.f[i + 1], "piece {i}");
        }
    }
}
