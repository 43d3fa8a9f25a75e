//! `plot surface`: tensor-product patches drawn — an SVG with shaded,
//! depth-sorted facets and the control nets, its pgfplots `surf` code
//! beside it (`NAME.tex`) — or exported as a mesh (`.obj`, `.ply`, `.stl`,
//! chosen by the extension of `--output`). The patches are the nets given
//! (`--net`, repeatable), or one net and the second patch a join forces
//! (`--join KIND` with `--param2`, `--alpha`, `--beta`; the thesis's
//! Figures 5.4–5.7).

use std::path::{Path, PathBuf};

use clap::Args;
use rug::Rational;
use trig_core::net::ControlNet;
use trig_core::surface::{Direction, TensorSurface};
use trig_core::{Described, input::Source, parse_exact};
use trig_deriv::JoinKind;
use trig_plot::{
    Mesh, MeshFormat, PATCH_COLOURS, SurfaceFigure, SurfacePatch, View, surface_pgf, surface_svg,
};
use trig_specfile::AnyBasis;

use super::revolution::{quarter_circle, revolution_nets};
use super::{FigureArgs, plot_err};
use crate::commands::join::cylinder::closing_net;
use crate::commands::join::surface::{Across, JoinValues, second_net};
use crate::commands::surface::VArgs;
use crate::commands::{CliError, CmdResult, range_hint};
use crate::output::{resolve, write_atomically, wrote};

/// Most samples per direction and patch (the cost model: 200 × 200 × 2
/// triangles per patch).
const MAX_SAMPLES: usize = 200;

#[derive(Debug, Args)]
pub struct SurfacePlotArgs {
    /// The u direction's basis: a family id (or --spec FILE).
    #[arg(long, required_unless_present = "spec")]
    family: Option<String>,
    /// The u direction's basis from a spec file (TOML, docs/spec.md).
    #[arg(long, value_name = "FILE", conflicts_with = "family")]
    spec: Option<PathBuf>,
    /// A shape parameter of the u direction as name=value, read exactly.
    #[arg(long = "param", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    params: Vec<String>,
    #[command(flatten)]
    v: VArgs,
    /// A control net (one point `x y z [w]` per line, net rows separated by
    /// blank lines); repeat for several patches.
    #[arg(long, value_name = "FILE", required = true)]
    net: Vec<PathBuf>,
    /// Draw a second patch that this join (c0, c1, c2, g1, g2) with the
    /// first forces (its free control points: the first net moved on by
    /// its extent across the boundary).
    #[arg(long, value_name = "KIND")]
    join: Option<String>,
    /// Sweep the profile (--net: one row of points `r 0 z` in the u basis)
    /// about the z axis by the exact quarter circle of the v basis (e.g.
    /// --v-spec examples/han-quadratic.toml --v-param lambda=0): four patches.
    #[arg(long, conflicts_with = "join")]
    revolution: bool,
    /// A uniform B-spline surface over a net of any size ≥ n × n, for a
    /// piecewise basis in both directions (bspline3, seed000-uniform, a spec
    /// with four segment functions): one patch per span, the n × n windows
    /// of the net.
    #[arg(long, conflicts_with_all = ["join", "revolution"])]
    bspline: bool,
    /// With --join: close the pair into a cylinder, the second patch joined
    /// to the first at both seams (thesis Figures 5.9–5.12; for c2, g2 of a
    /// cubic both patches are solved together, docs/surfaces.md).
    #[arg(long, requires = "join")]
    close: bool,
    /// With --join: the boundary (u: u = 1 of the first is u = 0 of the second).
    #[arg(long, value_enum, default_value = "u", requires = "join")]
    across: Across,
    /// With --join: a parameter of the second patch's joined direction
    /// (default: the first patch's).
    #[arg(
        long = "param2",
        value_name = "NAME=VALUE",
        requires = "join",
        allow_hyphen_values = true
    )]
    params2: Vec<String>,
    /// With --join g1 or g2: the factor α > 0 of Q'(0) = α P'(1).
    #[arg(
        long,
        default_value = "1",
        requires = "join",
        allow_hyphen_values = true
    )]
    alpha: String,
    /// With --join g2: the factor β of Q''(0) = α² P''(1) + β P'(1).
    #[arg(
        long,
        default_value = "0",
        requires = "join",
        allow_hyphen_values = true
    )]
    beta: String,
    /// Samples per direction and patch (2 to 200).
    #[arg(long, default_value_t = 25)]
    samples: usize,
    /// View azimuth in degrees, about z from the negative y axis (MATLAB's view).
    #[arg(long, default_value_t = -37.5, allow_hyphen_values = true)]
    azimuth: f64,
    /// View elevation in degrees above the xy plane.
    #[arg(long, default_value_t = 30.0, allow_hyphen_values = true)]
    elevation: f64,
    /// The title (default: the bases and parameter values).
    #[arg(long)]
    title: Option<String>,
    /// Allow parameters outside their published ranges (thesis Figure 5.3).
    #[arg(long)]
    allow_outside_range: bool,
    /// The file to write: NAME.svg (with its pgfplots code NAME.tex beside
    /// it), or a mesh NAME.obj, NAME.ply or NAME.stl.
    #[arg(long)]
    output: PathBuf,
    #[command(flatten)]
    look: FigureArgs,
}

