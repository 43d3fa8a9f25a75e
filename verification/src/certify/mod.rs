//! Certified inequalities: the engine is the crate `trig-certify` (one
//! path for the catalog and spec files alike); this module turns its
//! certificates into verdicts and evidence ([`evidence`]) and counts maxima
//! ([`unimodal`]).

pub mod evidence;
pub mod unimodal;

pub use trig_certify::{algebraic, bernstein, boundary, domain, nonneg, range, region, sturm};
