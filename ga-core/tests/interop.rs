//! The optional interop features: run with `--features glam,mint,serde,bytemuck` (or
//! `--all-features`).

#[cfg(feature = "glam")]
mod glam_conversions {
    use ga_core::cga::{self, Even, Rotor};
    use ga_core::interop::glam::{down_dvec3, up_dvec3, up_vec3};
    use ga_core::interop::InteropError;
    use ga_core::prelude::*;
    use ga_core::vga3;
    use glam::{DAffine3, DMat3, DQuat, DVec3, Vec3};
    use proptest::prelude::*;

    fn quat(axis: [f64; 3], angle: f64) -> DQuat {
        let a = DVec3::from_array(axis);
        DQuat::from_axis_angle(a.normalize(), angle)
    }

    proptest! {
        #[test]
        fn points_round_trip(p in prop::array::uniform3(-1e6f64..1e6)) {
            let p = DVec3::from_array(p);
            let back = down_dvec3(&up_dvec3(p)).unwrap();
            prop_assert!((back - p).length() <= 1e-15 * p.length().max(1.0));
            let v: vga3::Vector<f64> = p.into();
            prop_assert_eq!(DVec3::from(v), p);
        }

        #[test]
        fn quaternions_rotate_like_rotors(axis in prop::array::uniform3(-1.0f64..1.0), angle in -6.0f64..6.0, p in prop::array::uniform3(-10.0f64..10.0)) {
            prop_assume!(DVec3::from_array(axis).length() > 1e-3);
            let q = quat(axis, angle);
            let p = DVec3::from_array(p);
            let expected = q.mul_vec3(p);
            // vga3 rotor.
            let r = vga3::Rotor::from(q);
            let v = r.sandwich_unit(&vga3::Vector::from(p));
            prop_assert!((DVec3::from(v) - expected).length() < 1e-12);
            prop_assert_eq!(DQuat::from(r), q);
            // cga rotor on conformal points.
            let rc = Rotor::from(q);
            let moved = down_dvec3(&rc.sandwich_unit(&up_dvec3(p))).unwrap();
            prop_assert!((moved - expected).length() < 1e-12);
            prop_assert_eq!(DQuat::try_from(rc).unwrap(), q);
        }

        #[test]
        fn rigid_affine_maps_round_trip(axis in prop::array::uniform3(-1.0f64..1.0), angle in -3.0f64..3.0, t in prop::array::uniform3(-100.0f64..100.0), p in prop::array::uniform3(-10.0f64..10.0)) {
            prop_assume!(DVec3::from_array(axis).length() > 1e-3);
            let a = DAffine3::from_rotation_translation(quat(axis, angle), DVec3::from_array(t));
            let m = Even::from_affine(&a).unwrap();
            let p = DVec3::from_array(p);
            let moved = down_dvec3(&m.sandwich_unit(&up_dvec3(p))).unwrap();
            // The conformal sandwich multiplies motor coefficients ~|t| with ½|p|² terms and
            // cancels down to coordinates ~|t|: rounding grows like (|t| + |p|)³ ε.
            let size = 1.0 + DVec3::from_array(t).length() + p.length();
            prop_assert!((moved - a.transform_point3(p)).length() < 1e-15 * size * size * size);
            let back = m.to_affine().unwrap();
            prop_assert!(back.abs_diff_eq(a, 1e-11));
        }
    }

    #[test]
    fn non_rigid_input_is_a_typed_error() {
        let scaled = DAffine3::from_scale(DVec3::splat(2.0));
        assert!(matches!(
            Even::from_affine(&scaled),
            Err(InteropError::NotARotationMatrix { .. })
        ));
        let mirror = DAffine3::from_mat3(DMat3::from_diagonal(DVec3::new(1.0, 1.0, -1.0)));
        assert!(Even::from_affine(&mirror).is_err());
        let dilator = Even::from(Rotor::dilator(3.0).unwrap());
        assert_eq!(
            dilator.to_affine(),
            Err(InteropError::NotRigid("the motor is not a rigid motion"))
        );
        assert!(Even::<f64>::zero().to_affine().is_err());
        let t = Rotor::translator([1.0, 0.0, 0.0]);
        assert!(matches!(
            DQuat::try_from(t),
            Err(InteropError::NotARotation { blade: "e14", .. })
        ));
        assert_eq!(down_dvec3(&cga::n_inf()), None);
    }

