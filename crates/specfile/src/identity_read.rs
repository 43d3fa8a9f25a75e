//! Reading `check = "identity"`: printed identities `lhs = rhs` in which a
//! function of the basis (or the claim's curve) is applied at a printed
//! argument, with primes for derivatives in the variable:
//!
//! ```toml
//! check = "identity"
//! identities = ["b2(t) + b3(1 - t) = 1", "b1'(1/3) = 0"]
//! curve = "R"            # optional: R(x) = Σ bᵢ(x)Pᵢ, control points P0, P1, …
//! weights = true         # optional: R(x) = Σ wᵢbᵢ(x)Pᵢ / Σ wᵢbᵢ(x), weights w0, w1, …
//! symbols = ["q"]        # optional: further free symbols (constants of the ring)
//! readings = [{ of = "b2(t) + b3(1 - t) = 1", as = "b2(t) + b3(1 - t) = 0" }]
//! let = ["S = lambda^2 + 1", "Q = w0*b0/(w0*b0 + b1)"]   # optional, in order
//! ```
//!
//! A `let` name stands for its formula (over the functions at the
//! variable, the parameters, the symbols and earlier names) in every
//! identity, and is applied like a function, `Q''(0)`.
//!
//! An identity may be named for the report, `"(A1) Σ F_k = 1: F0 + F1 + F2 + F3 = 1"`
//! (the text before the first `: `; formulas have no colon).
//!
//! Each application `NAME'…'(ARG)` is cut out of the text and replaced by a
//! placeholder symbol; the rest is an ordinary claim formula (the bare
//! name of a function is its value at the variable). The argument must be
//! linear in the variable (`1 - t`, `pi/2 - t`, `0`, `1/3`); the judge
//! (`trig_judge::identity`) forms each application exactly.

use toml::Spanned;

use trig_symbolic::Sym;

use crate::check::{Application, Applied, Check, Curve, Identity, Let, Reading};
use crate::error::Result;
use crate::raw::RawClaim;
use crate::source::Source;
use crate::spec::{MAX_ORDER, Spec};

/// The prefix of the placeholder symbols (never a name of a file: the
/// formula names of a file do not start with two underscores).
const PLACEHOLDER: &str = "__at";

pub(crate) fn identity(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let Some(items) = &c.identities else {
        return src.invalid(
            c.check.span(),
            "claims.identities",
            format!(
                "check `identity` of claim `{}` needs the field `identities`",
                c.id.get_ref()
            ),
        );
    };
    let curve = match &c.curve {
        Some(name) => {
            let name = name.get_ref().trim().to_string();
            Some(Curve {
                name,
                weighted: c.weights.unwrap_or(false),
            })
        }
        None if c.weights.is_some() => {
            return src.invalid(
                c.check.span(),
                "claims.weights",
                "`weights` belongs to a claim with a `curve`".into(),
            );
        }
        None => None,
    };
    let mut extra: Vec<String> = Vec::new();
    let mut names = spec.names();
    if curve.is_some() {
        for prefix in ["P", "w"] {
            if prefix == "w" && !curve.as_ref().is_some_and(|k| k.weighted) {
                continue;
            }
            for i in 0..spec.functions.len() {
                let symbol = format!("{prefix}{i}");
                names
                    .fixed(&symbol, "a control point or weight of the curve")
                    .map_err(|e| crate::error::SpecError::Invalid {
                        at: src.at(c.check.span().start),
                        field: "claims.curve".into(),
                        message: e.to_string(),
                    })?;
                extra.push(symbol);
            }
        }
    }
    for symbol in c.symbols.iter().flatten() {
        let name = symbol.get_ref().trim();
        names
            .fixed(name, "a free symbol of the identities")
            .map_err(|e| crate::error::SpecError::Invalid {
                at: src.at(symbol.span().start),
                field: "claims.symbols".into(),
                message: e.to_string(),
            })?;
        if !extra.iter().any(|x| x == name) {
            extra.push(name.to_string());
        }
    }
    let mut lets: Vec<Let> = Vec::new();
    for item in c.lets.iter().flatten() {
        let Some((name, formula)) = item.get_ref().split_once('=') else {
            return src.invalid(
                item.span(),
                "claims.let",
                format!("`{}`: expected `NAME = formula`", item.get_ref()),
            );
        };
        let name = name.trim();
        names
            .fixed(name, "a name the claim's `let` defines")
            .map_err(|e| crate::error::SpecError::Invalid {
                at: src.at(item.span().start),
                field: "claims.let".into(),
                message: e.to_string(),
            })?;
        let (read, _) = spec
            .parse_claim_formula(formula, &extra, &[])
            .map_err(|e| src.formula_error(item, e))?;
        let value = substituted(&read, &lets).map_err(|e| crate::error::SpecError::Invalid {
            at: src.at(item.span().start),
            field: "claims.let".into(),
            message: format!("`{}`: {e}", item.get_ref()),
        })?;
        extra.push(name.to_string());
        lets.push(Let {
            name: name.to_string(),
            value,
        });
    }
    let identities = items
        .iter()
        .map(|item| one(src, spec, item, curve.as_ref(), &extra, &lets))
        .collect::<Result<Vec<_>>>()?;
    if identities.is_empty() {
        return src.invalid(
            c.check.span(),
            "claims.identities",
            "list at least one identity".into(),
        );
    }
    let mut readings = Vec::new();
    for r in c.readings.iter().flatten() {
        let Some(of) = identities
            .iter()
            .position(|i| [&i.text, &i.label].contains(&&r.of.get_ref().trim().to_string()))
        else {
            return src.invalid(
                r.of.span(),
                "claims.readings",
                format!("`{}` is not one of the claim's identities", r.of.get_ref()),
            );
        };
        readings.push(Reading {
            of,
            identity: one(src, spec, &r.read, curve.as_ref(), &extra, &lets)?,
        });
    }
    Ok(Check::Identity {
        identities,
        curve,
        readings,
        lets,
    })
}

