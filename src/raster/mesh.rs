//! Triangle meshes: the LearnOpenGL cube, UV sphere, icosphere, subdivided plane and torus.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `positions` | object-space vertex positions |
//! | `normals` | object-space unit vertex normals (must go through the normal matrix) |
//! | `uvs` | texture coordinates, (0, 0) at the first texel's corner |
//! | `triangles` | vertex indices; front faces are counter-clockwise seen from outside |
//!
//! Sources: LearnOpenGL, Lighting maps (`vertices[]`, 36 vertices);
//! `../shared/tools/llvmpipe_bench.py` (`learnopengl_cube`, `uv_sphere`).

use glam::{Vec2, Vec3};

use crate::normals::{vertex_normals, IndexOutOfRange, VertexWeighting};

/// An indexed triangle mesh with per-vertex normals and texture coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct Mesh {
    /// Object-space positions.
    pub positions: Vec<Vec3>,
    /// Object-space vertex normals, one per position.
    pub normals: Vec<Vec3>,
    /// Texture coordinates, one per position.
    pub uvs: Vec<Vec2>,
    /// Index triples.
    pub triangles: Vec<[u32; 3]>,
}

/// A mesh whose arrays disagree, naming the field (`normals`, `uvs` or `triangles`).
pub type MeshError = crate::error::FieldError;

/// The two triangles of every quad of a grid of `(rows + 1) × (cols + 1)` vertices
/// stored row by row, quads in row order:
///
/// ```text
/// quad (i, j): a = i (cols + 1) + j, b = a + cols + 1 -> [a, a+1, b], [a+1, b+1, b]
/// ```
///
/// (the vertex order of `llvmpipe_bench.py`'s `uv_sphere`). Zero rows or columns give
/// no triangles.
fn grid_triangles(rows: u32, cols: u32) -> impl Iterator<Item = [u32; 3]> {
    (0..rows).flat_map(move |i| {
        (0..cols).flat_map(move |j| {
            let a = i * (cols + 1) + j;
            let b = a + cols + 1;
            [[a, a + 1, b], [a + 1, b + 1, b]]
        })
    })
}

