//! The end direction judge: the curve `Q = Σ bᵢPᵢ` of any basis at one
//! end, along a difference of two control points with a factor of a
//! stated sign (`check = "end-direction"`). With `k` the derivative order,
//! `Pa − Pb` the printed difference and `δ = 1` for `k = 0` (else `0`),
//! the claim is
//!
//! `Q⁽ᵏ⁾(end) − δ·Pb = c·(Pa − Pb)`, `c = ∂Q⁽ᵏ⁾(end)/∂Pa`,
//!
//! decided exactly (the end tangent along `P1 − P0`: `k = 1`; the end point
//! on the segment towards `P1`: `k = 0`), and `c` positive (or nonzero) for
//! every parameter value of the range: `c = N/D` in one parameter has one
//! sign on the range when neither `N` nor `D` has a real root in it (exact
//! real roots, open ends excluded), that sign read at a rational point
//! inside. Optionally `c → 0` as the parameter tends to `±∞` (the end
//! approaches `Pb`): exactly when `deg N < deg D`.

use trig_core::{ParamRange, Parameter};
use trig_deriv::{End, Wrt, curve_endpoint_derivatives};
use trig_symbolic::{Poly, Sym};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use crate::domain::{describe_wrt, end_text, param_symbols};
use crate::exact::{ExactBasis, IDENTITY, identity_item, symbols};

/// Jet length: derivative orders `0..K`.
const K: usize = 8;

/// The sign the factor `c` is stated to have.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FactorSign {
    Positive,
    Nonzero,
}

/// What is claimed at one end (see the module documentation).
#[derive(Debug, Clone)]
pub struct Direction<'a> {
    pub end: End,
    pub order: usize,
    pub wrt: Wrt,
    /// `(a, b)`: the difference `Pa − Pb`.
    pub along: (usize, usize),
    pub sign: FactorSign,
    /// The claim's range of the only parameter (`None`: the declared one).
    pub range: Option<&'a ParamRange>,
    /// `c → 0` as the parameter tends to this infinity (`"∞"`, `"−∞"`).
    pub limit: Option<&'a str>,
}

/// Decides the direction, the sign of its factor and its limit.
pub fn end_direction<B: ExactBasis>(basis: &B, claim: &Direction<'_>) -> Verdict {
    let n = basis.function_names().len();
    let p = symbols("P", n);
    let d = curve_endpoint_derivatives::<Sym, K>(
        basis,
        &param_symbols(basis),
        &p,
        None,
        claim.end,
        claim.wrt,
        &Sym::one(),
    );
    let (a, b) = claim.along;
    let at = end_text(basis, claim.end);
    let (gap, value) = if claim.order == 0 {
        (d[0].clone() - &p[b], format!("Q({at}) − P{b}"))
    } else {
        (
            d[claim.order].clone(),
            format!(
                "Q^({})({at}) [{}]",
                claim.order,
                describe_wrt(basis, claim.wrt)
            ),
        )
    };
    let c = gap.diff(&format!("P{a}"));
    let along = identity_item(
        &format!("{value} − c·(P{a} − P{b}), c = ∂/∂P{a}"),
        &gap,
        &(c.clone() * &(p[a].clone() - &p[b])),
    );
    let (signed, sign_text) = sign_on_range(basis, &c, claim);
    let mut status = Status::conjunction([along.status.unwrap_or(Status::NotCheckable), signed]);
    let mut text = format!("c = {}: {sign_text}", c.to_unicode());
    if let Some(limit) = claim.limit {
        let (tends, why) = vanishes_at_infinity(basis, &c, limit);
        status = Status::conjunction([status, tends]);
        text.push_str(&format!("; {why}"));
    }
    let mut v = Verdict::new(status, IDENTITY, [along]);
    v.evidence.push(text);
    v
}