    #[test]
    fn f32_points_widen_exactly() {
        let p = Vec3::new(0.1, -2.5, 1e-7);
        assert_eq!(up_vec3(p), up_dvec3(p.as_dvec3()));
        let v: vga3::Vector<f64> = p.into();
        assert_eq!(v.e1, 0.1f32 as f64);
    }
}

#[cfg(feature = "mint")]
mod mint_conversions {
    use ga_core::cga::Rotor;
    use ga_core::interop::mint::{down_point, up_point};
    use ga_core::prelude::*;
    use ga_core::vga3;

    #[test]
    fn mint_round_trips() {
        let p = mint::Point3 {
            x: 1.5,
            y: -2.0,
            z: 0.25,
        };
        assert_eq!(down_point(&up_point(p)), Some(p));
        let v = mint::Vector3 {
            x: 1.0,
            y: 2.0,
            z: 3.0,
        };
        let gv: vga3::Vector<f64> = v.into();
        assert_eq!(mint::Vector3::from(gv), v);
        // A quarter turn about z: (x, y, z, w) = (0, 0, sin 45°, cos 45°) turns e1 into e2.
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let q = mint::Quaternion {
            v: mint::Vector3 {
                x: 0.0,
                y: 0.0,
                z: h,
            },
            s: h,
        };
        let r = vga3::Rotor::from(q);
        let turned = r.sandwich_unit(&vga3::Vector::new(1.0, 0.0, 0.0));
        assert!((turned.e2 - 1.0).abs() < 1e-15 && turned.e1.abs() < 1e-15);
        assert_eq!(mint::Quaternion::from(r), q);
        let rc = Rotor::from(q);
        assert_eq!(mint::Quaternion::try_from(rc).unwrap(), q);
        assert!(mint::Quaternion::try_from(Rotor::translator([0.0, 1.0, 0.0])).is_err());
    }
}

#[cfg(feature = "bytemuck")]
mod bytemuck_casts {
    use ga_core::cga::{Even, Multivector, Vector};
    use ga_core::{pga3, vga3};

    #[test]
    fn layouts_are_the_coefficients_in_canonical_order() {
        assert_eq!(std::mem::size_of::<Multivector<f64>>(), 32 * 8);
        assert_eq!(
            std::mem::align_of::<Even<f32>>(),
            std::mem::align_of::<f32>()
        );
        let coeffs: [f64; 32] = std::array::from_fn(|i| i as f64);
        let m = Multivector::from_coefficients(coeffs);
        let bytes: &[u8] = bytemuck::bytes_of(&m);
        let back: Multivector<f64> = bytemuck::pod_read_unaligned(bytes);
        assert_eq!(back, m);
        assert_eq!(bytemuck::cast::<Multivector<f64>, [f64; 32]>(m), coeffs);
        let vs = vec![Vector::new(1.0, 2.0, 3.0, 4.0, 5.0); 3];
        let flat: &[f64] = bytemuck::cast_slice(&vs);
        assert_eq!(flat.len(), 15);
        assert_eq!(flat[5..10], [1.0, 2.0, 3.0, 4.0, 5.0]);
        let z: pga3::Motor<f32> = bytemuck::Zeroable::zeroed();
        assert_eq!(z, pga3::Motor::zero());
        let r = vga3::Rotor::new(1.0f32, 2.0, 3.0, 4.0);
        assert_eq!(bytemuck::cast::<_, [f32; 4]>(r), [1.0, 2.0, 3.0, 4.0]);
        // A misaligned or wrongly sized byte slice is an error, not a panic.
        let raw = [0u8; 12];
        assert!(bytemuck::try_cast_slice::<u8, Vector<f64>>(&raw).is_err());
    }
}

#[cfg(feature = "serde")]
mod serde_round_trips {
    use ga_core::cga::{Bivector, Even, Vector};

    #[test]
    fn json_uses_blade_names() {
        let v = Vector::new(1.0, 2.0, 3.0, 4.0, 5.0);
        let json = serde_json::to_string(&v).unwrap();
        assert_eq!(json, r#"{"e1":1.0,"e2":2.0,"e3":3.0,"e4":4.0,"e5":5.0}"#);
        assert_eq!(serde_json::from_str::<Vector<f64>>(&json).unwrap(), v);
        let b = Bivector::<f64>::zero();
        let e: Even<f64> = b.exp();
        let back: Even<f64> = serde_json::from_str(&serde_json::to_string(&e).unwrap()).unwrap();
        assert_eq!(back, e);
        // A missing blade is an error.
        assert!(serde_json::from_str::<Vector<f64>>(r#"{"e1":1.0}"#).is_err());
    }
}
