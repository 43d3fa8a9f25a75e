//! End-to-end tests of the command line and across crates: one binary, one module per area.

mod audit;
mod catalog_parity;
mod cli_audit;
mod cli_audit_tex;
mod cli_certify;
mod cli_eval;
mod cli_figures;
mod cli_fit_plot;
mod cli_hostile;
mod cli_hostile_round2;
mod cli_hostile_round2_io;
mod cli_interp;
mod cli_join;
mod cli_output;
mod cli_paste;
mod cli_spec;
mod cli_spec_engine;
mod cli_spec_features;
mod cli_table;
mod cli_witness_points;
mod fuzz;
mod latex_statements;
mod sympy_forms;
mod witness_lines;
mod witness_recheck;
