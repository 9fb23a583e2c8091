// The brute-force batches: one query shape (or a triangle of a mesh) against triangles, every
// sign certified by a running error bound. Prepended by the host: `alias F = f32|f64;`, the
// constants U, ETA, MARGIN, INPUT_ERR, then the generated `cga::wgsl::RING` source over the
// certified scalar below.
//
// Answers are three-valued: 0 = no, 1 = yes, 2 = not certified (the host re-decides exactly).
// A sign is +1 or -1 when the error bound excludes zero, and 0 ("unknown") otherwise: an exact
// zero is never certified, so every degenerate configuration ends up flagged, and every
// certified answer follows the same decisions as the exact CPU algorithm.

const NO: u32 = 0u;
const YES: u32 = 1u;
const UNKNOWN: u32 = 2u;

// ---------------------------------------------------------------- certified scalar

struct Scalar {
    v: F,
    e: F,
}

fn scalar_zero() -> Scalar {
    return Scalar(F(0.0), F(0.0));
}

fn scalar_int(k: F) -> Scalar {
    return Scalar(k, F(0.0));
}

fn scalar_add(a: Scalar, b: Scalar) -> Scalar {
    let v = a.v + b.v;
    return Scalar(v, a.e + b.e + U * abs(v) + ETA);
}

fn scalar_sub(a: Scalar, b: Scalar) -> Scalar {
    let v = a.v - b.v;
    return Scalar(v, a.e + b.e + U * abs(v) + ETA);
}

fn scalar_mul(a: Scalar, b: Scalar) -> Scalar {
    let v = a.v * b.v;
    return Scalar(v, abs(a.v) * b.e + (abs(b.v) + b.e) * a.e + U * abs(v) + ETA);
}

fn scalar_neg(a: Scalar) -> Scalar {
    return Scalar(-a.v, a.e);
}

// An input coordinate (for f32 it carries the rounding of the host's f64 -> f32 conversion).
fn input(x: F) -> Scalar {
    return Scalar(x, INPUT_ERR * abs(x));
}

// +1 / -1 when certain, 0 when the bound does not exclude zero (or overflowed).
fn sgn(x: Scalar) -> i32 {
    if abs(x.v) > x.e * MARGIN {
        return select(-1, 1, x.v > F(0.0));
    }
    return 0;
}

// ---------------------------------------------------------------- three-valued logic

fn k_and(a: u32, b: u32) -> u32 {
    if a == NO || b == NO {
        return NO;
    }
    if a == YES && b == YES {
        return YES;
    }
    return UNKNOWN;
}

fn k_or(a: u32, b: u32) -> u32 {
    if a == YES || b == YES {
        return YES;
    }
    if a == NO && b == NO {
        return NO;
    }
    return UNKNOWN;
}

// `if c { x } else { y }` when `c` may be unknown.
fn k_ite(c: u32, x: u32, y: u32) -> u32 {
    if c == YES {
        return x;
    }
    if c == NO {
        return y;
    }
    if x == y {
        return x;
    }
    return UNKNOWN;
}

// The sign is `<= 0` (the CPU's `!= Greater`).
fn le0(s: i32) -> u32 {
    if s < 0 {
        return YES;
    }
    if s > 0 {
        return NO;
    }
    return UNKNOWN;
}

// The sign is `>= 0` (the CPU's `!= Less`).
fn ge0(s: i32) -> u32 {
    return le0(-s);
}

// ---------------------------------------------------------------- points

struct P3 {
    x: Scalar,
    y: Scalar,
    z: Scalar,
}

fn p3_zero() -> P3 {
    return P3(scalar_zero(), scalar_zero(), scalar_zero());
}

fn p3_sub(a: P3, b: P3) -> P3 {
    return P3(scalar_sub(a.x, b.x), scalar_sub(a.y, b.y), scalar_sub(a.z, b.z));
}

fn p3_dot(a: P3, b: P3) -> Scalar {
    return scalar_add(scalar_add(scalar_mul(a.x, b.x), scalar_mul(a.y, b.y)), scalar_mul(a.z, b.z));
}

