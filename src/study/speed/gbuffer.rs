//! The exact-input sphere: the ray caster's hit points and normals, rounded to `f32`, shaded directly by each variant.

use glam::{DVec3, Vec3};
use rayon::prelude::*;

use crate::raster::kernel::{LaneMaterial, MultiLightKernel, Specular, LANES};
use crate::raster::raycast::{shade_f64, RayScene};

use super::*;

pub(super) struct GFragment {
    pub(super) pixel: usize,
    pub(super) p: Vec3,
    pub(super) n: Vec3,
    p64: DVec3,
    n64: DVec3,
}

pub(super) fn gbuffer(ray: &RayScene, w: u32, h: u32) -> Vec<GFragment> {
    let inv_vp = (ray.camera.projection.as_dmat4() * ray.camera.view.as_dmat4()).inverse();
    let mut out = Vec::new();
    for row in 0..h {
        let j = (h - 1 - row) as f64 + 0.5;
        for i in 0..w {
            let ndc = |v: f64, size: u32| 2.0 * v / size as f64 - 1.0;
            let (x, y) = (ndc(i as f64 + 0.5, w), ndc(j, h));
            let near = inv_vp.project_point3(DVec3::new(x, y, -1.0));
            let far = inv_vp.project_point3(DVec3::new(x, y, 1.0));
            let dir = (far - near).normalize_or_zero();
            if let Some(hit) = ray.hit(near, dir) {
                let p64 = near + hit.t * dir;
                out.push(GFragment {
                    pixel: (row * w + i) as usize,
                    p: p64.as_vec3(),
                    n: hit.n.as_vec3(),
                    p64,
                    n64: hit.n,
                });
            }
        }
    }
    out
}

/// Shade every fragment of the G-buffer, 16 at a time, on all cores.
pub(super) fn shade_gbuffer(frags: &[GFragment], out: &mut [Vec3], shade: &(dyn Fn(&[GFragment], &mut [Vec3]) + Sync)) {
    frags.par_chunks(4 * LANES).zip(out.par_chunks_mut(4 * LANES)).for_each(|(f, o)| shade(f, o));
}

