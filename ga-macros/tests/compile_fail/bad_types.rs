ga_macros::algebra! {
    name: plane,
    signature: [+1, +1],
    types: { Vector: grade 1, Vector: grade 2 },
}

mod grade_too_high {
    ga_macros::algebra! {
        name: plane,
        signature: [+1, +1],
        types: { Vector: grade 3 },
    }
}

mod basis_mismatch {
    ga_macros::algebra! {
        name: plane,
        signature: [+1, +1],
        basis: [x, y, z],
        types: { Vector: grade 1 },
    }
}

fn main() {}