fn p3_cross(u: P3, v: P3) -> P3 {
    return P3(
        scalar_sub(scalar_mul(u.y, v.z), scalar_mul(u.z, v.y)),
        scalar_sub(scalar_mul(u.z, v.x), scalar_mul(u.x, v.z)),
        scalar_sub(scalar_mul(u.x, v.y), scalar_mul(u.y, v.x)),
    );
}

// ---------------------------------------------------------------- conformal embedding

// `2 up(x) = 2x + (|x|^2 - 1) e4 + (|x|^2 + 1) e5` (the thesis's scaling, no division).
fn up2(x: P3) -> Vector {
    let two = scalar_int(F(2.0));
    let one = scalar_int(F(1.0));
    let q = p3_dot(x, x);
    return Vector(
        scalar_mul(two, x.x),
        scalar_mul(two, x.y),
        scalar_mul(two, x.z),
        scalar_sub(q, one),
        scalar_add(q, one),
    );
}

fn n_inf() -> Vector {
    let one = scalar_int(F(1.0));
    return Vector(scalar_zero(), scalar_zero(), scalar_zero(), one, one);
}

// The dual sphere `2 up(c) - r^2 n_inf`.
fn sphere2(c: P3, r: Scalar) -> Vector {
    return Vector_sub_Vector(up2(c), Vector_scale(n_inf(), scalar_mul(r, r)));
}

// `2(|p - c|^2 - r^2) = -X.S` with `X = 2 up(p - c)`, `S = 2 up(0) - r^2 n_inf`.
fn point_power(p: P3, c: P3, r: Scalar) -> i32 {
    let x = up2(p3_sub(p, c));
    return -sgn(Vector_scalar_product_Vector(x, sphere2(p3_zero(), r)));
}

// The plane `2up(0) ^ 2up(b - a) ^ 2up(c - a) ^ n_inf` in the frame translated to `a`.
struct Plane {
    a: P3,
    q: Quadvector,
}

fn plane(a: P3, b: P3, c: P3) -> Plane {
    let o = up2(p3_zero());
    let w = Vector_wedge_Vector(o, up2(p3_sub(b, a)));
    let t = Bivector_wedge_Vector(w, up2(p3_sub(c, a)));
    return Plane(a, Trivector_wedge_Vector(t, n_inf()));
}

// The sign of `orient3d(a, b, c, d)`: `P ^ 2up(d - a) = -16 orient3d(a, b, c, d) e12345`.
fn side(pl: Plane, d: P3) -> i32 {
    let x = Quadvector_wedge_Vector(pl.q, up2(p3_sub(d, pl.a)));
    return -sgn(x.e12345);
}

fn orient3d(a: P3, b: P3, c: P3, d: P3) -> i32 {
    return side(plane(a, b, c), d);
}

// ---------------------------------------------------------------- Euclidean helpers

// `(c - a).(b - a)`.
fn segment_dot(a: P3, b: P3, c: P3) -> i32 {
    return sgn(p3_dot(p3_sub(c, a), p3_sub(b, a)));
}

// `|w x d|^2 - r^2 |d|^2`, `d = b - a`, `w = c - a`.
fn line_distance(a: P3, b: P3, c: P3, r: Scalar) -> i32 {
    let d = p3_sub(b, a);
    let w = p3_sub(c, a);
    let m = p3_cross(w, d);
    return sgn(scalar_sub(p3_dot(m, m), scalar_mul(scalar_mul(r, r), p3_dot(d, d))));
}

// `n.((b - a) x (q - a))`, `n = (b - a) x (c - a)`.
fn edge_side(a: P3, b: P3, c: P3, q: P3) -> i32 {
    let u = p3_sub(b, a);
    let v = p3_sub(c, a);
    let w = p3_sub(q, a);
    return sgn(p3_dot(p3_cross(u, v), p3_cross(u, w)));
}

// `(n.(q - a))^2 - r^2 |n|^2`.
fn plane_distance(a: P3, b: P3, c: P3, q: P3, r: Scalar) -> i32 {
    let n = p3_cross(p3_sub(b, a), p3_sub(c, a));
    let h = p3_dot(n, p3_sub(q, a));
    return sgn(scalar_sub(scalar_mul(h, h), scalar_mul(scalar_mul(r, r), p3_dot(n, n))));
}

// ---------------------------------------------------------------- the tests

