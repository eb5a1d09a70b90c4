//! Unit-box fitting of every primitive kind's mesh (`geom::normalize`): here,
//! not in the geometry crate, because it meshes through the engine's test scenes.

use crate::geom::normalize::*;
use crate::core::Budget;
use crate::core::budget::Limits;
use crate::export::gltf::tests::{all_nine, meshes_of};
use crate::mesh::MeshLayout;

#[test]
fn fits_the_unit_box_centred() {
    let meshes = meshes_of(&all_nine(), 8, MeshLayout::PerKind);
    let (fitted, _) = fit_unit_box(&meshes, &mut Budget::new(Limits::default())).expect("fits");
    let (lo, hi) = bounds(&fitted).expect("triangles");
    let ext = (0..3).map(|a| hi[a] - lo[a]).fold(0.0f64, f64::max);
    assert!((ext - 1.0).abs() < 1e-6, "{ext}");
    for a in 0..3 {
        assert!(((lo[a] + hi[a]) * 0.5).abs() < 1e-6);
    }
    assert_eq!(fitted[0].mesh.normals, meshes[0].mesh.normals);
    assert_eq!(fitted[0].mesh.indices, meshes[0].mesh.indices);
}
