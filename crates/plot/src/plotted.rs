//! What a basis or curve plot draws: any basis — a catalog family or a
//! spec file's — with its names, the parameters it fixes and the
//! parameter settings to draw, each setting checked against the published
//! ranges ([`Plotted::new`], from a [`Choice`]).
//!
//! Text meant for the figure (the heading, the axis label, the legend) is
//! marked text (`⟪…⟫` around its formulas, [`trig_tex::marked()`]): the
//! pgfplots code sets the formulas in math, the SVG in Unicode.

use std::sync::Arc;

use rug::Rational;
use trig_core::{Affine, Basis, Batch, CoreError, Described, End, Parameter, Variable};
use trig_fit::NumericBasis;
use trig_tex::marked::{CLOSE, OPEN};

use crate::error::{PlotError, Result};

/// Which parameters a plot fixes and which one it varies, as given.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Choice {
    /// `name=value` pairs (name or printed symbol; values read exactly,
    /// as every command reads a parameter value) of the fixed parameters.
    pub fixed: Vec<(String, String)>,
    /// The varied parameter (name or printed symbol); by default the one
    /// parameter not fixed.
    pub vary: Option<String>,
    /// Its values (read exactly); by default five evenly spread over its
    /// published range (open ends left out) when it is bounded with
    /// rational ends.
    pub values: Vec<Affine>,
    /// Allow values (fixed or varied) outside the published ranges.
    pub allow_outside: bool,
}

/// A basis to draw for one or more parameter settings.
#[derive(Debug, Clone)]
pub struct Plotted {
    pub basis: Arc<dyn NumericBasis>,
    pub id: String,
    /// A short name for headings: the basis's title, or its id.
    pub name: String,
    pub citation: String,
    pub functions: Vec<String>,
    /// The parameter the settings vary: its index and printed symbol (none
    /// for a basis without parameters, or with every parameter fixed).
    pub varied: Option<(usize, String)>,
    /// The fixed parameters: printed symbol and value.
    pub fixed: Vec<(String, Affine)>,
    /// The axis label of the basis's variable (marked text).
    pub variable: String,
    /// The values of every parameter in each setting (exact, checked).
    pub settings: Vec<Vec<Affine>>,
}

/// A formula as marked text.
pub(crate) fn formula(text: &str) -> String {
    format!("{OPEN}{text}{CLOSE}")
}

/// An exact value as printed: `π` for pi, a real minus sign.
fn value_text(v: &Affine) -> String {
    v.text(&[]).replace("pi", "π").replace('-', "−")
}

/// The index of the parameter named (or printed) `name`.
fn index_of(id: &str, params: &[Parameter], name: &str) -> Result<usize> {
    params
        .iter()
        .position(|p| p.name == name || p.symbol == name)
        .ok_or_else(|| {
            PlotError::Core(CoreError::UnknownParameter {
                family: id.into(),
                name: name.into(),
                expected: match params {
                    [] => "none".into(),
                    _ => params
                        .iter()
                        .map(|p| p.name.as_str())
                        .collect::<Vec<_>>()
                        .join(", "),
                },
            })
        })
}

/// Five values evenly spread over the range of `p`, `lo + k·w/4`,
/// `k = 0..4`, without open ends; an error when the range is unbounded or
/// in multiples of π.
fn spread(p: &Parameter) -> Result<Vec<Affine>> {
    let end = |e: &End| {
        e.value()
            .filter(|_| !p.range.pi)
            .map(|q| (Affine::rational(q.clone()), matches!(e, End::Open(_))))
    };
    let (Some((lo, lo_open)), Some((hi, hi_open))) = (end(&p.range.lo), end(&p.range.hi)) else {
        return Err(PlotError::Input(format!(
            "the range of {} is unbounded (or in multiples of pi): give --values",
            p.name
        )));
    };
    let w = hi
        .plus(&lo.scale(&Rational::from(-1)))
        .scale(&Rational::from((1, 4)));
    Ok((0..=4u32)
        .filter(|&k| !(k == 0 && lo_open || k == 4 && hi_open))
        .map(|k| lo.plus(&w.scale(&Rational::from(k))))
        .collect())
}

/// The axis label of a basis's variable: its domain as a formula, with
/// what the variable is (`u ∈ [0, 1]` (angle `θ = πu/2`)).
fn variable_label(basis: &impl Described) -> String {
    let domain = basis.domain().to_string().replace(" in ", " ∈ ");
    let what = match basis.variable() {
        Some(Variable::UnitAngle) => format!(" (angle {})", formula("θ = πu/2")),
        Some(Variable::Angle) => " (radians)".into(),
        _ => String::new(),
    };
    format!("{}{what}", formula(&domain.replace("pi", "π")))
}