/// The LearnOpenGL cube, one face per row: (normal axis, sign, vertices as
/// (position, uv)). Values transcribed from the chapter's `vertices[]`.
const LEARNOPENGL_CUBE: [[f32; 8]; 36] = [
    [-0.5, -0.5, -0.5, 0.0, 0.0, -1.0, 0.0, 0.0],
    [0.5, -0.5, -0.5, 0.0, 0.0, -1.0, 1.0, 0.0],
    [0.5, 0.5, -0.5, 0.0, 0.0, -1.0, 1.0, 1.0],
    [0.5, 0.5, -0.5, 0.0, 0.0, -1.0, 1.0, 1.0],
    [-0.5, 0.5, -0.5, 0.0, 0.0, -1.0, 0.0, 1.0],
    [-0.5, -0.5, -0.5, 0.0, 0.0, -1.0, 0.0, 0.0],
    [-0.5, -0.5, 0.5, 0.0, 0.0, 1.0, 0.0, 0.0],
    [0.5, -0.5, 0.5, 0.0, 0.0, 1.0, 1.0, 0.0],
    [0.5, 0.5, 0.5, 0.0, 0.0, 1.0, 1.0, 1.0],
    [0.5, 0.5, 0.5, 0.0, 0.0, 1.0, 1.0, 1.0],
    [-0.5, 0.5, 0.5, 0.0, 0.0, 1.0, 0.0, 1.0],
    [-0.5, -0.5, 0.5, 0.0, 0.0, 1.0, 0.0, 0.0],
    [-0.5, 0.5, 0.5, -1.0, 0.0, 0.0, 1.0, 0.0],
    [-0.5, 0.5, -0.5, -1.0, 0.0, 0.0, 1.0, 1.0],
    [-0.5, -0.5, -0.5, -1.0, 0.0, 0.0, 0.0, 1.0],
    [-0.5, -0.5, -0.5, -1.0, 0.0, 0.0, 0.0, 1.0],
    [-0.5, -0.5, 0.5, -1.0, 0.0, 0.0, 0.0, 0.0],
    [-0.5, 0.5, 0.5, -1.0, 0.0, 0.0, 1.0, 0.0],
    [0.5, 0.5, 0.5, 1.0, 0.0, 0.0, 1.0, 0.0],
    [0.5, 0.5, -0.5, 1.0, 0.0, 0.0, 1.0, 1.0],
    [0.5, -0.5, -0.5, 1.0, 0.0, 0.0, 0.0, 1.0],
    [0.5, -0.5, -0.5, 1.0, 0.0, 0.0, 0.0, 1.0],
    [0.5, -0.5, 0.5, 1.0, 0.0, 0.0, 0.0, 0.0],
    [0.5, 0.5, 0.5, 1.0, 0.0, 0.0, 1.0, 0.0],
    [-0.5, -0.5, -0.5, 0.0, -1.0, 0.0, 0.0, 1.0],
    [0.5, -0.5, -0.5, 0.0, -1.0, 0.0, 1.0, 1.0],
    [0.5, -0.5, 0.5, 0.0, -1.0, 0.0, 1.0, 0.0],
    [0.5, -0.5, 0.5, 0.0, -1.0, 0.0, 1.0, 0.0],
    [-0.5, -0.5, 0.5, 0.0, -1.0, 0.0, 0.0, 0.0],
    [-0.5, -0.5, -0.5, 0.0, -1.0, 0.0, 0.0, 1.0],
    [-0.5, 0.5, -0.5, 0.0, 1.0, 0.0, 0.0, 1.0],
    [0.5, 0.5, -0.5, 0.0, 1.0, 0.0, 1.0, 1.0],
    [0.5, 0.5, 0.5, 0.0, 1.0, 0.0, 1.0, 0.0],
    [0.5, 0.5, 0.5, 0.0, 1.0, 0.0, 1.0, 0.0],
    [-0.5, 0.5, 0.5, 0.0, 1.0, 0.0, 0.0, 0.0],
    [-0.5, 0.5, -0.5, 0.0, 1.0, 0.0, 0.0, 1.0],
];

impl Mesh {
    /// Check that every array has one entry per position and every index is in range.
    ///
    /// Errors name the field: `normals`, `uvs` (length mismatch) or
    /// `triangles` (index out of range).
    pub fn validate(&self) -> Result<(), MeshError> {
        let n = self.positions.len();
        for (field, len) in [("normals", self.normals.len()), ("uvs", self.uvs.len())] {
            if len != n {
                return Err(MeshError { field, reason: format!("expected {n} entries, got {len}") });
            }
        }
        for (t, tri) in self.triangles.iter().enumerate() {
            if let Some(&bad) = tri.iter().find(|&&i| i as usize >= n) {
                return Err(MeshError {
                    field: "triangles",
                    reason: format!("triangles[{t}]: index {bad} out of range (vertex count {n})"),
                });
            }
        }
        Ok(())
    }

    /// The LearnOpenGL 36-vertex cube (positions ±0.5, face normals, UVs): the
    /// chapter's `vertices[]` unchanged, drawn as 12 triangles wound
    /// counter-clockwise seen from outside, so it draws correctly with or
    /// without back-face culling.
    ///
    /// The tutorial's own order (one triangle per three consecutive vertices)
    /// has **mixed** winding: the back, right and top faces are clockwise seen
    /// from outside, so culling back faces loses them. Here those six
    /// triangles list their vertices as `[3k, 3k+2, 3k+1]`; the others keep
    /// `[3k, 3k+1, 3k+2]`. Without culling both orders give the same image
    /// (the rasterizer swaps a clockwise triangle's corners, which is this
    /// order). [`Mesh::learnopengl_cube_as_published`] keeps the tutorial's order.
    ///
    /// Source: LearnOpenGL, Lighting maps, `vertices[]`.
    pub fn learnopengl_cube() -> Mesh {
        let mut mesh = Mesh::learnopengl_cube_as_published();
        for t in &mut mesh.triangles {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            let n = mesh.normals[t[0] as usize];
            // geometric normal against the face normal the data gives
            if (b - a).cross(c - a).dot(n) < 0.0 {
                t.swap(1, 2);
            }
        }
        mesh
    }

