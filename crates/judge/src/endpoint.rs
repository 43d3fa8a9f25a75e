//! The endpoint judges: printed values and derivatives of the functions
//! of any basis at the ends of its domain, interpolation at the ends, and
//! the exact derivative table (Taylor jets cross-checked by symbolic
//! differentiation).

use trig_deriv::{End, Wrt, endpoint_derivatives};
use trig_specfile::{Differentiated, NamedCurve, Printed, PrintedDerivative};
use trig_symbolic::Sym;

use crate::domain::{describe_wrt, end_text, param_symbols, value_at};
use crate::exact::ExactBasis;
use crate::exact::{basis_of, defined_by, identities};
use trig_verdict::evidence::{Evidence, Expr};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// Jet length of printed derivatives: orders `0..K`.
const K: usize = 8;
/// Orders shown in the standard derivative table.
pub const TABLE_ORDERS: usize = 4;

/// Only the first function is 1 at the start, only the last at the end,
/// every other one 0 there.
pub fn interpolation<B: ExactBasis>(basis: &B) -> Verdict {
    let names = basis.function_names();
    let b = basis_of(basis);
    let n = b.len();
    let mut parts = Vec::new();
    for (end, one) in [(End::Start, 0), (End::End, n - 1)] {
        for (i, f) in b.iter().enumerate() {
            let expected = if i == one { Sym::one() } else { Sym::zero() };
            parts.push((
                format!("{}({}) = {expected}", names[i], end_text(basis, end)),
                value_at(basis, f, end),
                expected,
            ));
        }
    }
    defined_by(identities(parts), basis)
}

/// Printed values at one end; a failure names the computed values as the
/// correction.
pub fn endpoint_values<B: ExactBasis>(basis: &B, end: End, values: &[Printed]) -> Verdict {
    let names = basis.function_names();
    let b = basis_of(basis);
    let e = end_text(basis, end);
    let computed: Vec<Sym> = values
        .iter()
        .map(|p| value_at(basis, &b[p.function], end))
        .collect();
    let parts = values
        .iter()
        .zip(&computed)
        .map(|(p, c)| {
            let printed = p.text.split_once('=').map_or("", |(_, v)| v.trim());
            (
                format!("{}({e}) = {printed}", names[p.function]),
                c.clone(),
                p.value.clone(),
            )
        })
        .collect();
    let v = defined_by(identities(parts), basis);
    if v.status == Status::Holds {
        return v;
    }
    let mut groups: Vec<(Sym, Vec<String>)> = Vec::new();
    for (p, c) in values.iter().zip(&computed) {
        let name = format!("{}({e})", names[p.function]);
        match groups.iter_mut().find(|(g, _)| g == c) {
            Some((_, names)) => names.push(name),
            None => groups.push((c.clone(), vec![name])),
        }
    }
    let text = groups
        .iter()
        .map(|(g, names)| format!("{} = {g}", names.join(" = ")))
        .collect::<Vec<_>>()
        .join(" and ");
    v.with_correction(format!("{text} (the computed values)"))
}

/// Printed endpoint derivatives — of the functions and of the curves the
/// claim names (`Σ bᵢPᵢ` with its control points), each of its own order
/// and end, with the basis's parameters or the printed ones — against the
/// exact ones (Taylor jets over the symbolic ring). A failure names the computed
/// value of every printed one that differs as the correction.
pub fn endpoint_derivative_values<B: ExactBasis>(
    basis: &B,
    wrt: Wrt,
    values: &[PrintedDerivative],
    curves: &[NamedCurve],
) -> Verdict {
    let names = basis.function_names();
    let own = param_symbols(basis);
    let at =
        |params: &[Sym], end| endpoint_derivatives::<Sym, K>(basis, params, end, wrt, &Sym::one());
    let own_table = [End::Start, End::End].map(|end| at(&own, end));
    let mut parts = Vec::new();
    let mut corrections = Vec::new();
    for p in values {
        let e = end_text(basis, p.end);
        let printed_table;
        let table = match &p.params {
            None => &own_table[usize::from(p.end == End::End)],
            Some(params) => {
                printed_table = at(params, p.end);
                &printed_table
            }
        };
        let (computed, shown) = match p.of {
            Differentiated::Function(i) => {
                let d = table[i][p.order].clone();
                let shown = d.to_string();
                (d, shown)
            }
            Differentiated::Curve(k) => {
                let points = &curves[k].points;
                let d = crate::exact::sum(
                    &table
                        .iter()
                        .zip(points)
                        .map(|(f, q)| f[p.order].clone() * &Sym::var(q))
                        .collect::<Vec<_>>(),
                );
                let shown = d.to_combination(points);
                (d, shown)
            }
        };
        let name = match p.of {
            Differentiated::Function(i) => &names[i],
            Differentiated::Curve(k) => &curves[k].name,
        };
        let label = p.label.clone().unwrap_or_else(|| {
            format!(
                "{name}^({})({e}) [{}] = {}",
                p.order,
                describe_wrt(basis, wrt),
                p.printed
            )
        });
        if !computed.equals(&p.value) {
            corrections.push(format!("{} = {shown}", derivative_label(name, p.order, &e)));
        }
        parts.push((label, computed, p.value.clone()));
    }
    let v = defined_by(identities(parts), basis);
    if v.status == Status::Holds || corrections.is_empty() {
        return v;
    }
    v.with_correction(format!(
        "{} (computed, {})",
        corrections.join("; "),
        describe_wrt(basis, wrt)
    ))
}

