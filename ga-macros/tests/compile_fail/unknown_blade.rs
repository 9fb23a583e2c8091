ga_macros::algebra! {
    name: space,
    signature: [+1, +1, +1],
    types: { Rotor: [1, e21, e13] },
}

mod other {
    ga_macros::algebra! {
        name: space,
        signature: [+1, +1, +1],
        types: { Weird: [1, f7] },
    }
}

fn main() {}
