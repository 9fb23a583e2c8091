//! Arrays in and out: whatever numpy reads as numbers that float64 holds exactly (never a
//! rounding cast), checked shapes, poses from `(4, 4)` homogeneous matrices, and the errors
//! that say which argument was wrong and how.

use cga_collide::collider::{pose_from_degrees, pose_from_matrix, PosePair};
use cga_collide::nalgebra::{Isometry3, Matrix3, Point3};
use cga_collide::Error;
use numpy::ndarray::{Array1, Array2, ArrayViewD, Dimension};
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyArrayDescr, PyArrayDescrMethods, PyArrayDyn, PyArrayMethods,
    PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::IntoPyDict;

pyo3::create_exception!(
    cga_collide,
    CgaError,
    PyValueError,
    "An input the library refused (a mesh, a file, a pose, a batch item, a scene handle): the message says what was wrong and where. A subclass of ValueError."
);

/// A Python argument, read by the helpers of this module.
pub type Arg<'py> = Bound<'py, PyAny>;
/// A `(k,)` bool array.
pub type Bools<'py> = Bound<'py, PyArray1<bool>>;
/// A `(p, 2)` int64 array of index pairs.
pub type Pairs<'py> = Bound<'py, PyArray2<i64>>;
/// A `(p,)` int64 array of indices.
pub type Indices<'py> = Bound<'py, PyArray1<i64>>;

/// The Python exception for a library error: a `CgaError` whose message is the error's text.
pub fn err(e: Error) -> PyErr {
    CgaError::new_err(e.to_string())
}

/// A `CgaError` with a message.
pub fn value_error(message: String) -> PyErr {
    CgaError::new_err(message)
}

/// How far the rotation part of a pose may be from a rotation: `max |RᵀR − I|`, the library's
/// rule for poses given as matrices (`cga scene`'s 12-number lines use it too). The library's
/// own check on quaternions accepts `|q|²` in `[1/2, 2]` and normalises; a matrix this far from
/// orthonormal is a mistake (a scale, a shear), not rounding.
pub const ROTATION_TOLERANCE: f64 = cga_collide::collider::ROTATION_TOLERANCE;

/// Python's name of an object's type, for error messages.
fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "an object".to_owned())
}

fn dtype_name(dtype: &Bound<'_, PyArrayDescr>) -> String {
    dtype.str().map(|s| s.to_string()).unwrap_or_else(|_| "another dtype".to_owned())
}

/// `obj` as a numpy array: itself if it is one, else `numpy.asarray(obj)` (lists, tuples,
/// scalars, anything with `__array__`), without choosing a dtype.
fn ndarray<'py>(obj: &Bound<'py, PyAny>, name: &str) -> PyResult<Bound<'py, PyUntypedArray>> {
    if let Ok(a) = obj.cast::<PyUntypedArray>() {
        return Ok(a.clone());
    }
    let a = obj.py().import("numpy")?.call_method1("asarray", (obj,)).map_err(|e| {
        value_error(format!(
            "{name}: expected an array of numbers, got {} that numpy cannot read as one ({e})",
            type_name(obj)
        ))
    })?;
    Ok(a.cast::<PyUntypedArray>()?.clone())
}

/// Integers beyond this magnitude have no exact float64 in general (2^53).
const EXACT_INTEGER: u64 = 1 << 53;

/// The first entry of an integer array of 8-byte items beyond 2^53 in magnitude, as
/// `"[index] = value"`.
fn inexact_integer(a: &Bound<'_, PyUntypedArray>, unsigned: bool) -> PyResult<Option<String>> {
    fn first<T: numpy::Element + Copy + std::fmt::Display>(
        a: &Bound<'_, PyUntypedArray>, beyond: impl Fn(T) -> bool,
    ) -> PyResult<Option<String>> {
        let a = a.cast::<PyArrayDyn<T>>()?.readonly();
        let view = a.as_array();
        let found = view.indexed_iter().find(|(_, &v)| beyond(v));
        Ok(found.map(|(i, v)| format!("{:?} = {v}", i.slice())))
    }
    if unsigned {
        first(a, |v: u64| v > EXACT_INTEGER)
    } else {
        first(a, |v: i64| v.unsigned_abs() > EXACT_INTEGER)
    }
}

