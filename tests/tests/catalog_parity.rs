//! The catalog as spec files: every catalog family with formulas is also
//! written as a spec file, `examples/catalog/<id>.toml`, transcribed from
//! the family's Rust formula and checked against the printed source. This
//! test reads each file through the spec path and compares it with the
//! catalog path, exactly:
//!
//! * the functions: the spec's exact values against the family evaluated
//!   in the exact ring (`trig_judge::exact::basis`);
//! * the endpoint-derivative tables of orders 0–6 at both ends, in every
//!   convention (angle, `u`, data abscissa `x` with the symbol `h`, the
//!   basis variable), and for the families the catalog marks piecewise the
//!   one-sided derivatives at the knots of the assembled B-spline;
//! * the join formulas `trig_deriv::solve_join` derives: C⁰–C³, G¹, G², same
//!   and different parameters, in the angle, `u` and `x` conventions — the
//!   forced points, their pivots, or the same refusal;
//! * the metadata, as every command and judge reads it ([`Described`]): id,
//!   title, citation, variable and domain, parameters (name, symbol, range,
//!   where the range is stated), function names, piecewise.
//!
//! A catalog entry without a file must be listed in [`ABSENT`] with the
//! reason, and a file must belong to a catalog entry.

use std::path::PathBuf;

use trig_core::{Basis, Described, FamilyInfo, catalog};
use trig_deriv::{End, JoinKind, JoinSetup, Wrt, endpoint_derivatives, knot_derivatives};
use trig_judge::exact;
use trig_specfile::Spec;
use trig_symbolic::Sym;

/// Catalog entries written as no spec file, with the reason.
const ABSENT: &[(&str, &str)] = &[
    (
        "seed003",
        "no formulas: they are missing from our copy of seed 003 (Family::has_formulas is false)",
    ),
    (
        "seed000-nonuniform",
        "not a Family: its segment functions take a knot vector (seed000_nonuniform::NonUniform, the printed coefficients (2)-(3) over the knot spacings), so there is no catalog-path basis (Family::eval, exact tables, joins) to compare a file with",
    ),
];

/// Function names the spec language does not accept, and the names the
/// file uses instead: `(family, [(catalog name, file name)])`.
const RENAMED: &[(&str, &[(&str, &str)])] = &[(
    "hermite",
    &[
        ("alpha0", "alpha_0"),
        ("alpha1", "alpha_1"),
        ("beta0", "beta_0"),
        ("beta1", "beta_1"),
    ],
)];

/// Orders 0–6 of the exact tables.
const ORDERS: usize = 7;

fn catalog_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../examples/catalog")
}

fn spec_path(id: &str) -> PathBuf {
    catalog_dir().join(format!("{id}.toml"))
}