    /// The LearnOpenGL 36-vertex cube exactly as the chapter's `vertices[]`
    /// lists it, triangles `[3k, 3k+1, 3k+2]`: six of its twelve triangles
    /// (back, right and top faces) are clockwise seen from outside. Draw it
    /// without back-face culling, as the tutorial does; it is kept to show
    /// what culling does to mixed winding.
    ///
    /// Source: LearnOpenGL, Lighting maps, `vertices[]`.
    pub fn learnopengl_cube_as_published() -> Mesh {
        let v = &LEARNOPENGL_CUBE;
        Mesh {
            positions: v.iter().map(|r| Vec3::new(r[0], r[1], r[2])).collect(),
            normals: v.iter().map(|r| Vec3::new(r[3], r[4], r[5])).collect(),
            uvs: v.iter().map(|r| Vec2::new(r[6], r[7])).collect(),
            triangles: (0..12u32).map(|k| [3 * k, 3 * k + 1, 3 * k + 2]).collect(),
        }
    }

    /// The cube of the benchmark scenes: the LearnOpenGL cube's positions and
    /// normals, re-wound counter-clockwise outside, in the vertex order of
    /// `llvmpipe_bench.py`'s `learnopengl_cube()` (faces −x, +x, −y, +y, −z, +z).
    ///
    /// UVs follow the face's two tangent axes, (0, 0) to (1, 1).
    ///
    /// Source: `../shared/tools/llvmpipe_bench.py`.
    pub fn benchmark_cube() -> Mesh {
        let mut mesh = Mesh::empty();
        const QUAD: [(f32, f32); 6] = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
        for axis in 0..3 {
            for sign in [-1.0f32, 1.0] {
                let mut n = Vec3::ZERO;
                n[axis] = sign;
                let mut u = Vec3::ZERO;
                u[(axis + 1) % 3] = 1.0;
                let mut w = Vec3::ZERO;
                w[(axis + 2) % 3] = 1.0;
                let c = 0.5 * n;
                let mut corners: Vec<(Vec3, Vec2)> = QUAD
                    .iter()
                    .map(|&(a, b)| (c + 0.5 * (a * u + b * w), Vec2::new(0.5 * (a + 1.0), 0.5 * (b + 1.0))))
                    .collect();
                if sign < 0.0 {
                    corners.reverse();
                }
                for (p, uv) in corners {
                    mesh.positions.push(p);
                    mesh.normals.push(n);
                    mesh.uvs.push(uv);
                }
            }
        }
        mesh.triangles = (0..12u32).map(|k| [3 * k, 3 * k + 1, 3 * k + 2]).collect();
        mesh
    }

    fn empty() -> Mesh {
        Mesh { positions: Vec::new(), normals: Vec::new(), uvs: Vec::new(), triangles: Vec::new() }
    }

