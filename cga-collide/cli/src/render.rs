//! A small software rasteriser for `--image`: both meshes, flat-shaded, orthographic, with the
//! intersecting triangles highlighted (like the thesis's appendix B figures) and the
//! intersection curve drawn over them in black where it is visible.

use std::collections::HashSet;
use std::fs::File;
use std::io::BufWriter;
use std::path::Path;

use anyhow::Result;
use cga_collide::nalgebra::{Point3, Rotation3, Vector3};
use cga_collide::query::ContactGeometry;
use cga_collide::shape::mesh::TriMesh;

const WIDTH: usize = 960;
const HEIGHT: usize = 720;

/// The colour of the intersection curve (no shaded triangle is this dark).
const CURVE: [u8; 3] = [0, 0, 0];

/// Renders mesh `a` (blue-grey) and `b` (sand) with the triangles of `pairs` in red (A) and
/// orange (B), and the segments of `curve` in black, to a PNG.
pub fn render(
    a: &TriMesh,
    b: &TriMesh,
    pairs: &[(u32, u32)],
    curve: &[[Point3<f64>; 2]],
    path: &Path,
) -> Result<()> {
    let image = draw(a, b, pairs, curve);
    let file = BufWriter::new(File::create(path)?);
    let mut encoder = png::Encoder::new(file, WIDTH as u32, HEIGHT as u32);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header()?;
    let bytes: Vec<u8> = image.iter().flatten().copied().collect();
    writer.write_image_data(&bytes)?;
    Ok(())
}

/// The intersection curve as segments: each contact segment, and the outline of each coplanar
/// contact polygon (contact points are left out).
pub fn curve_segments<'a>(
    contacts: impl IntoIterator<Item = &'a ContactGeometry>,
) -> Vec<[Point3<f64>; 2]> {
    let mut out = Vec::new();
    for g in contacts {
        let p: Vec<Point3<f64>> = g.points_f64().into_iter().map(Point3::from).collect();
        match p.len() {
            0 | 1 => {}
            2 => out.push([p[0], p[1]]),
            n => out.extend((0..n).map(|k| [p[k], p[(k + 1) % n]])),
        }
    }
    out
}

/// The intersection curve of the triangle pairs `pairs` (indices into `a` and `b`), computed
/// in `f64` for the picture: each crossing segment, and the outline of each coplanar overlap.
/// The pairs themselves were decided exactly; only where the curve is drawn is rounded, so the
/// picture costs a few operations a pair (the exact geometry of `--contacts`, in rationals,
/// costs a hundred times the query on coincident meshes).
pub fn curve_of_pairs(a: &TriMesh, b: &TriMesh, pairs: &[(u32, u32)]) -> Vec<[Point3<f64>; 2]> {
    let mut out = Vec::new();
    for &(i, j) in pairs {
        let corners = |m: &TriMesh, t: u32| {
            m.triangles()[t as usize].map(|k| m.vertices()[k as usize].coords)
        };
        let (p, q) = (corners(a, i), corners(b, j));
        match crossing(&p, &q) {
            Some(Crossing::Segment(s)) => out.push(s.map(Point3::from)),
            Some(Crossing::Coplanar) => {
                let polygon = clip(&p, &q);
                let n = polygon.len();
                if n >= 2 {
                    out.extend(
                        (0..n).map(|k| [polygon[k], polygon[(k + 1) % n]].map(Point3::from)),
                    );
                }
            }
            None => {}
        }
    }
    out
}

/// How two triangles meet, in `f64`.
enum Crossing {
    Segment([Vector3<f64>; 2]),
    Coplanar,
}

fn normal(t: &[Vector3<f64>; 3]) -> Vector3<f64> {
    (t[1] - t[0]).cross(&(t[2] - t[0]))
}

