//! The partition-of-unity judge: `Σ bᵢ = 1` identically, decided in the
//! exact ring for any basis.

use trig_symbolic::Sym;

use crate::exact::ExactBasis;
use crate::exact::{basis_of, defined_by, identity, sum};
use trig_verdict::verdict::Verdict;

/// `Σ b_i − 1` when the names share a prefix (`b0, b1, …`), else the sum
/// written out.
pub fn sum_label(names: &[String]) -> String {
    match indexed_letter(names) {
        Some(first) => format!("Σ {first}_i − 1"),
        None => format!("{} − 1", names.join(" + ")),
    }
}

/// The common name of functions named `b0, b1, …` (`b`), when they are.
pub fn indexed_letter(names: &[String]) -> Option<String> {
    let first = names
        .first()?
        .trim_end_matches(|c: char| c.is_ascii_digit())
        .to_string();
    names
        .iter()
        .enumerate()
        .all(|(i, n)| *n == format!("{first}{i}"))
        .then_some(first)
}

/// The functions of `basis` sum to 1 identically.
pub fn unity<B: ExactBasis>(basis: &B) -> Verdict {
    defined_by(
        identity(
            &sum_label(&basis.function_names()),
            &sum(&basis_of(basis)),
            &Sym::one(),
        ),
        basis,
    )
}
