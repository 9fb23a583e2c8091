//! One simulation step of the scalable CCD dataset (Belgrod et al. 2023, Apache-2.0, copied
//! with its licence under `tests/fixtures/ccd/cloth-funnel/`): a cloth falling through a funnel,
//! 9,450 vertices. Every pair that touches during the step must be exactly the pairs the
//! dataset's exact (symbolic) truth marks as touching; every other swept-box candidate must be
//! found not touching (the dataset ships truth only for the candidates a conservative method
//! flagged, so the others are negatives).

use std::collections::BTreeSet;
use std::path::Path;

use cga_collide::motion::{mesh_edges, step_self_contacts};
use cga_collide::TriMesh;

fn fixture(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/ccd/cloth-funnel")
        .join(name)
}

fn json(name: &str) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(fixture(name)).expect("fixture")).expect("json")
}

#[test]
fn cloth_funnel_step_contacts_equal_the_exact_truth() {
    let start = TriMesh::load(fixture("227.ply.gz")).expect("frame 227");
    let end = TriMesh::load(fixture("228.ply.gz")).expect("frame 228");
    assert_eq!(start.triangles(), end.triangles());
    let (v, f) = (start.vertices().len(), start.num_triangles());
    assert_eq!((v, f), (9450, 18484));
    let edges = mesh_edges(start.triangles());
    assert_eq!(edges.len(), 27930);

    // Truth: element ids index [vertices | edges | faces].
    let truth = |kind: &str| -> Vec<(Vec<u64>, bool)> {
        let ids = json(&format!("227{kind}.json"));
        let flags = json(&format!("227{kind}_mma_bool.json"));
        ids.as_array()
            .unwrap()
            .iter()
            .zip(flags.as_array().unwrap())
            .map(|(p, t)| {
                let p = p
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|x| x.as_u64().unwrap())
                    .collect();
                (p, t.as_bool().unwrap())
            })
            .collect()
    };
    let (nv, ne) = (v as u64, edges.len() as u64);
    let true_vf: BTreeSet<(u32, u32)> = truth("vf")
        .into_iter()
        .filter(|(_, t)| *t)
        .map(|(p, _)| (p[0] as u32, (p[1] - nv - ne) as u32))
        .collect();
    let true_ee: BTreeSet<([u32; 2], [u32; 2])> = truth("ee")
        .into_iter()
        .filter(|(_, t)| *t)
        .map(|(p, _)| {
            let (a, b) = (edges[(p[0] - nv) as usize], edges[(p[1] - nv) as usize]);
            (a.min(b), a.max(b))
        })
        .collect();
    assert_eq!((true_vf.len(), true_ee.len()), (27, 107));

    let contacts = step_self_contacts(&start, end.vertices(), 1e-12).expect("valid step");
    let ours_vf: BTreeSet<(u32, u32)> = contacts.vertex_face.iter().copied().collect();
    let ours_ee: BTreeSet<([u32; 2], [u32; 2])> = contacts.edge_edge.iter().copied().collect();
    assert_eq!(ours_vf, true_vf);
    assert_eq!(ours_ee, true_ee);
    // Our own broad phase's candidate counts (swept boxes, closed, no inflation, pairs sharing
    // a vertex left out); the dataset ships only the candidates Tight Inclusion flags.
    assert_eq!(
        (
            contacts.vertex_face_candidates,
            contacts.edge_edge_candidates
        ),
        (7319, 33770)
    );
    let first = contacts.first_contact.expect("contacts");
    assert!(first.width() <= 1e-12 && first.lo() > 0.0 && first.lo() < 0.05);
}

#[test]
fn a_step_with_the_wrong_vertex_count_is_an_error() {
    let mesh = TriMesh::load(fixture("227.ply.gz")).expect("frame");
    let e = step_self_contacts(&mesh, &mesh.vertices()[1..], 1e-9).unwrap_err();
    assert!(
        e.to_string()
            .contains("9449 vertices but the mesh has 9450"),
        "{e}"
    );
    let mut bad = mesh.vertices().to_vec();
    bad[7].y = f64::NAN;
    let e = step_self_contacts(&mesh, &bad, 1e-9).unwrap_err();
    assert!(e.to_string().contains("vertex 7"), "{e}");
}
