//! Certified inequalities: the engine is the crate `trig-certify` (one
//! path for the catalog and spec files alike, re-exported here); its
//! certificates become verdicts in [`crate::judge::certificate`]; this
//! module counts maxima ([`unimodal`]).

pub mod unimodal;

pub use trig_certify::{algebraic, bernstein, boundary, domain, nonneg, range, region, sturm};
