//! # trig-certify
//!
//! One certification engine for every inequality the audit decides:
//! nonnegativity and monotonicity of a basis function on its whole domain
//! for every shape parameter in a set, maximal parameter ranges with
//! exact algebraic ends, and parameter regions of two shape parameters.
//!
//! A function is an element of the exact ring ([`trig_symbolic::Sym`]):
//! a quotient of polynomials in `s = sin θ`, `c = cos θ` (or `t`) and the
//! parameters. The domain and every parameter set are mapped onto unit
//! coordinates ([`domain`]); signs are decided by exact tensor Bernstein
//! subdivision ([`bernstein`], [`nonneg`]); range ends by boundary
//! polynomials (discriminants and end values, [`boundary`], computed by
//! [`resultant`]s) whose roots are isolated by Sturm sequences ([`sturm`])
//! and decided as real algebraic numbers ([`algebraic`]); the maximal
//! interval of one parameter in [`range`], the region of two in [`region`].
//! Everything is rational arithmetic: a `holds` is a proof and every
//! witness is an exact point, re-evaluated before it is returned.

pub mod algebraic;
pub mod analytic_end;
pub mod analytic_range;
pub mod atoms;
pub mod bernstein;
pub mod bernstein_bound;
pub mod boundary;
pub mod branch;
pub mod coordinates;
pub mod domain;
pub mod elementary;
pub mod elimination;
pub mod enclosure;
pub mod exp_half_line;
pub mod factors;
pub mod krawczyk;
pub mod maxima;
pub mod minors;
pub mod neville;
pub mod nonneg;
pub mod plane_zeros;
pub mod range;
pub mod real_point;
pub mod region;
pub mod resultant;
mod rounding;
pub mod standard;
pub mod sturm;
pub mod taylor;
pub mod total_positivity;
pub mod tp_box;
pub mod tp_set;
pub mod transcendental;
pub mod wronskian;

pub use domain::{Bound, ParamBox, describe_z, in_z};
pub use standard::{Standard, standardize};

#[cfg(test)]
mod testing;