/// The part of triangle `t` on the plane `(n, d)` (`n·x = d`): the interval of the line where
/// it crosses, as two points (equal for a touch at a corner), or `None` when it misses.
fn cut(t: &[Vector3<f64>; 3], n: &Vector3<f64>, d: f64) -> Option<[Vector3<f64>; 2]> {
    let s = t.map(|p| n.dot(&p) - d);
    let mut points = Vec::with_capacity(3);
    for k in 0..3 {
        let (u, v) = (k, (k + 1) % 3);
        if s[u] == 0.0 {
            points.push(t[u]);
        }
        if (s[u] < 0.0 && s[v] > 0.0) || (s[u] > 0.0 && s[v] < 0.0) {
            points.push(t[u] + (t[v] - t[u]) * (s[u] / (s[u] - s[v])));
        }
    }
    match points.len() {
        0 => None,
        1 => Some([points[0]; 2]),
        _ => Some([points[0], points[1]]),
    }
}

/// The segment where `p` and `q` meet (the overlap of their cuts along the planes' common
/// line), or `Coplanar` when their planes are (nearly) the same.
fn crossing(p: &[Vector3<f64>; 3], q: &[Vector3<f64>; 3]) -> Option<Crossing> {
    let (np, nq) = (normal(p), normal(q));
    let line = np.cross(&nq);
    if line.norm() <= 1e-12 * np.norm() * nq.norm() {
        return Some(Crossing::Coplanar);
    }
    let a = cut(p, &nq, nq.dot(&q[0]))?;
    let b = cut(q, &np, np.dot(&p[0]))?;
    let along = |x: &Vector3<f64>| line.dot(x);
    let order = |s: [Vector3<f64>; 2]| {
        if along(&s[0]) <= along(&s[1]) {
            s
        } else {
            [s[1], s[0]]
        }
    };
    let (a, b) = (order(a), order(b));
    let start = if along(&a[0]) >= along(&b[0]) {
        a[0]
    } else {
        b[0]
    };
    let end = if along(&a[1]) <= along(&b[1]) {
        a[1]
    } else {
        b[1]
    };
    (along(&start) <= along(&end)).then_some(Crossing::Segment([start, end]))
}

/// Triangle `p` clipped to triangle `q` in their common plane (Sutherland–Hodgman against the
/// planes through `q`'s edges, perpendicular to `q`).
fn clip(p: &[Vector3<f64>; 3], q: &[Vector3<f64>; 3]) -> Vec<Vector3<f64>> {
    let n = normal(q);
    let mut polygon: Vec<Vector3<f64>> = p.to_vec();
    for k in 0..3 {
        let (e0, e1) = (q[k], q[(k + 1) % 3]);
        // Points x with inward · (x - e0) >= 0 are on q's side of this edge.
        let inward = n.cross(&(e1 - e0));
        let side = |x: &Vector3<f64>| inward.dot(&(x - e0));
        let mut next = Vec::with_capacity(polygon.len() + 1);
        for (m, x) in polygon.iter().enumerate() {
            let y = &polygon[(m + 1) % polygon.len()];
            let (sx, sy) = (side(x), side(y));
            if sx >= 0.0 {
                next.push(*x);
            }
            if (sx >= 0.0) != (sy >= 0.0) {
                next.push(x + (y - x) * (sx / (sx - sy)));
            }
        }
        polygon = next;
        if polygon.is_empty() {
            break;
        }
    }
    polygon
}