/// The status of `c`'s stated sign on the range, with the reason.
fn sign_on_range<B: ExactBasis>(basis: &B, c: &Sym, claim: &Direction<'_>) -> (Status, String) {
    let stated = match claim.sign {
        FactorSign::Positive => "positive",
        FactorSign::Nonzero => "nonzero",
    };
    let params = basis.parameters();
    if let Some(k) = c
        .numerator()
        .as_constant()
        .filter(|_| c.denominator().is_empty())
    {
        let holds = match claim.sign {
            FactorSign::Positive => k > 0,
            FactorSign::Nonzero => k != 0,
        };
        return (
            if holds { Status::Holds } else { Status::Fails },
            format!("a constant, {}{stated}", if holds { "" } else { "not " }),
        );
    }
    let Some(param) = the_parameter(&params, c) else {
        return (
            Status::NotCheckable,
            format!(
                "its sign is decided for one parameter, not {}",
                params.len()
            ),
        );
    };
    let range = claim.range.unwrap_or(&param.range);
    let name = param.name.as_str();
    let on = format!("on {} ∈ {range}", param.symbol);
    let upoly = |q: &Poly| trig_certify::sturm::UPoly::from_poly(q, name);
    let (Some(num), Some(den)) = (upoly(c.numerator()), upoly(&c.denominator_poly())) else {
        return (
            Status::NotCheckable,
            format!(
                "not a rational function of {} alone: its sign {on} is not decided",
                param.symbol
            ),
        );
    };
    let zeros = trig_certify::plane_zeros::roots_in(&num, range);
    let poles = trig_certify::plane_zeros::roots_in(&den, range);
    if let Some(zero) = zeros.first() {
        return (
            Status::Fails,
            format!("it vanishes {on}, at {} = {zero}", param.symbol),
        );
    }
    if let Some(pole) = poles.first() {
        return (
            Status::NotCheckable,
            format!(
                "a pole {on}, at {} = {pole}: its sign is not decided",
                param.symbol
            ),
        );
    }
    let inside = range.interior_point();
    let positive = num.sign_at(&inside) * den.sign_at(&inside) > 0;
    let holds = positive || claim.sign == FactorSign::Nonzero;
    (
        if holds { Status::Holds } else { Status::Fails },
        format!(
            "{} {on} (no zero or pole of c in the range, exact real roots; {} at {} = {inside})",
            if holds {
                stated.to_string()
            } else {
                "negative".to_string()
            },
            if positive { "positive" } else { "negative" },
            param.symbol
        ),
    )
}

/// The parameter `c` is a function of: the basis's only one, or of
/// several the only one `c` depends on (Han, Ma & Huang's start tangent
/// `(2 + λ)(P1 − P0)` is the same for every `μ`, so its sign is decided on
/// `λ`'s range alone); `None` when `c` depends on several.
fn the_parameter<'p>(params: &'p [Parameter], c: &Sym) -> Option<&'p Parameter> {
    if let [one] = params {
        return Some(one);
    }
    let mut variables = c.numerator().variables();
    variables.extend(c.denominator_poly().variables());
    let mut used = params.iter().filter(|p| variables.contains(&p.name));
    match (used.next(), used.next()) {
        (Some(one), None) => Some(one),
        _ => None,
    }
}

