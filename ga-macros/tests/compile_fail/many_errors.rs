// One declaration with several mistakes: every one is reported, each at its own token.
ga_macros::algebra! {
    name: many,
    signature: [+1, +1, +1],
    types: {
        Vector: grade 1,
        Vector: grade 2,
        Odd: grades 1 3 7,
        Listed: [1, e21, e12, e12],
        Nothing: grades,
    },
    colour: blue,
}

fn main() {}
