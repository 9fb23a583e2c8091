// Key-level mistakes are all reported too: a key given twice, an unknown key, a bad signature
// entry and the missing `types`.
ga_macros::algebra! {
    name: keys,
    name: again,
    signature: [+1, +2, -1],
    flavour: strange,
}

fn main() {}
