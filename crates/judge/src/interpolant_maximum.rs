//! What a text says about the maximum of the interpolant of a printed data
//! table (`check = "interpolant-maximum"`): "rises to about 55", "near
//! x = 4.5", "then drops towards the endpoint".
//!
//! A maximum is the certified minimum of `−P`
//! ([`trig_interp::certified_minimum`] on the spline with every control
//! point negated): `max P ∈ [−upper, −lower]` on each piece. Readings:
//! "about `V`" — the maximum rounds to `V` at `V`'s last printed digit
//! (certified in `[V − ½u, V + ½u)`, `u` that digit's unit); "near
//! `x = X`" — the maximum lies on the piece that contains `X`, its certified
//! lower bound above every other piece's upper bound; "drops" — holds
//! where the maximum lies on the last piece and the last data value is
//! below it, fails where a data value after the maximum's piece rises
//! (`P(xᵢ) = fᵢ`), otherwise `not-checkable`.

use crate::exact::ExactBasis;
use rug::Rational;
use trig_interp::{
    DataSet, Interval, PieceMinimum, Scheme, Spline, Variant, build, certified_minimum,
};
use trig_specfile::data_query::MaximumQuery;
use trig_verdict::evidence::{Evidence, Expr, Kind, Relation, Value, Witness};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use crate::interpolant::{exact_spline, other_basis, prove};
use crate::interpolant_point::piece_witness;
use crate::quoted::half_unit;
use crate::recomputed::decimal;

/// How a maximum is certified, as the report states it.
const MAXIMUM: &str = "certified maximum per piece: the certified minimum of −P (control points enclosed for π ∈ [3.14159265358979323846264338327, …328], Weierstrass z = tan(θ/2) + exact Bernstein subdivision), so max P ∈ [−upper, −lower]";

/// `q` with 4 decimals, rounded down or up.
fn dec4(q: &Rational, up: bool) -> String {
    let scaled = q.clone() * Rational::from(10_000);
    let k = if up { scaled.ceil() } else { scaled.floor() };
    decimal(&(k / Rational::from(10_000)))
}

/// Certified bounds `[lo, hi]` of the maximum of a piece, where it is
/// (`x`, and `z = tan(θ/2)` rational).
type PieceMaximum = (Rational, Rational, f64, Rational);

