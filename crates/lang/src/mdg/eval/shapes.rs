//! Terminals other than primitives and lines: free vertices and
//! `FACENORMALS`, `FRAME`/`VERTEX` inside path rules, and the shapes of
//! isosurfaces and `mesh` declarations (each built once, on first use, and
//! charged to the budget before it is made).

use super::adjust::{Ctx, Env};
use super::machine::Machine;
use crate::core::frame::Frame;
use crate::ir::Target;
use crate::model::scene::{FreeVertex, FREE_VERTEX_BYTES};
use crate::model::EvalError;
use glam::DVec3;

impl<'p, 'b> Machine<'p, 'b> {
    /// `VERTEX`, `FACENORMALS` and `FRAME`.
    pub(super) fn special(&mut self, target: Target, ctx: &Ctx) -> Result<(), EvalError> {
        let frame_bytes = std::mem::size_of::<Frame>() as u64;
        if let Some(capture) = &mut self.capture {
            match target {
                Target::Vertex => {
                    self.budget.reserve_memory(24)?;
                    capture.vertices.push(ctx.frame.translation);
                }
                Target::Frame => {
                    self.budget.reserve_memory(frame_bytes)?;
                    capture.frames.push(ctx.frame);
                }
                _ => {}
            }
            return Ok(());
        }
        match target {
            Target::Vertex => {
                let vertices = self.scene.vertices.len() as u64 + 1;
                if vertices % 3 == 0 {
                    self.budget.charge_triangles(1)?;
                }
                self.budget.reserve_memory(FREE_VERTEX_BYTES.saturating_add(self.ev.cost.bytes(1, 1)))?;
                let local = self.ev.program.directives.normal.map_or(DVec3::Z, DVec3::from_array);
                let mut colour = ctx.colour;
                colour[3] += 1.0;
                self.tag(|r| &mut r.vertex_bone, ctx.bone)?;
                self.scene.vertices.push(FreeVertex {
                    position: ctx.frame.translation,
                    normal: ctx.frame.transform_normal(local).normalize_or_zero(),
                    colour: colour.map(|c| c.clamp(0.0, 1.0) as f32),
                });
                self.set_terminal(ctx.ns, ctx.frame);
            }
            Target::FaceNormals => {
                let n = self.scene.vertices.len();
                if n >= 3 {
                    let v = &mut self.scene.vertices[n - 3..];
                    // A degenerate triangle has no face normal: keep the vertex normals.
                    if let Some(face) = (v[1].position - v[0].position).cross(v[2].position - v[0].position).try_normalize() {
                        for x in v {
                            x.normal = face;
                        }
                    }
                }
            }
            // A FRAME outside a path (animation, cameras) does not draw.
            _ => {}
        }
        Ok(())
    }

    /// The scene shape of isosurface `i`, meshed on first use. The grid's
    /// samples are charged as steps and memory before any is computed.
    pub(super) fn isosurface(&mut self, i: u32) -> Result<u32, EvalError> {
        if let Some(&s) = self.isosurface_shape.get(&i) {
            return Ok(s);
        }
        let Some(iso) = self.ev.program.isosurfaces.get(i as usize) else { return Ok(0) };
        let samples = crate::geom::isosurface::sample_count(&iso.axes);
        self.budget.charge_steps(samples)?;
        // The grid (an f32 field and a u32 vertex map per sample) is transient but large.
        let grid_bytes = samples.saturating_mul(12);
        self.budget.reserve_memory(grid_bytes)?;
        let params = self.ev.params;
        let key = self.root_key;
        let proto = crate::geom::isosurface::mesh_isosurface(&iso.axes, |p| {
            iso.field.eval(&mut Env { params, key, pos: DVec3::from_array(p) })
        });
        self.budget.release_memory(grid_bytes);
        self.budget.reserve_memory(crate::geom::mesh::mesh_bytes(proto.positions.len() as u64, (proto.indices.len() / 3) as u64))?;
        self.scene.shapes.push(proto);
        let s = (self.scene.shapes.len() - 1) as u32;
        self.isosurface_shape.insert(i, s);
        Ok(s)
    }

    /// The scene shape of `mesh` declaration `i`, built on first use; the
    /// modifiers check every intermediate size against the budget first.
    pub(super) fn mesh(&mut self, i: u32) -> Result<u32, EvalError> {
        if let Some(&s) = self.mesh_shape.get(&i) {
            return Ok(s);
        }
        let Some(decl) = self.ev.program.meshes.get(i as usize) else { return Ok(0) };
        let proto = crate::geom::modifiers::build(&decl.base, &decl.modifiers, self.ev.detail, self.budget).map_err(|e| match e {
            crate::geom::modifiers::ModifyError::Limit(l) => EvalError::Limit(l),
            other => EvalError::Mesh { span: decl.span, name: decl.name.clone(), message: other.to_string() },
        })?;
        self.budget.reserve_memory(crate::geom::mesh::mesh_bytes(proto.positions.len() as u64, (proto.indices.len() / 3) as u64))?;
        self.scene.shapes.push(proto);
        let s = (self.scene.shapes.len() - 1) as u32;
        self.mesh_shape.insert(i, s);
        Ok(s)
    }
}