/// The catalog entries that have a spec file, with the family and the spec.
fn pairs() -> Vec<(trig_core::Family, Spec)> {
    trig_core::Family::ALL
        .into_iter()
        .filter(|f| !ABSENT.iter().any(|(id, _)| *id == f.info().id))
        .map(|f| {
            let path = spec_path(f.info().id);
            let spec = Spec::from_file(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            (f, spec)
        })
        .collect()
}

/// The family's parameters as symbols, with `suffix` (`""`, `"1"`, `"2"`).
fn symbols(names: &[String], suffix: &str) -> Vec<Sym> {
    names
        .iter()
        .map(|p| Sym::var(&format!("{p}{suffix}")))
        .collect()
}

#[test]
fn every_catalog_entry_has_a_spec_file_or_a_listed_reason() {
    let entries: Vec<FamilyInfo> = catalog();
    for info in &entries {
        let path = spec_path(info.id);
        let absent = ABSENT.iter().find(|(id, _)| *id == info.id);
        match absent {
            Some((id, _)) => assert!(
                !path.exists(),
                "{id} is listed as absent but {} exists: drop it from ABSENT",
                path.display()
            ),
            None => assert!(
                path.exists(),
                "catalog entry `{}` has no spec file {} and no reason in ABSENT",
                info.id,
                path.display()
            ),
        }
    }
    // every listed reason still names a catalog entry, and holds
    for (id, _) in ABSENT {
        assert!(
            entries.iter().any(|e| e.id == *id),
            "ABSENT names `{id}`, which is not in the catalog"
        );
    }
    let seed003 = trig_core::Family::from_id("seed003").expect("seed003 is catalogued");
    assert!(!seed003.has_formulas());
    assert!(
        trig_core::Family::from_id(trig_core::SEED000_NONUNIFORM.id).is_err(),
        "seed000-nonuniform is not a Family: it is evaluated with its knots"
    );
    // every file is a catalog entry's
    for file in std::fs::read_dir(catalog_dir()).expect("examples/catalog") {
        let name = file
            .expect("entry")
            .file_name()
            .to_string_lossy()
            .to_string();
        let id = name.strip_suffix(".toml").unwrap_or(&name);
        assert!(
            entries.iter().any(|e| e.id == id) && !ABSENT.iter().any(|(a, _)| *a == id),
            "examples/catalog/{name} is not the file of a catalog family with formulas"
        );
    }
}

#[test]
fn metadata_agree() {
    for (family, spec) in pairs() {
        let id = family.id();
        assert_eq!(spec.id(), id, "id");
        assert_eq!(spec.title(), family.title(), "{id}: title");
        assert_eq!(spec.citation(), family.citation(), "{id}: citation");
        assert_eq!(spec.variable(), family.variable(), "{id}: variable");
        assert_eq!(
            spec.variable_name(),
            family.variable_name(),
            "{id}: variable name"
        );
        assert_eq!(spec.domain(), family.domain(), "{id}: domain");
        // name, symbol, range (end by end, rational or in multiples of π),
        // where the range is stated
        assert_eq!(spec.parameters(), family.parameters(), "{id}: parameters");
        assert_eq!(spec.piecewise(), family.piecewise(), "{id}: piecewise");
        let expected: Vec<String> = match RENAMED.iter().find(|(f, _)| *f == id) {
            Some((_, map)) => family
                .function_names()
                .iter()
                .map(|n| {
                    let (_, renamed) = map.iter().find(|(c, _)| c == n).expect("every name");
                    renamed.to_string()
                })
                .collect(),
            None => family.function_names(),
        };
        assert_eq!(spec.function_names(), expected, "{id}: function names");
    }
}

/// The renamings of [`RENAMED`] are needed: the file with the catalog's
/// names is refused, naming the reserved name. When the spec language
/// accepts them, this fails: use the catalog's names and drop the entry.
#[test]
fn renamed_functions_are_still_refused_under_the_catalog_names() {
    for (id, map) in RENAMED {
        let path = spec_path(id);
        let mut text = std::fs::read_to_string(&path).expect("read");
        for (catalog, file) in *map {
            text = text.replace(
                &format!("name = \"{file}\""),
                &format!("name = \"{catalog}\""),
            );
        }
        match Spec::from_str_named(&text, &path.display().to_string()) {
            Ok(_) => {
                panic!("{id}: the catalog's function names are accepted now; rename them back")
            }
            Err(e) => {
                let message = e.to_string();
                assert!(
                    map.iter().any(|(c, _)| message.contains(&format!("`{c}`"))),
                    "{id}: refused for another reason: {message}"
                );
            }
        }
    }
}

#[test]
fn functions_are_equal_exactly() {
    for (family, spec) in pairs() {
        let id = family.info().id;
        let catalog = exact::basis(family);
        let from_spec = spec.symbolic();
        assert_eq!(from_spec.len(), catalog.len(), "{id}: number of functions");
        for ((name, s), c) in spec.function_names().iter().zip(&from_spec).zip(&catalog) {
            assert_eq!(s, c, "{id}: {name}: spec {s}, catalog {c}");
        }
    }
}

#[test]
fn endpoint_derivative_tables_are_equal() {
    let h = Sym::var("h");
    for (family, spec) in pairs() {
        let id = family.info().id;
        let p = symbols(&family.param_names(), "");
        for wrt in [Wrt::Angle, Wrt::U, Wrt::X, Wrt::Variable] {
            for end in [End::Start, End::End] {
                let catalog = endpoint_derivatives::<Sym, ORDERS>(family, &p, end, wrt, &h);
                let from_spec = endpoint_derivatives::<Sym, ORDERS>(&spec, &p, end, wrt, &h);
                assert_eq!(from_spec, catalog, "{id}: {end}, with respect to {wrt}");
            }
        }
        // what the catalog's `piecewise` promises — the uniform B-spline
        // basis function assembled from the segment functions — holds for
        // the spec's functions too (the spec format has no such flag)
        if family.info().piecewise {
            for wrt in [Wrt::Angle, Wrt::U] {
                let catalog = knot_derivatives::<Sym, ORDERS>(family, &p, wrt, &h);
                let from_spec = knot_derivatives::<Sym, ORDERS>(&spec, &p, wrt, &h);
                assert_eq!(from_spec, catalog, "{id}: knots, with respect to {wrt}");
            }
        }
    }
}

/// The second segment's points a join forces, with their pivots, or why
/// it cannot be met.
type Solved = Result<Vec<(usize, Sym, Sym)>, trig_deriv::JoinError>;

/// Two segments of `basis` with parameters `params` and the `G` factors
/// `factors`, joined by `kind` in the convention `wrt`.
fn solve(
    basis: impl Basis,
    params: (&[Sym], &[Sym]),
    factors: &[Sym; 2],
    wrt: Wrt,
    kind: JoinKind,
) -> Solved {
    let n = basis.function_names().len();
    let points =
        |name: &str| -> Vec<Sym> { (0..n).map(|i| Sym::var(&format!("{name}{i}"))).collect() };
    let setup = JoinSetup {
        basis,
        first_params: params.0,
        second_params: params.1,
        wrt,
        h: (Sym::var("h1"), Sym::var("h2")),
        factors: factors.clone(),
    };
    trig_deriv::solve_join(&setup, kind, &points("P"), &points("Q")).map(|join| {
        join.forced
            .into_iter()
            .map(|f| (f.index, f.value, f.pivot))
            .collect()
    })
}

/// The join formulas of both paths, with the same `G` factors for both:
/// the spec's (`gamma`, `delta` when a parameter is called `alpha` or
/// `beta`, as for usman and thesis-quadratic), so that no factor is the
/// symbol of a shape parameter.
#[test]
fn derived_join_formulas_are_equal() {
    for (family, spec) in pairs() {
        let id = family.info().id;
        let names = family.param_names();
        let factors = spec.join_factors().map(|f| Sym::var(&f));
        for (label, p1, p2) in [
            ("same", symbols(&names, ""), symbols(&names, "")),
            ("different", symbols(&names, "1"), symbols(&names, "2")),
        ] {
            for wrt in [Wrt::Angle, Wrt::U, Wrt::X] {
                for kind in JoinKind::ALL {
                    let catalog = solve(family, (&p1, &p2), &factors, wrt, kind);
                    let from_spec = solve(&spec, (&p1, &p2), &factors, wrt, kind);
                    assert_eq!(
                        from_spec, catalog,
                        "{id}: {kind}, {label} parameters, with respect to {wrt}"
                    );
                }
            }
        }
    }
}

/// The judges' verdicts on both paths: the same judge (generic over the
/// basis) decides the catalog family and its spec file, so status, method,
/// evidence and correction must agree — partition of unity, the maximal
/// nonnegativity range against the published one, symmetry, interpolation,
/// the derivative table in the angle and variable conventions, the derived
/// C¹/C² joins, and the continuity of the assembled B-spline for the
/// families the catalog marks piecewise (function names as in [`RENAMED`]).
#[test]
fn judges_give_the_same_verdicts() {
    for (family, spec) in pairs() {
        let id = family.info().id;
        let mut both: Vec<(&str, trig_verification::Verdict, trig_verification::Verdict)> = vec![
            (
                "unity",
                trig_judge::unity::unity(&family),
                trig_judge::unity::unity(&spec),
            ),
            (
                "nonnegativity",
                trig_judge::nonnegative::nonnegativity(&family),
                trig_judge::nonnegative::nonnegativity(&spec),
            ),
            (
                "symmetry",
                trig_judge::symmetry::battery_symmetry(&family).1,
                trig_judge::symmetry::battery_symmetry(&spec).1,
            ),
            (
                "interpolation",
                trig_judge::endpoint::interpolation(&family),
                trig_judge::endpoint::interpolation(&spec),
            ),
        ];
        for wrt in [Wrt::Angle, Wrt::Variable] {
            if wrt == Wrt::Angle && !family.domain().is_trigonometric() {
                continue;
            }
            both.push((
                "derivative table",
                trig_judge::endpoint::derivative_table(&family, wrt),
                trig_judge::endpoint::derivative_table(&spec, wrt),
            ));
        }
        for order in [1, 2] {
            both.push((
                "derived join",
                trig_judge::join::derived_join(&family, order),
                trig_judge::join::derived_join(&spec, order),
            ));
        }
        if family.piecewise() {
            for order in [1, 2, 3] {
                both.push((
                    "continuity",
                    trig_judge::continuity::bspline_continuity(&family, order),
                    trig_judge::continuity::bspline_continuity(&spec, order),
                ));
            }
        }
        // the files' names for functions the spec language renames
        let renames = RENAMED
            .iter()
            .find(|(f, _)| *f == id)
            .map_or(&[][..], |(_, r)| *r);
        for (what, catalog, from_spec) in both {
            let mut from_spec = format!("{from_spec:?}");
            for (catalog_name, file_name) in renames {
                from_spec = from_spec.replace(file_name, catalog_name);
            }
            assert_eq!(from_spec, format!("{catalog:?}"), "{id}: {what}");
        }
    }
}