/// The samples `S(u_i, v_j)` on an even grid of each direction's domain.
fn sampled(
    surface: &TensorSurface<AnyBasis>,
    samples: usize,
) -> Result<Vec<Vec<[f64; 3]>>, CliError> {
    let points = |dir: &Direction<AnyBasis>| {
        let p: Vec<f64> = dir.params.iter().map(|a| a.eval(&0.0, &[])).collect();
        let d = dir.basis.domain();
        let (a, b) = (d.start_value(&0.0, &p), d.end_value(&0.0, &p));
        (0..samples)
            .map(|k| a + (b - a) * k as f64 / (samples - 1) as f64)
            .collect::<Vec<f64>>()
    };
    let (us, vs) = (points(surface.u()), points(surface.v()));
    us.iter()
        .map(|u| {
            vs.iter()
                .map(|v| Ok(surface.eval(u, v, true)?))
                .collect::<Result<Vec<_>, CliError>>()
        })
        .collect()
}

/// The spans of the uniform B-spline surface over `net`: a patch over each
/// `n_u × n_v` window (the segment functions of a piecewise basis are the
/// blending functions of one span, `b_i` weighting the `i`-th point of the
/// window).
fn spans(
    u: &Direction<AnyBasis>,
    v: &Direction<AnyBasis>,
    net: &ControlNet,
) -> Result<Vec<TensorSurface<AnyBasis>>, CliError> {
    for d in [u, v] {
        if !d.basis.piecewise() {
            return Err(CliError::Usage(format!(
                "--bspline needs a basis of uniform B-spline segment functions in both directions (bspline3, seed000-uniform, a spec with four segment functions); `{}` is not one",
                d.basis.id()
            )));
        }
    }
    let (nu, nv) = (u.len(), v.len());
    if net.rows() < nu || net.columns() < nv {
        return Err(CliError::Usage(format!(
            "--bspline: the net is {} × {}, a span needs {nu} × {nv} points",
            net.rows(),
            net.columns()
        )));
    }
    let mut out = Vec::new();
    for row in 0..=net.rows() - nu {
        for column in 0..=net.columns() - nv {
            let window = net.window(row, column, nu, nv).expect("the window fits");
            out.push(TensorSurface::new(u.clone(), v.clone(), window)?);
        }
    }
    Ok(out)
}

/// The net in f64, for drawing.
fn net_f64(net: &ControlNet) -> Vec<Vec<[f64; 3]>> {
    net.points()
        .iter()
        .map(|row| row.iter().map(|p| p.clone().map(|q| q.to_f64())).collect())
        .collect()
}

/// The exact values of `pairs` for `basis`, in its parameter order.
fn exact_values(basis: &AnyBasis, raw: &[String], allow: bool) -> Result<Vec<Rational>, CliError> {
    let pairs = crate::commands::param_pairs(raw)?;
    basis
        .params_from_pairs(&pairs, allow)
        .map_err(range_hint)?
        .into_iter()
        .map(|a| {
            a.as_rational().cloned().ok_or_else(|| {
                CliError::Usage("a drawn join takes rational parameter values".into())
            })
        })
        .collect()
}