/// An array argument as float64, exactly: a numpy array of float64 as it is (any memory
/// layout), and anything else numpy reads as numbers that float64 holds exactly (lists,
/// tuples, Python and numpy integers up to 2^53, float16, float32) converted. Everything
/// else is a `CgaError` naming the argument: booleans (a mask is not coordinates), complex
/// numbers, objects, strings, integers beyond 2^53 and wider floats that float64 would round.
pub fn f64_array<'py>(
    obj: &Bound<'py, PyAny>, name: &str,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let a = ndarray(obj, name)?;
    let dtype = a.dtype();
    if dtype.is_equiv_to(&numpy::dtype::<f64>(obj.py())) {
        return Ok(a.cast::<PyArrayDyn<f64>>()?.clone());
    }
    let refuse = |why: String| {
        value_error(format!(
            "{name}: expected numbers that float64 holds exactly, got dtype {}: {why}",
            dtype_name(&dtype)
        ))
    };
    let (kind, wide) = (dtype.kind(), dtype.itemsize() > 4);
    match kind {
        b'f' | b'i' | b'u' => {}
        b'b' => return Err(refuse("booleans are not taken for numbers".to_owned())),
        b'c' => return Err(refuse("complex numbers have no float64 value".to_owned())),
        _ => return Err(refuse("not an array of real numbers".to_owned())),
    }
    if matches!(kind, b'i' | b'u') && wide {
        if let Some(at) = inexact_integer(&a, kind == b'u')? {
            return Err(refuse(format!("entry {at} is beyond 2^53, where float64 would round it")));
        }
    }
    let converted = a.call_method1("astype", ("float64",))?;
    if kind == b'f' && dtype.itemsize() > 8 {
        // long double: exact only if converting back gives every value again.
        let back = converted.call_method1("astype", (&dtype,))?;
        let numpy = obj.py().import("numpy")?;
        let same = numpy
            .call_method(
                "array_equal",
                (&back, &a),
                Some(&[("equal_nan", true)].into_py_dict(obj.py())?),
            )?
            .is_truthy()?;
        if !same {
            return Err(refuse("float64 would round some values".to_owned()));
        }
    }
    Ok(converted.cast::<PyArrayDyn<f64>>()?.clone())
}

