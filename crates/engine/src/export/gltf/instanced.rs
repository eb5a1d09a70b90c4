//! What instanced glTF (`EXT_mesh_gpu_instancing`) costs per placement, for
//! the descriptors' size bounds. The writer is `gpu_instancing`'s
//! [`InstancedSink`](super::gpu_instancing::InstancedSink); the pipeline's
//! drivers (`pipeline::feed`) find a flat scene's repeated meshes or walk a
//! hierarchy and feed it, so the output grows with the distinct meshes and
//! the placements, never with the triangles of the expansion.

use super::InstanceLayout;

/// The most per-instance attributes an instanced scene's mesh carries:
/// placements rotate, scale per axis and each has its own colour.
pub(crate) const SCENE_LAYOUT: InstanceLayout = InstanceLayout { rotation: true, scale: true, colour: true };

/// Output bytes per instance of an instanced scene at most (what a front
/// end promises per placement after a mesh's first, before it knows which
/// attributes vary).
pub(crate) const SCENE_INSTANCE_BYTES: u64 = SCENE_LAYOUT.bytes();
