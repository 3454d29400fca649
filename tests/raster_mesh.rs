//! Meshes and camera: counts, winding, normals, error fields.

use glam::Vec3;
use lightlab::normals::VertexWeighting;
use lightlab::raster::camera::{look_at, perspective, Camera};
use lightlab::raster::mesh::Mesh;

/// Share of triangles whose geometric normal agrees with their vertex normals (zero-area ones skipped).
fn outward_share(mesh: &Mesh) -> (usize, usize) {
    let (mut agree, mut total) = (0, 0);
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        let Some(n) = (b - a).cross(c - a).try_normalize() else { continue };
        let avg: Vec3 = t.iter().map(|&i| mesh.normals[i as usize]).sum();
        total += 1;
        if n.dot(avg) > 0.0 {
            agree += 1;
        }
    }
    (agree, total)
}

#[test]
fn benchmark_sphere_has_the_design_counts() {
    let s = Mesh::uv_sphere(32, 64);
    assert_eq!((s.positions.len(), s.triangles.len()), (2145, 4096));
    s.validate().unwrap();
    // counter-clockwise outside: every non-degenerate triangle agrees with its normals
    let (agree, total) = outward_share(&s);
    assert_eq!(agree, total);
    // the pole rows: 64 triangles at each pole with (numerically) no area; at the bottom pole
    // sin(π) = 1.2e-16 leaves some a tiny non-zero area, far below what snapping can resolve
    let slivers = s
        .triangles
        .iter()
        .filter(|t| {
            let [a, b, c] = t.map(|i| s.positions[i as usize]);
            (b - a).cross(c - a).length() < 1e-12
        })
        .count();
    assert_eq!(slivers, 128);
    assert!(total >= 4096 - 128);
    for n in &s.normals {
        assert!((n.length() - 1.0).abs() < 1e-6);
    }
}

#[test]
fn cubes_winding() {
    let bench = Mesh::benchmark_cube();
    assert_eq!(outward_share(&bench), (12, 12));
    let published = Mesh::learnopengl_cube_as_published();
    assert_eq!((published.positions.len(), published.triangles.len()), (36, 12));
    // the tutorial's order has mixed winding: back, right and top faces (6 triangles) are clockwise
    assert_eq!(outward_share(&published), (6, 12));
    // the mesh lightlab draws keeps the tutorial's vertices and winds every triangle outward
    let lo = Mesh::learnopengl_cube();
    assert_eq!(outward_share(&lo), (12, 12));
    assert_eq!((&lo.positions, &lo.normals, &lo.uvs), (&published.positions, &published.normals, &published.uvs));
    for (t, p) in lo.triangles.iter().zip(&published.triangles) {
        // the same three vertices, at most two swapped
        let (mut a, mut b) = (*t, *p);
        a.sort();
        b.sort();
        assert_eq!(a, b);
    }
    for m in [&bench, &lo, &published] {
        m.validate().unwrap();
        for (p, n) in m.positions.iter().zip(&m.normals) {
            // each vertex lies on the face its normal names
            assert_eq!(p.dot(*n), 0.5, "p {p} n {n}");
        }
    }
}

#[test]
fn other_meshes_are_closed_outward_and_valid() {
    for (name, m) in
        [("icosphere", Mesh::icosphere(2)), ("plane", Mesh::plane(4)), ("torus", Mesh::torus(0.7, 0.3, 24, 12))]
    {
        m.validate().unwrap();
        let (agree, total) = outward_share(&m);
        assert_eq!(agree, total, "{name}");
    }
    assert_eq!(Mesh::icosphere(2).triangles.len(), 320);
    assert_eq!(Mesh::plane(4).triangles.len(), 32);
}

#[test]
fn recomputed_vertex_normals_match_the_analytic_sphere() {
    // the icosphere shares its vertices (no seam), so averaged face normals can be compared with the radius
    let s = Mesh::icosphere(3);
    for w in [VertexWeighting::Unweighted, VertexWeighting::Area, VertexWeighting::Angle] {
        let m = s.clone().with_vertex_normals(w).unwrap();
        let worst = m
            .positions
            .iter()
            .zip(&m.normals)
            .map(|(p, n)| p.normalize().dot(*n).clamp(-1.0, 1.0).acos())
            .fold(0.0f32, f32::max);
        println!("{w:?}: worst angle to the radius {worst:.5} rad");
        // 0.02 rad: a cell of the 3-times subdivided icosahedron spans ~0.15 rad; its irregular
        // triangles tilt the average by a fraction of that (measured: unweighted 0.0083, area 0.0118,
        // angle 0.0052 — angle weighting is the most faithful here)
        assert!(worst < 0.02, "{w:?}: worst {worst} rad");
    }
}

#[test]
fn camera_errors_name_the_field() {
    assert_eq!(perspective(0.0, 1.0, 0.1, 10.0).unwrap_err().field, "fovy_deg");
    assert_eq!(perspective(45.0, -1.0, 0.1, 10.0).unwrap_err().field, "aspect");
    assert_eq!(perspective(45.0, 1.0, 0.0, 10.0).unwrap_err().field, "near");
    assert_eq!(perspective(45.0, 1.0, 1.0, 1.0).unwrap_err().field, "far");
    assert_eq!(look_at(Vec3::Z, Vec3::Z, Vec3::Y).unwrap_err().field, "target");
    assert_eq!(look_at(Vec3::Z, Vec3::ZERO, Vec3::Z).unwrap_err().field, "up");
    // the tutorials' camera is translate(0, 0, -3)
    let c = Camera::learnopengl(4.0 / 3.0);
    assert_eq!(c.view.transform_point3(Vec3::new(0.0, 0.0, 3.0)), Vec3::ZERO);
    let general = Camera::new(Vec3::new(0.0, 0.0, 3.0), Vec3::ZERO, Vec3::Y, 45.0, 4.0 / 3.0, 0.1, 100.0).unwrap();
    assert!(general.view.abs_diff_eq(c.view, 1e-6) && general.projection.abs_diff_eq(c.projection, 1e-6));
}
