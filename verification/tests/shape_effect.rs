//! `check = "shape-effect"` both ways on bases outside the catalog, with the
//! results derived independently in examples/independent/README.md, Part
//! D(e) (definition there and in the judge: end weights decrease and inner
//! weights increase as the parameter grows, on the whole domain × range).

use std::path::PathBuf;

use trig_specfile::Spec;
use trig_verification::Witness;
use trig_verification::{Status, Verdict, spec_audit};

/// An example spec file with one shape-effect claim appended, decided.
fn decide(name: &str, fields: &str) -> Verdict {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../examples")
        .join(format!("{name}.toml"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{e}"));
    let claim = format!(
        "[[claims]]\nid = \"SHAPE\"\nsource = \"test\"\nstatement = \"shape effect\"\ncheck = \"shape-effect\"\n{fields}\n"
    );
    let spec =
        Spec::from_str_named(&format!("{text}\n{claim}"), name).unwrap_or_else(|e| panic!("{e}"));
    spec_audit::decide(&spec, &spec.claims[spec.claims.len() - 1])
}

fn witness(v: &Verdict) -> &Witness {
    v.evidence
        .iter()
        .find_map(|e| e.witness.as_ref())
        .unwrap_or_else(|| panic!("a witness: {v:?}"))
}

fn at<'a>(w: &'a Witness, name: &str) -> &'a str {
    &w.point
        .iter()
        .find(|a| a.name == name)
        .unwrap_or_else(|| panic!("{name} in {w:?}"))
        .value
}

/// Holds: Han 2002 quadratic (∂b/∂λ = (−s(1 − s), s + c − 1, −c(1 − c))),
/// Yan & Liang (−t(1−t)³, t(1−t)³, t³(1−t), −t³(1−t)), squared Han on its
/// printed [−1, 1]; the half-angle basis through the interval engine. The
/// opposite direction fails on each.
#[test]
fn towards_the_polygon_holds_where_part_d_proves_it() {
    for name in [
        "han-quadratic",
        "yan-liang-cubic",
        "squares-han",
        "half-angle-lambda",
    ] {
        let v = decide(
            name,
            "parameter = \"lambda\"\ndirection = \"towards-polygon\"",
        );
        assert_eq!(v.status, Status::Holds, "{name}: {v:?}");
        assert!(format!("{v:?}").contains("weakest reasonable"), "{name}");
        let away = decide(
            name,
            "parameter = \"lambda\"\ndirection = \"away-from-polygon\"",
        );
        assert_eq!(away.status, Status::Fails, "{name}: {away:?}");
    }
}

/// Fails: squared Han beyond λ = 1, inside its maximal nonnegativity range
/// [−1, 2 + 2√2]: at λ = 2, (sin t, cos t) = (4/5, 3/5), ∂b0/∂λ =
/// −2 s(1 − s)²(1 − λs) = 24/625 > 0 (Part D(e)): the end weight grows.
#[test]
fn squared_han_beyond_one_moves_weight_to_the_ends() {
    let v = decide(
        "squares-han",
        "parameter = \"lambda\"\ndirection = \"towards-polygon\"\nrange = \"[-1, 2]\"",
    );
    assert_eq!(v.status, Status::Fails, "{v:?}");
    let w = witness(&v);
    assert_eq!(w.values[0].label, "∂b0/∂λ", "{w:?}");
    assert_eq!(
        (at(w, "λ"), at(w, "s"), at(w, "c")),
        ("2", "4/5", "3/5"),
        "{w:?}"
    );
    assert_eq!(w.values[0].value.plain, "24/625", "{w:?}");
}

/// A parameter the basis does not have, or a direction not known, is a
/// typed error of the file.
#[test]
fn malformed_shape_claims_are_refused() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../examples/han-quadratic.toml");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{e}"));
    for (fields, field) in [
        (
            "parameter = \"mu\"\ndirection = \"towards-polygon\"",
            "claims.parameter",
        ),
        (
            "parameter = \"lambda\"\ndirection = \"closer\"",
            "claims.direction",
        ),
        ("parameter = \"lambda\"", "claims.direction"),
    ] {
        let claim = format!(
            "[[claims]]\nid = \"SHAPE\"\nsource = \"test\"\nstatement = \"s\"\ncheck = \"shape-effect\"\n{fields}\n"
        );
        let err = Spec::from_str_named(&format!("{text}\n{claim}"), "han-quadratic")
            .expect_err("refused");
        assert!(err.to_string().contains(field), "{err}");
    }
}

