//! Arrays in and out: strict checks of dtype and shape (never a silent cast), poses from `(4, 4)`
//! homogeneous matrices, and the errors that say what was wrong.

use cga_collide::collider::PosePair;
use cga_collide::nalgebra::{Isometry3, Matrix3, Point3, Rotation3, Translation3, UnitQuaternion};
use cga_collide::Error;
use numpy::ndarray::{Array1, Array2, ArrayViewD};
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyArrayDescrMethods, PyArrayDyn, PyArrayMethods,
    PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

pyo3::create_exception!(
    cga_collide,
    CgaError,
    PyValueError,
    "An input the library refused (a mesh, a file, a pose, a batch item, a scene handle): the message says what was wrong and where. A subclass of ValueError."
);

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

/// The array behind `obj`, checked to be a numpy array of float64 (any memory layout).
pub fn f64_array<'py>(
    obj: &Bound<'py, PyAny>,
    name: &str,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let untyped = obj.cast::<PyUntypedArray>().map_err(|_| {
        PyTypeError::new_err(format!(
            "{name}: expected a numpy array of float64, got {} (wrap it with np.asarray(..., dtype=np.float64))",
            type_name(obj)
        ))
    })?;
    let dtype = untyped.dtype();
    if !dtype.is_equiv_to(&numpy::dtype::<f64>(obj.py())) {
        return Err(PyTypeError::new_err(format!(
            "{name}: expected dtype float64, got {} (values are never cast silently: convert explicitly with .astype(np.float64) if that is what you mean)",
            dtype_name(&dtype)
        )));
    }
    Ok(untyped.cast::<PyArrayDyn<f64>>()?.clone())
}

fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type()
        .name()
        .map(|n| n.to_string())
        .unwrap_or_else(|_| "an object".to_owned())
}

fn dtype_name(dtype: &Bound<'_, numpy::PyArrayDescr>) -> String {
    dtype
        .str()
        .map(|s| s.to_string())
        .unwrap_or_else(|_| "another dtype".to_owned())
}

