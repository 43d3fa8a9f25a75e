//! Reading `check = "same-basis"`: the other basis's file, its parameters
//! each given as a formula in this basis's, and the refusals.

use std::path::PathBuf;

use trig_specfile::{Check, Spec};
use trig_symbolic::Sym;

fn catalog(name: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/catalog")
        .join(name)
        .display()
        .to_string()
}

/// The thesis cubic with one claim `extra` (fields after `check`).
fn read(extra: &str) -> Result<Spec, String> {
    let base = std::fs::read_to_string(catalog("thesis-cubic.toml")).expect("the catalog file");
    let text =
        format!("{base}\n[[claims]]\nid = \"X\"\nsource = \"s\"\nstatement = \"x\"\n{extra}\n");
    Spec::from_str_named(&text, &catalog("x.toml")).map_err(|e| e.to_string())
}

#[test]
fn the_other_basis_and_its_parameters_are_read() {
    let spec = read(
        "check = \"same-basis\"\nother = \"majeed-qayyum.toml\"\nparams = { eta = \"m + 1\" }",
    )
    .expect("a same-basis claim");
    let Check::SameBasis {
        other,
        params,
        params_text,
        ..
    } = &spec.claims[0].check
    else {
        panic!("{:?}", spec.claims[0].check)
    };
    assert_eq!(other.id, "majeed-qayyum");
    assert_eq!(params, &[("eta".to_string(), Sym::var("m") + &Sym::one())]);
    assert_eq!(params_text, "η = m + 1");
}

#[test]
fn a_missing_or_unknown_parameter_and_a_stray_other_are_refused() {
    let cases = [
        (
            "check = \"same-basis\"\nother = \"han.toml\"",
            "`lambda` of han needs a value",
        ),
        (
            "check = \"same-basis\"\nother = \"han.toml\"\nparams = { lambda = \"m\", mu = \"1\" }",
            "`mu`: not a parameter of han",
        ),
        (
            "check = \"same-basis\"\nother = \"nowhere.toml\"\nparams = { lambda = \"m\" }",
            "nowhere.toml",
        ),
        (
            "check = \"unity\"\nother = \"han.toml\"",
            "`other` belongs to `check = \"same-basis\"`",
        ),
    ];
    for (extra, expected) in cases {
        let err = read(extra).expect_err(extra);
        assert!(err.contains(expected), "{extra}: {err}");
    }
}
