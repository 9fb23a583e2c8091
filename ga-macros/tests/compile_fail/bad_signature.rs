ga_macros::algebra! {
    name: odd,
    signature: [+1, 2, -1],
    types: { Vector: grade 1 },
}

mod other {
    ga_macros::algebra! {
        name: huge,
        signature: [+1, +1, +1, +1, +1, +1, +1, +1, +1, +1, +1],
        types: { Vector: grade 1 },
    }
}

fn main() {}