/// Whether `c → 0` as the only parameter tends to `limit` (`±∞`): the
/// numerator of lower degree than the denominator.
fn vanishes_at_infinity<B: ExactBasis>(basis: &B, c: &Sym, limit: &str) -> (Status, String) {
    let params = basis.parameters();
    let Some(param) = the_parameter(&params, c) else {
        return (
            Status::NotCheckable,
            format!("a limit is decided for one parameter, not {}", params.len()),
        );
    };
    let name = param.name.as_str();
    let (num, den) = (
        c.numerator().degree_in(name),
        c.denominator_poly().degree_in(name),
    );
    let mut variables = c.numerator().variables();
    variables.extend(c.denominator_poly().variables());
    let other = variables.iter().any(|v| v != name);
    if other {
        return (
            Status::NotCheckable,
            format!(
                "c is not a function of {} alone: its limit is not decided",
                param.symbol
            ),
        );
    }
    if num < den {
        (
            Status::Holds,
            format!(
                "c → 0 as {} → {limit} (numerator of degree {num} in {}, denominator of degree {den})",
                param.symbol, param.symbol
            ),
        )
    } else {
        (
            Status::Fails,
            format!(
                "c does not tend to 0 as {} → {limit} (numerator of degree {num} in {}, denominator of degree {den})",
                param.symbol, param.symbol
            ),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;

    fn direction<'a>(
        along: (usize, usize),
        order: usize,
        sign: FactorSign,
        range: Option<&'a ParamRange>,
        limit: Option<&'a str>,
    ) -> Direction<'a> {
        Direction {
            end: End::Start,
            order,
            wrt: Wrt::Angle,
            along,
            sign,
            range,
            limit,
        }
    }

    #[test]
    fn the_thesis_cubic_tangent_is_positive_exactly_where_m_exceeds_minus_two() {
        // Q'(0) = (m + 2)(P1 − P0): positive on (−2, 1], zero at m = −2
        let open = ParamRange::parse("(-2, 1]").unwrap();
        let closed = ParamRange::parse("[-2, 1]").unwrap();
        let cubic = Family::ThesisCubic;
        let v = end_direction(
            &cubic,
            &direction((1, 0), 1, FactorSign::Positive, Some(&open), None),
        );
        assert_eq!(v.status, Status::Holds);
        let v = end_direction(
            &cubic,
            &direction((1, 0), 1, FactorSign::Positive, Some(&closed), None),
        );
        assert_eq!(v.status, Status::Fails);
        assert!(
            v.evidence.iter().any(|e| e.text.contains("vanishes")),
            "{v:?}"
        );
        // the tangent is not along P2 − P0
        let v = end_direction(
            &cubic,
            &direction((2, 0), 1, FactorSign::Nonzero, Some(&open), None),
        );
        assert_eq!(v.status, Status::Fails);
    }

    #[test]
    fn the_quadratic_end_point_is_never_reached_and_approached_at_infinity() {
        // F(0) − P0 = (P1 − P0)/(β + 1) on β ≥ 0
        let quadratic = Family::ThesisQuadratic;
        let d = direction((1, 0), 0, FactorSign::Nonzero, None, Some("∞"));
        assert_eq!(end_direction(&quadratic, &d).status, Status::Holds);
        // the end tangent's factor does not vanish at infinity
        let d = direction((1, 0), 1, FactorSign::Nonzero, None, Some("∞"));
        let v = end_direction(&quadratic, &d);
        assert_ne!(v.status, Status::Holds, "{v:?}");
    }

    #[test]
    fn a_factor_of_one_parameter_is_decided_beside_another() {
        // Han, Ma & Huang 2009: Q'(0) = (2 + λ)(P1 − P0) for every μ, zero
        // at λ = −2 (it was not-checkable: "decided for one parameter, not 2")
        let hmh = trig_specfile::Spec::from_file(std::path::Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../examples/han-ma-huang-cubic.toml"
        )))
        .expect("the two-parameter basis");
        let v = end_direction(
            &hmh,
            &direction((1, 0), 1, FactorSign::Positive, None, None),
        );
        assert_eq!(v.status, Status::Fails, "{v:?}");
        assert!(
            v.evidence.iter().any(|e| e.text.contains("at λ = -2")),
            "{v:?}"
        );
        // its limit too: 2 + λ does not vanish as λ → ∞
        let d = direction((1, 0), 1, FactorSign::Nonzero, None, Some("∞"));
        let v = end_direction(&hmh, &d);
        assert!(
            v.evidence
                .iter()
                .any(|e| e.text.contains("does not tend to 0")),
            "{v:?}"
        );
    }
}
