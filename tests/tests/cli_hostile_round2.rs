//! Issue 22, item by item: no wrong exact result, no unbounded command,
//! every promised digit delivered. Each test names the item it covers and
//! failed on the code before the fix (`TRIG_AUDIT_BIN` runs them against
//! another build).

use std::path::PathBuf;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use trig_e2e::{binary, error_line, stdout_ok};

/// A scratch file for this test process.
fn scratch(name: &str, text: &str) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("hostile-round2");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    let path: PathBuf = dir.join(name);
    std::fs::write(&path, text).expect("scratch file");
    path.display().to_string()
}

/// `trig-audit ARGS`, killed after `limit` (then `None`: a hang).
fn run_within(args: &[&str], limit: Duration) -> Option<Output> {
    let mut child = Command::new(binary())
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run trig-audit");
    let start = Instant::now();
    while start.elapsed() < limit {
        if child.try_wait().expect("wait").is_some() {
            return Some(child.wait_with_output().expect("output"));
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let _ = child.kill();
    let _ = child.wait();
    None
}

/// Item 3: `sqrt(0)` (also as `sqrt(1-1)` and inside a product) is the
/// value 0; it looped forever in the spec reader.
#[test]
fn item3_the_square_root_of_zero_is_a_value_not_a_hang() {
    let path = scratch(
        "sqrt0.toml",
        "id = \"sqrt0\"\ncitation = \"issue 22\"\nvariable = \"polynomial\"\n\
         [[functions]]\nname = \"b0\"\nformula = \"1 - t + t*sqrt(0)\"\n\
         [[functions]]\nname = \"b1\"\nformula = \"t + sqrt(1-1)\"\n",
    );
    let out = run_within(
        &["eval", "--spec", &path, "--at", "1/4", "--digits", "5"],
        Duration::from_secs(30),
    )
    .expect("eval with sqrt(0) finishes");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}");
    assert!(text.contains("b0 = 7.5e-1"), "{text}");
    assert!(text.contains("b1 = 2.5e-1"), "{text}");
}

/// Item 4: a rational curve table where every function vanishes at an end
/// (`Σ wᵢbᵢ = 0` there) is a typed error naming the end, not a panic of
/// the exact ring ("division of 0 by exact zero", exit 101).
#[test]
fn item4_a_vanishing_weighted_sum_is_an_error_naming_the_end() {
    let path = scratch(
        "vanishing.toml",
        "id = \"vanishing\"\ncitation = \"issue 22\"\nvariable = \"polynomial\"\n\
         [[functions]]\nname = \"b0\"\nformula = \"t*(1 - t)\"\n\
         [[functions]]\nname = \"b1\"\nformula = \"t^2\"\n",
    );
    for order in ["0", "2"] {
        let err = error_line(&[
            "table",
            "--spec",
            &path,
            "--order",
            order,
            "--curve",
            "--rational",
        ]);
        assert!(
            err.contains("not defined at the start of the domain (t = 0)"),
            "{err}"
        );
    }
    // the end where the sum is 1 is fine alone
    let out = stdout_ok(&[
        "table",
        "--spec",
        &path,
        "--order",
        "1",
        "--curve",
        "--rational",
        "--at",
        "end",
    ]);
    assert!(out.contains("| 0 | (1)·P₁ |"), "{out}");
}

/// A one-parameter spec (`p` printed as `symbol`) with the formula `f` and
/// its complement.
fn symbol_spec(file: &str, variable: &str, symbol: &str, f: &str) -> String {
    scratch(
        file,
        &format!(
            "id = \"shadow\"\ncitation = \"issue 22\"\nvariable = \"{variable}\"\n\
             [[parameters]]\nname = \"p\"\nsymbol = \"{symbol}\"\nrange = \"[0, 1]\"\n\
             [[parameters]]\nname = \"q\"\nrange = \"[0, 1]\"\n\
             [[functions]]\nname = \"f\"\nformula = \"{f}\"\n\
             [[functions]]\nname = \"g\"\nformula = \"1 - ({f})\"\n"
        ),
    )
}

/// Item 2: a parameter's printed `symbol` may not shadow `s`, `c`, the
/// variable or another parameter (as a parameter *name* it was already
/// refused): with `symbol = "s"` on an angle basis, `(1 − s)²` was read
/// with `s` the parameter, not `sin t`.
#[test]
fn item2_a_symbol_never_shadows_s_c_the_variable_or_a_parameter() {
    for (variable, symbol, why) in [
        ("angle", "s", "shorthand sin/cos"),
        ("angle", "c", "shorthand sin/cos"),
        ("unit-angle", "u", "`u`"),
        ("angle", "π", "the number π"),
        ("angle", "q", "the parameter `q`"),
    ] {
        let path = symbol_spec(
            &format!("shadow-{variable}-{symbol}.toml"),
            variable,
            symbol,
            "(1 - s)^2",
        );
        let err = error_line(&[
            "eval", "--spec", &path, "--param", "p=1/2", "--param", "q=0", "--at", "0",
        ]);
        assert!(
            err.contains("parameters.symbol") && err.contains(why),
            "{symbol}: {err}"
        );
    }
    // an honest symbol still names the parameter, on the command line too
    let path = symbol_spec("shadow-ok.toml", "angle", "ϱ", "(1 - s)^2 + 0*ϱ");
    let out = stdout_ok(&[
        "eval", "--spec", &path, "--param", "ϱ=1/2", "--param", "q=0", "--at", "0", "--digits", "3",
    ]);
    assert!(out.contains("f = 1"), "{out}");
}
