//! The JSON report's SymPy forms: one symbol per parameter whatever its
//! name, enclosures as SymPy intervals (issue 40; the whole check, every
//! form parsed by SymPy, is `examples/independent/issue40_sympy_forms.py`).

use serde_json::Value;
use trig_e2e::{example, stdout_ok};

fn audit_json(spec: &str) -> Value {
    let out = stdout_ok(&["audit", "--spec", spec, "--format", "json"]);
    serde_json::from_str(&out).expect("JSON report")
}

/// Every expression object (`sympy` with its `symbols`) of a report.
fn exprs(v: &Value, out: &mut Vec<(String, Vec<String>)>) {
    match v {
        Value::Object(m) => {
            if let (Some(Value::String(s)), Some(Value::Array(symbols))) =
                (m.get("sympy"), m.get("symbols"))
            {
                let symbols = symbols
                    .iter()
                    .map(|x| x.as_str().expect("symbol").to_string())
                    .collect();
                out.push((s.clone(), symbols));
            }
            m.values().for_each(|x| exprs(x, out));
        }
        Value::Array(a) => a.iter().for_each(|x| exprs(x, out)),
        _ => {}
    }
}

/// The names of a SymPy form (identifiers not followed by `(`).
fn names_in(form: &str) -> Vec<String> {
    let re = regex::Regex::new(r"[A-Za-z_][A-Za-z0-9_]*(\()?").expect("regex");
    re.captures_iter(form)
        .filter(|c| c.get(1).is_none())
        .map(|c| c[0].to_string())
        .collect()
}

const PYTHON_KEYWORDS: &[&str] = &[
    "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class", "continue",
    "def", "del", "elif", "else", "except", "finally", "for", "from", "global", "if", "import",
    "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise", "return", "try", "while",
    "with", "yield",
];

/// `lambda` and `lamda` are two symbols: the residual `λ − lamda + …` of
/// the failing partition of unity keeps both; the keywords `in`, `None` and
/// SymPy's `I`, `S`, `N` are renamed; every name a form uses is one of its
/// symbols (or `pi`, SymPy's), and no form names a Python keyword.
#[test]
fn names_sympy_would_merge_or_refuse_get_their_own_symbols() {
    let report = audit_json(&example("independent/issue40/names.toml"));
    let unity = report["claims"]
        .as_array()
        .expect("claims")
        .iter()
        .find(|c| c["id"] == "N-unity")
        .expect("the unity claim");
    assert_eq!(unity["verdict"], "fails");
    let residual = &unity["evidence"][0]["exprs"][0]["expr"];
    let symbols: Vec<&str> = residual["symbols"]
        .as_array()
        .expect("symbols")
        .iter()
        .map(|s| s.as_str().expect("symbol"))
        .collect();
    // the residual names seven parameters and t: eight symbols, so no two
    // parameters share one
    assert_eq!(symbols.len(), 8, "{symbols:?}");
    for s in ["lamda", "lamda_", "in_", "None_", "I_", "S_", "N_", "t"] {
        assert!(symbols.contains(&s), "{s} in {symbols:?}");
    }
    let form = residual["sympy"].as_str().expect("sympy");
    assert!(
        names_in(form).iter().any(|n| n == "lamda") && names_in(form).iter().any(|n| n == "lamda_"),
        "{form}"
    );
    let mut all = Vec::new();
    exprs(&report, &mut all);
    assert!(all.len() > 10, "the report has forms");
    for (form, symbols) in &all {
        let mut sorted = symbols.clone();
        sorted.dedup();
        assert_eq!(&sorted, symbols, "symbols listed once: {symbols:?}");
        for n in names_in(form) {
            assert!(
                n == "pi" || symbols.contains(&n),
                "{n} of {form} is not among {symbols:?}"
            );
            assert!(!PYTHON_KEYWORDS.contains(&n.as_str()), "{n} in {form}");
        }
    }
    // the witness point names each parameter's symbol
    let point = unity["witness"]["point"].as_array().expect("point");
    let pairs: Vec<(&str, &str)> = point
        .iter()
        .map(|a| {
            (
                a["name"].as_str().expect("name"),
                a["symbol"].as_str().expect("symbol"),
            )
        })
        .collect();
    assert!(pairs.contains(&("λ", "lamda")), "{pairs:?}");
    assert!(pairs.contains(&("lamda", "lamda_")), "{pairs:?}");
    assert!(pairs.contains(&("in", "in_")), "{pairs:?}");
}

/// The spec files of `examples/` and `examples/catalog/`.
fn example_specs() -> Vec<String> {
    let mut out = Vec::new();
    for dir in ["", "catalog"] {
        let path = std::path::PathBuf::from(example(dir));
        for entry in std::fs::read_dir(&path).expect("examples") {
            let p = entry.expect("entry").path();
            if p.extension().is_some_and(|e| e == "toml") {
                out.push(p.display().to_string());
            }
        }
    }
    out.sort();
    out
}

/// A certified enclosure is `Interval(Rational('lo'), Rational('hi'))`,
/// never `Float('[lo, hi]', 30)` (which SymPy cannot read) — in the JSON
/// audit of no example —, and an atom `exp(alpha)` lists the symbol
/// `alpha`, not the atom.
#[test]
fn enclosures_are_intervals_and_atoms_list_their_parameter() {
    let re =
        regex::Regex::new(r"^Interval\(Rational\('-?[0-9.e-]+'\), Rational\('-?[0-9.e-]+'\)\)$")
            .expect("regex");
    let (mut intervals, mut atoms) = (0, 0);
    let specs = example_specs();
    assert!(specs.len() > 30, "{specs:?}");
    for spec in &specs {
        let text = stdout_ok(&["audit", "--spec", spec, "--format", "json"]);
        assert!(!text.contains("Float('["), "{spec}: an interval as a Float");
        let report: Value = serde_json::from_str(&text).expect("JSON");
        let mut all = Vec::new();
        exprs(&report, &mut all);
        for (form, symbols) in &all {
            if form.starts_with("Interval(") {
                intervals += 1;
                assert!(re.is_match(form), "{spec}: {form}");
            }
            assert!(
                !symbols.iter().any(|s| s.contains('(')),
                "{spec}: an atom among the symbols {symbols:?}"
            );
            if form.contains("exp(alpha)") {
                atoms += 1;
                assert!(symbols.iter().any(|s| s == "alpha"), "{form}: {symbols:?}");
            }
        }
    }
    // the exponential Bernstein bases' real witnesses have enclosures and
    // atoms exp(alpha)
    assert!(
        intervals > 0 && atoms > 0,
        "{intervals} intervals, {atoms} atoms"
    );
}
