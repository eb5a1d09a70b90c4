use super::*;
use crate::core::budget::{Limit, Limits};
use crate::export::gltf::tests::{all_nine, meshes_of};
use crate::geom::Mesh;
use crate::mesh::MeshLayout;

fn triangle(colours: [[u8; 4]; 3]) -> NamedMesh {
    NamedMesh {
        name: "t".into(),
        mesh: Mesh {
            positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.5, -2.0]],
            normals: vec![[0.0, 0.0, 1.0]; 3],
            colours: colours.to_vec(),
            indices: vec![0, 1, 2],
        },
    }
}

/// The one entry's data: the stored layer text.
fn layer_of(usdz: &[u8]) -> String {
    let mut zip = zip::ZipArchive::new(std::io::Cursor::new(usdz)).unwrap();
    assert_eq!(zip.len(), 1);
    let mut f = zip.by_index(0).unwrap();
    assert_eq!(f.name().unwrap(), package::LAYER_NAME);
    assert_eq!(f.compression(), zip::CompressionMethod::Stored);
    assert_eq!(f.data_start().unwrap() % 64, 0);
    let mut s = String::new();
    std::io::Read::read_to_string(&mut f, &mut s).unwrap();
    s
}

#[test]
fn a_triangle_is_one_mesh_prim_with_its_material() {
    let red = [255, 0, 0, 255];
    let out = write_usdz(&[triangle([red; 3])], &ExportMeta::default(), &mut Budget::new(Limits::default())).unwrap();
    let text = layer_of(&out);
    let expected_mesh = "
    def Mesh \"Mesh_0_0\" (
        prepend apiSchemas = [\"MaterialBindingAPI\"]
    )
    {
        float3[] extent = [(0, 0, -2), (1, 0.5, 0)]
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        rel material:binding = </Model/Materials/Colour_ff0000ff>
        normal3f[] normals = [(0, 0, 1), (0, 0, 1), (0, 0, 1)] (
            interpolation = \"vertex\"
        )
        point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 0.5, -2)]
        color3f[] primvars:displayColor = [(1, 0, 0)] (
            interpolation = \"constant\"
        )
        uniform token subdivisionScheme = \"none\"
    }
}
";
    assert!(text.ends_with(expected_mesh), "{text}");
    assert!(text.starts_with("#usda 1.0\n"));
    assert!(text.contains("    defaultPrim = \"Model\"\n    metersPerUnit = 1\n    upAxis = \"Y\"\n"));
    assert_eq!(text.matches("def Material ").count(), 1);
    assert!(text.contains("color3f inputs:diffuseColor = (1, 0, 0)"));
}

#[test]
fn colours_split_a_mesh_and_share_materials() {
    let (red, blue) = ([255, 0, 0, 255], [0, 0, 255, 128]);
    let mut two = triangle([red; 3]);
    two.mesh.positions.push([5.0, 5.0, 5.0]);
    two.mesh.normals.push([0.0, 1.0, 0.0]);
    two.mesh.colours.push(blue);
    two.mesh.indices.extend([3, 1, 2]);
    let out = write_usdz(&[two, triangle([blue; 3])], &ExportMeta::default(), &mut Budget::new(Limits::default())).unwrap();
    let text = layer_of(&out);
    assert_eq!(text.matches("def Mesh ").count(), 3);
    assert_eq!(text.matches("def Material ").count(), 2);
    assert!(text.contains("def Mesh \"Mesh_0_1\""));
    assert!(text.contains("def Mesh \"Mesh_1_0\""));
    // The blue group re-indexes its vertices 3, 1, 2 as 0, 1, 2.
    assert_eq!(text.matches("int[] faceVertexIndices = [0, 1, 2]").count(), 3);
    assert_eq!(text.matches("float inputs:opacity = 0.5019608").count(), 1);
    assert_eq!(text.matches("float[] primvars:displayOpacity = [0.5019608]").count(), 2);
}

#[test]
fn floats_are_short_and_exact() {
    for (x, s) in [(0.0f32, "0"), (-0.0, "0"), (0.1, "0.1"), (1e-7, "1e-7"), (3.4e38, "3.4e38"), (-1234567.9, "-1234567.9"), (1.0e-5, "0.00001")] {
        let mut out = String::new();
        layer::float(&mut out, x);
        assert_eq!(out, s);
    }
    for x in [f32::MIN_POSITIVE, -f32::MAX, 1.234_567_9e-5, -9.876_543e6, f32::from_bits(1)] {
        let mut out = String::new();
        layer::float(&mut out, x);
        assert!(out.len() <= 16, "{out}");
        assert_eq!(out.parse::<f32>().unwrap(), x);
    }
}

#[test]
fn provenance_and_truncation_are_layer_data() {
    use crate::core::ParamValue;
    let provenance = crate::export::Provenance {
        language: crate::lang::Language::Mdg,
        seed: u64::MAX,
        params: [("n".to_string(), ParamValue::Text("a\"b".into()))].into(),
        model_key: "ab".repeat(32),
    };
    let meta = ExportMeta { provenance: Some(provenance), truncated: true, ..ExportMeta::default() };
    let text = layer_of(&write_usdz(&[], &meta, &mut Budget::new(Limits::default())).unwrap());
    assert!(text.contains("            string seed = \"18446744073709551615\"\n"), "{text}");
    assert!(text.contains("            string params = \"{\\\"n\\\":\\\"a\\\\\\\"b\\\"}\"\n"), "{text}");
    assert!(text.contains("            bool truncated = 1\n"));
    assert!(!text.contains("def Mesh"));
}

#[test]
fn the_bound_holds_and_reruns_are_identical() {
    let meshes = meshes_of(&all_nine(), 16, MeshLayout::PerKind);
    let lim = Limits::default();
    let a = write_usdz(&meshes, &ExportMeta::default(), &mut Budget::new(lim)).unwrap();
    let b = write_usdz(&meshes, &ExportMeta::default(), &mut Budget::new(lim)).unwrap();
    assert_eq!(a, b);
    let t: u64 = meshes.iter().map(|m| m.mesh.triangle_count() as u64).sum();
    assert!(a.len() as u64 <= USDZ.size.of(0, t), "{} > {}", a.len(), USDZ.size.of(0, t));
}

#[test]
fn a_memory_limit_is_named_and_nothing_stays_reserved() {
    let meshes = meshes_of(&all_nine(), 16, MeshLayout::Merged);
    let mut b = Budget::new(Limits { max_memory: 1000, ..Limits::default() });
    match write_usdz(&meshes, &ExportMeta::default(), &mut b) {
        Err(ExportError::Limit(e)) => assert_eq!(e.limit, Limit::Memory),
        other => panic!("expected a memory limit, got {other:?}"),
    }
    assert_eq!(b.memory(), 0);
}

#[test]
fn malformed_meshes_are_refused() {
    let mut bad = triangle([[1; 4]; 3]);
    bad.mesh.indices[2] = 9;
    assert!(matches!(write_usdz(&[bad], &ExportMeta::default(), &mut Budget::new(Limits::default())), Err(ExportError::InvalidMesh { .. })));
    let mut bad = triangle([[1; 4]; 3]);
    bad.mesh.positions[0][1] = f32::NAN;
    assert!(matches!(write_usdz(&[bad], &ExportMeta::default(), &mut Budget::new(Limits::default())), Err(ExportError::InvalidMesh { .. })));
}