/// The picture as rows of RGB pixels.
fn draw(
    a: &TriMesh,
    b: &TriMesh,
    pairs: &[(u32, u32)],
    curve: &[[Point3<f64>; 2]],
) -> Vec<[u8; 3]> {
    let hit_a: HashSet<u32> = pairs.iter().map(|p| p.0).collect();
    let hit_b: HashSet<u32> = pairs.iter().map(|p| p.1).collect();
    // A three-quarter view: turn about y, then tilt about x.
    let view = Rotation3::from_axis_angle(&Vector3::x_axis(), 0.35)
        * Rotation3::from_axis_angle(&Vector3::y_axis(), -0.6);
    let project = |p: &Point3<f64>| view * p;
    let (mut lo, mut hi) = (
        Vector3::repeat(f64::INFINITY),
        Vector3::repeat(f64::NEG_INFINITY),
    );
    for p in a.vertices().iter().chain(b.vertices()) {
        let q = project(p).coords;
        lo = lo.inf(&q);
        hi = hi.sup(&q);
    }
    let span = (hi - lo).xy().max().max(f64::MIN_POSITIVE);
    let scale = 0.92 * (WIDTH.min(HEIGHT) as f64) / span;
    let centre = (lo + hi) * 0.5;
    let to_screen = |p: &Point3<f64>| {
        let q = project(p).coords - centre;
        Vector3::new(
            WIDTH as f64 / 2.0 + q.x * scale,
            HEIGHT as f64 / 2.0 - q.y * scale,
            q.z,
        )
    };
    let mut depth = vec![f64::NEG_INFINITY; WIDTH * HEIGHT];
    let mut image = vec![[250u8, 250, 252]; WIDTH * HEIGHT];
    let light = Vector3::new(0.3, 0.5, 1.0).normalize();
    for (mesh, base, hit, hit_colour) in [
        (a, [120.0, 150.0, 200.0], &hit_a, [220.0, 30.0, 30.0]),
        (b, [215.0, 190.0, 140.0], &hit_b, [250.0, 140.0, 0.0]),
    ] {
        for (i, t) in mesh.triangles().iter().enumerate() {
            let v = t.map(|k| mesh.vertices()[k as usize]);
            let s = v.map(|p| to_screen(&p));
            let normal = (view * (v[1] - v[0])).cross(&(view * (v[2] - v[0])));
            let shade = normal
                .try_normalize(0.0)
                .map_or(0.6, |n| 0.25 + 0.75 * n.dot(&light).abs());
            let colour = if hit.contains(&(i as u32)) {
                hit_colour
            } else {
                base
            };
            let rgb = colour.map(|c| (c * shade).clamp(0.0, 255.0) as u8);
            fill_triangle(&s, rgb, &mut depth, &mut image);
        }
    }
    // The curve lies on both surfaces: draw it where it is no deeper than the nearest surface,
    // give or take a small bias, so that hidden parts stay hidden.
    let bias = 0.01 * (hi.z - lo.z).abs().max(f64::MIN_POSITIVE);
    for [p, q] in curve {
        draw_segment(&to_screen(p), &to_screen(q), bias, &depth, &mut image);
    }
    image
}

/// A line two pixels wide from `p` to `q` (screen coordinates, depth in `z`), drawn where it
/// is within `bias` of the depth buffer's nearest surface.
fn draw_segment(
    p: &Vector3<f64>,
    q: &Vector3<f64>,
    bias: f64,
    depth: &[f64],
    image: &mut [[u8; 3]],
) {
    let length = (q.xy() - p.xy()).norm();
    if !length.is_finite() {
        return;
    }
    let steps = (2.0 * length).ceil().clamp(1.0, 1e5) as usize;
    for k in 0..=steps {
        let r = p + (q - p) * (k as f64 / steps as f64);
        for (dx, dy) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)] {
            let (x, y) = ((r.x + dx - 0.5).floor(), (r.y + dy - 0.5).floor());
            if x < 0.0 || y < 0.0 || x >= WIDTH as f64 || y >= HEIGHT as f64 {
                continue;
            }
            let i = y as usize * WIDTH + x as usize;
            if r.z + bias >= depth[i] {
                image[i] = CURVE;
            }
        }
    }
}

