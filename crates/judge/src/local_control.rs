//! The local-control judge: which segments of a piecewise curve a control
//! point or a shape parameter enters — the question behind every "local
//! control" claim ("changing `P_j` changes only the segments …", "a local
//! shape parameter affects only two segments").
//!
//! The curve is the uniform B-spline assembled from the `n` functions of a
//! basis, as the continuity judge assembles it (piece `k` of the basis
//! function is function `n − 1 − k`): segment `i` is
//! `rᵢ(x) = Σ_{k=0}^{n−1} b_k(x) P_{i+f+k}` (`f`, the index of the first
//! control point of segment 0, is `0` unless printed otherwise). So
//! - `P_j` enters segment `i` exactly with the weight `b_{j−i−f}(x)` when
//!   `0 ≤ j − i − f < n`, and with weight `0` otherwise (`∂rᵢ/∂P_j`);
//! - a parameter `p` with one value per segment (segment `i` uses
//!   `p_{i+σ}`) enters segment `i = j − σ` only, with the weights
//!   `∂b_k/∂p`, `k = 0 … n − 1` (the control points are free, so
//!   `∂rᵢ/∂p ≢ 0` exactly when one of them is `≢ 0`), and no other segment;
//! - a parameter with one value for the whole curve enters every segment
//!   when one `∂b_k/∂p ≢ 0`: no finite set of segments is all it changes.
//!
//! Each weight is decided exactly: `≡ 0` in the exact ring proves that the
//! control does not enter; a nonzero weight is shown nonzero at an exact
//! point (the witness), which proves that it does. The printed set of
//! segments is compared with the computed one: a segment printed but not
//! entered shows its identically-zero weight, a segment entered but not
//! printed shows the witness.

use std::collections::BTreeSet;

use trig_certify::atoms::{d_param, param_atoms};
use trig_symbolic::Sym;

use crate::exact::{ExactBasis, basis_of, symbols};
use trig_verdict::evidence::{Evidence, Expr, Kind};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// How local control is decided, as the report states it.
pub const METHOD: &str = "exact: the weight with which the control enters each segment (∂rᵢ/∂P_j = b_{j−i−f}, ∂rᵢ/∂p = (∂b_k/∂p)_k) decided ≡ 0 in the exact ring, or shown nonzero at an exact point (witness); the computed set of segments compared with the printed one";

/// What the claim varies.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Control {
    /// The control point `P_j`.
    Point,
    /// The parameter `name` with one value per segment: segment `i` uses
    /// the value `p_{i+shift}`.
    SegmentParameter { name: String, shift: i64 },
    /// The parameter `name` with one value for the whole curve.
    CurveParameter { name: String },
}

/// The weights with which the control enters the segment `j + offset`
/// (one or several; the control enters when one is not identically zero).
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    pub offset: i64,
    pub weights: Vec<(String, Sym)>,
}

/// The text of the segment `j + o`.
pub fn segment(o: i64) -> String {
    format!("segment j{}", signed(o))
}

