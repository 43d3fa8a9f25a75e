//! The scratch files a campaign writes before it draws cases: spec files of
//! issue 22's hostile classes (parameters named like the tool's symbols,
//! shadowing names, degenerate radicals, wide bases, rational quotients),
//! a hostile spec and outline, `--at-file` inputs with a byte-order mark or
//! an over-long line, and a symbolic link to write through. The grammar
//! ([`super::grammar`]) names them in its command lines.

use std::path::Path;

/// Parameters named like the symbols the tool introduces: the G factors
/// (`alpha`, `gamma`), a weight (`w1`), interval lengths (`h1`, `l1`).
const CLASH_SPEC: &str = r#"
id = "clash"
citation = "fuzz suite"
variable = "polynomial"
[[parameters]]
name = "alpha"
range = "[0, 1]"
[[parameters]]
name = "gamma"
symbol = "γ"
range = "[0, 1]"
[[parameters]]
name = "w1"
range = "[1, 2]"
[[parameters]]
name = "h1"
range = "[1, 2]"
[[parameters]]
name = "l1"
range = "[1, 2]"
[[functions]]
name = "b0"
formula = "(1 - t)^2*(1 + alpha*t)"
[[functions]]
name = "b1"
formula = "2*t*(1 - t)*w1*l1"
[[functions]]
name = "b2"
formula = "t^2*(gamma + h1)"
"#;

/// Degenerate radicals: `sqrt(0)`, `sqrt(1-1)`, `t*sqrt(0)`.
const RADICAL_SPEC: &str = r#"
id = "radical"
citation = "fuzz suite"
variable = "polynomial"
[[functions]]
name = "b0"
formula = "1 - t + t*sqrt(0)"
[[functions]]
name = "b1"
formula = "t + sqrt(1-1)*t^2"
"#;

/// A printed symbol that would shadow `s` (refused when loading).
const SHADOW_SPEC: &str = r#"
id = "shadow"
citation = "fuzz suite"
variable = "angle"
[[parameters]]
name = "lambda"
symbol = "s"
range = "[0, 1]"
[[functions]]
name = "b0"
formula = "(1 - s)^2"
"#;

/// `n` functions `1 + (i+1)t + (i+2)t² + t³`: rational curve tables grow
/// with `n` and the order (the cost model's bound is reached at order 3–4
/// for twelve functions).
fn wide_spec(n: usize) -> String {
    let mut text =
        String::from("id = \"wide\"\ncitation = \"fuzz suite\"\nvariable = \"polynomial\"\n");
    for i in 0..n {
        text.push_str(&format!(
            "[[functions]]\nname = \"b{i}\"\nformula = \"1 + {}*t + {}*t^2 + t^3\"\n",
            i + 1,
            i + 2
        ));
    }
    text
}

/// Four functions over `1 + a₁t + … + a₈t⁸`: exact tables and joins grow
/// with the eight parameters.
fn quotient_spec() -> String {
    let mut text =
        String::from("id = \"quotient\"\ncitation = \"fuzz suite\"\nvariable = \"polynomial\"\n");
    for k in 1..=8 {
        text.push_str(&format!(
            "[[parameters]]\nname = \"a{k}\"\nrange = \"[0, 1]\"\n"
        ));
    }
    let d: String = (1..=8).map(|k| format!(" + a{k}*t^{k}")).collect();
    for (i, n) in ["(1 - t)^3", "3*t*(1 - t)^2", "3*t^2*(1 - t)", "t^3"]
        .iter()
        .enumerate()
    {
        text.push_str(&format!(
            "[[functions]]\nname = \"b{i}\"\nformula = \"{n}/(1{d})\"\n"
        ));
    }
    text
}

/// A spec whose expanded form cancels (`((1 + s + c)⁸)⁴`), with a pole
/// just outside its parameter range (`1/(2 + p·s)` at `p = −2`, `s = 1`).
const HOSTILE_SPEC: &str = r#"
id = "hostile"
citation = "fuzz suite"
variable = "angle"
[[parameters]]
name = "p"
range = "[-1, 1]"
source = "fuzz suite"
[[functions]]
name = "f"
formula = "((1 + s + c)^8)^4"
[[functions]]
name = "g"
formula = "1/(2 + p*s)"
[[functions]]
name = "q"
formula = "(p*s - 1)^2*(1 - c)^3 - p^2"
"#;

/// Writes the hostile outline `hostile.csv` (huge, tiny and repeated
/// coordinates) and the hostile spec `hostile.toml` into `scratch`.
pub fn write(scratch: &Path) -> std::io::Result<()> {
    std::fs::create_dir_all(scratch)?;
    std::fs::write(scratch.join("hostile.toml"), HOSTILE_SPEC)?;
    std::fs::write(scratch.join("clash.toml"), CLASH_SPEC)?;
    std::fs::write(scratch.join("radical.toml"), RADICAL_SPEC)?;
    std::fs::write(scratch.join("shadow.toml"), SHADOW_SPEC)?;
    std::fs::write(scratch.join("wide.toml"), wide_spec(12))?;
    std::fs::write(scratch.join("quotient.toml"), quotient_spec())?;
    // a byte-order mark, a comment and a blank line; an over-long line
    std::fs::write(scratch.join("points.txt"), "\u{feff}0.25\n# note\n\n1/3\n")?;
    std::fs::write(scratch.join("long-line.txt"), "1".repeat(30_000))?;
    std::fs::write(scratch.join("target.svg"), "")?;
    let link = scratch.join("link.svg");
    if std::fs::symlink_metadata(&link).is_err() {
        #[cfg(unix)]
        std::os::unix::fs::symlink(scratch.join("target.svg"), &link)?;
    }
    let mut text = String::from("# hostile outline\ncontour,x,y\n");
    for i in 0..60 {
        let (x, y) = match i % 6 {
            0 => ("9e99".to_string(), "-9e99".to_string()),
            1 => ("0".to_string(), "0".to_string()),
            2 => ("0".to_string(), "0".to_string()),
            3 => (format!("{}", i as f64 * 1e-300), "1e-320".to_string()),
            4 => (format!("{i}"), format!("{}", i * i)),
            _ => ("1e99".to_string(), format!("{i}")),
        };
        text.push_str(&format!("0,{x},{y}\n"));
    }
    std::fs::write(scratch.join("hostile.csv"), text)
}
