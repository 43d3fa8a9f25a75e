//! A figure of tensor-product surface patches: each patch sampled on a grid
//! of `(u, v)` points, with its control net, and the fixed view it is seen
//! from (azimuth and elevation in degrees, as MATLAB's `view(az, el)`, the
//! thesis's figures' tool: azimuth about the `z` axis from the negative `y`
//! axis, elevation above the `xy` plane). The SVG ([`crate::surface_svg`]),
//! the pgfplots code ([`crate::surface_pgf`]) and the meshes
//! ([`crate::mesh`]) are written from it.

use crate::error::{PlotError, Result};

/// The direction a surface is seen from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// Degrees about the `z` axis, from the negative `y` axis (MATLAB's
    /// default −37.5).
    pub azimuth: f64,
    /// Degrees above the `xy` plane (MATLAB's default 30).
    pub elevation: f64,
}

impl Default for View {
    fn default() -> Self {
        View {
            azimuth: -37.5,
            elevation: 30.0,
        }
    }
}

impl View {
    /// The unit vectors of the screen: right, up, and towards the viewer.
    pub fn axes(&self) -> [[f64; 3]; 3] {
        let (sa, ca) = self.azimuth.to_radians().sin_cos();
        let (se, ce) = self.elevation.to_radians().sin_cos();
        [
            [ca, sa, 0.0],
            [-se * sa, se * ca, ce],
            [ce * sa, -ce * ca, se],
        ]
    }

    /// `(x, y, depth)` of a point on the screen: `depth` grows towards the
    /// viewer.
    pub fn project(&self, p: &[f64; 3]) -> [f64; 3] {
        self.axes().map(|a| dot(&a, p))
    }
}

/// One patch: its samples `grid[i][j] = S(u_i, v_j)` and its control net.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfacePatch {
    pub grid: Vec<Vec<[f64; 3]>>,
    pub net: Vec<Vec<[f64; 3]>>,
    /// The fill colour of the patch.
    pub rgb: (u8, u8, u8),
}

/// Patches seen from one view, with a title (empty: none).
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceFigure {
    pub title: String,
    pub patches: Vec<SurfacePatch>,
    pub view: View,
}

/// The colours of successive patches (the thesis's orange and blue first).
pub const PATCH_COLOURS: [(u8, u8, u8); 4] = [
    (230, 140, 50),
    (70, 130, 200),
    (200, 90, 150),
    (90, 170, 110),
];

impl SurfaceFigure {
    /// Checks the figure: at least one patch, every grid at least 2 × 2
    /// and rectangular, every point finite.
    pub fn check(&self) -> Result<()> {
        if self.patches.is_empty() {
            return Err(PlotError::Input("a surface figure needs a patch".into()));
        }
        for (k, patch) in self.patches.iter().enumerate() {
            let rows = patch.grid.len();
            let columns = patch.grid.first().map_or(0, Vec::len);
            if rows < 2 || columns < 2 || patch.grid.iter().any(|r| r.len() != columns) {
                return Err(PlotError::Input(format!(
                    "patch {k}: the samples are not a grid of at least 2 × 2 points"
                )));
            }
            let points = patch.grid.iter().chain(&patch.net).flatten();
            if points.flatten().any(|x| !x.is_finite()) {
                return Err(PlotError::Input(format!(
                    "patch {k} has a point that is not finite (a weighted sum that vanishes?)"
                )));
            }
        }
        Ok(())
    }

    /// Every sample and control point.
    pub fn points(&self) -> impl Iterator<Item = &[f64; 3]> {
        self.patches
            .iter()
            .flat_map(|p| p.grid.iter().chain(&p.net).flatten())
    }
}

/// `a · b`.
pub fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `(b − a) × (c − a)`.
pub fn normal(a: &[f64; 3], b: &[f64; 3], c: &[f64; 3]) -> [f64; 3] {
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_view_looks_from_the_negative_x_and_y_quadrant() {
        let v = View::default();
        let [right, up, towards] = v.axes();
        // an orthonormal frame
        for (a, b) in [(&right, &up), (&up, &towards), (&right, &towards)] {
            assert!(dot(a, b).abs() < 1e-15);
        }
        assert!(towards[0] < 0.0 && towards[1] < 0.0 && towards[2] > 0.0);
        // seen from straight above, x is right and y is up
        let top = View {
            azimuth: 0.0,
            elevation: 90.0,
        };
        let p = top.project(&[1.0, 2.0, 3.0]);
        assert!((p[0] - 1.0).abs() < 1e-15 && (p[1] - 2.0).abs() < 1e-15);
        assert!((p[2] - 3.0).abs() < 1e-15);
    }

    #[test]
    fn figures_with_bad_points_are_refused() {
        let patch = |x: f64| SurfacePatch {
            grid: vec![
                vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]],
                vec![[0.0, 1.0, 0.0], [1.0, 1.0, x]],
            ],
            net: vec![],
            rgb: PATCH_COLOURS[0],
        };
        let figure = |x| SurfaceFigure {
            title: String::new(),
            patches: vec![patch(x)],
            view: View::default(),
        };
        assert!(figure(0.5).check().is_ok());
        assert!(matches!(figure(f64::NAN).check(), Err(PlotError::Input(_))));
        let empty = SurfaceFigure {
            patches: vec![],
            ..figure(0.0)
        };
        assert!(empty.check().is_err());
    }
}
