//! The nonnegativity judge: nonnegativity, maximal ranges and regions,
//! monotonicity and the convex hull of any basis — decided by the one
//! certification engine on the standard pieces of the domain
//! ([`trig_certify::standardize`]): exact Bernstein subdivision where the
//! functions are polynomial in `sin`, `cos` or the variable, the interval
//! engine ([`super::by_intervals`]) otherwise.

use rug::Rational;
use trig_certify::standard::PieceMap;
use trig_certify::{ParamBox, standardize};
use trig_core::ParamRange;
use trig_specfile::Monotone;
use trig_symbolic::Sym;

use super::by_intervals;
use super::certificate::{
    CERTIFIED, Published, maximal_against, monotone_named, nonnegative_named,
};
use super::region::{self, Axis};
use super::unity::unity;
use crate::exact::ExactBasis;
use crate::exact::basis_of;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// The functions on the standard domain: `(trigonometric, functions,
/// names)`, every function split into its pieces (named `b0 on θ ∈ …` when
/// there are several), or why the basis is not standard.
pub fn pieces<B: ExactBasis>(basis: &B) -> Result<(bool, Vec<Sym>, Vec<String>), String> {
    if let Some(p) = basis.parameters().iter().find(|p| p.range.pi) {
        return Err(format!(
            "the range {} of {} is in multiples of π",
            p.range, p.symbol
        ));
    }
    let mut trig = None;
    let (mut fs, mut names) = (Vec::new(), Vec::new());
    let domain = basis.domain();
    for (value, name) in basis_of(basis).iter().zip(basis.function_names()) {
        let st = standardize(value, &domain).map_err(|why| format!("{name}: {why}"))?;
        if trig.is_some_and(|t| t != st.trigonometric) {
            return Err("the functions mix sin/cos and the variable".into());
        }
        trig = Some(st.trigonometric);
        for (piece, label) in st.pieces.into_iter().zip(st.labels) {
            fs.push(piece);
            names.push(if label.is_empty() {
                name.clone()
            } else {
                format!("{name} on {label}")
            });
        }
    }
    Ok((trig.unwrap_or(false), fs, names))
}

/// How each piece of [`pieces`] maps to the basis variable, in the same
/// order (a witness on a piece is in the piece's own variable).
fn piece_maps<B: ExactBasis>(basis: &B) -> Vec<PieceMap> {
    let domain = basis.domain();
    basis_of(basis)
        .iter()
        .flat_map(|f| standardize(f, &domain).map_or_else(|_| Vec::new(), |st| st.maps))
        .collect()
}

/// Every function `≥ 0` for the parameters in `range` (one parameter;
/// the declared ranges otherwise): exact Bernstein subdivision on the
/// standard pieces, the interval engine for other bases.
fn nonnegative_on<B: ExactBasis>(basis: &B, range: Option<&ParamRange>) -> Verdict {
    match pieces(basis) {
        Ok((trig, fs, names)) => match basis.parameters().as_slice() {
            [] => nonnegative_named(trig, &fs, &names, None, &point_box(), &piece_maps(basis)),
            [p] => {
                let r = range.unwrap_or(&p.range);
                nonnegative_named(
                    trig,
                    &fs,
                    &names,
                    Some(&p.name),
                    &ParamBox::from_range(r),
                    &piece_maps(basis),
                )
            }
            _ => several(basis, false),
        },
        Err(why) => interval_engine(basis, range, &why),
    }
}

/// The interval engine on the whole basis, with why it was needed.
fn interval_engine<B: ExactBasis>(basis: &B, range: Option<&ParamRange>, why: &str) -> Verdict {
    let (axes, notes) = by_intervals::axes(basis, range);
    let fs = by_intervals::functions(basis);
    let mut v = by_intervals::all_nonnegative(basis, &fs, &axes, &notes);
    v.evidence.insert(0, format!("not polynomial in sin, cos or the variable on a standard domain ({why}): the interval engine decides"));
    v
}

/// Several parameters: the box of declared ranges against the region —
/// containment, and when `maximal`, equality (two parameters).
fn several<B: ExactBasis>(basis: &B, maximal: bool) -> Verdict {
    let (trig, fs, names) = match pieces(basis) {
        Ok(p) => p,
        Err(why) => {
            let mut v = interval_engine(basis, None, &why);
            if maximal && v.status == Status::Holds {
                v.status = Status::NotCheckable;
                v.evidence.push("the box is contained in the region; its maximality needs the polynomial method (boundary polynomials), which does not apply");
            }
            return v;
        }
    };
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let params = basis.parameters();
    let axes: Vec<Axis<'_>> = params
        .iter()
        .map(|p| Axis {
            name: &p.name,
            symbol: &p.symbol,
            set: ParamBox::from_range(&p.range),
            source: &p.source,
        })
        .collect();
    match <[Axis<'_>; 2]>::try_from(axes) {
        Ok(two) if maximal => region::maximal(&fs, &names, trig, two),
        Ok(two) => region::contained(&fs, &names, trig, &two),
        Err(axes) => {
            let mut v = region::contained(&fs, &names, trig, &axes);
            if maximal && v.status == Status::Holds {
                v.status = Status::NotCheckable;
                v.evidence
                    .push("maximality is decided for two parameters at most: containment only");
            }
            v
        }
    }
}

