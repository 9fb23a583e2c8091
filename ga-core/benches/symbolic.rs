//! Symbolic expansion speed: the thesis's sphere S = P1∧P2∧P3∧P4 over `Poly` with the generated
//! typed products, the generated dense multivector, and (baseline) the independent bitmask
//! products of `SymMultivector`; and one large polynomial product.
//!
//! `cargo bench -p ga-core --bench symbolic -- --warm-up-time 1 --measurement-time 3`

use criterion::{criterion_group, criterion_main, Criterion};
use ga_core::cga::{Multivector, Vector};
use ga_core::prelude::*;
use ga_core::symbolic::thesis::SymMultivector;
use ga_core::symbolic::Poly;
use std::hint::black_box;

fn coords(l: &str) -> [Poly; 3] {
    [1, 2, 3].map(|i| Poly::var(&format!("{l}{i}")))
}

fn point(l: &str) -> Vector<Poly> {
    let p = SymMultivector::thesis_point(coords(l));
    Vector::new(p.get(1), p.get(2), p.get(4), p.get(8), p.get(16))
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
    let sym: Vec<SymMultivector> = dense.iter().map(SymMultivector::from).collect();
    g.bench_function("baseline: SymMultivector bitmask products", |bn| {
        bn.iter(|| black_box(sym[0].wedge(&sym[1]).wedge(&sym[2]).wedge(&sym[3])))
    });
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