impl Plotted {
    /// `basis` for the parameter values of `choice`: the fixed ones, and
    /// each value of the varied one; `what` names the plot in errors.
    /// Unknown names, a parameter fixed twice or both fixed and varied,
    /// values outside the published ranges (unless allowed), and several
    /// free parameters with none chosen are errors.
    pub fn new<B>(basis: B, choice: &Choice, what: &str) -> Result<Plotted>
    where
        B: Basis + std::fmt::Debug + Send + Sync + 'static,
    {
        let id = basis.id();
        let params = basis.parameters();
        let mut fixed = Vec::new();
        for (name, _) in &choice.fixed {
            let k = index_of(&id, &params, name)?;
            if fixed.contains(&k) {
                return Err(PlotError::Input(format!(
                    "--param fixes {} twice",
                    params[k].name
                )));
            }
            fixed.push(k);
        }
        // stated in the parameters' order, whatever the order given
        fixed.sort_unstable();
        let free: Vec<usize> = (0..params.len()).filter(|k| !fixed.contains(k)).collect();
        let varied = match (&choice.vary, free.as_slice()) {
            (Some(name), _) => {
                let k = index_of(&id, &params, name)?;
                if fixed.contains(&k) {
                    return Err(PlotError::Input(format!(
                        "{} is both fixed (--param) and varied (--vary)",
                        params[k].name
                    )));
                }
                Some(k)
            }
            (None, []) => None,
            (None, [k]) => Some(*k),
            (None, _) => {
                return Err(PlotError::Vary {
                    id,
                    what: what.into(),
                    free: free.iter().map(|&k| params[k].name.clone()).collect(),
                });
            }
        };
        // every parameter other than the varied one must be fixed
        if let Some(&k) = free.iter().find(|&&k| Some(k) != varied) {
            return Err(PlotError::Input(format!(
                "{} is neither fixed nor varied: give --param {}=VALUE",
                params[k].name, params[k].name
            )));
        }
        let values = match varied {
            None if !choice.values.is_empty() => {
                return Err(PlotError::Input(format!(
                    "`{id}` has no parameter left to vary: --values draws nothing"
                )));
            }
            None => Vec::new(),
            Some(k) if choice.values.is_empty() => spread(&params[k])?,
            Some(_) => choice.values.clone(),
        };
        let pairs = |value: Option<&Affine>| {
            let mut pairs = choice.fixed.clone();
            if let (Some(k), Some(v)) = (varied, value) {
                pairs.push((params[k].name.clone(), v.text(&[])));
            }
            basis.params_from_pairs(&pairs, choice.allow_outside)
        };
        let settings = match varied {
            None => vec![pairs(None)?],
            Some(_) => values
                .iter()
                .map(|v| pairs(Some(v)))
                .collect::<std::result::Result<_, _>>()?,
        };
        let first: &Vec<Affine> = settings.first().ok_or_else(|| {
            PlotError::Input(format!("give at least one value of {}", params[0].name))
        })?;
        let fixed = fixed
            .iter()
            .map(|&k| (params[k].symbol.clone(), first[k].clone()))
            .collect();
        let title = basis.title();
        Ok(Plotted {
            id: id.clone(),
            name: if title.trim().is_empty() { id } else { title },
            citation: basis.citation(),
            functions: basis.function_names(),
            varied: varied.map(|k| (k, params[k].symbol.clone())),
            fixed,
            variable: variable_label(&basis),
            settings,
            basis: Arc::new(basis),
        })
    }

    /// A heading `title` of a plot of this basis with the fixed
    /// parameters (`… at ⟪μ = 1/2⟫`).
    pub fn heading(&self, title: &str) -> String {
        let mut out = title.to_string();
        if !self.fixed.is_empty() {
            let fixed: Vec<String> = self
                .fixed
                .iter()
                .map(|(s, v)| formula(&format!("{s} = {}", value_text(v))))
                .collect();
            out = format!("{out} at {}", fixed.join(", "));
        }
        out
    }

    /// The legend text of settings drawn together (`⟪λ = −1, 0⟫`: marked,
    /// a real minus sign), or the function names for a plot without a
    /// varied parameter.
    pub fn label(&self, same: &[Vec<Affine>]) -> String {
        match &self.varied {
            Some((k, p)) => {
                let vals: Vec<String> = same.iter().map(|s| value_text(&s[*k])).collect();
                formula(&format!("{p} = {}", vals.join(", ")))
            }
            None => formula(&self.functions.join(", ")),
        }
    }