/// The printed set as text.
fn set_text(offsets: &BTreeSet<i64>) -> String {
    if offsets.is_empty() {
        return "no segment".into();
    }
    offsets
        .iter()
        .map(|o| segment(*o).replace("segment ", ""))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Whether a control enters a segment with the weights of one entry.
enum Enters {
    /// Proved: a nonzero weight with a point where it is nonzero.
    Yes(Evidence),
    /// Proved not: every weight is exactly 0 (why, as text).
    No(String),
    /// A weight is nonzero in the ring but no point showed it (why).
    Unknown(String),
}

/// Decides [`Enters`] for the weights of one segment.
fn enters(weights: &[(String, Sym)]) -> Enters {
    let nonzero: Vec<&(String, Sym)> = weights.iter().filter(|(_, w)| !w.is_zero()).collect();
    if nonzero.is_empty() {
        let names: Vec<&str> = weights.iter().map(|(l, _)| l.as_str()).collect();
        return Enters::No(if names.is_empty() {
            "the control is not among the segment's terms (weight 0)".into()
        } else {
            format!("{} ≡ 0 (exact)", names.join(", "))
        });
    }
    for (label, w) in &nonzero {
        if let Some(point) = trig_verdict::witness::find(w, &Sym::zero(), (label, "0")) {
            let mut point = point;
            point.values.truncate(1);
            return Enters::Yes(
                Evidence::new(Kind::Identity, "")
                    .with(label.clone(), Expr::new(w))
                    .witnessed(Some(point)),
            );
        }
    }
    Enters::Unknown(format!(
        "{} is not 0 in the exact ring, but no point where it is visibly nonzero was found",
        nonzero[0].0
    ))
}

/// The printed set of segments `j + o` (`printed`) against the segments
/// the control enters (`entries`: every segment it may enter, with its
/// weights); `what` names the control (`P_j`, `α_j`).
pub fn compare(what: &str, entries: &[Entry], printed: &[i64]) -> Verdict {
    let printed: BTreeSet<i64> = printed.iter().copied().collect();
    let mut offsets: BTreeSet<i64> = entries.iter().map(|e| e.offset).collect();
    offsets.extend(printed.iter().copied());
    let mut evidence: Vec<Evidence> = Vec::new();
    let mut entered = BTreeSet::new();
    let mut status = Status::Holds;
    for o in offsets {
        let weights = entries
            .iter()
            .find(|e| e.offset == o)
            .map_or(&[][..], |e| &e.weights[..]);
        let subject = format!("{what} in {}", segment(o));
        let is_printed = printed.contains(&o);
        let item = match enters(weights) {
            Enters::Yes(item) => {
                entered.insert(o);
                let st = if is_printed {
                    Status::Holds
                } else {
                    Status::Fails
                };
                let text = if is_printed {
                    "enters (printed)"
                } else {
                    "enters, but the segment is not printed"
                };
                Evidence {
                    text: text.into(),
                    ..item
                }
                .about(subject, st)
            }
            Enters::No(why) if is_printed => Evidence::new(
                Kind::Identity,
                format!("printed, but does not enter: {why}"),
            )
            .about(subject, Status::Fails),
            Enters::No(_) => continue,
            Enters::Unknown(why) => {
                Evidence::new(Kind::Identity, why).about(subject, Status::NotCheckable)
            }
        };
        status = Status::conjunction([status, item.status.unwrap_or(Status::NotCheckable)]);
        evidence.push(item);
    }
    // the segments where the print is wrong first (the report shows the
    // first witness beside the verdict), each group in segment order
    evidence.sort_by_key(|e| e.status == Some(Status::Holds));
    evidence.insert(
        0,
        Evidence::note(format!(
            "{what} enters exactly: {} (printed: {})",
            set_text(&entered),
            set_text(&printed)
        )),
    );
    Verdict::new(status, METHOD, evidence)
}

/// The entries of `control` for the uniform B-spline of `functions`
/// (segment `i` is `Σ b_k P_{i+first+k}`); `d` is `∂/∂p` of the parameter.
fn entries(
    functions: &[Sym],
    control: &Control,
    first: i64,
    d: impl Fn(&str, &Sym) -> Sym,
) -> Vec<Entry> {
    let n = functions.len() as i64;
    match control {
        Control::Point => (0..n)
            .map(|k| Entry {
                offset: -k - first,
                weights: vec![(format!("b{k}"), functions[k as usize].clone())],
            })
            .collect(),
        Control::SegmentParameter { name, shift } => vec![Entry {
            offset: -shift,
            weights: functions
                .iter()
                .enumerate()
                .map(|(k, b)| (format!("∂b{k}/∂{name}"), d(name, b)))
                .collect(),
        }],
        Control::CurveParameter { .. } => Vec::new(),
    }
}

/// `+k`, `−k`, or nothing for `0` (an index offset as printed).
fn signed(k: i64) -> String {
    match k {
        0 => String::new(),
        k if k > 0 => format!("+{k}"),
        k => format!("−{}", -k),
    }
}

/// An entry with the parameter's name in its labels replaced by its
/// printed symbol.
fn relabel(e: Entry, name: &str, symbol: &str) -> Entry {
    Entry {
        offset: e.offset,
        weights: e
            .weights
            .into_iter()
            .map(|(l, w)| (l.replace(&format!("∂{name}"), &format!("∂{symbol}")), w))
            .collect(),
    }
}

/// The printed local-control claim about the uniform B-spline assembled
/// from the functions of `basis`: `control` enters exactly the segments
/// `j + o`, `o ∈ printed` (segment `i` is `Σ_k b_k P_{i+first+k}`).
pub fn local_control<B: ExactBasis>(
    basis: &B,
    control: &Control,
    first: i64,
    printed: &[i64],
) -> Verdict {
    let functions = basis_of(basis);
    let domain = basis.domain();
    let atoms = param_atoms(&domain);
    let names = basis.param_names();
    let index = |name: &str| names.iter().position(|p| p == name);
    if let Control::SegmentParameter { name, .. } | Control::CurveParameter { name } = control
        && index(name).is_none()
    {
        return Verdict::not_checkable(format!(
            "`{name}` is not a parameter of the basis ({})",
            names.join(", ")
        ));
    }
    let params = basis.parameters();
    let symbol = |name: &str| printed_symbol(&params, name);
    let d = |name: &str, f: &Sym| match index(name) {
        Some(i) => d_param(f, &domain, i, &atoms),
        None => Sym::zero(),
    };
    let n = functions.len();
    let layout = match control {
        Control::Point => format!(
            "segment i = Σ_{{k=0}}^{{{}}} b_k(x) P_{{i{}+k}} (uniform B-spline of the {n} functions; piece k is function {} − k)",
            n - 1,
            signed(first),
            n - 1
        ),
        Control::SegmentParameter { name, shift } => {
            let p = symbol(name);
            format!(
                "segment i = Σ_{{k=0}}^{{{}}} b_k(x; {p}_{{i{}}}) times its control points (however they are shared): {p}_j is the parameter of segment j{} only",
                n - 1,
                signed(*shift),
                signed(-shift)
            )
        }
        Control::CurveParameter { name } => {
            let p = symbol(name);
            format!(
                "segment i = Σ_{{k=0}}^{{{}}} b_k(x; {p}) times its control points, one {p} for every segment",
                n - 1
            )
        }
    };
    let mut v = match control {
        Control::Point => compare("P_j", &entries(&functions, control, first, d), printed),
        Control::SegmentParameter { name, .. } => compare(
            &format!("{}_j", symbol(name)),
            &entries(&functions, control, first, |_, f| d(name, f))
                .into_iter()
                .map(|e| relabel(e, name, &symbol(name)))
                .collect::<Vec<_>>(),
            printed,
        ),
        Control::CurveParameter { name } => {
            curve_parameter(&symbol(name), &functions, |f| d(name, f), printed)
        }
    };
    v.evidence.insert(0, Evidence::note(layout));
    v
}

/// The printed local-control claim about the rational uniform B-spline
/// assembled from the functions of `basis` (a NURBS curve): segment `i` is
/// `Zᵢ = Σ_k w_{i+f+k} b_k P_{i+f+k} / Σ_k w_{i+f+k} b_k` (`curve`: the printed
/// name `Z`, `point`: that of the control points `P`, `first`: `f`). The
/// control point `P_j` and the weight `w_j` enter segment `i` through the
/// local index `k = j − i − f`, with the weights `∂Z/∂P_k = w_k b_k / Σ w b`
/// and `∂Z/∂w_k = b_k (P_k − Z) / Σ w b`; each is decided exactly as for a
/// polynomial curve, against the printed segments `j + o`, `o ∈ printed`.
pub fn rational_local_control<B: ExactBasis>(
    basis: &B,
    curve: &str,
    point: &str,
    first: i64,
    printed: &[i64],
) -> Verdict {
    let functions = basis_of(basis);
    let n = functions.len();
    let (p, w) = (symbols(point, n), symbols("w", n));
    let sum = |f: &dyn Fn(usize) -> Sym| (0..n).fold(Sym::zero(), |acc, k| acc + &f(k));
    let z =
        sum(&|k| w[k].clone() * &p[k] * &functions[k]) / &sum(&|k| w[k].clone() * &functions[k]);
    let entries = |name: &str| -> Vec<Entry> {
        (0..n)
            .map(|k| Entry {
                offset: -(k as i64) - first,
                weights: vec![(
                    format!("∂{curve}/∂{name}{k}"),
                    z.diff(&format!("{name}{k}")),
                )],
            })
            .collect()
    };
    let mut v = Verdict::all(
        METHOD,
        vec![
            (
                format!("control point {point}_j"),
                compare(&format!("{point}_j"), &entries(point), printed),
            ),
            ("weight w_j".into(), compare("w_j", &entries("w"), printed)),
        ],
    );
    v.evidence.insert(
        0,
        Evidence::note(format!(
            "segment i is {curve}_i = Σ_{{k=0}}^{{{last}}} w_{{i{f}+k}} b_k(x) {point}_{{i{f}+k}} / Σ_{{k=0}}^{{{last}}} w_{{i{f}+k}} b_k(x) (rational uniform B-spline of the {n} functions; piece k is function {last} − k): {point}_j and w_j enter it as the local {point}_k, w_k, k = j − i{back}, with the weights ∂{curve}/∂{point}_k, ∂{curve}/∂w_k",
            last = n - 1,
            f = signed(first),
            back = match first {
                0 => String::new(),
                f if f < 0 => format!(" + {}", -f),
                f => format!(" − {f}"),
            },
        )),
    );
    v
}

/// For information, not a verdict: the printed claim decided under
/// another reading of what is varied (one value of a parameter per segment
/// or for the whole curve), as one line.
pub fn other_reading<B: ExactBasis>(basis: &B, control: &Control, printed: &[i64]) -> Evidence {
    let v = local_control(basis, control, 0, printed);
    let params = basis.parameters();
    let symbol = |name: &str| printed_symbol(&params, name);
    let reading = match control {
        Control::Point => "the control point P_j".to_string(),
        Control::SegmentParameter { name, .. } => format!("one {} per segment", symbol(name)),
        Control::CurveParameter { name } => format!("one {} for the whole curve", symbol(name)),
    };
    Evidence::note(format!(
        "for information, not a verdict: the other reading, {reading}, {}",
        v.status
    ))
}

/// A parameter with one value for the whole curve: it enters every
/// segment when one `∂b_k/∂p ≢ 0`, so a finite printed set fails with the
/// first segment past it (the same weights in every segment).
fn curve_parameter(
    name: &str,
    functions: &[Sym],
    d: impl Fn(&Sym) -> Sym,
    printed: &[i64],
) -> Verdict {
    let weights: Vec<(String, Sym)> = functions
        .iter()
        .enumerate()
        .map(|(k, b)| (format!("∂b{k}/∂{name}"), d(b)))
        .collect();
    let outside = printed.iter().max().map_or(0, |m| m + 1);
    let mut all: Vec<i64> = printed.to_vec();
    all.push(outside);
    let entries: Vec<Entry> = all
        .into_iter()
        .map(|offset| Entry {
            offset,
            weights: weights.clone(),
        })
        .collect();
    let mut v = compare(name, &entries, printed);
    let every = v
        .evidence
        .iter()
        .any(|item| item.text.starts_with("enters"));
    for item in v.evidence.iter_mut() {
        if item.text.starts_with(&format!("{name} enters exactly")) {
            item.text = format!(
                "{name} enters {} (printed: {})",
                if every { "every segment" } else { "no segment" },
                set_text(&printed.iter().copied().collect())
            );
        }
    }
    v.evidence.insert(
        0,
        Evidence::note(format!(
            "one value of {name} for the whole curve: every segment has the same weights ∂b_k/∂{name}, so {name} enters every segment or none; shown on the printed segments and the next one"
        )),
    );
    v
}

/// The printed symbol of the parameter `name` (the name itself when the
/// basis has no such parameter).
fn printed_symbol(params: &[trig_core::Parameter], name: &str) -> String {
    params
        .iter()
        .find(|p| p.name == name)
        .map_or_else(|| name.to_string(), |p| p.symbol.clone())
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;

    fn offsets(v: &Verdict) -> String {
        v.evidence
            .iter()
            .find(|e| e.text.contains("enters exactly"))
            .map(|e| e.text.clone())
            .unwrap_or_default()
    }

    #[test]
    fn a_point_of_the_thesis_cubic_enters_four_segments() {
        let f = Family::ThesisCubic;
        let four = local_control(&f, &Control::Point, 0, &[-3, -2, -1, 0]);
        assert_eq!(four.status, Status::Holds, "{:?}", four.evidence);
        assert!(offsets(&four).contains("j−3, j−2, j−1, j (printed"));
        let three = local_control(&f, &Control::Point, 0, &[-2, -1, 0]);
        assert_eq!(three.status, Status::Fails);
        let missing = three
            .evidence
            .iter()
            .find(|e| e.status == Some(Status::Fails))
            .expect("the segment left out");
        assert_eq!(missing.subject.as_deref(), Some("P_j in segment j−3"));
        assert!(missing.witness.is_some());
        let five = local_control(&f, &Control::Point, 0, &[-4, -3, -2, -1, 0]);
        assert_eq!(five.status, Status::Fails);
        assert!(five.evidence.iter().any(|e| e.contains("weight 0")));
    }

    #[test]
    fn the_one_m_of_the_thesis_is_not_local_but_one_m_per_segment_is() {
        let f = Family::ThesisCubic;
        let name = "m".to_string();
        let global = local_control(&f, &Control::CurveParameter { name: name.clone() }, 0, &[0]);
        assert_eq!(global.status, Status::Fails);
        let per = Control::SegmentParameter { name, shift: 0 };
        assert_eq!(local_control(&f, &per, 0, &[0]).status, Status::Holds);
        assert_eq!(local_control(&f, &per, 0, &[0, 1]).status, Status::Fails);
    }

    #[test]
    fn a_point_and_its_weight_of_a_rational_curve_enter_the_same_four_segments() {
        let f = Family::ThesisCubic;
        let v = rational_local_control(&f, "Z", "H", -3, &[0, 1, 2, 3]);
        assert_eq!(v.status, Status::Holds, "{:?}", v.evidence);
        let sets: Vec<String> = v
            .evidence
            .iter()
            .filter(|e| e.text.contains("enters exactly"))
            .map(|e| e.text.clone())
            .collect();
        assert_eq!(
            sets,
            [
                "H_j enters exactly: j, j+1, j+2, j+3 (printed: j, j+1, j+2, j+3)",
                "w_j enters exactly: j, j+1, j+2, j+3 (printed: j, j+1, j+2, j+3)"
            ]
        );
        // a segment left out fails with the witness of its nonzero weight
        let short = rational_local_control(&f, "Z", "H", -3, &[0, 1, 2]);
        assert_eq!(short.status, Status::Fails);
        assert!(
            short
                .evidence
                .iter()
                .any(|e| e.status == Some(Status::Fails) && e.witness.is_some())
        );
    }

    #[test]
    fn an_identically_zero_weight_is_not_an_entry() {
        let entries = [
            Entry {
                offset: 0,
                weights: vec![("w".into(), Sym::zero())],
            },
            Entry {
                offset: 1,
                weights: vec![("v".into(), Sym::var("t"))],
            },
        ];
        assert_eq!(compare("P_j", &entries, &[1]).status, Status::Holds);
        let v = compare("P_j", &entries, &[0, 1]);
        assert_eq!(v.status, Status::Fails);
        assert!(v.evidence.iter().any(|e| e.contains("w ≡ 0 (exact)")));
    }
}
