//! Built-in meshes, embedded in the library so that nothing is read from disk (feature
//! `builtin-meshes`, off by default: about 1.8 MB of mesh data in the binary).

use super::{MeshFormat, TriMesh};

const BUNNY_OBJ: &[u8] = include_bytes!("../../../data/bunny.obj");
const BUNNY00_OFF_GZ: &[u8] = include_bytes!("../../../data/bunny00.off.gz");
const ARMADILLO_OFF_GZ: &[u8] = include_bytes!("../../../data/armadillo.off.gz");

fn embedded(bytes: &[u8], format: MeshFormat, name: &str) -> TriMesh {
    // The embedded files are fixed and tested (`builtin_meshes_load`), so failure here would be
    // a build defect, not bad user input.
    TriMesh::from_bytes(bytes, format, name).expect("embedded mesh is valid")
}

impl TriMesh {
    /// The low-resolution Stanford bunny (3 674 triangles; `data/bunny.obj`).
    ///
    /// ```
    /// use cga_collide::TriMesh;
    /// let bunny = TriMesh::bunny();
    /// assert_eq!(bunny.num_triangles(), 3_674);
    /// ```
    pub fn bunny() -> TriMesh {
        embedded(BUNNY_OBJ, MeshFormat::Obj, "bunny.obj")
    }

    /// The Stanford bunny at 75 408 triangles (`data/bunny00.off.gz`).
    ///
    /// ```
    /// use cga_collide::TriMesh;
    /// assert_eq!(TriMesh::bunny00().num_triangles(), 75_408);
    /// ```
    pub fn bunny00() -> TriMesh {
        embedded(BUNNY00_OFF_GZ, MeshFormat::Off, "bunny00.off.gz")
    }

    /// The Stanford armadillo at 52 000 triangles (`data/armadillo.off.gz`).
    ///
    /// ```
    /// use cga_collide::TriMesh;
    /// assert_eq!(TriMesh::armadillo().num_triangles(), 52_000);
    /// ```
    pub fn armadillo() -> TriMesh {
        embedded(ARMADILLO_OFF_GZ, MeshFormat::Off, "armadillo.off.gz")
    }

    /// A bunny with at least `min_triangles` triangles: the 3 674-triangle bunny subdivided
    /// 1→4 as often as needed (3.7K, 14.7K, 58.8K, 235K, 941K, 3.76M, …), for scaling runs
    /// at the thesis's sizes.
    ///
    /// ```
    /// use cga_collide::TriMesh;
    /// assert_eq!(TriMesh::bunny_with_at_least(10_000).num_triangles(), 4 * 3_674);
    /// ```
    pub fn bunny_with_at_least(min_triangles: usize) -> TriMesh {
        TriMesh::bunny().subdivided_to(min_triangles)
    }
}