/// `formula` with the earlier `let` names replaced by their values, in
/// one pass (their values hold no `let` name).
fn substituted(formula: &Sym, lets: &[Let]) -> std::result::Result<Sym, trig_symbolic::SymError> {
    if lets.is_empty() {
        return Ok(formula.clone());
    }
    formula.eval(&Sym::one(), &|name| {
        Some(
            lets.iter()
                .find(|l| l.name == name)
                .map_or_else(|| Sym::var(name), |l| l.value.clone()),
        )
    })
}

/// One printed identity: its applications cut out, both sides read.
fn one(
    src: &Source<'_>,
    spec: &Spec,
    item: &Spanned<String>,
    curve: Option<&Curve>,
    extra: &[String],
    lets: &[Let],
) -> Result<Identity> {
    let text = item.get_ref();
    let (label, formula) = match text.split_once(": ") {
        Some((label, formula)) => (label.trim(), formula),
        None => (text.trim(), text.as_str()),
    };
    let (rest, applications) = applications(src, spec, formula, item, curve, lets)?;
    let sides: Vec<&str> = rest.split('=').collect();
    if sides.len() != 2 {
        return src.invalid(
            item.span(),
            "claims.identities",
            format!("`{text}`: expected one `=` between the two sides"),
        );
    }
    let mut names: Vec<String> = extra.to_vec();
    names.extend(applications.iter().map(|a| a.symbol.clone()));
    let side = |s: &str| {
        spec.parse_claim_formula(s, &names, &[])
            .map(|(v, _)| v)
            .map_err(|e| src.formula_error(item, e))
    };
    Ok(Identity {
        text: text.trim().to_string(),
        label: label.to_string(),
        lhs: side(sides[0])?,
        rhs: side(sides[1])?,
        applications,
    })
}

/// The text with every application `NAME'…'(ARG)` of a function (or the
/// curve) replaced by a placeholder, and the applications in order.
fn applications(
    src: &Source<'_>,
    spec: &Spec,
    formula: &str,
    item: &Spanned<String>,
    curve: Option<&Curve>,
    lets: &[Let],
) -> Result<(String, Vec<Application>)> {
    let chars: Vec<char> = formula.chars().collect();
    let mut out = String::new();
    let mut found: Vec<Application> = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if !(c.is_alphabetic() || c == '_') {
            out.push(c);
            i += 1;
            continue;
        }
        let start = i;
        while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
            i += 1;
        }
        let name: String = chars[start..i].iter().collect();
        let mut j = i;
        while j < chars.len() && chars[j] == '\'' {
            j += 1;
        }
        let applied = if curve.is_some_and(|k| k.name == name) {
            Some(Applied::Curve)
        } else {
            spec.functions
                .iter()
                .position(|f| f.name == name)
                .map(Applied::Function)
                .or_else(|| lets.iter().position(|l| l.name == name).map(Applied::Let))
        };
        let (Some(applied), Some('(')) = (applied, chars.get(j)) else {
            out.push_str(&name);
            continue;
        };
        let order = j - i;
        let close = matching(&chars, j).ok_or_else(|| crate::error::SpecError::Invalid {
            at: src.at(item.span().start),
            field: "claims.identities".into(),
            message: format!(
                "`{}`: unbalanced parentheses after `{name}`",
                item.get_ref()
            ),
        })?;
        let argument_text: String = chars[j + 1..close].iter().collect();
        if order > MAX_ORDER {
            return src.invalid(
                item.span(),
                "claims.identities",
                format!("`{name}`: derivative order {order} above {MAX_ORDER}"),
            );
        }
        let argument = spec
            .parse_linear(&argument_text, "the argument of a function in an identity")
            .map_err(|e| src.formula_error(item, e))?;
        i = close + 1;
        // one placeholder per distinct application: a print that repeats
        // `F0(t)` (a sum over a common denominator) reads as one symbol, so
        // the sides simplify before anything is substituted
        if let Some(same) = found
            .iter()
            .find(|a| a.applied == applied && a.order == order && a.argument == argument)
        {
            out.push_str(&format!(" {} ", same.symbol));
            continue;
        }
        let symbol = format!("{PLACEHOLDER}{}", found.len());
        out.push_str(&format!(" {symbol} "));
        found.push(Application {
            symbol,
            applied,
            order,
            argument,
            argument_text: argument_text.trim().to_string(),
        });
    }
    Ok((out, found))
}