// Closed segment against closed ball (the CPU's `seg_ball`).
fn seg_ball(a: P3, b: P3, c: P3, r: Scalar) -> u32 {
    let before_a = le0(segment_dot(a, b, c));
    if before_a == YES {
        return le0(point_power(a, c, r));
    }
    let near_a = le0(point_power(a, c, r));
    let after_b = le0(segment_dot(b, a, c));
    let near_b = le0(point_power(b, c, r));
    let near_line = le0(line_distance(a, b, c, r));
    return k_ite(before_a, near_a, k_ite(after_b, near_b, near_line));
}

// Closed triangle against closed ball (the CPU's `tri_ball`).
fn tri_ball(t: array<P3, 3>, c: P3, r: Scalar) -> u32 {
    let n = p3_cross(p3_sub(t[1], t[0]), p3_sub(t[2], t[0]));
    if sgn(n.x) == 0 && sgn(n.y) == 0 && sgn(n.z) == 0 {
        // Possibly degenerate: the CPU treats it as a segment.
        return UNKNOWN;
    }
    let inside = k_and(
        k_and(ge0(edge_side(t[0], t[1], t[2], c)), ge0(edge_side(t[1], t[2], t[0], c))),
        ge0(edge_side(t[2], t[0], t[1], c)),
    );
    var foot = UNKNOWN;
    var edges = UNKNOWN;
    if inside != NO {
        foot = le0(plane_distance(t[0], t[1], t[2], c, r));
    }
    if inside != YES {
        edges = k_or(k_or(seg_ball(t[0], t[1], c, r), seg_ball(t[1], t[2], c, r)), seg_ball(t[2], t[0], c, r));
    }
    return k_ite(inside, foot, edges);
}

fn seg_sphere(a: P3, b: P3, c: P3, r: Scalar) -> u32 {
    let reaches = k_or(ge0(point_power(a, c, r)), ge0(point_power(b, c, r)));
    if reaches == NO {
        return NO;
    }
    return k_and(reaches, seg_ball(a, b, c, r));
}

fn tri_sphere(t: array<P3, 3>, c: P3, r: Scalar) -> u32 {
    let reaches = k_or(k_or(ge0(point_power(t[0], c, r)), ge0(point_power(t[1], c, r))), ge0(point_power(t[2], c, r)));
    if reaches == NO {
        return NO;
    }
    return k_and(reaches, tri_ball(t, c, r));
}

// Segment against triangle (the CPU's `seg_tri`, proper-crossing branch).
fn seg_tri(a: P3, b: P3, t: array<P3, 3>) -> u32 {
    let pl = plane(t[0], t[1], t[2]);
    let sa = side(pl, a);
    let sb = side(pl, b);
    if sa != 0 && sa == sb {
        return NO;
    }
    if sa == 0 || sb == 0 {
        return UNKNOWN;
    }
    let o1 = orient3d(a, b, t[0], t[1]);
    let o2 = orient3d(a, b, t[1], t[2]);
    let o3 = orient3d(a, b, t[2], t[0]);
    let pos = o1 > 0 || o2 > 0 || o3 > 0;
    let neg = o1 < 0 || o2 < 0 || o3 < 0;
    if pos && neg {
        return NO;
    }
    if o1 != 0 && o2 != 0 && o3 != 0 {
        return YES;
    }
    return UNKNOWN;
}

fn strictly_one_side(s: array<i32, 3>) -> bool {
    return s[0] != 0 && s[0] == s[1] && s[0] == s[2];
}

// Index of the vertex alone on its side (all three signs nonzero, not all equal).
fn alone(s: array<i32, 3>) -> u32 {
    if s[1] == s[2] {
        return 0u;
    }
    if s[0] == s[2] {
        return 1u;
    }
    return 2u;
}

