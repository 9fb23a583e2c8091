ga_macros::algebra! {
    name: plane,
    signature: [+1, +1],
    types: { Nothing: [] },
}

mod other {
    ga_macros::algebra! {
        name: plane,
        signature: [+1, +1],
        types: { Vector: grades },
    }
}

fn main() {}