/// The certified maximum of each piece of `spline`.
fn piece_maxima(spline: &Spline<Interval>) -> Result<Vec<PieceMaximum>, String> {
    let mut negated = spline.clone();
    for piece in &mut negated.pieces {
        piece.points = piece.points.clone().map(|v| -v);
    }
    let minima = certified_minimum(&negated, &prove).map_err(|e| e.to_string())?;
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

fn status(ok: bool) -> Status {
    if ok { Status::Holds } else { Status::Fails }
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

/// The statements `queries` about the maximum of the interpolant of `data`
/// by `scheme` (as printed), about `basis`.
pub fn maximum<B: ExactBasis>(
    basis: &B,
    data: &DataSet,
    scheme: Scheme,
    queries: &[MaximumQuery],
) -> Verdict {
    if let Some(why) = other_basis(basis) {
        return Verdict::not_checkable(why);
    }
    decide(data, scheme, queries).unwrap_or_else(Verdict::not_checkable)
}

fn decide(data: &DataSet, scheme: Scheme, queries: &[MaximumQuery]) -> Result<Verdict, String> {
    let variant = Variant::Printed;
    let spline = build(data, scheme, variant, &Interval::point(Rational::new()))
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
    let mut readings = Vec::new();
    for q in queries {
        match q {
            MaximumQuery::Near { text, x: place } => {
                let near = alone && a <= place && place <= b;
                readings.push(format!(
                    "of \"{text}\": the maximum lies on the piece that contains {}",
                    decimal(place)
                ));
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
                    .about(text.as_str(), status(near)),
                );
            }
            MaximumQuery::About { text, printed } => {
                let value = trig_core::parse_exact(printed).map_err(|e| e.to_string())?;
                let u = half_unit(printed);
                let (low, high) = (value.clone() - &u, value.clone() + &u);
                let about = *lo >= low && *hi < high;
                readings.push(format!(
                    "of \"about {printed}\": the maximum rounds to {printed} at its last printed digit (certified in [{}, {}))",
                    decimal(&low),
                    decimal(&high)
                ));
                items.push(
                    Evidence::new(
                        Kind::Comparison,
                        format!(
                            "max P ∈ [{}, {}] ⊂ [{}, {}): {}",
                            dec4(lo, false),
                            dec4(hi, true),
                            decimal(&low),
                            decimal(&high),
                            if about { "yes" } else { "no" }
                        ),
                    )
                    .about(text.as_str(), status(about))
                    .witnessed((!about).then(|| {
                        // above the range: a simple point where P is exactly ≥ the upper end
                        let exact = exact_spline(data, scheme, variant).ok();
                        let above = exact.as_ref().filter(|_| *lo >= high).and_then(|spline| {
                            piece_witness(
                                spline,
                                j,
                                z,
                                Relation::Less,
                                (&format!("upper end of about {printed}"), &high),
                            )
                        });
                        above.unwrap_or_else(|| bound_witness(lo, hi))
                    })),
                );
                // the lower bound's distance from V, in per cent of |V|
                // (absolute at V = 0)
                let gap = lo.to_f64() - value.to_f64();
                let side = if gap < 0.0 { "below" } else { "above" };
                let size = if value == 0 {
                    format!("{:.4}", gap.abs())
                } else {
                    format!("{:.1}%", 100.0 * gap.abs() / value.to_f64().abs())
                };
                let tenth = value.clone().abs() / 10u32;
                let loose = *lo >= value.clone() - &tenth && *hi <= value.clone() + &tenth;
                items.push(Evidence::note(format!(
                    "for comparison: the certified maximum is {size} {side} {printed}; a looser reading of \"about\" (within 10%) would {}",
                    if loose { "accept it" } else { "not accept it either" }
                )));
            }
            MaximumQuery::Drops { text } => {
                let n = data.f.len() - 1;
                let end = &data.f[n];
                let last = j + 1 == maxima.len();
                // P(x_i) = f_i: a rise between data values after the
                // maximum's piece is a rise of P after its maximum
                let rise = (j + 1..n).find(|&i| data.f[i + 1] > data.f[i]);
                let st = if end < lo && last {
                    Status::Holds
                } else if rise.is_some() || end >= lo {
                    Status::Fails
                } else {
                    Status::NotCheckable
                };
                readings.push(format!(
                    "of \"{text}\": the maximum lies on the last piece and the last data value is below it{}",
                    if st == Status::Holds {
                        ""
                    } else {
                        " (refuted where P rises between data values after the maximum's piece, P(x_i) = f_i, or ends at it; otherwise not decided: a decrease between data values is not certified)"
                    }
                ));
                let found = match rise {
                    Some(i) => format!(
                        "P rises after the maximum: P(x_{i}) = f_{i} = {} < P(x_{}) = f_{} = {}",
                        decimal(&data.f[i]),
                        i + 1,
                        i + 1,
                        decimal(&data.f[i + 1])
                    ),
                    None if st == Status::Holds => format!(
                        "P(x_n) = f_n = {} below the maximum, which lies on the last piece: yes",
                        decimal(end)
                    ),
                    None => format!(
                        "the maximum lies on piece {} of {}; P(x_n) = f_n = {} is below it; the data values after it do not rise",
                        j + 1,
                        maxima.len(),
                        decimal(end)
                    ),
                };
                items.push(Evidence::new(Kind::Comparison, found).about(text.as_str(), st));
            }
        }
    }
    let st = Status::conjunction(items.iter().filter_map(|e| e.status));
    Ok(Verdict::new(
        st,
        format!("{MAXIMUM}; reading {}", readings.join("; ")),
        items,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_specfile::data_query::maximum as query;

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

    #[test]
    fn readings_decide_on_the_certified_maximum() {
        let data = DataSet::named("thesis-table-4.4").unwrap();
        let v = |q: &str| {
            decide(&data, Scheme::G2, &[query(q).unwrap()])
                .unwrap()
                .status
        };
        // the maximum is certified to lie on [4, 5], and is far above 8
        assert_eq!(v("near x = 4.5"), Status::Holds);
        assert_eq!(v("near x = 1.5"), Status::Fails);
        assert_eq!(v("about 8"), Status::Fails);
        // the side of the quoted value the maximum lies on, for any sign of
        // it, and at 0 the distance itself
        let text = |q: &str| -> String {
            let v = decide(&data, Scheme::G2, &[query(q).unwrap()]).unwrap();
            v.evidence.iter().map(|e| e.line()).collect()
        };
        for (q, side) in [
            ("about 1000", "% below 1000;"),
            ("about -55", "% above -55;"),
            ("about 0", " above 0;"),
        ] {
            let t = text(q);
            assert!(t.contains(side) && !t.contains("inf"), "{q}: {t}");
        }
    }

    #[test]
    fn then_drops_fails_only_on_a_rise_after_the_maximum() {
        // P(xᵢ) = fᵢ, C¹ scheme, m = 1/2: the maximum (about 8.01) lies on
        // piece 2 of 4; after it 8, 4, 1 do not rise (undecided: a decrease
        // between the data values is not certified), 8, 4, 6 rise
        let drops = |f: [&str; 5]| {
            let rows: String = (0..5)
                .map(|i| {
                    let m = if i < 4 { "0.5" } else { "-" };
                    format!("{}\t{i}\t{}\t{m}\n", i + 1, f[i])
                })
                .collect();
            let data = DataSet::parse(&format!(
                "name: peak\ncaption: c\ncitation: c\nscheme: c1\ni\tx\tf\tm\n{rows}"
            ))
            .unwrap();
            decide(
                &data,
                Scheme::C1,
                &[query("then drops towards the endpoint").unwrap()],
            )
            .unwrap()
            .status
        };
        assert_eq!(drops(["0", "5", "8", "4", "1"]), Status::NotCheckable);
        assert_eq!(drops(["0", "5", "8", "4", "6"]), Status::Fails);
        // the maximum on the last piece and the last value below it (the
        // thesis's Table 4.4, G² scheme: T55)
        let table = DataSet::named("thesis-table-4.4").unwrap();
        let v = decide(
            &table,
            Scheme::G2,
            &[query("then drops towards the endpoint").unwrap()],
        );
        assert_eq!(v.unwrap().status, Status::Holds);
    }
}
