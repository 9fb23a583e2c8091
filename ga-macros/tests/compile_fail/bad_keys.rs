ga_macros::algebra! {
    name: plane,
    signatur: [+1, +1],
    types: { Vector: grade 1 },
}

mod missing {
    ga_macros::algebra! {
        name: plane,
        types: { Vector: grade 1 },
    }
}

fn main() {}