/// The index of the parenthesis closing the one at `open`.
fn matching(chars: &[char], open: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (k, c) in chars.iter().enumerate().skip(open) {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(k);
                }
            }
            _ => {}
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use crate::check::{Applied, Check};
    use crate::spec::Spec;

    fn hermite_with(claim: &str) -> crate::error::Result<Spec> {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples/catalog/hermite.toml");
        let text = std::fs::read_to_string(path).unwrap();
        Spec::from_str_named(
            &format!(
                "{text}\n[[claims]]\nid = \"h\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"identity\"\n{claim}\n"
            ),
            "hermite.toml",
        )
    }

    #[test]
    fn applications_are_cut_out_with_their_order_and_argument() {
        let spec =
            hermite_with("curve = \"H\"\nidentities = [\"beta_0'(1 - t) + H(0) = alpha_0 + P1\", \"step: alpha_0(0) = 2\"]\nreadings = [{ of = \"step\", as = \"alpha_0(0) = 1\" }]")
                .unwrap();
        let Check::Identity {
            identities,
            curve,
            readings,
            ..
        } = &spec.claims[0].check
        else {
            panic!("an identity claim");
        };
        assert_eq!(curve.as_ref().unwrap().name, "H");
        let apps = &identities[0].applications;
        assert_eq!(apps.len(), 2);
        assert_eq!((apps[0].applied, apps[0].order), (Applied::Function(2), 1));
        assert_eq!(apps[0].argument_text, "1 - t");
        assert_eq!((apps[1].applied, apps[1].order), (Applied::Curve, 0));
        // a name for the report, and a reading of the named identity
        assert_eq!(identities[1].label, "step");
        assert_eq!(
            (readings[0].of, readings[0].identity.label.as_str()),
            (1, "alpha_0(0) = 1")
        );
        // the bare name is the function at the variable
        assert_eq!(
            identities[0].rhs,
            spec.functions[0].value.clone() + &trig_symbolic::Sym::var("P1")
        );
    }

    #[test]
    fn a_repeated_application_is_one_symbol() {
        let spec = hermite_with(
            "identities = [\"alpha_0(0)/(alpha_0(0) + alpha_1(0)) + alpha_0'(0) = alpha_0(0)\"]",
        )
        .unwrap();
        let Check::Identity { identities, .. } = &spec.claims[0].check else {
            panic!("an identity claim");
        };
        let apps = &identities[0].applications;
        // alpha_0(0) three times, alpha_1(0) once, alpha_0'(0) once
        assert_eq!(apps.len(), 3);
        assert_eq!(identities[0].rhs, trig_symbolic::Sym::var(&apps[0].symbol));
    }

    #[test]
    fn let_names_are_symbols_of_the_sides_and_applied_like_functions() {
        let spec = hermite_with(
            "symbols = [\"w\"]\nlet = [\"K = w + 1\", \"Q = K*alpha_0\"]\nidentities = [\"Q'(0) + K = alpha_0'(0)\"]",
        )
        .unwrap();
        let Check::Identity {
            identities, lets, ..
        } = &spec.claims[0].check
        else {
            panic!("an identity claim");
        };
        // K's value is substituted into Q's; the sides keep the names
        let k = trig_symbolic::Sym::var("w") + &trig_symbolic::Sym::one();
        assert_eq!(lets[0].value, k);
        assert_eq!(lets[1].value, k * &spec.functions[0].value);
        assert_eq!(identities[0].applications[0].applied, Applied::Let(1));
        assert!(identities[0].lhs.variables().contains("K"));
        // a name that clashes, or a line without `=`, is refused
        assert!(
            hermite_with("let = [\"alpha_0 = 1\"]\nidentities = [\"alpha_0(0) = 1\"]").is_err()
        );
        let e = hermite_with("let = [\"K\"]\nidentities = [\"alpha_0(0) = 1\"]").unwrap_err();
        assert!(e.to_string().contains("expected `NAME = formula`"), "{e}");
    }

    #[test]
    fn malformed_identities_are_refused_with_the_reason() {
        let e = hermite_with("identities = [\"alpha_0(0) = alpha_1(1) = 1\"]").unwrap_err();
        assert!(e.to_string().contains("expected one `=`"), "{e}");
        let e = hermite_with("identities = [\"alpha_0(0 = 1\"]").unwrap_err();
        assert!(e.to_string().contains("unbalanced parentheses"), "{e}");
        let e = hermite_with("weights = true\nidentities = [\"alpha_0(0) = 1\"]").unwrap_err();
        assert!(e.to_string().contains("`weights` belongs"), "{e}");
        // P0 is a control point only with a curve
        assert!(hermite_with("identities = [\"alpha_0(0) = P0\"]").is_err());
    }
}
