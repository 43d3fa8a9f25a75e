//! What a basis or curve plot draws: any basis — a catalog family or a
//! spec file's — with its names and the parameter settings to draw, each
//! setting validated by whoever built it.

use std::sync::Arc;

use rug::Rational;
use trig_core::{Affine, Batch, Described, Family, Variable};
use trig_fit::NumericBasis;

use crate::error::{PlotError, Result};
use crate::style::settings;

/// A basis to draw for one or more parameter settings.
#[derive(Debug, Clone)]
pub struct Plotted {
    pub basis: Arc<dyn NumericBasis>,
    pub id: String,
    pub citation: String,
    pub functions: Vec<String>,
    /// The printed symbol of the parameter the settings vary (none for a
    /// basis without parameters).
    pub symbol: Option<String>,
    /// The axis label of the basis's variable.
    pub variable: String,
    /// The parameter values of each setting (exact, already checked).
    pub settings: Vec<Vec<Affine>>,
}

impl Plotted {
    /// A catalog family for the values `values` of its one parameter
    /// (none for a family without parameters), checked against the
    /// published range unless `allow_outside`; `what` names the plot in
    /// errors.
    pub fn family(
        family: Family,
        values: &[Affine],
        allow_outside: bool,
        what: &str,
    ) -> Result<Plotted> {
        let info = family.info();
        let settings = settings(&info, values, what)?;
        for s in &settings {
            let pairs: Vec<(String, String)> = info
                .params
                .iter()
                .zip(s)
                .map(|(p, v)| (p.name.to_string(), v.text(&[])))
                .collect();
            family.params_from_pairs(&pairs, allow_outside)?;
        }
        Ok(Plotted {
            basis: Arc::new(family),
            id: info.id.to_string(),
            citation: info.citation.to_string(),
            functions: info.functions.iter().map(ToString::to_string).collect(),
            symbol: info.params.first().map(|p| p.symbol.to_string()),
            variable: match info.variable {
                Variable::UnitAngle => "u (angle θ = πu/2)",
                Variable::Angle => "t (angle, radians)",
                Variable::Polynomial => "t",
            }
            .into(),
            settings,
        })
    }

    /// The legend text of settings drawn together (`λ = −1, 0`: a real
    /// minus sign), or the
    /// function names for a basis without parameters.
    pub fn label(&self, same: &[Vec<Affine>]) -> String {
        match &self.symbol {
            Some(p) if !same[0].is_empty() => {
                let vals: Vec<String> = same
                    .iter()
                    .map(|s| s[0].text(&[]).replace("pi", "π").replace('-', "−"))
                    .collect();
                format!("{p} = {}", vals.join(", "))
            }
            _ => self.functions.join(", "),
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