/// Checks the shape of an array against a pattern (`None` = any length).
pub fn check_shape(shape: &[usize], want: &[Option<usize>], name: &str) -> PyResult<()> {
    let ok = shape.len() == want.len()
        && shape
            .iter()
            .zip(want)
            .all(|(s, w)| w.is_none_or(|w| *s == w));
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

/// The vertices of a mesh: an `(n, 3)` float64 array.
pub fn vertices(obj: &Bound<'_, PyAny>) -> PyResult<Vec<Point3<f64>>> {
    points(obj, "vertices")
}

/// Points from an `(n, 3)` float64 array; `name` says which argument in errors.
pub fn points(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<Point3<f64>>> {
    let a = f64_array(obj, name)?;
    let r = a.readonly();
    let v = r.as_array();
    check_shape(v.shape(), &[None, Some(3)], name)?;
    Ok(v.outer_iter()
        .map(|row| Point3::new(row[0], row[1], row[2]))
        .collect())
}

/// The faces of a mesh: an `(m, 3)` integer array (any integer dtype), each index checked.
pub fn faces(obj: &Bound<'_, PyAny>, vertex_count: usize) -> PyResult<Vec<[u32; 3]>> {
    let untyped = obj.cast::<PyUntypedArray>().map_err(|_| {
        PyTypeError::new_err(format!(
            "faces: expected a numpy array of integers, got {}",
            type_name(obj)
        ))
    })?;
    let dtype = untyped.dtype();
    let kind = dtype.kind();
    if kind != b'i' && kind != b'u' {
        return Err(PyTypeError::new_err(format!(
            "faces: expected an integer dtype, got {} (vertex indices are never cast from floats silently)",
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
    let converted = obj.call_method1("astype", ("int64",))?;
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

/// A point: a `(3,)` float64 array.
pub fn point(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Point3<f64>> {
    let a = f64_array(obj, name)?;
    let r = a.readonly();
    let v = r.as_array();
    check_shape(v.shape(), &[Some(3)], name)?;
    Ok(Point3::new(v[0], v[1], v[2]))
}

/// One pose from a `(4, 4)` view; `name` says where it came from in errors.
fn pose_of(m: &ArrayViewD<'_, f64>, name: &str) -> PyResult<Isometry3<f64>> {
    for ((i, j), &x) in (0..4)
        .flat_map(|i| (0..4).map(move |j| (i, j)))
        .map(|(i, j)| ((i, j), &m[[i, j]]))
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
    let r = Matrix3::from_fn(|i, j| m[[i, j]]);
    let gram = r.transpose() * r - Matrix3::identity();
    let off = gram.iter().fold(0.0f64, |acc, x| acc.max(x.abs()));
    let det = r.determinant();
    if off > ROTATION_TOLERANCE || det <= 0.0 {
        return Err(value_error(format!(
            "{name}: the upper-left 3x3 block is not a rotation (max |RᵀR − I| = {off:.3e}, det = {det}); \
             a pose is a rotation and a translation, without scale, shear or reflection"
        )));
    }
    let q = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(r));
    Ok(Isometry3::from_parts(
        Translation3::new(m[[0, 3]], m[[1, 3]], m[[2, 3]]),
        q,
    ))
}

/// A pose from a `(4, 4)` float64 homogeneous matrix.
pub fn pose(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Isometry3<f64>> {
    let a = f64_array(obj, name)?;
    let r = a.readonly();
    let v = r.as_array();
    check_shape(v.shape(), &[Some(4), Some(4)], name)?;
    pose_of(&v, name)
}

/// An optional pose (`None` is the identity).
pub fn pose_or_identity(obj: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Isometry3<f64>> {
    match obj {
        None => Ok(Isometry3::identity()),
        Some(o) if o.is_none() => Ok(Isometry3::identity()),
        Some(o) => pose(o, name),
    }
}

/// Many poses from a `(k, 4, 4)` float64 array.
pub fn poses(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<Isometry3<f64>>> {
    let a = f64_array(obj, name)?;
    let r = a.readonly();
    let v = r.as_array();
    check_shape(v.shape(), &[None, Some(4), Some(4)], name)?;
    v.outer_iter()
        .enumerate()
        .map(|(k, m)| pose_of(&m, &format!("{name}[{k}]")))
        .collect()
}

/// A motion between two poses: a `(2, 4, 4)` float64 array (the pose at `t = 0`, then at
/// `t = 1`).
pub fn pose_motion(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<[Isometry3<f64>; 2]> {
    let a = f64_array(obj, name)?;
    let r = a.readonly();
    let v = r.as_array();
    check_shape(v.shape(), &[Some(2), Some(4), Some(4)], name)?;
    let start = pose_of(
        &v.index_axis(numpy::ndarray::Axis(0), 0),
        &format!("{name}[0]"),
    )?;
    let end = pose_of(
        &v.index_axis(numpy::ndarray::Axis(0), 1),
        &format!("{name}[1]"),
    )?;
    Ok([start, end])
}

/// The pose pairs of a batch: `(k, 4, 4)` arrays of the same length; either may also be one
/// `(4, 4)` pose, used for every query.
pub fn pose_pairs(a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>) -> PyResult<Vec<PosePair>> {
    let many = |obj: &Bound<'_, PyAny>, name: &str| -> PyResult<Result<Vec<_>, Isometry3<f64>>> {
        let arr = f64_array(obj, name)?;
        if arr.ndim() == 2 {
            pose(obj, name).map(Err)
        } else {
            poses(obj, name).map(Ok)
        }
    };
    let (pa, pb) = (many(a, "poses_a")?, many(b, "poses_b")?);
    Ok(match (pa, pb) {
        (Ok(x), Ok(y)) => {
            if x.len() != y.len() {
                return Err(value_error(format!(
                    "poses_a has {} poses and poses_b has {}: give the same number (or one (4, 4) pose for every query)",
                    x.len(),
                    y.len()
                )));
            }
            x.into_iter()
                .zip(y)
                .map(|(a, b)| PosePair::new(a, b))
                .collect()
        }
        (Ok(x), Err(b)) => x.into_iter().map(|a| PosePair::new(a, b)).collect(),
        (Err(a), Ok(y)) => y.into_iter().map(|b| PosePair::new(a, b)).collect(),
        (Err(a), Err(b)) => vec![PosePair::new(a, b)],
    })
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
