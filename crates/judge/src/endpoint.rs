//! The endpoint judges: printed values and derivatives of the functions
//! of any basis at the ends of its domain, interpolation at the ends, and
//! the exact derivative table (Taylor jets cross-checked by symbolic
//! differentiation).

use trig_deriv::{End, Wrt, endpoint_derivatives};
use trig_specfile::Printed;
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

/// Exact endpoint derivatives (jets over the symbolic ring) against the
/// printed values.
pub fn endpoint_derivative_values<B: ExactBasis>(
    basis: &B,
    end: End,
    order: usize,
    wrt: Wrt,
    values: &[Printed],
) -> Verdict {
    let names = basis.function_names();
    let table = endpoint_derivatives::<Sym, K>(basis, &param_symbols(basis), end, wrt, &Sym::one());
    let e = end_text(basis, end);
    let parts = values
        .iter()
        .map(|p| {
            let printed = p.text.split_once('=').map_or("", |(_, v)| v.trim());
            (
                format!(
                    "{}^({order})({e}) [{}] = {printed}",
                    names[p.function],
                    describe_wrt(basis, wrt)
                ),
                table[p.function][order].clone(),
                p.value.clone(),
            )
        })
        .collect();
    defined_by(identities(parts), basis)
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
