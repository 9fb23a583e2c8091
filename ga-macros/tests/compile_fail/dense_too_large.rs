// Past six generators a dense type would have 4^n-term products: declaring one is an error.
ga_macros::algebra! {
    name: big,
    signature: [+1, +1, +1, +1, +1, +1, -1, -1],
    types: { Vector: grade 1 },
    dense: Multivector,
}

fn main() {}