// Triangle against triangle (the CPU's `tri_tri`: plane sides, then Guigue-Devillers).
fn tri_tri(p: array<P3, 3>, q: array<P3, 3>) -> u32 {
    let pl1 = plane(p[0], p[1], p[2]);
    let dq = array<i32, 3>(side(pl1, q[0]), side(pl1, q[1]), side(pl1, q[2]));
    if strictly_one_side(dq) {
        return NO;
    }
    let pl2 = plane(q[0], q[1], q[2]);
    let dp = array<i32, 3>(side(pl2, p[0]), side(pl2, p[1]), side(pl2, p[2]));
    if strictly_one_side(dp) {
        return NO;
    }
    if dq[0] == 0 || dq[1] == 0 || dq[2] == 0 || dp[0] == 0 || dp[1] == 0 || dp[2] == 0 {
        return UNKNOWN;
    }
    let i = alone(dp);
    let j = alone(dq);
    var a = array<P3, 3>(p[i], p[(i + 1u) % 3u], p[(i + 2u) % 3u]);
    var b = array<P3, 3>(q[j], q[(j + 1u) % 3u], q[(j + 2u) % 3u]);
    if dp[i] < 0 {
        let s = b[1];
        b[1] = b[2];
        b[2] = s;
    }
    if dq[j] < 0 {
        let s = a[1];
        a[1] = a[2];
        a[2] = s;
    }
    let o1 = orient3d(a[0], a[1], b[0], b[1]);
    if o1 > 0 {
        return NO;
    }
    let o2 = orient3d(a[0], a[2], b[2], b[0]);
    if o2 > 0 {
        return NO;
    }
    if o1 < 0 && o2 < 0 {
        return YES;
    }
    return UNKNOWN;
}

// ---------------------------------------------------------------- the batch

struct Params {
    // 0 segment, 1 triangle, 2 sphere, 3 ball.
    kind: u32,
    // 0: every query against every triangle; 1: the listed pairs.
    mode: u32,
    n_queries: u32,
    n_items: u32,
    capacity: u32,
    // Threads per row of the 2D dispatch.
    width: u32,
    first_query: u32,
    last_query: u32,
}

@group(0) @binding(0) var<uniform> params: Params;
// 12 numbers a query: segment `a b`, triangle `p q r`, sphere / ball `c r`.
@group(0) @binding(1) var<storage, read> queries: array<F>;
// 9 numbers a triangle.
@group(0) @binding(2) var<storage, read> triangles: array<F>;
// `(query, triangle)` pairs for mode 1.
@group(0) @binding(3) var<storage, read> pairs: array<u32>;
// Number of hits and of flagged pairs.
@group(0) @binding(4) var<storage, read_write> counts: array<atomic<u32>, 2>;
@group(0) @binding(5) var<storage, read_write> hits: array<u32>;
@group(0) @binding(6) var<storage, read_write> flagged: array<u32>;

fn load_point(buf_is_query: bool, base: u32) -> P3 {
    if buf_is_query {
        return P3(input(queries[base]), input(queries[base + 1u]), input(queries[base + 2u]));
    }
    return P3(input(triangles[base]), input(triangles[base + 1u]), input(triangles[base + 2u]));
}

fn test_pair(qi: u32, tj: u32) -> u32 {
    let qb = 12u * qi;
    let tb = 9u * tj;
    let t = array<P3, 3>(load_point(false, tb), load_point(false, tb + 3u), load_point(false, tb + 6u));
    switch params.kind {
        case 0u: {
            return seg_tri(load_point(true, qb), load_point(true, qb + 3u), t);
        }
        case 1u: {
            let p = array<P3, 3>(load_point(true, qb), load_point(true, qb + 3u), load_point(true, qb + 6u));
            return tri_tri(p, t);
        }
        case 2u: {
            return tri_sphere(t, load_point(true, qb), input(queries[qb + 3u]));
        }
        default: {
            return tri_ball(t, load_point(true, qb), input(queries[qb + 3u]));
        }
    }
}

fn record(qi: u32, tj: u32, answer: u32) {
    if answer == YES {
        let k = atomicAdd(&counts[0], 1u);
        if k < params.capacity {
            hits[2u * k] = qi;
            hits[2u * k + 1u] = tj;
        }
    } else if answer == UNKNOWN {
        let k = atomicAdd(&counts[1], 1u);
        if k < params.capacity {
            flagged[2u * k] = qi;
            flagged[2u * k + 1u] = tj;
        }
    }
}

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let t = id.x + id.y * params.width;
    if t >= params.n_items {
        return;
    }
    if params.mode == 1u {
        let qi = pairs[2u * t];
        let tj = pairs[2u * t + 1u];
        record(qi, tj, test_pair(qi, tj));
        return;
    }
    for (var qi = params.first_query; qi < params.last_query; qi++) {
        record(qi, t, test_pair(qi, t));
    }
}
