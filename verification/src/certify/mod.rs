//! Certified inequalities: the engine is the crate `trig-certify` (one
//! path for the catalog and spec files alike, re-exported here); its
//! certificates become verdicts in [`crate::judge::certificate`], its
//! counts of maxima in [`crate::judge::maxima`].

pub use trig_certify::{algebraic, bernstein, boundary, domain, nonneg, range, region, sturm};