pub(super) fn gbuffer_study(ctx: &mut Ctx) {
    let (w, h) = (ctx.opts.width, ctx.opts.height);
    let scenes::UnitSphere { camera, lights, material, ray } = scenes::unit_sphere(w, h);
    let eye = camera.eye;
    (ctx.progress)(&format!("{GBUFFER}: exact inputs and references"));
    let frags = gbuffer(&ray, w, h);
    let reference_for = |spec: Specular| -> Vec<Option<DVec3>> {
        let mut r = vec![None; (w * h) as usize];
        for f in &frags {
            r[f.pixel] = Some(shade_f64(&lights, &material, f.p64, f.n64, eye.as_dvec3(), spec));
        }
        r
    };
    let ref_phong = reference_for(Specular::Phong);
    let ref_blinn = reference_for(Specular::Blinn);
    let variant = |pow: PowMethod, normalize: Normalize, specular: Specular| VariantShader {
        scene: lights.clone(),
        material,
        eye,
        pow,
        normalize,
        specular,
    };
    let s = material.shininess;
    let scalar = |v: VariantShader| {
        move |f: &[GFragment], o: &mut [Vec3]| {
            for (g, c) in f.iter().zip(o) {
                *c = v.shade(g.p, g.n);
            }
        }
    };
    type Method<'a> = (&'static str, &'static str, Specular, Box<dyn Fn(&[GFragment], &mut [Vec3]) + Sync + 'a>);
    let lights_ref = &lights;
    let kernel_fn = |spec: Specular| {
        let kernel = MultiLightKernel::new(&lights, eye, s, spec);
        let lm = LaneMaterial::uniform(&material);
        move |f: &[GFragment], o: &mut [Vec3]| {
            for (fc, oc) in f.chunks(LANES).zip(o.chunks_mut(LANES)) {
                let (mut pos, mut nrm, mut rgb) = ([[0.0; LANES]; 3], [[0.0; LANES]; 3], [[0.0; LANES]; 3]);
                for (l, g) in fc.iter().enumerate() {
                    for k in 0..3 {
                        pos[k][l] = g.p[k];
                        nrm[k][l] = g.n[k];
                    }
                }
                kernel.shade(&pos, &nrm, &lm, &mut rgb);
                for (l, c) in oc.iter_mut().enumerate() {
                    *c = Vec3::new(rgb[0][l], rgb[1][l], rgb[2][l]);
                }
            }
        }
    };
    // The scalar variants: (group, method, pow, normalize, lobe), each shading with
    // `VariantShader` and compared with the reference of its lobe.
    let scalar_variants = [
        ("pow", "powf (scalar f32)", PowMethod::Powf, Normalize::Exact, Specular::Phong),
        ("pow", "LUT 256", PowMethod::lut(256, s), Normalize::Exact, Specular::Phong),
        ("pow", "LUT 1024", PowMethod::lut(1024, s), Normalize::Exact, Specular::Phong),
        ("pow", "Schlick x/(n−nx+x)", PowMethod::Schlick, Normalize::Exact, Specular::Phong),
        ("pow", "exp2/log2 polynomial", PowMethod::Exp2Log2, Normalize::Exact, Specular::Phong),
        ("normalize", "rsqrt + 1 Newton step", PowMethod::Powf, Normalize::RsqrtNewton, Specular::Phong),
        ("lobe", "Blinn-Phong (scalar f32)", PowMethod::Powf, Normalize::Exact, Specular::Blinn),
    ];
    let mut methods: Vec<Method<'_>> = scalar_variants
        .into_iter()
        .map(|(group, method, pow, normalize, spec)| -> Method<'_> {
            (group, method, spec, Box::new(scalar(variant(pow, normalize, spec))))
        })
        .collect();
    methods.extend::<[Method<'_>; 4]>([
        (
            "precision",
            "f64 shading",
            Specular::Phong,
            Box::new(move |f: &[GFragment], o: &mut [Vec3]| {
                for (g, c) in f.iter().zip(o) {
                    let n = g.n.as_dvec3().normalize_or_zero();
                    *c = shade_f64(lights_ref, &material, g.p.as_dvec3(), n, eye.as_dvec3(), Specular::Phong).as_vec3();
                }
            }),
        ),
        (
            "simd",
            "Scene::shade (scalar core)",
            Specular::Phong,
            Box::new(move |f: &[GFragment], o: &mut [Vec3]| {
                for (g, c) in f.iter().zip(o) {
                    *c = lights_ref.shade(&material, g.p, g.n, eye).rgb();
                }
            }),
        ),
        ("simd", "16-lane kernel, Phong", Specular::Phong, Box::new(kernel_fn(Specular::Phong))),
        ("simd", "16-lane kernel, Blinn-Phong", Specular::Blinn, Box::new(kernel_fn(Specular::Blinn))),
    ]);
    let mut out = vec![Vec3::ZERO; frags.len()];
    for (group, method, spec, shade) in &methods {
        (ctx.progress)(&format!("{GBUFFER}: {method}"));
        shade_gbuffer(&frags, &mut out, shade.as_ref());
        let mut img = vec![None; (w * h) as usize];
        for (f, c) in frags.iter().zip(&out) {
            img[f.pixel] = Some(*c);
        }
        let reference = if *spec == Specular::Blinn { &ref_blinn } else { &ref_phong };
        let error = compare(w, h, &img, reference);
        let timing = time(ctx.opts.runs, ctx.opts.min_run_seconds, || shade_gbuffer(&frags, &mut out, shade.as_ref()));
        ctx.push(GBUFFER, group, method, frags.len(), timing, error);
    }
}
