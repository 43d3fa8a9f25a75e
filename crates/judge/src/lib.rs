//! # trig-judge
//!
//! The judges: each decides one kind of claim for any basis — a catalog
//! family or a spec file alike ([`trig_core::Basis`]) — from the engines
//! below it (the exact ring, jets, the join solver, the certifiers), and
//! returns a [`trig_verdict::Verdict`] with its evidence. A claim (catalog
//! or spec file, in `trig-verification`) only states what is printed and
//! calls a judge; nothing here knows what a claim is.
//!
//! Beside the judges, their shared tools: exact bases and identities
//! ([`exact`]), MPFR counterexamples ([`numeric`]) and the per-process
//! memo of work several claims ask for ([`memo`]).
//!
//! ```
//! use trig_core::Family;
//! use trig_judge::unity::unity;
//! use trig_verdict::Status;
//!
//! // Σ bᵢ = 1 for the thesis's cubic basis (3.7), decided exactly
//! assert_eq!(unity(&Family::ThesisCubic).status, Status::Holds);
//! ```

pub mod analytic;
pub mod by_intervals;
pub mod certificate;
pub mod continuity;
pub mod curve;
pub mod data_values;
pub mod domain;
pub mod end_curvature;
pub mod end_direction;
pub mod endpoint;
pub mod exact;
pub mod exact_ends;
pub mod exceptional;
pub mod fourier;
pub mod identity;
pub mod independence;
pub mod instance;
pub mod interpolant;
pub mod interpolant_jumps;
pub mod interpolant_maximum;
pub mod interpolant_point;
pub mod join;
pub mod join_singular;
pub mod knot_coefficients;
pub mod leaves_hull;
pub mod local_control;
pub mod maxima;
pub mod memo;
pub mod nonnegative;
pub mod numeric;
pub mod point_jet;
pub mod quoted;
pub mod recomputed;
pub mod region;
pub mod same_basis;
pub mod shape_effect;
pub mod span;
pub mod surface;
pub mod surface_join;
pub mod symmetry;
pub mod table_arithmetic;
pub mod table_compare;
pub mod table_count;
pub mod table_quotes;
pub mod total_positivity;
pub(crate) mod tp_conditions;
pub mod tp_maximal;
pub mod tp_maximal_box;
pub mod tp_wronskian;
pub mod unity;
