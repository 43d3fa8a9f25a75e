//! Seed 000's appendices print long formulas; they are transcribed here as
//! text, as close to the print as plain ASCII allows, and read by the one
//! formula parser (the spec crate's, in its printed grammar
//! [`Grammar::Printed`]: juxtaposition multiplies, as in `4(S + 1) c1`, and
//! `[]`, `{}` group) into an [`Expression`] over the symbols of the
//! appendices ([`POINT`]). `S` stands for `s(ξ) = ξ² − ξ + 1` (the paper's
//! `s(ξ)`), `pi` for `π`, `zeta` for `ζ = ξ`; the shorthands of a print
//! (Appendix E's `A`, `B`, …) are substituted by their printed definitions.
//! An expression is evaluated exactly at a rational point (cheap, whatever
//! its size) and built in the symbolic ring only when needed.
//!
//! Also: the comparison of a printed value with the computed one, whose
//! evidence shows both.

use rug::Rational;
use trig_specfile::{Expression, FormulaError, Grammar};
use trig_symbolic::Sym;

use trig_judge::exact::IDENTITY;
use trig_verdict::evidence::{self, Evidence, Kind};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;
use trig_verdict::witness::witness;

/// `ζ` as the catalog names it.
pub fn zeta() -> Sym {
    Sym::var("zeta")
}

/// The paper's `s(ξ) = ξ² − ξ + 1` as printed (the catalog's
/// [`trig_core::families::seed000::s_of_xi`]; a unit test ties the two).
const S_OF_XI: &str = "zeta^2 - zeta + 1";

/// A shorthand of a print and its printed definition.
pub type Shorthand = (&'static str, &'static str);

/// Reads a transcribed formula: `S` stands for `s(ξ)`, and each shorthand
/// for its definition (itself read over the appendices' symbols and `S`).
pub fn read(text: &str, shorthands: &[Shorthand]) -> Result<Expression, FormulaError> {
    let mut symbols: Vec<&str> = POINT
        .iter()
        .map(|(n, _)| *n)
        .filter(|n| *n != "pi")
        .collect();
    symbols.push("S");
    let definitions = shorthands
        .iter()
        .map(|(name, def)| Ok((*name, Expression::parse(def, Grammar::Printed, &symbols)?)))
        .collect::<Result<Vec<_>, FormulaError>>()?;
    symbols.extend(shorthands.iter().map(|(name, _)| *name));
    let printed = definitions.iter().fold(
        Expression::parse(text, Grammar::Printed, &symbols)?,
        |e, (name, by)| e.substitute(name, by),
    );
    let s = Expression::parse(S_OF_XI, Grammar::Printed, &["zeta"])?;
    Ok(printed.substitute("S", &s))
}

/// The rational test point of [`compare`]: every symbol of the appendices.
/// `π` is given a rational stand-in: it is transcendental, so a rational
/// function over ℚ that is nonzero at some value of the symbol `π` is not
/// the zero function, and neither is its value at `π` itself once the other
/// symbols are generic.
const POINT: [(&str, (i64, i64)); 28] = [
    ("zeta", (2, 1)),
    ("pi", (355, 113)),
    ("q", (3, 1)),
    ("s", (3, 5)),
    ("c", (4, 5)),
    ("w0", (2, 1)),
    ("w1", (3, 1)),
    ("w2", (5, 1)),
    ("w3", (7, 1)),
    ("H0", (11, 1)),
    ("H1", (13, 1)),
    ("H2", (17, 1)),
    ("H3", (19, 1)),
    ("a", (1, 2)),
    ("d", (1, 3)),
    ("b0", (1, 5)),
    ("b1", (2, 7)),
    ("b2", (3, 11)),
    ("b3", (5, 13)),
    ("c0", (7, 17)),
    ("c1", (11, 19)),
    ("c2", (13, 23)),
    ("c3", (17, 29)),
    ("z", (1, 2)),
    ("S0", (23, 1)),
    ("S1", (29, 1)),
    ("S2", (31, 1)),
    ("S3", (37, 1)),
];

fn point_value(name: &str) -> Option<Rational> {
    POINT
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, q)| Rational::from(*q))
}

/// The verdict on a printed value against the computed one: holds (exact
/// identity), or fails with the computed value and, as exact proof, the two
/// values at a rational point. Large residuals are expensive in the ring;
/// the printed formula is evaluated at the point first (from its syntax
/// tree), and built in the ring for the full identity only when it agrees
/// there.
pub fn compare(printed: &Expression, computed: &Sym) -> Verdict {
    if let (Ok(p), Ok(c)) = (
        printed.at(&point_value),
        computed.eval_rational(&point_value),
    ) && p != c
    {
        let item = Evidence::new(Kind::Comparison, "")
            .with("computed", evidence::Expr::new(computed))
            .witnessed(simple_witness(printed, computed));
        return Verdict::new(Status::Fails, IDENTITY, [item]);
    }
    let residual = match printed.to_sym() {
        Ok(p) => p - computed,
        Err(e) => {
            return Verdict::not_checkable(format!(
                "the printed value cannot be formed exactly: {e}"
            ));
        }
    };
    if residual.is_zero() {
        Verdict::new(
            Status::Holds,
            IDENTITY,
            [Evidence::new(
                Kind::Comparison,
                "printed = computed exactly",
            )],
        )
    } else {
        let item = Evidence::new(Kind::Comparison, "")
            .with("computed", evidence::Expr::new(computed))
            .with("printed − computed", evidence::Expr::new(&residual))
            .witnessed(trig_verdict::witness::of_residual(&residual));
        Verdict::new(Status::Fails, IDENTITY, [item])
    }
}

/// Why a transcription was not compared: it does not read (a defect of the
/// transcription; a unit test reads every one).
pub const UNREADABLE: &str = "the transcription does not read";

