//! The fields every kind of claim reads alike: a required field, a
//! function by name, a formula inside a printed item, the convention of a
//! derivative (`wrt`), a derivative order, an end, a file beside the claim's
//! file, a figure. Shared by the readers of the checks (`claims.rs`,
//! `property_read.rs`, `join_read.rs`, `derivative_read.rs`, `listing.rs`).

use std::path::Path;
use toml::Spanned;
use trig_core::input::{MAX_TEXT_BYTES, Source as Input, read_text};
use trig_deriv::{End, Wrt};
use trig_symbolic::Sym;

use crate::check::ClaimFigure;
use crate::error::{Result, SpecError};
use crate::raw::RawClaim;
use crate::source::Source;
use crate::spec::{MAX_ORDER, Spec};

pub(crate) fn need<'r, T>(
    src: &Source<'_>,
    c: &'r RawClaim,
    field: &'r Option<T>,
    name: &str,
) -> Result<&'r T> {
    field.as_ref().ok_or_else(|| SpecError::Invalid {
        at: src.at(c.check.span().start),
        field: format!("claims.{name}"),
        message: format!(
            "check `{}` of claim `{}` needs the field `{name}`",
            c.check.get_ref(),
            c.id.get_ref()
        ),
    })
}

pub(crate) fn function_index(
    src: &Source<'_>,
    spec: &Spec,
    name: &Spanned<String>,
    text: &str,
) -> Result<usize> {
    spec.functions
        .iter()
        .position(|f| f.name == text.trim())
        .ok_or_else(|| SpecError::Invalid {
            at: src.at(name.span().start),
            field: "claims".into(),
            message: format!(
                "`{}`: unknown function (expected one of {})",
                text.trim(),
                spec.functions
                    .iter()
                    .map(|f| f.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        })
}

/// A formula after `prefix` in the string `item` (`NAME = formula`):
/// errors point into the item.
pub(crate) fn formula_in(
    src: &Source<'_>,
    spec: &Spec,
    item: &Spanned<String>,
    prefix: &str,
    text: &str,
    extra: &[String],
) -> Result<Sym> {
    spec.parse_formula(text, extra).map_err(|mut e| {
        e.position += prefix.chars().count();
        src.formula_error(item, e)
    })
}

/// `wrt`: `angle` (the declared angle of the legacy variables, the angle
/// of the atoms otherwise), `u` (the unit parameter, `θ = πu/2` for the
/// thesis), or the variable's own name.
pub(crate) fn wrt_field(
    src: &Source<'_>,
    spec: &Spec,
    wrt: Option<&Spanned<String>>,
) -> Result<Wrt> {
    let text = wrt.map_or("angle", |w| w.get_ref().trim());
    let span = wrt.map_or(0..0, |w| w.span());
    let angle_is_variable = spec
        .legacy
        .is_some_and(|v| v != trig_core::Variable::UnitAngle);
    let refined = spec.shorthand.is_some_and(|k| k != 1);
    let angle = if refined && angle_is_variable {
        // the declared angle is t itself; the atoms' angle is a fraction of it
        Wrt::Variable
    } else {
        Wrt::Angle
    };
    let refuse = |other: &str| {
        src.invalid(
            span.clone(),
            "claims.wrt",
            format!(
                "`{other}`: expected `angle`, `u` (the unit parameter) or the basis variable `{}`",
                spec.var_name
            ),
        )
    };
    match text {
        _ if wrt.is_none() && spec.legacy.is_none() => Ok(Wrt::Variable),
        "angle" | "theta" | "θ" if refined && !angle_is_variable => src.invalid(
            span,
            "claims.wrt",
            "derivatives in the declared angle πu/2 are not available when the formulas use other multiples of it: use wrt = \"u\"".into(),
        ),
        "angle" | "theta" | "θ" if spec.domain.is_trigonometric() || spec.legacy.is_some() => {
            Ok(angle)
        }
        "u" if spec.legacy == Some(trig_core::Variable::UnitAngle) => Ok(Wrt::U),
        t if t == spec.var_name && angle_is_variable => Ok(angle),
        t if t == spec.var_name => Ok(Wrt::Variable),
        "u" if spec.legacy.is_none() => Ok(Wrt::U),
        other => refuse(other),
    }
}

/// `order = k`: a derivative order from 0 to [`MAX_ORDER`].
pub(crate) fn order_field(src: &Source<'_>, c: &RawClaim, order: &Spanned<i64>) -> Result<usize> {
    usize::try_from(*order.get_ref())
        .ok()
        .filter(|k| *k <= MAX_ORDER)
        .ok_or_else(|| SpecError::Invalid {
            at: src.at(order.span().start),
            field: "claims.order".into(),
            message: format!(
                "{}: expected an order from 0 to {MAX_ORDER} (claim `{}`)",
                order.get_ref(),
                c.id.get_ref()
            ),
        })
}

/// `end = "start"` or `"end"` (also `0`, `1`).
pub(crate) fn end_field(src: &Source<'_>, end: &Spanned<String>) -> Result<End> {
    match end.get_ref().trim() {
        "start" | "0" => Ok(End::Start),
        "end" | "1" => Ok(End::End),
        other => src.invalid(
            end.span(),
            "claims.end",
            format!("`{other}`: expected `start` or `end`"),
        ),
    }
}

/// The table file `data = "…"` names (relative to the claim's file), as
/// written and as read: a file that cannot be read is an error of the file.
pub(crate) fn data_file(src: &Source<'_>, c: &RawClaim) -> Result<(String, String)> {
    file_field(src, need(src, c, &c.data, "data")?, "data")
}

/// The file a field names (relative to the claim's file), as written and
/// as read: a file that cannot be read is an error of the file.
pub(crate) fn file_field(
    src: &Source<'_>,
    path: &Spanned<String>,
    field: &str,
) -> Result<(String, String)> {
    let dir = Path::new(src.file).parent().unwrap_or(Path::new(""));
    let file = dir.join(path.get_ref().trim());
    match read_text(&Input::of(&file), MAX_TEXT_BYTES) {
        Ok(text) => Ok((path.get_ref().trim().to_string(), text)),
        Err(e) => src.invalid(
            path.span(),
            &format!("claims.{field}"),
            format!("{}: {}", file.display(), e.reason()),
        ),
    }
}

/// `[claims.figure]`, when given. The file need not exist (a copied
/// document folder links its figures where they were, and `trig-audit
/// plot` draws a figure with the arguments the report states).
pub(crate) fn figure_field(src: &Source<'_>, c: &RawClaim) -> Result<Option<ClaimFigure>> {
    let Some(f) = &c.figure else {
        return Ok(None);
    };
    let dir = Path::new(src.file).parent().unwrap_or(Path::new(""));
    let path = dir.join(f.file.get_ref().trim());
    if f.plot.contains("--output") {
        return src.invalid(
            f.file.span(),
            "claims.figure.plot",
            "`plot` gives the arguments without `--output` (the figure's `file`)".into(),
        );
    }
    Ok(Some(ClaimFigure {
        path,
        caption: f.caption.trim().to_string(),
        plot: f.plot.trim().to_string(),
    }))
}
