ga_macros::algebra! {
    name: plane,
    signature: [+1, +1],
    types: { Rotor: [1, e12, e12] },
}

fn main() {}
