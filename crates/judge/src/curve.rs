//! The curve judge: a printed derivative of the curve `Σ bᵢPᵢ` at one end
//! of any basis (terminal tangents), decided exactly.

use trig_deriv::{End, Wrt, curve_endpoint_derivatives};
use trig_symbolic::Sym;

use crate::domain::{describe_wrt, end_text, param_symbols};
use crate::exact::ExactBasis;
use crate::exact::{identities, symbols};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// Jet length: derivative orders `0..K`.
const K: usize = 8;

/// A printed derivative of the curve `Σ bᵢPᵢ` at one end (terminal
/// tangents): exact; a failure shows the computed combination.
pub fn curve_derivative<B: ExactBasis>(
    basis: &B,
    end: End,
    order: usize,
    wrt: Wrt,
    text: &str,
    value: &Sym,
) -> Verdict {
    let p = symbols("P", basis.function_names().len());
    let d = curve_endpoint_derivatives::<Sym, K>(
        basis,
        &param_symbols(basis),
        &p,
        None,
        end,
        wrt,
        &Sym::one(),
    );
    let computed = d[order].clone();
    let names: Vec<String> = p.iter().map(ToString::to_string).collect();
    let v = identities(vec![(
        format!(
            "r^({order})({}) [{}] = {text}",
            end_text(basis, end),
            describe_wrt(basis, wrt)
        ),
        computed.clone(),
        value.clone(),
    )]);
    if v.status == Status::Holds {
        v
    } else {
        v.with_correction(format!(
            "r^({order})({}) = {} (computed)",
            end_text(basis, end),
            computed.to_combination(&names)
        ))
    }
}
