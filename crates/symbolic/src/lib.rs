//! # trig-symbolic
//!
//! The exact ring of the audit: rational functions over ℚ in named
//! variables, with the trigonometric atoms `s = sin θ`, `c = cos θ` tied by
//! `s² + c² = 1`.
//!
//! Mathematically, a [`Sym`] is an element of the field of fractions of
//!
//! `A = ℚ[x₁, …, x_k][s, c] / (s² + c² − 1)`,
//!
//! where `x₁, …, x_k` are any other names: shape parameters (`m`, `beta`,
//! `lambda`, `mu`, `eta`, `alpha`, `zeta`), `pi`, `t`, control points `P0`,
//! weights `w0`, … . `A` is an integral domain, and every element has a
//! unique representative with `s`-degree ≤ 1 (basis `cⁱ`, `s·cⁱ` over
//! `ℚ[x₁, …, x_k]`), the normal form of a [`Poly`]. Hence a quotient
//! `N / D` is zero exactly when the reduced numerator `N` is the zero
//! polynomial: [`Sym::is_zero`] and [`Sym::equals`] are exact decisions,
//! never numerical tests.
//!
//! Coefficients are rationals held in a machine word while numerator and
//! denominator fit ([`Coef`]), as GMP rationals beyond.
//!
//! Denominators are kept factored, `D = Π fᵢ^eᵢ`, with primitive factors of
//! positive leading coefficient; a factor is cancelled when it divides the
//! numerator exactly ([`Poly::exact_div`]), and a factor free of `s`, `c`
//! also by its greatest common divisor with the numerator ([`gcd`]), so
//! `(m + 2)/(m² − 4)` is `1/(m − 2)`.
//!
//! [`Sym`] implements [`trig_core::Ring`], so every formula of the catalog
//! can be evaluated symbolically:
//!
//! ```
//! use trig_core::Family;
//! use trig_symbolic::{Sym, symbolic_atoms};
//! let b = Family::ThesisCubic.eval(&symbolic_atoms(), &[Sym::var("m")]);
//! let sum = b.iter().fold(Sym::int(0), |acc, x| acc + x);
//! assert_eq!(sum, Sym::int(1));
//! assert_eq!(b[0].d_angle().to_string(), "3*m*c^3 + 4*m*s*c - 4*m*c + 2*s*c - 2*c");
//! ```
//!
//! Derivations ([`Sym::diff`], [`Sym::derive`], [`Sym::d_angle`] for
//! `d/dθ`, [`Sym::d_t`]), substitution ([`Sym::subs`]), exact and generic
//! evaluation ([`Sym::eval_rational`], [`Sym::eval`]) and canonical printing
//! (plain, Unicode, LaTeX) complete the crate.

mod calculus;
pub mod coef;
mod determinant;
mod division;
mod error;
mod eval;
pub mod factor;
pub mod gcd;
mod linear;
mod modular;
pub mod monomial;
pub mod names;
pub mod poly;
mod power;
mod print;
pub mod residue;
mod ring;
mod roots;
pub mod sym;
pub mod sympy_names;
pub mod var;

pub use coef::Coef;
pub use error::SymError;
pub use factor::{Factored, FactoredQuotient};
pub use linear::combine;
pub use monomial::Monomial;
pub use names::{NameClash, Names};
pub use poly::Poly;
pub use print::Style;
pub use residue::Residue;
pub use ring::symbolic_atoms;
pub use roots::rational_roots;
pub use sym::Sym;
pub use sympy_names::{sympy_symbol, sympy_symbols};
pub use var::Var;