    /// A UV sphere of radius 1: `(stacks + 1) · (slices + 1)` vertices and
    /// `2 · stacks · slices` triangles, in the index order of `llvmpipe_bench.py`.
    ///
    /// ```text
    /// θ = π i / stacks, φ = 2π j / slices
    /// p = n = (sin θ cos φ, cos θ, sin θ sin φ);  uv = (j / slices, i / stacks)
    /// quad (i, j): a = i (slices + 1) + j, b = a + slices + 1 -> [a, a+1, b], [a+1, b+1, b]
    /// ```
    ///
    /// The pole rows keep their zero-area triangles (the rasterizer skips
    /// them), so 32 × 64 gives the benchmark's 2145 vertices and 4096
    /// triangles. Counts below 1 stack or 3 slices are raised to those.
    ///
    /// Source: `../shared/tools/llvmpipe_bench.py`, `uv_sphere`.
    pub fn uv_sphere(stacks: u32, slices: u32) -> Mesh {
        let (stacks, slices) = (stacks.max(1), slices.max(3));
        let mut mesh = Mesh::empty();
        for i in 0..=stacks {
            let theta = std::f64::consts::PI * i as f64 / stacks as f64;
            for j in 0..=slices {
                let phi = 2.0 * std::f64::consts::PI * j as f64 / slices as f64;
                let p =
                    Vec3::new((theta.sin() * phi.cos()) as f32, theta.cos() as f32, (theta.sin() * phi.sin()) as f32);
                mesh.positions.push(p);
                mesh.normals.push(p);
                mesh.uvs.push(Vec2::new(j as f32 / slices as f32, i as f32 / stacks as f32));
            }
        }
        mesh.triangles.extend(grid_triangles(stacks, slices));
        mesh
    }

