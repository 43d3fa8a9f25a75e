//! The triangle mesh of a [`SurfaceFigure`] and its files: every sample a
//! vertex (patch by patch, row by row), every grid cell two triangles
//! `(i,j) (i+1,j) (i+1,j+1)` and `(i,j) (i+1,j+1) (i,j+1)` (counter-clockwise
//! seen from the side of `∂S/∂u × ∂S/∂v`), written as Wavefront OBJ, ASCII
//! PLY or ASCII STL — the formats MeshLab, ParaView and Blender open.
//! Coordinates are written as the shortest decimals that read back as the
//! same f64.

use std::fmt::Write;

use crate::error::{PlotError, Result};
use crate::surface::{SurfaceFigure, normal};

/// A mesh file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeshFormat {
    Obj,
    Ply,
    Stl,
}

impl MeshFormat {
    /// The format a file name's extension names (`.obj`, `.ply`, `.stl`).
    pub fn of_extension(extension: &str) -> Option<MeshFormat> {
        match extension.to_ascii_lowercase().as_str() {
            "obj" => Some(MeshFormat::Obj),
            "ply" => Some(MeshFormat::Ply),
            "stl" => Some(MeshFormat::Stl),
            _ => None,
        }
    }
}

/// Vertices and triangles (indices into the vertices, from 0).
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    pub vertices: Vec<[f64; 3]>,
    pub triangles: Vec<[usize; 3]>,
}

impl Mesh {
    /// The mesh of every patch of `figure`.
    pub fn of(figure: &SurfaceFigure) -> Result<Mesh> {
        figure.check()?;
        let mut mesh = Mesh {
            vertices: Vec::new(),
            triangles: Vec::new(),
        };
        for patch in &figure.patches {
            let base = mesh.vertices.len();
            let columns = patch.grid[0].len();
            mesh.vertices.extend(patch.grid.iter().flatten());
            let at = |i: usize, j: usize| base + i * columns + j;
            for i in 0..patch.grid.len() - 1 {
                for j in 0..columns - 1 {
                    mesh.triangles
                        .push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                    mesh.triangles
                        .push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
                }
            }
        }
        Ok(mesh)
    }

    /// The file text in `format`; `name` goes into the header.
    pub fn write(&self, format: MeshFormat, name: &str) -> Result<String> {
        if name.contains(['\n', '\r']) {
            return Err(PlotError::Input("a mesh name on one line".into()));
        }
        let mut out = String::new();
        let v = |p: &[f64; 3]| format!("{} {} {}", p[0], p[1], p[2]);
        match format {
            MeshFormat::Obj => {
                let _ = writeln!(out, "# {name}");
                for p in &self.vertices {
                    let _ = writeln!(out, "v {}", v(p));
                }
                for t in &self.triangles {
                    let _ = writeln!(out, "f {} {} {}", t[0] + 1, t[1] + 1, t[2] + 1);
                }
            }
            MeshFormat::Ply => {
                let _ = write!(
                    out,
                    "ply\nformat ascii 1.0\ncomment {name}\nelement vertex {}\nproperty double x\nproperty double y\nproperty double z\nelement face {}\nproperty list uchar int vertex_indices\nend_header\n",
                    self.vertices.len(),
                    self.triangles.len()
                );
                for p in &self.vertices {
                    let _ = writeln!(out, "{}", v(p));
                }
                for t in &self.triangles {
                    let _ = writeln!(out, "3 {} {} {}", t[0], t[1], t[2]);
                }
            }
            MeshFormat::Stl => {
                let solid = name.split_whitespace().next().unwrap_or("surface");
                let _ = writeln!(out, "solid {solid}");
                for t in &self.triangles {
                    let [a, b, c] = t.map(|i| &self.vertices[i]);
                    let n = normal(a, b, c);
                    let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
                    let n = if length > 0.0 {
                        n.map(|x| x / length)
                    } else {
                        [0.0; 3]
                    };
                    let _ = writeln!(out, "facet normal {}\n outer loop", v(&n));
                    for p in [a, b, c] {
                        let _ = writeln!(out, "  vertex {}", v(p));
                    }
                    let _ = writeln!(out, " endloop\nendfacet");
                }
                let _ = writeln!(out, "endsolid {solid}");
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::{PATCH_COLOURS, SurfacePatch, View};

    fn figure() -> SurfaceFigure {
        let grid = (0..3)
            .map(|i| (0..2).map(|j| [f64::from(i), f64::from(j), 0.1]).collect())
            .collect();
        SurfaceFigure {
            title: String::new(),
            patches: vec![SurfacePatch {
                grid,
                net: vec![],
                rgb: PATCH_COLOURS[0],
            }],
            view: View::default(),
        }
    }

    #[test]
    fn a_grid_becomes_two_triangles_per_cell_in_every_format() {
        let mesh = Mesh::of(&figure()).unwrap();
        assert_eq!(mesh.vertices.len(), 6);
        assert_eq!(
            mesh.triangles,
            vec![[0, 2, 3], [0, 3, 1], [2, 4, 5], [2, 5, 3]]
        );
        let obj = mesh.write(MeshFormat::Obj, "t").unwrap();
        assert!(obj.contains("v 2 1 0.1\nf 1 3 4\n"), "{obj}");
        let ply = mesh.write(MeshFormat::Ply, "t").unwrap();
        assert!(ply.contains("element vertex 6\n") && ply.contains("element face 4\n"));
        assert!(ply.ends_with("3 2 5 3\n"), "{ply}");
        let stl = mesh.write(MeshFormat::Stl, "t x").unwrap();
        assert_eq!(stl.matches("facet normal").count(), 4);
        // ∂S/∂u × ∂S/∂v = +z for this grid
        assert!(stl.contains("facet normal 0 0 1\n"), "{stl}");
        assert!(stl.starts_with("solid t\n") && stl.ends_with("endsolid t\n"));
        assert_eq!(MeshFormat::of_extension("PLY"), Some(MeshFormat::Ply));
        assert_eq!(MeshFormat::of_extension("svg"), None);
    }
}