/// Z-buffered fill with barycentric coverage tests (larger z is nearer the viewer).
fn fill_triangle(s: &[Vector3<f64>; 3], rgb: [u8; 3], depth: &mut [f64], image: &mut [[u8; 3]]) {
    let area = (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[2].x - s[0].x) * (s[1].y - s[0].y);
    if area.abs() < 1e-12 || !area.is_finite() {
        return;
    }
    let x0 = s
        .iter()
        .map(|p| p.x)
        .fold(f64::INFINITY, f64::min)
        .floor()
        .max(0.0) as usize;
    let x1 = s
        .iter()
        .map(|p| p.x)
        .fold(f64::NEG_INFINITY, f64::max)
        .ceil()
        .min(WIDTH as f64 - 1.0);
    let y0 = s
        .iter()
        .map(|p| p.y)
        .fold(f64::INFINITY, f64::min)
        .floor()
        .max(0.0) as usize;
    let y1 = s
        .iter()
        .map(|p| p.y)
        .fold(f64::NEG_INFINITY, f64::max)
        .ceil()
        .min(HEIGHT as f64 - 1.0);
    if x1 < 0.0 || y1 < 0.0 {
        return;
    }
    for y in y0..=(y1 as usize) {
        for x in x0..=(x1 as usize) {
            let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
            let w0 = ((s[1].x - px) * (s[2].y - py) - (s[2].x - px) * (s[1].y - py)) / area;
            let w1 = ((s[2].x - px) * (s[0].y - py) - (s[0].x - px) * (s[2].y - py)) / area;
            let w2 = 1.0 - w0 - w1;
            if w0 < 0.0 || w1 < 0.0 || w2 < 0.0 {
                continue;
            }
            let z = w0 * s[0].z + w1 * s[1].z + w2 * s[2].z;
            let k = y * WIDTH + x;
            if z > depth[k] {
                depth[k] = z;
                image[k] = rgb;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cga_collide::collider::Collider;

    fn cube_at(x: f64) -> TriMesh {
        TriMesh::cuboid(Point3::new(x, 0.0, 0.0), Point3::new(x + 1.0, 1.0, 1.0)).unwrap()
    }

    fn curve_pixels(b: &TriMesh) -> usize {
        let a = cube_at(0.0);
        let (ca, cb) = (Collider::new(a.clone()), Collider::new(b.clone()));
        let contacts = ca.contacts(&cb);
        let pairs = ca.intersecting_pairs(&cb);
        draw(
            &a,
            b,
            &pairs,
            &curve_segments(contacts.iter().map(|(_, g)| g)),
        )
        .iter()
        .filter(|&&c| c == CURVE)
        .count()
    }

    #[test]
    fn the_curve_shows_where_the_meshes_cross_and_nowhere_else() {
        // Two unit cubes overlapping by half: the crossing curve is two squares of side 1 (the
        // faces x = 0.5 and x = 1 inside the other cube), most of it in view.
        let crossing = curve_pixels(&cube_at(0.5));
        assert!(crossing > 1000, "{crossing} curve pixels");
        assert_eq!(curve_pixels(&cube_at(3.0)), 0);
    }

    #[test]
    fn the_rounded_curve_draws_what_the_exact_one_draws() {
        for x in [0.5, 0.25, 1.0] {
            let (a, b) = (cube_at(0.0), cube_at(x));
            let (ca, cb) = (Collider::new(a.clone()), Collider::new(b.clone()));
            let pairs = ca.intersecting_pairs(&cb);
            let exact = curve_segments(ca.contacts(&cb).iter().map(|(_, g)| g));
            let rounded = curve_of_pairs(&a, &b, &pairs);
            let pixels = |curve: &[[Point3<f64>; 2]]| {
                draw(&a, &b, &pairs, curve)
                    .iter()
                    .filter(|&&c| c == CURVE)
                    .count()
            };
            let (e, r) = (pixels(&exact), pixels(&rounded));
            assert!(
                e > 0 && e.abs_diff(r) * 50 <= e,
                "x = {x}: {e} exact, {r} rounded"
            );
        }
    }

    #[test]
    fn polygons_give_their_outline_and_points_nothing() {
        let q = |x: i64| cga_collide::ga_core::scalar::Rational::from_integer(x.into());
        let p = |x, y, z| [q(x), q(y), q(z)];
        let square = ContactGeometry::Polygon(vec![p(0, 0, 0), p(1, 0, 0), p(1, 1, 0), p(0, 1, 0)]);
        let point = ContactGeometry::Point(p(0, 0, 0));
        let segments = curve_segments(&[square, point]);
        assert_eq!(segments.len(), 4);
        assert_eq!(segments[3], [Point3::new(0.0, 1.0, 0.0), Point3::origin()]);
    }
}