/// The whole battery entry for nonnegativity.
pub fn nonnegativity<B: ExactBasis>(basis: &B) -> Verdict {
    match basis.parameters().len() {
        0 => nonnegative_on(basis, None),
        1 => maximal_versus_published(basis, None),
        _ => several(basis, true),
    }
}

/// A printed nonnegativity claim.
pub fn nonnegative_claim<B: ExactBasis>(
    basis: &B,
    range: Option<&ParamRange>,
    maximal: bool,
) -> Verdict {
    let v = match (basis.parameters().len(), maximal) {
        (1, true) => maximal_versus_published(basis, range),
        (0 | 1, _) => nonnegative_on(basis, range),
        _ => several(basis, maximal),
    };
    crate::exact::defined_by(v, basis)
}

/// The convex-hull property: unity and nonnegativity on the range.
pub fn convex_hull<B: ExactBasis>(basis: &B, range: Option<&ParamRange>) -> Verdict {
    convex_hull_claim(basis, range, false)
}

/// [`convex_hull`], with `maximal` the claim that the range is the maximal
/// one: with the partition of unity, the convex-hull property of every
/// control polygon holds exactly where the functions are nonnegative (a
/// negative `bᵢ(x)` puts the curve of `Pᵢ = 1`, the others `0`, outside
/// `[0, 1]`), so the maximal set is the maximal nonnegativity set.
pub fn convex_hull_claim<B: ExactBasis>(
    basis: &B,
    range: Option<&ParamRange>,
    maximal: bool,
) -> Verdict {
    let mut v = Verdict::all(
        CERTIFIED,
        vec![
            ("partition of unity".into(), unity(basis)),
            (
                "nonnegativity".into(),
                nonnegative_claim(basis, range, maximal),
            ),
        ],
    );
    v.evidence.insert(
        0,
        "a curve Σ b_i P_i lies in the convex hull of its control points when the b_i sum to 1 and are ≥ 0 (both decided below)",
    );
    v
}

/// The maximal nonnegativity interval of a one-parameter basis against the
/// published (declared, or the claim's) range.
fn maximal_versus_published<B: ExactBasis>(basis: &B, claimed: Option<&ParamRange>) -> Verdict {
    let p = &basis.parameters()[0];
    let published = claimed.unwrap_or(&p.range);
    let (trig, fs, names) = match pieces(basis) {
        Ok(p) => p,
        Err(why) => {
            let mut v = by_intervals::maximal(basis, published);
            v.evidence.insert(0, format!("published range of {}: {published} ({}); not polynomial in sin, cos or the variable on a standard domain ({why}): the interval engine decides", p.symbol, if claimed.is_some() { "as claimed" } else { &p.source }));
            return v;
        }
    };
    let source = if claimed.is_some() {
        "as claimed".to_string()
    } else {
        p.source.clone()
    };
    let cited = Published {
        name: &p.name,
        symbol: &p.symbol,
        range: published.to_string(),
        set: ParamBox::from_range(published),
        source: &source,
    };
    maximal_against(&fs, &names, trig, &cited).1
}

/// Printed monotonicity: the certified sign of the derivative on every
/// piece (a continuous function monotone on each closed piece is monotone
/// on their union; the pieces keep the direction of the variable).
pub fn monotone_claim<B: ExactBasis>(
    basis: &B,
    items: &[Monotone],
    range: Option<&ParamRange>,
) -> Verdict {
    let params = basis.parameters();
    let r = range
        .cloned()
        .or_else(|| params.first().map(|p| p.range.clone()));
    let (values, names, domain) = (basis_of(basis), basis.function_names(), basis.domain());
    let (param, bx) = match (params.as_slice(), &r) {
        ([], _) => (None, point_box()),
        ([p], Some(r)) => (Some(p.name.as_str()), ParamBox::from_range(r)),
        _ => {
            return Verdict::not_checkable(
                "monotonicity is certified for bases with at most one parameter",
            );
        }
    };
    let single = |m: &Monotone| -> Verdict {
        let (name, value) = (&names[m.function], &values[m.function]);
        let st = match standardize(value, &domain) {
            Ok(st) => st,
            Err(_) => {
                return by_intervals::monotone(basis, name, value, m.increasing, r.as_ref());
            }
        };
        let parts: Vec<(String, Verdict)> = st
            .pieces
            .iter()
            .zip(&st.labels)
            .map(|(piece, label)| {
                let name = if label.is_empty() {
                    name.clone()
                } else {
                    format!("{name} on {label}")
                };
                let v = monotone_named(piece, &name, st.trigonometric, m.increasing, param, &bx);
                (name, v)
            })
            .collect();
        match <[(String, Verdict); 1]>::try_from(parts) {
            Ok([(_, v)]) => v,
            Err(parts) => Verdict::all(CERTIFIED, parts),
        }
    };
    let v = if let [m] = items {
        single(m)
    } else {
        Verdict::all(
            CERTIFIED,
            items
                .iter()
                .map(|m| (names[m.function].clone(), single(m)))
                .collect(),
        )
    };
    crate::exact::defined_by(v, basis)
}

/// The parameter box of a basis without parameters: one point.
fn point_box() -> ParamBox {
    ParamBox::closed(Rational::new(), Rational::new())
}