/// The part of a claim that compares the printed `text` (read with
/// `shorthands`, [`read`]) with `computed`: named `label`, the printed text
/// kept with the evidence.
pub fn printed_part(
    label: String,
    text: &str,
    shorthands: &[Shorthand],
    computed: &Sym,
) -> (String, Verdict) {
    let mut v = match read(text, shorthands) {
        Ok(printed) => compare(&printed, computed),
        Err(e) => Verdict::not_checkable(format!("{UNREADABLE}: {e}")),
    };
    for e in v.evidence.iter_mut() {
        e.printed = Some(text.to_string());
    }
    (label, v)
}

/// A small witness of `printed ≠ computed`: the test point of [`POINT`]
/// simplified variable by variable ([`trig_verdict::witness::search`], with `π`
/// given its rational stand-in while searching: sides that differ there
/// are different rational functions of `π`, so they differ at `π` too), the
/// two values then shown with `π` as a symbol.
fn simple_witness(printed: &Expression, computed: &Sym) -> Option<crate::Witness> {
    let (pv, cv) = (printed.variables(), computed.variables());
    let names: Vec<String> = POINT
        .iter()
        .filter(|(n, _)| *n != "pi" && (pv.contains(*n) || cv.contains(*n)))
        .map(|(n, _)| n.to_string())
        .collect();
    let pi = point_value("pi")?;
    // Images modulo a prime that differ prove a difference cheaply. Finding
    // a first point falls back to the exact values when the images agree
    // (a coincidence modulo the prime must not hide the witness); while
    // simplifying it, equal images are taken as equal values (a coincidence
    // only leaves the witness less simple).
    let differ = |p: &trig_verdict::witness::Point, exact_when_equal: bool| {
        let value = |n: &str| -> Option<Rational> {
            if n == "pi" {
                return Some(pi.clone());
            }
            p.iter().find(|(m, _)| m == n).map(|(_, q)| q.clone())
        };
        if let (Some(a), Some(b)) = (printed.at_mod(&value), computed.eval_mod(&value))
            && (a != b || !exact_when_equal)
        {
            return a != b;
        }
        matches!(
            (printed.at(&value), computed.eval_rational(&value)),
            (Ok(a), Ok(b)) if a != b
        )
    };
    let start: trig_verdict::witness::Point = names
        .iter()
        .filter_map(|n| point_value(n).map(|q| (n.clone(), q)))
        .collect();
    let found = if differ(&start, true) {
        start
    } else {
        trig_verdict::witness::first_point(&names, &|p| differ(p, true))?
    };
    let point = trig_verdict::witness::search_from(found, &|p| differ(p, false));
    let symbolic = |n: &str| -> Option<Sym> {
        if n == "pi" {
            return Some(Sym::pi());
        }
        point
            .iter()
            .find(|(m, _)| m == n)
            .map(|(_, q)| Sym::rational(q.clone()))
    };
    let p = printed.at_sym(&symbolic).ok()?;
    let c = computed.eval(&Sym::one(), &symbolic).ok()?;
    let mut all = names;
    if pv.contains("pi") || cv.contains("pi") {
        all.push("pi".into());
    }
    Some(witness(&point, &all, vec![("printed", p), ("computed", c)]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::claim::Claim;
    use trig_core::families::seed000::s_of_xi;

    #[test]
    fn s_is_the_catalogs_s_of_xi_and_reads_into_formulas() {
        let s = read("S", &[]).unwrap().to_sym().unwrap();
        assert_eq!(s, s_of_xi(&zeta()));
        let got = read("4(S + 1)c1 - [d/2]^2", &[]).unwrap().to_sym().unwrap();
        let want = Sym::int(4) * &(s + &Sym::one()) * &Sym::var("c1")
            - &(Sym::var("d") * &Sym::var("d") / &Sym::int(4));
        assert_eq!(got, want);
        // shorthands are read over the same symbols and substituted
        let f = read("(A + S)/(d - 1)", &[("A", "2a")]).unwrap();
        let names: Vec<String> = f.variables().into_iter().collect();
        assert_eq!(names, ["a", "d", "zeta"]);
        assert!(
            read("2x", &[])
                .unwrap_err()
                .message
                .contains("unknown symbol `x`")
        );
        assert!(read("A", &[("A", "B")]).is_err());
        assert!(read("[1 + S)", &[]).is_err());
    }

    #[test]
    fn compare_shows_computed_value_on_failure() {
        let one = |text: &str| compare(&read(text, &[]).unwrap(), &Sym::one());
        assert_eq!(one("1").status, Status::Holds);
        let v = one("2");
        assert_eq!(v.status, Status::Fails);
        assert!(v.evidence[0].contains("computed = 1"), "{:?}", v.evidence);
        let (_, v) = printed_part("x".into(), "2 +", &[], &Sym::one());
        assert_eq!(v.status, Status::NotCheckable);
        assert!(v.evidence[0].contains(UNREADABLE), "{:?}", v.evidence);
    }

    /// Every transcribed formula of the appendices reads: no claim that
    /// compares prints reports an unreadable one.
    #[test]
    fn every_transcription_reads() {
        let claims: Vec<&Claim> = [super::super::seed000_appendix_e::CLAIMS]
            .into_iter()
            .flatten()
            .collect();
        // M15
        assert_eq!(claims.len(), 1);
        for claim in claims {
            let v = (claim.check)();
            let printed = v.evidence.iter().filter(|e| e.printed.is_some()).count();
            assert!(printed > 0, "{}: no printed formula compared", claim.id);
            assert!(
                !v.evidence.iter().any(|e| e.contains(UNREADABLE)),
                "{}: {:?}",
                claim.id,
                v.evidence
            );
        }
    }
}
