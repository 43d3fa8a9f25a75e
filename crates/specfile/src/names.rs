//! The names a spec gives its parameters read as exactly one thing.
//!
//! In a formula a name is looked up as a parameter (its ASCII name or its
//! printed `symbol`) before the variable and the shorthands `s`, `c`; so a
//! symbol `s` would silently turn `(1 − s)²` into a polynomial in the
//! parameter. A parameter's printed symbol is therefore held to the rules
//! of its name: one name token of the formula language, none of the
//! reserved words (`s`, `c`, the variable, `pi`/`π`, `theta`/`θ`, the
//! functions), and no other parameter's name or symbol. Nor may a
//! parameter's name or symbol read as a control point `Pᵢ`, `Qᵢ`: the join
//! and curve claims (and the standard battery's joins) write those.

/// Why `symbol`, the printed symbol of parameter `name`, may not be used
/// (`None`: it may). `reserved` are the words no parameter may take,
/// `var_name` the variable's name, `others` the names and symbols of the
/// other parameters.
pub(crate) fn symbol_refusal(
    symbol: &str,
    name: &str,
    var_name: &str,
    reserved: &[&str],
    others: &[(&str, &str)],
) -> Option<String> {
    if symbol == name {
        return None;
    }
    let mut chars = symbol.chars();
    let one_name = chars.next().is_some_and(|c| c.is_alphabetic() || c == '_')
        && chars.all(|c| c.is_alphanumeric() || c == '_');
    if !one_name {
        return Some(format!(
            "`{symbol}`: a symbol must read as one name in formulas (letters, digits, `_`), e.g. `λ` or `w₁`"
        ));
    }
    if symbol == var_name {
        return Some(format!(
            "`{symbol}`: the symbol would shadow the variable `{var_name}` in formulas"
        ));
    }
    if let Some(word) = reserved.iter().chain(&["π", "θ"]).find(|w| **w == symbol) {
        let meaning = match *word {
            "s" | "c" => " (the shorthand sin/cos of the angle)",
            "pi" | "π" => " (the number π)",
            "theta" | "θ" => " (the angle)",
            _ => "",
        };
        return Some(format!(
            "`{symbol}`: the symbol would shadow the reserved name `{word}`{meaning} in formulas"
        ));
    }
    if let Some(why) = control_point_refusal(symbol) {
        return Some(why);
    }
    others
        .iter()
        .find(|(n, s)| *n == symbol || *s == symbol)
        .map(|(n, _)| {
            format!("`{symbol}`: the symbol already names the parameter `{n}`; each name must read as one parameter")
        })
}

/// Why a parameter name or symbol that reads as a control point (`P1`,
/// `Q₀`) may not be used (`None`: it may).
pub(crate) fn control_point_refusal(name: &str) -> Option<String> {
    let reading = trig_symbolic::names::reading(name);
    let mut chars = reading.chars();
    let point = matches!(chars.next(), Some('P' | 'Q'))
        && !chars.as_str().is_empty()
        && chars.all(|c| ('₀'..='₉').contains(&c));
    point.then(|| {
        format!("`{name}` reads as a control point ({reading}) of the joins and curve claims: choose another name")
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const RESERVED: &[&str] = &["s", "c", "t", "u", "pi", "sin"];

    fn refused(symbol: &str) -> Option<String> {
        symbol_refusal(symbol, "m", "u", RESERVED, &[("lambda", "λ")])
    }

    #[test]
    fn symbols_that_would_shadow_are_refused_with_the_reason() {
        assert!(refused("s").unwrap().contains("shorthand sin/cos"));
        assert!(refused("c").unwrap().contains("shorthand sin/cos"));
        assert!(refused("u").unwrap().contains("the variable `u`"));
        assert!(refused("π").unwrap().contains("the number π"));
        assert!(refused("θ").unwrap().contains("the angle"));
        assert!(refused("sin").unwrap().contains("reserved name `sin`"));
        assert!(refused("λ").unwrap().contains("the parameter `lambda`"));
        assert!(
            refused("lambda")
                .unwrap()
                .contains("the parameter `lambda`")
        );
        assert!(refused("a b").unwrap().contains("one name"));
        assert!(refused("").unwrap().contains("one name"));
        assert_eq!(refused("μ"), None);
        assert_eq!(refused("w₁"), None);
        assert_eq!(refused("m"), None);
        assert!(refused("P₁").unwrap().contains("control point"));
        assert!(control_point_refusal("Q10").is_some());
        assert!(control_point_refusal("P").is_none() && control_point_refusal("Pa1").is_none());
    }
}
