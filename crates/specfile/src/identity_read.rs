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
//! positive = ["q"]       # optional: symbols the claim's conditions make positive
//! readings = [{ of = "b2(t) + b3(1 - t) = 1", as = "b2(t) + b3(1 - t) = 0" }]
//! let = ["S = lambda^2 + 1", "Q = w0*b0/(w0*b0 + b1)"]   # optional, in order
//! ```
//!
//! A `let` name stands for its formula (over the functions at the
//! variable, the parameters, the symbols and earlier names) in every
//! identity, and is applied like a function, `Q''(0)`.
//!
//! An identity may be named for the report, `"(A1) Σ F_k = 1: F0 + F1 + F2 + F3 = 1"`
//! (the text before the last `: `, which may itself contain `: `; formulas have no colon).
//!
//! Each application `NAME'…'(ARG)` is cut out of the text and replaced by a
//! placeholder symbol; the rest is an ordinary claim formula (the bare
//! name of a function is its value at the variable). The argument must be
//! linear in the variable (`1 - t`, `pi/2 - t`, `0`, `1/3`); the judge
//! (`trig_judge::identity`) forms each application exactly.

use toml::Spanned;

use trig_symbolic::Sym;

use crate::check::{
    Application, Applied, Argument, Change, Check, Correction, Curve, Identity, Let, Reading,
};
use crate::error::Result;
use crate::raw::{RawClaim, RawCurve};
use crate::source::Source;
use crate::spec::{MAX_ORDER, Spec};

