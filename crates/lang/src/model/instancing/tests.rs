use super::*;
use crate::core::budget::Limits;
use crate::core::frame::Frame;
use glam::DVec3;

fn box_at(x: f32, parity: bool) -> Instance {
    Instance {
        kind: PrimitiveKind::Box,
        parity,
        translation: Vec3::new(x, 0.0, 0.0),
        rotation: Quat::from_rotation_y(0.4),
        scale: 2.0,
        colour: [1.0, 0.5, 0.25, 1.0],
    }
}

fn affine(linear: Mat3) -> AffineInstance {
    AffineInstance { kind: PrimitiveKind::Sphere, linear, translation: Vec3::ONE, colour: [0.2; 4], class: 0 }
}

/// Where the instanced form puts prototype point `p` of `key`'s (possibly mirrored) prototype.
fn placed(p: &Placement, point: Vec3) -> Vec3 {
    p.translation + p.rotation * (p.scale * point)
}

#[test]
fn decompose_splits_rotation_scale_and_mirror_and_refuses_shear() {
    let r = Quat::from_euler(glam::EulerRot::XYZ, 0.3, -1.1, 2.0);
    let s = Vec3::new(0.5, 2.0, 3.0);
    let l = Mat3::from_quat(r) * Mat3::from_diagonal(s);
    let (q, scale, mirrored) = decompose(l).expect("orthogonal columns");
    assert!(!mirrored);
    assert!((scale - s).abs().max_element() < 1e-6, "{scale}");
    assert!(q.dot(r).abs() > 1.0 - 1e-6);
    // Mirrored: L = R·S·(−I), the prototype is reflected and the scale stays positive.
    let (q, scale, mirrored) = decompose(l * -1.0).expect("orthogonal columns");
    assert!(mirrored);
    assert!((scale - s).abs().max_element() < 1e-6 && q.dot(r).abs() > 1.0 - 1e-6);
    // A plane reflection is mirrored too.
    assert!(decompose(Mat3::from_diagonal(Vec3::new(1.0, -1.0, 1.0))).expect("reflection").2);
    // A shear, a flat map and a non-finite one have no TRS form.
    assert_eq!(decompose(Mat3::from_cols(Vec3::X, Vec3::new(0.1, 1.0, 0.0), Vec3::Z)), None);
    assert_eq!(decompose(Mat3::from_diagonal(Vec3::new(1.0, 0.0, 1.0))), None);
    assert_eq!(decompose(Mat3::from_diagonal(Vec3::new(1.0, f32::NAN, 1.0))), None);
}

/// Every vertex of an instance, mirrored or not, lands where the mesh stage
/// puts it, and the winding still faces outward (positive signed volume).
#[test]
fn instances_land_where_flat_copies_do_with_outward_winding() {
    let scene = Scene::default();
    let l = Mat3::from_quat(Quat::from_rotation_z(0.7)) * Mat3::from_diagonal(Vec3::new(1.0, 3.0, 0.5));
    let cases = [
        (Placement::of_instance(&box_at(1.0, false)).expect("drawable"), box_at(1.0, false).linear(), box_at(1.0, false).translation),
        (Placement::of_instance(&box_at(1.0, true)).expect("drawable"), box_at(1.0, true).linear(), box_at(1.0, true).translation),
        (Placement::of_affine(&affine(l * -1.0)).expect("TRS"), l * -1.0, Vec3::ONE),
    ];
    for (p, linear, t) in cases {
        let proto = prototype(&p.key, &scene, 8).expect("prototype");
        let flat = primitives::tessellate(match p.key.source {
            Source::Primitive(k) => k,
            Source::Shape(_) => unreachable!(),
        }, 8);
        for (a, b) in proto.positions.iter().zip(&flat.positions) {
            let want = linear * Vec3::from_array(*b) + t;
            assert!((placed(&p, Vec3::from_array(*a)) - want).length() < 1e-5, "{:?}", p.key);
        }
        let volume: f32 = proto
            .indices
            .chunks_exact(3)
            .map(|t| {
                let [a, b, c] = [0, 1, 2].map(|k| placed(&p, Vec3::from_array(proto.positions[t[k] as usize])));
                a.dot(b.cross(c)) / 6.0
            })
            .sum();
        assert!(volume > 0.0, "{:?}: volume {volume}", p.key);
    }
}

#[test]
fn a_plan_instances_what_repeats_and_leaves_the_rest_plain() {
    let sheared = Mat3::from_cols(Vec3::X, Vec3::new(0.5, 1.0, 0.0), Vec3::Z);
    let mut scene = Scene {
        instances: vec![box_at(0.0, false), box_at(1.0, false), box_at(2.0, true), box_at(3.0, false), Instance { scale: 0.0, ..box_at(4.0, false) }],
        affine: vec![affine(Mat3::IDENTITY), affine(Mat3::from_diagonal(Vec3::new(1.0, 2.0, 3.0))), affine(sheared), affine(sheared)],
        shape_instances: (0..2).map(|k| ShapeInstance { shape: 0, frame: Frame::from_translation(DVec3::X * f64::from(k)), colour: [1.0; 4] }).collect(),
        shapes: vec![primitives::tessellate(PrimitiveKind::Octahedron, 4)],
        ..Scene::default()
    };
    let plan = Plan::new(&scene);
    let key = |source, mirrored| MeshKey { class: 0, source, mirrored };
    let (boxes, spheres, shape) = (key(Source::Primitive(PrimitiveKind::Box), false), key(Source::Primitive(PrimitiveKind::Sphere), false), key(Source::Shape(0), false));
    // Three upright boxes, two spheres with a TRS form (the sheared ones stay plain), two shape placements.
    assert_eq!(plan.meshes(), &[(boxes, 3), (spheres, 2), (shape, 2)]);
    assert_eq!(plan.instances(), 7);
    let mut walked = Vec::new();
    plan.walk(&scene, &mut |slot, p| walked.push((slot, p.translation.x)));
    assert_eq!(walked, [(0, 0.0), (0, 1.0), (0, 3.0), (1, 1.0), (1, 1.0), (2, 0.0), (2, 1.0)]);
    let mut budget = Budget::new(Limits::default());
    let residual = plan.residual(&mut scene, &mut budget).expect("fits");
    // The mirrored box (placed once), the undrawable one and the sheared spheres.
    assert_eq!((residual.instances.len(), residual.affine.len(), residual.shape_instances.len()), (2, 2, 0));
    assert_eq!(budget.memory(), residual_bytes(residual_counts(&residual)));
    assert!(scene.shapes.is_empty() && residual.shapes.len() == 1);
}

#[test]
fn a_tally_charges_repeats_as_instances_only_when_the_output_instances() {
    let boxes = Some(MeshKey { class: 0, source: Source::Primitive(PrimitiveKind::Box), mirrored: false });
    let mirrored = boxes.map(|k| MeshKey { mirrored: true, ..k });
    let mut t = Tally::new(Some(52));
    assert_eq!(t.cost(boxes, 12, 1000), (12, 1000));
    assert_eq!(t.cost(boxes, 12, 1000), (1, 52));
    assert_eq!(t.cost(mirrored, 12, 1000), (12, 1000));
    assert_eq!(t.cost(None, 12, 1000), (12, 1000));
    assert_eq!(t.cost(None, 12, 1000), (12, 1000));
    let mut flat = Tally::new(None);
    assert_eq!(flat.cost(boxes, 12, 1000), (12, 1000));
    assert_eq!(flat.cost(boxes, 12, 1000), (12, 1000));
}