    /// The basis over its domain `[a, b]` for one setting: `samples` points
    /// `xᵢ` and the values, function-major (`b_k(xᵢ)` at `k·samples + i`).
    /// A catalog family goes through [`Batch`] (with its checks); any other
    /// basis point by point, a non-finite value being an error.
    pub fn sample(&self, setting: &[Affine], samples: usize) -> Result<(Vec<f64>, Vec<f64>)> {
        let params: Vec<f64> = setting.iter().map(Affine::to_f64).collect();
        let domain = self.basis.basis_domain();
        let (a, b) = (
            domain.start_value(&0.0, &params),
            domain.end_value(&0.0, &params),
        );
        if !(a.is_finite() && b.is_finite() && a < b) {
            return Err(PlotError::Input(format!(
                "`{}`: the domain {domain} is [{a}, {b}] at these parameters",
                self.id
            )));
        }
        let xs: Vec<f64> = (0..samples)
            .map(|i| a + (b - a) * i as f64 / (samples - 1) as f64)
            .collect();
        // a catalog family at rational parameters through its batch; at a
        // multiple of π point by point like any other basis
        let rational: Option<Vec<Rational>> =
            setting.iter().map(|a| a.as_rational().cloned()).collect();
        if let (Some(family), Some(rational)) = (self.basis.as_family(), rational) {
            let values = Batch::new(family, &rational, &0.0, true)?.eval(&xs)?;
            return Ok((xs, values));
        }
        let n = self.functions.len();
        let mut values = vec![0.0; n * samples];
        for (i, &x) in xs.iter().enumerate() {
            let v = self.basis.values(&domain, x, &params);
            if let Some(bad) = v.iter().position(|y| !y.is_finite()) {
                return Err(PlotError::Input(format!(
                    "`{}`: {} is not finite at {x}",
                    self.id, self.functions[bad]
                )));
            }
            for (k, y) in v.into_iter().enumerate() {
                values[k * samples + i] = y;
            }
        }
        Ok((xs, values))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::{Family, parse_point};

    fn choice(fixed: &[(&str, &str)], vary: Option<&str>, values: &[&str]) -> Choice {
        Choice {
            fixed: fixed
                .iter()
                .map(|(n, v)| (n.to_string(), v.to_string()))
                .collect(),
            vary: vary.map(String::from),
            values: values.iter().map(|v| parse_point(v).unwrap()).collect(),
            allow_outside: false,
        }
    }

    fn q(text: &str) -> Affine {
        parse_point(text).unwrap()
    }

    #[test]
    fn every_parameter_but_one_fixed_draws_the_other_s_family() {
        // EH (seed 004): λ, μ ∈ [−1, 1]
        let plot = Plotted::new(Family::Eh, &choice(&[("mu", "1/2")], None, &[]), "basis").unwrap();
        assert_eq!(plot.varied, Some((0, "λ".to_string())));
        assert_eq!(plot.fixed, [("μ".to_string(), q("1/2"))]);
        // five values spread over [−1, 1], μ = 1/2 in each
        assert_eq!(plot.settings.len(), 5);
        assert_eq!(plot.settings[0], [q("-1"), q("1/2")]);
        assert_eq!(plot.settings[4], [q("1"), q("1/2")]);
        assert_eq!(plot.label(&plot.settings[1..2]), "⟪λ = −1/2⟫");
        assert_eq!(
            plot.heading(&plot.name),
            "EH interpolation-spline bases b_{i,3}(t; lambda, mu) at ⟪μ = 1/2⟫"
        );
        // the symbol names a parameter as well as its name; --vary chooses
        let plot = Plotted::new(
            Family::Eh,
            &choice(&[("λ", "0")], Some("μ"), &["-1", "1"]),
            "curve",
        )
        .unwrap();
        assert_eq!(plot.varied, Some((1, "μ".to_string())));
        assert_eq!(plot.settings, [[q("0"), q("-1")], [q("0"), q("1")]]);
        // every parameter fixed: one setting, nothing varied
        let plot = Plotted::new(
            Family::Eh,
            &choice(&[("lambda", "0"), ("mu", "1")], None, &[]),
            "basis",
        )
        .unwrap();
        assert_eq!((&plot.varied, plot.settings.len()), (&None, 1));
        assert_eq!(plot.label(&plot.settings), "⟪b0, b1, b2, b3⟫");
    }

    #[test]
    fn a_missing_choice_unknown_names_and_values_outside_are_errors() {
        let err = |c: Choice| Plotted::new(Family::Eh, &c, "basis").unwrap_err();
        let free = err(choice(&[], None, &[]));
        assert!(
            matches!(&free, PlotError::Vary { free, .. } if free == &["lambda", "mu"]),
            "{free:?}"
        );
        let text = free.to_string();
        assert!(
            text.contains("lambda, mu") && text.contains("--param") && text.contains("--vary"),
            "{text}"
        );
        assert!(matches!(
            err(choice(&[("nu", "0")], None, &[])),
            PlotError::Core(CoreError::UnknownParameter { .. })
        ));
        assert!(matches!(
            err(choice(&[], Some("nu"), &[])),
            PlotError::Core(CoreError::UnknownParameter { .. })
        ));
        assert!(matches!(
            err(choice(&[("mu", "2")], None, &[])),
            PlotError::Core(CoreError::OutOfRange { .. })
        ));
        assert!(matches!(
            err(choice(&[("mu", "0")], None, &["2"])),
            PlotError::Core(CoreError::OutOfRange { .. })
        ));
        for bad in [
            choice(&[("mu", "0")], Some("mu"), &[]),
            choice(&[("mu", "0"), ("μ", "1")], None, &[]),
            choice(&[("mu", "0"), ("lambda", "0")], None, &["1"]),
        ] {
            assert!(matches!(err(bad), PlotError::Input(_)));
        }
        // allowed outside the range when asked
        let outside = Choice {
            allow_outside: true,
            ..choice(&[("mu", "2")], None, &["0"])
        };
        assert!(Plotted::new(Family::Eh, &outside, "basis").is_ok());
    }
}