pub fn run(args: &SurfacePlotArgs) -> CmdResult {
    if !(2..=MAX_SAMPLES).contains(&args.samples) {
        return Err(CliError::Usage(format!(
            "--samples {}: expected 2 to {MAX_SAMPLES} samples per direction",
            args.samples
        )));
    }
    if !(args.azimuth.is_finite() && args.elevation.is_finite()) {
        return Err(CliError::Usage(
            "--azimuth and --elevation take finite degrees".into(),
        ));
    }
    let (output, mesh) = output_of(&args.output)?;
    let u = AnyBasis::open(args.family.as_deref(), args.spec.as_deref())?;
    let [du, dv] = args
        .v
        .directions(&u, &args.params, args.allow_outside_range)?;
    let mut surfaces = Vec::new();
    for path in &args.net {
        let net =
            ControlNet::read(&Source::of(path)).map_err(|e| CliError::Usage(e.to_string()))?;
        if args.revolution {
            let circle = quarter_circle(&dv)?;
            for quarter in revolution_nets(&net, &circle)? {
                surfaces.push(TensorSurface::new(du.clone(), dv.clone(), quarter)?);
            }
        } else if args.bspline {
            surfaces.extend(spans(&du, &dv, &net)?);
        } else {
            surfaces.push(TensorSurface::new(du.clone(), dv.clone(), net)?);
        }
    }
    if let Some(kind) = &args.join {
        if surfaces.len() != 1 {
            return Err(CliError::Usage(
                "--join draws one --net and the patch the join forces".into(),
            ));
        }
        let kind: JoinKind = kind
            .parse()
            .map_err(|e: trig_deriv::JoinError| CliError::Usage(e.to_string()))?;
        let joined = match args.across {
            Across::U => &du,
            Across::V => &dv,
        };
        let first = exact_values(
            &joined.basis,
            &args.params_for(args.across),
            args.allow_outside_range,
        )?;
        let second = if args.params2.is_empty() {
            first.clone()
        } else {
            exact_values(&joined.basis, &args.params2, args.allow_outside_range)?
        };
        let (alpha, beta) = (parse_exact(&args.alpha)?, parse_exact(&args.beta)?);
        if alpha <= 0 {
            return Err(CliError::Usage(
                "--alpha must be positive (a G join's α > 0)".into(),
            ));
        }
        let values = JoinValues {
            first,
            second: second.clone(),
            alpha,
            beta,
        };
        let bases = [&du.basis, &dv.basis];
        let net2 = if args.close {
            let [first, second] =
                closing_net(bases, kind, args.across, surfaces[0].net(), &values)?;
            surfaces[0] = TensorSurface::new(du.clone(), dv.clone(), first)?;
            second
        } else {
            second_net(bases, kind, args.across, surfaces[0].net(), &values)?
        };
        let mut d2 = joined.clone();
        d2.params = second
            .into_iter()
            .map(trig_core::Affine::rational)
            .collect();
        let (u2, v2) = match args.across {
            Across::U => (d2, dv.clone()),
            Across::V => (du.clone(), d2),
        };
        surfaces.push(TensorSurface::new(u2, v2, net2)?);
    }
    let patches = surfaces
        .iter()
        .zip(PATCH_COLOURS.iter().cycle())
        .map(|(s, rgb)| {
            Ok(SurfacePatch {
                grid: sampled(s, args.samples)?,
                net: net_f64(s.net()),
                rgb: *rgb,
            })
        })
        .collect::<Result<Vec<_>, CliError>>()?;
    let title = if args.look.no_title {
        String::new()
    } else {
        args.title
            .clone()
            .unwrap_or_else(|| default_title(args, &du, &dv))
    };
    let figure = SurfaceFigure {
        title,
        patches,
        view: View {
            azimuth: args.azimuth,
            elevation: args.elevation,
        },
    };
    write(&output, mesh, &figure, &args.look, "plot surface")
}

