//! The audit's integration tests: one binary, one module per area.

mod certified;
mod common;
mod documents;
mod fixed_values;
mod joins;
mod local_control;
mod nonnegative_options;
mod seed000;
mod seed002_004;
mod several_parameters;
mod shape_effect;
mod size;
mod spec_audit;
mod thesis_interp;
mod total_positivity;
