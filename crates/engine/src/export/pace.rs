//! Looking at the deadline while writing: once every [`DEADLINE_EVERY`]
//! items (vertices welded, triangles split, numbers written, bytes
//! compressed), so one large mesh is never written whole between two
//! looks. Text formats cost ten to twenty times glb's work per triangle:
//! before, a 23-million-triangle model took USDZ 4.4 s, 3MF 4.4 s and UG
//! 1.7 s past a 1 s deadline (`deadline::every_format_keeps_the_deadline…`).

use super::{ExportError, DEADLINE_EVERY};
use crate::core::budget::Budget;

/// A count of items written against `budget`'s deadline.
pub(crate) struct Pace<'a> {
    budget: &'a Budget,
    n: usize,
}

impl<'a> Pace<'a> {
    /// Counting from zero against `budget`'s deadline.
    pub(crate) fn new(budget: &'a Budget) -> Pace<'a> {
        Pace { budget, n: 0 }
    }

    /// Counts one item, failing with the deadline when it has passed.
    pub(crate) fn step(&mut self) -> Result<(), ExportError> {
        self.n += 1;
        if self.n % DEADLINE_EVERY == 0 {
            self.budget.check_deadline()?;
        }
        Ok(())
    }
}

/// `mesh` welded ([`super::Welded`]), keeping `pace` per position and
/// triangle: welding hashes every position, which for millions of them is
/// itself a second.
pub(crate) fn welded(mesh: &crate::geom::Mesh, pace: &mut Pace<'_>) -> Result<super::Welded, ExportError> {
    use crate::geom::weld;
    let watch = pace.budget.deadline_stop();
    let (points, remap) = weld::weld_by_until(mesh.positions.iter().copied(), weld::f32_key, &|| watch.stop()).ok_or_else(|| watch.error())?;
    let tris = weld::welded_triangles(&mesh.indices, &remap).map(|t| pace.step().map(|()| t)).collect::<Result<Vec<_>, _>>()?;
    Ok((points, tris))
}