impl SurfacePlotArgs {
    /// The `name=value` pairs of the direction a join crosses.
    fn params_for(&self, across: Across) -> Vec<String> {
        match across {
            Across::U => self.params.clone(),
            Across::V if self.v.given() => self.v.v_params.clone(),
            Across::V => self.params.clone(),
        }
    }
}

/// `thesis-cubic surface, m = 1/2` (`u: …; v: …` when they differ).
fn default_title(
    args: &SurfacePlotArgs,
    u: &Direction<AnyBasis>,
    v: &Direction<AnyBasis>,
) -> String {
    let text = |d: &Direction<AnyBasis>| {
        let values: Vec<String> = d
            .basis
            .param_names()
            .iter()
            .zip(&d.params)
            .map(|(n, a)| format!("⟪{n}⟫ = {}", a.text(&[])))
            .collect();
        if values.is_empty() {
            d.basis.id()
        } else {
            format!("{}, {}", d.basis.id(), values.join(", "))
        }
    };
    let (a, b) = (text(u), text(v));
    let mut title = if a == b {
        format!("{a} surface")
    } else {
        format!("surface, u: {a}; v: {b}")
    };
    if args.revolution {
        title = format!("surface of revolution, profile {a}; circle {b}");
    }
    if let Some(kind) = &args.join {
        let closed = if args.close { " closed" } else { "" };
        title.push_str(&format!(",{closed} {} join", kind.to_uppercase()));
        if let Ok(pairs) = crate::commands::param_pairs(&args.params2)
            && !pairs.is_empty()
        {
            let shown: Vec<String> = pairs.iter().map(|(n, v)| format!("⟪{n}⟫ = {v}")).collect();
            title.push_str(&format!(" to {}", shown.join(", ")));
        }
        if kind.starts_with('g') {
            title.push_str(&format!(", ⟪alpha⟫ = {}", args.alpha));
        }
        if kind == "g2" {
            title.push_str(&format!(", ⟪beta⟫ = {}", args.beta));
        }
    }
    title
}

/// Where a surface goes and how: an SVG (`None`) or a mesh, by the
/// extension of `path`.
pub(crate) fn output_of(path: &Path) -> Result<(PathBuf, Option<MeshFormat>), CliError> {
    let output = resolve(path)?;
    let extension = output
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    let mesh = MeshFormat::of_extension(&extension);
    if mesh.is_none() && extension != "svg" {
        return Err(CliError::Usage(format!(
            "{}: give a name ending in .svg (a picture, its pgfplots code beside it) or .obj, .ply, .stl (a mesh)",
            output.display()
        )));
    }
    Ok((output, mesh))
}

/// Writes the SVG and its pgfplots code beside it, or the mesh (its header
/// naming `command`).
pub(crate) fn write(
    output: &Path,
    mesh: Option<MeshFormat>,
    figure: &SurfaceFigure,
    look: &FigureArgs,
    command: &str,
) -> CmdResult {
    if std::fs::metadata(output).is_ok_and(|m| !m.is_file()) {
        return Err(CliError::Usage(format!(
            "{}: not a regular file",
            output.display()
        )));
    }
    if let Some(format) = mesh {
        let mesh = Mesh::of(figure).map_err(plot_err)?;
        let text = mesh
            .write(
                format,
                &format!("trig-audit {command}: {}", trig_tex::plain(&figure.title)),
            )
            .map_err(plot_err)?;
        write_atomically(output, text.as_bytes())?;
        wrote(
            output,
            &format!(
                "{} vertices, {} triangles",
                mesh.vertices.len(),
                mesh.triangles.len()
            ),
        );
        return Ok(String::new());
    }
    let svg = surface_svg(figure).map_err(plot_err)?;
    let tex = surface_pgf(figure, &look.options()?).map_err(plot_err)?;
    let tex_path = output.with_extension("tex");
    write_atomically(output, svg.as_bytes())?;
    write_atomically(&tex_path, tex.as_bytes())?;
    wrote(output, &format!("{} bytes", svg.len()));
    wrote(&tex_path, "pgfplots");
    Ok(String::new())
}
