//! What the surface modes of `eval`, `table`, `join` and `plot` share: the
//! two directions of a tensor-product surface (thesis (5.11),
//! `S(u, v; m₁, m₂)`: the `u` basis is the command's family or `--spec`
//! with `--param`; the `v` basis is the same unless `--v-family` or
//! `--v-spec` names another, with `--v-param`, default the `u` values when
//! the bases are the same) and the control net read from `--net`.

use std::path::{Path, PathBuf};

use clap::Args;
use trig_core::net::ControlNet;
use trig_core::surface::{Direction, TensorSurface};
use trig_core::{Affine, Described, echo, input::Source, parse_point};
use trig_specfile::AnyBasis;

use super::param_pairs;
use super::{CliError, range_hint};

/// The options of a tensor-product surface in `eval`, `table`, `join`.
#[derive(Debug, Clone, Args)]
pub struct SurfaceArgs {
    /// Work on the tensor-product surface S(u, v) = Σ Σ P_ij B_i(u) B_j(v)
    /// (rational with weights) instead of the basis (docs/surfaces.md).
    #[arg(long)]
    pub surface: bool,
    #[command(flatten)]
    pub v: VArgs,
}

impl SurfaceArgs {
    /// The `v` options go with `--surface`.
    pub fn check(&self) -> Result<(), CliError> {
        if !self.surface && self.v.given() {
            return Err(CliError::Usage(
                "--v-family, --v-spec and --v-param describe a surface: they go with --surface"
                    .into(),
            ));
        }
        Ok(())
    }
}

/// The `v` direction of a surface.
#[derive(Debug, Clone, Args)]
pub struct VArgs {
    /// The v direction's basis: a catalog family id (default: the u basis).
    #[arg(long, value_name = "ID", conflicts_with = "v_spec")]
    pub v_family: Option<String>,
    /// The v direction's basis from a spec file (default: the u basis).
    #[arg(long, value_name = "FILE")]
    pub v_spec: Option<PathBuf>,
    /// A shape parameter of the v direction as name=value (default: the
    /// --param values when both directions have the same basis).
    #[arg(
        long = "v-param",
        value_name = "NAME=VALUE",
        allow_hyphen_values = true
    )]
    pub v_params: Vec<String>,
}

impl VArgs {
    /// True when any `v` option is given.
    pub fn given(&self) -> bool {
        self.v_family.is_some() || self.v_spec.is_some() || !self.v_params.is_empty()
    }

    /// The `v` basis: the one named, else the `u` basis.
    pub fn v_basis(&self, u: &AnyBasis) -> Result<AnyBasis, CliError> {
        if self.v_family.is_none() && self.v_spec.is_none() {
            return Ok(u.clone());
        }
        Ok(AnyBasis::open(
            self.v_family.as_deref(),
            self.v_spec.as_deref(),
        )?)
    }

    /// The `v` parameters as `name=value` pairs: `--v-param`, else the `u`
    /// pairs when the `v` basis is the `u` basis.
    pub fn v_pairs(&self, u_pairs: &[(String, String)]) -> Result<Vec<(String, String)>, CliError> {
        if self.v_params.is_empty() && self.v_family.is_none() && self.v_spec.is_none() {
            return Ok(u_pairs.to_vec());
        }
        param_pairs(&self.v_params)
    }

    /// Both directions with their exact parameters, read and checked
    /// against the published ranges unless `allow_outside`.
    pub fn directions(
        &self,
        u: &AnyBasis,
        u_params: &[String],
        allow_outside: bool,
    ) -> Result<[Direction<AnyBasis>; 2], CliError> {
        let u_pairs = param_pairs(u_params)?;
        let v = self.v_basis(u)?;
        let v_pairs = self.v_pairs(&u_pairs)?;
        let read = |basis: AnyBasis, pairs: &[(String, String)]| {
            let params = basis
                .params_from_pairs(pairs, allow_outside)
                .map_err(range_hint)?;
            Ok::<_, CliError>(Direction { basis, params })
        };
        let v = read(v, &v_pairs).map_err(|e| match e {
            CliError::Core(_) | CliError::Usage(_) => {
                CliError::Usage(format!("the v direction (--v-param): {e}"))
            }
            e => e,
        })?;
        Ok([read(u.clone(), &u_pairs)?, v])
    }

    /// The `v` parameters as typed (`name=value`), for headers.
    pub fn v_text(&self, u_params: &[String]) -> String {
        let pairs = param_pairs(u_params)
            .and_then(|p| self.v_pairs(&p))
            .unwrap_or_default();
        pairs
            .iter()
            .map(|(n, v)| format!("{n}={v}"))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// The surface over the net in `net` (`-`: standard input).
pub fn open(
    directions: [Direction<AnyBasis>; 2],
    net: &Path,
) -> Result<TensorSurface<AnyBasis>, CliError> {
    let net = ControlNet::read(&Source::of(net)).map_err(|e| CliError::Usage(e.to_string()))?;
    let [u, v] = directions;
    Ok(TensorSurface::new(u, v, net)?)
}

/// A point `u,v` of the surface, each read exactly like `--at`.
pub fn parse_uv(text: &str) -> Result<[(Affine, String); 2], CliError> {
    let Some((u, v)) = text.split_once(',') else {
        return Err(CliError::Usage(format!(
            "--at `{}`: a surface point is `u,v` (two numbers separated by a comma)",
            echo(text)
        )));
    };
    let read = |t: &str| Ok::<_, CliError>((parse_point(t)?, t.trim().to_string()));
    Ok([read(u)?, read(v)?])
}

/// The surface's name in headers: `u-id × v-id surface`.
pub fn name(surface: &TensorSurface<AnyBasis>) -> String {
    format!(
        "{} × {} surface",
        surface.u().basis.id(),
        surface.v().basis.id()
    )
}
