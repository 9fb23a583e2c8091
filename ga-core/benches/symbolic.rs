//! Symbolic expansion speed: the sphere S = P1∧P2∧P3∧P4 through four points `2·up(x)` over
//! `Poly` with the generated typed products, the generated dense multivector, and (baseline) the
//! independent bitmask products of the dense reference (`reference::DenseMultivector`); and one
//! large polynomial product.
//!
//! `cargo bench -p ga-core --bench symbolic -- --warm-up-time 1 --measurement-time 3`

use criterion::{criterion_group, criterion_main, Criterion};
use ga_core::cga::{Multivector, Vector};
use ga_core::prelude::*;
use ga_core::reference::{DenseMultivector, Signature};
use ga_core::symbolic::Poly;
use std::hint::black_box;

fn coords(l: &str) -> [Poly; 3] {
    [1, 2, 3].map(|i| Poly::var(&format!("{l}{i}")))
}

/// `2·up(x) = 2x + x² n_inf − 2 n_0`, with `n_inf = e4 + e5` and `2 n_0 = e5 − e4`.
fn point(l: &str) -> Vector<Poly> {
    let [a, b, c] = coords(l);
    let sq = &(&(&a * &a) + &(&b * &b)) + &(&c * &c);
    let (one, two) = (Poly::from(1), Poly::from(2));
    Vector::new(&two * &a, &two * &b, &two * &c, &sq - &one, &sq + &one)
}

fn bench(c: &mut Criterion) {
    let [a, b, cc, d] = ["a", "b", "c", "d"].map(point);
    let mut g = c.benchmark_group("sphere P1^P2^P3^P4 over Poly");
    g.bench_function("generated typed (Vector^Vector^...)", |bn| {
        bn.iter(|| black_box(a.wedge(&b).wedge(&cc).wedge(&d)))
    });
    let dense: Vec<Multivector<Poly>> = [&a, &b, &cc, &d]
        .iter()
        .map(|v| Multivector::from((*v).clone()))
        .collect();
    g.bench_function("generated dense Multivector", |bn| {
        bn.iter(|| black_box(dense[0].wedge(&dense[1]).wedge(&dense[2]).wedge(&dense[3])))
    });
    let cl41 = Signature::new(&[1, 1, 1, 1, -1]).expect("Cl(4,1)");
    let reference: Vec<DenseMultivector<Poly>> = dense
        .iter()
        .map(|m| {
            DenseMultivector::from_canonical(&cl41, m.coefficients().to_vec())
                .expect("32 coefficients")
        })
        .collect();
    g.bench_function(
        "baseline: reference DenseMultivector bitmask products",
        |bn| {
            bn.iter(|| {
                black_box(
                    reference[0]
                        .wedge(&reference[1])
                        .wedge(&reference[2])
                        .wedge(&reference[3]),
                )
            })
        },
    );
    g.finish();

    let s = a.wedge(&b).wedge(&cc).wedge(&d);
    let (p, q) = (s.e1234.clone(), s.e1235.clone());
    c.bench_function(
        &format!("Poly product ({} × {} terms)", p.num_terms(), q.num_terms()),
        |bn| bn.iter(|| black_box(&p * &q)),
    );
}

criterion_group!(benches, bench);
criterion_main!(benches);
