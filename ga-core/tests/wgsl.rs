//! The generated WGSL (`cga::wgsl`) parses and validates with naga, with no device: the `f32`
//! and `f64` sources, and the ring source with a struct scalar carrying an error bound.

use ga_core::cga::wgsl;
use naga::valid::{Capabilities, ValidationFlags, Validator};

/// Parses and validates `src`, panicking with naga's readable report.
fn validate(src: &str, caps: Capabilities) -> naga::Module {
    let module = naga::front::wgsl::parse_str(src)
        .unwrap_or_else(|e| panic!("WGSL does not parse:\n{}", e.emit_to_string(src)));
    Validator::new(ValidationFlags::all(), caps)
        .validate(&module)
        .unwrap_or_else(|e| panic!("WGSL does not validate:\n{}", e.emit_to_string(src)));
    module
}

/// Every function of the table is in the module with the table's parameter count, and nothing
/// else is.
fn check_table(module: &naga::Module) {
    let names: Vec<&str> = module
        .functions
        .iter()
        .filter_map(|(_, f)| f.name.as_deref())
        .filter(|n| !n.starts_with("scalar_"))
        .collect();
    assert_eq!(names.len(), wgsl::FUNCTIONS.len());
    for f in wgsl::FUNCTIONS {
        let (_, func) = module
            .functions
            .iter()
            .find(|(_, g)| g.name.as_deref() == Some(f.name))
            .unwrap_or_else(|| panic!("{} is in the table but not in the source", f.name));
        assert_eq!(func.arguments.len(), f.inputs.len(), "{}", f.name);
        assert_eq!(
            f.output.fields.len(),
            if f.output.ty == "Scalar" {
                0
            } else {
                f.output.blades.len()
            }
        );
    }
}

#[test]
fn f32_source_validates() {
    let module = validate(wgsl::F32, Capabilities::empty());
    check_table(&module);
    assert_eq!(wgsl::SOURCE, wgsl::F32);
}

#[test]
fn f64_source_needs_and_validates_with_float64() {
    let module = validate(wgsl::F64, Capabilities::FLOAT64);
    check_table(&module);
    let plain = naga::front::wgsl::parse_str(wgsl::F64).expect("parses");
    assert!(
        Validator::new(ValidationFlags::all(), Capabilities::empty())
            .validate(&plain)
            .is_err(),
        "f64 must be rejected without the FLOAT64 capability"
    );
}

#[test]
fn ring_source_validates_over_a_struct_scalar() {
    let prelude = r"
        struct Scalar { v: f32, e: f32 }
        fn scalar_add(a: Scalar, b: Scalar) -> Scalar { let v = a.v + b.v; return Scalar(v, a.e + b.e + abs(v)); }
        fn scalar_sub(a: Scalar, b: Scalar) -> Scalar { let v = a.v - b.v; return Scalar(v, a.e + b.e + abs(v)); }
        fn scalar_mul(a: Scalar, b: Scalar) -> Scalar { let v = a.v * b.v; return Scalar(v, abs(v)); }
        fn scalar_neg(a: Scalar) -> Scalar { return Scalar(-a.v, a.e); }
        fn scalar_zero() -> Scalar { return Scalar(0.0, 0.0); }
    ";
    let module = validate(&format!("{prelude}\n{}", wgsl::RING), Capabilities::empty());
    check_table(&module);
}

#[test]
fn the_table_covers_the_conformal_products_the_gpu_code_uses() {
    let has = |name: &str| wgsl::FUNCTIONS.iter().any(|f| f.name == name);
    assert!(has("Vector_scalar_product_Vector"));
    assert!(has("Vector_wedge_Vector"));
    assert!(has("Quadvector_wedge_Vector"));
    assert!(has("Vector_add_Vector") && has("Vector_scale") && has("Bivector_reverse"));
    // Vector * Vector is a rotor (grades 0 and 2), not a listed type: not emitted.
    assert!(!has("Vector_geometric_Vector"));
    // The scalar product returns the bare scalar.
    let sp = wgsl::FUNCTIONS
        .iter()
        .find(|f| f.name == "Vector_scalar_product_Vector")
        .expect("listed");
    assert_eq!(sp.output.ty, "Scalar");
    assert_eq!(sp.inputs[0].blades, &[1, 2, 3, 4, 5]);
}