/// The catalog's shape claims, with the values derived by hand: Usman's
/// (6.3) at (S, U) = (4/5, 3/5) has ∂a0/∂α = S² − S = −4/25 (a0 falls as α
/// grows: the curve moves towards the polygon, not away); the EH bases
/// give ∂b0/∂λ = t²(1 − t)² = 1/16 at t = 1/2 (a concurrent increase raises
/// the end weight b0); D15 compares curvatures at the common end P0.
#[test]
fn catalog_shape_claims_are_decided() {
    let verdict = |id: &str| {
        trig_verification::run(None, Some(id)).expect("the document files")[0]
            .verdict
            .clone()
    };
    for (id, status) in [
        ("T44", Status::Holds),
        ("T47", Status::Holds),
        ("T53", Status::Holds),
        ("D21", Status::Fails),
        ("S5", Status::NotCheckable),
    ] {
        assert_eq!(verdict(id).status, status, "{id}: {:?}", verdict(id));
    }
    let t61 = verdict("T61");
    assert_eq!(t61.status, Status::Fails, "{t61:?}");
    let w = witness(&t61);
    assert_eq!((at(w, "s"), at(w, "c")), ("4/5", "3/5"), "{w:?}");
    assert_eq!(
        (w.values[0].label.as_str(), w.values[0].value.plain.as_str()),
        ("∂a0/∂α", "-4/25")
    );
    // the rational quartic with w2 = 2 bends at P0 with curvature
    // (3/4)·w0w2/w1² = 3/2 against the quintic Bézier curve's 4/5
    let d15 = verdict("D15");
    assert_eq!(d15.status, Status::Fails, "{d15:?}");
    let w = witness(&d15);
    assert_eq!(
        (
            w.values[0].value.plain.as_str(),
            w.values[1].value.plain.as_str()
        ),
        ("3/2", "4/5")
    );
    let e21 = verdict("E21");
    assert_eq!(e21.status, Status::Fails, "{e21:?}");
    let w = witness(&e21);
    assert_eq!(at(w, "t"), "1/2", "{w:?}");
    assert_eq!(w.values[0].value.plain, "1/16", "{w:?}");
    // (i), (ii): weight moves onto the segment as the parameter decreases
    // or increases (one direction decides); (iii): the total derivative
    // raises the end weight b0 as λ, μ increase together, b2 as they fall
    for (part, status) in [
        ("(i)", Status::Holds),
        ("(ii)", Status::Holds),
        ("(iii)", Status::Fails),
    ] {
        assert!(
            e21.evidence.iter().any(|e| e
                .parts
                .first()
                .is_some_and(|p| p.name.starts_with(part) && p.status == status)),
            "{part}: {e21:?}"
        );
    }
    assert_eq!(w.values[0].label, "∂b0/∂λ + ∂b0/∂μ", "{w:?}");
}

/// A parameter inside a rational basis (the rational quadratic's weight w:
/// the inner weight grows with w), inside `cos` (weight cos α: it falls as
/// α grows on [0, 1], so the curve moves away, decided through
/// ∂cos α/∂α = −sin α by the interval engine), and one that moves the
/// domain (the quadratic C-Bézier basis on [0, α]).
#[test]
fn parameters_in_weights_atoms_and_domains() {
    let v = decide(
        "rational-quadratic",
        "parameter = \"w\"\ndirection = \"towards-polygon\"",
    );
    assert_eq!(v.status, Status::Holds, "{v:?}");
    let spec = |direction: &str| {
        format!(
            "id = \"weight-cos\"\ncitation = \"test\"\nvariable = \"t\"\ndomain = \"[0, 1]\"\n\n[[parameters]]\nname = \"alpha\"\nrange = \"[0, 1]\"\n\n[[functions]]\nname = \"b0\"\nformula = \"(1 - t)^2 / ((1 - t)^2 + 2*cos(alpha)*t*(1 - t) + t^2)\"\n\n[[functions]]\nname = \"b1\"\nformula = \"2*cos(alpha)*t*(1 - t) / ((1 - t)^2 + 2*cos(alpha)*t*(1 - t) + t^2)\"\n\n[[functions]]\nname = \"b2\"\nformula = \"t^2 / ((1 - t)^2 + 2*cos(alpha)*t*(1 - t) + t^2)\"\n\n[[claims]]\nid = \"SHAPE\"\nsource = \"test\"\nstatement = \"s\"\ncheck = \"shape-effect\"\nparameter = \"alpha\"\ndirection = \"{direction}\"\n"
        )
    };
    for (direction, status) in [
        ("away-from-polygon", Status::Holds),
        ("towards-polygon", Status::Fails),
    ] {
        let s =
            Spec::from_str_named(&spec(direction), "weight-cos").unwrap_or_else(|e| panic!("{e}"));
        let v = spec_audit::decide(&s, &s.claims[0]);
        assert_eq!(v.status, status, "{direction}: {v:?}");
    }
    // the quadratic C-Bézier basis on [0, α], compared at a fixed point of
    // u = t/α: the inner weight falls as α grows (Part D(e): at the middle
    // b1 = cos(α/2)/(1 + cos(α/2)), decreasing), so away holds
    for (direction, status) in [
        ("away-from-polygon", Status::Holds),
        ("towards-polygon", Status::Fails),
    ] {
        let c = decide(
            "c-bezier-quadratic",
            &format!("parameter = \"alpha\"\ndirection = \"{direction}\""),
        );
        assert_eq!(c.status, status, "{direction}: {c:?}");
        assert!(format!("{c:?}").contains("normalised variable"), "{c:?}");
    }
}
