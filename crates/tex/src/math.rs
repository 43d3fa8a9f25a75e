//! LaTeX math: formula-like Unicode text in math mode ([`math`]), and the
//! ways a formula is set in text (inline, or on its own line scaled to fit).

use crate::symbols::{MATH, SUB, SUPER, TEXT, lookup};

/// A formula (LaTeX math) inline in text: `$…$`.
pub fn inline_math(latex: &str) -> String {
    format!("${latex}$")
}

/// A long formula (LaTeX math) on its own line, scaled down only if wider
/// than the line (`\fitmath`, defined by [`crate::PREAMBLE`]).
pub fn fitted_math(latex: &str) -> String {
    format!(r"\fitmath{{{latex}}}")
}

/// A formula-like piece of text in LaTeX math (without `$`): `_`/`^` with
/// their groups, Unicode symbols, runs of super- and subscripts merged,
/// `x̄` as `\bar{x}`, literal braces escaped.
pub fn math(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    // a stack of open braces: true = a grouping brace of `_`/`^`
    let mut braces: Vec<bool> = Vec::new();
    while i < chars.len() {
        let ch = chars[i];
        if chars.get(i + 1) == Some(&'\u{304}') {
            out.push_str(&format!(r"\bar{{{}}}", atom(ch)));
            i += 2;
            continue;
        }
        for (table, op) in [(SUPER, '^'), (SUB, '_')] {
            if lookup(table, ch).is_some() {
                let mut run = String::new();
                while let Some(s) = chars.get(i).and_then(|c| lookup(table, *c)) {
                    run.push_str(s);
                    i += 1;
                }
                out.push_str(&format!("{op}{{{run}}}"));
            }
        }
        let Some(&ch) = chars.get(i) else { break };
        if lookup(SUPER, ch).is_some() || lookup(SUB, ch).is_some() {
            continue;
        }
        match ch {
            '_' | '^' => {
                out.push(ch);
                match chars.get(i + 1) {
                    Some('{') => {
                        out.push('{');
                        braces.push(true);
                        i += 2;
                    }
                    // `^(−3)`, `F^(4)`: the bracketed group is the script
                    Some('(') if let Some(end) = closing(&chars, i + 1) => {
                        let group: String = chars[i + 1..=end].iter().collect();
                        out.push_str(&format!("{{{}}}", math(&group)));
                        i = end + 1;
                    }
                    Some(&next) => {
                        out.push_str(&format!("{{{}}}", atom(next)));
                        i += 2;
                    }
                    None => {
                        out.push_str("{}");
                        i += 1;
                    }
                }
                continue;
            }
            '{' => {
                out.push_str(r"\{");
                braces.push(false);
            }
            '}' => match braces.pop() {
                Some(true) => out.push('}'),
                _ => out.push_str(r"\}"),
            },
            _ => out.push_str(&atom(ch)),
        }
        i += 1;
    }
    for grouping in braces.into_iter().rev() {
        if grouping {
            out.push('}');
        }
    }
    out
}

/// The index of the `)` closing the `(` at `open`, if any.
fn closing(chars: &[char], open: usize) -> Option<usize> {
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

/// One character in math mode.
fn atom(ch: char) -> String {
    if let Some(m) = lookup(MATH, ch) {
        // a command needs a space before a following letter
        return if m.starts_with('\\') && m.chars().last().is_some_and(char::is_alphabetic) {
            format!("{m} ")
        } else {
            m.to_string()
        };
    }
    match ch {
        '\\' => r"\backslash ".into(),
        '$' | '&' | '#' | '%' => format!(r"\{ch}"),
        '~' => r"\sim ".into(),
        // an apostrophe after a superscript would be a second one
        '\'' => r"\text{'}".into(),
        '"' => r"\text{''}".into(),
        ' ' => " ".into(),
        _ if ch.is_ascii() => ch.to_string(),
        _ => match lookup(TEXT, ch) {
            Some(t) => format!(r"\text{{{t}}}"),
            None => format!(r"\text{{[U+{:04X}]}}", u32::from(ch)),
        },
    }
}