/// One exact derivative in the table's convention: `d/dθ` (`s ↦ c`,
/// `c ↦ −s`) or `d/dx` (`s ↦ ωc`, `c ↦ −ωs`, `t ↦ 1`, `E ↦ κE`).
fn derive<B: ExactBasis>(basis: &B, wrt: Wrt, f: &Sym) -> Sym {
    if wrt == Wrt::Angle && basis.domain().is_trigonometric() {
        return f.d_angle();
    }
    trig_certify::atoms::d_variable(f, &basis.domain())
}

/// The standard derivative table, computed twice: by Taylor jets seeded
/// with the exact end atoms, and by repeated exact differentiation
/// evaluated at the end. Holds when they agree.
/// The `k`-th derivative of the function `name` at `at`, as a label:
/// `b0(0)`, `b0′(0)`, `b0″(0)`, then `b0^(3)(0)`.
fn derivative_label(name: &str, k: usize, at: &str) -> String {
    match k {
        0 => format!("{name}({at})"),
        1 => format!("{name}′({at})"),
        2 => format!("{name}″({at})"),
        _ => format!("{name}^({k})({at})"),
    }
}

pub fn derivative_table<B: ExactBasis>(basis: &B, wrt: Wrt) -> Verdict {
    let names = basis.function_names();
    let mut parts = Vec::new();
    let mut table = Vec::new();
    for end in [End::Start, End::End] {
        let jets = endpoint_derivatives::<Sym, TABLE_ORDERS>(
            basis,
            &param_symbols(basis),
            end,
            wrt,
            &Sym::one(),
        );
        for (i, f) in basis_of(basis).iter().enumerate() {
            let mut d = f.clone();
            for (k, jet) in jets[i].iter().enumerate() {
                let exact = value_at(basis, &d, end);
                if !exact.equals(jet) {
                    parts.push((
                        format!(
                            "{}^({k})({}): jets − symbolic",
                            names[i],
                            end_text(basis, end)
                        ),
                        jet.clone(),
                        exact,
                    ));
                }
                d = derive(basis, wrt, &d);
            }
            let at = end_text(basis, end);
            table.push(
                jets[i]
                    .iter()
                    .enumerate()
                    .fold(Evidence::note(""), |row, (k, jet)| {
                        row.with(derivative_label(&names[i], k, &at), Expr::new(jet))
                    }),
            );
        }
    }
    let method =
        "exact: Taylor jets over the symbolic ring, cross-checked by symbolic differentiation";
    if parts.is_empty() {
        let mut evidence = vec![Evidence::note(format!(
            "orders 0–{} {}; jets and symbolic differentiation agree exactly",
            TABLE_ORDERS - 1,
            describe_wrt(basis, wrt)
        ))];
        evidence.extend(table);
        Verdict::new(Status::Holds, method, evidence)
    } else {
        identities(parts)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_specfile::{Check, Spec};

    /// The thesis cubic with one `endpoint-derivatives` claim listing `values`.
    fn decided(values: &str) -> Verdict {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples/catalog/thesis-cubic.toml");
        let text = std::fs::read_to_string(path).unwrap();
        let spec = Spec::from_str_named(
            &format!(
                "{text}\n[[claims]]\nid = \"d\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"endpoint-derivatives\"\nwrt = \"angle\"\ncurves = [{{ name = \"Q\", points = [\"P4\", \"P5\", \"P6\", \"P7\"] }}]\nsymbols = [\"m1\"]\nvalues = [{values}]\n"
            ),
            "thesis-cubic.toml",
        )
        .unwrap_or_else(|e| panic!("{e}"));
        let Check::EndpointDerivatives {
            wrt,
            values,
            curves,
        } = &spec.claims[0].check
        else {
            panic!("an endpoint-derivatives claim");
        };
        endpoint_derivative_values(&spec, *wrt, values, curves)
    }

    #[test]
    fn listed_derivatives_of_several_orders_ends_and_curves() {
        // thesis 4.2.1, Condition 2: Q2 with m1, derivatives in the angle
        let v = decided(
            "\"Q'(0; m1) = (m1 + 2)*P5 - (m1 + 2)*P4\", \"Q''(0) = 2*P6 - (4*m + 4)*P5 + (4*m + 2)*P4\", \"b3'(1) = m + 2\"",
        );
        assert_eq!(v.status, Status::Holds, "{v:?}");
        // a wrong sign fails, the computed value its correction
        let v = decided("\"b0'(0) = m + 2\", \"b3'(1) = m + 2\"");
        assert_eq!(v.status, Status::Fails);
        let correction = v.correction.expect("the computed values");
        assert!(correction.contains("b0′(0) = -m - 2"), "{correction}");
        assert!(!correction.contains("b3"), "{correction}");
    }
}
