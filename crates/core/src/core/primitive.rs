//! The built-in primitive kinds: the drawables every language places and
//! every mesher tessellates, so they sit below both.

/// The built-in drawables. Each is unit-sized and centred at the origin (see `docs/mdg.md`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[repr(u8)]
pub enum PrimitiveKind {
    /// Axis-aligned cube with edge 1.
    Box,
    /// Sphere of diameter 1.
    Sphere,
    /// Cylinder of diameter 1 and height 1 along +Y.
    Cylinder,
    /// Cone of base diameter 1 and height 1, apex at +Y.
    Cone,
    /// Torus in the XZ plane with outer diameter 1 (major radius 0.375, minor 0.125).
    Torus,
    /// Regular tetrahedron with circumradius 0.5.
    Tetrahedron,
    /// Regular octahedron with circumradius 0.5.
    Octahedron,
    /// Regular icosahedron with circumradius 0.5.
    Icosahedron,
    /// Regular dodecahedron with circumradius 0.5.
    Dodecahedron,
}

impl PrimitiveKind {
    /// Every primitive, in a fixed order (used for per-kind meshes).
    pub const ALL: [PrimitiveKind; 9] = [
        PrimitiveKind::Box,
        PrimitiveKind::Sphere,
        PrimitiveKind::Cylinder,
        PrimitiveKind::Cone,
        PrimitiveKind::Torus,
        PrimitiveKind::Tetrahedron,
        PrimitiveKind::Octahedron,
        PrimitiveKind::Icosahedron,
        PrimitiveKind::Dodecahedron,
    ];

    /// The canonical (upper-case) keyword.
    pub fn name(self) -> &'static str {
        match self {
            PrimitiveKind::Box => "BOX",
            PrimitiveKind::Sphere => "SPHERE",
            PrimitiveKind::Cylinder => "CYLINDER",
            PrimitiveKind::Cone => "CONE",
            PrimitiveKind::Torus => "TORUS",
            PrimitiveKind::Tetrahedron => "TETRAHEDRON",
            PrimitiveKind::Octahedron => "OCTAHEDRON",
            PrimitiveKind::Icosahedron => "ICOSAHEDRON",
            PrimitiveKind::Dodecahedron => "DODECAHEDRON",
        }
    }

    /// Looks a keyword up case-insensitively (`sphere` = `SPHERE`).
    pub fn from_keyword(word: &str) -> Option<PrimitiveKind> {
        PrimitiveKind::ALL
            .into_iter()
            .find(|k| k.name().eq_ignore_ascii_case(word))
    }
}