/// The prefix of the placeholder symbols (never a name of a file: the
/// formula names of a file do not start with two underscores).
const PLACEHOLDER: &str = "__at";
/// The prefix of the placeholders of partial derivatives `diff(EXPR, NAME)`.
const PARTIAL: &str = "__diff";

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
    let mut curves: Vec<Curve> = Vec::new();
    match &c.curve {
        Some(name) => curves.push(Curve {
            name: name.get_ref().trim().to_string(),
            weighted: c.weights.unwrap_or(false),
            points: None,
            change: None,
        }),
        None if c.weights.is_some() => {
            return src.invalid(
                c.check.span(),
                "claims.weights",
                "`weights` belongs to a claim with a `curve`".into(),
            );
        }
        None => {}
    }
    let mut extra: Vec<String> = Vec::new();
    let mut names = spec.names();
    if let Some(curve) = curves.first() {
        for prefix in ["P", "w"] {
            if prefix == "w" && !curve.weighted {
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
    let change = change(src, spec, c, &mut names, &mut extra)?;
    let changed = change.is_some();
    for raw in c.curves.iter().flatten() {
        curves.push(printed_curve(src, spec, raw, &curves, &extra, changed)?);
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
        .map(|item| one(src, spec, item, &curves, &extra, changed, &lets))
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
            identity: one(src, spec, &r.read, &curves, &extra, changed, &lets)?,
        });
    }
    let correction = match &c.correction {
        Some(raw) => Some(Correction {
            says: raw.says.get_ref().trim().to_string(),
            identities: raw
                .identities
                .iter()
                .map(|item| one(src, spec, item, &curves, &extra, changed, &lets))
                .collect::<Result<Vec<_>>>()?,
        }),
        None => None,
    };
    let mut positive = Vec::new();
    for symbol in c.positive.iter().flatten() {
        let name = symbol.get_ref().trim();
        if !extra.iter().any(|x| x == name) || lets.iter().any(|l| l.name == name) {
            return src.invalid(
                symbol.span(),
                "claims.positive",
                format!("`{name}` is not a free symbol of the identities (`symbols`, the curve's control points or weights)"),
            );
        }
        positive.push(name.to_string());
    }
    Ok(Check::Identity {
        identities,
        curves,
        readings,
        change,
        lets,
        correction,
        positive,
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

/// A curve of printed control points: one formula per function, in the
/// parameters and the free symbols; its name unlike every other name;
/// under the claim's change of variable (`changed`) optionally its own.
fn printed_curve(
    src: &Source<'_>,
    spec: &Spec,
    raw: &RawCurve,
    before: &[Curve],
    extra: &[String],
    changed: bool,
) -> Result<Curve> {
    let name = raw.name.get_ref().trim().to_string();
    let taken = spec.names().fixed(&name, "a curve of the identities");
    if let Err(e) = taken {
        return src.invalid(raw.name.span(), "claims.curves", e.to_string());
    }
    if before.iter().any(|k| k.name == name) || extra.contains(&name) {
        return src.invalid(
            raw.name.span(),
            "claims.curves",
            format!("`{name}` names another curve or symbol of the claim"),
        );
    }
    if raw.points.len() != spec.functions.len() {
        return src.invalid(
            raw.name.span(),
            "claims.curves",
            format!(
                "curve `{name}`: {} control points for {} functions",
                raw.points.len(),
                spec.functions.len()
            ),
        );
    }
    let points = raw
        .points
        .iter()
        .map(|p| {
            spec.parse_claim_formula(p.get_ref(), extra, &[])
                .map(|(v, _)| v)
                .map_err(|e| src.formula_error(p, e))
        })
        .collect::<Result<Vec<_>>>()?;
    let change = match &raw.change {
        Some(formula) if changed => Some(
            spec.parse_claim_formula(formula.get_ref(), extra, &[])
                .map_err(|e| src.formula_error(formula, e))?
                .0,
        ),
        Some(formula) => {
            return src.invalid(
                formula.span(),
                "claims.curves",
                format!(
                    "curve `{name}`: its own `change` needs the claim's `change` (the new variable)"
                ),
            );
        }
        None => None,
    };
    Ok(Curve {
        name,
        weighted: false,
        points: Some(points),
        change,
    })
}

/// `change = { x = "(x - x_i)/h_i" }`: the identities are in the new
/// variable `x` (a free symbol beside the claim's `symbols`), the basis's
/// variable being the printed formula in it.
fn change(
    src: &Source<'_>,
    spec: &Spec,
    c: &RawClaim,
    names: &mut trig_symbolic::Names,
    extra: &mut Vec<String>,
) -> Result<Option<Change>> {
    let Some(given) = &c.change else {
        return Ok(None);
    };
    let mut entries = given.iter();
    let (Some((variable, formula)), None) = (entries.next(), entries.next()) else {
        return src.invalid(
            c.check.span(),
            "claims.change",
            "expected one new variable: `change = { x = \"formula in x\" }`".into(),
        );
    };
    names
        .fixed(variable, "the variable of a change of variable")
        .map_err(|e| crate::error::SpecError::Invalid {
            at: src.at(formula.span().start),
            field: "claims.change".into(),
            message: e.to_string(),
        })?;
    extra.push(variable.clone());
    let (value, _) = spec
        .parse_claim_formula(formula.get_ref(), extra, &[])
        .map_err(|e| src.formula_error(formula, e))?;
    Ok(Some(Change {
        variable: variable.clone(),
        text: formula.get_ref().trim().to_string(),
        value,
    }))
}

/// One printed identity: its applications cut out, both sides read.
fn one(
    src: &Source<'_>,
    spec: &Spec,
    item: &Spanned<String>,
    curves: &[Curve],
    extra: &[String],
    changed: bool,
    lets: &[Let],
) -> Result<Identity> {
    let text = item.get_ref();
    let (label, formula) = match text.rsplit_once(": ") {
        Some((label, formula)) => (label.trim(), formula),
        None => (text.trim(), text.as_str()),
    };
    let (formula, partials) = partials(src, spec, formula, item, extra, lets)?;
    let arguments = changed.then_some(extra);
    let (rest, applications) = applications(src, spec, &formula, item, curves, arguments, lets)?;
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
    names.extend(partials.iter().map(|(symbol, _)| symbol.clone()));
    let side = |s: &str| {
        spec.parse_claim_formula(s, &names, &[])
            .map(|(v, _)| {
                partials
                    .iter()
                    .fold(v, |v, (symbol, value)| v.subs(symbol, value))
            })
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

/// The text with every partial derivative `diff(EXPR, NAME)` (`EXPR` a
/// formula without applications, `NAME` a free symbol of the claim)
/// replaced by a placeholder, and each placeholder's value `∂EXPR/∂NAME`,
/// formed exactly in the ring — the claim's `let` names in `EXPR` by their
/// values first (`diff(P1, alpha1)` with `P1 = P0 + alpha1*d` is `d`).
fn partials(
    src: &Source<'_>,
    spec: &Spec,
    formula: &str,
    item: &Spanned<String>,
    extra: &[String],
    lets: &[Let],
) -> Result<(String, Vec<(String, Sym)>)> {
    let chars: Vec<char> = formula.chars().collect();
    let mut out = String::new();
    let mut found: Vec<(String, Sym)> = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let starts = chars[i..].starts_with(&['d', 'i', 'f', 'f', '('])
            && (i == 0 || !(chars[i - 1].is_alphanumeric() || chars[i - 1] == '_'));
        if !starts {
            out.push(chars[i]);
            i += 1;
            continue;
        }
        let open = i + 4;
        let refuse = |why: String| {
            src.invalid::<(String, Vec<(String, Sym)>)>(
                item.span(),
                "claims.identities",
                format!("`{}`: {why}", item.get_ref()),
            )
        };
        let Some(close) = matching(&chars, open) else {
            return refuse("unbalanced parentheses after `diff`".into());
        };
        let inner: String = chars[open + 1..close].iter().collect();
        let Some((expr, name)) = inner.rsplit_once(',') else {
            return refuse("expected `diff(EXPR, NAME)`".into());
        };
        let name = name.trim();
        if !extra.iter().any(|x| x == name) {
            return refuse(format!(
                "`diff(…, {name})`: `{name}` is not a free symbol of the claim (`symbols`)"
            ));
        }
        let (read, _) = spec
            .parse_claim_formula(expr, extra, &[])
            .map_err(|e| src.formula_error(item, e))?;
        let value = match substituted(&read, lets) {
            Ok(value) => value,
            Err(e) => return refuse(e.to_string()),
        };
        let symbol = format!("{PARTIAL}{}", found.len());
        out.push_str(&format!(" {symbol} "));
        found.push((symbol, value.diff(name)));
        i = close + 1;
    }
    Ok((out, found))
}

/// The text with every application `NAME'…'(ARG)` of a function (or the
/// curve) replaced by a placeholder, and the applications in order.
fn applications(
    src: &Source<'_>,
    spec: &Spec,
    formula: &str,
    item: &Spanned<String>,
    curves: &[Curve],
    changed: Option<&[String]>,
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
        let applied = if let Some(k) = curves.iter().position(|k| k.name == name) {
            Some(Applied::Curve(k))
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
        let argument = match changed {
            // under a change of variable: any formula in the new variable
            Some(names) => Argument::Formula(
                spec.parse_claim_formula(&argument_text, names, &[])
                    .map_err(|e| src.formula_error(item, e))?
                    .0,
            ),
            None => Argument::Linear(
                spec.parse_linear(&argument_text, "the argument of a function in an identity")
                    .map_err(|e| src.formula_error(item, e))?,
            ),
        };
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
            curves,
            readings,
            ..
        } = &spec.claims[0].check
        else {
            panic!("an identity claim");
        };
        assert_eq!(curves[0].name, "H");
        let apps = &identities[0].applications;
        assert_eq!(apps.len(), 2);
        assert_eq!((apps[0].applied, apps[0].order), (Applied::Function(2), 1));
        assert_eq!(apps[0].argument_text, "1 - t");
        assert_eq!((apps[1].applied, apps[1].order), (Applied::Curve(0), 0));
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

    #[test]
    fn printed_curves_are_read_with_one_point_per_function() {
        let spec = hermite_with(
            "symbols = [\"q\"]\ncurves = [{ name = \"R\", points = [\"q\", \"0\", \"1\", \"2*q\"] }]\nidentities = [\"R(0) = q\"]",
        )
        .unwrap();
        let Check::Identity {
            curves, identities, ..
        } = &spec.claims[0].check
        else {
            panic!("an identity claim");
        };
        assert_eq!(curves[0].name, "R");
        assert_eq!(
            curves[0].points.as_ref().unwrap()[3],
            trig_symbolic::Sym::var("q") * &trig_symbolic::Sym::int(2)
        );
        assert_eq!(identities[0].applications[0].applied, Applied::Curve(0));
        let e = hermite_with(
            "curves = [{ name = \"R\", points = [\"0\", \"1\"] }]\nidentities = [\"R(0) = 0\"]",
        )
        .unwrap_err();
        assert!(
            e.to_string().contains("2 control points for 4 functions"),
            "{e}"
        );
        let e = hermite_with("curve = \"R\"\ncurves = [{ name = \"R\", points = [\"0\", \"0\", \"0\", \"0\"] }]\nidentities = [\"R(0) = 0\"]").unwrap_err();
        assert!(e.to_string().contains("another curve"), "{e}");
    }

    #[test]
    fn positive_symbols_are_free_symbols_of_the_identities() {
        let spec = hermite_with(
            "symbols = [\"q\", \"r\"]\npositive = [\"q\"]\nidentities = [\"q*alpha_0(0) = r\"]",
        )
        .unwrap();
        let Check::Identity { positive, .. } = &spec.claims[0].check else {
            panic!("an identity claim");
        };
        assert_eq!(positive, &["q"]);
        for refused in ["z", "K"] {
            let e = hermite_with(&format!(
                "symbols = [\"q\"]\nlet = [\"K = q + 1\"]\npositive = [\"{refused}\"]\nidentities = [\"q*alpha_0(0) = 1\"]"
            ))
            .unwrap_err();
            assert!(e.to_string().contains("not a free symbol"), "{e}");
        }
    }

    #[test]
    fn a_partial_derivative_sees_through_the_let_names() {
        let c = hermite_with(
            "symbols = [\"q\", \"r\"]\nlet = [\"K = q*r + 1\"]\nidentities = [\"diff(K, q) = r\"]",
        )
        .expect("the claim reads");
        let Check::Identity { identities, .. } = &c.claims[0].check else {
            panic!("an identity claim");
        };
        assert_eq!(identities[0].lhs, trig_symbolic::Sym::var("r"));
    }

    #[test]
    fn partial_derivatives_in_free_symbols_are_formed_exactly() {
        let spec = hermite_with(
            "symbols = [\"q\", \"r\"]\nidentities = [\"diff((q*r - 1)^2, q)/2 = r*(q*r - 1)\"]",
        )
        .unwrap();
        let Check::Identity { identities, .. } = &spec.claims[0].check else {
            panic!("an identity claim");
        };
        assert!((identities[0].lhs.clone() - &identities[0].rhs).is_zero());
        let e = hermite_with("symbols = [\"q\"]\nidentities = [\"diff(q^2, z) = 0\"]").unwrap_err();
        assert!(e.to_string().contains("not a free symbol"), "{e}");
        let e = hermite_with("symbols = [\"q\"]\nidentities = [\"diff(q^2) = 0\"]").unwrap_err();
        assert!(e.to_string().contains("expected `diff(EXPR, NAME)`"), "{e}");
    }
}
