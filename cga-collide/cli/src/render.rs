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