/// Reads an array argument of the given shape (see [`f64_array`] and [`check_shape`]).
pub fn read<T>(
    obj: &Bound<'_, PyAny>, name: &str, shape: &[Option<usize>],
    f: impl FnOnce(ArrayViewD<'_, f64>) -> PyResult<T>,
) -> PyResult<T> {
    let a = f64_array(obj, name)?;
    let r = a.readonly();
    let v = r.as_array();
    check_shape(v.shape(), shape, name)?;
    f(v)
}

/// Checks the shape of an array against a pattern (`None` = any length).
pub fn check_shape(shape: &[usize], want: &[Option<usize>], name: &str) -> PyResult<()> {
    let ok =
        shape.len() == want.len() && shape.iter().zip(want).all(|(s, w)| w.is_none_or(|w| *s == w));
    if ok {
        return Ok(());
    }
    let pattern: Vec<String> = want
        .iter()
        .zip(["k", "n", "m"].iter().cycle())
        .map(|(w, k)| w.map_or_else(|| (*k).to_owned(), |w| w.to_string()))
        .collect();
    Err(value_error(format!(
        "{name}: expected an array of shape ({}), got shape {:?}",
        pattern.join(", "),
        shape
    )))
}

/// The vertices of a mesh: an `(n, 3)` array (the mesh checks them: its errors name the
/// vertex).
pub fn vertices(obj: &Bound<'_, PyAny>) -> PyResult<Vec<Point3<f64>>> {
    points(obj, "vertices")
}

/// Points from an `(n, 3)` array; `name` says which argument in errors.
pub fn points(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<Point3<f64>>> {
    read(obj, name, &[None, Some(3)], |v| {
        Ok(v.outer_iter().map(|row| Point3::new(row[0], row[1], row[2])).collect())
    })
}

/// The faces of a mesh: an `(m, 3)` array of integers (any integer dtype, or a list of
/// them), each index checked.
pub fn faces(obj: &Bound<'_, PyAny>, vertex_count: usize) -> PyResult<Vec<[u32; 3]>> {
    let untyped = ndarray(obj, "faces")?;
    let dtype = untyped.dtype();
    let kind = dtype.kind();
    if kind != b'i' && kind != b'u' {
        return Err(value_error(format!(
            "faces: expected integers, got dtype {} (vertex indices are never cast from other numbers)",
            dtype_name(&dtype)
        )));
    }
    check_shape(untyped.shape(), &[None, Some(3)], "faces")?;
    // Integers to int64 is exact for every integer dtype but uint64 above 2^63, which is out of
    // range anyway: refuse it rather than wrap.
    if kind == b'u' && dtype.itemsize() == 8 {
        let as_u64 = untyped.cast::<numpy::PyArray2<u64>>()?.readonly();
        if let Some((f, &i)) = as_u64
            .as_array()
            .indexed_iter()
            .find(|(_, &i)| i >= vertex_count as u64)
            .map(|((f, _), i)| (f, i))
        {
            return Err(bad_index(f, i as i128, vertex_count));
        }
        return Ok(as_u64
            .as_array()
            .outer_iter()
            .map(|r| [r[0] as u32, r[1] as u32, r[2] as u32])
            .collect());
    }
    let converted = untyped.call_method1("astype", ("int64",))?;
    let a = converted.cast::<numpy::PyArray2<i64>>()?.readonly();
    let view = a.as_array();
    let mut out = Vec::with_capacity(view.nrows());
    for (f, row) in view.outer_iter().enumerate() {
        let mut t = [0u32; 3];
        for (k, &i) in row.iter().enumerate() {
            if i < 0 || i as u64 >= vertex_count as u64 {
                return Err(bad_index(f, i as i128, vertex_count));
            }
            t[k] = i as u32;
        }
        out.push(t);
    }
    Ok(out)
}

fn bad_index(face: usize, index: i128, vertex_count: usize) -> PyErr {
    value_error(format!(
        "faces: face {face}: vertex index {index} out of range (the mesh has {vertex_count} vertices; indices are 0-based)"
    ))
}

/// Three numbers from a `(3,)` array, as given: the library's constructors check them and
/// name the argument (a shape's point or vector, whose range rule is the library's).
pub fn triple(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<[f64; 3]> {
    read(obj, name, &[Some(3)], |v| Ok([v[0], v[1], v[2]]))
}

/// Rows of three numbers from an `(n, 3)` array (`n` given or any), as given.
pub fn triples(obj: &Bound<'_, PyAny>, name: &str, n: Option<usize>) -> PyResult<Vec<[f64; 3]>> {
    read(obj, name, &[n, Some(3)], |v| Ok(v.outer_iter().map(|r| [r[0], r[1], r[2]]).collect()))
}

/// One number (a Python or numpy number, or a 0-d array) that float64 holds exactly, as
/// given: the library's constructors check it (a radius: finite, at least 0).
pub fn number(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<f64> {
    let a = f64_array(obj, name)?;
    let r = a.readonly();
    let v = r.as_array();
    if v.ndim() != 0 {
        return Err(value_error(format!(
            "{name}: expected a number, got an array of shape {:?}",
            v.shape()
        )));
    }
    Ok(v.iter().next().copied().unwrap_or(f64::NAN))
}

/// A point: a `(3,)` array of finite numbers (a NaN point answers no question).
pub fn point(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Point3<f64>> {
    read(obj, name, &[Some(3)], |v| {
        if let Some((i, x)) = v.iter().enumerate().find(|(_, x)| !x.is_finite()) {
            return Err(value_error(format!("{name}: coordinate {i} is not finite ({x})")));
        }
        Ok(Point3::new(v[0], v[1], v[2]))
    })
}

/// A tolerance of the motion queries: a width of time, finite and at least 0 (`0.0` asks for
/// the narrowest interval float64 allows).
pub fn tolerance(t: f64, name: &str) -> PyResult<f64> {
    if t.is_finite() && t >= 0.0 {
        Ok(t)
    } else {
        Err(value_error(format!(
            "{name}: expected a finite width of time, at least 0 (0.0 for the narrowest), got {t}"
        )))
    }
}

/// A distance to compare with: any number but NaN (a negative one is never reached, an
/// infinite one always).
pub fn distance_bound(c: f64, name: &str) -> PyResult<f64> {
    if c.is_nan() {
        Err(value_error(format!("{name}: expected a distance, got NaN")))
    } else {
        Ok(c)
    }
}

/// One pose from a `(4, 4)` view; `name` says where it came from in errors.
fn pose_of(m: &ArrayViewD<'_, f64>, name: &str) -> PyResult<Isometry3<f64>> {
    for ((i, j), &x) in
        (0..4).flat_map(|i| (0..4).map(move |j| (i, j))).map(|(i, j)| ((i, j), &m[[i, j]]))
    {
        if !x.is_finite() {
            return Err(value_error(format!(
                "{name}: entry [{i}, {j}] is not finite ({x}); a pose must be a finite rigid motion"
            )));
        }
    }
    if m[[3, 0]] != 0.0 || m[[3, 1]] != 0.0 || m[[3, 2]] != 0.0 || m[[3, 3]] != 1.0 {
        return Err(value_error(format!(
            "{name}: the last row is [{}, {}, {}, {}], not [0, 0, 0, 1]: a pose is a homogeneous rigid motion",
            m[[3, 0]],
            m[[3, 1]],
            m[[3, 2]],
            m[[3, 3]]
        )));
    }
    // The library's one rotation check (the scene files' too); only the message is Python's.
    let r = Matrix3::from_fn(|i, j| m[[i, j]]);
    pose_from_matrix(&r, [m[[0, 3]], m[[1, 3]], m[[2, 3]]]).map_err(|e| match e {
        Error::NotARotation { deviation, determinant } => value_error(format!(
            "{name}: the upper-left 3x3 block is not a rotation (max |RᵀR − I| = {deviation:.3e}, det = {determinant}); \
             a pose is a rotation and a translation, without scale, shear or reflection"
        )),
        other => value_error(format!("{name}: {other}")),
    })
}

/// A pose from a `(4, 4)` homogeneous matrix.
pub fn pose(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Isometry3<f64>> {
    read(obj, name, &[Some(4), Some(4)], |v| pose_of(&v, name))
}

/// An optional pose (`None` is the identity).
pub fn pose_or_identity(obj: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Isometry3<f64>> {
    match obj {
        None => Ok(Isometry3::identity()),
        Some(o) if o.is_none() => Ok(Isometry3::identity()),
        Some(o) => pose(o, name),
    }
}

/// The poses of a `(k, 4, 4)` view, each error naming its index.
fn poses_of(v: &ArrayViewD<'_, f64>, name: &str) -> PyResult<Vec<Isometry3<f64>>> {
    v.outer_iter().enumerate().map(|(k, m)| pose_of(&m, &format!("{name}[{k}]"))).collect()
}

/// Many poses from a `(k, 4, 4)` array.
pub fn poses(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<Isometry3<f64>>> {
    read(obj, name, &[None, Some(4), Some(4)], |v| poses_of(&v, name))
}

/// A motion between two poses: a `(2, 4, 4)` array (the pose at `t = 0`, then at `t = 1`).
pub fn pose_motion(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<[Isometry3<f64>; 2]> {
    read(obj, name, &[Some(2), Some(4), Some(4)], |v| {
        let p = poses_of(&v, name)?;
        Ok([p[0], p[1]])
    })
}

/// The poses of one side of a batch: `Ok` many from `(k, 4, 4)`, `Err` one `(4, 4)` pose
/// for every query.
fn many_or_one(
    obj: &Bound<'_, PyAny>, name: &str,
) -> PyResult<Result<Vec<Isometry3<f64>>, Isometry3<f64>>> {
    let a = f64_array(obj, name)?;
    let r = a.readonly();
    let v = r.as_array();
    if v.ndim() == 2 {
        check_shape(v.shape(), &[Some(4), Some(4)], name)?;
        pose_of(&v, name).map(Err)
    } else {
        check_shape(v.shape(), &[None, Some(4), Some(4)], name)?;
        poses_of(&v, name).map(Ok)
    }
}

/// The pose pairs of a batch: `(k, 4, 4)` arrays of the same length; either may also be one
/// `(4, 4)` pose, used for every query.
pub fn pose_pairs(a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<Vec<PosePair>> {
    let (pa, pb) = (many_or_one(a, "poses_a")?, many_or_one(b, "poses_b")?);
    Ok(match (pa, pb) {
        (Ok(x), Ok(y)) => {
            if x.len() != y.len() {
                return Err(value_error(format!(
                    "poses_a has {} poses and poses_b has {}: give the same number (or one (4, 4) pose for every query)",
                    x.len(),
                    y.len()
                )));
            }
            x.into_iter().zip(y).map(|(a, b)| PosePair::new(a, b)).collect()
        }
        (Ok(x), Err(b)) => x.into_iter().map(|a| PosePair::new(a, b)).collect(),
        (Err(a), Ok(y)) => y.into_iter().map(|b| PosePair::new(a, b)).collect(),
        (Err(a), Err(b)) => vec![PosePair::new(a, b)],
    })
}

/// The pose of [`pose_from_degrees`]: `degrees`
/// and `translation` `(3,)` arrays (the translation `None` for none).
pub fn degrees_pose(
    degrees: &Bound<'_, PyAny>, translation: Option<&Bound<'_, PyAny>>,
) -> PyResult<Isometry3<f64>> {
    let d = point(degrees, "degrees")?;
    let t = match translation {
        Some(t) if !t.is_none() => point(t, "translation")?,
        _ => Point3::origin(),
    };
    Ok(pose_from_degrees([d.x, d.y, d.z], [t.x, t.y, t.z]))
}

/// The homogeneous `(4, 4)` matrix of a pose.
pub fn matrix<'py>(py: Python<'py>, pose: &Isometry3<f64>) -> Bound<'py, PyArray2<f64>> {
    let h = pose.to_homogeneous();
    Array2::from_shape_fn((4, 4), |(i, j)| h[(i, j)]).into_pyarray(py)
}

/// Index pairs as a `(p, 2)` int64 array.
pub fn pairs<'py>(py: Python<'py>, pairs: &[(u32, u32)]) -> Bound<'py, PyArray2<i64>> {
    let mut a = Array2::<i64>::zeros((pairs.len(), 2));
    for (k, &(i, j)) in pairs.iter().enumerate() {
        a[[k, 0]] = i64::from(i);
        a[[k, 1]] = i64::from(j);
    }
    a.into_pyarray(py)
}

/// Indices as a `(p,)` int64 array.
pub fn indices<'py>(py: Python<'py>, idx: &[u32]) -> Bound<'py, PyArray1<i64>> {
    Array1::from_iter(idx.iter().map(|&i| i64::from(i))).into_pyarray(py)
}

/// Answers as a `(k,)` bool array.
pub fn bools(py: Python<'_>, v: Vec<bool>) -> Bools<'_> {
    Array1::from_vec(v).into_pyarray(py)
}
