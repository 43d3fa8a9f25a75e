//! The judges: each decides one kind of claim for any basis — a catalog
//! family or a spec file alike ([`trig_core::Basis`]) — from the engines
//! below it (the exact ring, jets, the join solver, the certifiers), and
//! returns a [`crate::Verdict`] with its evidence. A claim (catalog or spec
//! file) only states what is printed and calls a judge.

pub mod analytic;
pub mod by_intervals;
pub mod certificate;
pub mod continuity;
pub mod curve;
pub mod domain;
pub mod endpoint;
pub mod independence;
pub mod join;
pub mod local_control;
pub mod maxima;
pub mod nonnegative;
pub mod quoted;
pub mod recomputed;
pub mod region;
pub mod shape_effect;
pub mod span;
pub mod symmetry;
pub mod total_positivity;
pub mod unity;