    /// An icosphere of radius 1: the icosahedron with each triangle split into
    /// four `subdivisions` times, new vertices pushed to the sphere.
    ///
    /// `20 · 4^s` triangles; normals equal positions; UVs are the spherical
    /// angles `(atan2(z, x) / 2π + ½, acos(y) / π)` (seamed, for lighting
    /// maps only). `subdivisions` above 7 is clamped to 7 (327 680 triangles).
    pub fn icosphere(subdivisions: u32) -> Mesh {
        let t = (1.0 + 5f32.sqrt()) / 2.0;
        let mut positions: Vec<Vec3> = [
            (-1.0, t, 0.0),
            (1.0, t, 0.0),
            (-1.0, -t, 0.0),
            (1.0, -t, 0.0),
            (0.0, -1.0, t),
            (0.0, 1.0, t),
            (0.0, -1.0, -t),
            (0.0, 1.0, -t),
            (t, 0.0, -1.0),
            (t, 0.0, 1.0),
            (-t, 0.0, -1.0),
            (-t, 0.0, 1.0),
        ]
        .iter()
        .map(|&(x, y, z)| Vec3::new(x, y, z).normalize())
        .collect();
        let mut triangles: Vec<[u32; 3]> = vec![
            [0, 11, 5],
            [0, 5, 1],
            [0, 1, 7],
            [0, 7, 10],
            [0, 10, 11],
            [1, 5, 9],
            [5, 11, 4],
            [11, 10, 2],
            [10, 7, 6],
            [7, 1, 8],
            [3, 9, 4],
            [3, 4, 2],
            [3, 2, 6],
            [3, 6, 8],
            [3, 8, 9],
            [4, 9, 5],
            [2, 4, 11],
            [6, 2, 10],
            [8, 6, 7],
            [9, 8, 1],
        ];
        for _ in 0..subdivisions.min(7) {
            let mut midpoints = std::collections::HashMap::new();
            let mut midpoint = |a: u32, b: u32, positions: &mut Vec<Vec3>| -> u32 {
                *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                    positions.push((positions[a as usize] + positions[b as usize]).normalize());
                    (positions.len() - 1) as u32
                })
            };
            let mut next = Vec::with_capacity(triangles.len() * 4);
            for [a, b, c] in triangles {
                let ab = midpoint(a, b, &mut positions);
                let bc = midpoint(b, c, &mut positions);
                let ca = midpoint(c, a, &mut positions);
                next.extend_from_slice(&[[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
            }
            triangles = next;
        }
        let uvs = positions
            .iter()
            .map(|p| {
                Vec2::new(
                    p.z.atan2(p.x) / std::f32::consts::TAU + 0.5,
                    p.y.clamp(-1.0, 1.0).acos() / std::f32::consts::PI,
                )
            })
            .collect();
        Mesh { normals: positions.clone(), positions, uvs, triangles }
    }

    /// A square in the plane y = 0 from (−1, 0, −1) to (1, 0, 1), cut into
    /// `cells × cells` squares of two triangles each, normal +y, counter-clockwise
    /// seen from above; uv = ((x + 1)/2, (z + 1)/2). `cells` 0 is raised to 1.
    pub fn plane(cells: u32) -> Mesh {
        let n = cells.max(1);
        let mut mesh = Mesh::empty();
        for i in 0..=n {
            for j in 0..=n {
                let (u, v) = (j as f32 / n as f32, i as f32 / n as f32);
                mesh.positions.push(Vec3::new(2.0 * u - 1.0, 0.0, 2.0 * v - 1.0));
                mesh.normals.push(Vec3::Y);
                mesh.uvs.push(Vec2::new(u, v));
            }
        }
        // counter-clockwise seen from +y: (x, z) → (x+1, z) → (x, z+1) turns clockwise in
        // xz, so each grid triangle is taken the other way round: a, b, a+1
        mesh.triangles.extend(grid_triangles(n, n).map(|[p, q, r]| [p, r, q]));
        mesh
    }

    /// A torus around the y axis: tube centre radius `major`, tube radius
    /// `minor`, `rings` segments around y and `sides` around the tube.
    ///
    /// ```text
    /// p = ((R + r cos v) cos u, r sin v, (R + r cos v) sin u)
    /// n = (cos v cos u, sin v, cos v sin u)
    /// ```
    ///
    /// Front faces counter-clockwise outside. Segment counts below 3 are raised to 3.
    pub fn torus(major: f32, minor: f32, rings: u32, sides: u32) -> Mesh {
        let (rings, sides) = (rings.max(3), sides.max(3));
        let mut mesh = Mesh::empty();
        for i in 0..=rings {
            let u = std::f32::consts::TAU * i as f32 / rings as f32;
            for j in 0..=sides {
                let v = std::f32::consts::TAU * j as f32 / sides as f32;
                let n = Vec3::new(v.cos() * u.cos(), v.sin(), v.cos() * u.sin());
                let center = Vec3::new(major * u.cos(), 0.0, major * u.sin());
                mesh.positions.push(center + minor * n);
                mesh.normals.push(n);
                mesh.uvs.push(Vec2::new(i as f32 / rings as f32, j as f32 / sides as f32));
            }
        }
        mesh.triangles.extend(grid_triangles(rings, sides));
        mesh
    }

    /// Replace the normals with vertex normals averaged from the faces, with
    /// the chosen weighting ([`vertex_normals`]).
    ///
    /// Vertices that no valid triangle touches get a zero normal (they shade
    /// ambient-only). An index out of range is an error naming the triangle.
    pub fn with_vertex_normals(mut self, weighting: VertexWeighting) -> Result<Mesh, IndexOutOfRange> {
        self.normals = vertex_normals(&self.positions, &self.triangles, weighting)?;
        Ok(self)
    }

    /// The same mesh with shared vertices merged by position (exactly equal
    /// coordinates, −0 equal to +0), so that averaged vertex normals smooth across seams.
    /// UVs and normals of the first occurrence are kept.
    pub fn welded(&self) -> Mesh {
        let mut map = std::collections::HashMap::new();
        let mut out = Mesh::empty();
        let remap: Vec<u32> = self
            .positions
            .iter()
            .enumerate()
            .map(|(i, p)| {
                // + 0.0 turns −0.0 into +0.0, so the two zeros weld together
                let key = ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits(), (p.z + 0.0).to_bits());
                *map.entry(key).or_insert_with(|| {
                    out.positions.push(*p);
                    out.normals.push(self.normals.get(i).copied().unwrap_or(Vec3::ZERO));
                    out.uvs.push(self.uvs.get(i).copied().unwrap_or(Vec2::ZERO));
                    (out.positions.len() - 1) as u32
                })
            })
            .collect();
        out.triangles = self
            .triangles
            .iter()
            .filter_map(|t| {
                let g = |k: usize| remap.get(t[k] as usize).copied();
                Some([g(0)?, g(1)?, g(2)?])
            })
            .collect();
        out
    }
}
